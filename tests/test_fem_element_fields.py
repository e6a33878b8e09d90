"""Beam internal forces of dynamic results: CALC_CHAMP adds the element
inertia M_e a_e to K_e u_e when the dyna_trans carries ACCE (code_aster's beam
elements do), static and modal results keep K_e u_e."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.transient import DynaTrans
from tests.test_fem_structures import AREA, RHO, _static, beam_model, line_mesh
from tests.test_fem_support import FakeSession, run

LENGTH, N_EL = 2.0, 8
ACCEL = {"DX": 3.0, "DY": -5.0}


def _uniform(numbering, per_component: dict[str, float]) -> np.ndarray:
    """A nodal vector equal to ``value`` on every DOF of each component."""
    out = np.zeros(numbering.n_dofs)
    for k, (_, component) in enumerate(numbering.dofs):
        out[k] = per_component.get(component, 0.0)
    return out


def _accelerated_cantilever(modelisation="POU_D_E"):
    """A cantilever whose clamp accelerates uniformly (ACCEL), quasi-static:
    the relative displacement is the static response to the inertia load
    q = -rho A a, and the result holds that DEPL with the uniform ACCE."""
    session = FakeSession()
    model, field, cara = beam_model(session, line_mesh(N_EL, LENGTH), modelisation)
    load = {f"F{c[-1]}": -RHO * AREA * a for c, a in ACCEL.items()}
    numbering, u, _ = _static(
        session,
        model,
        field,
        cara,
        [{"GROUP_NO": ("A",), "LIAISON": "ENCASTRE"}],
        [{"FORCE_POUTRE": {"TOUT": "OUI", **load}}],
    )
    acce = _uniform(numbering, ACCEL)
    result = DynaTrans(
        numbering,
        np.array([0.0]),
        np.array([1]),
        {"DEPL": u[None, :], "VITE": 0 * u[None, :], "ACCE": acce[None, :]},
    )
    return session, model, result


@pytest.mark.parametrize("modelisation", ["POU_D_E", "POU_D_T"])
def test_inertia_of_a_uniformly_accelerated_beam_is_its_internal_force(modelisation):
    session, model, result = _accelerated_cantilever(modelisation)
    out = run(session, "CALC_CHAMP", RESULTAT=result, CONTRAINTE=("EFGE_ELNO", "SIPO_ELNO"))
    efge = out.element_fields["EFGE_ELNO"].values[0]  # (n_cells, 2, 6)
    x = model.mesh.coords[np.array(model.mesh.cell_nodes)][..., 0]
    mass_per_length = RHO * AREA
    # the free length beyond x carries the inertia: N = -m a_x (L - x), VY likewise
    np.testing.assert_allclose(
        efge[..., 0], -mass_per_length * ACCEL["DX"] * (LENGTH - x), atol=1e-8
    )
    np.testing.assert_allclose(
        efge[..., 1], -mass_per_length * ACCEL["DY"] * (LENGTH - x), atol=1e-8
    )
    if modelisation == "POU_D_E":  # consistent mass = consistent load: exact moments
        np.testing.assert_allclose(
            efge[..., 5], -mass_per_length * ACCEL["DY"] * (LENGTH - x) ** 2 / 2, atol=1e-8
        )
    # the free end carries no force, the clamp the whole inertia
    assert efge[-1, 1, 1] == pytest.approx(0.0, abs=1e-8)
    assert efge[0, 0, 1] == pytest.approx(-mass_per_length * LENGTH * ACCEL["DY"], rel=1e-9)
    sipo = out.element_fields["SIPO_ELNO"].values[0]
    np.testing.assert_allclose(sipo[..., 0], efge[..., 0] / AREA, rtol=1e-12)


def test_rigid_acceleration_alone_gives_the_element_inertia():
    session, model, result = _accelerated_cantilever()
    result.fields["DEPL"] = np.zeros_like(result.fields["DEPL"])
    efge = run(session, "CALC_CHAMP", RESULTAT=result, CONTRAINTE="EFGE_ELNO")
    values = efge.element_fields["EFGE_ELNO"].values[0]
    element_mass = RHO * AREA * LENGTH / N_EL
    # each element: half its inertia at each end, node 1 with the section sign
    np.testing.assert_allclose(values[:, 0, 0], -element_mass * ACCEL["DX"] / 2, rtol=1e-12)
    np.testing.assert_allclose(values[:, 1, 0], element_mass * ACCEL["DX"] / 2, rtol=1e-12)
    np.testing.assert_allclose(
        values[:, 1, 1] - values[:, 0, 1], element_mass * ACCEL["DY"], rtol=1e-12
    )


def test_results_without_acceleration_keep_stiffness_forces():
    session, model, result = _accelerated_cantilever()
    options = ("EFGE_ELNO", "SIEF_ELNO", "EFGE_ELGA", "SIEF_ELGA")
    with_acce = run(session, "CALC_CHAMP", RESULTAT=result, CONTRAINTE=options)
    del result.fields["ACCE"]
    without = run(session, "CALC_CHAMP", RESULTAT=result, CONTRAINTE=options)
    inertia = with_acce.element_fields["EFGE_ELNO"].values
    stiffness = without.element_fields["EFGE_ELNO"].values
    assert np.abs(inertia - stiffness).max() > 1.0
    # code_aster's SIEF_ELGA (and EFGE_ELGA, SIEF_ELNO from it) take DEPL only
    for name in options[1:]:
        np.testing.assert_array_equal(
            with_acce.element_fields[name].values, without.element_fields[name].values
        )
    np.testing.assert_array_equal(with_acce.element_fields["SIEF_ELNO"].values, stiffness)
    # K u alone: the element ends balance (no load inside the elements)
    np.testing.assert_allclose(stiffness[0, :, 0, :3], stiffness[0, :, 1, :3], atol=1e-8)


def test_cham_util_on_chosen_instants_only():
    session, _, result = _accelerated_cantilever()
    two = DynaTrans(
        result.numbering,
        np.array([0.0, 1.0]),
        np.array([1, 2]),
        {name: np.vstack([0 * v, v]) for name, v in result.fields.items()},
    )
    sipo = run(session, "CALC_CHAMP", RESULTAT=two, CONTRAINTE="SIPO_ELNO")
    double = run(session, "FORMULE", VALE="2*SN", NOM_PARA="SN")
    out = run(
        session,
        "CALC_CHAMP",
        RESULTAT=sipo,
        INST=1.0,
        CHAM_UTIL={"NOM_CHAM": "SIPO_ELNO", "FORMULE": double, "NUME_CHAM_RESU": 1},
    )
    ut = out.element_fields["UT01_ELNO"].values
    sn = out.element_fields["SIPO_ELNO"].values[..., 0]
    np.testing.assert_allclose(ut[1, ..., 0], 2 * sn[1], rtol=1e-12)
    assert np.isnan(ut[0]).all()  # not computed at the other instant
