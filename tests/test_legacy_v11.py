"""code_aster 10-11 forms that are values, not renames (asterlite.legacy.v11), and
the macros of that era (MACRO_MATR_ASSE, MACRO_PROJ_BASE): small decks written
as in 2011, run unmodified, with checks whose verdicts follow code_aster 11."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from asterlite.errors import UnsupportedError
from asterlite.legacy import v11
from asterlite.runtime.runner import run_deck

# a 1-dof oscillator: a spring N1-N2 (N1 clamped), a point mass on N2 given on a
# node group (no point cell in the mesh), groups written with the old prefixes
MESH = """\
COOR_3D
N1 0. 0. 0.
N2 1. 0. 0.
FINSF
SEG2
S1 N1 N2
FINSF
GROUP_MA NOM=GROUP_MA_RESSORT
S1
FINSF
GROUP_NO NOM=GROUP_NO_ENCASTRE
N1
FINSF
GROUP_NO NOM=MASSE
N2
FINSF
FIN
"""

K, M = 1.0e4, 4.0
FREQ = math.sqrt(K / M) / (2 * math.pi)

OSCILLATOR = """\
DEBUT()
K = 1.E4
M = 4.
MA = LIRE_MAILLAGE()
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=(
    _F(GROUP_MA='RESSORT', PHENOMENE='MECANIQUE', MODELISATION='DIS_T'),
    _F(GROUP_NO='MASSE', PHENOMENE='MECANIQUE', MODELISATION='DIS_T')))
CA = AFFE_CARA_ELEM(MODELE=MO, DISCRET=(
    _F(GROUP_MA='RESSORT', CARA='K_T_D_L', VALE=(K, K, K)),
    _F(GROUP_NO='MASSE', CARA='M_T_D_N', VALE=M)))
CL = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(
    _F(GROUP_NO='ENCASTRE', DX=0., DY=0., DZ=0.),
    _F(GROUP_NO='MASSE', DY=0., DZ=0.)))
MACRO_MATR_ASSE(MODELE=MO, CARA_ELEM=CA, CHARGE=CL, NUME_DDL=CO('NU'),
    MATR_ASSE=(_F(MATRICE=CO('MASS'), OPTION='MASS_MECA'),
               _F(MATRICE=CO('RIGI'), OPTION='RIGI_MECA')))
MODES = CALC_MODES(MATR_RIGI=RIGI, MATR_MASS=MASS, OPTION='PLUS_PETITE',
                   CALC_FREQ=_F(NMAX_FREQ=1))
MODES = NORM_MODE(reuse=MODES, MODE=MODES, NORME='MASS_GENE')
"""


def _run(tmp_path: Path, body: str, name: str = "deck"):
    (tmp_path / "mesh.mail").write_text(MESH)
    (tmp_path / f"{name}.comm").write_text(OSCILLATOR + body + "FIN()\n")
    export = tmp_path / f"{name}.export"
    export.write_text(f"F comm {name}.comm D 1\nF mail mesh.mail D 20\n")
    return run_deck(export, tmp_path / "out")


def _verdicts(report) -> list[str]:
    return [t.verdict for t in report.tests]


def _log(tmp_path: Path) -> str:
    return (tmp_path / "out" / "message.log").read_text()


# ------------------------------------------------------------------ version


def test_version_from_text():
    assert v11.deck_version("MACRO_PROJ_BASE(BASE=M)") == 11
    assert v11.deck_version("TEST_RESU(RESU=_F(VALE=1.))") == 11
    # a current deck: no version, or today's (asterlite.legacy.version)
    assert (v11.deck_version("TEST_RESU(RESU=_F(VALE_CALC=1.))") or 99) > 11
    assert (v11.deck_version("DYNA_VIBRA(TYPE_CALCUL='TRAN')") or 99) > 11


def test_modern_check_left_as_written():
    level = {"VALE_CALC": 1.0, "VALE": 2.0}
    assert v11.reference_check(level, {"VALE": ""}, 1e-3) is None


# --------------------------------------------------- elements, macros, checks


def test_oscillator_of_2011_runs(tmp_path):
    """Point mass on a node group, prefixed mesh groups, MACRO_MATR_ASSE, and a
    TEST_RESU VALE= checked at its PRECISION (1e-6: the frequency is exact)."""
    report = _run(
        tmp_path,
        f"TEST_RESU(RESU=_F(RESULTAT=MODES, NUME_ORDRE=1, PARA='FREQ', VALE={FREQ!r},"
        " PRECISION=1.E-6))\n",
    )
    assert report.status == "PASS", report.message
    assert _verdicts(report) == ["OK"]
    log = _log(tmp_path)
    assert "GROUP_NO_ENCASTRE named ENCASTRE" in log
    assert "point elements on nodes" in log


def test_vale_is_checked_at_the_decks_precision(tmp_path):
    """code_aster 11 judged VALE= within PRECISION (here 1e-4 relative): a value
    2.6e-4 off is NOOK, though asterlite's non-regression tolerance is 1e-3."""
    body = (
        f"TEST_RESU(RESU=(_F(RESULTAT=MODES, NUME_ORDRE=1, PARA='FREQ', VALE={FREQ * 1.00026!r},"
        " PRECISION=1.E-4),\n"
        f"  _F(RESULTAT=MODES, NUME_ORDRE=1, PARA='FREQ', VALE={FREQ * 1.0009!r}),\n"
        f"  _F(RESULTAT=MODES, NUME_ORDRE=1, PARA='FREQ', VALE={FREQ + 0.005!r},"
        " CRITERE=('ABSOLU', 'RELATIF'), PRECISION=(1.E-2, 1.E-6))))\n"
    )
    report = _run(tmp_path, body)
    # 2.6e-4 > 1e-4: NOOK; 9e-4 < default 1e-3: OK; absolute 0.005 < 0.01: OK
    assert _verdicts(report) == ["NOOK", "OK", "OK"]


def test_test_table_default_precision_is_that_of_code_aster_11(tmp_path):
    """TEST_TABLE's PRECISION defaulted to 1.2e-3 (code_aster 10-11 catalogue)."""
    table = "TAB = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=(1.0,)))\n"
    body = table + "".join(
        f"TEST_TABLE(TABLE=TAB, NOM_PARA='X', VALE={v!r})\n" for v in (1.0011, 1.0013)
    )
    report = _run(tmp_path, body)
    assert _verdicts(report) == ["OK", "NOOK"]


def test_macro_proj_base_diag_default_and_old_type_vect(tmp_path):
    """MACRO_PROJ_BASE binds its CO outputs; VECT_ASSE_GENE without TYPE_VECT and
    PROJ_VECT_BASE without TYPE_VECT project a force (Φᵀ f = f / sqrt(M))."""
    body = """\
FO = AFFE_CHAR_MECA(MODELE=MO, FORCE_NODALE=_F(GROUP_NO='MASSE', FX=3.))
VE = CALC_VECT_ELEM(CHARGE=FO, OPTION='CHAR_MECA')
FA = ASSE_VECTEUR(VECT_ELEM=VE, NUME_DDL=NU)
MACRO_PROJ_BASE(BASE=MODES,
    MATR_ASSE_GENE=(_F(MATRICE=CO('MG'), MATR_ASSE=MASS), _F(MATRICE=CO('KG'), MATR_ASSE=RIGI)),
    VECT_ASSE_GENE=_F(VECTEUR=CO('FG'), VECT_ASSE=FA))
NG = NUME_DDL_GENE(BASE=MODES, STOCKAGE='DIAG')
FG2 = PROJ_VECT_BASE(BASE=MODES, NUME_DDL_GENE=NG, VECT_ASSE=FA)
TEST_RESU(GENE=(_F(RESU_GENE=FG, NUME_CMP_GENE=1, VALE=1.5, VALE_ABS='OUI', PRECISION=1.E-8),
                _F(RESU_GENE=FG2, NUME_CMP_GENE=1, VALE=1.5, VALE_ABS='OUI', PRECISION=1.E-8)))
"""
    report = _run(tmp_path, body)
    assert report.status == "PASS", report.message
    assert _verdicts(report) == ["OK", "OK"]
    assert "PROJ_VECT_BASE without TYPE_VECT" in _log(tmp_path)


def test_formule_reads_deck_variables_as_defined(tmp_path):
    """A 2011 FORMULE reads deck variables without passing them; it keeps the
    value they had when it was defined (code_aster 11's parent context)."""
    body = """\
OMEGA = 2.
F = FORMULE(NOM_PARA='INST', VALE='OMEGA*INST + M')
OMEGA = 100.
TAB = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=(F(3.),)))
TEST_TABLE(TABLE=TAB, NOM_PARA='X', VALE=10., PRECISION=1.E-12)
"""
    report = _run(tmp_path, body)
    assert report.status == "PASS", report.message
    assert "FORMULE reading deck variables" in _log(tmp_path)


def test_lame_fluide_is_refused_by_name(tmp_path):
    """The fluid film runs with EULER and ADAPT_ORDRE2 (tests/test_lame_fluide.py,
    tests/test_fluid_film_adapt.py); code_aster 11's ADAPT_ORDRE1 with a film
    is refused by name."""
    body = """\
MACRO_PROJ_BASE(BASE=MODES, MATR_ASSE_GENE=(_F(MATRICE=CO('MG'), MATR_ASSE=MASS),
                                             _F(MATRICE=CO('KG'), MATR_ASSE=RIGI)))
OBS = DEFI_OBSTACLE(TYPE='PLAN_Z')
TR = DYNA_TRAN_MODAL(MATR_MASS=MG, MATR_RIGI=KG, SCHEMA_TEMPS=_F(SCHEMA='ADAPT_ORDRE1'),
    INCREMENT=_F(INST_INIT=0., INST_FIN=0.01, PAS=1.E-4),
    CHOC=_F(NOEUD_1='N2', OBSTACLE=OBS, NORM_OBST=(0., 0., 1.), RIGI_NOR=1.E5,
            LAME_FLUIDE='OUI', ALPHA=0.1, BETA=0.1, CHI=0.1, DELTA=0.))
TEST_RESU(RESU=_F(RESULTAT=MODES, NUME_ORDRE=1, PARA='FREQ', VALE=1.))
"""
    report = _run(tmp_path, body)
    assert report.status == "UNSUPPORTED"
    assert "LAME_FLUIDE" in report.message and "code_aster 11" in report.message


class _Session:
    def __init__(self, path: Path):
        self.current_file = str(path)
        self.messages: list[str] = []

    def log(self, text: str) -> None:
        self.messages.append(text)


def test_modern_deck_is_not_adjusted(tmp_path):
    """A deck with VALE_CALC is not a code_aster 11 deck: its calls stay as written."""
    from asterlite.lang.values import CallSite

    call = {"BASE": None, "VECT_ASSE": None}
    modern = tmp_path / "modern.comm"
    modern.write_text("TEST_RESU(RESU=_F(VALE_CALC=1.))\n")
    assert v11.before_call("PROJ_VECT_BASE", call, CallSite(), _Session(modern)) == call
    old = tmp_path / "old.comm"
    old.write_text("TEST_RESU(RESU=_F(VALE=1.))\n")
    session = _Session(old)
    adjusted = v11.before_call("PROJ_VECT_BASE", call, CallSite(), session)
    assert adjusted == {**call, "TYPE_VECT": "FORC"}
    assert len(session.messages) == 1


def _adjust(tmp_path, command: str, call: dict) -> tuple[dict, list[str]]:
    """``call`` as before_call adjusts it in a code_aster 11 deck, and the notes."""
    from asterlite.lang.values import CallSite

    deck = tmp_path / "old.comm"
    deck.write_text("TEST_RESU(RESU=_F(VALE=1.))\n")
    session = _Session(deck)
    return v11.before_call(command, call, CallSite(), session), session.messages


def test_devoge_keeps_the_decks_step(tmp_path):
    call = {"SCHEMA_TEMPS": {"SCHEMA": "DEVOGE"}, "INCREMENT": {"PAS": 1.0e-4, "INST_FIN": 1.0}}
    adjusted, notes = _adjust(tmp_path, "DYNA_TRAN_MODAL", call)
    assert adjusted["INCREMENT"]["PAS_MINI"] == adjusted["INCREMENT"]["PAS_MAXI"] == 1.0e-4
    euler = {"SCHEMA_TEMPS": {"SCHEMA": "EULER"}, "INCREMENT": {"PAS": 1.0e-4}}
    assert _adjust(tmp_path, "DYNA_TRAN_MODAL", euler)[0] == euler


def test_excit_of_code_aster_11(tmp_path):
    """EXCIT/VECT_ASSE became VECT_ASSE_GENE; EXCIT/MODE_STAT, the same in every
    occurrence, went to the top level."""
    stat = object()
    call = {"EXCIT": ({"VECT_ASSE": 1, "MODE_STAT": stat}, {"VECT_ASSE": 2, "MODE_STAT": stat})}
    adjusted, _ = _adjust(tmp_path, "DYNA_TRAN_MODAL", call)
    assert adjusted["MODE_STAT"] is stat
    assert [dict(o) for o in adjusted["EXCIT"]] == [{"VECT_ASSE_GENE": 1}, {"VECT_ASSE_GENE": 2}]
    other = {
        "EXCIT": ({"VECT_ASSE": 1, "MODE_STAT": stat}, {"VECT_ASSE": 2, "MODE_STAT": object()})
    }
    with pytest.raises(UnsupportedError):
        _adjust(tmp_path, "DYNA_TRAN_MODAL", other)


def test_interv_r_and_no_effect_keywords(tmp_path):
    adjusted, _ = _adjust(
        tmp_path, "DEFI_LIST_ENTI", {"OPERATION": "NUME_ORDRE", "INTERV_R": (1.0, 2.0)}
    )
    assert [dict(o) for o in adjusted["INTERVALLE"]] == [{"VALE": (1.0, 2.0)}]
    adjusted, notes = _adjust(tmp_path, "NUME_DDL", {"MATR_RIGI": 1, "METHODE": "LDLT"})
    assert adjusted == {"MATR_RIGI": 1} and "changes no result" in notes[0]
