"""SIGINT and SIGTERM end a run cleanly: the signal raises
:class:`RunInterrupted` where the run is, the runner records INTERRUPTED in
the output folder, and a signal that comes while the run writes its final
files waits until they are written (then RunInterrupted is raised to the
caller).

Signal handlers belong to the main thread: a run in another thread (a sweep
worker) leaves them alone.
"""

from __future__ import annotations

import signal
import threading
from contextlib import contextmanager

STOP_SIGNALS = (signal.SIGINT, signal.SIGTERM)


class RunInterrupted(KeyboardInterrupt):
    """A stop signal reached the run (a KeyboardInterrupt, so that code which
    catches ``Exception`` cannot swallow it)."""

    def __init__(self, name: str = "SIGINT"):
        super().__init__(name)
        self.signal_name = name


class Stops:
    """While active, a stop signal raises RunInterrupted; once ``finishing()``
    is called it is only remembered, and re-delivered when the block ends."""

    def __init__(self):
        self.finishing_now = False
        self.pending: int | None = None

    def handle(self, number, _frame) -> None:
        if self.finishing_now:
            self.pending = number
            return
        raise RunInterrupted(signal.Signals(number).name)

    def finishing(self) -> None:
        self.finishing_now = True


@contextmanager
def stop_on_signals():
    """Install the handlers for the block (main thread only)."""
    stops = Stops()
    if threading.current_thread() is not threading.main_thread():
        yield stops
        return
    previous = {number: signal.signal(number, stops.handle) for number in STOP_SIGNALS}
    try:
        yield stops
    finally:
        for number, handler in previous.items():
            signal.signal(number, handler)
    if stops.pending is not None:  # a signal that came while finishing: the caller stops now
        raise RunInterrupted(signal.Signals(stops.pending).name)
