"""The run's time and memory limits (an export's ``P time_limit`` and
``P memory_limit``, or the ``asterlite run`` options that override them).

code_aster gives a study ``time_limit`` seconds of CPU time in all (its
supervisor stops a study that runs out of time) and ``memory_limit``
megabytes for its data on top of what the process held at start-up.
asterlite does the same:

- time: the process's CPU time (so a loaded machine does not cut a study
  short), checked where a run can stop cleanly, before each command and at
  every pause of the compiled time loop (a few times a second), raising
  :class:`TimeLimitError` located at the running command;
- memory: the resident memory the run has added since it started is checked
  where the time is (:class:`MemoryLimitError`), and the address space is
  capped (``RLIMIT_AS``) at the start-up size plus four times the limit, so
  that a runaway allocation fails at once with a MemoryError that the
  session turns into a :class:`MemoryLimitError` located at the command.

numba's compilation of a kernel (once per install, cached afterwards) is
not the study's work: the time it takes is not counted and the cap is lifted
while it runs, then moved up by what the compiler kept.

The limits are per thread (``threading.local``): runs in other threads of
the same process (a sweep) keep their own.

In the main thread the time limit is also enforced between those points: a
CPU-time timer (``ITIMER_PROF``) raises TimeLimitError wherever Python code
runs once the time is spent (a long deck loop, a slow Python-level call),
and again every second if something swallowed it; and the soft
``RLIMIT_CPU`` is set a grace period beyond the limit, so a computation stuck
in compiled code that never returns to Python ends the process (SIGXCPU)
instead of running on.
"""

from __future__ import annotations

import os
import signal
import threading
import time
from contextlib import contextmanager

from asterlite.errors import AsterliteError

_state = threading.local()
MEGABYTE = 1024 * 1024
PAGE_SIZE = os.sysconf("SC_PAGE_SIZE") if hasattr(os, "sysconf") else 4096
ADDRESS_SPACE_HEADROOM = 4  # address-space cap, in memory limits


class TimeLimitError(AsterliteError):
    """The run went past its time limit."""

    kind = "time limit exceeded"
    fatal = True  # ends the run even where other errors are collected (check)


class MemoryLimitError(AsterliteError):
    """An allocation went past the run's memory limit."""

    kind = "memory limit exceeded"
    fatal = True


def _spent() -> float:
    """CPU seconds of the process, less the time spent compiling kernels."""
    return time.process_time() - _compiling.seconds


def check_limits() -> None:
    """Where a run can stop cleanly (between commands, at the time loop's
    pauses): MemoryLimitError or TimeLimitError when a limit is passed."""
    check_memory()
    check_time()


def check_time() -> None:
    """Raise TimeLimitError when the current run's deadline has passed (the
    CPU timer's signal handler asks this alone: no memory work there)."""
    deadline = getattr(_state, "deadline", None)
    if deadline is None or _spent() < deadline:
        return
    limit = _state.seconds
    raise TimeLimitError(
        f"the run's time limit of {limit:g} s is exhausted (export 'P time_limit', "
        "or asterlite run --time-limit to change it)"
    )


def _resident_size() -> int | None:
    """The process's resident memory in bytes (Linux), None where unknown."""
    try:
        with open("/proc/self/statm", encoding="ascii") as statm:
            return int(statm.read().split()[1]) * PAGE_SIZE
    except (OSError, ValueError, IndexError):
        return None


def _released_size() -> int | None:
    """The resident size once unreachable objects are collected and the C
    allocator has returned its free pages to the system (glibc)."""
    import gc

    gc.collect()
    try:
        import ctypes

        ctypes.CDLL("libc.so.6").malloc_trim(0)
    except (OSError, AttributeError):
        pass
    return _resident_size()


def check_memory() -> None:
    """Raise MemoryLimitError when the resident memory has grown past the limit
    since the run started (checked where the time limit is)."""
    limit = getattr(_state, "memory_mb", None)
    start = getattr(_state, "resident_start", None)
    if limit is None or start is None:
        return
    # what numba's compiler kept during this run is not the study's
    start += _compiling.resident - getattr(_state, "compiled_at_start", 0)
    resident = _resident_size()
    if resident is not None and resident - start > limit * MEGABYTE:
        resident = _released_size()  # garbage not yet given back is not the study's
    if resident is not None and resident - start > limit * MEGABYTE:
        raise MemoryLimitError(
            f"the run holds {(resident - start) / MEGABYTE:.0f} MB, more than its limit of "
            f"{limit:g} MB (export 'P memory_limit', or asterlite run --memory-limit to change it)"
        )


def memory_limit_mb() -> float | None:
    """The memory limit of the current run in MB (None when unlimited)."""
    return getattr(_state, "memory_mb", None)


@contextmanager
def limits(seconds: float | None = None, megabytes: float | None = None, compiles: bool = True):
    """Enforce a time and a memory limit for the duration of the block;
    ``compiles=False`` (``asterlite check``, which compiles nothing) leaves
    numba unimported."""
    if compiles:
        _listen_to_compilation()
    _state.deadline = None if seconds is None else _spent() + seconds
    _state.seconds = seconds
    _state.memory_mb = megabytes
    _state.resident_start = _resident_size()
    _state.compiled_at_start = _compiling.resident
    try:
        with _address_space_cap(megabytes), _cpu_timer(seconds):
            yield
    finally:
        _state.deadline = _state.seconds = _state.memory_mb = _state.resident_start = None


def address_space_size() -> int | None:
    """The process's address space in bytes (Linux), None where unknown."""
    try:
        with open("/proc/self/status", encoding="ascii") as status:
            for line in status:
                if line.startswith("VmSize:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        return None
    return None


class _Compilation:
    """Time spent in numba's compiler, and the address-space cap lifted meanwhile."""

    def __init__(self):
        self.seconds = 0.0
        self.depth = 0
        self.started = 0.0
        self.size_before = None
        self.resident_before = None
        self.resident = 0  # resident memory the compiler kept (code, LLVM state)
        self.cap = None  # (soft, hard) in force before a compilation lifted it


_compiling = _Compilation()
_listening = False


def _listen_to_compilation() -> None:
    """Follow numba's compile events (once per process)."""
    global _listening
    if _listening:
        return
    try:
        from numba.core import event
    except ImportError:  # no numba, nothing is ever compiled
        return

    class CompileListener(event.Listener):
        def on_start(self, _event):
            _compile_started()

        def on_end(self, _event):
            _compile_ended()

    event.register("numba:compile", CompileListener())
    _listening = True


def _compile_started() -> None:
    _compiling.depth += 1
    if _compiling.depth > 1:  # a callee compiled inside an outer compilation
        return
    _compiling.started = time.process_time()
    _compiling.size_before = address_space_size()
    _compiling.resident_before = _resident_size()
    try:
        import resource

        soft, hard = resource.getrlimit(resource.RLIMIT_AS)
        if soft != resource.RLIM_INFINITY:
            _compiling.cap = (soft, hard)
            resource.setrlimit(resource.RLIMIT_AS, (hard, hard))
    except (ImportError, ValueError, OSError):
        _compiling.cap = None


def _compile_ended() -> None:
    _compiling.depth -= 1
    if _compiling.depth > 0:
        return
    spent = time.process_time() - _compiling.started
    _compiling.seconds += spent
    _extend_cpu_backstop(spent)
    after, before = _resident_size(), _compiling.resident_before
    if after is not None and before is not None:
        _compiling.resident += max(0, after - before)
    if _compiling.cap is None:
        return
    import resource

    soft, hard = _compiling.cap
    grown = max(0, (address_space_size() or 0) - (_compiling.size_before or 0))
    raised = soft + grown if hard == resource.RLIM_INFINITY else min(soft + grown, hard)
    resource.setrlimit(resource.RLIMIT_AS, (raised, hard))
    _compiling.cap = None


@contextmanager
def address_space_cap(cap_bytes: int | None):
    """Cap RLIMIT_AS at ``cap_bytes`` for the block (never raising an existing
    lower cap), then restore it; a no-op where the platform cannot set it."""
    try:
        import resource

        soft, hard = resource.getrlimit(resource.RLIMIT_AS)
    except (ImportError, ValueError, OSError, AttributeError):
        soft = hard = None
    if cap_bytes is None or soft is None:
        yield
        return
    for existing in (soft, hard):
        if existing != resource.RLIM_INFINITY:
            cap_bytes = min(cap_bytes, existing)
    resource.setrlimit(resource.RLIMIT_AS, (cap_bytes, hard))
    try:
        yield
    finally:
        resource.setrlimit(resource.RLIMIT_AS, (soft, hard))


def _address_space_cap(megabytes: float | None):
    """RLIMIT_AS at the current size plus a multiple of ``megabytes``: the
    address space runs well ahead of the resident memory (thread stacks,
    allocator arenas), so the cap only stops a runaway allocation at once; the
    limit itself is checked on resident memory (check_memory)."""
    size = address_space_size()
    if megabytes is None or size is None:
        return address_space_cap(None)
    return address_space_cap(size + int(ADDRESS_SPACE_HEADROOM * megabytes * MEGABYTE))


def preload_engine() -> None:
    """Import the libraries every run needs before the memory cap is set, so
    that the cap measures the study's data, not the interpreter's libraries
    (code_aster likewise adds its start-up footprint to memory_limit)."""
    import numba  # noqa: F401
    import numpy  # noqa: F401
    import scipy.linalg  # noqa: F401
    import scipy.sparse  # noqa: F401
    import scipy.sparse.linalg  # noqa: F401


# seconds of CPU past the time limit before RLIMIT_CPU ends a process stuck
# in compiled code (a Python-level stop is tried first, see _cpu_timer)
CPU_GRACE_SECONDS = 30.0
CPU_GRACE_FRACTION = 0.25


def _on_cpu_timer(_number, _frame) -> None:
    """SIGPROF: stop the run if its time is spent, else wait for the rest."""
    deadline = getattr(_state, "deadline", None)
    if deadline is None:
        return
    remaining = deadline - _spent()
    if remaining > 0.0:  # compilation time was not the study's: wait longer
        signal.setitimer(signal.ITIMER_PROF, max(remaining, 0.01))
        return
    signal.setitimer(signal.ITIMER_PROF, 1.0)  # again, in case this one is swallowed
    check_time()


@contextmanager
def _cpu_timer(seconds: float | None):
    """Arm the CPU-time timer and the RLIMIT_CPU backstop (main thread only)."""
    if seconds is None or threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = signal.signal(signal.SIGPROF, _on_cpu_timer)
    signal.setitimer(signal.ITIMER_PROF, max(seconds, 0.01))
    backstop = _set_cpu_backstop(seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0.0)
        signal.signal(signal.SIGPROF, previous)
        _restore_cpu_backstop(backstop)


def _set_cpu_backstop(seconds: float):
    """Lower the soft RLIMIT_CPU to now + limit + grace; the previous limits."""
    try:
        import resource

        soft, hard = resource.getrlimit(resource.RLIMIT_CPU)
        grace = max(CPU_GRACE_SECONDS, CPU_GRACE_FRACTION * seconds)
        target = int(time.process_time() + seconds + grace) + 1
        if soft != resource.RLIM_INFINITY:
            target = min(target, soft)
        if hard != resource.RLIM_INFINITY:
            target = min(target, hard)
        resource.setrlimit(resource.RLIMIT_CPU, (target, hard))
    except (ImportError, ValueError, OSError):
        return None
    _backstop.previous = (soft, hard)
    return soft, hard


def _extend_cpu_backstop(seconds: float) -> None:
    """Compilation is not the study's time: move the backstop by what it took."""
    if _backstop.previous is None or seconds <= 0.0:
        return
    try:
        import resource

        soft, hard = resource.getrlimit(resource.RLIMIT_CPU)
        if soft == resource.RLIM_INFINITY:
            return
        raised = soft + int(seconds) + 1
        if hard != resource.RLIM_INFINITY:
            raised = min(raised, hard)
        resource.setrlimit(resource.RLIMIT_CPU, (raised, hard))
    except (ImportError, ValueError, OSError):
        pass


def _restore_cpu_backstop(previous) -> None:
    _backstop.previous = None
    if previous is None:
        return
    try:
        import resource

        resource.setrlimit(resource.RLIMIT_CPU, previous)
    except (ImportError, ValueError, OSError):
        pass


class _Backstop:
    previous = None  # (soft, hard) RLIMIT_CPU before the run lowered it


_backstop = _Backstop()
