# ruff: noqa: E501 (deck text is kept on one line per command, as in the corpus)
"""An impact on a substructure of a coupled model against the same problem
run as one structure (issue 19).

A cantilever beam bending in the XY plane is cut at mid-span into two
Craig-Bampton substructures; its tip (node B of the second one, named with
SOUS_STRUC_1) is pushed by a step force onto a circular obstacle with a
gap. With complete bases the coupled modes are the one-piece model's
(the same space), so the two transients with every mode agree to
round-off; with truncated bases the tip history converges to it as
modes are added.
"""

from __future__ import annotations

import numpy as np
import pytest

from tests.test_substructure_beam import FRONT, GUIDED, LENGTH, beam_mesh, matrices, run_case

N_HALF = 3
GAP = 1.0e-4
END = 0.01

OBSTACLE = """
OBST = DEFI_OBSTACLE(TYPE="CERCLE")
"""


def transient(base: str, gene: str, shock: str) -> str:
    """Projection on the modes ``base`` and DIFF_CENTRE with one DIS_CHOC."""
    return f"""
NUMODE = NUME_DDL_GENE(BASE={base}, STOCKAGE="DIAG")
KPRO = PROJ_MATR_BASE(BASE={base}, NUME_DDL_GENE=NUMODE, {gene}=KGEN)
MPRO = PROJ_MATR_BASE(BASE={base}, NUME_DDL_GENE=NUMODE, {gene}=MGEN)
FPRO = PROJ_VECT_BASE(BASE={base}, NUME_DDL_GENE=NUMODE, {gene.replace("MATR", "VECT")}=FGEN, TYPE_VECT="FORC")
TRAN = DYNA_VIBRA(TYPE_CALCUL="TRAN", BASE_CALCUL="GENE", SCHEMA_TEMPS=_F(SCHEMA="DIFF_CENTRE"),
    MATR_MASS=MPRO, MATR_RIGI=KPRO, EXCIT=_F(VECT_ASSE_GENE=FPRO, COEF_MULT=1.0),
    INCREMENT=_F(INST_INIT=0.0, INST_FIN={END}, PAS=2.0e-7),
    COMPORTEMENT=_F(RELATION="DIS_CHOC", GROUP_NO_1="B", {shock} OBSTACLE=OBST,
        NORM_OBST=(1.0, 0.0, 0.0), JEU={GAP}, RIGI_NOR=1.0e7),
    ARCHIVAGE=_F(PAS_ARCH=100))
"""


def one_piece(n_modes: int) -> str:
    deck = FRONT.format(guided=GUIDED) + OBSTACLE
    deck += 'CLAMP = AFFE_CHAR_MECA(MODELE=MODEL, DDL_IMPO=_F(GROUP_NO="A", DY=0.0, DRZ=0.0))\n'
    deck += 'PUSH = AFFE_CHAR_MECA(MODELE=MODEL, FORCE_NODALE=_F(GROUP_NO="B", FY=-200.0))\n'
    deck += matrices("W", "GUIDE, CLAMP")
    deck += f"""
MODES = CALC_MODES(MATR_RIGI=KA_W, MATR_MASS=MA_W, CALC_FREQ=_F(NMAX_FREQ={n_modes}))
FEL = CALC_VECT_ELEM(OPTION="CHAR_MECA", CHARGE=PUSH)
FAS = ASSE_VECTEUR(VECT_ELEM=FEL, NUME_DDL=NU_W)
KGEN = KA_W
MGEN = MA_W
FGEN = FAS
"""
    deck += transient("MODES", "MATR_ASSE", "")
    deck += "TIP = REST_GENE_PHYS(RESU_GENE=TRAN, NOM_CHAM='DEPL', MODE_MECA=MODES)\nFIN()\n"
    return deck


def coupled(nmax: dict, n_modes: int, direct: bool = False) -> str:
    """``nmax``: fixed-interface modes kept on each side ("L", "R");
    ``direct``: the transient on the assembled generalized matrices (the
    interface relations kept), restored with REST_SOUS_STRUC."""
    deck = FRONT.format(guided=GUIDED) + OBSTACLE
    deck += 'JONC_B = AFFE_CHAR_MECA(MODELE=MODEL, DDL_IMPO=_F(GROUP_NO="B", DY=0.0, DRZ=0.0))\n'
    deck += 'JONC_A = AFFE_CHAR_MECA(MODELE=MODEL, DDL_IMPO=_F(GROUP_NO="A", DY=0.0, DRZ=0.0))\n'
    deck += 'PUSH = AFFE_CHAR_MECA(MODELE=MODEL, FORCE_NODALE=_F(GROUP_NO="B", FY=-200.0))\n'
    deck += matrices("L", "GUIDE, JONC_B, JONC_A") + matrices("R", "GUIDE, JONC_A")
    for side, node, name in (("L", "B", "DROITE"), ("R", "A", "GAUCHE")):
        deck += f"""
MO_{side} = CALC_MODES(MATR_RIGI=KA_{side}, MATR_MASS=MA_{side}, CALC_FREQ=_F(NMAX_FREQ={nmax[side]}))
IN_{side} = DEFI_INTERF_DYNA(NUME_DDL=NU_{side}, INTERFACE=_F(NOM="{name}", TYPE="CRAIGB",
    GROUP_NO="{node}", MASQUE=("DX", "DZ", "DRX", "DRY")))
BA_{side} = DEFI_BASE_MODALE(CLASSIQUE=_F(INTERF_DYNA=IN_{side}, MODE_MECA=MO_{side}, NMAX_MODE={nmax[side]}))
ME_{side} = MACR_ELEM_DYNA(BASE_MODALE=BA_{side})
"""
    deck += f"""
MODEGE = DEFI_MODELE_GENE(
    SOUS_STRUC=(_F(NOM="COTE1", MACR_ELEM_DYNA=ME_L, ANGL_NAUT=(0.0, 0.0, 0.0), TRANS=(0.0, 0.0, 0.0)),
                _F(NOM="COTE2", MACR_ELEM_DYNA=ME_R, ANGL_NAUT=(0.0, 0.0, 0.0), TRANS=({LENGTH / 2}, 0.0, 0.0))),
    LIAISON=_F(SOUS_STRUC_1="COTE1", INTERFACE_1="DROITE", SOUS_STRUC_2="COTE2", INTERFACE_2="GAUCHE"),
)
NUMEGE = NUME_DDL_GENE(MODELE_GENE=MODEGE)
KGEN = ASSE_MATR_GENE(NUME_DDL_GENE=NUMEGE, OPTION="RIGI_GENE")
MGEN = ASSE_MATR_GENE(NUME_DDL_GENE=NUMEGE, OPTION="MASS_GENE")
FEL = CALC_VECT_ELEM(OPTION="CHAR_MECA", CHARGE=PUSH)
FAS = ASSE_VECTEUR(VECT_ELEM=FEL, NUME_DDL=NU_R)
FGEN = ASSE_VECT_GENE(NUME_DDL_GENE=NUMEGE, CHAR_SOUS_STRUC=_F(SOUS_STRUC="COTE2", VECT_ASSE=FAS))
RESGEN = CALC_MODES(MATR_RIGI=KGEN, MATR_MASS=MGEN, CALC_FREQ=_F(NMAX_FREQ={n_modes}))
"""
    if direct:
        deck += f"""
TRAN = DYNA_VIBRA(TYPE_CALCUL="TRAN", BASE_CALCUL="GENE", SCHEMA_TEMPS=_F(SCHEMA="DIFF_CENTRE"),
    MATR_MASS=MGEN, MATR_RIGI=KGEN, EXCIT=_F(VECT_ASSE_GENE=FGEN, COEF_MULT=1.0),
    INCREMENT=_F(INST_INIT=0.0, INST_FIN={END}, PAS=2.0e-7),
    COMPORTEMENT=_F(RELATION="DIS_CHOC", GROUP_NO_1="B", SOUS_STRUC_1="COTE2", OBSTACLE=OBST,
        NORM_OBST=(1.0, 0.0, 0.0), JEU={GAP}, RIGI_NOR=1.0e7, INTITULE="TIP"),
    ARCHIVAGE=_F(PAS_ARCH=100))
TIP = REST_SOUS_STRUC(RESU_GENE=TRAN, SOUS_STRUC="COTE2", NOM_CHAM="DEPL")
FN = RECU_FONCTION(RESU_GENE=TRAN, INTITULE="TIP", NOEUD_CHOC="N{N_HALF}", SOUS_STRUC="COTE2",
    PARA_X="INST", PARA_Y="FN")
STAT = POST_DYNA_MODA_T(RESU_GENE=TRAN, CHOC=_F(INST_INIT=0.0, INST_FIN={END}, NB_BLOC=1,
    SEUIL_FORCE=0.0, DUREE_REPOS=0.0))
FIN()
"""
        return deck
    deck += transient("RESGEN", "MATR_ASSE_GENE", 'SOUS_STRUC_1="COTE2", REPERE="COTE2",')
    deck += """
MODR = REST_SOUS_STRUC(RESU_GENE=RESGEN, SOUS_STRUC="COTE2", TOUT_ORDRE="OUI")
TIP = REST_GENE_PHYS(RESU_GENE=TRAN, NOM_CHAM="DEPL", MODE_MECA=MODR)
FIN()
"""
    return deck


def tip_history(result) -> np.ndarray:
    tip = result.concepts.raw["TIP"]
    node = int(tip.numbering.mesh.node_groups["B"][0])
    row = tip.numbering.dof_index(node, "DY")
    return np.asarray(tip.fields["DEPL"])[:, row]


def normal_force(result) -> np.ndarray:
    return np.asarray(result.concepts.raw["TRAN"].shocks[0].fields["FN"])


@pytest.mark.slow
def test_impact_on_a_substructure_matches_the_one_piece_model(tmp_path):
    n_modes = 4 * N_HALF  # in-plane DOFs of the clamped beam: every mode
    whole = run_case(tmp_path / "whole", "whole", one_piece(n_modes), beam_mesh(2 * N_HALF, LENGTH))
    mesh = beam_mesh(N_HALF, LENGTH / 2)
    # every fixed-interface mode: the left half is also clamped at A
    full = {"L": 2 * (N_HALF + 1) - 4, "R": 2 * (N_HALF + 1) - 2}
    cut = run_case(tmp_path / "cut", "cut", coupled(full, n_modes), mesh)
    reference, coupled_tip = tip_history(whole), tip_history(cut)
    scale = np.max(np.abs(reference))
    assert np.min(reference) < -GAP  # the tip reached the obstacle (penalised contact)
    assert np.max(normal_force(whole)) > 0.0
    np.testing.assert_allclose(coupled_tip, reference, atol=1e-7 * scale)
    np.testing.assert_allclose(normal_force(cut), normal_force(whole), atol=1e-6 * 200.0)
    # the transient on the assembled generalized matrices: the same response
    direct = run_case(tmp_path / "direct", "cut", coupled(full, n_modes, direct=True), mesh)
    np.testing.assert_allclose(tip_history(direct), reference, atol=1e-7 * scale)
    # its post-processing names the shock's node in its substructure's mesh
    fn = direct.concepts.raw["FN"]
    np.testing.assert_array_equal(fn.ordinates, normal_force(direct))
    stat = direct.concepts.raw["STAT"]
    node_b = N_HALF + 1  # B, the last node of the half beam's mesh, by number
    assert str(node_b) in [str(v).strip() for v in stat.column("NOEUD")]
    # truncated bases: the same impact, approached as modes are added
    errors = []
    for nmax, count in (({"L": 1, "R": 2}, 8), ({"L": 2, "R": 4}, 10), ({"L": 3, "R": 5}, 12)):
        rough = run_case(tmp_path / f"rough{count}", "cut", coupled(nmax, count), mesh)
        errors.append(np.max(np.abs(tip_history(rough) - reference)) / scale)
    print("tip displacement error by basis size:", errors)
    assert errors[0] > errors[1] > errors[2] > 1e-6
    assert errors[2] < 0.05
