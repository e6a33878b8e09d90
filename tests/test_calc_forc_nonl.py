"""CALC_FORC_NONL (asterlite.fem.discrete_contact): the FONL_NOEU forces of a
DIS_CHOC spring in closed form, closing and opening, along x and along y;
DYNA_VIBRA PHYS EXCIT_RESU reading a force history as code_aster's dlnew0."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.mesh import Mesh
from asterlite.concepts.transient import DynaTrans
from asterlite.errors import CommandError
from tests.test_fem_support import FakeSession, run

K, K2, K3, KN, GAP = 1.0e4, 2.0e4, 3.0e4, 1.0e7, 1.0e-3


def spring(direction, coulomb=None):
    session = FakeSession()
    d = np.asarray(direction, float)
    mesh = Mesh(
        coords=np.array([np.zeros(3), 2 * GAP * d]),
        node_names=["N1", "N2"],
        cell_names=["S1"],
        cell_types=["SEG2"],
        cell_nodes=[(0, 1)],
        node_groups={},
        cell_groups={"RES": np.array([0])},
    )
    affe = {"TOUT": "OUI", "PHENOMENE": "MECANIQUE", "MODELISATION": "DIS_T"}
    model = run(session, "AFFE_MODELE", MAILLAGE=mesh, AFFE=affe)
    cara = run(session, "AFFE_CARA_ELEM", MODELE=model,
               DISCRET={"GROUP_MA": "RES", "REPERE": "LOCAL", "CARA": "K_T_D_L",
                        "VALE": (K, K2, K3)})  # fmt: skip
    law = {"RIGI_NOR": KN, "DIST_1": GAP, "DIST_2": GAP}
    if coulomb is not None:
        law["COULOMB"] = coulomb
    material = run(session, "DEFI_MATERIAU", DIS_CONTACT=law)
    field = run(session, "AFFE_MATERIAU", MAILLAGE=mesh, AFFE={"TOUT": "OUI", "MATER": material})
    numbering = run(session, "NUME_DDL", MODELE=model)
    return session, model, cara, field, numbering


def forces(direction, relative, coulomb=None):
    """FONL_NOEU at one instant where node 2 moves by ``relative`` (global)."""
    session, model, cara, field, numbering = spring(direction, coulomb)
    u = np.zeros(numbering.n_dofs)
    u[numbering.dof_indices([1, 1, 1], ["DX", "DY", "DZ"])] = relative
    result = DynaTrans(numbering=numbering, times=np.array([0.5]), order=np.array([3]),
                       fields={"DEPL": u[None, :]}, model=model)  # fmt: skip
    out = run(session, "CALC_FORC_NONL", RESULTAT=result, MODELE=model, CHAM_MATER=field,
              CARA_ELEM=cara, TOUT_ORDRE="OUI",
              COMPORTEMENT=[{"RELATION": "ELAS"},
                            {"RELATION": "DIS_CHOC", "GROUP_MA": "RES"}])  # fmt: skip
    assert out.order.tolist() == [3] and out.times.tolist() == [0.5]
    values = out.fields["DEPL"][0]
    first = values[numbering.dof_indices([0, 0, 0], ["DX", "DY", "DZ"])]
    second = values[numbering.dof_indices([1, 1, 1], ["DX", "DY", "DZ"])]
    return first, second


def test_closing_spring_along_x():
    dx, dy, dz = -1.0e-4, 2.0e-5, -3.0e-5
    first, second = forces((1, 0, 0), [dx, dy, dz])
    assert not first.any()  # code_aster keeps the second node only
    penetration = dx - np.finfo(float).eps
    # contact: normal force KN d, tangential K2/K3 springs; minus the linear K u
    np.testing.assert_allclose(second, [KN * penetration - K * dx, 0.0, 0.0], rtol=1e-12)


def test_opening_spring_along_y_gives_minus_k_u_in_global_axes():
    # local x is global y; local y is -global x (nautical angles of the y axis)
    dx, dy, dz = 2.0e-5, 1.0e-4, -3.0e-5
    first, second = forces((0, 1, 0), [dx, dy, dz])
    assert not first.any()
    np.testing.assert_allclose(second, [-K2 * dx, -K * dy, -K3 * dz], rtol=1e-12)


def test_friction_is_refused_by_name():
    with pytest.raises(CommandError, match="COULOMB"):
        forces((1, 0, 0), [-1e-4, 0.0, 0.0], coulomb=0.3)


def test_excit_resu_history_as_dlnew0_reads_it():
    from commands.dyna_vibra_phys import _result_load

    session, model, cara, field, numbering = spring((1, 0, 0))
    n = numbering.n_dofs
    values = np.outer([1.0, 3.0, 7.0], np.ones(n))
    result = DynaTrans(numbering=numbering, times=np.array([0.0, 0.1, 0.2]),
                       order=np.array([0, 1, 2]), fields={"DEPL": values})  # fmt: skip

    class Ctx:
        def error(self, message, *_args):
            raise CommandError(message)

    load = _result_load(Ctx(), {"RESULTAT": result, "COEF_MULT": -2.0}, numbering)
    assert load.coefficients(np.array([0.3]))[0] == -2.0
    got = load.history.values(np.array([0.1, 0.15, 0.05, 0.0, 0.25]))[:, 0]
    # stored instants exactly; linear between orders 1 and 2; before order 1's
    # instant, order 1's field (code_aster's loop starts at order 1); after, the last
    np.testing.assert_allclose(got, [3.0, 5.0, 3.0, 1.0, 7.0])
