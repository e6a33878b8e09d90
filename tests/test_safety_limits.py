"""Whole-run limits and the evaluator's guards (docs/safety.md): every case
ends quickly with a located ERROR (exit status 2), the process alive."""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from asterlite.runtime.runner import run_deck
from asterlite.runtime.session import KeywordOverride

SAMPLE = Path(__file__).resolve().parents[1] / "samples" / "friction_oscillator"


def run_text(tmp_path: Path, body: str, **options):
    deck = tmp_path / "d.comm"
    deck.write_text("DEBUT()\n" + body + "FIN()\n")
    start = time.monotonic()
    report = run_deck(deck, tmp_path / "out", **options)
    return report, time.monotonic() - start, deck


# deeply nested values: hashing one in C has no depth check (SIGSEGV before)
NESTING = [
    "t = ()\nfor i in range(300):\n    t = (t,)\ns = {t}\n",
    "t = ()\nfor i in range(300):\n    t = (t,)\nd = {t: 1}\n",
    "t = ()\nfor i in range(300):\n    t = (t,)\nok = t in {1, 2}\n",
    "t = ()\nfor i in range(300):\n    t = (t,)\ns = set([t])\n",
    "t = ()\nfor i in range(300):\n    t = (t,)\nd = dict([(t, 1)])\n",
    "t = ()\nfor i in range(300):\n    t = (t,)\nd = {}\nx = d.get(t)\n",
    "t = ()\nfor i in range(300):\n    t = list(zip([t]))[0]\ns = {t}\n",
    "t = ()\nfor i in range(300):\n    t = (t,)\nL = DEFI_LIST_REEL(VALE=t)\n",
]


@pytest.mark.parametrize("body", NESTING)
def test_deep_nesting_is_a_located_error(tmp_path, body):
    report, _, deck = run_text(tmp_path, body)
    assert report.status == "ERROR" and report.exit_code == 2, report.message
    assert "nested containers" in report.message and f"{deck}:" in report.message


def test_a_million_deep_tuple_never_crashes(tmp_path):
    """The issue's case, in a child process: a crash would be a signal."""
    import subprocess
    import sys

    deck = tmp_path / "d.comm"
    deck.write_text("DEBUT()\nt = ()\nfor i in range(1000000):\n    t = (t,)\ns = {t}\nFIN()\n")
    command = [sys.executable, "-m", "asterlite", "run", str(deck), "-o", str(tmp_path / "o")]
    child = subprocess.run(command + ["-q"], capture_output=True, text=True, timeout=300)
    assert child.returncode == 2 and "nested containers" in child.stderr


@pytest.mark.parametrize(
    "body, expected",
    [
        ("x = np.concatenate([np.zeros(10**4)] * 10**5)\n", "numpy.concatenate size"),
        ("x = np.vstack([np.zeros(10**4)] * 10**4)\n", "numpy.vstack size"),
        ("x = np.diff(np.zeros(10), n=10**12)\n", "exceeds the axis length"),
        ("a = np.ones((4000, 1))\nc = a.dot(np.ones((1, 4000)))\n", "numpy.dot size"),
        (
            "a = np.zeros((1000, 1, 1000))\nb = np.zeros((1, 1000, 1000))\nc = np.matmul(a, b)\n",
            "size",
        ),
        ("a = np.ones((3000, 3000))\nb = np.linalg.inv(a)\n", "arithmetic"),
        ("x = np.convolve(np.ones(10**6), np.ones(10**6))\n", "numpy.convolve"),
        ("x = np.polyval(np.ones(10**5), np.ones(10**6))\n", "numpy.polyval"),
        ("x = lcm(*range(1, 10**6))\n", "integer size"),
    ],
)
def test_calls_are_refused_before_they_allocate_or_run_long(tmp_path, body, expected):
    report, seconds, deck = run_text(tmp_path, "import numpy as np\n" + body)
    assert report.status == "ERROR" and report.exit_code == 2, report.message
    assert expected in report.message and f"{deck}:" in report.message
    assert seconds < 30


def test_a_runaway_loop_stops_at_the_time_limit(tmp_path):
    report, _, deck = run_text(tmp_path, "x = 0\nwhile True:\n    x = x + 1\n", time_limit=1.0)
    assert report.status == "ERROR" and "time limit" in report.message
    assert f"{deck}:" in report.message


def test_colliding_dict_keys_stop_at_the_time_limit(tmp_path):
    body = "M = 2**61 - 1\nd = {i * M: i for i in range(200000)}\n"
    report, _, deck = run_text(tmp_path, body, time_limit=1.0)
    assert report.status == "ERROR" and "time limit" in report.message


def test_check_is_bounded_too(tmp_path):
    deck = tmp_path / "d.comm"
    deck.write_text("DEBUT()\nx = 0\nwhile True:\n    x = x + 1\nFIN()\n")
    report = run_deck(deck, check_only=True, time_limit=1.0)
    assert report.status == "ERROR" and "time limit" in report.message


def test_print_output_is_capped(tmp_path):
    body = 's = "x" * 1000000\nfor i in range(50):\n    print(s)\n'
    report, _, _ = run_text(tmp_path, body, output_limit=5)
    assert report.status == "ERROR" and "output limit" in report.message
    log = tmp_path / "out" / "message.log"
    assert log.stat().st_size < 6_000_000
    assert "output limit" in log.read_text()[-2000:]


def test_files_written_by_the_deck_are_capped(tmp_path):
    body = (
        "T = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=tuple(float(i) for i in range(200000))))\n"
        "for i in range(40):\n    IMPR_TABLE(UNITE=30, TABLE=T)\n"
    )
    report, _, deck = run_text(tmp_path, body, output_limit=3)
    assert report.status == "ERROR" and report.exit_code == 2
    assert "output limit" in report.message or "cap" in report.message, report.message
    out = tmp_path / "out"
    assert sum(p.stat().st_size for p in out.rglob("*") if p.is_file()) < 8_000_000


def test_a_transient_too_long_is_refused_before_it_starts():
    pytest.importorskip("numba")
    override = KeywordOverride("DYNA_VIBRA", {"INCREMENT/INST_FIN": 1.0e9})
    report = run_deck(SAMPLE / "friction_oscillator.export", keyword_overrides=[override])
    assert report.status == "ERROR", report.message
    assert "INST_FIN" in report.message and "steps" in report.message


def test_long_unary_chains_are_located_syntax_errors(tmp_path):
    body = 'F = FORMULE(VALE="' + "-" * 100_000 + 'X", NOM_PARA="X")\n'
    report, seconds, deck = run_text(tmp_path, body)
    assert report.status == "ERROR" and "nested too deeply" in report.message
    assert f"{deck}:2" in report.message and seconds < 30
    assert len(report.message) < 1000  # the excerpt shows part of the long line
    body = "x = " + "-" * 100_000 + "1\n"
    report, _, deck = run_text(tmp_path, body)
    assert report.status == "ERROR" and "nested too deeply" in report.message
    assert f"{deck}:2" in report.message and len(report.message) < 1000


@pytest.mark.parametrize(
    "body, hidden",
    [
        ("T = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=(1.0,)))\nprint('{0.rows}'.format(T))\n", None),
        ("print(_F)\n", " at 0x"),
        ("print('%s' % (print,))\n", " at 0x"),
        ("print(str([print, _F]))\n", " at 0x"),
    ],
)
def test_format_and_print_do_not_reach_engine_internals(tmp_path, body, hidden):
    report, _, _ = run_text(tmp_path, body)
    log = (tmp_path / "out" / "message.log").read_text()
    if hidden is None:
        assert report.status == "ERROR" and "format fields may read attributes" in report.message
    else:
        assert report.status == "DONE", report.message
        assert hidden not in log


def test_a_run_maps_large_arrays_on_their_own(monkeypatch):
    """A run fixes glibc's mapping threshold at 32 MB, so that the large
    temporaries a command frees go back to the system at once."""
    from asterlite import watchdog

    calls = []

    class FakeLibc:
        def mallopt(self, parameter, value):
            calls.append((parameter, value))
            return 1

    monkeypatch.setattr(watchdog.ctypes, "CDLL", lambda name: FakeLibc())
    with watchdog.limits(None, None, compiles=False):
        assert calls == [(watchdog.M_MMAP_THRESHOLD, 32 << 20)]
    assert watchdog.M_MMAP_THRESHOLD == -3  # glibc's M_MMAP_THRESHOLD
