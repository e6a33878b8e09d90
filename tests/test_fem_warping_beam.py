"""POU_D_TG (Timoshenko beams with warping) and VARI_SECT sections whose
start and end are equal: non-uniform torsion of a cantilever against
Vlasov's solution, the POU_D_T part unchanged, and the constant section
recovered from R_DEBUT/R_FIN or A1/A2 data."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.fem.beam import (
    beam_mass_local,
    beam_stiffness_local,
    local_matrices,
    warping_beam_stiffness_local,
)
from asterlite.fem.sections import section_properties, uniform_varying_section

E, NU = 2.1e11, 0.3
G = E / (2 * (1 + NU))
SECTION = {"A": 1e-2, "IY": 2e-5, "IZ": 5e-6, "JX": 1e-7, "JG": 4e-9, "AY": 1.2, "AZ": 1.3}


def _cantilever_twist(n, length, torque, jx, jg, restrained=True):
    """Tip twist and twist rate of a cantilever of n POU_D_TG elements under
    an end torque, the root's warping (GRX) held when ``restrained``."""
    size = 7 * (n + 1)
    k = np.zeros((size, size))
    section = dict(SECTION, JX=jx, JG=jg)
    element = local_matrices("POU_D_TG", "K", length / n, section, E, NU)[0]
    for e in range(n):
        rows = np.arange(7 * e, 7 * e + 14)
        k[np.ix_(rows, rows)] += element
    free = np.arange(7 if restrained else 6, size)
    f = np.zeros(size)
    f[7 * n + 3] = torque
    u = np.zeros(size)
    u[free] = np.linalg.solve(k[np.ix_(free, free)], f[free])
    return u[7 * n + 3], u[7 * n + 6]


def test_non_uniform_torsion_against_vlasov():
    """phi(L) = T / (G J) (L - tanh(k L) / k), k^2 = G J / (E JG): the
    cubic-twist elements converge to it; without warping, T L / (G J) exactly."""
    length, torque = 2.0, 1.0e3
    k = np.sqrt(G * SECTION["JX"] / (E * SECTION["JG"]))
    exact = torque / (G * SECTION["JX"]) * (length - np.tanh(k * length) / k)
    errors = [
        abs(_cantilever_twist(n, length, torque, SECTION["JX"], SECTION["JG"])[0] / exact - 1)
        for n in (2, 4, 8, 16)
    ]
    assert all(a > b for a, b in zip(errors, errors[1:], strict=False))
    assert errors[-1] < 1e-4
    free_warping = _cantilever_twist(1, length, torque, SECTION["JX"], 0.0, restrained=False)
    assert free_warping[0] == pytest.approx(torque * length / (G * SECTION["JX"]), rel=1e-12)
    assert free_warping[1] == pytest.approx(torque / (G * SECTION["JX"]), rel=1e-12)


def test_pou_d_t_terms_are_kept():
    """Without the torsion rows, POU_D_TG is POU_D_T; GRX has no mass."""
    tg = warping_beam_stiffness_local(0.7, E, G, 1e-2, 2e-5, 5e-6, 1e-7, 4e-9, 1.2, 1.3)[0]
    t = beam_stiffness_local(0.7, E, G, 1e-2, 2e-5, 5e-6, 1e-7, ay=1.2, az=1.3)[0]
    keep = [0, 1, 2, 4, 5, 7, 8, 9, 11, 12]
    same = [0, 1, 2, 4, 5, 6, 7, 8, 10, 11]
    assert np.allclose(tg[np.ix_(keep, keep)], t[np.ix_(same, same)], rtol=1e-14)
    m = local_matrices("POU_D_TG", "M", 0.7, SECTION, E, NU, 7800.0)[0]
    mt = beam_mass_local(0.7, 7800.0, E, G, 1e-2, 2e-5, 5e-6, 1.2, 1.3)[0]
    assert np.allclose(m[np.ix_(keep, keep)], mt[np.ix_(same, same)], rtol=1e-14)
    assert not m[[6, 13]].any()
    assert np.allclose(tg, tg.T)


def test_vari_sect_with_equal_ends_is_the_constant_section():
    cara = {"R_DEBUT": 0.02, "R_FIN": 0.02, "EP_DEBUT": 0.005, "EP_FIN": 0.005}
    uniform = uniform_varying_section("CERCLE", "HOMOTHETIQUE", cara)
    assert uniform == {"R": 0.02, "EP": 0.005}
    assert section_properties("CERCLE", uniform)["A"] == pytest.approx(np.pi * (4e-4 - 2.25e-4))
    general = {"A1": 1.0, "A2": 1.0, "IY1": 2.0, "IY2": 2.0}
    assert uniform_varying_section("GENERALE", "HOMOTHETIQUE", general) == {"A": 1.0, "IY": 2.0}
    affine = {"HY": 0.1, "EPY": 0.01, "HZ1": 0.2, "HZ2": 0.2}
    assert uniform_varying_section("RECTANGLE", "AFFINE", affine) == {
        "HY": 0.1,
        "EPY": 0.01,
        "HZ": 0.2,
    }
    tapered = dict(cara, R_FIN=0.03)
    assert uniform_varying_section("CERCLE", "HOMOTHETIQUE", tapered) is None


def test_inclined_element_in_the_global_frame():
    """An inclined POU_D_TG element turns its two vector triples per node with
    the element's rotation and keeps GRX: its global stiffness has the local
    one's eigenvalues, and on the 12 DOFs of POU_D_T (with JG = 0 and the
    twist rows left out) it is POU_D_T's global stiffness."""
    from asterlite.fem.beam import element_rotation, global_matrices, rotation_from_angles

    x1, x2 = np.array([[0.0, 0.0, 0.0]]), np.array([[0.3, -0.4, 0.5]])
    tg = global_matrices("POU_D_TG", "K", x1, x2, SECTION, E, NU)[0]
    length = float(np.linalg.norm(x2 - x1))
    local = local_matrices("POU_D_TG", "K", length, SECTION, E, NU)[0]
    assert np.allclose(np.linalg.eigvalsh(tg), np.linalg.eigvalsh(local), rtol=1e-10, atol=1e-3)
    r = element_rotation(rotation_from_angles(np.array([[0.2, -0.7, 0.4]])), 7)[0]
    assert np.allclose(r @ r.T, np.eye(14), atol=1e-14)
    assert r[6, 6] == r[13, 13] == 1.0 and np.count_nonzero(r[[6, 13]]) == 2
    t = global_matrices("POU_D_T", "K", x1, x2, SECTION, E, NU)[0]
    keep = [0, 1, 2, 7, 8, 9]  # translations: no torsion term reaches them
    same = [0, 1, 2, 6, 7, 8]
    assert np.allclose(tg[np.ix_(keep, keep)], t[np.ix_(same, same)], rtol=1e-12)


def test_line_load_on_an_inclined_cantilever():
    """FORCE_POUTRE on POU_D_TG cells: the consistent load of POU_D_T on the
    translations and rotations, none on GRX; an inclined cantilever under a
    uniform transverse load q deflects q L^4 / (8 E I) + q L^2 / (2 G A / AY)
    at its tip (Timoshenko), as with POU_D_T."""
    from types import SimpleNamespace

    from asterlite.fem import loads
    from asterlite.fem.beam import global_matrices

    n, length, q = 8, 2.0, -1.0e3
    direction = np.array([1.0, 1.0, 0.0]) / np.sqrt(2.0)
    coords = np.outer(np.linspace(0.0, length, n + 1), direction)
    mesh = SimpleNamespace(
        coords=coords,
        cell_nodes=[[e, e + 1] for e in range(n)],
        cell_names=[f"E{e}" for e in range(n)],
        cell_types=["SEG2"] * n,
    )
    model = SimpleNamespace(mesh=mesh, cell_modelisation={e: "POU_D_TG" for e in range(n)})
    terms = loads.beam_force_terms(model, None, np.arange(n), {"FZ": q}, local=False)
    names = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ", "GRX")
    size = 7 * (n + 1)
    f = np.zeros(size)
    for node, name, value in terms:
        f[7 * node + names.index(name)] += value
    assert not f[6::7].any()
    assert f[2::7].sum() == pytest.approx(q * length, rel=1e-12)
    k = np.zeros((size, size))
    elements = global_matrices("POU_D_TG", "K", coords[:-1], coords[1:], SECTION, E, NU)
    for e in range(n):
        rows = np.arange(7 * e, 7 * e + 14)
        k[np.ix_(rows, rows)] += elements[e]
    free = np.arange(7, size)
    u = np.linalg.solve(k[np.ix_(free, free)], f[free])
    # an element in the horizontal plane bends about its local y axis under FZ
    shear = G * SECTION["A"] / SECTION["AZ"]
    exact = q * length**4 / (8 * E * SECTION["IY"]) + q * length**2 / (2 * shear)
    assert u[7 * n + 2 - 7] == pytest.approx(exact, rel=1e-9)


def _efge_of_tip_loads(modelisation, n, length, tip_loads, restrained_warping=True):
    """EFGE_ELNO of a cantilever of n cells (CALC_CHAMP on a static state
    stored as a dyna_trans: the POU_D_TG element adds no inertia anyway)."""
    from asterlite.concepts.transient import DynaTrans
    from tests.test_fem_structures import _static, beam_model, line_mesh
    from tests.test_fem_support import FakeSession, run

    session = FakeSession()
    names = ("A", "IY", "IZ", "JX", "JG", "AY", "AZ")
    section = ("GENERALE", names, tuple(SECTION[k] for k in names))
    model, field, cara = beam_model(session, line_mesh(n, length), modelisation, section)
    clamp = [{"GROUP_NO": ("A",), "LIAISON": "ENCASTRE"}]
    if restrained_warping and modelisation == "POU_D_TG":
        clamp.append({"GROUP_NO": ("A",), "GRX": 0.0})
    numbering, u, _ = _static(
        session, model, field, cara, clamp, [{"FORCE_NODALE": {"GROUP_NO": ("B",), **tip_loads}}]
    )
    result = DynaTrans(numbering, np.array([1.0]), np.array([1]), {"DEPL": u[None, :]})
    out = run(session, "CALC_CHAMP", RESULTAT=result, CONTRAINTE=("EFGE_ELNO",))
    return out.element_fields["EFGE_ELNO"]


def test_efge_elno_bending_is_pou_d_t_and_torsion_carries_the_bimoment():
    """POU_D_TG's EFGE_ELNO (N VY VZ MT MFY MFZ BX): bending and axial forces
    as POU_D_T's; under an end torque T, MT = T everywhere and the root's
    bimoment tends to Vlasov's T tanh(k L) / k (k^2 = G J / (E JG)), which
    vanishes at the free end."""
    length, force = 2.0, {"FY": 1.0e3, "FZ": -400.0, "FX": 50.0}
    tg = _efge_of_tip_loads("POU_D_TG", 4, length, force)
    t = _efge_of_tip_loads("POU_D_T", 4, length, force)
    assert tg.components == ("N", "VY", "VZ", "MT", "MFY", "MFZ", "BX")
    np.testing.assert_allclose(tg.values[..., :6], t.values, rtol=1e-9, atol=1e-6)
    assert tg.values[0, 0, 0, 5] == pytest.approx(1.0e3 * length, rel=1e-9)
    torque = 1.0e3
    k = np.sqrt(G * SECTION["JX"] / (E * SECTION["JG"]))
    vlasov = torque * np.tanh(k * length) / k
    errors = []
    for n in (4, 8, 16):
        field = _efge_of_tip_loads("POU_D_TG", n, length, {"MX": torque})
        np.testing.assert_allclose(field.values[0, :, :, 3], torque, rtol=1e-9)
        errors.append(abs(abs(field.values[0, 0, 0, 6]) / vlasov - 1.0))
        assert abs(field.values[0, -1, 1, 6]) < 1e-3 * vlasov
    assert errors[0] > errors[1] > errors[2] and errors[2] < 1e-4
