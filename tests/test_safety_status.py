"""Exit status 2 and a located message for every failure, internal ones
included: one line on the terminal, the traceback in message.log."""

from __future__ import annotations

import errno
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from asterlite.cli import main
from asterlite.runtime import manifest, runner
from asterlite.runtime.outdir import LOCK_NAME, STAGING_NAME
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


# ------------------------------------------------- a run ends with a true status

# loops until a signal stops it: each pass costs a sum of 2000 terms, so the
# deck's budget of loop iterations and calls (1e7) lasts far longer than the
# test takes to send its signal, even on a loaded machine
LOOP_DECK = """DEBUT()
T = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=(1.0, 2.0)))
IMPR_TABLE(UNITE=30, TABLE=T)
print("started")
x = 0
while True:
    x = x + sum(range(2000))
FIN()
"""
PASS_DECK = """DEBUT()
F = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 1.0, 1.0, 3.0))
TEST_FONCTION(VALEUR=_F(FONCTION=F, VALE_PARA=0.5, VALE_CALC=2.0))
FIN()
"""


@pytest.fixture(autouse=True)
def private_manifest_key(tmp_path, monkeypatch):
    """This test's own manifest key (children inherit the variable)."""
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "config"))
    manifest._key_cache.clear()


def summary_of(folder: Path) -> dict:
    return json.loads((folder / "summary.json").read_text())


def asterlite_command(*args: str) -> list[str]:
    return [sys.executable, "-m", "asterlite", *args]


def start_looping_run(tmp_path: Path, out: Path) -> subprocess.Popen:
    """A child ``asterlite run`` of a deck that loops after its IMPR_TABLE,
    returned once its log shows the loop has started."""
    deck = tmp_path / "loop.comm"
    deck.write_text(LOOP_DECK)
    command = asterlite_command("run", str(deck), "-o", str(out), "-q")
    child = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    deadline = time.monotonic() + 60
    log = out / "message.log"
    while time.monotonic() < deadline:
        if log.exists() and "started" in log.read_text():
            return child
        time.sleep(0.1)
    child.kill()
    pytest.fail("message.log never showed the deck's print")


@pytest.mark.parametrize(
    "number",
    [signal.SIGHUP, signal.SIGQUIT, signal.SIGUSR1, signal.SIGUSR2, signal.SIGALRM],
    ids=lambda number: number.name,
)
def test_any_stop_signal_ends_the_run_interrupted_and_clears_the_folder(tmp_path, number):
    out = tmp_path / "out"
    child = start_looping_run(tmp_path, out)
    try:
        running = summary_of(out)
        assert running["status"] == "RUNNING" and "pid" in running["message"]
        child.send_signal(number)
        child.wait(timeout=60)
    finally:
        child.kill()
    assert child.returncode == 2
    data = summary_of(out)
    assert data["status"] == "INTERRUPTED"
    assert signal.Signals(number).name in data["message"]
    assert "after IMPR_TABLE (loop.comm:3)" in data["message"]
    assert not (out / LOCK_NAME).exists() and not (out / STAGING_NAME).exists()
    assert (out / "incomplete" / "fort.30").exists()


def test_a_killed_run_is_told_by_status_which_clears_its_lock_and_staging(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "summary.json").write_text('{"status": "PASS", "deck": "old", "output": {}}')
    child = start_looping_run(tmp_path, out)
    try:
        # the earlier result was moved aside before the run started, and it says so
        running = summary_of(out)
        assert running["status"] == "RUNNING" and "moved to previous-" in running["message"]
        live = subprocess.run(asterlite_command("status", str(out)), capture_output=True, text=True)
        assert live.returncode == 3, live.stdout + live.stderr
        assert f"RUNNING — pid {child.pid}, after IMPR_TABLE (loop.comm:3)" in live.stdout
        child.send_signal(signal.SIGKILL)
        child.wait(timeout=60)
    finally:
        child.kill()
    assert summary_of(out)["status"] == "RUNNING" and (out / LOCK_NAME).exists()
    told = subprocess.run(asterlite_command("status", str(out)), capture_output=True, text=True)
    assert told.returncode == 2, told.stdout + told.stderr
    assert "KILLED" in told.stdout and "after IMPR_TABLE (loop.comm:3)" in told.stdout
    data = summary_of(out)
    assert data["status"] == "KILLED" and "after IMPR_TABLE (loop.comm:3)" in data["message"]
    assert not (out / LOCK_NAME).exists() and not (out / STAGING_NAME).exists()
    assert (out / "incomplete" / "fort.30").exists()
    assert "KILLED" in (out / "message.log").read_text()
    # the next run moves the killed run aside and leaves no lock behind
    deck = tmp_path / "p.comm"
    deck.write_text(PASS_DECK)
    assert run_deck(deck, out).status == "PASS"
    assert not (out / LOCK_NAME).exists() and not (out / "incomplete").exists()
    killed = [p for p in out.glob("previous-*") if (p / "incomplete").exists()]
    assert len(killed) == 1 and summary_of(killed[0])["status"] == "KILLED"


def test_status_of_a_folder_the_user_may_not_write_is_read_only(tmp_path, monkeypatch):
    from asterlite.runtime import outdir
    from asterlite.runtime.folder_status import folder_status

    out = tmp_path / "out"
    child = start_looping_run(tmp_path, out)
    child.send_signal(signal.SIGKILL)
    child.wait(timeout=60)

    def refused(self):
        raise PermissionError(errno.EACCES, "Permission denied", str(self.path))

    monkeypatch.setattr(outdir.OutputFolder, "take", refused)
    found = folder_status(out)
    assert found.status == "KILLED" and found.exit_code == 2
    assert "read-only here: left as is" in found.lines[0]
    assert summary_of(out)["status"] == "RUNNING" and (out / STAGING_NAME).exists()


def test_a_stale_lock_is_taken_over_and_cleared_by_the_next_run(tmp_path):
    out = tmp_path / "out"
    child = start_looping_run(tmp_path, out)
    child.send_signal(signal.SIGKILL)
    child.wait(timeout=60)
    deck = tmp_path / "p.comm"
    deck.write_text(PASS_DECK)
    report = run_deck(deck, out)
    assert report.status == "PASS", report.message
    assert not (out / LOCK_NAME).exists()
    assert "the earlier run had ended without its result (KILLED)" in report_message(out)
    assert summary_of(next(out.glob("previous-*")))["status"] == "KILLED"


def report_message(out: Path) -> str:
    return (out / "message.log").read_text() + json.dumps(summary_of(out))


def test_a_signal_while_the_folder_is_taken_still_moves_the_earlier_result_aside(tmp_path):
    """SIGTERM arriving before the run has written its RUNNING summary waits:
    the earlier PASS is moved aside and the run ends INTERRUPTED."""
    out = tmp_path / "out"
    deck = tmp_path / "p.comm"
    deck.write_text(PASS_DECK)
    assert run_deck(deck, out).status == "PASS"
    script = (
        "import os, signal, sys\n"
        "from asterlite.runtime import outdir\n"
        "from asterlite.cli import main\n"
        "original = outdir.OutputFolder._move_earlier_result\n"
        "def move(self, earlier):\n"
        "    os.kill(os.getpid(), signal.SIGTERM)\n"
        "    return original(self, earlier)\n"
        "outdir.OutputFolder._move_earlier_result = move\n"
        f"sys.exit(main(['run', {str(deck)!r}, '-o', {str(out)!r}, '-q']))\n"
    )
    child = subprocess.run([sys.executable, "-c", script], capture_output=True, timeout=120)
    assert child.returncode == 2, child.stderr
    data = summary_of(out)
    assert data["status"] == "INTERRUPTED" and "SIGTERM" in data["message"]
    assert summary_of(next(out.glob("previous-*")))["status"] == "PASS"


def test_a_second_signal_while_starting_stops_at_once_leaving_nothing_half_made(tmp_path):
    out = tmp_path / "out"
    deck = tmp_path / "p.comm"
    deck.write_text(PASS_DECK)
    assert run_deck(deck, out).status == "PASS"
    before = sorted(os.listdir(out))
    script = (
        "import os, signal, sys\n"
        "from asterlite.runtime import outdir\n"
        "from asterlite.cli import main\n"
        "original = outdir.OutputFolder._move_earlier_result\n"
        "def move(self, earlier):\n"
        "    os.kill(os.getpid(), signal.SIGINT)\n"
        "    os.kill(os.getpid(), signal.SIGINT)\n"
        "    return original(self, earlier)\n"
        "outdir.OutputFolder._move_earlier_result = move\n"
        f"sys.exit(main(['run', {str(deck)!r}, '-o', {str(out)!r}, '-q']))\n"
    )
    child = subprocess.run([sys.executable, "-c", script], capture_output=True, timeout=120)
    assert child.returncode == 2 and b"interrupted" in child.stderr, child.stderr
    assert sorted(os.listdir(out)) == before  # the run never started: no lock, no staging


def test_a_signal_once_the_result_is_written_keeps_the_verdict(tmp_path):
    """SIGTERM while the final files are written: the run completes, and its
    exit status is its summary's (PASS, 0), not 2."""
    out = tmp_path / "out"
    deck = tmp_path / "p.comm"
    deck.write_text(PASS_DECK)
    script = (
        "import os, signal, sys\n"
        "from asterlite.runtime import runner\n"
        "from asterlite.cli import main\n"
        "original = runner._finish_output\n"
        "def finish(*args, **kwargs):\n"
        "    os.kill(os.getpid(), signal.SIGTERM)\n"
        "    return original(*args, **kwargs)\n"
        "runner._finish_output = finish\n"
        f"sys.exit(main(['run', {str(deck)!r}, '-o', {str(out)!r}, '-q']))\n"
    )
    child = subprocess.run([sys.executable, "-c", script], capture_output=True, timeout=120)
    assert summary_of(out)["status"] == "PASS"
    assert child.returncode == 0, child.stderr


def test_a_closed_stdout_pipe_does_not_change_the_verdict(tmp_path):
    deck = tmp_path / "p.comm"
    deck.write_text(PASS_DECK)
    out = tmp_path / "out"
    command = asterlite_command("run", str(deck), "-o", str(out))
    child = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    assert len(child.stdout.read(5)) == 5  # as `| head -c 5`
    child.stdout.close()
    _, errors = child.communicate(timeout=120)
    assert child.returncode == 0, errors
    assert summary_of(out)["status"] == "PASS"
    assert b"Broken pipe" not in errors and b"Traceback" not in errors


# ------------------------------------------------------------------ full disk

MANY_COMMANDS_DECK = """DEBUT()
for i in range(150):
    T = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=(1.0, 2.0)))
FIN()
"""


def test_a_summary_too_large_for_the_disk_leaves_a_true_status_and_no_temporary(tmp_path):
    """RLIMIT_FSIZE lets the RUNNING summary (8 kB) and the log be written,
    not the final summary: it says ERROR in the RUNNING one's place, and the
    next run into the folder works (a 0-byte .summary.json.tmp blocked it)."""
    deck = tmp_path / "many.comm"
    deck.write_text(MANY_COMMANDS_DECK)
    out = tmp_path / "out"
    script = (
        "import resource, signal, sys\n"
        "signal.signal(signal.SIGXFSZ, signal.SIG_IGN)\n"
        "resource.setrlimit(resource.RLIMIT_FSIZE, (12000, 12000))\n"
        "from asterlite.cli import main\n"
        f"sys.exit(main(['run', {str(deck)!r}, '-o', {str(out)!r}, '-q']))\n"
    )
    child = subprocess.run([sys.executable, "-c", script], capture_output=True, timeout=120)
    assert child.returncode == 2, child.stderr
    data = summary_of(out)
    assert data["status"] == "ERROR", data
    assert "summary.json could not be written (file too large)" in data["message"]
    assert "the run had ended DONE" in data["message"]
    assert not (out / ".summary.json.tmp").exists() and not (out / LOCK_NAME).exists()
    deck.write_text(PASS_DECK)
    assert run_deck(deck, out).status == "PASS"


def test_a_temporary_summary_left_by_a_killed_run_does_not_block_the_folder(tmp_path):
    out = tmp_path / "out"
    deck = tmp_path / "p.comm"
    deck.write_text(PASS_DECK)
    assert run_deck(deck, out).status == "PASS"
    (out / ".summary.json.tmp").write_bytes(b"")
    report = run_deck(deck, out)
    assert report.status == "PASS", report.message
    assert (next(out.glob("previous-*")) / ".summary.json.tmp").exists()


@pytest.fixture
def small_disk(tmp_path):
    """A 1 MB tmpfs (root only, where mounting is allowed)."""
    mount_point = tmp_path / "disk"
    mount_point.mkdir()
    if os.geteuid() != 0:
        pytest.skip("mounting a small tmpfs needs root")
    mounted = subprocess.run(
        ["mount", "-t", "tmpfs", "-o", "size=1m", "tmpfs", str(mount_point)], capture_output=True
    )
    if mounted.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs here: {mounted.stderr.decode().strip()}")
    try:
        yield mount_point
    finally:
        subprocess.run(["umount", "-l", str(mount_point)], capture_output=True)


def test_a_full_disk_ends_the_run_with_a_true_status_and_the_next_run_recovers(
    tmp_path, small_disk
):
    deck = tmp_path / "big.comm"
    deck.write_text(
        "DEBUT()\nT = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=[float(i) for i in range(200000)]))\n"
        "IMPR_TABLE(UNITE=30, TABLE=T)\nFIN()\n"
    )
    out = small_disk / "out"
    report = run_deck(deck, out)
    assert report.status == "ERROR" and report.exit_code == 2
    assert "no space left" in report.message
    data = summary_of(out)
    assert data["status"] == "ERROR" and "no space left" in data["message"]
    assert not (out / ".summary.json.tmp").exists() and not (out / LOCK_NAME).exists()
    # the disk is still full: the next run cannot start; it leaves nothing half
    # made (the earlier result moved aside, as always before a run starts)
    again = run_deck(deck, out)
    assert again.status == "ERROR" and "No space left" in again.message
    assert all(name.startswith("previous-") for name in os.listdir(out)), os.listdir(out)
    # space freed: a run works again
    for previous in out.glob("previous-*"):
        subprocess.run(["rm", "-rf", str(previous)], check=True)
    subprocess.run(["rm", "-rf", str(out / "incomplete")], check=True)
    small = tmp_path / "p.comm"
    small.write_text(PASS_DECK)
    assert run_deck(small, out).status == "PASS"


# --------------------------------------------------------------- export limits


@pytest.mark.parametrize(
    "line",
    [
        "P time_limit inf",
        "P time_limit 1e308",
        "P memory_limit inf",
        "P memory_limit 1e308",
        "P time_limit -5",
        "P memory_limit nan",
    ],
)
def test_export_limits_are_finite_positive_or_a_located_export_error(tmp_path, line):
    (tmp_path / "p.comm").write_text(PASS_DECK)
    export = tmp_path / "p.export"
    export.write_text(f"F comm p.comm D 1\n{line}\n")
    out = tmp_path / "out"
    child = subprocess.run(
        asterlite_command("run", str(export), "-o", str(out), "-q"),
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert child.returncode == 2, child.stderr
    assert f"{export}:2:1: export error" in child.stderr, child.stderr
    assert "internal error" not in child.stderr


@pytest.mark.parametrize("option", ["--time-limit", "--memory-limit", "--output-limit"])
@pytest.mark.parametrize("value", ["inf", "nan", "-1", "1e308"])
def test_limit_options_are_finite_and_not_negative(tmp_path, option, value):
    (tmp_path / "p.comm").write_text(PASS_DECK)
    with pytest.raises(SystemExit) as stopped:
        main(["run", str(tmp_path / "p.comm"), "-o", str(tmp_path / "out"), option, value])
    assert stopped.value.code == 2
    assert not (tmp_path / "out").exists()
