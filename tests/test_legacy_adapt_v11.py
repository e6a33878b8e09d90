"""code_aster 10-12's ADAPT_ORDRE2 (mdadap) for decks of those versions, and
the version line `asterlite port` writes when a deck relies on it."""

import math
from types import SimpleNamespace

import numpy as np
import pytest

from asterlite.dynamics import scheme_adapt_ordre2_v11 as V11
from asterlite.legacy.port import port_text
from asterlite.legacy.v15 import OLD_BEHAVIOURS, computes
from asterlite.legacy.version import (
    CURRENT,
    deck_version,
    pragma_needed,
    pragma_version,
    with_pragma,
)
from commands import dyna_vibra
from tests.test_dynamics_vibra import ctx, kws, one_mode, vector
from tests.validated import occurrence

OMEGA = 2.0 * math.pi
V11_ADAPT = (
    "DEBUT()\nTR = DYNA_TRAN_MODAL(MATR_MASS=M, MATR_RIGI=K, SCHEMA_TEMPS=_F("
    "SCHEMA='ADAPT_ORDRE2'), INCREMENT=_F(INST_FIN=1., PAS=1.E-5, PAS_MAXI=1.E-4), "
    "ARCHIVAGE=_F(PAS_ARCH=10))\nTEST_TABLE(TABLE=T, NOM_PARA='X', VALE=2.5)\nFIN()\n"
)


# ------------------------------------------------------------------ version line


def deck_session(tmp_path, text, aster_version=None):
    """A session whose run reads the deck ``text``."""
    deck = tmp_path / "deck.comm"
    deck.write_text(text)
    return SimpleNamespace(aster_version=aster_version, run=SimpleNamespace(deck_files=[deck]))


def test_a_version_line_wins_over_the_markers_for_what_syntax_cannot_say(tmp_path):
    modern = "DEBUT()\nTEST_TABLE(TABLE=T, NOM_PARA='X', VALE_CALC=2.5)\nFIN()\n"
    stated = deck_session(tmp_path, with_pragma(modern, 11))
    assert computes(stated, "ADAPT_ORDRE2_MDADAP")  # the line's version
    # the rest of a ported deck is today's meaning: its markers decide
    assert not computes(stated, "TEST_RESU_GENE_NUME_ORDRE_AS_POSITION")
    assert deck_version(with_pragma(modern, 11)) == CURRENT
    assert not computes(deck_session(tmp_path, modern), "ADAPT_ORDRE2_MDADAP")
    # --aster-version overrides both
    assert not computes(deck_session(tmp_path, with_pragma(modern, 11), 17), "ADAPT_ORDRE2_MDADAP")
    assert computes(deck_session(tmp_path, V11_ADAPT), "ADAPT_ORDRE2_MDADAP")  # markers: 11
    assert pragma_version("#asterlite:aster-version 12\nDEBUT()\n") == 12
    assert pragma_version("x = 1  # asterlite: aster-version 12\n") is None  # a line of its own


def test_with_pragma_replaces_the_line():
    once = with_pragma("DEBUT()\n", 11)
    assert once.splitlines()[0] == "# asterlite: aster-version 11"
    assert with_pragma(once, 12).count("aster-version") == 1
    assert with_pragma(once, None) == "DEBUT()\n"


def test_only_decks_relying_on_an_inexpressible_behaviour_need_the_line():
    assert OLD_BEHAVIOURS["ADAPT_ORDRE2_MDADAP"] == (0, 12)
    assert pragma_needed(V11_ADAPT, 11)[0]
    assert not pragma_needed(V11_ADAPT, CURRENT)[0]
    assert not pragma_needed(V11_ADAPT.replace("ADAPT_ORDRE2", "EULER"), 11)[0]
    assert not pragma_needed(V11_ADAPT.replace("ADAPT_ORDRE2", "ADAPT_ORDRE1"), 11)[0]
    wear = "DEBUT()\nT = POST_DYNA_MODA_T(RESU_GENE=TR, CHOC=_F(OPTION='USURE'))\nFIN()\n"
    assert pragma_needed(wear, 15)[0] and not pragma_needed(wear, 16)[0]


def test_port_states_the_version_of_a_deck_relying_on_mdadap():
    result = port_text(V11_ADAPT, "deck.comm", version=11)
    assert result.text.startswith("# asterlite: aster-version 11\n")
    assert "DYNA_VIBRA" in result.text and "ADAPT_ORDRE2" in result.text
    assert pragma_version(result.text) == 11 and deck_version(result.text) == CURRENT
    assert not result.skipped and "ADAPT_ORDRE2_MDADAP" in result.notes[0].old
    again = port_text(result.text, "deck.comm")  # porting a ported deck: one line, same version
    assert again.text.count("aster-version") == 1 and pragma_version(again.text) == 11


def test_port_writes_no_line_for_a_deck_today_s_syntax_expresses():
    text = V11_ADAPT.replace("ADAPT_ORDRE2", "EULER")
    result = port_text(text, "deck.comm", version=11)
    assert pragma_version(result.text) is None
    assert deck_version(result.text) == CURRENT


# ------------------------------------------------------------------ the scheme


def test_planned_slots_follow_the_archive_grid():
    slots = V11.planned_slots.py_func
    assert slots(0.0, 1.0, 1.0e-3) == 1001
    assert slots(0.0, 1.0, 3.0e-1) == 5  # 0, .3, .6, .9 and the end


def v11_oscillator(schema, pas=1.0e-3, t_end=1.0):
    """Undamped 1 Hz oscillator run as a code_aster 11 deck ran it."""
    gnum, m, kk = one_mode(OMEGA**2, coords=(0.0, 0.0, 0.0), shape=(1.0, 0.0, 0.0))
    context = ctx()
    context.session.aster_version = 11
    kw = kws(
        TYPE_CALCUL="TRAN",
        BASE_CALCUL="GENE",
        MATR_MASS=m,
        MATR_RIGI=kk,
        SCHEMA_TEMPS=[occurrence("SCHEMA_TEMPS", {"SCHEMA": "ADAPT_ORDRE2", **schema})],
        INCREMENT=[kws("DYNA_VIBRA/INCREMENT", PAS=pas, INST_FIN=t_end)],
        ETAT_INIT=[kws("DYNA_VIBRA/ETAT_INIT", VITE=vector(gnum, OMEGA, "VITE"))],
        ARCHIVAGE=[kws("DYNA_VIBRA/ARCHIVAGE", PAS_ARCH=5)],
    )
    return dyna_vibra.run(context, kw)


@pytest.mark.slow  # compiles the scheme's loop
def test_without_pas_maxi_the_v11_scheme_grows_to_a_twentieth_of_the_period():
    """code_aster 10-12's default PAS_MAXI (mdptem): 1/20 of the shortest
    period, here the 1 Hz mode's (NB_POIN_PERIODE=5 lets the step grow)."""
    result = v11_oscillator({"NB_POIN_PERIODE": 5}, pas=1.0e-3)
    assert result.info["max_step"] == pytest.approx(1.0 / 20.0)


@pytest.mark.slow  # compiles the scheme's loop (a minute or more on a loaded machine)
def test_v11_scheme_archives_the_nearest_step_and_fills_the_slots():
    result = v11_oscillator({"PAS_MAXI": 4.0e-3}, pas=1.0e-3)
    spacing = 4.0e-3 * 5
    times = np.asarray(result.times)
    assert len(times) == V11.planned_slots.py_func(0.0, 1.0, spacing)  # 51
    grid = np.arange(len(times)) * spacing
    # never landing on the grid: each archived instant is a computed one, at
    # most half a step away, and some are off it
    assert np.all(np.abs(times[:-1] - grid[:-1]) <= 0.5 * 4.0e-3 + 1e-12)
    assert np.max(np.abs(times[1:-1] - grid[1:-1])) > 1.0e-9
    assert result.info["max_step"] == pytest.approx(4.0e-3)  # grew from PAS to PAS_MAXI
    q_exact = np.sin(OMEGA * times)
    assert np.max(np.abs(np.asarray(result.depl)[:, 0] - q_exact)) < 0.05
