"""Progress bars at the terminal (tqdm): for long DYNA_VIBRA integrations
(simulated time, steps per second, ETA) and for corpus runs.

They draw on standard error only when it is a terminal, and only for work
lasting more than ``DELAY`` seconds, so logs, pipes, tests and short runs
see nothing. ``enable(False)`` (``asterlite run --no-progress``) or the
environment variable ``ASTERLITE_PROGRESS=0`` switch them off.
"""

from __future__ import annotations

import os
import sys
import time

DELAY = 1.0  # seconds before a bar appears
_enabled: bool | None = None  # None: decide from the terminal


def enable(on: bool | None) -> None:
    """Force bars on or off (None: back to the terminal test)."""
    global _enabled
    _enabled = on


def wanted() -> bool:
    if _enabled is not None:
        return _enabled
    if os.environ.get("ASTERLITE_PROGRESS", "1") == "0":
        return False
    return sys.stderr.isatty()


class NoBar:
    """What callers get when bars are off: every call does nothing."""

    def update(self, *args, **kwargs) -> None:
        pass

    def write(self, text: str) -> None:
        print(text, file=sys.stderr)

    def close(self) -> None:
        pass


class TimeBar:
    """Simulated time of an integration, with steps per second."""

    def __init__(self, label: str, t0: float, t_end: float, stream=None):
        from tqdm import tqdm

        self.t0 = t0
        self.started = time.perf_counter()
        self.bar = tqdm(
            total=max(t_end - t0, 0.0),
            desc=label,
            delay=DELAY,
            file=stream or sys.stderr,
            leave=False,
            mininterval=0.0,  # the loop pauses only every quarter second anyway
            dynamic_ncols=True,
            # simulated time since the start; the postfix (", N steps/s") follows
            bar_format=(
                "{desc}: {percentage:3.0f}%|{bar}| {n:.4g}/{total:.4g} s simulated"
                "{postfix} [{elapsed}<{remaining}]"
            ),
        )

    def update(self, t: float, steps: int) -> None:
        rate = steps / max(time.perf_counter() - self.started, 1.0e-9)
        self.bar.set_postfix_str(f"{rate:,.0f} steps/s", refresh=False)
        self.bar.update(max(t - self.t0, 0.0) - self.bar.n)

    def close(self) -> None:
        self.bar.close()


class CountBar:
    """A count of finished items (corpus decks), the last one in the postfix."""

    def __init__(self, label: str, total: int, stream=None):
        from tqdm import tqdm

        self.bar = tqdm(
            total=total, desc=label, delay=DELAY, file=stream or sys.stderr, dynamic_ncols=True
        )

    def update(self, done: int, last: str = "") -> None:
        self.bar.set_postfix_str(last, refresh=False)
        self.bar.update(done - self.bar.n)

    def write(self, text: str) -> None:
        self.bar.write(text, file=sys.stderr)

    def close(self) -> None:
        self.bar.close()


def time_bar(label: str, t0: float, t_end: float):
    return TimeBar(label, t0, t_end) if wanted() else NoBar()


def count_bar(label: str, total: int):
    return CountBar(label, total) if wanted() else NoBar()
