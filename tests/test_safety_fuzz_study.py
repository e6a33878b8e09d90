"""Fuzzing what surrounds a deck (docs/safety.md, "Threat model"): hostile
export lines, special files, engine objects reached through format fields,
signals at random moments, and a full disk.

Whatever a generated study holds, a run must end with a final status (never
RUNNING), exit status 0, 1 or 2 without an internal error, leave every file
outside its output folder as it was (the deck, its inputs, a neighbouring
"victim" folder) and never show a path or memory address of the engine.

The CI budget is small; ASTERLITE_FUZZ_EXAMPLES raises it for a longer run.
"""

from __future__ import annotations

import hashlib
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from asterlite.runtime.runner import run_deck

EXAMPLES = int(os.environ.get("ASTERLITE_FUZZ_EXAMPLES", "25"))
FUZZ = settings(
    max_examples=EXAMPLES,
    deadline=None,
    derandomize=True,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)
FINAL = {"PASS", "NOOK", "DONE", "ERROR", "UNSUPPORTED", "INTERRUPTED", "KILLED", "CHECKED"}

DECK = """DEBUT()
T = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=(1.0, 2.0)))
IMPR_TABLE(UNITE=30, TABLE=T, TITRE='echo pwned > /tmp/pwned')
FIN()
"""


def tree_digest(folder: Path) -> dict[str, str]:
    """Every entry below ``folder`` with its kind and content digest."""
    seen = {}
    for path in sorted(folder.rglob("*")):
        key = path.relative_to(folder).as_posix()
        if path.is_symlink():
            seen[key] = "link:" + os.readlink(path)
        elif path.is_file():
            seen[key] = hashlib.sha256(path.read_bytes()).hexdigest()
        else:
            seen[key] = "dir"
    return seen


def make_study(root: Path) -> dict[str, Path]:
    """A study folder, a victim folder beside it, and a few special files."""
    study = root / "study"
    victim = root / "victim"
    study.mkdir()
    victim.mkdir()
    (study / "case.comm").write_text(DECK)
    (victim / "bashrc").write_text("# the user's own file\n")
    (victim / "private").write_text("hunter2\n")
    (study / "link-to-private").symlink_to(victim / "private")
    os.mkfifo(study / "pipe")
    return {"study": study, "victim": victim}


# an F or R line may point anywhere a hostile export could
PATHS = [
    "case.comm",
    "../victim/bashrc",
    "../victim/new-file",
    "../victim/sub/new",
    "/etc/passwd",
    "link-to-private",
    "pipe",
    "/dev/zero",
    "/dev/urandom",
    "out/message.log",
    "out/summary.json",
    "out/.asterlite.lock",
    "out",
    ".",
    "",
    "../victim",
]
LIMITS = ["inf", "-inf", "nan", "1e308", "-1", "0", "5", "abc", "1e-300"]
export_lines = st.one_of(
    st.sampled_from(PATHS).map(lambda p: f"F mail {p} D 20"),
    st.sampled_from(PATHS).map(lambda p: f"F libr {p} D 31"),
    st.sampled_from(PATHS).map(lambda p: f"R resu {p} R 30"),
    st.sampled_from(PATHS).map(lambda p: f"F comm {p} D 1"),
    st.tuples(st.sampled_from(["time_limit", "memory_limit"]), st.sampled_from(LIMITS)).map(
        lambda p: f"P {p[0]} {p[1]}"
    ),
)
exports = st.lists(export_lines, max_size=5).map(lambda lines: ["F comm case.comm D 1", *lines])


@FUZZ
@given(lines=exports)
def test_hostile_exports_touch_nothing_outside_the_run(lines):
    with tempfile.TemporaryDirectory(prefix="asterlite-fuzz-study-") as scratch:
        places = make_study(Path(scratch))
        study, victim = places["study"], places["victim"]
        export = study / "case.export"
        export.write_text("\n".join(lines) + "\n")
        before_victim = tree_digest(victim)
        deck_before = (study / "case.comm").read_bytes()
        out = study / "out"
        start = time.monotonic()
        report = run_deck(export, out, time_limit=5.0, output_limit=2.0)
        assert time.monotonic() - start < 60
        assert report.exit_code in (0, 1, 2)
        if report.status == "ERROR":
            assert "internal error" not in report.message, report.message + report.traceback
        assert "hunter2" not in report.message
        assert tree_digest(victim) == before_victim
        assert (study / "case.comm").read_bytes() == deck_before
        assert not Path("/tmp/pwned").exists()
        if (out / "summary.json").exists():
            data = json.loads((out / "summary.json").read_text())
            assert data["status"] in FINAL
            assert data["status"] == report.status


# ------------------------------------------------------------ format fields

OBJECTS = ["DEBUT", "T", "[DEBUT]", "{'a': T}", "(T,)", "1.5", "'text'", "np.zeros(3)", "FIN"]
ACCESSORS = [
    ".session",
    ".output_dir",
    "[0]",
    "['a']",
    ".real",
    ".imag",
    ".__class__",
    ".__globals__",
    ".rows",
    ".name",
    "[0][0]",
]
fields = st.tuples(
    st.sampled_from(OBJECTS),
    st.lists(st.sampled_from(ACCESSORS), min_size=1, max_size=4),
    st.sampled_from(["", "!r", "!s", ":>10", ":e"]),
    st.sampled_from(["format", "fstring", "percent"]),
)


def field_statement(obj: str, chain: list[str], spec: str, how: str) -> str:
    if how == "fstring":
        return f'print(f"{{X{"".join(chain)}{spec}}}")'
    if how == "percent":
        return 'print("%s %r" % (X, X))'
    return f'print("{{0{"".join(chain)}{spec}}}".format(X))'


@FUZZ
@given(field=fields)
def test_format_fields_never_reach_engine_internals(field):
    obj, chain, spec, how = field
    text = (
        "DEBUT()\nimport numpy as np\n"
        "T = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=(1.0, 2.0)))\n"
        f"X = {obj}\n{field_statement(obj, chain, spec, how)}\nFIN()\n"
    )
    with tempfile.TemporaryDirectory(prefix="asterlite-fuzz-fmt-") as scratch:
        scratch = Path(scratch)
        deck = scratch / "fmt.comm"
        deck.write_text(text)
        out = scratch / "out"
        report = run_deck(deck, out, time_limit=5.0, output_limit=2.0)
        assert report.status in ("DONE", "ERROR", "UNSUPPORTED"), report.message
        if report.status == "ERROR":
            assert "internal error" not in report.message, report.message + report.traceback
        log = (out / "message.log").read_text(errors="replace")
        printed = log + report.message
        assert str(scratch) not in printed.replace(str(deck), "").replace(str(out), "")
        assert "object at 0x" not in printed
        assert "/site-packages/" not in printed and "asterlite/" not in printed


# ------------------------------------------------------------------ signals

LOOP = "DEBUT()\nx = 0\nfor i in range(10**7):\n    x = x + i\nFIN()\n"
SIGNALS = [
    signal.SIGHUP,
    signal.SIGQUIT,
    signal.SIGUSR1,
    signal.SIGUSR2,
    signal.SIGTERM,
    signal.SIGINT,
    signal.SIGPIPE,
]


@settings(max_examples=max(3, EXAMPLES // 8), deadline=None, derandomize=True)
@given(number=st.sampled_from(SIGNALS), delay=st.floats(0.0, 2.5))
def test_a_signal_at_any_moment_leaves_a_true_final_status(number, delay):
    with tempfile.TemporaryDirectory(prefix="asterlite-fuzz-sig-") as scratch:
        scratch = Path(scratch)
        deck = scratch / "loop.comm"
        deck.write_text(LOOP)
        out = scratch / "out"
        command = [sys.executable, "-m", "asterlite", "run", str(deck), "-o", str(out), "--quiet"]
        child = subprocess.Popen(
            command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, cwd=scratch
        )
        time.sleep(delay)
        child.send_signal(number)
        try:
            child.wait(timeout=60)
        except subprocess.TimeoutExpired:
            child.kill()
            child.wait()
        status = subprocess.run(
            [sys.executable, "-m", "asterlite", "status", str(out)],
            capture_output=True,
            text=True,
            timeout=60,
            cwd=scratch,
        )
        assert "Traceback" not in status.stderr, status.stderr
        if (out / "summary.json").exists():
            data = json.loads((out / "summary.json").read_text())
            assert data["status"] in FINAL, (number, delay, data["status"])
        # the folder is usable again: no stale lock or staging blocks the next run
        quick = scratch / "quick.comm"
        quick.write_text("DEBUT()\nFIN()\n")
        again = run_deck(quick, out)
        assert again.status == "DONE", again.message


# ---------------------------------------------------------------- full disk


@pytest.fixture
def small_disk(tmp_path):
    """A 512 kB tmpfs (root only; skipped elsewhere, required in CI)."""
    mount = tmp_path / "disk"
    mount.mkdir()
    done = subprocess.run(
        ["mount", "-t", "tmpfs", "-o", "size=512k", "tmpfs", str(mount)], capture_output=True
    )
    if done.returncode != 0:
        if os.environ.get("CI") == "true" and os.geteuid() == 0:
            pytest.fail(f"could not mount a small tmpfs: {done.stderr.decode()}")
        pytest.skip("a small tmpfs cannot be mounted here")
    yield mount
    subprocess.run(["umount", "-l", str(mount)], check=False)


FLOOD = (
    "DEBUT()\nT = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=tuple(range({n}))))\n"
    "IMPR_TABLE(UNITE=30, TABLE=T)\nFIN()\n"
)


@pytest.mark.parametrize("rows", [100, 20_000, 200_000])
def test_a_full_disk_ends_with_a_final_status_and_the_next_run_recovers(small_disk, rows):
    deck = small_disk.parent / "flood.comm"
    deck.write_text(FLOOD.format(n=rows))
    out = small_disk / "out"
    report = run_deck(deck, out)
    assert report.exit_code in (0, 2)
    if report.status == "ERROR":
        assert "internal error" not in report.message, report.message + report.traceback
    summary = out / "summary.json"
    if summary.exists():
        assert json.loads(summary.read_text())["status"] in FINAL
    assert not list(out.glob(".summary.json*.tmp"))
    # room again: the next run into the same folder works
    for path in sorted(out.rglob("*"), reverse=True):
        if path.is_file() and path.name.startswith("fort"):
            path.unlink()
    for folder in out.glob("previous-*"):
        subprocess.run(["rm", "-rf", str(folder)], check=True)
    quick = small_disk.parent / "quick.comm"
    quick.write_text("DEBUT()\nFIN()\n")
    again = run_deck(quick, out)
    assert again.status == "DONE", again.message
