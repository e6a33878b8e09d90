"""Run statuses and refusals: DONE for a deck without checks, DEBUT/POURSUITE
required, code_aster commands and modules asterlite lacks refused by name,
export R lines, time and memory limits."""

from __future__ import annotations

import json

import pytest

from asterlite.cli import main
from asterlite.runtime.runner import run_deck
from asterlite.watchdog import TimeLimitError
from tests.conftest import CORPUS


def write(folder, name: str, text: str):
    path = folder / name
    path.write_text(text)
    return path


# ------------------------------------------------------------------ DONE


def test_deck_without_checks_is_done_not_pass(tmp_path):
    deck = write(tmp_path, "d.comm", "DEBUT()\nL = DEFI_LIST_REEL(VALE=(1.0, 2.0))\nFIN()\n")
    out = tmp_path / "out"
    report = run_deck(deck, out)
    assert report.status == "DONE" and report.exit_code == 0, report.message
    assert json.loads((out / "summary.json").read_text())["status"] == "DONE"
    assert "d: DONE in" in (out / "message.log").read_text()
    assert main(["run", str(deck), "-o", str(tmp_path / "cli"), "-q"]) == 0


def test_deck_with_an_ok_check_still_passes(tmp_path):
    deck = write(
        tmp_path,
        "d.comm",
        "DEBUT()\nF = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 1.0, 1.0, 3.0))\n"
        "TEST_FONCTION(VALEUR=_F(FONCTION=F, VALE_PARA=0.5, VALE_CALC=2.0))\nFIN()\n",
    )
    assert run_deck(deck, tmp_path / "out").status == "PASS"


# ------------------------------------------------------------ DEBUT first


@pytest.mark.parametrize("text", ["", "# only a comment\nx = 1\n"])
def test_deck_without_debut_is_a_located_error(tmp_path, text):
    deck = write(tmp_path, "e.comm", text)
    report = run_deck(deck, tmp_path / "out")
    assert report.status == "ERROR" and report.exit_code == 2
    assert f"{deck}:1" in report.message and "DEBUT" in report.message
    check = run_deck(deck, check_only=True)
    assert check.status == "ERROR" and "DEBUT" in check.message


def test_command_before_debut_is_refused_where_it_is(tmp_path):
    deck = write(tmp_path, "e.comm", "x = 1\nL = DEFI_LIST_REEL(VALE=(1.0,))\nDEBUT()\nFIN()\n")
    report = run_deck(deck, tmp_path / "out")
    assert report.status == "ERROR"
    assert f"{deck}:2:" in report.message and "DEFI_LIST_REEL comes before" in report.message


# ------------------------------------------------- unknown code_aster names


def test_code_aster_command_asterlite_lacks_is_unsupported_by_name(tmp_path):
    deck = write(tmp_path, "u.comm", "DEBUT()\nx = 1\nR = LIRE_CHAMP(UNITE=20)\nFIN()\n")
    for report in (run_deck(deck, tmp_path / "out"), run_deck(deck, check_only=True)):
        assert report.status == "UNSUPPORTED" and report.exit_code == 2
        assert "LIRE_CHAMP is a code_aster command" in report.message
        assert f"{deck}:3:" in report.message


def test_command_known_only_to_code_aster_15_names_its_version(tmp_path):
    deck = write(tmp_path, "u.comm", "DEBUT()\nR = CALC_H(RESULTAT=1)\nFIN()\n")
    report = run_deck(deck, tmp_path / "out")
    assert report.status == "UNSUPPORTED" and "version 15" in report.message


def test_misspelled_command_stays_a_name_error(tmp_path):
    deck = write(tmp_path, "u.comm", "DEBUT()\nR = LIRE_RESUX(UNITE=20)\nFIN()\n")
    report = run_deck(deck, tmp_path / "out")
    assert report.status == "ERROR"
    assert "name 'LIRE_RESUX' is not defined" in report.message and f"{deck}:2:" in report.message


def test_command_imports_are_accepted(tmp_path):
    deck = write(
        tmp_path,
        "i.comm",
        "from code_aster.Commands import *\nfrom code_aster.Commands import DEBUT, FIN\n"
        "from code_aster import CA\nimport code_aster\nDEBUT()\nT = CA.TestCase()\n"
        "T.assertTrue(1 + 1 == 2)\nFIN()\n",
    )
    report = run_deck(deck, tmp_path / "out")
    assert report.status == "PASS", report.message


@pytest.mark.parametrize(
    "line, module",
    [
        ("from code_aster.Objects import Mesh", "code_aster.Objects"),
        ("from code_aster.Utilities import ExecutionParameter", "code_aster.Utilities"),
        ("import code_aster.MacroCommands.Utils", "code_aster.MacroCommands"),
        ("from code_aster.CA import MPI", "code_aster.CA"),
    ],
)
def test_other_code_aster_modules_are_unsupported_by_name(tmp_path, line, module):
    deck = write(tmp_path, "i.comm", f"DEBUT()\n{line}\nFIN()\n")
    report = run_deck(deck, tmp_path / "out")
    assert report.status == "UNSUPPORTED" and report.exit_code == 2, report.message
    assert module in report.message and f"{deck}:2:" in report.message


def test_ca_members_other_than_testcase_are_unsupported(tmp_path):
    deck = write(
        tmp_path, "i.comm", "from code_aster import CA\nDEBUT()\nm = CA.ThermalModel()\nFIN()\n"
    )
    report = run_deck(deck, tmp_path / "out")
    assert report.status == "UNSUPPORTED" and "code_aster.CA.ThermalModel" in report.message
    assert f"{deck}:3:" in report.message


def test_command_name_data_lists_both_versions():
    from asterlite.runtime.checking import code_aster_commands

    names = code_aster_commands()
    assert names["DYNA_VIBRA"] == "17" and names["DEFI_INTERF_DYNA"] == "17"
    assert names["CALC_H"] == "15"
    assert len(names) > 250


# ------------------------------------------------------------- export R / P


TABLE_DECK = (
    "DEBUT()\nT = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=(1.0, 2.0)))\n"
    "IMPR_TABLE(TABLE=T, UNITE=8)\nFIN()\n"
)


def test_r_line_copies_the_unit_written_by_the_deck(tmp_path):
    write(tmp_path, "t.comm", TABLE_DECK)
    export = write(
        tmp_path,
        "t.export",
        "F comm t.comm D 1\nR resu kept/t.resu R 8\nR base t.base R 0\nR mess t.mess R 6\n",
    )
    out = tmp_path / "out"
    report = run_deck(export, out)  # into the output folder, under the line's file name
    assert report.status == "DONE", report.message
    assert (out / "t.resu").read_text() == (out / "fort.8").read_text()
    assert not (tmp_path / "kept").exists()
    (tmp_path / "kept").mkdir()  # at the line's path: asked for, into an existing folder
    report = run_deck(export, out, result_paths=True)
    assert report.status == "DONE", report.message
    kept = tmp_path / "kept" / "t.resu"
    assert kept.read_text() == (out / "fort.8").read_text() and "X" in kept.read_text()
    log = (out / "message.log").read_text()
    assert "unit 8 copied to" in log and "code_aster database, not produced" in log


def test_r_line_is_not_copied_when_the_run_fails(tmp_path):
    write(tmp_path, "t.comm", TABLE_DECK.replace("FIN()", "x = 1 / 0\nFIN()"))
    export = write(tmp_path, "t.export", "F comm t.comm D 1\nR resu t.resu R 8\n")
    assert run_deck(export, tmp_path / "out").status == "ERROR"
    assert not (tmp_path / "t.resu").exists()


def test_export_limits_are_read_and_checked(tmp_path):
    from asterlite.io.export import ExportError, read_export

    write(tmp_path, "a.comm", "DEBUT()\nFIN()\n")
    export = write(tmp_path, "a.export", "P time_limit 60\nP memory_limit 512\nF comm a.comm D 1\n")
    run = read_export(export)
    assert (run.time_limit, run.memory_limit) == (60.0, 512.0)
    bad = write(tmp_path, "b.export", "P time_limit soon\nF comm a.comm D 1\n")
    with pytest.raises(ExportError, match="time_limit must be a positive number") as info:
        read_export(bad)
    assert "b.export:1" in str(info.value)


def test_time_limit_stops_the_run_between_commands(tmp_path):
    write(tmp_path, "t.comm", TABLE_DECK)
    export = write(tmp_path, "t.export", "P time_limit 0.000001\nF comm t.comm D 1\n")
    report = run_deck(export, tmp_path / "out")
    assert report.status == "ERROR" and report.exit_code == 2
    # the limit is past before the first command: the run stops there
    assert "t.comm:1:1: time limit exceeded" in report.message
    # the option overrides the export (0: no limit)
    assert run_deck(export, tmp_path / "again", time_limit=0).status == "DONE"


def test_time_limit_is_checked_at_the_time_loop_pauses(tmp_path, monkeypatch):
    """The compiled loop pauses every chunk of steps; the watchdog is asked
    there, and its error is located at the DYNA_VIBRA call."""
    from asterlite.dynamics import integrate

    deck = CORPUS / "sdnd100a" / "sdnd100a.export"
    if not deck.exists():
        pytest.skip("../shared/aster-corpus is not available")
    calls = []

    class ExpiredWatchdog:
        @staticmethod
        def check_limits():
            calls.append(1)
            raise TimeLimitError("the run's time limit of 1 s is exhausted")

    monkeypatch.setattr(integrate, "watchdog", ExpiredWatchdog)
    monkeypatch.setattr(integrate.StepBudget, "FIRST_CHUNK", 10)
    report = run_deck(deck, tmp_path / "out")
    assert calls and report.status == "ERROR"
    assert "time limit exceeded: DYNA_VIBRA" in report.message
    assert "sdnd100a.comm:" in report.message


def test_memory_limit_turns_a_failed_allocation_into_a_located_error(tmp_path):
    write(
        tmp_path,
        "m.comm",
        "DEBUT()\nL = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, NOMBRE=2000000000))\n"
        "FIN()\n",
    )
    export = write(tmp_path, "m.export", "P memory_limit 300\nF comm m.comm D 1\n")
    report = run_deck(export, tmp_path / "out")
    assert report.status == "ERROR" and report.exit_code == 2, report.message
    assert "memory limit exceeded: DEFI_LIST_REEL" in report.message
    assert "m.comm:2:" in report.message and "300 MB" in report.message


def test_kernel_compilation_counts_against_neither_limit():
    """numba compiles a kernel once per install: its time is not the study's,
    and the address-space cap is lifted while the compiler runs (a fresh
    install's first run of the bundled sample, 256 MB, once failed there)."""
    import numba
    import numpy as np

    from asterlite import watchdog

    watchdog.preload_engine()
    before = watchdog._compiling.seconds
    with watchdog.limits(seconds=600, megabytes=1):

        @numba.njit(cache=False)
        def total(values):  # a new function: compiled here, never cached
            result = 0.0
            for value in values:
                result += np.sin(value) ** 2
            return result

        assert total(np.ones(4)) == pytest.approx(4 * np.sin(1.0) ** 2)
    assert watchdog._compiling.seconds > before
