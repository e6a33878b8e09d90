"""The output folder contract (docs/safety.md): a run owns its folder, never
deletes, replaces or writes through what it did not make, moves an earlier
result aside, and says ERROR/INTERRUPTED in files written as it goes."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from asterlite.cli import main
from asterlite.runtime.outdir import LOCK_NAME, OutputFolder
from asterlite.runtime.runner import run_deck

TABLE_DECK = """DEBUT()
T = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=(1.0, 2.0)))
DEFI_FICHIER(UNITE=30, FICHIER={name!r})
IMPR_TABLE(UNITE=30, TABLE=T)
FIN()
"""
PLAIN_DECK = """DEBUT()
T = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=(1.0, 2.0)))
IMPR_TABLE(UNITE=30, TABLE=T)
FIN()
"""


def write(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.write_text(text)
    return path


def snapshot(folder: Path) -> dict:
    """Every entry under ``folder`` with its content (files) or kind."""
    found = {}
    for path in sorted(folder.rglob("*")):
        key = str(path.relative_to(folder))
        if path.is_symlink():
            found[key] = ("link", os.readlink(path))
        elif path.is_file():
            found[key] = path.read_bytes()
        else:
            found[key] = "dir"
    return found


def summary(folder: Path) -> dict:
    return json.loads((folder / "summary.json").read_text())


def only_run_files(folder: Path, before: set[str]) -> set[str]:
    """What the folder holds beyond ``before`` and the run's listed files."""
    listed = set(summary(folder)["output"]["files"])
    moved = summary(folder)["output"]["moved_aside"]
    return set(os.listdir(folder)) - before - listed - ({moved} if moved else set())


# ------------------------------------------------------------------ deletion


@pytest.mark.parametrize("name", [".git", "deck.comm"])
def test_a_deck_cannot_replace_what_the_folder_holds(tmp_path, name):
    out = tmp_path / "out"
    (out / ".git").mkdir(parents=True)
    (out / ".git" / "HEAD").write_text("ref: refs/heads/main\n")
    (out / "deck.comm").write_text("my deck\n")
    before = snapshot(out)
    deck = write(tmp_path, "d.comm", TABLE_DECK.format(name=name))
    report = run_deck(deck, out)
    assert report.status == "ERROR" and report.exit_code == 2
    assert f"{deck}:3:" in report.message and f"already holds '{name}'" in report.message
    after = snapshot(out)
    assert {k: v for k, v in after.items() if k in before} == before
    assert only_run_files(out, set(before)) == set()


@pytest.mark.parametrize(
    "name, why",
    [
        (".running", "keeps for itself"),
        (".asterlite-running", "keeps for itself"),
        ("message.log", "keeps for itself"),
        ("summary.json", "keeps for itself"),
        ("incomplete", "keeps for itself"),
        ("..", "not a file name"),
        (".", "not a file name"),
        ("/", "not a file name"),
    ],
)
def test_names_the_run_keeps_or_no_file_names_are_located_errors(tmp_path, name, why):
    out = tmp_path / "out"
    deck = write(tmp_path, "d.comm", TABLE_DECK.format(name=name))
    report = run_deck(deck, out)
    assert report.status == "ERROR" and report.exit_code == 2, report.message
    assert f"{deck}:3:" in report.message and why in report.message
    assert only_run_files(out, set()) == set()
    assert summary(out)["status"] == "ERROR"


def test_a_complete_run_holds_only_what_it_listed(tmp_path):
    out = tmp_path / "out"
    report = run_deck(write(tmp_path, "d.comm", PLAIN_DECK), out)
    assert report.status == "DONE", report.message
    assert set(os.listdir(out)) == set(summary(out)["output"]["files"])
    assert {"message.log", "summary.json", "fort.30"} == set(os.listdir(out))


# ------------------------------------------------------------- stale results


def test_an_earlier_result_is_moved_aside_before_anything_is_written(tmp_path):
    out = tmp_path / "out"
    first = run_deck(write(tmp_path, "d.comm", PLAIN_DECK), out)
    assert first.status == "DONE"
    failing = write(tmp_path, "e.comm", "DEBUT()\nx = 1 / 0\nFIN()\n")
    second = run_deck(failing, out)
    assert second.status == "ERROR"
    assert summary(out)["status"] == "ERROR"
    assert not (out / "fort.30").exists()  # the earlier table is not beside the new summary
    previous = [p for p in out.iterdir() if p.name.startswith("previous-")]
    assert len(previous) == 1
    assert json.loads((previous[0] / "summary.json").read_text())["status"] == "DONE"
    assert (previous[0] / "fort.30").exists()
    assert summary(out)["output"]["moved_aside"] == previous[0].name


def test_a_summary_that_is_not_ours_stops_the_run(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "summary.json").write_text("my notes\n")
    report = run_deck(write(tmp_path, "d.comm", PLAIN_DECK), out)
    assert report.status == "ERROR" and "not an asterlite summary" in report.message
    assert os.listdir(out) == ["summary.json"]
    assert (out / "summary.json").read_text() == "my notes\n"


# ------------------------------------------------------------------ symlinks


def test_a_symlinked_message_log_is_never_written_through(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    victim = tmp_path / "victim.txt"
    victim.write_text("precious\n")
    (out / "message.log").symlink_to(victim)
    report = run_deck(write(tmp_path, "d.comm", PLAIN_DECK), out)
    assert report.status == "ERROR" and report.exit_code == 2
    assert victim.read_text() == "precious\n"
    assert (out / "message.log").is_symlink()


def test_an_r_line_replaces_a_symlink_instead_of_writing_through_it(tmp_path):
    victim = tmp_path / "victim.txt"
    victim.write_text("precious\n")
    (tmp_path / "table.resu").symlink_to(victim)
    deck = write(tmp_path, "d.comm", PLAIN_DECK)
    export = write(tmp_path, "d.export", "F comm d.comm D 1\nR resu table.resu R 30\n")
    report = run_deck(export, tmp_path / "out")
    assert report.status == "DONE", report.message
    assert victim.read_text() == "precious\n"
    assert not (tmp_path / "table.resu").is_symlink()
    assert "X" in (tmp_path / "table.resu").read_text()
    assert deck.exists()


# ------------------------------------------------------------------- locking


def test_a_second_run_into_a_locked_folder_is_refused(tmp_path):
    out = tmp_path / "out"
    holder = OutputFolder(out).open()
    try:
        before = snapshot(out)
        report = run_deck(write(tmp_path, "d.comm", PLAIN_DECK), out)
        assert report.status == "ERROR" and report.exit_code == 2
        assert "another asterlite run" in report.message
        assert snapshot(out) == before
    finally:
        holder.release()
    assert run_deck(write(tmp_path, "d.comm", PLAIN_DECK), out).status == "DONE"
    assert not (out / LOCK_NAME).exists()


def test_an_output_option_naming_a_file_is_exit_status_2(tmp_path):
    target = write(tmp_path, "taken", "data\n")
    deck = write(tmp_path, "d.comm", PLAIN_DECK)
    assert main(["run", str(deck), "-o", str(target), "-q"]) == 2
    assert target.read_text() == "data\n"


# ------------------------------------------------------------------- signals

LOOP_DECK = """DEBUT()
T = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=(1.0, 2.0)))
IMPR_TABLE(UNITE=30, TABLE=T)
print("started")
x = 0
while True:
    x = x + 1
FIN()
"""


@pytest.mark.parametrize("number", [signal.SIGTERM, signal.SIGINT])
def test_a_signal_ends_the_run_cleanly_and_the_log_streams(tmp_path, number):
    out = tmp_path / "out"
    assert run_deck(write(tmp_path, "d.comm", PLAIN_DECK), out).status == "DONE"
    deck = write(tmp_path, "loop.comm", LOOP_DECK)
    command = [sys.executable, "-m", "asterlite", "run", str(deck), "-o", str(out), "-q"]
    child = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        deadline = time.monotonic() + 60
        log = out / "message.log"
        # message.log is written as the run goes: the deck's print shows up while it loops
        while time.monotonic() < deadline:
            if log.exists() and "started" in log.read_text():
                break
            time.sleep(0.1)
        else:
            pytest.fail("message.log never showed the deck's print")
        assert summary(out)["status"] == "RUNNING"
        child.send_signal(number)
        child.wait(timeout=60)
    finally:
        child.kill()
    assert child.returncode == 2
    data = summary(out)
    assert data["status"] == "INTERRUPTED"
    assert signal.Signals(number).name in data["message"]
    assert "INTERRUPTED" in (out / "message.log").read_text()
    assert not (out / "fort.30").exists()  # the earlier run's file was moved aside
    assert (out / "incomplete" / "fort.30").exists()
    assert not (out / LOCK_NAME).exists()
