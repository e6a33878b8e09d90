"""POST_NEWMARK RESULTAT_PESANTEUR (asterlite.post.newmark_safety): the slip
circle's safety factors in a uniform stress state against closed forms."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.assembly import DofNumbering, ElementField, NodalField
from asterlite.concepts.static_result import EvolElas
from asterlite.concepts.transient import DynaTrans
from asterlite.fem.assemble import build_numbering_dofs


def _case(static_stress, dynamic_scale):
    from tests.test_fem_plane import grid_mesh, plane_model

    # the structure [0, 12] x [0, 10]; the circle about (10, 10) of radius 5
    # (refine 0: 8 segments) has its vertices at 180, 225 and 270 degrees in it
    mesh = grid_mesh("QUAD4", n=(12, 10), size=(12.0, 10.0))
    mesh.cell_groups["TOUT"] = np.arange(mesh.n_cells)
    model, materials = plane_model(mesh, "D_PLAN")
    numbering = DofNumbering(mesh=mesh, dofs=build_numbering_dofs(model.node_components()))
    cells = np.arange(mesh.n_cells)

    def sief(scales):
        values = np.broadcast_to(
            np.asarray(scales)[:, None, None, None] * np.asarray(static_stress),
            (len(scales), mesh.n_cells, 4, 4),
        ).copy()
        return {
            "SIEF_ELGA": ElementField("SIEF_ELGA", cells, ("SIXX", "SIYY", "SIZZ", "SIXY"), values)
        }

    times = np.linspace(0.0, 1.0, 5)
    depl = np.zeros((times.size, numbering.n_dofs))
    dynamic = DynaTrans(numbering=numbering, times=times, order=np.arange(5),
                        fields={"DEPL": depl}, model=model, materials=materials)  # fmt: skip
    dynamic.element_fields = sief(dynamic_scale * times)
    static = EvolElas(numbering=numbering, times=np.array([0.0]), order=np.array([1]),
                      fields={"DEPL": depl[:1]}, model=model, materials=materials)  # fmt: skip
    static.element_fields = sief([1.0])

    def neut(component, value):
        num = DofNumbering(mesh=mesh, dofs=[(n, component) for n in range(mesh.n_nodes)])
        return NodalField(numbering=num, values=np.full(mesh.n_nodes, value))

    return dynamic, static, neut("X1", 30.0), neut("X2", 0.0)


def _expected(stress, dynamic_scale, times):
    sxx, syy, _, sxy = stress
    mids = np.radians([202.5, 247.5])
    n = np.column_stack([np.cos(mids), np.sin(mids)])
    t = np.column_stack([-np.sin(mids), np.cos(mids)])
    sig_n = sxx * n[:, 0] ** 2 + syy * n[:, 1] ** 2 + 2 * sxy * n[:, 0] * n[:, 1]
    sig_tn = (
        sxx * t[:, 0] * n[:, 0]
        + syy * t[:, 1] * n[:, 1]
        + sxy * (t[:, 0] * n[:, 1] + t[:, 1] * n[:, 0])
    )
    tan = np.tan(np.radians(30.0))
    scale = dynamic_scale * times
    return tan * sig_n.sum() * (1 - scale) / (sig_tn.sum() * (1 - scale))


def test_safety_factor_of_a_partial_circle_in_uniform_stress():
    from tests.test_fem_support import FakeSession, run

    stress = (-100.0, -200.0, 0.0, 0.0)
    dynamic, static, phi, cohesion = _case(stress, 0.5)
    table = run(FakeSession(), "POST_NEWMARK", RESULTAT=dynamic, RESULTAT_PESANTEUR=static,
                CHAM_PHI=phi, CHAM_COHESION=cohesion, RAYON=5.0, CENTRE_X=10.0, CENTRE_Y=10.0,
                RAFF_CERCLE=0, GROUP_MA_CALC="TOUT")  # fmt: skip
    columns = table.EXTR_TABLE().values()
    expected = _expected(stress, 0.5, dynamic.times)
    # tan(30) x 300 / 70.7: above 1.2 at every instant, so KY = 1.1 max(acc) / g = 0 here
    assert expected[0] == pytest.approx(np.tan(np.radians(30.0)) * 300.0 / (50.0 * np.sqrt(2.0)))
    np.testing.assert_allclose(columns["FS"], expected, rtol=1e-10)
    assert columns["KY"] == pytest.approx([0.0] * 5)
    assert columns["DEPL"] == pytest.approx([0.0] * 5)


def test_collocation_and_slip_mesh_refused_by_name():
    from tests.test_fem_support import FakeSession, run

    dynamic, static, phi, cohesion = _case((-100.0, -200.0, 0.0, 0.0), 0.5)
    with pytest.raises(Exception, match="COLLOCATION"):
        run(FakeSession(), "POST_NEWMARK", RESULTAT=dynamic, RESULTAT_PESANTEUR=static,
            CHAM_PHI=phi, CHAM_COHESION=cohesion, RAYON=5.0, CENTRE_X=10.0, CENTRE_Y=10.0,
            GROUP_MA_CALC="TOUT", METHODE="COLLOCATION")  # fmt: skip
