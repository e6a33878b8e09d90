"""ADAPT_ORDRE2 as code_aster 10 to 12 ran it (its routine mdadap, replaced
in code_aster 13 by intadapt2, :mod:`asterlite.dynamics.scheme_adapt_ordre2`).
Decks of those versions select it through
``asterlite.legacy.v15.OLD_BEHAVIOURS["ADAPT_ORDRE2_MDADAP"]``.

The step itself is the same leapfrog: with dt' the previous accepted step
(0 on the first step) and dt the trial step,

    v_mid' = v_mid + a_n (dt' + dt)/2      q_{n+1} = q_n + v_mid' dt
    v_{n+1} = v_mid' + a_n dt/2            a_{n+1} = acceleration(q_{n+1}, v_{n+1})

What differs from code_aster 17 is the control around it:

- err = N f dt (N points per period, f: the apparent frequency of the trial,
  :func:`adapt_control.apparent_frequency`); while err > 1, the step is
  divided by the division factor and retried, at most the largest number
  of trials. When
  the last trial still fails the step is divided once more after it was
  computed: the state is that of the trial, the clock moves by the divided
  step (as code_aster did).
- calm steps (err < 0.75) are counted; the sixth calm step in a row and
  every calm step after it multiplies the next step by the growth factor (at
  most the upper bound); any other step resets the count.
- the step's upper bound defaults to a twentieth of the shortest period, shock stiffness
  included (mdptem; :func:`default_step_max`), even below dt.
- archiving: the archive times are t0 + k dt_max period; a step that
  brackets one archives whichever of its two ends is nearer (the step is
  never shortened to land on it). At the end, the slots left of the
  int((t_end - t0)/spacing) + 1 (+1 if a remainder) planned are filled with
  the final state.

The pieces of a step (:func:`predict`, :func:`judge`, :func:`accept`) also
serve the loop with fluid films (:func:`asterlite.dynamics.fluid_film.run_adapt_loop`),
whose trials compute the end acceleration by iterations.
"""

from __future__ import annotations

import numpy as np

from asterlite.dynamics import adapt_control as A
from asterlite.dynamics import kernel as K
from asterlite.dynamics.forces import all_finite, copy_into, loads_ready, state_acceleration
from asterlite.dynamics.jit import njit
from asterlite.dynamics.layouts import LOADS, ROWS, SCALARS
from asterlite.errors import NumericalError
from asterlite.errors import field as named

Q_TRIAL, V_TRIAL, A_TRIAL, V_MIN, V_MID, V_MID_TRIAL, RESIDUAL = range(7)
VECTOR_ROWS = 7
# scalars after adapt_control's (whose S_KEPT_AT_MAX_TRIALS the driver reads)
S_PREVIOUS_STEP, S_CALM, S_NEXT_ARCHIVE, S_SPACING, S_SLOTS = range(A.N_SCALARS, A.N_SCALARS + 5)
N_SCALARS = A.N_SCALARS + 5
CALM_BEFORE_GROWTH = 5  # mdadap's NPAS: growth once five calm steps have passed
CALM_ERROR = 0.75
MACHINE_EPS = np.finfo(np.float64).eps


def prepare(system, dt, options):
    """The step's upper bound is required here: the command gives code_aster 10-12's default
    when the deck has none (:func:`default_step_max`)."""
    if options.dt_max is None:
        raise NumericalError(
            f"ADAPT_ORDRE2 of code_aster 10-12 without an upper step bound "
            f"({named('options.dt_max')}; the command fills in that version's default, a "
            "twentieth of the shortest period: default_step_max)"
        )
    base, _ = A.control_scalars(dt, options)
    scalars = np.zeros(N_SCALARS)
    scalars[: A.N_SCALARS] = base
    rows = np.zeros((VECTOR_ROWS, system.n_modes))
    rows[V_MIN] = 1.0e-15
    return (rows, scalars, np.zeros((1, 1))), True


def default_step_max(shortest_period: float) -> float:
    """code_aster 10-12's upper bound of the step when the deck gives none (mdptem): a
    twentieth of the shortest period among the modes, each stiffened by every
    shock's normal and tangential stiffness on each shape component
    (:func:`asterlite.dynamics.step_limits.stability_limit`; 1e10 s without any)."""
    return shortest_period / 20.0


@njit(cache=True)
def planned_slots(t0, t_end, spacing):
    """Archive slots code_aster allocated: the instants t0 + k spacing up to
    t_end, plus one when t_end lies beyond the last."""
    slots = int((t_end - t0) / spacing) + 1
    if t_end - (t0 + (slots - 1) * spacing) >= MACHINE_EPS:
        slots += 1
    return slots


@njit(cache=True)
def start(clock, state, rows, scalars, pas_arch):
    scalars[A.S_FIRST_CALL] = 0.0
    copy_into(rows[V_MID], state.v)
    scalars[S_PREVIOUS_STEP] = 0.0
    scalars[S_CALM] = 0.0
    spacing = scalars[A.S_DTMAX] * max(pas_arch, 1)
    scalars[S_SPACING] = spacing
    scalars[S_NEXT_ARCHIVE] = clock[K.C_TIME] + spacing
    scalars[S_SLOTS] = planned_slots(clock[K.C_TIME], clock[K.C_END], spacing)


@njit(cache=True)
def predict(dt, state, rows, scalars):
    """The leapfrog prediction of the step ``dt`` into the trial rows: the
    mid-step velocity, the displacement and the end velocity (without the
    acceleration at the end, which the caller computes)."""
    q, a = state.q, state.a
    q2, v2 = rows[Q_TRIAL], rows[V_TRIAL]
    v_mid, v_mid2 = rows[V_MID], rows[V_MID_TRIAL]
    p = 0.5 * (scalars[S_PREVIOUS_STEP] + dt)
    for i in range(q.shape[0]):
        v_mid2[i] = v_mid[i] + a[i] * p
        q2[i] = q[i] + dt * v_mid2[i]
        v2[i] = v_mid2[i] + 0.5 * dt * a[i]


@njit(cache=True)
def trial(t, dt, state, rows, scalars, model):
    """One trial of the step ``dt`` from ``t`` into the trial rows: the index
    of a shock that diverged (>= 0), -2 for a non-finite acceleration, else -1."""
    f, vint, vint_save, work = state.f, state.vint, state.vint_save, state.work
    predict(dt, state, rows, scalars)
    copy_into(vint, vint_save)
    a2 = rows[A_TRIAL]
    shock = state_acceleration(
        t + dt, rows[Q_TRIAL], rows[V_TRIAL], a2, f, rows[RESIDUAL], vint, work, model
    )
    if shock >= 0:
        return shock
    if not all_finite(a2):
        return -2
    return -1


@njit(cache=True)
def store(clock, counters, archive, t, step, q, v, a, vint, dt):
    out_t, out_order, out_q, out_v, out_a, out_vint, out_info = archive
    n = counters[K.K_ARCHIVED]
    K.archive(
        n, t, step, q, v, a, vint, dt, counters[K.K_REJECTED],
        out_t, out_order, out_q, out_v, out_a, out_vint, out_info,
    )  # fmt: skip
    counters[K.K_ARCHIVED] = n + 1


@njit(cache=True)
def archive_nearest(clock, counters, state, rows, scalars, archive, t_new, dt_next):
    """mdadap's archiving: the step [t, t_new] bracketing the next archive
    time stores its nearer end (the start: the state before the step)."""
    t = clock[K.C_TIME]
    target = scalars[S_NEXT_ARCHIVE]
    if not (t <= target and t_new >= target):
        return
    step = counters[K.K_STEP]
    if t_new - target <= target - t:
        store(clock, counters, archive, t_new, step, rows[Q_TRIAL], rows[V_TRIAL],
              rows[A_TRIAL], state.vint, dt_next)  # fmt: skip
    else:
        store(clock, counters, archive, t, step - 1, state.q, state.v, state.a,
              state.vint_save, dt_next)  # fmt: skip
    scalars[S_NEXT_ARCHIVE] = target + scalars[S_SPACING]


@njit(cache=True)
def update_reference_velocities(rows, scalars):
    """The reference velocities from the mid-step velocity of the accepted step."""
    A.update_reference_velocities(rows[V_MID_TRIAL], rows[V_MIN], scalars)


@njit(cache=True)
def first_trial_step(clock):
    """The step a new step starts its trials with (clipped at the end)."""
    dt = clock[K.C_STEP]
    if clock[K.C_TIME] + dt > clock[K.C_END]:
        dt = clock[K.C_END] - clock[K.C_TIME]
    return dt


@njit(cache=True)
def judge(clock, tried, state, rows, scalars):
    """(error, step, underflow): the error of the trial of step ``tried``
    just computed, the step of the next trial (divided by the division factor when
    the error exceeds 1), and whether that step fell to the lower bound before the end."""
    t, t_end = clock[K.C_TIME], clock[K.C_END]
    freq = A.apparent_frequency(tried, state.q, rows[Q_TRIAL], state.a, rows[A_TRIAL],
                                rows[V_MIN])  # fmt: skip
    err = scalars[A.S_POINTS] * freq * tried
    dt = tried
    if err > 1.0:
        dt = dt / scalars[A.S_DIVI]
    underflow = dt <= scalars[A.S_DTMIN] and abs(t_end - (t + dt)) > MACHINE_EPS
    return err, dt, underflow


@njit(cache=True)
def accept(clock, counters, state, rows, scalars, archive, dt, err, trials):
    """Close a step whose last trial (of step ``dt``: the trial's step, or
    that step divided once more when every trial failed) is kept: the next
    step, the archive, the reference velocities, the state."""
    t, t_end = clock[K.C_TIME], clock[K.C_END]
    if err > 1.0:
        scalars[A.S_KEPT_AT_MAX_TRIALS] += 1.0
    counters[K.K_REJECTED] += trials - 1
    scalars[S_PREVIOUS_STEP] = dt
    t_new = t + dt
    dt_used = dt
    if err < CALM_ERROR:
        if scalars[S_CALM] == CALM_BEFORE_GROWTH:
            dt = min(scalars[A.S_MULT] * dt, scalars[A.S_DTMAX])
            scalars[S_CALM] = CALM_BEFORE_GROWTH - 1
        scalars[S_CALM] += 1.0
    else:
        scalars[S_CALM] = 0.0
    if t + dt > t_end:  # mdadap clips against the step's start here
        dt = t_end - t
    counters[K.K_STEP] += 1
    archive_nearest(clock, counters, state, rows, scalars, archive, t_new, dt)
    update_reference_velocities(rows, scalars)
    clock[K.C_TIME] = t_new
    clock[K.C_STEP] = dt
    clock[K.C_MIN_STEP] = min(clock[K.C_MIN_STEP], dt_used)
    clock[K.C_MAX_STEP] = max(clock[K.C_MAX_STEP], dt_used)
    copy_into(state.q, rows[Q_TRIAL])
    copy_into(state.v, rows[V_TRIAL])
    copy_into(state.a, rows[A_TRIAL])
    copy_into(rows[V_MID], rows[V_MID_TRIAL])


@njit(cache=True)
def take_step(clock, counters, state, rows, scalars, model, archive):
    """One accepted step (trials included); a kernel status."""
    t = clock[K.C_TIME]
    dt = first_trial_step(clock)
    max_trials = int(round(scalars[A.S_MAX_TRIALS]))
    err = 100.0
    trials = 0
    copy_into(state.vint_save, state.vint)  # the shock states of the step's start
    while err > 1.0 and trials < max_trials:
        tried = dt
        failed = trial(t, tried, state, rows, scalars, model)
        if failed >= 0:
            return K.record_failure(clock, counters, K.STATUS_SHOCK_DIVERGED, failed, tried)
        if failed == -2:
            K.expose_trial(state.q, state.v, state.a, rows[Q_TRIAL], rows[V_TRIAL],
                           rows[A_TRIAL])  # fmt: skip
            return K.record_failure(clock, counters, K.STATUS_NOT_FINITE, -1, tried)
        err, dt, underflow = judge(clock, tried, state, rows, scalars)
        if underflow:
            return K.record_failure(clock, counters, K.STATUS_STEP_UNDERFLOW, -1, dt)
        trials += 1
    accept(clock, counters, state, rows, scalars, archive, dt, err, trials)
    return K.STATUS_DONE


@njit(cache=True)
def fill_slots(clock, counters, state, scalars, archive):
    """At the end, the archive slots code_aster allocated and left unused hold
    the final state; STATUS_FULL when the buffers must grow first."""
    while scalars[S_SLOTS] > counters[K.K_ARCHIVED]:
        if counters[K.K_ARCHIVED] >= archive.times.shape[0]:
            return K.STATUS_FULL
        store(clock, counters, archive, clock[K.C_TIME], counters[K.K_STEP], state.q,
              state.v, state.a, state.vint, clock[K.C_STEP])  # fmt: skip
    return K.STATUS_DONE


@njit(cache=True)
def run_loop(clock, counters, state, memory, model, instants, pas_arch, eps, archive, energy):
    """The whole time loop (the archiving instants are not read: code_aster
    10-12's ADAPT archived on its own grid); resumable after any pause."""
    rows, scalars = memory[ROWS], memory[SCALARS]
    out_t = archive.times
    if scalars[A.S_FIRST_CALL] == 1.0:
        start(clock, state, rows, scalars, pas_arch)
    while clock[K.C_TIME] < clock[K.C_END]:
        paused = K.pause_status(counters, out_t)
        if paused:
            return paused
        if not loads_ready(clock, model[LOADS]):
            return K.STATUS_LOADS
        status = take_step(clock, counters, state, rows, scalars, model, archive)
        if status != K.STATUS_DONE:
            return status
    return fill_slots(clock, counters, state, scalars, archive)
