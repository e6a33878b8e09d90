# ruff: noqa: E501 (deck text is kept on one line per command, as in the corpus)
"""Static substructuring end to end against the cantilever's closed form.

A cantilever (POU_D_E, length L, clamped at A) is cut at mid-span: its left
half becomes a superelement (MACR_ELEM_STAT, clamped by CHAR_MACR_ELEM,
external node N5), placed in a mesh (DEFI_MAILLAGE) joined to the whole
beam mesh (ASSE_MAILLAGE SOUS_STR: N5 of both is one node), whose right
half carries beam elements. Static condensation is exact for statics: the
tip deflection under a tip force is F L³ / (3 E I), and DEPL_INTERNE gives
the left half's interior deflection F x² (3 L - x) / (6 E I).
"""

from __future__ import annotations

import numpy as np
import pytest

from asterlite import api

N_ELEMENTS = 10
LENGTH = 1.0
YOUNG = 2.0e11
RADIUS = 0.02
FORCE = 100.0
INERTIA = np.pi * RADIUS**4 / 4.0


def beam_mesh() -> str:
    names = ["A"] + [f"N{i}" for i in range(1, N_ELEMENTS + 1)]
    lines = ["TITRE", "beam", "FINSF", "COOR_3D"]
    # N<i> listed i-th (code_aster 17 reads N<i> as the i-th node), A last
    listed = [*range(1, N_ELEMENTS + 1), 0]
    lines += [f"{names[k]} {k * LENGTH / N_ELEMENTS:.15e} 0.0 0.0" for k in listed]
    lines += ["FINSF", "SEG2"] + [f"S{k + 1} {names[k]} {names[k + 1]}" for k in range(N_ELEMENTS)]
    half = N_ELEMENTS // 2
    lines += ["FINSF", "GROUP_NO", "A", "A", "FINSF", "GROUP_NO", "MID", f"N{half}", "FINSF"]
    lines += ["GROUP_MA", "LEFT"] + [f"S{k + 1}" for k in range(half)] + ["FINSF"]
    lines += ["GROUP_MA", "RIGHT"] + [f"S{k + 1}" for k in range(half, N_ELEMENTS)]
    return "\n".join(lines + ["FINSF", "FIN"]) + "\n"


DECK = f"""
DEBUT()
MAYA = LIRE_MAILLAGE(FORMAT="ASTER")
MAT = DEFI_MATERIAU(ELAS=_F(E={YOUNG}, NU=0.3, RHO=7800.0))
MO_L = AFFE_MODELE(MAILLAGE=MAYA, AFFE=_F(GROUP_MA="LEFT", PHENOMENE="MECANIQUE", MODELISATION="POU_D_E"))
CM_L = AFFE_MATERIAU(MAILLAGE=MAYA, AFFE=_F(GROUP_MA="LEFT", MATER=MAT))
CA_L = AFFE_CARA_ELEM(MODELE=MO_L, POUTRE=_F(GROUP_MA="LEFT", SECTION="CERCLE", CARA="R", VALE={RADIUS}))
CLAMP = AFFE_CHAR_MECA(MODELE=MO_L, DDL_IMPO=_F(GROUP_NO="A", DX=0.0, DY=0.0, DZ=0.0, DRX=0.0, DRY=0.0, DRZ=0.0))
SUPER = MACR_ELEM_STAT(DEFINITION=_F(MODELE=MO_L, CHAM_MATER=CM_L, CARA_ELEM=CA_L, CHAR_MACR_ELEM=CLAMP),
    EXTERIEUR=_F(GROUP_NO="MID"), RIGI_MECA=_F())
SUPER = MACR_ELEM_STAT(reuse=SUPER, MACR_ELEM=SUPER, MASS_MECA=_F())
MESH_S = DEFI_MAILLAGE(DEFI_SUPER_MAILLE=_F(MACR_ELEM=SUPER, SUPER_MAILLE="LEFTSE"),
    DEFI_NOEUD=_F(TOUT="OUI", INDEX=(1, 0, 1, 8)), DEFI_GROUP_NO=_F(TOUT="OUI", INDEX=(1, 0, 1, 8)))
MESH = ASSE_MAILLAGE(MAILLAGE_1=MESH_S, MAILLAGE_2=MAYA, OPERATION="SOUS_STR")
MODEL = AFFE_MODELE(MAILLAGE=MESH, AFFE=_F(GROUP_MA="RIGHT", PHENOMENE="MECANIQUE", MODELISATION="POU_D_E"),
    AFFE_SOUS_STRUC=_F(SUPER_MAILLE="LEFTSE"))
CM = AFFE_MATERIAU(MAILLAGE=MESH, AFFE=_F(GROUP_MA="RIGHT", MATER=MAT))
CA = AFFE_CARA_ELEM(MODELE=MODEL, POUTRE=_F(GROUP_MA="RIGHT", SECTION="CERCLE", CARA="R", VALE={RADIUS}))
TIP = AFFE_CHAR_MECA(MODELE=MODEL, FORCE_NODALE=_F(NOEUD="N{N_ELEMENTS}", FY={FORCE}))
STAT = MECA_STATIQUE(MODELE=MODEL, CHAM_MATER=CM, CARA_ELEM=CA, EXCIT=_F(CHARGE=TIP))
U = CREA_CHAMP(OPERATION="EXTR", TYPE_CHAM="NOEU_DEPL_R", RESULTAT=STAT, NOM_CHAM="DEPL", NUME_ORDRE=1)
U_LEFT = DEPL_INTERNE(DEPL_GLOBAL=U, SUPER_MAILLE="LEFTSE")
K = CALC_MATR_ELEM(MODELE=MODEL, OPTION="RIGI_MECA", CHAM_MATER=CM, CARA_ELEM=CA)
M = CALC_MATR_ELEM(MODELE=MODEL, OPTION="MASS_MECA", CHAM_MATER=CM, CARA_ELEM=CA)
NU = NUME_DDL(MATR_RIGI=K)
KA = ASSE_MATRICE(MATR_ELEM=K, NUME_DDL=NU)
MA = ASSE_MATRICE(MATR_ELEM=M, NUME_DDL=NU)
MODES = CALC_MODES(MATR_RIGI=KA, MATR_MASS=MA, CALC_FREQ=_F(NMAX_FREQ=4))
MAC = MAC_MODES(BASE_1=MODES, BASE_2=MODES)
MAC_M = MAC_MODES(BASE_1=MODES, BASE_2=MODES, MATR_ASSE=MA)
IERI = MAC_MODES(BASE_1=MODES, BASE_2=MODES, MATR_ASSE=KA, IERI="OUI")
FIN()
"""


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    folder = tmp_path_factory.mktemp("static_substructure")
    (folder / "cut.comm").write_text(DECK)
    (folder / "cut.mail").write_text(beam_mesh())
    result = api.run(folder / "cut.comm")
    assert result.status == "DONE", result.message
    return result.concepts.raw


def deflection(x: float) -> float:
    return FORCE * x**2 * (3.0 * LENGTH - x) / (6.0 * YOUNG * INERTIA)


def test_the_condensed_half_carries_the_cantilever_exactly(run):
    field = run["U"]
    tip = field.numbering.dof_index(f"N{N_ELEMENTS}", "DY")
    assert field.values[tip] == pytest.approx(FORCE * LENGTH**3 / (3 * YOUNG * INERTIA), rel=1e-10)
    middle = field.numbering.dof_index("N5", "DY")
    assert field.values[middle] == pytest.approx(deflection(0.5), rel=1e-10)


def test_depl_interne_restitutes_the_interior(run):
    inside = run["U_LEFT"]
    assert inside.numbering.mesh is run["MAYA"]
    for node in ("N1", "N3", "N5"):
        x = float(node[1:]) / N_ELEMENTS
        value = inside.values[inside.numbering.dof_index(node, "DY")]
        assert value == pytest.approx(deflection(x), rel=1e-10)
    assert inside.values[inside.numbering.dof_index("A", "DY")] == 0.0


def test_the_super_mesh_joins_the_superelement_to_the_cells(run):
    mesh = run["MESH"]
    assert mesh.node_names.count("N5") == 1
    assert set(mesh.super_cells) == {"LEFTSE"}
    assert mesh.node_names[int(mesh.super_cells["LEFTSE"].nodes[0])] == "N5"
    # the superelement's groups restricted to its external node
    assert list(run["MESH_S"].node_groups) == ["MID"]


def test_assembled_matrices_hold_the_condensed_ones(run):
    stiffness, mass = run["KA"], run["MA"]
    macro = run["SUPER"]
    rows = stiffness.numbering.dof_indices(["N5"] * 6, list(macro.components))
    right = run["MODEL"]
    assert sorted(right.substructures) == ["LEFTSE"]
    # the superelement's share at N5: assembled minus the right half's elements
    alone = right_half_assembled(right, run, stiffness.numbering)
    share = stiffness.matrix.toarray()[np.ix_(rows, rows)] - alone[np.ix_(rows, rows)]
    assert np.allclose(share, macro.matrices["RIGI"], rtol=1e-12, atol=1e-6)
    # the condensed mass of a clamped half holds its static shapes' mass: positive definite
    assert np.all(np.linalg.eigvalsh(macro.matrices["MASS"]) > 0.0)
    assert mass.matrix.shape == stiffness.matrix.shape


def right_half_assembled(model, run, numbering):
    """The right half's own elements assembled on the same numbering."""
    from asterlite.fem.assemble import assemble_blocks
    from asterlite.fem.elements import element_blocks

    blocks = element_blocks(model, run["CA"], "K", materials=run["CM"])
    return assemble_blocks(blocks, numbering).toarray()


def _matrix(table, column: str) -> np.ndarray:
    out = np.zeros((4, 4))
    for row in table.rows:
        out[row["NUME_MODE_1"] - 1, row["NUME_MODE_2"] - 1] = row[column]
    return out


def test_mac_modes_of_a_base_with_itself(run):
    modes = run["MODES"]
    mac = _matrix(run["MAC"], "MAC")
    shapes = modes.shapes
    expected = (shapes.T @ shapes) ** 2 / np.outer(
        np.sum(shapes**2, axis=0), np.sum(shapes**2, axis=0)
    )
    assert np.allclose(mac, expected, rtol=1e-12)
    assert np.allclose(np.diag(mac), 1.0, rtol=1e-12)
    # mass-weighted: the modes are M-orthogonal
    assert np.allclose(_matrix(run["MAC_M"], "MAC"), np.eye(4), atol=1e-10)
    weighted = _matrix(run["MAC_M"], "Y1_W_Y2")
    assert np.allclose(np.diag(weighted), modes.generalized_mass, rtol=1e-10)
    # IERI of a mode with itself: no energy in the difference
    assert np.allclose(np.diag(_matrix(run["IERI"], "IERI")), 0.0, atol=1e-20)


TURNED = f"""
DEBUT()
MAYA = LIRE_MAILLAGE(FORMAT="ASTER")
MAT = DEFI_MATERIAU(ELAS=_F(E={YOUNG}, NU=0.3, RHO=7800.0))
MO = AFFE_MODELE(MAILLAGE=MAYA, AFFE=_F(TOUT="OUI", PHENOMENE="MECANIQUE", MODELISATION="POU_D_E"))
CM = AFFE_MATERIAU(MAILLAGE=MAYA, AFFE=_F(TOUT="OUI", MATER=MAT))
CA = AFFE_CARA_ELEM(MODELE=MO, POUTRE=_F(GROUP_MA=("LEFT", "RIGHT"), SECTION="CERCLE", CARA="R", VALE={RADIUS}))
CLAMP = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_NO="A", DX=0.0, DY=0.0, DZ=0.0, DRX=0.0, DRY=0.0, DRZ=0.0))
BEAM = MACR_ELEM_STAT(DEFINITION=_F(MODELE=MO, CHAM_MATER=CM, CARA_ELEM=CA, CHAR_MACR_ELEM=CLAMP),
    EXTERIEUR=_F(NOEUD=("A", "N{N_ELEMENTS}")), RIGI_MECA=_F())
MESH = DEFI_MAILLAGE(DEFI_SUPER_MAILLE=_F(MACR_ELEM=BEAM, SUPER_MAILLE="UP", ANGL_NAUT=(90.0, 0.0, 0.0)),
    DEFI_NOEUD=_F(TOUT="OUI", INDEX=(1, 0, 1, 8)))
MODEL = AFFE_MODELE(MAILLAGE=MESH, AFFE_SOUS_STRUC=_F(TOUT="OUI"))
PUSH = AFFE_CHAR_MECA(MODELE=MODEL, FORCE_NODALE=_F(NOEUD="N{N_ELEMENTS}", FX={FORCE}))
K = CALC_MATR_ELEM(MODELE=MODEL, OPTION="RIGI_MECA")
NU = NUME_DDL(MATR_RIGI=K)
KA = ASSE_MATRICE(MATR_ELEM=K, NUME_DDL=NU)
KA = FACTORISER(reuse=KA, MATR_ASSE=KA)
VE = CALC_VECT_ELEM(OPTION="CHAR_MECA", CHARGE=PUSH)
F = ASSE_VECTEUR(VECT_ELEM=VE, NUME_DDL=NU)
U = RESOUDRE(MATR=KA, CHAM_NO=F)
U_IN = DEPL_INTERNE(DEPL_GLOBAL=U, SUPER_MAILLE="UP")
FIN()
"""


def test_a_turned_superelement_bends_in_the_global_frame(tmp_path):
    """The cantilever turned 90 degrees about Z (ANGL_NAUT) stands along Y: a
    force FX at its tip bends it by F L³ / (3 E I) along X, its clamped
    external node A stays fixed, and inside (its own frame) it deflects
    along -y."""
    (tmp_path / "turned.comm").write_text(TURNED)
    (tmp_path / "turned.mail").write_text(beam_mesh())
    result = api.run(tmp_path / "turned.comm")
    assert result.status == "DONE", result.message
    raw = result.concepts.raw
    mesh = raw["MESH"]
    tip = mesh.find_node(f"N{N_ELEMENTS}")
    assert np.allclose(mesh.coords[tip], [0.0, LENGTH, 0.0], atol=1e-14)
    field = raw["U"]
    assert field.values[field.numbering.dof_index(tip, "DX")] == pytest.approx(
        deflection(LENGTH), rel=1e-10
    )
    assert abs(field.values[field.numbering.dof_index(tip, "DY")]) < 1e-12 * deflection(LENGTH)
    # A, listed last in a mesh that keeps no names, is N11 in the super mesh
    assert field.values[field.numbering.dof_index(f"N{N_ELEMENTS + 1}", "DX")] == 0.0
    inside = raw["U_IN"]
    value = inside.values[inside.numbering.dof_index("N3", "DY")]
    assert value == pytest.approx(-deflection(0.3), rel=1e-10)


LOADED = DECK.replace(
    "SUPER = MACR_ELEM_STAT(reuse=SUPER, MACR_ELEM=SUPER, MASS_MECA=_F())",
    'PUSH_IN = AFFE_CHAR_MECA(MODELE=MO_L, FORCE_NODALE=_F(NOEUD="N3", FY=' + f"{FORCE}" + "))\n"
    "SUPER = MACR_ELEM_STAT(reuse=SUPER, MACR_ELEM=SUPER, MASS_MECA=_F(),\n"
    '    CAS_CHARGE=_F(NOM_CAS="INSIDE", CHARGE=(CLAMP, PUSH_IN)))',
).replace(
    "FIN()",
    'VE = CALC_VECT_ELEM(OPTION="CHAR_MECA", MODELE=MODEL, SOUS_STRUC=_F(CAS_CHARGE="INSIDE", TOUT="OUI"))\n'
    "F_IN = ASSE_VECTEUR(VECT_ELEM=VE, NUME_DDL=NU)\n"
    "KF = FACTORISER(MATR_ASSE=KA)\n"
    "U_CASE = RESOUDRE(MATR=KF, CHAM_NO=F_IN)\n"
    'U_CASE_IN = DEPL_INTERNE(DEPL_GLOBAL=U_CASE, SUPER_MAILLE="LEFTSE", NOM_CAS="INSIDE")\n'
    "FIN()",
)


def test_a_condensed_load_case_inside_the_superelement(tmp_path):
    """CAS_CHARGE: a force P at N3 (x = a) inside the superelement; the tip
    moves by P a² (3L - a) / (6EI) and, with the case's interior response,
    the load point by P a³ / (3EI) and N1 by P x² (3a - x) / (6EI)."""
    (tmp_path / "loaded.comm").write_text(LOADED)
    (tmp_path / "loaded.mail").write_text(beam_mesh())
    result = api.run(tmp_path / "loaded.comm")
    assert result.status == "DONE", result.message
    raw = result.concepts.raw
    a, stiffness = 0.3, YOUNG * INERTIA
    field = raw["U_CASE"]
    tip = field.values[field.numbering.dof_index(f"N{N_ELEMENTS}", "DY")]
    assert tip == pytest.approx(FORCE * a**2 * (3 * LENGTH - a) / (6 * stiffness), rel=1e-10)
    inside = raw["U_CASE_IN"]
    at_load = inside.values[inside.numbering.dof_index("N3", "DY")]
    assert at_load == pytest.approx(FORCE * a**3 / (3 * stiffness), rel=1e-10)
    x = 0.1
    before = inside.values[inside.numbering.dof_index("N1", "DY")]
    assert before == pytest.approx(FORCE * x**2 * (3 * a - x) / (6 * stiffness), rel=1e-10)
