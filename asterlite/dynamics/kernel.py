"""Pieces of the compiled time loop shared by every scheme: step planning,
archiving, status codes.

The time loop (:mod:`asterlite.dynamics.loop`, written once and compiled
around each scheme's ``step``, so that everything is cached across
processes) is built from the helpers here::

    while unfinished(clock, counters, eps):
        paused = pause_status(counters, archive.times)
        if paused: return paused            # STATUS_FULL or STATUS_PAUSE
        if not loads_ready(clock, exc): return STATUS_LOADS
        t, dt = plan_step(clock, counters, instants, eps)
        status, shock, dt_used, dt_next, rejected = step(t, dt, index, state, memory, model)
        if status != STATUS_DONE: return record_failure(...)
        complete_step(...)

A step function has the signature

    step(t, dt, index, state, memory, model)
        -> (status, shock, dt_used, dt_next, n_rejected)

with ``index`` the number of steps already taken, ``state`` a
``layouts.State`` (q, v, a, f, vint, vint_save, work) advanced in place
from t to t + dt_used, ``memory = (rows, scalars, table)`` the scheme's own
persistent arrays (rows of length n, scalars, and a coefficient table such
as a Butcher tableau; ``layouts.ROWS``...) and ``model = (linear, shocks,
loads)`` the bundles of ``model.py`` (``layouts.LINEAR``...; each a named
tuple of :mod:`asterlite.dynamics.layouts`).

The loop follows code_aster's archiving rules (dtmcalc): the step is
shortened to land exactly on each requested instant (and on the final instant), the
remainder of the shortened step is taken next, and otherwise every
``pas_arch``-th step is archived. A fixed-step loop stands on the grid
t0 + n dt (code_aster's list of instants, mdptem): the instant of a step
that completes grid interval n is computed from n, never summed step after
step, so that 2e8 steps of 1e-5 s end at 2000 s exactly (a running sum
drifts by 4e-6 s there and takes one more, tiny, step). Adaptive loops
accumulate their steps. It stops with STATUS_FULL when the archive
buffers are full so that the driver can grow them and resume: memory
follows the archived instants, never the number of steps. Likewise it
stops with STATUS_LOADS when a multiplier sampled by windows (a formula)
needs its next window, and with STATUS_PAUSE when it has taken the steps
the driver granted (``counters[K_PAUSE_AT]``): the driver reports progress,
checks the step budget and resumes, so that a long run stays responsive
without any Python inside the loop.

Besides the state, each archived instant records the step that led to it
and the number of steps rejected so far (``out_info``; code_aster keeps the
step of each archived instant too), the step-size history of adaptive runs.
"""

from __future__ import annotations

import math

import numpy as np

from asterlite.dynamics.jit import njit

STATUS_DONE = 0
STATUS_NOT_FINITE = 1
STATUS_SHOCK_DIVERGED = 2
STATUS_STEP_UNDERFLOW = 3
STATUS_REJECTED = 4
STATUS_SWITCH_NOT_LOCATED = 5  # implicit shocks: a contact switch not located in 100 tries
STATUS_FULL = 10
STATUS_LOADS = 11  # a windowed multiplier needs its next window (excitation.Excitation.refill)
STATUS_PAUSE = 12  # the granted steps are taken: the driver reports progress and resumes

# clock[]: time, stored step, nominal step, end time, shortened step,
#          smallest and largest step taken, origin of the fixed-step grid
C_TIME, C_STEP, C_STEP0, C_END, C_NEWDT, C_MIN_STEP, C_MAX_STEP, C_ORIGIN = range(8)
N_CLOCK = 8
# counters[]: step index, archived, next instant, forced-archiving state,
#             forced irregular archivings, rejected steps, adaptive flag, failing shock,
#             step index at which to pause, grid intervals completed since C_ORIGIN
(
    K_STEP,
    K_ARCHIVED,
    K_INSTANT,
    K_FORCE,
    K_IRREGULAR,
    K_REJECTED,
    K_ADAPTIVE,
    K_SHOCK,
    K_PAUSE_AT,
    K_GRID,
) = range(10)
N_COUNTERS = 10
# a fixed step ending this close (relative to dt) to the next grid instant
# completes the grid interval: far above the round-off of a sum of two
# instants, far below any step cut short (implicit shocks cut at >= 1 %)
GRID_TOLERANCE = 1.0e-6
# out_info[] columns of an archived instant: the step that led to it, the
# steps rejected since the start
INFO_STEP, INFO_REJECTED = range(2)
N_INFO = 2


@njit(cache=True, inline="always")
def archive(
    n,
    t,
    step,
    q,
    v,
    a,
    vint,
    dt,
    rejected,
    out_t,
    out_order,
    out_q,
    out_v,
    out_a,
    out_vint,
    out_info,
):
    out_t[n] = t
    out_order[n] = step
    out_info[n, INFO_STEP] = dt
    out_info[n, INFO_REJECTED] = rejected
    for i in range(q.shape[0]):
        out_q[n, i] = q[i]
        out_v[n, i] = v[i]
        out_a[n, i] = a[i]
    for s in range(vint.shape[0]):
        for j in range(vint.shape[1]):
            out_vint[n, s, j] = vint[s, j]


@njit(cache=True, inline="always")
def unfinished(clock, counters, eps):
    """code_aster's loop test: the remaining time exceeds i * eps (the
    tolerance grows with the running step index i)."""
    i = counters[K_STEP] + 1
    return (clock[C_END] - clock[C_TIME]) > i * eps


@njit(cache=True, inline="always")
def pause_status(counters, out_t):
    """STATUS_FULL when the archive buffers are full, STATUS_PAUSE when the
    granted steps are taken, else 0 (go on)."""
    if counters[K_ARCHIVED] >= out_t.shape[0]:
        return STATUS_FULL
    if counters[K_STEP] >= counters[K_PAUSE_AT]:
        return STATUS_PAUSE
    return 0


@njit(cache=True, inline="always")
def plan_step(clock, counters, instants, eps):
    """(t, dt) of the next step: the stored step, shortened to land on the
    next requested instant."""
    i = counters[K_STEP] + 1
    t = clock[C_TIME]
    dt = clock[C_STEP]
    k = counters[K_INSTANT]
    if k < instants.shape[0]:
        target = instants[k]
        if t + dt - target > i * eps:
            clock[C_NEWDT] = target - t
            dt = clock[C_NEWDT]
            counters[K_FORCE] = 1
        elif abs(t + dt - target) < i * eps:
            clock[C_NEWDT] = dt
            counters[K_FORCE] = 1
    return t, dt


@njit(cache=True, inline="always")
def expose_trial(q, v, a, q_trial, v_trial, a_trial):
    """A scheme whose trial step became non-finite copies the trial into the
    state before it returns STATUS_NOT_FINITE: the run stops there, and the
    driver reads the state to say which quantity went wrong."""
    for i in range(q.shape[0]):
        q[i] = q_trial[i]
        v[i] = v_trial[i]
        a[i] = a_trial[i]


@njit(cache=True, inline="always")
def record_failure(clock, counters, status, shock, dt):
    """Stop on a failed step: ``dt`` the step last tried (the driver reports
    the failure at clock time + dt), ``shock`` the one at fault or -1."""
    clock[C_STEP] = dt
    counters[K_SHOCK] = shock
    return status


@njit(cache=True, inline="always")
def complete_step(clock, counters, state, instants, pas_arch, eps, archive_buffers, step_result):
    """Advance the clock after an accepted step, choose the next step and
    archive when due (dtmcalc's rules)."""
    dt_used, dt_next, rejected = step_result
    out_t, out_order, out_q, out_v, out_a, out_vint, out_info = archive_buffers
    advance_clock(
        clock,
        counters,
        state.q,
        state.v,
        state.a,
        state.vint,
        instants,
        pas_arch,
        eps,
        out_t,
        out_order,
        out_q,
        out_v,
        out_a,
        out_vint,
        out_info,
        dt_used,
        dt_next,
        rejected,
    )


@njit(cache=True, inline="always")
def advance_clock(
    clock,
    counters,
    q,
    v,
    a,
    vint,
    instants,
    pas_arch,
    eps,
    out_t,
    out_order,
    out_q,
    out_v,
    out_a,
    out_vint,
    out_info,
    dt_used,
    dt_next,
    rejected,
):
    """:func:`complete_step` on plain arrays (the specialised loops)."""
    i = counters[K_STEP] + 1
    adaptive = counters[K_ADAPTIVE] == 1
    dt_stored = clock[C_STEP]
    counters[K_REJECTED] += rejected
    if dt_used < clock[C_MIN_STEP]:
        clock[C_MIN_STEP] = dt_used
    if dt_used > clock[C_MAX_STEP]:
        clock[C_MAX_STEP] = dt_used
    t = clock[C_TIME] + dt_used
    clock[C_STEP] = dt_next if adaptive else dt_stored
    counters[K_STEP] = i
    k = counters[K_INSTANT]
    if counters[K_FORCE] == 2:
        counters[K_FORCE] = 0
        if not adaptive:
            clock[C_STEP] = clock[C_STEP0]
    landing = counters[K_FORCE] == 1 and abs(t - instants[k]) <= i * eps
    if not adaptive:
        if landing:  # a step not cut short to land there completes its interval
            if abs(dt_stored - clock[C_NEWDT]) <= i * eps:
                counters[K_GRID] += 1
        else:
            t = grid_instant(clock, counters, t)
    if counters[K_FORCE] == 1:
        if landing:
            t = instants[k]
            n = counters[K_ARCHIVED]
            archive(
                n, t, i, q, v, a, vint, dt_used, counters[K_REJECTED],
                out_t, out_order, out_q, out_v, out_a, out_vint, out_info,
            )  # fmt: skip
            counters[K_ARCHIVED] += 1
            counters[K_INSTANT] = k + 1
            counters[K_FORCE] = 0
            if abs(dt_stored - clock[C_NEWDT]) > i * eps:
                counters[K_IRREGULAR] += 1
                clock[C_STEP] = dt_stored - clock[C_NEWDT]
                counters[K_FORCE] = 2
            elif not adaptive:
                clock[C_STEP] = clock[C_STEP0]
    elif (i - counters[K_IRREGULAR]) % pas_arch == 0:
        n = counters[K_ARCHIVED]
        archive(
            n, t, i, q, v, a, vint, dt_used, counters[K_REJECTED],
            out_t, out_order, out_q, out_v, out_a, out_vint, out_info,
        )  # fmt: skip
        counters[K_ARCHIVED] += 1
    clock[C_TIME] = t


@njit(cache=True, inline="always")
def grid_instant(clock, counters, t):
    """The end ``t`` of a fixed step, replaced by t0 + n dt when the step
    completes grid interval n; a step ending elsewhere (cut short at a
    contact switch: code_aster's grid shifts there) starts a new grid."""
    n = counters[K_GRID] + 1
    node = clock[C_ORIGIN] + n * clock[C_STEP0]
    if abs(t - node) <= GRID_TOLERANCE * clock[C_STEP0]:
        counters[K_GRID] = n
        return node
    clock[C_ORIGIN] = t
    counters[K_GRID] = 0
    return t


def grid_step_count(t0: float, t_end: float, dt: float) -> int:
    """Number of fixed steps from t0 to t_end: (t_end - t0)/dt rounded when
    within round-off of an integer (code_aster's NINT), else the next
    integer (the last step is then shortened to land on t_end)."""
    ratio = (t_end - t0) / dt
    nearest = round(ratio)
    if abs(ratio - nearest) <= 1.0e-9 * max(1.0, abs(ratio)):
        return max(1, int(nearest))
    return max(1, math.ceil(ratio))


def new_clock(t0: float, dt: float, t_end: float) -> np.ndarray:
    clock = np.zeros(N_CLOCK)
    clock[C_TIME], clock[C_STEP], clock[C_STEP0], clock[C_END] = t0, dt, dt, t_end
    clock[C_ORIGIN] = t0
    clock[C_MIN_STEP], clock[C_MAX_STEP] = np.inf, 0.0
    return clock


def new_counters(adaptive: bool) -> np.ndarray:
    counters = np.zeros(N_COUNTERS, dtype=np.int64)
    counters[K_ADAPTIVE] = 1 if adaptive else 0
    counters[K_SHOCK] = -1
    counters[K_PAUSE_AT] = np.iinfo(np.int64).max
    return counters
