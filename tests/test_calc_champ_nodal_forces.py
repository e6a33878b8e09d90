"""CALC_CHAMP FORCE (FORC_NODA, REAC_NODA) of a physical transient, against
the hand computation of a spring-mass system: a spring k from the clamped
node NA to node NB of mass m, pulled by a step force F on NB.

code_aster (ccfnrn) takes FORC_NODA = K u and REAC_NODA = K u - F(t) + M a
(damping left out): at NA the reaction is -k u_B, at NB the equation of
motion makes it zero, and FORC_NODA at NB is k u_B.
"""

from __future__ import annotations

import numpy as np
import pytest

import asterlite

K, M, F = 4.0e4, 2.5, 10.0

MESH = """COOR_3D
NA 0.0 0.0 0.0
NB 1.0 0.0 0.0
FINSF
SEG2
S1 NA NB
FINSF
POI1
P1 NB
FINSF
GROUP_MA
RESSORT S1
FINSF
GROUP_MA
MASSE P1
FINSF
GROUP_NO
GA NA
FINSF
GROUP_NO
GB NB
FINSF
FIN
"""


def deck(calc_champ: str, damping: bool = False) -> str:
    amor = "MATR_AMOR=MATRAMOR," if damping else ""
    return f"""DEBUT(CODE="OUI")
MAIL = LIRE_MAILLAGE(FORMAT="ASTER")
MODELE = AFFE_MODELE(MAILLAGE=MAIL, AFFE=_F(GROUP_MA=("RESSORT", "MASSE"),
                     PHENOMENE="MECANIQUE", MODELISATION="DIS_T"))
CARA = AFFE_CARA_ELEM(MODELE=MODELE, DISCRET=(
    _F(GROUP_MA="RESSORT", CARA="K_T_D_L", VALE=({K}, {K}, {K})),
    _F(GROUP_MA="RESSORT", CARA="A_T_D_L", VALE=(30.0, 30.0, 30.0)),
    _F(GROUP_MA="MASSE", CARA="M_T_D_N", VALE={M})))
BLOCAGE = AFFE_CHAR_MECA(MODELE=MODELE, DDL_IMPO=(
    _F(GROUP_NO="GA", DX=0.0, DY=0.0, DZ=0.0), _F(GROUP_NO="GB", DY=0.0, DZ=0.0)))
TIRE = AFFE_CHAR_MECA(MODELE=MODELE, FORCE_NODALE=_F(GROUP_NO="GB", FX={F}))
RIGIELEM = CALC_MATR_ELEM(MODELE=MODELE, CHARGE=BLOCAGE, CARA_ELEM=CARA, OPTION="RIGI_MECA")
MASSELEM = CALC_MATR_ELEM(MODELE=MODELE, CHARGE=BLOCAGE, CARA_ELEM=CARA, OPTION="MASS_MECA")
AMORELEM = CALC_MATR_ELEM(MODELE=MODELE, CHARGE=BLOCAGE, CARA_ELEM=CARA, OPTION="AMOR_MECA")
NUMEROTA = NUME_DDL(MATR_RIGI=RIGIELEM)
MATRRIGI = ASSE_MATRICE(MATR_ELEM=RIGIELEM, NUME_DDL=NUMEROTA)
MATRMASS = ASSE_MATRICE(MATR_ELEM=MASSELEM, NUME_DDL=NUMEROTA)
MATRAMOR = ASSE_MATRICE(MATR_ELEM=AMORELEM, NUME_DDL=NUMEROTA)
MARCHE = DEFI_FONCTION(NOM_PARA="INST", VALE=(0.0, 1.0, 10.0, 1.0))
U = DYNA_VIBRA(TYPE_CALCUL="TRAN", BASE_CALCUL="PHYS", MODELE=MODELE, CARA_ELEM=CARA,
               MATR_MASS=MATRMASS, MATR_RIGI=MATRRIGI, {amor}
               SCHEMA_TEMPS=_F(SCHEMA="NEWMARK"),
               EXCIT=(_F(CHARGE=BLOCAGE), _F(CHARGE=TIRE, FONC_MULT=MARCHE)),
               INCREMENT=_F(INST_INIT=0.0, INST_FIN=0.2, PAS=1.0e-4))
{calc_champ}
FIN()
"""


def run(tmp_path, calc_champ: str, damping: bool = False):
    (tmp_path / "springs.comm").write_text(deck(calc_champ, damping))
    (tmp_path / "springs.mail").write_text(MESH)
    (tmp_path / "springs.export").write_text(
        "P time_limit 300\nP memory_limit 2048\nP ncpus 1\n"
        "F comm springs.comm D 1\nF mail springs.mail D 20\n"
    )
    return asterlite.run(tmp_path / "springs.export", tmp_path / "out")


def columns(result, name):
    """(values at NA DX, values at NB DX) of a nodal field of the result."""
    a = result.numbering.dof_index("NA", "DX")
    b = result.numbering.dof_index("NB", "DX")
    values = np.asarray(result.fields[name])
    return values[:, a], values[:, b]


def test_reactions_of_a_spring_mass_transient_are_its_hand_computation(tmp_path):
    done = run(tmp_path, 'U = CALC_CHAMP(reuse=U, RESULTAT=U, FORCE=("FORC_NODA", "REAC_NODA"))')
    assert done.status == "DONE", done
    result = done.concepts.raw["U"]
    _, u_b = columns(result, "DEPL")
    _, a_b = columns(result, "ACCE")
    forc_a, forc_b = columns(result, "FORC_NODA")
    reac_a, reac_b = columns(result, "REAC_NODA")
    # the step response F/k (1 - cos ωt), half a step late: from rest the
    # scheme starts with a zero acceleration (not F/m), as code_aster's
    dt = result.times[1] - result.times[0]
    late = np.maximum(result.times - dt / 2.0, 0.0)
    exact = F / K * (1.0 - np.cos(np.sqrt(K / M) * late))
    assert np.max(np.abs(u_b - exact)) < 1.0e-3 * F / K
    np.testing.assert_allclose(forc_b, K * u_b, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(forc_a, -K * u_b, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(reac_a, -K * u_b, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(reac_b, K * u_b - F + M * a_b, rtol=1e-12, atol=1e-12)
    # the equation of motion at NB from the first step on (from rest the
    # scheme starts with a zero acceleration, so order 0 holds -F)
    assert reac_b[0] == pytest.approx(-F)
    assert np.max(np.abs(reac_b[1:])) < 1.0e-9 * F


def test_damping_is_left_out_and_excit_replaces_the_result_loads(tmp_path):
    done = run(
        tmp_path,
        """V = CALC_CHAMP(RESULTAT=U, FORCE="REAC_NODA", NUME_ORDRE=(5, 7),
               EXCIT=_F(CHARGE=TIRE, COEF_MULT=3.0))
U = CALC_CHAMP(reuse=U, RESULTAT=U, FORCE="REAC_NODA")""",
        damping=True,
    )
    assert done.status == "DONE", done
    result = done.concepts.raw["U"]
    _, v_b = columns(result, "VITE")
    _, reac_b = columns(result, "REAC_NODA")
    # code_aster neglects C v in REAC_NODA: what is left at NB is -c v
    np.testing.assert_allclose(reac_b[1:], -30.0 * v_b[1:], rtol=1e-8, atol=1e-9 * F)
    _, reac_v = columns(done.concepts.raw["V"], "REAC_NODA")
    # EXCIT gives the loads instead of the result's: 3 F instead of F
    np.testing.assert_allclose(reac_v[[5, 7]], reac_b[[5, 7]] - 2.0 * F, rtol=1e-12)
    assert np.isnan(np.delete(reac_v, [5, 7])).all()


def test_crea_table_resu_of_a_field_on_the_dofs(tmp_path):
    done = run(
        tmp_path,
        """U = CALC_CHAMP(reuse=U, RESULTAT=U, FORCE="REAC_NODA")
TD = CREA_TABLE(RESU=_F(RESULTAT=U, NOM_CHAM="DEPL", TOUT_CMP="OUI", TOUT="OUI"))
TR = CREA_TABLE(RESU=_F(RESULTAT=U, NOM_CHAM="REAC_NODA", NOM_CMP="DX", GROUP_NO="GA",
                        NUME_ORDRE=(3, 4)))""",
    )
    assert done.status == "DONE", done
    result = done.concepts.raw["U"]
    depl = done.concepts.raw["TD"]
    assert list(depl.types)[:5] == ["RESULTAT", "NOM_CHAM", "INST", "NUME_ORDRE", "NOEUD"]
    assert len(depl.rows) == 2 * result.times.size  # every order, both nodes
    _, u_b = columns(result, "DEPL")
    rows_b = [row for row in depl.rows if row["NOEUD"] == "2"]  # NB, node number 2
    np.testing.assert_array_equal([row["DX"] for row in rows_b], u_b)
    assert rows_b[7]["INST"] == pytest.approx(result.times[7]) and rows_b[7]["DY"] == 0.0
    reac = done.concepts.raw["TR"]
    reac_a, _ = columns(result, "REAC_NODA")
    assert [(row["NUME_ORDRE"], row["NOEUD"]) for row in reac.rows] == [(3, "1"), (4, "1")]
    np.testing.assert_array_equal([row["DX"] for row in reac.rows], reac_a[[3, 4]])
    assert "DY" not in reac.types


def test_reactions_of_a_harmonic_response_are_its_exact_solution(tmp_path):
    # F e^{iωt} on NB: u_B = F / (k - m ω²); REAC_NODA at NA is -k u_B, at NB
    # the equation of motion leaves nothing (undamped). code_aster reads a
    # dyna_harmo's loads from CALC_CHAMP's EXCIT: without it, refused
    harmonic = """H = DYNA_VIBRA(TYPE_CALCUL="HARM", BASE_CALCUL="PHYS",
               MODELE=MODELE, CARA_ELEM=CARA,
               MATR_MASS=MATRMASS, MATR_RIGI=MATRRIGI, FREQ=(5.0, 30.0), TOUT_CHAM="OUI",
               EXCIT=_F(CHARGE=TIRE, COEF_MULT=1.0))
H = CALC_CHAMP(reuse=H, RESULTAT=H, FORCE=("FORC_NODA", "REAC_NODA"),
               EXCIT=_F(CHARGE=TIRE, COEF_MULT_C=1.0 + 0.0j))"""
    done = run(tmp_path, harmonic)
    assert done.status == "DONE", done
    result = done.concepts.raw["H"]
    omega = 2.0 * np.pi * np.array([5.0, 30.0])
    u_b = F / (K - M * omega**2)
    _, depl_b = columns(result, "DEPL")
    np.testing.assert_allclose(depl_b, u_b, rtol=1e-12)
    reac_a, reac_b = columns(result, "REAC_NODA")
    np.testing.assert_allclose(reac_a, -K * u_b, rtol=1e-12)
    assert np.max(np.abs(reac_b)) < 1e-9 * F
    _, forc_b = columns(result, "FORC_NODA")
    np.testing.assert_allclose(forc_b, K * u_b, rtol=1e-12)
    refused = run(
        tmp_path,
        harmonic.split("\nH = CALC_CHAMP")[0]
        + '\nH = CALC_CHAMP(reuse=H, RESULTAT=H, FORCE="REAC_NODA")',
    )
    assert refused.status == "UNSUPPORTED"
