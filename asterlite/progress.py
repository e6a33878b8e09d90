"""Progress bars at the terminal (tqdm): for long DYNA_VIBRA integrations
(simulated time, steps per second, ETA) and for corpus runs.

They draw on standard error only when it is a terminal, and only for work
lasting more than ``DELAY`` seconds, so logs, pipes, tests and short runs
see nothing. ``enable(False)`` (``asterlite run --no-progress``) or the
environment variable ``ASTERLITE_PROGRESS=0`` switch them off.

Compile notices are another matter: whenever numba compiles a kernel (once
per install, ``asterlite warmup`` does it ahead of time) one line on
standard error says so, with the time it usually takes, and one more
when it is done, whatever the terminal (see :func:`kernel`).
"""

from __future__ import annotations

import os
import sys
import time
from contextlib import contextmanager

DELAY = 1.0  # seconds before a bar appears
# the size of the screen when the terminal does not say: a pseudo-terminal
# opened by script, docker -t or a CI runner often reports 0 x 0, from which
# tqdm's own measure makes -1 x -1, and it then draws nothing at all
DEFAULT_COLUMNS, DEFAULT_ROWS = 80, 24
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


def screen(stream=None) -> tuple[int, int]:
    """(columns, rows) to draw a bar in on ``stream`` (standard error): the
    terminal's, else ``COLUMNS``/``LINES``, else 80 x 24 (a terminal that
    reports 0 x 0 is no reason to draw nothing). tqdm is given them instead
    of measuring the terminal itself (``dynamic_ncols``)."""
    stream = stream or sys.stderr
    try:
        size = os.get_terminal_size(stream.fileno())
        width, height = size.columns, size.lines
    except (AttributeError, OSError, ValueError):
        width = height = 0
    return (
        width if width > 0 else _environment_size("COLUMNS", DEFAULT_COLUMNS),
        height if height > 0 else _environment_size("LINES", DEFAULT_ROWS),
    )


def _environment_size(name: str, default: int) -> int:
    try:
        value = int(os.environ.get(name, ""))
    except ValueError:
        return default
    return value if value > 0 else default


def _fit(bar, stream) -> None:
    """Size a tqdm bar to the screen, one column short of the width (tqdm's
    own margin, so that the cursor never wraps)."""
    width, height = screen(stream)
    bar.ncols, bar.nrows = max(width - 1, 10), height


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
        self.stream = stream or sys.stderr
        self.bar = tqdm(
            total=max(t_end - t0, 0.0),
            desc=label,
            delay=DELAY,
            file=self.stream,
            leave=False,
            mininterval=0.0,  # the loop pauses only every quarter second anyway
            ncols=DEFAULT_COLUMNS,  # then the screen's, measured at each update
            nrows=DEFAULT_ROWS,
            # simulated time since the start; the postfix (", N steps/s") follows
            bar_format=(
                "{desc}: {percentage:3.0f}%|{bar}| {n:.4g}/{total:.4g} s simulated"
                "{postfix} [{elapsed}<{remaining}]"
            ),
        )
        _fit(self.bar, self.stream)

    def update(self, t: float, steps: int) -> None:
        rate = steps / max(time.perf_counter() - self.started, 1.0e-9)
        _fit(self.bar, self.stream)
        self.bar.set_postfix_str(f"{rate:,.0f} steps/s", refresh=False)
        self.bar.update(max(t - self.t0, 0.0) - self.bar.n)

    def close(self) -> None:
        self.bar.close()


class CountBar:
    """A count of finished items (corpus decks), the last one in the postfix."""

    def __init__(self, label: str, total: int, stream=None):
        from tqdm import tqdm

        self.stream = stream or sys.stderr
        self.bar = tqdm(
            total=total,
            desc=label,
            delay=DELAY,
            file=self.stream,
            ncols=DEFAULT_COLUMNS,
            nrows=DEFAULT_ROWS,
        )
        _fit(self.bar, self.stream)

    def update(self, done: int, last: str = "") -> None:
        _fit(self.bar, self.stream)
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


# --- compile notices -------------------------------------------------------


class CompileNotice:
    """One block of kernel work (:func:`kernel`): its name, the usual time
    to compile it and the wall seconds numba spent compiling inside it."""

    def __init__(self, name: str, estimate: float | None):
        self.name = name
        self.estimate = estimate
        self.seconds = 0.0
        self.announced = False


_blocks: list[CompileNotice] = []  # the kernel blocks in progress, innermost last
_compile = {"depth": 0, "started": 0.0, "cpu": 0.0, "generic": None, "total": 0.0, "cpu_total": 0.0}
_listening = False
# where notices go (sys.stderr when None; tests and warmup may redirect)
notice_stream = None


def _say(text: str) -> None:
    print(f"asterlite: {text}", file=notice_stream or sys.stderr, flush=True)


@contextmanager
def kernel(name: str, estimate: float | None = None):
    """Run a block that calls the compiled kernel ``name`` (e.g. "NEWMARK"):
    if numba has to compile anything inside it, one line says so before the
    wait ("compiling the NEWMARK kernel, once per install: ~20 s") and one
    after it. Yields the :class:`CompileNotice`, whose ``seconds`` is the
    wall time spent compiling (what a timing of the block should leave out)."""
    if "numba" in sys.modules:  # else asterlite.dynamics.jit listens when it imports numba
        listen_to_compiles()
    notice = CompileNotice(name, estimate)
    _blocks.append(notice)
    try:
        yield notice
    finally:
        _blocks.pop()
        if notice.announced:
            _say(
                f"compiled the {name} kernel in {notice.seconds:.1f} s "
                "(kept in numba's cache: later runs load it)"
            )


def compiled_seconds(cpu: bool = False) -> float:
    """Wall (or CPU) seconds this process has spent compiling kernels so far."""
    return _compile["cpu_total" if cpu else "total"]


def listen_to_compiles() -> None:
    """Follow numba's compile events (once per process; a no-op without numba)."""
    global _listening
    if _listening:
        return
    try:
        from numba.core import event
    except ImportError:
        return

    class CompileListener(event.Listener):
        def on_start(self, event_):
            _compile_started(event_.data.get("dispatcher"))

        def on_end(self, event_):
            _compile_ended()

    event.register("numba:compile", CompileListener())
    _listening = True


def _compile_started(dispatcher) -> None:
    _compile["depth"] += 1
    if _compile["depth"] > 1:  # a callee compiled for the outer function
        return
    _compile["started"], _compile["cpu"] = time.perf_counter(), time.process_time()
    notice = _blocks[-1] if _blocks else None
    if notice is None:  # a compiled function called outside any kernel block
        function = getattr(dispatcher, "py_func", None)
        name = getattr(function, "__module__", "?") + "." + getattr(function, "__qualname__", "?")
        _compile["generic"] = name
        _say(f"compiling {name}, once per install")
    elif not notice.announced:
        notice.announced = True
        usual = f": ~{notice.estimate:.0f} s" if notice.estimate else ""
        _say(f"compiling the {notice.name} kernel, once per install{usual}")


def _compile_ended() -> None:
    _compile["depth"] -= 1
    if _compile["depth"] > 0:
        return
    spent = time.perf_counter() - _compile["started"]
    _compile["total"] += spent
    _compile["cpu_total"] += time.process_time() - _compile["cpu"]
    if _blocks:
        _blocks[-1].seconds += spent
    elif _compile["generic"]:
        _say(f"compiled {_compile['generic']} in {spent:.1f} s")
    _compile["generic"] = None
