"""Discrete element matrices, frames, constraints and mesh commands."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as sla

from asterlite.concepts.mesh import Mesh
from asterlite.fem.constraints import eliminate
from asterlite.fem.discrete import expected_count, local_matrix
from asterlite.io.aster_mesh import AsterMeshError, parse_aster_mesh
from tests.test_fem_support import CO, FakeSession, chain_mesh, run

MESH_TEXT = """\
 TITRE
 two nodes, one spring   % a comment
 FINSF
 COOR_2D
 A 0.0 0.0
 B 3.0D0 4.0
 FINSF
 SEG2
 S1 A
    B
 FINSF
 POI1 NOM=IGNORED
 PA A  PB B
 FINSF
 GROUP_NO NOM=BOTH
 A B
 FINSF
 GROUP_MA
 SPRING S1
 FINSF
 FIN
"""


def test_aster_mesh_reader():
    mesh = parse_aster_mesh(MESH_TEXT)
    assert mesh.dim == 2 and mesh.n_nodes == 2 and mesh.n_cells == 3
    np.testing.assert_allclose(mesh.coords[1], [3.0, 4.0, 0.0])
    assert mesh.cell_types == ["SEG2", "POI1", "POI1"]
    assert mesh.cell_nodes[0] == (0, 1)
    assert mesh.node_groups["BOTH"].tolist() == [0, 1]
    assert mesh.cell_groups["SPRING"].tolist() == [0]
    assert "two nodes" in mesh.title
    with pytest.raises(AsterMeshError, match="m.mail:9: cell S1 uses unknown node Z"):
        parse_aster_mesh(MESH_TEXT.replace("SEG2\n S1 A", "SEG2\n S1 Z"), "m.mail")


def test_characteristic_counts():
    assert expected_count("K_TR_L", 3) == 78
    assert expected_count("M_TR_D_N", 3) == 10
    assert expected_count("M_TR_D_N", 2) == 4
    assert expected_count("K_T_L", 2) == 10
    full = local_matrix("K_T_N", (1, 2, 3, 4, 5, 6), 3)
    np.testing.assert_allclose(full, [[1, 2, 4], [2, 3, 5], [4, 5, 6]])


def _inclined_spring(session, repere):
    mesh = Mesh(
        coords=np.array([[0.0, 0.0, 0.0], [3.0, 4.0, 0.0]]),
        node_names=["A", "B"],
        cell_names=["S"],
        cell_types=["SEG2"],
        cell_nodes=[(0, 1)],
        cell_groups={"S": np.array([0])},
    )
    model = run(
        session,
        "AFFE_MODELE",
        MAILLAGE=mesh,
        AFFE={"TOUT": "OUI", "PHENOMENE": "MECANIQUE", "MODELISATION": "DIS_T"},
    )
    cara = run(
        session,
        "AFFE_CARA_ELEM",
        MODELE=model,
        DISCRET={"GROUP_MA": "S", "CARA": "K_T_D_L", "VALE": (10.0, 0.0, 0.0), "REPERE": repere},
    )
    rigi = run(session, "CALC_MATR_ELEM", OPTION="RIGI_MECA", MODELE=model, CARA_ELEM=cara)
    numbering = run(session, "NUME_DDL", MATR_RIGI=rigi)
    return run(session, "ASSE_MATRICE", MATR_ELEM=rigi, NUME_DDL=numbering).matrix.toarray()


def test_local_frame_of_a_segment_is_along_it():
    session = FakeSession()
    k_local = _inclined_spring(session, "LOCAL")
    e = np.array([0.6, 0.8, 0.0])
    block = 10.0 * np.outer(e, e)
    np.testing.assert_allclose(k_local, np.block([[block, -block], [-block, block]]), atol=1e-12)
    k_global = _inclined_spring(session, "GLOBAL")
    np.testing.assert_allclose(k_global[0, :], [10, 0, 0, -10, 0, 0])


def test_dis_tr_rotational_inertia_frequency():
    # one DIS_TR node, rotational spring kr about z and inertia Izz: ω² = kr / Izz
    mesh = Mesh(
        coords=np.zeros((1, 3)),
        node_names=["N"],
        cell_names=["P"],
        cell_types=["POI1"],
        cell_nodes=[(0,)],
        cell_groups={"P": np.array([0])},
    )
    session = FakeSession()
    model = run(
        session,
        "AFFE_MODELE",
        MAILLAGE=mesh,
        AFFE={"TOUT": "OUI", "PHENOMENE": "MECANIQUE", "MODELISATION": "DIS_TR"},
    )
    kr, izz, m = 50.0, 2.0, 3.0
    cara = run(
        session,
        "AFFE_CARA_ELEM",
        MODELE=model,
        DISCRET=[
            {"GROUP_MA": "P", "CARA": "K_TR_D_N", "VALE": (1e3, 1e3, 1e3, 1e3, 1e3, kr)},
            {"GROUP_MA": "P", "CARA": "M_TR_D_N", "VALE": (m, 1, 1, izz, 0, 0, 0, 0, 0, 0)},
        ],
    )
    charge = run(
        session,
        "AFFE_CHAR_MECA",
        MODELE=model,
        DDL_IMPO={"TOUT": "OUI", "DX": 0, "DY": 0, "DZ": 0, "DRX": 0, "DRY": 0},
    )
    common = {"MODELE": model, "CHARGE": charge, "CARA_ELEM": cara}
    rigi = run(session, "CALC_MATR_ELEM", OPTION="RIGI_MECA", **common)
    mass = run(session, "CALC_MATR_ELEM", OPTION="MASS_MECA", **common)
    numbering = run(session, "NUME_DDL", MATR_RIGI=rigi)
    k = run(session, "ASSE_MATRICE", MATR_ELEM=rigi, NUME_DDL=numbering)
    mm = run(session, "ASSE_MATRICE", MATR_ELEM=mass, NUME_DDL=numbering)
    modes = run(
        session,
        "CALC_MODES",
        MATR_RIGI=k,
        MATR_MASS=mm,
        OPTION="PLUS_PETITE",
        CALC_FREQ={"NMAX_FREQ": 1},
    )
    np.testing.assert_allclose(modes.frequencies, [np.sqrt(kr / izz) / (2 * np.pi)])
    assert modes.shape_at("N", "DRZ")[0] == 1.0


def test_eccentric_mass_matches_a_rigid_offset_point():
    # point mass m at offset e: M = Gᵀ m G with G the rigid transfer u_p = u + θ × e
    m, e = 2.0, np.array([0.3, -0.2, 0.5])
    skew = np.array([[0, -e[2], e[1]], [e[2], 0, -e[0]], [-e[1], e[0], 0]])
    g = np.hstack([np.eye(3), -skew])
    expected = m * g.T @ g
    got = local_matrix("M_TR_D_N", (m, 0, 0, 0, 0, 0, 0, *e), 3)
    np.testing.assert_allclose(got, expected, atol=1e-14)


def test_elimination_matches_lagrange_multipliers():
    rng = np.random.default_rng(0)
    n = 8
    a = rng.normal(size=(n, n))
    k = a @ a.T + n * np.eye(n)
    mass = np.diag(rng.uniform(1, 2, n))
    b = np.zeros((3, n))
    b[0, 0] = 1.0  # DDL_IMPO
    b[1, [1, 2]] = [0.7, -0.7]  # LIAISON_DDL
    b[2, [2, 3, 4]] = [1.0, 2.0, -1.0]
    elim = eliminate(b, np.zeros(3), n)
    kr, mr = elim.reduce(k).toarray(), elim.reduce(mass).toarray()
    ours = np.sort(sla.eigh(kr, mr, eigvals_only=True))
    # reference: eigenvalues of K on the null space of B (orthonormal basis)
    z = sla.null_space(b)
    ref = np.sort(sla.eigh(z.T @ k @ z, z.T @ mass @ z, eigvals_only=True))
    np.testing.assert_allclose(ours, ref, rtol=1e-10)
    np.testing.assert_allclose(b @ elim.T.toarray(), 0.0, atol=1e-12)


def test_crea_maillage_poi1_and_defi_group():
    session = FakeSession()
    mesh = chain_mesh(4)
    new = run(
        session,
        "CREA_MAILLAGE",
        MAILLAGE=mesh,
        CREA_POI1={"NOM_GROUP_MA": "PTS", "GROUP_NO": "ENDS"},
    )
    assert new is not mesh and new.n_cells == mesh.n_cells + 2
    assert [new.cell_types[c] for c in new.cell_groups["PTS"]] == ["POI1", "POI1"]
    assert [new.cell_nodes[c] for c in new.cell_groups["PTS"]] == [(0,), (3,)]
    run(
        session,
        "DEFI_GROUP",
        MAILLAGE=new,
        CREA_GROUP_NO=[{"GROUP_MA": "RESSORTS"}, {"NOM": "MID", "NOEUD": ("N2", "N3")}],
        CREA_GROUP_MA={"NOM": "ALL2", "UNION": ("RESSORTS", "PTS")},
    )
    assert new.node_groups["RESSORTS"].tolist() == [0, 1, 2, 3]
    assert new.node_groups["MID"].tolist() == [1, 2]
    assert len(new.cell_groups["ALL2"]) == 5


def test_assemblage_binds_numbering_and_matrices():
    session = FakeSession()
    mesh = chain_mesh(3)
    model = run(
        session,
        "AFFE_MODELE",
        MAILLAGE=mesh,
        AFFE={"TOUT": "OUI", "PHENOMENE": "MECANIQUE", "MODELISATION": "DIS_T"},
    )
    cara = run(
        session,
        "AFFE_CARA_ELEM",
        MODELE=model,
        DISCRET=[
            {"GROUP_MA": "RESSORTS", "CARA": "K_T_D_L", "VALE": (1.0, 2.0, 3.0)},
            {"GROUP_MA": "MASSES", "CARA": "M_T_D_N", "VALE": 5.0},
            {"GROUP_MA": "RESSORTS", "CARA": "A_T_D_L", "VALE": (0.1, 0.1, 0.1)},
        ],
    )
    load = run(
        session,
        "AFFE_CHAR_MECA",
        MODELE=model,
        FORCE_NODALE={"NOEUD": "N3", "FY": 2.0},
        DDL_IMPO={"NOEUD": "N1", "DX": 0.0, "DY": 0.0, "DZ": 0.0},
    )
    run(
        session,
        "ASSEMBLAGE",
        MODELE=model,
        CARA_ELEM=cara,
        CHARGE=load,
        NUME_DDL=CO("NUM"),
        MATR_ASSE=[
            {"MATRICE": CO("K"), "OPTION": "RIGI_MECA"},
            {"MATRICE": CO("M"), "OPTION": "MASS_MECA"},
            {"MATRICE": CO("C"), "OPTION": "AMOR_MECA"},
        ],
        VECT_ASSE={"VECTEUR": CO("F"), "OPTION": "CHAR_MECA", "CHARGE": load},
    )
    bound = session.bound
    assert bound["NUM"].n_dofs == 9 and len(bound["NUM"].relations) == 3
    np.testing.assert_allclose(bound["M"].matrix.diagonal(), 5.0)
    assert bound["K"].matrix[1, 1] == 2.0 and bound["K"].matrix[4, 4] == 4.0
    np.testing.assert_allclose(bound["C"].matrix.toarray()[0, 3], -0.1)
    assert bound["F"].values[bound["NUM"].dof_index("N3", "DY")] == 2.0
