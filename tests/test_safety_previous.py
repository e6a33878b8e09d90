"""Earlier results under previous-*/ (issue 32, item 5; docs/safety.md): a
rerun keeps the N most recent (3 by default, --keep-previous N, --no-previous)
and deletes older ones only as far as a verified manifest records them as
asterlite's: a foreign previous-x, anything added to or replaced in a
recorded folder, and whatever a tampered summary claims are never touched."""

from __future__ import annotations

import json
import os
import threading
import time
from pathlib import Path

import pytest

from asterlite.cli import main
from asterlite.runtime import manifest
from asterlite.runtime.previous_results import DEFAULT_KEEP
from asterlite.runtime.runner import run_deck

DECK = """DEBUT()
T = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=(1.0, 2.0)))
IMPR_TABLE(UNITE=30, TABLE=T)
FIN()
"""
FAILING_DECK = """DEBUT()
T = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=(1.0, 2.0)))
IMPR_TABLE(UNITE=30, TABLE=T)
x = 1 / 0
FIN()
"""


@pytest.fixture(autouse=True)
def private_manifest_key(tmp_path, monkeypatch):
    """This test's own manifest key (never the user's ~/.config)."""
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "config"))
    manifest._key_cache.clear()


@pytest.fixture
def deck(tmp_path) -> Path:
    path = tmp_path / "d.comm"
    path.write_text(DECK)
    return path


def previous(out: Path) -> list[str]:
    return sorted(p.name for p in out.iterdir() if p.name.startswith("previous-"))


def summary(out: Path) -> dict:
    return json.loads((out / "summary.json").read_text())


def rerun(deck: Path, out: Path, **options) -> str | None:
    """One run into ``out``; the name of the folder its earlier result went to."""
    report = run_deck(deck, out, **options)
    assert report.status in ("DONE", "ERROR"), report.message
    return summary(out)["output"]["moved_aside"]


def test_a_rerun_keeps_the_n_most_recent_earlier_results(tmp_path, deck):
    out = tmp_path / "out"
    rerun(deck, out, keep_previous=2)
    moved = [rerun(deck, out, keep_previous=2) for _ in range(4)]
    assert previous(out) == sorted(moved[-2:])  # the two most recent, the others deleted
    for name in moved[-2:]:
        assert sorted(os.listdir(out / name)) == ["fort.30", "message.log", "summary.json"]
        assert json.loads((out / name / "summary.json").read_text())["status"] == "DONE"
    log = (out / "message.log").read_text()
    assert "deleted 1 earlier result(s) beyond the 2 most recent" in log
    assert f"{moved[1]}/" in log  # the one this run deleted, named
    assert set(summary(out)["manifest"]["previous"]) == set(moved[-2:])


def test_the_default_keeps_three(tmp_path, deck):
    assert DEFAULT_KEEP == 3
    out = tmp_path / "out"
    moved = [rerun(deck, out) for _ in range(6)][1:]
    assert previous(out) == sorted(moved[-3:])


def test_no_previous_keeps_none_and_the_new_result_stands(tmp_path, deck):
    out = tmp_path / "out"
    rerun(deck, out)
    rerun(deck, out)  # one earlier result kept by default
    assert len(previous(out)) == 1
    assert main(["run", str(deck), "-o", str(out), "-q", "--no-previous"]) == 0
    assert previous(out) == []
    assert sorted(os.listdir(out)) == ["fort.30", "message.log", "summary.json"]
    assert summary(out)["status"] == "DONE" and summary(out)["output"]["moved_aside"] is None
    log = (out / "message.log").read_text()
    assert "the earlier result was deleted" in log and "none kept" in log


def test_keep_previous_is_a_count(tmp_path, deck, capsys):
    with pytest.raises(SystemExit) as stop:
        main(["run", str(deck), "--keep-previous", "-1"])
    assert stop.value.code == 2 and "not a count" in capsys.readouterr().err
    report = run_deck(deck, tmp_path / "out", keep_previous=-2)
    assert report.status == "ERROR" and "keep_previous" in report.message
    assert not (tmp_path / "out").exists()


def test_a_foreign_previous_folder_is_never_touched(tmp_path, deck):
    out = tmp_path / "out"
    out.mkdir()
    (out / "previous-x").mkdir()
    (out / "previous-x" / "notes.txt").write_text("mine\n")
    (out / "previous-20200101-000000").mkdir()  # empty, named as asterlite names them
    for _ in range(4):
        rerun(deck, out, keep_previous=0)
    assert (out / "previous-x" / "notes.txt").read_text() == "mine\n"
    assert (out / "previous-20200101-000000").is_dir()
    assert previous(out) == ["previous-20200101-000000", "previous-x"]


def test_what_the_user_adds_or_replaces_in_a_recorded_folder_stays(tmp_path, deck):
    out = tmp_path / "out"
    rerun(deck, out)
    first = rerun(deck, out)
    second = rerun(deck, out)
    (out / first / "my-notes.txt").write_text("about this run\n")
    (out / second / "fort.30").unlink()
    (out / second / "fort.30").write_text("my own table\n")  # same name, another file
    rerun(deck, out, keep_previous=0)
    assert sorted(os.listdir(out / first)) == ["my-notes.txt"]  # asterlite's files went
    assert sorted(os.listdir(out / second)) == ["fort.30"]
    assert (out / second / "fort.30").read_text() == "my own table\n"
    log = (out / "message.log").read_text()
    assert f"{first}/ is left as it is" in log and f"{second}/ is left as it is" in log
    # forgotten once left: the next runs never look into them again
    rerun(deck, out, keep_previous=0)
    assert first not in summary(out)["manifest"].get("previous", {})
    assert (out / first / "my-notes.txt").exists() and (out / second / "fort.30").exists()


def test_a_recorded_folder_replaced_by_a_link_or_another_folder_is_not_followed(tmp_path, deck):
    out = tmp_path / "out"
    rerun(deck, out)
    linked = rerun(deck, out)
    replaced = rerun(deck, out)
    victim = tmp_path / "victim"
    victim.mkdir()
    for name in ("fort.30", "message.log", "summary.json"):
        (victim / name).write_text("victim\n")
    for name in os.listdir(out / linked):
        (out / linked / name).unlink()
    (out / linked).rmdir()
    (out / linked).symlink_to(victim)
    for name in os.listdir(out / replaced):
        os.rename(out / replaced / name, tmp_path / f"kept-{name}")
    (out / replaced).rmdir()
    (out / replaced).mkdir()  # another folder under the recorded name
    (out / replaced / "fort.30").write_text("mine\n")
    rerun(deck, out, keep_previous=0)
    assert sorted(os.listdir(victim)) == ["fort.30", "message.log", "summary.json"]
    assert (out / linked).is_symlink()
    assert (out / replaced / "fort.30").read_text() == "mine\n"


def test_a_tampered_manifest_is_not_trusted(tmp_path, deck):
    out = tmp_path / "out"
    rerun(deck, out)
    kept = rerun(deck, out)  # a real earlier result, recorded
    foreign = out / "previous-x"
    foreign.mkdir()
    (foreign / "data.csv").write_text("1,2\n")
    data = summary(out)
    info = os.lstat(foreign)
    claim = manifest.identity(info)
    claim["made"] = 0.0
    claim["contents"] = {"data.csv": manifest.identity(os.lstat(foreign / "data.csv"))}
    data["manifest"]["previous"]["previous-x"] = claim  # would be deleted if believed
    (out / "summary.json").write_text(json.dumps(data, indent=1))
    report = run_deck(deck, out, keep_previous=0)
    assert report.status == "DONE", report.message
    assert (foreign / "data.csv").read_text() == "1,2\n"
    assert (out / kept / "summary.json").exists()  # its record came from the edited summary
    # the edited summary's own result is moved by name, never deleted on its word
    aside = summary(out)["output"]["moved_aside"]
    assert aside and sorted(os.listdir(out / aside)) == ["fort.30", "message.log", "summary.json"]
    assert f"{aside}/ is left as it is" in (out / "message.log").read_text()
    assert "previous-x" not in summary(out)["manifest"].get("previous", {})


def test_a_failed_runs_incomplete_folder_is_recorded_and_pruned(tmp_path, deck):
    out = tmp_path / "out"
    failing = tmp_path / "f.comm"
    failing.write_text(FAILING_DECK)
    assert run_deck(failing, out).status == "ERROR"
    assert (out / "incomplete" / "fort.30").exists()
    record = summary(out)["manifest"]["entries"]["incomplete"]
    assert set(record["contents"]) == {"fort.30"}
    aside = rerun(deck, out)
    assert (out / aside / "incomplete" / "fort.30").exists()
    rerun(deck, out, keep_previous=0)
    assert previous(out) == []


def test_a_killed_runs_staging_folder_is_never_deleted(tmp_path, deck):
    """A run killed outright left files nobody recorded: its previous folder
    stays whole however many runs follow."""
    out = tmp_path / "out"
    rerun(deck, out)
    data = summary(out)
    # what a run killed while RUNNING leaves: its staging folder with a file,
    # and a RUNNING summary (signed: the run's own) listing that folder
    (out / ".asterlite-running").mkdir()
    (out / ".asterlite-running" / "fort.31").write_text("half a table\n")
    entries = dict(data["manifest"]["entries"])
    entries[".asterlite-running"] = manifest.identity(os.lstat(out / ".asterlite-running"), False)
    data = {"deck": "d", "status": "RUNNING", "message": "running", "output": data["output"]}
    manifest.sign(data, os.stat(out), entries)
    (out / "summary.json").write_text(json.dumps(data))
    killed = rerun(deck, out)
    assert (out / killed / "incomplete" / "fort.31").exists()
    for _ in range(2):
        rerun(deck, out, keep_previous=0)
        time.sleep(0.01)
    assert (out / killed / "incomplete" / "fort.31").read_text() == "half a table\n"


def test_deck_assignments_read_decks_as_the_run_does(tmp_path):
    """The variant note quotes the deck's own assignments: decoded as the run
    decodes the deck (Windows-1252 here, never a byte replaced), and a FIFO
    given as a deck file is skipped, not waited on."""
    from asterlite.runtime.verdicts import deck_assignments

    latin = tmp_path / "latin.comm"
    latin.write_bytes("TITRE = 'essai à froid'\nMU = 0.15\n".encode("cp1252"))
    fifo = tmp_path / "fifo.comm"
    os.mkfifo(fifo)
    found = {}
    reader = threading.Thread(
        target=lambda: found.update(deck_assignments([fifo, latin], ["TITRE", "MU"])),
        daemon=True,
    )
    reader.start()
    reader.join(timeout=10)
    if reader.is_alive():  # blocked opening the FIFO: release it, then fail
        os.close(os.open(fifo, os.O_WRONLY | os.O_NONBLOCK))
        reader.join(timeout=10)
        pytest.fail("deck_assignments waited on a FIFO")
    assert found["TITRE"]["text"] == "TITRE = 'essai à froid'"
    assert found["MU"] == {"text": "MU = 0.15", "file": "latin.comm", "line": 2}


def test_records_survive_a_report_and_a_killed_run_settled(tmp_path, deck):
    """Re-signing a summary (asterlite report adding report.html, a killed
    run settled by asterlite status) keeps the records of previous folders."""
    from asterlite.report import write_report
    from asterlite.runtime.folder_status import folder_status

    out = tmp_path / "out"
    rerun(deck, out)
    first = rerun(deck, out)
    write_report(out)
    assert "report.html" in summary(out)["output"]["files"]
    assert set(summary(out)["manifest"]["previous"]) == {first}
    # the run after it is killed while RUNNING: its summary (signed, the
    # records carried) says RUNNING and no process holds the folder
    second = rerun(deck, out)
    data = summary(out)
    data.update(status="RUNNING", message="running")
    manifest.sign(data, os.stat(out), data["manifest"]["entries"], data["manifest"]["previous"])
    (out / "summary.json").write_text(json.dumps(data))
    assert folder_status(out).status == "KILLED"
    assert set(summary(out)["manifest"]["previous"]) == {first, second}
    rerun(deck, out, keep_previous=0)
    assert previous(out) == []
