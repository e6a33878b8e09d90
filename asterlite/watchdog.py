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
- memory: the resident memory the run has added since it started (pages
  backed by files, which the system takes back at will, not counted: the
  memory maps of archives kept on disk) is checked
  where the time is (:class:`MemoryLimitError`), and the address space is
  capped (``RLIMIT_AS``) at the start-up size plus four times the limit, so
  that a runaway allocation fails at once with a MemoryError that the
  session turns into a :class:`MemoryLimitError` located at the command.
  The address space runs well ahead of the resident memory (thread stacks,
  allocator arenas), which is why the cap is that loose: a deck loop could
  grow to four times the limit under it, so in the main thread the
  resident memory is also sampled every 10 ms of CPU time while anything
  runs (the CPU-time timer below), which stops deck code at the limit.

A run also fixes glibc's mapping threshold at 32 MB (``steady_allocator``):
an array of that size or more is returned to the system when freed, so the
resident size a command leaves is what it holds, not the high-water mark of
its large temporaries in the heap.

numba's compilation of a kernel (once per install, cached afterwards) and
its loading from the cache are not the study's work (code_aster does not
count its own code either): the time they take is not counted and the cap is
lifted while they run, then moved up by what they kept.

The limits are per thread (``threading.local``): runs in other threads of
the same process (a sweep) keep their own.

In the main thread the limits are also enforced between those points: a
CPU-time timer (``ITIMER_PROF``, every 10 ms of CPU when there is a memory
limit) raises MemoryLimitError or TimeLimitError wherever Python code runs
(a long deck loop, a slow Python-level call), and again a second later if
something swallowed it. A computation in compiled code that does not return
to Python within a grace period past the limit (a quarter of the limit, at
least 2 s) gets SIGXCPU from the soft ``RLIMIT_CPU``, handled as a
TimeLimitError where Python resumes, so the run still ends with its status;
if it never returns, a CPU-time timer with no handler (``ITIMER_VIRTUAL``,
SIGVTALRM) ends the process one grace period later. Neither is permanent:
both are restored when the run ends (a hard RLIMIT_CPU could never be
raised again, and an API user's process outlives the run).
"""

from __future__ import annotations

import ctypes
import gc
import os
import resource
import signal
import sys
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
    """The process's resident memory in bytes that the system cannot take
    back without writing it out (Linux), None where unknown: the resident
    pages less those shared with files, which the system drops when it needs
    them (memory maps of archives on disk, of libraries)."""
    try:
        with open("/proc/self/statm", encoding="ascii") as statm:
            fields = statm.read().split()
        return (int(fields[1]) - int(fields[2])) * PAGE_SIZE
    except (OSError, ValueError, IndexError):
        return None


def _released_size() -> int | None:
    """The resident size once the C allocator has returned its free pages to
    the system (glibc) and, at most once a CPU second (a full collection of
    a large heap takes long), unreachable objects are collected."""

    trim_allocator()
    now = time.process_time()
    if now - getattr(_state, "collected_at", -1.0e9) >= GC_INTERVAL_SECONDS:
        _state.collected_at = now
        gc.collect()
        trim_allocator()
    return _resident_size()


GC_INTERVAL_SECONDS = 1.0


def trim_allocator() -> None:
    """Give the C allocator's free pages back to the system (glibc; a fraction
    of a millisecond when little is free)."""
    try:
        ctypes.CDLL("libc.so.6").malloc_trim(0)
    except (OSError, AttributeError):
        pass


# glibc's mallopt parameter, and the size from which a block is mapped on its own
M_MMAP_THRESHOLD = -3
# 32 MB, glibc's own ceiling for the threshold: at 1 MB, mapping and zeroing
# every temporary anew cost sdlv126h 6 s of system CPU (58.8 against 53.1 s
# at 32 MB, 2026-11-29) for 18 MB less in forma12b (VmHWM 429 against 447 MB)
MAPPED_BLOCK_BYTES = 32 << 20


def steady_allocator() -> None:
    """Give arrays of 32 MB and more their own mappings, returned to the
    system when freed. glibc's threshold for that starts at 128 kB and
    rises to the size of each mapped block freed (up to 32 MB): after the
    first large temporary is freed, the next ones come from the heap, whose
    free space the system gets back only once its top is free, so the
    resident size keeps the high-water mark of every command's temporaries
    (a NEWMARK step's operator held 40 MB more). Setting the threshold fixes
    it for the process (glibc has no way back to the rising one)."""
    try:
        ctypes.CDLL("libc.so.6").mallopt(M_MMAP_THRESHOLD, MAPPED_BLOCK_BYTES)
    except (OSError, AttributeError):
        pass


def _study_start() -> int | None:
    """The resident size the run's memory is counted from: its start-up
    size, plus what numba's compiler kept during the run (not the study's)."""
    start = getattr(_state, "resident_start", None)
    if start is None:
        return None
    return start + _compiling.resident - getattr(_state, "compiled_at_start", 0)


def check_memory() -> None:
    """Raise MemoryLimitError when the resident memory has grown past the limit
    since the run started (checked where the time limit is)."""
    limit, start = getattr(_state, "memory_mb", None), _study_start()
    if limit is None or start is None:
        return
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


def memory_headroom() -> int | None:
    """Bytes the run may still add before its memory limit (None when
    unlimited): what a computation that can trade memory for disk (MUMPS's
    out-of-core factor) compares its estimate with."""
    limit, start = getattr(_state, "memory_mb", None), _study_start()
    if limit is None or start is None:
        return None
    resident = _released_size()
    if resident is None:
        return None
    cap = int(limit * MEGABYTE)  # memory freed since the start gives no more than the limit
    return max(0, min(cap, cap - (resident - start)))


@contextmanager
def limits(seconds: float | None = None, megabytes: float | None = None, compiles: bool = True):
    """Enforce a time and a memory limit for the duration of the block;
    ``compiles=False`` (``asterlite check``, which compiles nothing) leaves
    numba unimported."""
    if compiles and "numba" in sys.modules:  # else asterlite.dynamics.jit listens on import
        listen_to_compilation()
    steady_allocator()
    _state.deadline = None if seconds is None else _spent() + seconds
    _state.seconds = seconds
    _state.memory_mb = megabytes
    # counted from the size once the allocator's free pages are given back, as
    # the checks count (else pages freed later hide as much of the study's own
    # growth); no collection: a run starts with next to no garbage, and a full
    # collection of the imported modules costs ~10 ms of a start
    if megabytes is not None:
        trim_allocator()
    _state.resident_start = _resident_size()
    _state.collected_at = time.process_time()  # the first collection a CPU second in
    _state.compiled_at_start = _compiling.resident
    _state.quiet_until = None
    try:
        with _address_space_cap(megabytes), _cpu_timer(seconds, megabytes):
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


@contextmanager
def compiler_work():
    """Account a block as numba's compilations are (numba's own import): its
    time and the memory it keeps are not the study's, the address-space cap
    is lifted meanwhile."""
    _compile_started()
    try:
        yield
    finally:
        _compile_ended()


def listen_to_compilation() -> None:
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

    # numba holds its compiler lock to compile a kernel and to load it from
    # the cache (the compile event covers compilations only)
    event.register("numba:compiler_lock", CompileListener())
    _listening = True


def _compile_started() -> None:
    _compiling.depth += 1
    if _compiling.depth > 1:  # a callee compiled inside an outer compilation
        return
    _compiling.started = time.process_time()
    _pause_cpu_backstop()  # a long compilation must not meet SIGXCPU or SIGVTALRM
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
    _resume_cpu_backstop(spent)
    after, before = _resident_size(), _compiling.resident_before
    if after is not None and before is not None:
        _compiling.resident += max(0, after - before)
    if _compiling.cap is None:
        return

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
    (code_aster likewise adds its start-up footprint to memory_limit). numba
    is imported only when a numba kernel runs, its import accounted as a
    compilation (:mod:`asterlite.dynamics.jit`)."""
    import numpy  # noqa: F401
    import scipy.linalg  # noqa: F401
    import scipy.sparse  # noqa: F401
    import scipy.sparse.linalg  # noqa: F401


# CPU seconds past the time limit before SIGXCPU stops compiled code that
# has not returned to Python, and again before SIGVTALRM ends the process
CPU_GRACE_SECONDS = 2.0
CPU_GRACE_FRACTION = 0.25
MEMORY_SAMPLE_SECONDS = 0.01  # CPU seconds between two looks at the resident memory
REPEAT_SECONDS = 1.0  # a stop swallowed somewhere is raised again this much later


def cpu_grace(seconds: float) -> float:
    return max(CPU_GRACE_SECONDS, CPU_GRACE_FRACTION * seconds)


def _next_tick() -> float:
    """CPU seconds until the timer must look again: the next memory sample,
    or the deadline (compilation time is not the study's: it moves it)."""
    waits = []
    if getattr(_state, "memory_mb", None) is not None:
        waits.append(MEMORY_SAMPLE_SECONDS)
    deadline = getattr(_state, "deadline", None)
    if deadline is not None:
        waits.append(deadline - _spent())
    return max(min(waits, default=REPEAT_SECONDS), MEMORY_SAMPLE_SECONDS)


def _on_cpu_timer(_number, _frame) -> None:
    """SIGPROF: stop the run if its memory or its time is spent (never while
    numba compiles: neither its time nor its memory is the study's)."""
    if not getattr(_state, "timer_armed", False):
        return  # arrived while the timer was being disarmed: re-arming it would outlive the handler
    if getattr(_state, "memory_mb", None) is None and getattr(_state, "deadline", None) is None:
        return
    signal.setitimer(signal.ITIMER_PROF, _next_tick())
    if _compiling.depth > 0:
        return
    now = time.process_time()
    quiet_until = getattr(_state, "quiet_until", None)
    if quiet_until is not None and now < quiet_until:
        return  # a stop is on its way out: give it time to end the run
    try:
        check_memory()
        check_time()
    except (MemoryLimitError, TimeLimitError):
        _state.quiet_until = now + REPEAT_SECONDS
        raise


def _on_cpu_exhausted(_number, _frame) -> None:
    """SIGXCPU (the soft RLIMIT_CPU, a grace period past the limit): compiled
    code held the CPU past the limit; stop where Python resumes."""
    limit = getattr(_state, "seconds", None)
    if limit is None:
        return
    raise TimeLimitError(
        f"the run's time limit of {limit:g} s is exhausted: a computation in compiled code "
        f"went on {cpu_grace(limit):g} s past it (export 'P time_limit', or asterlite run "
        "--time-limit to change it)"
    )


@contextmanager
def _cpu_timer(seconds: float | None, megabytes: float | None = None):
    """Arm the CPU-time timer, and the SIGXCPU and SIGVTALRM backstops of a
    time limit (main thread only: signals are handled there)."""
    if (seconds is None and megabytes is None) or (
        threading.current_thread() is not threading.main_thread()
    ):
        yield
        return
    previous = signal.signal(signal.SIGPROF, _on_cpu_timer)
    signal.siginterrupt(signal.SIGPROF, False)  # 100 times a second: restart system calls
    previous_xcpu = signal.signal(signal.SIGXCPU, _on_cpu_exhausted) if seconds else None
    was_armed = getattr(_state, "timer_armed", False)
    _state.timer_armed = True
    signal.setitimer(signal.ITIMER_PROF, _next_tick())
    backstop = _set_cpu_backstop(seconds) if seconds else None
    try:
        yield
    finally:
        # disarmed before the timer stops: a SIGPROF already pending runs its
        # handler after setitimer(0), and must not start the timer again under
        # the previous (often default: fatal) disposition
        _state.timer_armed = False
        signal.setitimer(signal.ITIMER_PROF, 0.0)
        signal.signal(signal.SIGPROF, previous)
        if was_armed:  # an enclosing run's timer goes on
            _state.timer_armed = True
            signal.setitimer(signal.ITIMER_PROF, _next_tick())
        _restore_cpu_backstop(backstop)
        if previous_xcpu is not None:
            signal.signal(signal.SIGXCPU, previous_xcpu)


def _set_cpu_backstop(seconds: float):
    """Lower the soft RLIMIT_CPU to now + limit + grace (SIGXCPU) and arm the
    SIGVTALRM timer one grace later (its default action ends the process);
    the previous RLIMIT_CPU."""
    grace = cpu_grace(seconds)
    _arm_kill_timer(seconds + 2 * grace)
    try:
        import resource

        soft, hard = resource.getrlimit(resource.RLIMIT_CPU)
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


def _arm_kill_timer(seconds: float) -> None:
    """SIGVTALRM after ``seconds`` more of user CPU time, with its default
    action (the process ends): what compiled code that never returns meets."""
    try:
        signal.signal(signal.SIGVTALRM, signal.SIG_DFL)
        signal.setitimer(signal.ITIMER_VIRTUAL, max(seconds, 0.01))
        _backstop.kill_armed = True
    except (AttributeError, OSError, ValueError):
        _backstop.kill_armed = False


def _pause_cpu_backstop() -> None:
    """While numba compiles: the soft RLIMIT_CPU at its hard value, the
    SIGVTALRM timer stopped (what it had left is kept)."""
    if _backstop.previous is None:
        return
    if _backstop.kill_armed:
        _backstop.kill_left, _interval = signal.getitimer(signal.ITIMER_VIRTUAL)
        signal.setitimer(signal.ITIMER_VIRTUAL, 0.0)
    try:
        import resource

        _backstop.soft_before_compiling, hard = resource.getrlimit(resource.RLIMIT_CPU)
        resource.setrlimit(resource.RLIMIT_CPU, (hard, hard))
    except (ImportError, ValueError, OSError):
        _backstop.soft_before_compiling = None


def _resume_cpu_backstop(seconds: float) -> None:
    """Compilation is not the study's time: the backstops resume, moved by
    what it took."""
    if _backstop.previous is None:
        return
    if _backstop.kill_armed and _backstop.kill_left > 0.0:
        signal.setitimer(signal.ITIMER_VIRTUAL, _backstop.kill_left)
    soft = _backstop.soft_before_compiling
    _backstop.soft_before_compiling = None
    try:
        import resource

        _, hard = resource.getrlimit(resource.RLIMIT_CPU)
        if soft is None or soft == resource.RLIM_INFINITY:
            return
        raised = soft + int(seconds) + 1
        if hard != resource.RLIM_INFINITY:
            raised = min(raised, hard)
        resource.setrlimit(resource.RLIMIT_CPU, (raised, hard))
    except (ImportError, ValueError, OSError):
        pass


def _restore_cpu_backstop(previous) -> None:
    _backstop.previous = None
    if _backstop.kill_armed:
        signal.setitimer(signal.ITIMER_VIRTUAL, 0.0)
        _backstop.kill_armed = False
    if previous is None:
        return
    try:
        import resource

        resource.setrlimit(resource.RLIMIT_CPU, previous)
    except (ImportError, ValueError, OSError):
        pass


class _Backstop:
    previous = None  # (soft, hard) RLIMIT_CPU before the run lowered it
    kill_armed = False  # the SIGVTALRM timer is set
    kill_left = 0.0  # its seconds left when a compilation stopped it
    soft_before_compiling = None  # the soft RLIMIT_CPU a compilation lifted


_backstop = _Backstop()
