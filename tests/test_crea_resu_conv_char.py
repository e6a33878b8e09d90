"""CREA_RESU CONV_CHAR (the loads' nodal forces at each instant), its
CONV_RESU to an evol_char and the EVOL_CHAR load it feeds, on the
spring-mass system of test_calc_champ_nodal_forces (spring from the clamped
NA to NB, the step force F on NB through the load TIRE)."""

from __future__ import annotations

import numpy as np

from tests.test_calc_champ_nodal_forces import F, columns, run

CONVERTED = """ACIER = DEFI_MATERIAU(ELAS=_F(E=2.0e11, NU=0.3, RHO=7800.0))
CHMAT = AFFE_MATERIAU(MAILLAGE=MAIL, AFFE=_F(TOUT="OUI", MATER=ACIER))
LRESU = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=0.2, PAS=0.1))
CH = CREA_RESU(OPERATION="CONV_CHAR", TYPE_RESU="DYNA_TRANS",
               CONV_CHAR=_F(MATR_RIGI=MATRRIGI, CHAM_MATER=CHMAT, CHARGE=(BLOCAGE, TIRE),
                            PRECISION=1.0e-6, CRITERE="RELATIF", LIST_INST=LRESU))
EV = CREA_RESU(OPERATION="CONV_RESU", TYPE_RESU="EVOL_CHAR",
               CONV_RESU=_F(RESU_INIT=CH, NOM_CHAM_INIT="DEPL", MATR_RIGI=MATRRIGI,
                            COEF=1.0, LIST_INST=LRESU))
CHEV = AFFE_CHAR_MECA(MODELE=MODELE, EVOL_CHAR=EV)
V = DYNA_VIBRA(TYPE_CALCUL="TRAN", BASE_CALCUL="PHYS", MODELE=MODELE, CARA_ELEM=CARA,
               MATR_MASS=MATRMASS, MATR_RIGI=MATRRIGI, SCHEMA_TEMPS=_F(SCHEMA="NEWMARK"),
               EXCIT=(_F(CHARGE=BLOCAGE), _F(CHARGE=CHEV)),
               INCREMENT=_F(INST_INIT=0.0, INST_FIN=0.2, PAS=1.0e-4))"""


def test_conv_char_holds_the_nodal_forces_and_drives_the_same_motion(tmp_path):
    done = run(tmp_path, CONVERTED)
    assert done.status == "DONE", done
    converted = done.concepts.raw["CH"]
    assert converted.aster_type == "dyna_trans"
    assert np.asarray(converted.times).tolist() == [0.0, 0.1, 0.2]
    at_a, at_b = columns(converted, "DEPL")
    # F on DX of NB at every instant, nothing else (the clamping is no force)
    np.testing.assert_array_equal(at_b, F)
    np.testing.assert_array_equal(at_a, 0.0)
    assert np.count_nonzero(np.asarray(converted.fields["DEPL"])) == 3
    reference = columns(done.concepts.raw["U"], "DEPL")[1]
    np.testing.assert_allclose(
        columns(done.concepts.raw["V"], "DEPL")[1],
        reference,
        rtol=0,
        atol=1e-10 * np.abs(reference).max(),
    )
