"""Beam and bar elements: sections, element matrices, frames, and small
assembled beams checked against analytic frequencies."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg

from asterlite.fem import beam
from asterlite.fem.frames import rotation_from_angles
from asterlite.fem.sections import (
    SectionError,
    cara_dict,
    circle_shear_coefficient,
    rectangle_shear_coefficient,
    section_properties,
)

E, NU, RHO = 2.0e11, 0.3, 7800.0
G = E / (2 * (1 + NU))

# beta_n L of the first five bending modes
CANTILEVER = np.array([1.875104069, 4.694091133, 7.854757438, 10.99554073, 14.13716839])
CLAMPED = np.array([4.730040745, 7.853204624, 10.99560784, 14.13716549, 17.27875966])


# -- a tiny assembler for straight lines of beams ------------------------------------


def line_nodes(length, n_el, direction=(1.0, 0.0, 0.0), origin=(0.0, 0.0, 0.0)):
    d = np.asarray(direction, float) / np.linalg.norm(direction)
    return np.asarray(origin, float) + np.linspace(0.0, length, n_el + 1)[:, None] * d


def assemble(coords, modelisation, section, angles=None, lumped=False):
    """Global K and M (dense) of a chain of SEG2 elements node i -> i+1."""
    x1, x2 = coords[:-1], coords[1:]
    per = len(beam.COMPONENTS[modelisation])
    n = len(coords) * per
    mats = {}
    for kind in ("K", "M"):
        blocks = beam.global_matrices(
            modelisation, kind, x1, x2, section, E, NU, RHO, angles=angles, lumped=lumped
        )
        full = np.zeros((n, n))
        for e, block in enumerate(blocks):
            s = slice(e * per, (e + 2) * per)
            full[s, s] += block
        mats[kind] = full
    return mats["K"], mats["M"]


def dof(node, component, modelisation="POU_D_E"):
    comps = beam.COMPONENTS[modelisation]
    return node * len(comps) + comps.index(component)


def frequencies(k, m, fixed=(), keep=None, count=5):
    """Lowest natural frequencies (Hz) with ``fixed`` DOFs removed, or on ``keep``."""
    idx = np.arange(len(k)) if keep is None else np.asarray(keep)
    idx = np.setdiff1d(idx, fixed)
    w2 = scipy.linalg.eigh(k[np.ix_(idx, idx)], m[np.ix_(idx, idx)], eigvals_only=True)
    return np.sqrt(np.abs(w2[:count])) / (2 * np.pi)


def plane_dofs(n_nodes, components, modelisation="POU_D_E"):
    return [dof(i, c, modelisation) for i in range(n_nodes) for c in components]


def euler_frequencies(beta_l, length, section):
    return beta_l**2 * np.sqrt(E * section["IZ"] / (RHO * section["A"] * length**4)) / (2 * np.pi)


# -- sections -------------------------------------------------------------------------


def test_circle_properties():
    p = section_properties("CERCLE", {"R": 0.1, "EP": 0.02})
    re, ri = 0.1, 0.08
    assert p["A"] == pytest.approx(np.pi * (re**2 - ri**2))
    assert p["IY"] == pytest.approx(np.pi * (re**4 - ri**4) / 4)
    assert p["IZ"] == p["IY"]
    assert p["JX"] == pytest.approx(2 * p["IY"])
    assert p["AY"] == pytest.approx(1.95983)  # table value at Ri/Re = 0.8
    solid = section_properties("CERCLE", cara_dict("R", 0.05))
    assert solid["AY"] == pytest.approx(1.16667)
    assert solid["A"] == pytest.approx(np.pi * 0.05**2)


def test_rectangle_properties():
    p = section_properties("RECTANGLE", cara_dict(("HY", "HZ"), (0.02, 0.04)))
    assert p["A"] == pytest.approx(0.02 * 0.04)
    assert p["IY"] == pytest.approx(0.02 * 0.04**3 / 12)  # about y: bending along z
    assert p["IZ"] == pytest.approx(0.04 * 0.02**3 / 12)
    assert p["AY"] == p["AZ"] == 1.2
    # Saint-Venant constant of a 2:1 rectangle: 0.229 h b^3 (Roark)
    assert p["JX"] == pytest.approx(0.2287 * 0.04 * 0.02**3, rel=2e-3)
    square = section_properties("RECTANGLE", {"H": 0.02})
    assert square["JX"] == pytest.approx(0.1406 * 0.02**4, rel=2e-3)


def test_rectangular_tube_properties():
    p = section_properties("RECTANGLE", {"HY": 0.1, "HZ": 0.2, "EPY": 0.01, "EPZ": 0.02})
    assert p["A"] == pytest.approx(0.1 * 0.2 - 0.08 * 0.16)
    assert p["AY"] == pytest.approx(rectangle_shear_coefficient(0.8, 0.8))
    assert p["AY"] == pytest.approx(2.25238)
    # Bredt: 4 Am^2 / sum(ds/t) with the mean-line rectangle
    am = (0.1 - 0.01) * (0.2 - 0.02)
    bredt = 4 * am**2 / (2 * (0.1 - 0.01) / 0.02 + 2 * (0.2 - 0.02) / 0.01)
    assert p["JX"] == pytest.approx(bredt)


def test_shear_coefficient_tables():
    assert circle_shear_coefficient(0.0) == pytest.approx(1.16667)
    assert circle_shear_coefficient(1.0) == 2.0
    assert circle_shear_coefficient(0.25) == pytest.approx((1.28947 + 1.41882) / 2)
    assert rectangle_shear_coefficient(0.0, 0.9) == 1.2
    assert rectangle_shear_coefficient(0.95, 0.95) == pytest.approx(2.37116)
    with pytest.raises(SectionError, match="too thin"):
        rectangle_shear_coefficient(0.97, 0.5)


def test_general_section_defaults_and_errors():
    p = section_properties(
        "GENERALE", cara_dict(("A", "IY", "IZ", "JX", "AY", "AZ"), (1e-3, 2e-7, 3e-7, 4e-7, 2, 2))
    )
    assert p["RY"] == p["RT"] == 1.0 and p["EY"] == 0.0 and p["AY"] == 2
    no_shear = section_properties("GENERALE", {"A": 1e-3, "IY": 1, "IZ": 1, "JX": 1})
    assert "AY" not in no_shear
    with pytest.raises(beam.BeamError, match="AY and AZ"):
        beam.local_matrices("POU_D_T", "K", 1.0, no_shear, E, NU)
    beam.local_matrices("POU_D_E", "K", 1.0, no_shear, E, NU)  # Euler needs none
    with pytest.raises(SectionError, match="needs CARA 'JX'"):
        section_properties("GENERALE", {"A": 1.0, "IY": 1.0, "IZ": 1.0})
    with pytest.raises(SectionError, match="needs CARA 'R'"):
        section_properties("CERCLE", {"EP": 0.01})
    with pytest.raises(SectionError, match="EP must be"):
        section_properties("CERCLE", {"R": 0.01, "EP": 0.02})
    with pytest.raises(SectionError, match="does not accept CARA HY"):
        section_properties("CERCLE", {"R": 0.01, "HY": 0.02})
    with pytest.raises(SectionError, match="H excludes HY"):
        section_properties("RECTANGLE", {"H": 0.01, "HY": 0.02})
    with pytest.raises(SectionError, match="VARI_SECT"):
        section_properties("CERCLE", {"R": 0.01}, vari_sect="HOMOTHETIQUE")
    with pytest.raises(SectionError, match="VALE"):
        cara_dict(("R", "EP"), (0.1,))


# -- element matrices ---------------------------------------------------------------


@pytest.mark.parametrize("modelisation", ["POU_D_E", "POU_D_T"])
def test_element_matrices_rigid_modes_and_mass(modelisation):
    sec = section_properties("RECTANGLE", {"HY": 0.03, "HZ": 0.05})
    k = beam.local_matrices(modelisation, "K", 0.7, sec, E, NU)[0]
    m = beam.local_matrices(modelisation, "M", 0.7, sec, E, NU, RHO)[0]
    assert np.allclose(k, k.T) and np.allclose(m, m.T)
    eig = np.linalg.eigvalsh(k)
    assert np.sum(np.abs(eig) < 1e-9 * eig.max()) == 6  # 6 rigid body modes
    assert np.all(np.linalg.eigvalsh(m) > 0)
    # a rigid translation carries the element mass in every direction
    for c in range(3):
        u = np.zeros(12)
        u[[c, c + 6]] = 1.0
        assert u @ m @ u == pytest.approx(RHO * sec["A"] * 0.7)


def test_euler_mass_has_no_rotary_inertia_but_torsion():
    sec = section_properties("CERCLE", {"R": 0.05})
    m = beam.local_matrices("POU_D_E", "M", 1.0, sec, E, NU, RHO)[0]
    mass = RHO * sec["A"]
    assert m[5, 5] == pytest.approx(mass / 105)  # rho A L^3 / 105, no rho I term
    assert m[3, 3] == pytest.approx(RHO * (sec["IY"] + sec["IZ"]) / 3)
    t = beam.local_matrices("POU_D_T", "M", 1.0, sec, E, NU, RHO)[0]
    assert t[5, 5] > m[5, 5]


def test_lumped_mass_is_code_aster_diagonal():
    sec = section_properties("CERCLE", {"R": 0.05})
    m = beam.local_matrices("POU_D_T", "M", 2.0, sec, E, NU, RHO, lumped=True)[0]
    assert np.count_nonzero(m - np.diag(np.diag(m))) == 0
    mass = RHO * sec["A"] * 2.0
    assert np.diag(m)[[0, 1, 2, 6, 7, 8]] == pytest.approx([mass / 2] * 6)
    assert m[3, 3] == pytest.approx(RHO * 2.0 * 2 * sec["IY"] / 2)
    assert m[4, 4] == pytest.approx(mass * 4 / 105 + 2 * RHO * sec["IY"] * 2 / 15)


def test_shear_centre_offset_is_a_change_of_reference_point():
    sec = section_properties("RECTANGLE", {"HY": 0.03, "HZ": 0.05})
    off = dict(sec, EY=0.01, EZ=-0.02)
    k0 = beam.local_matrices("POU_D_T", "K", 1.0, sec, E, NU)[0]
    k1 = beam.local_matrices("POU_D_T", "K", 1.0, off, E, NU)[0]
    assert np.allclose(k1, k1.T)
    # code_aster's EY, EZ place the centroid (the nodes) relative to the shear
    # centre: twisting about the shear centre strains torsion only, the
    # centroid moving by (v, w) = (-EZ, EY) rx
    theta = 1e-3
    u = np.zeros(12)
    u[[9, 7, 8]] = [theta, 0.02 * theta, 0.01 * theta]
    assert u @ k1 @ u == pytest.approx(G * sec["JX"] * theta**2, rel=1e-9)
    assert u @ k0 @ u > G * sec["JX"] * theta**2 * (1 + 1e-6)  # without offset: bending too
    m1 = beam.local_matrices("POU_D_T", "M", 1.0, off, E, NU, RHO)[0]
    assert np.allclose(m1, m1.T) and np.all(np.linalg.eigvalsh(m1) > 0)
    assert m1[3, 3] > beam.local_matrices("POU_D_T", "M", 1.0, sec, E, NU, RHO)[0][3, 3]


def test_bar_matrices():
    sec = section_properties("CERCLE", {"R": 0.01})
    k = beam.local_matrices("BARRE", "K", 2.0, sec, E)[0]
    assert k[0, 0] == pytest.approx(E * sec["A"] / 2) and k[0, 3] == -k[0, 0]
    assert np.count_nonzero(k) == 4
    m = beam.local_matrices("BARRE", "M", 2.0, sec, E, density=RHO)[0]
    assert m.sum() == pytest.approx(3 * RHO * sec["A"] * 2)
    m2 = beam.local_matrices("2D_BARRE", "M", 2.0, sec, E, density=RHO, lumped=True)[0]
    assert np.allclose(m2, np.eye(4) * RHO * sec["A"])
    # an inclined plane bar: stiff along its axis only
    kg = beam.global_matrices("2D_BARRE", "K", [[0, 0]], [[1, 1]], sec, E)[0]
    axis = np.array([1, 1, 0, 0]) / np.sqrt(2)
    normal = np.array([1, -1, 0, 0]) / np.sqrt(2)
    assert axis @ kg @ axis == pytest.approx(E * sec["A"] / np.sqrt(2))
    assert normal @ kg @ normal == pytest.approx(0.0, abs=1e-6)


# -- frames -------------------------------------------------------------------------


def test_default_frames_follow_code_aster():
    x1 = np.zeros((3, 3))
    x2 = np.array([[2.0, 0, 0], [0, 0, 3.0], [0, 1.0, 1.0]])
    p = rotation_from_angles(beam.seg2_angles(x1, x2))
    assert np.allclose(p[:, 0], x2 / np.linalg.norm(x2, axis=1)[:, None])
    assert np.allclose(p[0], np.eye(3))  # along X: the global frame
    assert np.allclose(p[1, 1], [0, 1, 0])  # vertical: local y is global Y
    assert np.allclose(p[2, 2, 2], np.cos(np.pi / 4))  # gamma = 0 keeps z "up"
    with pytest.raises(beam.BeamError, match="ANGL_NAUT"):
        beam.seg2_angles(x1[:1], x2[:1], "ANGL_NAUT", (0, 0, 0))


def test_orientation_vect_y_and_vect_z_match_angl_vril():
    x1, x2 = np.zeros((1, 3)), np.array([[1.0, 2.0, 0.5]])
    for gamma in (0.0, 30.0, 90.0, -120.0):
        p = rotation_from_angles(beam.seg2_angles(x1, x2, "ANGL_VRIL", gamma))[0]
        py = rotation_from_angles(beam.seg2_angles(x1, x2, "VECT_Y", p[1] + 0.7 * p[0]))[0]
        pz = rotation_from_angles(beam.seg2_angles(x1, x2, "VECT_Z", 3 * p[2] - p[0]))[0]
        assert np.allclose(py, p) and np.allclose(pz, p)


def test_angl_vril_turns_the_section_axes():
    """Horizontal cantilever along X with HY != HZ: a 90 degree twist swaps
    which inertia resists a tip load along global Y."""
    sec = section_properties("RECTANGLE", {"HY": 0.02, "HZ": 0.05})
    coords = line_nodes(1.0, 4)
    n = len(coords)
    tip = dof(n - 1, "DY")
    for gamma, inertia in ((0.0, sec["IZ"]), (90.0, sec["IY"]), (180.0, sec["IZ"])):
        angles = beam.seg2_angles(coords[:-1], coords[1:], "ANGL_VRIL", gamma)
        k, _ = assemble(coords, "POU_D_E", sec, angles=angles)
        free = np.arange(6, 6 * n)
        f = np.zeros(len(free))
        f[tip - 6] = 1.0
        u = np.linalg.solve(k[np.ix_(free, free)], f)
        assert u[tip - 6] == pytest.approx(1.0 / (3 * E * inertia), rel=1e-10)


def test_rotated_beam_has_the_same_eigenvalues():
    rng = np.random.default_rng(7)
    sec = section_properties("RECTANGLE", {"HY": 0.02, "HZ": 0.035})
    coords = line_nodes(1.3, 6)
    k0, m0 = assemble(coords, "POU_D_T", sec)
    ref = scipy.linalg.eigh(k0, m0, eigvals_only=True)[6:]
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    q *= np.sign(np.linalg.det(q))
    moved = coords @ q.T + rng.normal(size=3)
    # keep the section axes attached to the beam: VECT_Y follows the rotation
    angles = beam.seg2_angles(moved[:-1], moved[1:], "VECT_Y", q @ [0.0, 1.0, 0.0])
    k1, m1 = assemble(moved, "POU_D_T", sec, angles=angles)
    got = scipy.linalg.eigh(k1, m1, eigvals_only=True)[6:]
    assert got == pytest.approx(ref, rel=1e-8)
    # a circular section does not care about the twist
    circ = section_properties("CERCLE", {"R": 0.02, "EP": 0.003})
    ref = scipy.linalg.eigh(*assemble(coords, "POU_D_E", circ), eigvals_only=True)[6:]
    got = scipy.linalg.eigh(*assemble(moved, "POU_D_E", circ), eigvals_only=True)[6:]
    assert got == pytest.approx(ref, rel=1e-8)


# -- assembled beams against analytic frequencies --------------------------------------


@pytest.mark.parametrize("support", ["cantilever", "clamped"])
def test_euler_bending_frequencies(support):
    sec = section_properties("CERCLE", {"R": 0.02})
    length = 2.0
    beta_l = CANTILEVER if support == "cantilever" else CLAMPED
    exact = euler_frequencies(beta_l, length, sec)
    errors = []
    for n_el in (5, 10, 40):
        coords = line_nodes(length, n_el)
        k, m = assemble(coords, "POU_D_E", sec)
        keep = plane_dofs(n_el + 1, ("DY", "DRZ"))
        fixed = [dof(0, "DY"), dof(0, "DRZ")]
        if support == "clamped":
            fixed += [dof(n_el, "DY"), dof(n_el, "DRZ")]
        got = frequencies(k, m, fixed, keep)
        errors.append(np.max(np.abs(got / exact - 1)))
    assert errors[-1] < 1e-3
    assert errors[0] > errors[1] > errors[2]  # converges with refinement
    assert np.all(np.diff(errors) < 0) and errors[1] / errors[2] > 10


def test_both_bending_planes_and_full_model():
    """A clamped rectangular cantilever in the full 6-DOF model: the spectrum
    holds both bending families, torsion and traction."""
    sec = section_properties("RECTANGLE", {"HY": 0.02, "HZ": 0.03})
    length, n_el = 1.5, 40
    k, m = assemble(line_nodes(length, n_el), "POU_D_E", sec)
    fixed = [dof(0, c) for c in beam.BEAM_COMPONENTS]
    got = frequencies(k, m, fixed, count=8)
    scale = np.sqrt(E / (RHO * sec["A"] * length**4)) / (2 * np.pi)
    bend_y = CANTILEVER[:3] ** 2 * scale * np.sqrt(sec["IZ"])
    bend_z = CANTILEVER[:3] ** 2 * scale * np.sqrt(sec["IY"])
    expected = np.sort(np.concatenate([bend_y, bend_z]))[:5]
    assert got[:5] == pytest.approx(expected, rel=1e-3)


def test_axial_and_torsional_frequencies():
    sec = section_properties("CERCLE", {"R": 0.03, "EP": 0.005})
    length, n_el = 3.0, 60
    k, m = assemble(line_nodes(length, n_el), "POU_D_T", sec)
    n = np.arange(1, 4)
    # fixed-free bar: f = (2n - 1) c / (4 L)
    keep = plane_dofs(n_el + 1, ("DX",))
    axial = frequencies(k, m, [dof(0, "DX")], keep, count=3)
    c_axial = np.sqrt(E / RHO)
    assert axial == pytest.approx((2 * n - 1) * c_axial / (4 * length), rel=1e-3)
    # torsion: stiffness G JX, inertia rho (IY + IZ); equal for a circle
    keep = plane_dofs(n_el + 1, ("DRX",))
    torsion = frequencies(k, m, [dof(0, "DRX")], keep, count=3)
    c_torsion = np.sqrt(G * sec["JX"] / (RHO * (sec["IY"] + sec["IZ"])))
    assert torsion == pytest.approx((2 * n - 1) * c_torsion / (4 * length), rel=1e-3)


def timoshenko_pinned_frequencies(modes, length, sec):
    """Exact Timoshenko frequencies (Hz) of a simply supported beam (xOy plane),
    sorted: both spectra of each mode and the pure shear mode (v = 0,
    uniform rotation, w^2 = kGA / rho I)."""
    a, i = sec["A"], sec["IZ"]
    kga = G * a / sec["AY"]
    out = [np.sqrt(kga / (RHO * i)) / (2 * np.pi)]
    for n in modes:
        q = n * np.pi / length
        # rho I rho A / kGA w^4 - (rho A + rho I q^2 + rho A E I q^2 / kGA) w^2 + E I q^4 = 0
        c2 = RHO * i * RHO * a / kga
        c1 = -(RHO * a + RHO * i * q**2 + RHO * a * E * i * q**2 / kga)
        c0 = E * i * q**4
        for sign in (-1.0, 1.0):
            w2 = (-c1 + sign * np.sqrt(c1 * c1 - 4 * c2 * c0)) / (2 * c2)
            out.append(np.sqrt(w2) / (2 * np.pi))
    return np.sort(out)


def test_timoshenko_short_beam():
    """Stocky pinned-pinned tube (L / R = 5): POU_D_T matches Timoshenko
    theory; Euler-Bernoulli overestimates."""
    sec = section_properties("CERCLE", {"R": 0.1, "EP": 0.02})
    length, n_el = 0.5, 40
    coords = line_nodes(length, n_el)
    keep = plane_dofs(n_el + 1, ("DY", "DRZ"))
    fixed = [dof(0, "DY"), dof(n_el, "DY")]
    exact = timoshenko_pinned_frequencies(range(1, 5), length, sec)
    k, m = assemble(coords, "POU_D_T", sec)
    timo = frequencies(k, m, fixed, keep, count=5)
    assert timo == pytest.approx(exact[:5], rel=2e-3)
    k, m = assemble(coords, "POU_D_E", sec)
    euler = frequencies(k, m, fixed, keep, count=3)
    bernoulli = (
        (np.arange(1, 4) * np.pi) ** 2
        / (2 * np.pi)
        * np.sqrt(E * sec["IZ"] / (RHO * sec["A"] * length**4))
    )
    assert euler == pytest.approx(bernoulli, rel=1e-3)
    first = timoshenko_pinned_frequencies([1, 2, 3], length, sec)[[0, 1, 3]]
    assert first == pytest.approx(timo[[0, 1, 3]], rel=2e-3)  # first spectrum
    assert np.all(first < 0.95 * euler)  # shear and rotary inertia soften


def test_timoshenko_tends_to_euler_for_slender_beams():
    sec = section_properties("CERCLE", {"R": 0.01})
    length, n_el = 5.0, 20
    coords = line_nodes(length, n_el)
    keep = plane_dofs(n_el + 1, ("DY", "DRZ"))
    fixed = [dof(0, "DY"), dof(0, "DRZ")]
    timo = frequencies(*assemble(coords, "POU_D_T", sec), fixed, keep, count=3)
    euler = frequencies(*assemble(coords, "POU_D_E", sec), fixed, keep, count=3)
    assert timo == pytest.approx(euler, rel=2e-4)
    assert np.all(timo < euler)


def test_lumped_mass_converges():
    sec = section_properties("CERCLE", {"R": 0.02})
    length, n_el = 2.0, 80
    coords = line_nodes(length, n_el)
    keep = plane_dofs(n_el + 1, ("DY", "DRZ"))
    fixed = [dof(0, "DY"), dof(0, "DRZ")]
    got = frequencies(*assemble(coords, "POU_D_E", sec, lumped=True), fixed, keep, count=3)
    assert got == pytest.approx(euler_frequencies(CANTILEVER[:3], length, sec), rel=2e-3)


def test_zero_length_and_unknown_inputs():
    sec = section_properties("CERCLE", {"R": 0.02})
    with pytest.raises(beam.BeamError, match="zero length"):
        beam.global_matrices("POU_D_E", "K", [[0, 0, 0]], [[0, 0, 0]], sec, E, NU)
    with pytest.raises(beam.BeamError, match="not a straight beam"):
        beam.local_matrices("DIS_T", "K", 1.0, sec, E)


def test_channel_with_shear_centre_offset_matches_code_aster():
    """sdll400a of code_aster 17: a 7.5 m POU_D_E channel (EZ = -0.2215 m)
    in 15 elements, its lateral displacement held at the shear centre at
    both ends (DY - 0.2215 DRX = 0), DZ and DRY held: the coupled
    bending-torsion frequencies of code_aster (VALE_CALC), to 1e-9."""
    young, poisson, density, n, length = 2.07e11, 0.3, 7850.0, 15, 7.5
    section = {"A": 6.117e-3, "IY": 5.022e-5, "IZ": 5.022e-5, "JX": 1.28e-7, "EY": 0.0}
    section["EZ"] = -0.2215
    x = np.linspace(0.0, length, n + 1)
    ends = np.zeros((n, 3))
    x1, x2 = ends.copy(), ends.copy()
    x1[:, 0], x2[:, 0] = x[:-1], x[1:]
    size = 6 * (n + 1)
    k, m = np.zeros((size, size)), np.zeros((size, size))
    for matrix, name in ((k, "K"), (m, "M")):
        blocks = beam.global_matrices("POU_D_E", name, x1, x2, section, young, poisson, density)
        for e, block in enumerate(blocks):
            rows = np.arange(6 * e, 6 * e + 12)
            matrix[np.ix_(rows, rows)] += block
    relations = []
    for node in range(n + 1):
        for dof in (2, 4):  # DZ, DRY
            relations.append(np.eye(size)[6 * node + dof])
    for node in (0, n):
        relations.append(np.eye(size)[6 * node])  # DX
        support = np.zeros(size)
        support[6 * node + 1], support[6 * node + 3] = 1.0, -0.2215  # DY - 0.2215 DRX
        relations.append(support)
    basis = scipy.linalg.null_space(np.array(relations))
    omega2 = scipy.linalg.eigh(basis.T @ k @ basis, basis.T @ m @ basis, eigvals_only=True)
    frequencies = np.sqrt(np.abs(omega2[1:6])) / (2 * np.pi)
    code_aster = [3.7966934137, 7.451391005, 11.510857283, 15.502793726, 19.806054061]
    np.testing.assert_allclose(frequencies, code_aster, rtol=1e-9)
