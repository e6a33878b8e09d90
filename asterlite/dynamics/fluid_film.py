"""Fluid-film shocks (the film option of the shocks of code_aster 10-12) and the
two loops that integrate them: code_aster 11's EULER, and its ADAPT_ORDRE2.

The model (code_aster 11: mdeul1, mdfcho, mdfflu, mdmasf, ponder):

- While the gap d (the DIS_CHOC normal distance, > 0 apart) is open, a
  fluid film pushes node 1 along the obstacle normal with
  F = α a_n / d + β (v_n / d)^2 + χ v_n / d^3 + δ v_n |v_n| / d^2,
  v_n, a_n the relative normal velocity and acceleration (node 1 - node 2;
  v_n < 0 closing). α < 0 is an added mass, χ < 0 a viscous
  squeeze film, β and δ pressure losses.
- A boundary layer of thickness e = F / k_n (k_n the normal stiffness) blends the film into the
  dry shock: it is entered when d <= e (e is then frozen) and left when
  d >= e. Inside, the film force is weighted by p(d) (0 below e/2, 1 above
  e, linear between) and the dry force -k_n (d - e) - c_n v_n
  (positive part) by 1 - p(d).
- The film force depends on the acceleration, so each step solves for it by
  fixed-point iterations: the film's added mass is moved to the left-hand
  side with a diagonal stand-in, M'_ii = M_ii - λ p α / d Σ_k φ_ki²
  (φ: the relative mode shape of the shock's nodes, three components), and
  the same term times the previous iterate is added to the force, so that it
  cancels at convergence (the relaxation λ only makes the iterations contract). The
  iterations stop when |a_new - a_old|² <= tol |a_new|² (squared norms,
  as code_aster tests them) and fail after the largest number of iterations.

The scheme is code_aster 11's EULER (v += dt a, q += dt v, then a at the new
state: asterlite's DIFF_CENTRE arithmetic) on diagonal generalized matrices;
the initial acceleration is one evaluation with a zero acceleration in the
film law, as code_aster 11 starts. Shocks without a film in the same run
follow the DIS_CHOC law (:func:`contact.contact_law`), evaluated once per
step (their force does not depend on the acceleration).

Under code_aster 10-12's ADAPT_ORDRE2 (mdadap, :func:`run_adapt_loop`) the
step control, the leapfrog prediction and the archive grid are those of
:mod:`scheme_adapt_ordre2_v11`; each trial step computes its end acceleration
by the same fixed-point iterations, started from the acceleration of the
step's start, and the apparent frequency judges the converged one. As in
mdadap, a trial whose iterations do not converge stops the run (no smaller
step is tried), and the boundary-layer state a rejected trial changed is kept.
The iterations stop on a relative change, not on the fixed point: with
a loose tolerance, the diagonal added-mass stand-in leaves a lag that depends
on the modal basis (poor when a shock's relative motion spreads over several modes).
"""

from __future__ import annotations

import math
import time as wallclock
from dataclasses import dataclass, replace

import numpy as np

from asterlite import progress, watchdog
from asterlite.dynamics import adapt_control as A
from asterlite.dynamics import kernel as K
from asterlite.dynamics import native
from asterlite.dynamics import scheme_adapt_ordre2_v11 as V11
from asterlite.dynamics.contact import (
    F_GEOMETRY,
    F_NPOLAR,
    F_TWO_NODES,
    F_UNIDIR,
    P_CN,
    P_DIST1,
    P_DIST2,
    P_GAP,
    P_KN,
    P_SIGN_Y,
    P_SIGN_Z,
    V_FN,
    V_LOC1,
    V_LOC2,
    V_VN,
    contact_law,
    obstacle_gap,
)
from asterlite.dynamics.forces import add_external_force, copy_into, loads_ready
from asterlite.dynamics.integrate import (
    RunResult,
    SchemeOptions,
    StepBudget,
    archive_start,
    divergence_error,
    grow,
    new_buffers,
    run_info,
)
from asterlite.dynamics.jit import njit
from asterlite.dynamics.layouts import ROWS, SCALARS, State
from asterlite.errors import NumericalError
from asterlite.errors import field as named

# columns of the per-shock film rows: film present, the law's coefficients,
# in the boundary layer (0/1), the frozen thickness of that layer
FL_ON, FL_ALPHA, FL_BETA, FL_CHI, FL_DELTA, FL_LAYER, FL_THICKNESS = range(7)
N_FILM = 7

# the names of the two loops (asterlite.dynamics.warmup's kernels; RunResult.info["loop"])
FILM_LOOP = "fluid film"
FILM_ADAPT_LOOP = "fluid film, ADAPT_ORDRE2 (code_aster 10-12)"
# status of a step whose fixed-point iterations did not converge
STATUS_FILM_NOT_CONVERGED = 20
# scalars[]: last residual ratio, iterations of the worst step, total iterations
S_RATIO, S_WORST, S_TOTAL = range(3)
# kin[]: local y, z of node 1 and node 2, then relative position, velocity,
# acceleration (node 1 - node 2, local frame)
KIN_Y1, KIN_Z1, KIN_Y2, KIN_Z2, KIN_X, KIN_V, KIN_A = 0, 1, 2, 3, 4, 7, 10
N_KIN = 13


@dataclass
class FluidFilm:
    """The film parameters of a run: one row per shock (``FL_*`` columns;
    FL_ON = 0 for a shock without film) and the iteration controls, as the
    command read them (the catalogue gives their defaults)."""

    rows: np.ndarray
    max_iterations: int
    tolerance: float
    relaxation: float

    @property
    def active(self) -> bool:
        return bool(self.rows.shape[0]) and bool(np.any(self.rows[:, FL_ON] != 0.0))


def film_row(alpha: float, beta: float, chi: float, delta: float) -> np.ndarray:
    row = np.zeros(N_FILM)
    row[FL_ON] = 1.0
    row[FL_ALPHA], row[FL_BETA], row[FL_CHI], row[FL_DELTA] = alpha, beta, chi, delta
    return row


def mass_weights(shapes: np.ndarray, flags: np.ndarray, film: FluidFilm) -> np.ndarray:
    """λ Σ_k φ_ki² per film shock and mode (φ: node 1's shape, minus node
    2's for a two-node obstacle; the sum over the three components is the
    same in any frame). Zero rows for shocks without film."""
    n_shocks, n_modes = shapes.shape[0], shapes.shape[3]
    weights = np.zeros((n_shocks, n_modes))
    for s in range(n_shocks):
        if film.rows[s, FL_ON] == 0.0:
            continue
        phi = shapes[s, 0].copy()
        if flags[s, F_TWO_NODES] == 1:
            phi -= shapes[s, 1]
        weights[s] = film.relaxation * np.sum(phi * phi, axis=0)
    return weights


@njit(cache=True, inline="always")
def blend(gap, thickness):
    """Weight of the film force in the boundary layer: 1 at d >= e, 0 at
    d <= e/2, linear between (code_aster's ponder)."""
    if gap >= thickness:
        return 1.0
    if gap <= 0.5 * thickness:
        return 0.0
    return (gap - 0.5 * thickness) / (0.5 * thickness)


@njit(cache=True)
def kinematics(s, q, v, a, flags, shapes, rest, kin):
    """Local (y, z) of both nodes and the relative position, velocity and
    acceleration of shock ``s`` in its local frame, into ``kin``."""
    two_nodes = flags[s, F_TWO_NODES] == 1
    for node in range(2 if two_nodes else 1):
        sign = 1.0 if node == 0 else -1.0
        for i in range(3):
            x = rest[s, node, i]
            u = 0.0
            w = 0.0
            for m in range(q.shape[0]):
                x += shapes[s, node, i, m] * q[m]
                u += shapes[s, node, i, m] * v[m]
                w += shapes[s, node, i, m] * a[m]
            if node == 0:
                kin[KIN_X + i] = x
                kin[KIN_V + i] = u
                kin[KIN_A + i] = w
            else:
                kin[KIN_X + i] += sign * x
                kin[KIN_V + i] += sign * u
                kin[KIN_A + i] += sign * w
            if i > 0:
                kin[2 * node + i - 1] = x
    if not two_nodes:
        kin[KIN_Y2] = 0.0
        kin[KIN_Z2] = 0.0


@njit(cache=True, inline="always")
def shock_gap(s, flags, params, polars, kin):
    return obstacle_gap(
        flags[s, F_GEOMETRY],
        kin[KIN_Y1],
        kin[KIN_Z1],
        kin[KIN_Y2],
        kin[KIN_Z2],
        params[s, P_GAP],
        params[s, P_DIST1],
        params[s, P_DIST2],
        params[s, P_SIGN_Y],
        params[s, P_SIGN_Z],
        polars,
        s,
        flags[s, F_NPOLAR],
    )


@njit(cache=True, inline="always")
def add_local_force(s, flags, shapes, fx, fy, fz, out):
    """out += Φᵀ f at node 1 and -Φᵀ f at node 2 (local-frame shapes)."""
    for m in range(out.shape[0]):
        out[m] += shapes[s, 0, 0, m] * fx + shapes[s, 0, 1, m] * fy + shapes[s, 0, 2, m] * fz
    if flags[s, F_TWO_NODES] == 1:
        for m in range(out.shape[0]):
            out[m] -= shapes[s, 1, 0, m] * fx + shapes[s, 1, 1, m] * fy + shapes[s, 1, 2, m] * fz


@njit(cache=True)
def store_positions(s, q, flags, shapes, rest, vint):
    for node in range(2):
        for i in range(3):
            x = 0.0
            if node == 0 or flags[s, F_TWO_NODES] == 1:
                x = rest[s, node, i]
                for m in range(q.shape[0]):
                    x += shapes[s, node, i, m] * q[m]
            vint[s, (V_LOC1 if node == 0 else V_LOC2) + i] = x


@njit(cache=True)
def dry_shock_forces(q, v, a, flags, params, shapes, rest, polars, film, vint, kin, out):
    """The DIS_CHOC force of every shock without film, added to ``out``;
    returns the index of a shock whose velocity diverged, or -1."""
    for s in range(flags.shape[0]):
        if film[s, FL_ON] != 0.0:
            continue
        kinematics(s, q, v, a, flags, shapes, rest, kin)
        store_positions(s, q, flags, shapes, rest, vint)
        gap, cos_n, sin_n = shock_gap(s, flags, params, polars, kin)
        diverged, in_contact, fx, fy, fz = contact_law(
            params, flags[s, F_UNIDIR] == 1, vint, s, gap, cos_n, sin_n,
            kin[KIN_X], kin[KIN_X + 1], kin[KIN_X + 2],
            kin[KIN_V], kin[KIN_V + 1], kin[KIN_V + 2],
        )  # fmt: skip
        if diverged:
            return s
        if in_contact:
            add_local_force(s, flags, shapes, fx, fy, fz, out)
    return -1


@njit(cache=True)
def film_forces(q, v, a, flags, params, shapes, rest, polars, film, weights, vint, kin, f, mass):
    """Every film shock's force at the acceleration iterate ``a``, added to
    ``f``, and its added-mass stand-in, added to ``mass`` (M') and, times
    ``a``, to ``f``; updates the boundary-layer state in ``film``."""
    for s in range(flags.shape[0]):
        if film[s, FL_ON] == 0.0:
            continue
        kinematics(s, q, v, a, flags, shapes, rest, kin)
        store_positions(s, q, flags, shapes, rest, vint)
        gap, cos_n, sin_n = shock_gap(s, flags, params, polars, kin)
        vn = kin[KIN_V + 1] * cos_n + kin[KIN_V + 2] * sin_n
        an = kin[KIN_A + 1] * cos_n + kin[KIN_A + 2] * sin_n
        thickness = film[s, FL_THICKNESS]
        f_film = 0.0
        if gap > 0.0:
            f_film = (
                film[s, FL_ALPHA] * an / gap
                + film[s, FL_BETA] * (vn / gap) ** 2
                + film[s, FL_CHI] * vn / gap**3
                + film[s, FL_DELTA] * vn * abs(vn) / (gap * gap)
            )
            if film[s, FL_LAYER] == 1.0:
                if gap >= thickness:  # out of the boundary layer
                    film[s, FL_LAYER] = 0.0
                    film[s, FL_THICKNESS] = 0.0
                    thickness = 0.0
            else:
                thickness = f_film / params[s, P_KN]
                if gap <= thickness:  # into the boundary layer: its thickness is kept
                    film[s, FL_LAYER] = 1.0
                    film[s, FL_THICKNESS] = thickness
            weight = blend(gap, thickness)
            f_film *= weight
            add_local_force(s, flags, shapes, 0.0, f_film * cos_n, f_film * sin_n, f)
            added = -film[s, FL_ALPHA] * weight / gap
            for m in range(f.shape[0]):
                mass[m] += added * weights[s, m]
                f[m] += added * weights[s, m] * a[m]
        f_dry = 0.0
        if gap <= thickness:
            f_dry = -params[s, P_KN] * (gap - thickness) - params[s, P_CN] * vn
            f_dry = max(f_dry, 0.0) * (1.0 - blend(gap, thickness))
            add_local_force(s, flags, shapes, 0.0, f_dry * cos_n, f_dry * sin_n, f)
        vint[s, V_FN] = f_film + f_dry
        vint[s, V_VN] = vn


@njit(cache=True)
def film_acceleration(q, v, a, base, mass, stiffness, damping, model, vint, kin, f, mass_mod):
    """One evaluation: a <- (f - K q - C v) / M' with the film at the
    iterate ``a``; returns (|a_new - a|², |a_new|², finite)."""
    flags, params, shapes, rest, polars, film, weights = model
    for m in range(q.shape[0]):
        f[m] = base[m]
        mass_mod[m] = mass[m]
    film_forces(q, v, a, flags, params, shapes, rest, polars, film, weights, vint, kin, f, mass_mod)
    change, size, finite = 0.0, 0.0, True
    for m in range(q.shape[0]):
        new = (f[m] - stiffness[m] * q[m] - damping[m] * v[m]) / mass_mod[m]
        if not (abs(new) < 1.0e300):
            finite = False
        change += (new - a[m]) ** 2
        size += new * new
        a[m] = new
    return change, size, finite


@njit(cache=True)
def external_force(t, exc, out):
    for m in range(out.shape[0]):
        out[m] = 0.0
    add_external_force(
        t, exc.vectors, exc.abscissas, exc.ordinates, exc.layout, exc.cursors, exc.codes,
        exc.constants, exc.stack, out,
    )  # fmt: skip


@njit(cache=True)
def start(t0, q, v, a, linear, model, exc, vint, work):
    """The initial acceleration: one evaluation with a zero acceleration in
    the film law (code_aster 11 starts so). Returns a failing shock or -1,
    and whether the acceleration is finite."""
    mass, stiffness, damping = linear
    flags, params, shapes, rest, polars, film = model[:6]
    base, f, mass_mod, kin = work[0], work[1], work[2], work[3]
    external_force(t0, exc, base)
    for m in range(a.shape[0]):
        a[m] = 0.0
    shock = dry_shock_forces(q, v, a, flags, params, shapes, rest, polars, film, vint, kin, base)
    _, _, finite = film_acceleration(
        q, v, a, base, mass, stiffness, damping, model, vint, kin, f, mass_mod
    )
    return shock, finite


@njit(cache=True)
def run_loop(clock, counters, q, v, a, vint, linear, model, exc, controls, scalars, work, archive,
             instants, pas_arch, eps):  # fmt: skip
    """The EULER loop with fluid films (module docstring); the kernel's
    status codes and archiving rules, plus STATUS_FILM_NOT_CONVERGED."""
    mass, stiffness, damping = linear
    flags, params, shapes, rest, polars, film = model[:6]
    base, f, mass_mod, kin = work[0], work[1], work[2], work[3]
    out_t, out_order, out_q, out_v, out_a, out_vint, out_info = archive
    max_iterations, tolerance = int(controls[0]), controls[1]
    n = q.shape[0]
    while K.unfinished(clock, counters, eps):
        paused = K.pause_status(counters, out_t)
        if paused:
            return paused
        if not loads_ready(clock, exc):
            return K.STATUS_LOADS
        t, dt = K.plan_step(clock, counters, instants, eps)
        for i in range(n):
            v[i] += dt * a[i]
            q[i] += dt * v[i]
        external_force(t + dt, exc, base)
        shock = dry_shock_forces(
            q, v, a, flags, params, shapes, rest, polars, film, vint, kin, base
        )  # fmt: skip
        if shock >= 0:
            return K.record_failure(clock, counters, K.STATUS_SHOCK_DIVERGED, shock, dt)
        converged = False
        for iteration in range(1, max_iterations + 1):
            change, size, finite = film_acceleration(
                q, v, a, base, mass, stiffness, damping, model, vint, kin, f, mass_mod
            )
            if not finite:
                return K.record_failure(clock, counters, K.STATUS_NOT_FINITE, -1, dt)
            scalars[S_TOTAL] += 1.0
            scalars[S_RATIO] = change / size if size > 0.0 else 0.0
            if change <= tolerance * size:
                converged = True
                scalars[S_WORST] = max(scalars[S_WORST], float(iteration))
                break
        if not converged:
            return K.record_failure(clock, counters, STATUS_FILM_NOT_CONVERGED, -1, dt)
        K.advance_clock(
            clock, counters, q, v, a, vint, instants, pas_arch, eps,
            out_t, out_order, out_q, out_v, out_a, out_vint, out_info, dt, dt, 0,
        )  # fmt: skip
    return K.STATUS_DONE


# ------------------------------------------- code_aster 10-12's ADAPT_ORDRE2


@njit(cache=True)
def film_trial(t, dt, state, rows, scalars, linear, model, exc, controls, counts, work):
    """One trial of mdadap's step ``dt`` with fluid films: the leapfrog
    prediction, then the acceleration at its end by the fixed-point
    iterations, started from the acceleration of the step's start (as
    mdadap starts each trial). -1 when converged, a shock index (>= 0) whose
    velocity diverged, -2 for a non-finite acceleration, -3 when the largest number of iterations
    iterations did not converge."""
    mass, stiffness, damping = linear
    flags, params, shapes, rest, polars, film = model[:6]
    base, f, mass_mod, kin = work[0], work[1], work[2], work[3]
    vint, vint_save = state.vint, state.vint_save
    q2, v2, a2 = rows[V11.Q_TRIAL], rows[V11.V_TRIAL], rows[V11.A_TRIAL]
    V11.predict(dt, state, rows, scalars)
    copy_into(vint, vint_save)  # the dry shocks' states of the step's start
    copy_into(a2, state.a)
    external_force(t + dt, exc, base)
    shock = dry_shock_forces(q2, v2, a2, flags, params, shapes, rest, polars, film, vint, kin, base)
    if shock >= 0:
        return shock
    for iteration in range(1, int(controls[0]) + 1):
        change, size, finite = film_acceleration(
            q2, v2, a2, base, mass, stiffness, damping, model, vint, kin, f, mass_mod
        )
        if not finite:
            return -2
        counts[S_TOTAL] += 1.0
        counts[S_RATIO] = change / size if size > 0.0 else 0.0
        if change <= controls[1] * size:
            counts[S_WORST] = max(counts[S_WORST], float(iteration))
            return -1
    return -3


@njit(cache=True)
def adapt_step(clock, counters, state, rows, scalars, linear, model, exc, controls, counts, work,
               archive):  # fmt: skip
    """One accepted step of mdadap with fluid films (its trials included):
    the control of :func:`scheme_adapt_ordre2_v11.take_step` around
    :func:`film_trial`; a kernel status."""
    t = clock[K.C_TIME]
    dt = V11.first_trial_step(clock)
    max_trials = int(round(scalars[A.S_MAX_TRIALS]))
    err = 100.0
    trials = 0
    copy_into(state.vint_save, state.vint)
    while err > 1.0 and trials < max_trials:
        tried = dt
        failed = film_trial(t, tried, state, rows, scalars, linear, model, exc, controls, counts,
                            work)  # fmt: skip
        if failed >= 0:
            return K.record_failure(clock, counters, K.STATUS_SHOCK_DIVERGED, failed, tried)
        if failed == -2:
            K.expose_trial(state.q, state.v, state.a, rows[V11.Q_TRIAL], rows[V11.V_TRIAL],
                           rows[V11.A_TRIAL])  # fmt: skip
            return K.record_failure(clock, counters, K.STATUS_NOT_FINITE, -1, tried)
        if failed == -3:  # mdadap stops the run (ALGORITH15_99)
            return K.record_failure(clock, counters, STATUS_FILM_NOT_CONVERGED, -1, tried)
        err, dt, underflow = V11.judge(clock, tried, state, rows, scalars)
        if underflow:
            return K.record_failure(clock, counters, K.STATUS_STEP_UNDERFLOW, -1, dt)
        trials += 1
    V11.accept(clock, counters, state, rows, scalars, archive, dt, err, trials)
    return K.STATUS_DONE


@njit(cache=True)
def run_adapt_loop(clock, counters, state, memory, linear, model, exc, controls, counts, work,
                   archive, pas_arch):  # fmt: skip
    """code_aster 10-12's ADAPT_ORDRE2 (mdadap) with fluid films: its step
    control and archive grid (:mod:`scheme_adapt_ordre2_v11`), the film's
    iterations in each trial; resumable after any pause."""
    rows, scalars = memory[ROWS], memory[SCALARS]
    if scalars[A.S_FIRST_CALL] == 1.0:
        V11.start(clock, state, rows, scalars, pas_arch)
    while clock[K.C_TIME] < clock[K.C_END]:
        paused = K.pause_status(counters, archive.times)
        if paused:
            return paused
        if not loads_ready(clock, exc):
            return K.STATUS_LOADS
        status = adapt_step(clock, counters, state, rows, scalars, linear, model, exc, controls,
                            counts, work, archive)  # fmt: skip
        if status != K.STATUS_DONE:
            return status
    return V11.fill_slots(clock, counters, state, scalars, archive)


# ------------------------------------------------------------------ driver


def integrate_film(system, shocks, film: FluidFilm, excitation, q0, v0, t0, t_end, dt, instants,
                   pas_arch, options: SchemeOptions, label=None):  # fmt: skip
    """Integrate from t0 to t_end with fluid films: code_aster 11's EULER, or,
    where ``options.adapt_v11`` (the step's upper bound given), its
    ADAPT_ORDRE2 (mdadap); returns an :class:`integrate.RunResult`."""

    if not system.diagonal:
        raise NumericalError(
            f"the fluid film ({named('film')}) needs diagonal generalized matrices (a modal basis)"
        )
    scheme = "ADAPT_ORDRE2" if options.adapt_v11 else "EULER"
    n = system.n_modes
    linear = tuple(
        np.ascontiguousarray(np.diag(m), dtype=float)
        for m in (system.mass, system.stiffness, system.damping)
    )
    shapes, rest = shocks.local_arrays()
    rows = np.ascontiguousarray(film.rows, dtype=float).copy()
    weights = mass_weights(shapes, shocks.flags, replace(film, rows=rows))
    model = (shocks.flags, shocks.params, shapes, rest, shocks.polars, rows, weights)
    exc = excitation.bundle()
    q, v = np.array(q0, dtype=float), np.array(v0, dtype=float)
    a = np.zeros(n)
    vint = shocks.initial_vint(t0)
    work = (np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(N_KIN))
    # the C++ loops and start (asterlite.dynamics.native), else numba's: the same bits
    compiled = native.film_loops()
    fixed_loop, adapt_loop, first = compiled or (run_loop, run_adapt_loop, start)
    shock, finite = first(t0, q, v, a, linear, model, exc, vint, work)
    if shock >= 0 or not finite:
        raise NumericalError(
            f"non-finite initial acceleration at t={t0:.9g} (fluid film, {named('film')})"
        )
    controls = np.array([film.max_iterations, film.tolerance])
    scalars = np.zeros(3)
    eps = 10.0 * np.finfo(float).eps
    instants = np.asarray(instants, dtype=float)
    capacity = 2 + len(instants) + K.grid_step_count(t0, t_end, dt) // max(pas_arch, 1)
    adaptive = options.adapt_v11
    if adaptive:  # mdadap's state (the scheme's rows and scalars) in the generic layout
        memory, _ = V11.prepare(system, dt, options)
        state = State(q, v, a, np.zeros(n), vint, np.zeros_like(vint), np.zeros((5, 3)))
        capacity = min(capacity, 4096)
    clock, counters = K.new_clock(t0, dt, t_end), K.new_counters(adaptive)
    budget = StepBudget(t0, t_end, dt, adaptive, options)
    row_bytes = 8 * (2 + 3 * n + shocks.count * shocks.vint_width + K.N_INFO)
    budget.check_archive(capacity, row_bytes, pas_arch, clock, counters)
    buffers = new_buffers(capacity, n, shocks.count, shocks.vint_width)
    archive_start(buffers, t0, q, v, a, vint, dt)
    counters[K.K_ARCHIVED] = 1
    bar = progress.time_bar(label or f"{scheme} with fluid films", t0, t_end)
    started = wallclock.perf_counter()
    try:
        while True:
            counters[K.K_PAUSE_AT] = budget.next_pause(int(counters[K.K_STEP]))
            chunk_started = wallclock.perf_counter()
            if adaptive:
                status = adapt_loop(
                    clock, counters, state, memory, linear, model, exc, controls, scalars, work,
                    buffers, pas_arch,
                )  # fmt: skip
            else:
                status = fixed_loop(
                    clock, counters, q, v, a, vint, linear, model, exc, controls, scalars, work,
                    buffers, instants, pas_arch, eps,
                )  # fmt: skip
            if status == K.STATUS_FULL:
                budget.check_archive(2 * len(buffers.times), row_bytes, pas_arch, clock, counters)
                buffers = grow(buffers)
            elif status == K.STATUS_LOADS:
                excitation.refill(clock[K.C_TIME], clock[K.C_STEP])
                exc = excitation.bundle()
            elif status == K.STATUS_PAUSE:
                budget.check_steps(clock, counters, scheme)
                watchdog.check_limits()
                budget.resize_chunk(wallclock.perf_counter() - chunk_started)
                bar.update(clock[K.C_TIME], int(counters[K.K_STEP]))
            else:
                break
    finally:
        bar.close()
    elapsed = wallclock.perf_counter() - started
    if status == STATUS_FILM_NOT_CONVERGED:
        t = clock[K.C_TIME] + clock[K.C_STEP]
        raise NumericalError(
            f"{named('film')}: the acceleration did not converge in "
            f"{named('film.max_iterations')}={film.max_iterations} iterations at t={t:.6g} "
            f"(residual {math.sqrt(scalars[S_RATIO]):.3g} of the acceleration, "
            f"{named('film.tolerance')}={film.tolerance:g} on its square): raise "
            f"{named('film.max_iterations')} or {named('film.relaxation')}, or reduce "
            f"{named('grid.step')}"
        )
    if status != K.STATUS_DONE:
        raise divergence_error(status, clock, counters, shocks, system, scheme)
    count = counters[K.K_ARCHIVED]
    out = tuple(b[:count].copy() for b in buffers)
    info = run_info(clock, counters, t0, dt, elapsed, adaptive=adaptive)
    name = FILM_ADAPT_LOOP if adaptive else FILM_LOOP
    info["loop"] = f"{name} [{'C++' if compiled else 'numba'}]"
    info["film_iterations"] = int(scalars[S_TOTAL])
    info["film_worst_iterations"] = int(scalars[S_WORST])
    if adaptive:
        info["steps_kept_at_nmax_iter_pas"] = int(memory[SCALARS][A.S_KEPT_AT_MAX_TRIALS])
    return RunResult(*out, info=info)
