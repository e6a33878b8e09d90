"""Signals that would end the process end a run cleanly instead: the signal
raises :class:`RunInterrupted` where the run is, and the runner records
INTERRUPTED in the output folder.

Handled: SIGINT, SIGTERM, SIGHUP (a closed terminal), SIGQUIT, SIGUSR1,
SIGUSR2 and SIGALRM, whose default action ends the process without a word,
leaving ``summary.json`` saying RUNNING. A signal the process ignores (SIGHUP
under ``nohup``, SIGPIPE: Python ignores it, a broken pipe is an error on
the write) stays ignored.

A signal is *held* (remembered, not raised) while the run takes its output
folder, so that an earlier result is always moved aside and the RUNNING
summary written before the run stops, and while it writes its final files;
:meth:`Stops.release` raises one that came meanwhile. While the run starts,
a second signal stops it at once (a user who insists is not kept waiting).

Signal handlers belong to the main thread: a run in another thread (a sweep
worker) leaves them alone.
"""

from __future__ import annotations

import signal
import threading
from contextlib import contextmanager

STOP_SIGNALS = tuple(
    getattr(signal, name)
    for name in ("SIGINT", "SIGTERM", "SIGHUP", "SIGQUIT", "SIGUSR1", "SIGUSR2", "SIGALRM")
    if hasattr(signal, name)
)


class RunInterrupted(KeyboardInterrupt):
    """A stop signal reached the run (a KeyboardInterrupt, so that code which
    catches ``Exception`` cannot swallow it). ``report`` is the run's report
    when the signal came after the run's result was written."""

    def __init__(self, name: str = "SIGINT"):
        super().__init__(name)
        self.signal_name = name
        self.report = None


class Stops:
    """While active, a stop signal raises RunInterrupted; while held it is
    only remembered, and raised by :meth:`release`."""

    def __init__(self, held: bool = False):
        self.held = held
        self.starting = held  # held while the run starts: a second signal stops it
        self.pending: int | None = None

    def handle(self, number, _frame) -> None:
        if self.held and not (self.starting and self.pending is not None):
            if self.pending is None:
                self.pending = number
            return
        self.pending = None
        raise RunInterrupted(signal.Signals(number).name)

    def hold(self) -> None:
        """From now on a signal waits (the run writes its final files)."""
        self.held = True
        self.starting = False

    def release(self) -> None:
        """Signals stop the run from now on; one that came while held does now."""
        self.held = self.starting = False
        if self.pending is not None:
            number, self.pending = self.pending, None
            raise RunInterrupted(signal.Signals(number).name)

    def take_pending(self) -> str | None:
        """The name of a signal that came while held (forgotten here)."""
        number, self.pending = self.pending, None
        return signal.Signals(number).name if number is not None else None


def _handled(number: int) -> bool:
    """Whether to take ``number`` over: not when the process ignores it."""
    try:
        return signal.getsignal(number) is not signal.SIG_IGN
    except (ValueError, OSError):
        return False


@contextmanager
def stop_on_signals(held: bool = False):
    """Install the handlers for the block (main thread only). A signal an
    enclosing :class:`Stops` holds (``asterlite run`` holds them from its
    start) passes to this one."""
    stops = Stops(held)
    if threading.current_thread() is not threading.main_thread():
        yield stops
        return
    previous = {}
    for number in STOP_SIGNALS:
        if _handled(number):
            previous[number] = signal.signal(number, stops.handle)
    for handler in previous.values():
        outer = getattr(handler, "__self__", None)
        if isinstance(outer, Stops) and outer.pending is not None and stops.pending is None:
            stops.pending, outer.pending = outer.pending, None
    try:
        yield stops
    finally:
        for number, handler in previous.items():
            signal.signal(number, handler)


def hold_signals() -> Stops:
    """Hold every stop signal for the rest of the process (``asterlite run``
    from its start: a signal before the run has taken its folder waits, the
    run then records it). Main thread only."""
    stops = Stops(held=True)
    if threading.current_thread() is threading.main_thread():
        for number in STOP_SIGNALS:
            if _handled(number):
                signal.signal(number, stops.handle)
    return stops
