"""Exit status 2 and a located message for every failure, internal ones
included: one line on the terminal, the traceback in message.log."""

from __future__ import annotations

import errno
import json

import pytest

from asterlite.cli import main
from asterlite.runtime import runner
from asterlite.runtime.runner import run_deck

DECK = """DEBUT()
T = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=(1.0, 2.0)))
IMPR_TABLE(UNITE=30, TABLE=T)
FIN()
"""


@pytest.fixture
def deck(tmp_path):
    path = tmp_path / "d.comm"
    path.write_text(DECK)
    return path


def broken_impr_table(error: BaseException, monkeypatch):
    import importlib

    command = importlib.import_module("asterlite.commands.impr_table")

    def run(ctx, kw):
        raise error

    monkeypatch.setattr(command, "run", run)


def test_an_internal_error_is_one_located_line_and_a_logged_traceback(
    tmp_path, deck, monkeypatch, capsys
):
    broken_impr_table(RuntimeError("bug in the table writer\nsecond line"), monkeypatch)
    out = tmp_path / "out"
    assert main(["run", str(deck), "-o", str(out), "-q"]) == 2
    printed = capsys.readouterr().err.strip().splitlines()
    assert len(printed) == 1 and "internal error, please report" in printed[0]
    assert f"{deck}:3:" in printed[0] and "second line" not in printed[0]
    log = (out / "message.log").read_text()
    assert "Traceback (most recent call last)" in log and "bug in the table writer" in log
    assert json.loads((out / "summary.json").read_text())["status"] == "ERROR"


def test_a_full_disk_is_a_located_error_with_status_2(tmp_path, deck, monkeypatch):
    broken_impr_table(OSError(errno.ENOSPC, "No space left on device", "fort.30"), monkeypatch)
    report = run_deck(deck, tmp_path / "out")
    assert report.status == "ERROR" and report.exit_code == 2
    assert "no space left" in report.message and f"{deck}:3:" in report.message
    assert "internal error" not in report.message


def test_a_memory_error_while_printing_the_report_is_status_2(tmp_path, deck, monkeypatch):
    def no_memory(report):
        raise MemoryError

    monkeypatch.setattr(runner, "format_summary", no_memory)
    assert main(["run", str(deck), "-o", str(tmp_path / "out")]) == 2


def test_an_export_naming_a_folder_as_deck_is_located(tmp_path):
    export = tmp_path / "x.export"
    export.write_text("F comm . D 1\n")
    report = run_deck(export, tmp_path / "out")
    assert report.status == "ERROR" and f"{export}:1" in report.message
    assert "not a file" in report.message


def test_only_nook_is_status_1(tmp_path):
    deck = tmp_path / "n.comm"
    deck.write_text(
        "DEBUT()\nF = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 1.0, 1.0, 3.0))\n"
        "TEST_FONCTION(VALEUR=_F(FONCTION=F, VALE_PARA=0.5, VALE_CALC=9.0))\nFIN()\n"
    )
    assert main(["run", str(deck), "-o", str(tmp_path / "out"), "-q"]) == 1
