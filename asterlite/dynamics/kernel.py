"""The compiled time loop shared by every scheme: stepping, archiving, status.

A scheme is an njit function with the signature

    step(t, dt, q, v, a, f, mem, smem, vint, vint_save, lin, shk, exc, work)
        -> (status, shock, dt_used, dt_next, n_rejected)

advancing (q, v, a, f, vint) in place from t to t + dt_used. ``mem`` (rows
of length n) and ``smem`` (scalars) are the scheme's persistent memory,
``vint_save`` a scratch copy of the shock states for rejected steps.

The loop follows code_aster's archiving rules (dtmcalc): the step is
shortened to land exactly on each requested instant (and on INST_FIN), the
remainder of the shortened step is taken next, and otherwise every
``pas_arch``-th step is archived. It stops with STATUS_FULL when the
archive buffers are full so that the driver can grow them and resume:
memory follows the archived instants, never the number of steps.
"""

from __future__ import annotations

import numpy as np
from numba import njit

STATUS_DONE = 0
STATUS_NOT_FINITE = 1
STATUS_SHOCK_DIVERGED = 2
STATUS_STEP_UNDERFLOW = 3
STATUS_REJECTED = 4
STATUS_FULL = 10

# clock[]: time, stored step, nominal step, end time, shortened step
C_TIME, C_STEP, C_STEP0, C_END, C_NEWDT = range(5)
N_CLOCK = 5
# counters[]: step index, archived, next instant, forced-archiving state,
#             forced irregular archivings, rejected steps, adaptive flag, failing shock
K_STEP, K_ARCHIVED, K_INSTANT, K_FORCE, K_IRREGULAR, K_REJECTED, K_ADAPTIVE, K_SHOCK = range(8)
N_COUNTERS = 8


@njit(cache=True)
def archive(n, t, step, q, v, a, vint, out_t, out_order, out_q, out_v, out_a, out_vint):
    out_t[n] = t
    out_order[n] = step
    out_q[n] = q
    out_v[n] = v
    out_a[n] = a
    out_vint[n] = vint


# Not cached: numba cannot cache a function taking another compiled function
# as argument (it is recompiled once per process and scheme; everything it
# calls is cached).
@njit
def run_loop(
    step_fn,
    clock,
    counters,
    q,
    v,
    a,
    f,
    mem,
    smem,
    vint,
    vint_save,
    lin,
    shk,
    exc,
    work,
    instants,
    pas_arch,
    eps,
    out_t,
    out_order,
    out_q,
    out_v,
    out_a,
    out_vint,
):
    t = clock[C_TIME]
    t_end = clock[C_END]
    i = counters[K_STEP] + 1  # code_aster's running index (tolerance grows with it)
    adaptive = counters[K_ADAPTIVE] == 1
    while (t_end - t) > i * eps:
        if counters[K_ARCHIVED] >= out_t.shape[0]:
            clock[C_TIME] = t
            return STATUS_FULL
        k = counters[K_INSTANT]
        dt_stored = clock[C_STEP]
        dt = dt_stored
        if k < instants.shape[0]:
            target = instants[k]
            if t + dt - target > i * eps:
                clock[C_NEWDT] = target - t
                dt = clock[C_NEWDT]
                counters[K_FORCE] = 1
            elif abs(t + dt - target) < i * eps:
                clock[C_NEWDT] = dt
                counters[K_FORCE] = 1
        status, shock, dt_used, dt_next, rejected = step_fn(
            t, dt, q, v, a, f, mem, smem, vint, vint_save, lin, shk, exc, work
        )
        counters[K_REJECTED] += rejected
        if status != STATUS_DONE:
            clock[C_TIME] = t
            clock[C_STEP] = dt
            counters[K_SHOCK] = shock
            return status
        t = t + dt_used
        clock[C_STEP] = dt_next if adaptive else dt_stored
        counters[K_STEP] = i
        if counters[K_FORCE] == 2:
            counters[K_FORCE] = 0
            if not adaptive:
                clock[C_STEP] = clock[C_STEP0]
        if counters[K_FORCE] == 1:
            if abs(t - instants[k]) <= i * eps:
                t = instants[k]
                archive(
                    counters[K_ARCHIVED],
                    t,
                    i,
                    q,
                    v,
                    a,
                    vint,
                    out_t,
                    out_order,
                    out_q,
                    out_v,
                    out_a,
                    out_vint,
                )
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
            archive(
                counters[K_ARCHIVED],
                t,
                i,
                q,
                v,
                a,
                vint,
                out_t,
                out_order,
                out_q,
                out_v,
                out_a,
                out_vint,
            )
            counters[K_ARCHIVED] += 1
        i += 1
    clock[C_TIME] = t
    return STATUS_DONE


def new_clock(t0: float, dt: float, t_end: float) -> np.ndarray:
    clock = np.zeros(N_CLOCK)
    clock[C_TIME], clock[C_STEP], clock[C_STEP0], clock[C_END] = t0, dt, dt, t_end
    return clock


def new_counters(adaptive: bool) -> np.ndarray:
    counters = np.zeros(N_COUNTERS, dtype=np.int64)
    counters[K_ADAPTIVE] = 1 if adaptive else 0
    counters[K_SHOCK] = -1
    return counters
