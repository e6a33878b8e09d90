"""POST_DECOLLEMENT: the lifted share of a surface in closed form (two unit
squares, nodes lifted on one side), and CREA_CHAMP EXTR onto a NUME_DDL."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.mesh import Mesh
from asterlite.concepts.transient import DynaTrans
from tests.test_fem_support import FakeSession, run


def slab():
    coords = np.array(
        [[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 0], [2, 1, 0]], dtype=float
    )
    return Mesh(
        coords=coords,
        node_names=[f"N{i + 1}" for i in range(6)],
        cell_names=["Q1", "T1", "T2"],
        cell_types=["QUAD4", "TRIA3", "TRIA3"],
        cell_nodes=[(0, 1, 4, 3), (1, 2, 5), (1, 5, 4)],
        node_groups={},
        cell_groups={"DALLE": np.array([0, 1, 2])},
    )


def test_lifted_share_in_closed_form():
    session = FakeSession()
    mesh = slab()
    affe = {"TOUT": "OUI", "PHENOMENE": "MECANIQUE", "MODELISATION": "DKT"}
    model = run(session, "AFFE_MODELE", MAILLAGE=mesh, AFFE=affe)
    numbering = run(session, "NUME_DDL", MODELE=model)
    dz = numbering.dof_indices(np.arange(6), "DZ")
    values = np.zeros((3, numbering.n_dofs))
    values[1, dz[[2, 5]]] = 1e-3  # the right edge lifts
    values[2, dz] = 1e-3  # everything lifts
    result = DynaTrans(numbering=numbering, times=np.array([0.0, 0.5, 1.0]),
                       order=np.arange(3), fields={"DEPL": values})  # fmt: skip
    table = run(session, "POST_DECOLLEMENT", RESULTAT=result, GROUP_MA="DALLE",
                NOM_CHAM="DEPL", NOM_CMP="DZ")  # fmt: skip
    shares = [row["%DECOL"] for row in table.rows]
    # N3 and N6: a third of T1 each, N6 a third of T2: (1/6 + 1/6 + 1/6) of an area of 2
    assert shares == pytest.approx([0.0, 100.0 * 0.5 / 2.0, 100.0], rel=1e-14)


def test_crea_champ_extr_onto_a_numbering():
    session = FakeSession()
    mesh = slab()
    affe = {"TOUT": "OUI", "PHENOMENE": "MECANIQUE", "MODELISATION": "DKT"}
    model = run(session, "AFFE_MODELE", MAILLAGE=mesh, AFFE=affe)
    numbering = run(session, "NUME_DDL", MODELE=model)
    values = np.arange(numbering.n_dofs, dtype=float)[None, :]
    result = DynaTrans(numbering=numbering, times=np.array([0.0]), order=np.array([0]),
                       fields={"DEPL": values})  # fmt: skip
    other = run(session, "NUME_DDL", MODELE=model)
    field = run(session, "CREA_CHAMP", OPERATION="EXTR", TYPE_CHAM="NOEU_DEPL_R",
                RESULTAT=result, NOM_CHAM="DEPL", INST=0.0, NUME_DDL=other)  # fmt: skip
    assert field.numbering is other
    np.testing.assert_allclose(field.values, values[0])
