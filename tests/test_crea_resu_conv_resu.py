"""CREA_RESU CONV_RESU (a result's field as a dyna_trans's DEPL or an
evol_char's FORC_NODA) and the EVOL_CHAR load it feeds, on the spring-mass
system of test_calc_champ_nodal_forces (spring k from the clamped NA to NB
of mass m, step force F on NB through the load TIRE)."""

from __future__ import annotations

import numpy as np
import pytest

from tests.test_calc_champ_nodal_forces import F, columns, run

# the step force F on NB as a history: a DEPL field DX = F at NB, stored at
# 0 and 0.2 s, turned into the FORC_NODA of an evol_char
HISTORY = f"""CHF = CREA_CHAMP(OPERATION="AFFE", TYPE_CHAM="NOEU_DEPL_R", MAILLAGE=MAIL,
                AFFE=(_F(TOUT="OUI", NOM_CMP=("DX", "DY", "DZ"), VALE=(0.0, 0.0, 0.0)),
                      _F(GROUP_NO="GB", NOM_CMP="DX", VALE={F})))
DF = CREA_RESU(OPERATION="AFFE", TYPE_RESU="DYNA_TRANS",
               AFFE=_F(NOM_CHAM="DEPL", CHAM_GD=CHF, INST=(0.0, 0.2)))
LINST = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=0.2, PAS=1.0e-4))
LRESU = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=0.2, PAS=0.2))
EV = CREA_RESU(OPERATION="CONV_RESU", TYPE_RESU="EVOL_CHAR",
               CONV_RESU=_F(RESU_INIT=DF, NOM_CHAM_INIT="DEPL", NUME_DDL=NUMEROTA,
                            LIST_INST=LRESU))
CHEV = AFFE_CHAR_MECA(MODELE=MODELE, EVOL_CHAR=EV)
V = DYNA_VIBRA(TYPE_CALCUL="TRAN", BASE_CALCUL="PHYS", MODELE=MODELE, CARA_ELEM=CARA,
               MATR_MASS=MATRMASS, MATR_RIGI=MATRRIGI, SCHEMA_TEMPS=_F(SCHEMA="NEWMARK"),
               EXCIT=(_F(CHARGE=BLOCAGE), _F(CHARGE=CHEV)),
               INCREMENT=_F(INST_INIT=0.0, INST_FIN=0.2, PAS=1.0e-4))"""


def test_an_evol_char_load_is_the_load_it_was_made_from(tmp_path):
    done = run(tmp_path, HISTORY)
    assert done.status == "DONE", done
    with_load = done.concepts.raw["U"]
    with_history = done.concepts.raw["V"]
    forces = np.asarray(done.concepts.raw["EV"].fields["FORC_NODA"])
    assert forces.shape[0] == 2 and done.concepts.raw["EV"].aster_type == "evol_char"
    np.testing.assert_array_equal(columns(done.concepts.raw["EV"], "FORC_NODA")[1], F)
    reference = columns(with_load, "DEPL")[1]
    # the same motion to round-off (the history is summed apart from the vector loads)
    np.testing.assert_allclose(
        columns(with_history, "DEPL")[1], reference, rtol=0, atol=1e-10 * np.abs(reference).max()
    )


def test_conv_resu_delays_the_interface_nodes_and_scales(tmp_path):
    # NB is 1 m from COOR_REFE along DIRECTION: at 1/(3.5 dt) m/s its delay
    # is 3.5 steps, of which code_aster keeps the whole steps (3)
    dt = 1.0e-4
    done = run(
        tmp_path,
        f"""LRESU = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=0.01, PAS={dt}))
D = CREA_RESU(OPERATION="CONV_RESU", TYPE_RESU="DYNA_TRANS",
              CONV_RESU=_F(RESU_INIT=U, NOM_CHAM_INIT="ACCE", MATR_RIGI=MATRRIGI,
                           LIST_INST=LRESU, COEF=2.0, GROUP_NO_INTERF="GB",
                           COOR_REFE=(0.0, 0.0, 0.0), DIRECTION=(2.0, 0.0, 0.0),
                           VITE_ONDE={1.0 / (3.5 * dt)}))
E = CREA_RESU(OPERATION="CONV_RESU", TYPE_RESU="DYNA_TRANS",
              CONV_RESU=_F(RESU_INIT=U, NOM_CHAM_INIT="ACCE", MATR_RIGI=MATRRIGI,
                           INST=(0.001, 0.002), DDL_EXCLUS="DX"))""",
    )
    assert done.status == "DONE", done
    source = done.concepts.raw["U"]
    delayed = done.concepts.raw["D"]
    assert list(delayed.fields) == ["DEPL"]
    assert delayed.times.size == 101
    np.testing.assert_allclose(delayed.times, source.times[:101], atol=1e-15)
    _, acce_b = columns(source, "ACCE")
    _, depl_b = columns(delayed, "DEPL")
    assert np.all(depl_b[:3] == 0.0)  # no stored instant 3 steps before
    np.testing.assert_array_equal(depl_b[3:], 2.0 * acce_b[: 101 - 3])
    excluded = done.concepts.raw["E"]
    assert np.all(np.asarray(excluded.fields["DEPL"]) == 0.0)  # every DX excluded
    assert excluded.times.tolist() == pytest.approx([0.001, 0.002])


def test_an_evol_char_is_not_extrapolated(tmp_path):
    # code_aster stops when the load history has no forces at an instant
    done = run(
        tmp_path, HISTORY.replace("INST_FIN=0.2, PAS=1.0e-4))", "INST_FIN=0.3, PAS=1.0e-4))")
    )
    assert done.status == "ERROR"
    assert "no forces at INST=0.2001" in (tmp_path / "out" / "message.log").read_text()


def test_conv_resu_formulas_and_nappes_of_the_components(tmp_path):
    # FONC_DX a nappe of (DX, INST) equal to DX + INST (DEFI_NAPPE, linear in
    # DX between its two functions of INST), FONC_DZ a formula 3 DX: both of
    # the source's DX; the field keeps its name (ACCE)
    done = run(
        tmp_path,
        """LRESU = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=0.01, PAS=1.0e-4))
F0 = DEFI_FONCTION(NOM_PARA="INST", VALE=(0.0, 0.0, 1.0, 1.0),
                   PROL_DROITE="LINEAIRE", PROL_GAUCHE="LINEAIRE")
F1 = DEFI_FONCTION(NOM_PARA="INST", VALE=(0.0, 1.0, 1.0, 2.0))
NDX = DEFI_NAPPE(NOM_PARA="DX", PARA=(0.0, 1.0), FONCTION=(F0, F1),
                 PROL_DROITE="LINEAIRE", PROL_GAUCHE="LINEAIRE")
N2 = DEFI_NAPPE(NOM_PARA="AMOR", PARA=(0.0, 1.0), NOM_PARA_FONC="FREQ",
                DEFI_FONCTION=(_F(VALE=(1.0, 1.0, 2.0, 2.0)), _F(VALE=(1.0, 3.0, 2.0, 5.0))))
FDZ = FORMULE(NOM_PARA=("DX", "INST"), VALE="3.0 * DX")
G = CREA_RESU(OPERATION="CONV_RESU", TYPE_RESU="DYNA_TRANS",
              CONV_RESU=_F(RESU_INIT=U, NOM_CHAM_INIT="ACCE", MATR_RIGI=MATRRIGI,
                           LIST_INST=LRESU, FONC_DX=NDX, FONC_DZ=FDZ))""",
    )
    assert done.status == "DONE", done
    source, made = done.concepts.raw["U"], done.concepts.raw["G"]
    assert list(made.fields) == ["ACCE"]
    _, acce_b = columns(source, "ACCE")
    b = made.numbering.dof_index("NB", "DX")
    dz = made.numbering.dof_index("NB", "DZ")
    values = np.asarray(made.fields["ACCE"])
    np.testing.assert_allclose(values[:, b], acce_b[:101] + made.times, rtol=1e-12)
    np.testing.assert_allclose(values[:, dz], 3.0 * acce_b[:101], rtol=1e-12)
    nappe = done.concepts.raw["N2"]
    assert nappe.NOM_PARA_FONC == "FREQ"
    assert nappe(0.5, 1.5) == pytest.approx(0.5 * 1.5 + 0.5 * 4.0)


def test_kucv_and_defi_char_sol_from_a_result(tmp_path):
    # KUCV: C v + K u of the result at each instant; DEFI_CHAR_SOL builds its
    # EVOL_CHAR load with KUCV (ONDE_PLANE) or CONV_RESU (FORCE, times COEF)
    done = run(
        tmp_path,
        """U = CALC_CHAMP(reuse=U, RESULTAT=U, FORCE="REAC_NODA")
LRESU = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=0.01, PAS=1.0e-4))
K = CREA_RESU(OPERATION="KUCV", TYPE_RESU="EVOL_CHAR",
              KUCV=_F(RESU_INIT=U, MATR_AMOR=MATRAMOR, MATR_RIGI=MATRRIGI, LIST_INST=LRESU))
SOL1 = DEFI_CHAR_SOL(CHARGEMENT="ONDE_PLANE", MODELE=MODELE, RESU_INIT=U, MATR_AMOR=MATRAMOR,
                     LIST_INST=LRESU)
SOL2 = DEFI_CHAR_SOL(MODELE=MODELE, RESU_INIT=U, NOM_CHAM_INIT="REAC_NODA", COEF=-2.0,
                     NUME_DDL=NUMEROTA, LIST_INST=LRESU)""",
        damping=True,
    )
    assert done.status == "DONE", done
    source = done.concepts.raw["U"]
    _, u_b = columns(source, "DEPL")
    _, v_b = columns(source, "VITE")
    _, reac_b = columns(source, "REAC_NODA")
    k_forces = done.concepts.raw["K"]
    a_side, b_side = columns(k_forces, "FORC_NODA")
    # spring k and dashpot c = 30 between NA (fixed) and NB
    np.testing.assert_allclose(b_side, 30.0 * v_b[:101] + 4.0e4 * u_b[:101], rtol=1e-12)
    np.testing.assert_allclose(a_side, -b_side, rtol=1e-12)
    wave = done.concepts.raw["SOL1"].extra["EVOL_CHAR"]
    np.testing.assert_allclose(columns(wave, "FORC_NODA")[1], 30.0 * v_b[:101], rtol=1e-12)
    force = done.concepts.raw["SOL2"].extra["EVOL_CHAR"]
    np.testing.assert_array_equal(columns(force, "FORC_NODA")[1], -2.0 * reac_b[:101])
