"""The integration's progress bar at a pseudo-terminal.

A pseudo-terminal opened by ``script``, ``docker -t`` or a CI runner often
reports a screen of 0 x 0: tqdm measured it as -1 x -1 and drew nothing,
so a long run at such a terminal showed no bar although the README
promises one. The bar is now drawn at 80 x 24 when the terminal does not
say its size (:func:`asterlite.progress.screen`).
"""

from __future__ import annotations

import os
import pty
import select
import subprocess
import sys
import time
from pathlib import Path

from asterlite import progress
from tests.test_extremes_decks import Chain, Shock, write


def read_all(fd: int, process: subprocess.Popen, timeout: float) -> bytes:
    """Everything written on the terminal until the process ends."""
    out = b""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        ready, _, _ = select.select([fd], [], [], 0.2)
        if ready:
            try:
                chunk = os.read(fd, 65536)
            except OSError:  # the other side is closed
                break
            if not chunk:
                break
            out += chunk
        elif process.poll() is not None:
            break
    return out


def long_deck(folder: Path) -> Path:
    """One mass on a spring against a stop, ~10^8 steps: a few seconds."""
    chain = Chain(
        depl={1: (0.0, 1.0e-3, 0.0)},
        shocks=[Shock(1, 5.0e-4, 1.0e6)],
        pas=1.0e-6,
        inst_fin=100.0,
        pas_arch=10**6,
        post=False,
    )
    return write(chain, folder)


def test_bar_is_drawn_at_a_terminal_of_zero_size(tmp_path):
    export = long_deck(tmp_path / "deck")
    main, child = pty.openpty()  # a new pseudo-terminal reports 0 x 0
    assert os.get_terminal_size(child) == os.terminal_size((0, 0))
    env = {**os.environ, "ASTERLITE_PROGRESS": "1"}
    env.pop("COLUMNS", None)
    env.pop("LINES", None)
    command = [sys.executable, "-m", "asterlite", "run", str(export), "-o", str(tmp_path / "out")]
    process = subprocess.Popen(
        command, stdin=child, stdout=subprocess.DEVNULL, stderr=child, env=env, close_fds=True
    )
    os.close(child)
    try:
        screen = read_all(main, process, timeout=300).decode("utf-8", "replace")
    finally:
        os.close(main)
        process.wait(timeout=60)
    assert process.returncode == 0, screen[-2000:]
    assert "s simulated" in screen and "steps/s" in screen, screen[-2000:]
    assert "DIFF_CENTRE:" in screen and "%|" in screen


def test_screen_size_defaults(monkeypatch):
    main, child = pty.openpty()
    try:
        stream = os.fdopen(child, "w")
        monkeypatch.delenv("COLUMNS", raising=False)
        monkeypatch.delenv("LINES", raising=False)
        assert progress.screen(stream) == (80, 24)
        monkeypatch.setenv("COLUMNS", "132")
        assert progress.screen(stream) == (132, 24)
        stream.close()
    finally:
        os.close(main)
