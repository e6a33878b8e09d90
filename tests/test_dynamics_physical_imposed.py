"""Imposed motion in a PHYS transient: a DDL_IMPO load times a function
of time (EXCIT FONC_MULT), the constrained DOFs following the Newmark
scheme as in code_aster's dlnew0."""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from asterlite.concepts.assembly import LinearRelation
from asterlite.dynamics.physical import newmark
from asterlite.dynamics.physical.archive import Archive
from asterlite.dynamics.physical.imposed import newmark_states
from asterlite.dynamics.physical.system import build_system


class Sine:
    """sin(ω t) with the ``evaluate`` of a deck function."""

    def __init__(self, omega):
        self.omega = omega

    def evaluate(self, times):
        return np.sin(self.omega * np.asarray(times, dtype=float))


class ThreeNodes:
    """Nodes 0-1-2 on one component: springs 1e7 (0-1) and 1 (1-2), unit masses."""

    def __init__(self):
        self.dofs = [(0, "DX"), (1, "DX"), (2, "DX")]
        self.index = {dof: i for i, dof in enumerate(self.dofs)}
        self.n_dofs = 3
        self.relations = [LinearRelation([(0, "DX", 1.0)], 1.0)]

    def constraint_matrix(self, rhs_in_time=False):
        from asterlite.fem.constraints import relation_matrix

        return relation_matrix(self.relations, self.index, self.n_dofs)


def spring_chain():
    k1, k2 = 1.0e7, 1.0
    stiffness = np.array([[k1, -k1, 0.0], [-k1, k1 + k2, -k2], [0.0, -k2, k2]])
    return sp.csr_matrix(np.eye(3)), sp.csr_matrix(stiffness)


def test_base_driven_oscillator_matches_the_analytic_solution():
    # code_aster's sdld110a: node 0 moves as sin(2t), node 2 hangs on a unit
    # spring: x'' + x = sin(2t) from rest, x = (2 sin t - sin 2t) / 3
    numbering = ThreeNodes()
    mass, stiffness = spring_chain()
    system = build_system(numbering, mass, stiffness, None, [], [(np.array([1.0]), Sine(2.0))])
    times = np.linspace(0.0, 9.0, 361)
    q = np.zeros(system.n_free)
    archive = Archive(system.n_free)
    newmark.integrate(system, times, q, q.copy(), q.copy(), np.ones(times.size, bool), archive)
    out_t, out_q, _, _ = archive.arrays()
    depl = system.expand(out_q) + system.imposed_fields(np.arange(times.size))[0]
    exact = (2.0 * np.sin(out_t) - np.sin(2.0 * out_t)) / 3.0
    assert np.max(np.abs(depl[:, 2] - exact)) < 1.0e-3
    # code_aster's value of the same case (sdld110a, max |error| of DX at node 2)
    assert abs(np.max(np.abs(depl[:, 2] - exact)) - 4.491310788155012e-4) < 1.0e-9
    np.testing.assert_allclose(depl[:, 0], np.sin(2.0 * out_t), atol=1e-15)


def test_newmark_state_of_an_imposed_ramp_is_the_trapezoidal_rule():
    # average acceleration: (ċ_n + ċ_{n+1}) / 2 = (c_{n+1} - c_n) / dt, from ċ_0 = 0
    times = np.linspace(0.0, 1.0, 11)
    values = (3.0 * times)[:, None]
    c, c_dot, c_ddot = newmark_states(values, times, 0.25, 0.5)
    dt = times[1] - times[0]
    np.testing.assert_allclose((c_dot[1:] + c_dot[:-1]) / 2.0, np.diff(c, axis=0) / dt)
    np.testing.assert_allclose(c_dot[:, 0], np.where(np.arange(11) % 2 == 1, 6.0, 0.0), atol=1e-12)
    np.testing.assert_allclose((c_ddot[1:] + c_ddot[:-1]) / 2.0, np.diff(c_dot, axis=0) / dt)


class SineOfInst:
    """A deck function of INST (AFFE_CHAR_MECA_F): ``nom_para``, ``evaluate_many``."""

    nom_para = ("INST",)

    def evaluate_many(self, times):
        return np.sin(2.0 * np.asarray(times, dtype=float))


def test_a_relation_given_in_time_times_coef_mult_is_the_same_motion():
    from asterlite.concepts.assembly import ValueInTime
    from asterlite.dynamics.physical.imposed import ScaledInTime

    value = ValueInTime(SineOfInst(), (0.0, 0.0, 0.0))
    times = np.linspace(0.0, 9.0, 361)
    np.testing.assert_allclose(value.evaluate(times), np.sin(2.0 * times))
    # g(t) = 2 sin 2t with COEF_MULT=0.5, and FONC_MULT=sin 2t on u = 1: one motion
    doubled = ValueInTime(
        type("Twice", (SineOfInst,), {"evaluate_many": lambda s, t: 2 * np.sin(2 * t)})(), (0, 0, 0)
    )
    np.testing.assert_allclose(
        ScaledInTime(0.5, doubled).evaluate(times), Sine(2.0).evaluate(times)
    )
    mass, stiffness = spring_chain()
    runs = []
    for multiplier in (Sine(2.0), ScaledInTime(0.5, doubled)):
        system = build_system(
            ThreeNodes(), mass, stiffness, None, [], [(np.array([1.0]), multiplier)]
        )
        q = np.zeros(system.n_free)
        archive = Archive(system.n_free)
        newmark.integrate(system, times, q, q.copy(), q.copy(), np.ones(times.size, bool), archive)
        runs.append(system.expand(archive.arrays()[1]))
    np.testing.assert_allclose(runs[0], runs[1], rtol=1e-12, atol=1e-15)


MESH = """COOR_2D
P1 0.0 0.0
P2 1.0 0.0
P3 2.0 0.0
FINSF
SEG2
S1 P1 P2
S2 P2 P3
FINSF
GROUP_NO
P P1 P2 P3
FINSF
GROUP_NO
P1 P1
FINSF
GROUP_NO
P3 P3
FINSF
GROUP_MA
GRMA S1 S2
FINSF
GROUP_MA
S1 S1
FINSF
GROUP_MA
S2 S2
FINSF
FIN
"""

DECK = """DEBUT(CODE="OUI")
MA = LIRE_MAILLAGE(FORMAT="ASTER")
MA = CREA_MAILLAGE(MAILLAGE=MA, CREA_POI1=_F(NOM_GROUP_MA="P", GROUP_NO="P"))
MOD = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA=("GRMA", "P"), MODELISATION="2D_DIS_T",
                                       PHENOMENE="MECANIQUE"))
CARA = AFFE_CARA_ELEM(MODELE=MOD, DISCRET_2D=(
    _F(GROUP_MA="S1", CARA="K_T_D_L", VALE=(1.0e7, 1.0e7)),
    _F(GROUP_MA="S2", CARA="K_T_D_L", VALE=(1.0, 1.0)),
    _F(GROUP_MA="P", CARA="M_T_D_N", VALE=1.0)))
MOTION = FORMULE(VALE="2*sin(2*INST)", NOM_PARA="INST")
ZERO = DEFI_CONSTANTE(VALE=0.0)
CHAR = AFFE_CHAR_MECA_F(MODELE=MOD, DDL_IMPO=_F(GROUP_NO="P1", DX=MOTION, DY=ZERO))
LINST = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=9.0, NOMBRE=360))
ASSEMBLAGE(MODELE=MOD, CARA_ELEM=CARA, CHARGE=CHAR, NUME_DDL=CO("NUME"),
           MATR_ASSE=(_F(MATRICE=CO("RIGI"), OPTION="RIGI_MECA"),
                      _F(MATRICE=CO("MASSE"), OPTION="MASS_MECA")))
DYNA = DYNA_VIBRA(TYPE_CALCUL="TRAN", BASE_CALCUL="PHYS", MODELE=MOD, MATR_MASS=MASSE,
                  MATR_RIGI=RIGI, EXCIT=_F(CHARGE=CHAR, COEF_MULT=0.5),
                  SCHEMA_TEMPS=_F(SCHEMA="NEWMARK"), INCREMENT=_F(LIST_INST=LINST))
D1 = RECU_FONCTION(RESULTAT=DYNA, NOM_CHAM="DEPL", NOM_CMP="DX", GROUP_NO="P1")
D3 = RECU_FONCTION(RESULTAT=DYNA, NOM_CHAM="DEPL", NOM_CMP="DX", GROUP_NO="P3")
IMPR_FONCTION(FORMAT="TABLEAU", UNITE=30, COURBE=(_F(FONCTION=D1), _F(FONCTION=D3)))
EXACT = FORMULE(VALE="1./3 *(2 * sin(INST) - sin(2*INST))", NOM_PARA="INST")
GAP = FORMULE(VALE="abs(D3(INST)-EXACT(INST))", NOM_PARA="INST", D3=D3, EXACT=EXACT)
FGAP = CALC_FONC_INTERP(FONCTION=GAP, NOM_RESU="DEPL", LIST_PARA=LINST, NOM_PARA="INST")
TEST_TABLE(CRITERE="ABSOLU", REFERENCE="ANALYTIQUE", VALE_REFE=0.0,
           VALE_CALC=0.0004491310788155012, NOM_PARA="DEPL", TYPE_TEST="SOMM_ABS",
           TABLE=INFO_FONCTION(MAX=_F(FONCTION=FGAP)))
FIN()
"""


def test_affe_char_meca_f_ddl_impo_of_inst_drives_a_phys_transient(tmp_path):
    # sdld110a's base-driven oscillator, its motion 2 sin 2t given by
    # AFFE_CHAR_MECA_F and halved by COEF_MULT: code_aster's error figure
    from asterlite.runtime.runner import run_deck

    (tmp_path / "d.comm").write_text(DECK)
    (tmp_path / "d.mail").write_text(MESH)
    (tmp_path / "d.export").write_text("F comm d.comm D 1\nF mail d.mail D 20\nF libr f.txt R 30\n")
    report = run_deck(tmp_path / "d.export", tmp_path / "out")
    assert report.exit_code == 0, report.message
    rows = [
        line.split()
        for line in (tmp_path / "out" / "f.txt").read_text().splitlines()
        if line.strip() and line.split()[0][0] in "-0123456789"
    ]
    values = np.array(rows, dtype=float)  # D1 then D3, each (INST, DX)
    assert values.shape == (722, 2)
    times, d1, d3 = values[:361, 0], values[:361, 1], values[361:, 1]
    np.testing.assert_allclose(d1, np.sin(2.0 * times), atol=1e-6)  # 6 digits printed
    assert np.abs(d3 - (2.0 * np.sin(times) - np.sin(2.0 * times)) / 3.0).max() < 1.0e-3
    # the deck's TEST_TABLE: code_aster's figure of max |error| to its TOLE_MACHINE
    assert report.status == "PASS", report.message


def test_a_value_in_time_is_refused_where_the_right_hand_side_is_used_statically():
    import pytest

    from asterlite.concepts.assembly import DofNumbering, ValueInTime
    from asterlite.errors import UnsupportedError

    relation = LinearRelation([(0, "DX", 1.0)], 0.0, ValueInTime(SineOfInst(), (0.0, 0.0, 0.0)))
    numbering = DofNumbering(mesh=None, dofs=[(0, "DX")], relations=[relation])
    with pytest.raises(UnsupportedError, match="DDL_IMPO of INST"):
        numbering.constraint_matrix()
    b_matrix, rhs = numbering.constraint_matrix(rhs_in_time=True)
    assert b_matrix.shape == (1, 1) and rhs[0] == 0.0
