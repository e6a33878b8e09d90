"""Step control shared by ADAPT_ORDRE1 and ADAPT_ORDRE2 (code_aster's
intadapt1 / intadapt2): the step follows an apparent frequency of the
motion so that a period holds about N steps (the points per period).

Apparent frequency of a trial step (frqapp): for each mode,
ω_i² = |a_{n+1} - a_n| / max(v_min,i dt, |q_{n+1} - q_n|), and
f = sqrt(max(ε, max_i ω_i²)) / 2π. The error is err = N f dt.

err >= 1 divides the step by the division factor and retries (up to the
largest number of trials, then the step is kept with a warning); a step is
multiplied by the growth factor only after more than four calm steps in a row
with err < 0.75. After each step the reference velocities v_min are 1 % of
the velocity norm ('NORM') or the running maximum of 1 % of each
modal velocity ('MAXI').
"""

from __future__ import annotations

import math

import numpy as np

from asterlite.dynamics import contact as C
from asterlite.dynamics.jit import njit

S_NORM_VMIN, S_POINTS, S_MAX_TRIALS, S_MULT, S_DIVI, S_DTMIN, S_DTMAX = range(7)
S_ADAPTIVE, S_CALM_STEPS, S_FIRST_CALL, S_KEPT_AT_MAX_TRIALS = range(7, 11)
N_SCALARS = 11
EPS = 100.0 * np.finfo(np.float64).eps
TINY = np.finfo(np.float64).tiny
MACHINE_EPS = np.finfo(np.float64).eps


def control_scalars(dt, options) -> tuple[np.ndarray, bool]:
    """The step's upper bound defaults to 1e6 dt, its lower bound to the
    relative limit (``pas_limi_rela``) times dt."""
    dt_max = options.dt_max if options.dt_max is not None else 1.0e6 * dt
    dt_min = options.dt_min if options.dt_min is not None else options.pas_limi_rela * dt
    adaptive = abs(dt_max / dt_min - 1.0) >= EPS
    scalars = np.zeros(N_SCALARS)
    scalars[S_NORM_VMIN] = 1.0 if options.vite_min == "NORM" else 0.0
    scalars[S_POINTS] = float(options.nb_poin_periode)
    scalars[S_MAX_TRIALS] = float(options.nmax_iter_pas)
    scalars[S_MULT], scalars[S_DIVI] = options.coef_mult_pas, options.coef_divi_pas
    scalars[S_DTMIN], scalars[S_DTMAX] = dt_min, dt_max
    scalars[S_ADAPTIVE] = 1.0 if adaptive else 0.0
    scalars[S_CALM_STEPS] = 1.0
    scalars[S_FIRST_CALL] = 1.0
    return scalars, adaptive


@njit(cache=True)
def apparent_frequency(dt, q1, q2, a1, a2, vmin):
    largest = MACHINE_EPS
    for i in range(q1.shape[0]):
        da = a2[i] - a1[i]
        reference = vmin[i] * dt
        dq = abs(q2[i] - q1[i])
        b = reference if reference >= dq else dq
        if b <= TINY:
            b = MACHINE_EPS
        ratio = abs(da / b)
        if ratio >= largest:
            largest = ratio
    return math.sqrt(largest) / (2.0 * math.pi)


@njit(cache=True)
def frequency_error(dt, q1, q2, a1, a2, vmin, scalars):
    """The points per period times the apparent frequency times the step (>= ε)."""
    return max(scalars[S_POINTS] * apparent_frequency(dt, q1, q2, a1, a2, vmin) * dt, EPS)


@njit(cache=True)
def step_factor(err, scalars):
    """Factor on the step from the error, updating the calm-step counter."""
    factor = 1.0
    if err >= 1.0:
        factor = 1.0 / scalars[S_DIVI]
    elif scalars[S_CALM_STEPS] > 4.5:
        if err < 0.75:
            factor = scalars[S_MULT]
            scalars[S_CALM_STEPS] = 1.0
    else:
        scalars[S_CALM_STEPS] += 1.0
    return factor


@njit(cache=True)
def update_reference_velocities(velocity, vmin, scalars):
    n = velocity.shape[0]
    if scalars[S_NORM_VMIN] == 1.0:
        norm = 0.0
        for i in range(n):
            norm += velocity[i] ** 2
        norm = math.sqrt(norm) * 0.01
        for i in range(n):
            vmin[i] = norm
    else:
        for i in range(n):
            vmin[i] = max(abs(velocity[i] * 0.01), vmin[i])


# --------------------------------------------------------------------------- damping cap
# RUNGE_KUTTA_* and DEVOGE evaluate the shock forces explicitly: with a stiff
# normal or tangential shock damping the stages are stable only while c·dt stays inside the
# scheme's real stability interval. Their controllers never take a step above
# shock_damping_step (asterlite.dynamics.model.shock_damping_limit names it).


@njit(cache=True)
def explicit_step(omega2, damping):
    """Largest stable step of v += dt (-ω² q - c v), q += dt v."""
    return 4.0 / (damping + math.sqrt(damping * damping + 4.0 * omega2))


@njit(cache=True)
def shock_damping_step(lin, shk, modal, radius):
    """radius/2 times the explicit step of every mode stiffened and damped by
    each damped shock on each shape component (inf without shock damping);
    ``modal``: count the modal damping (explicit in the stages)."""
    minv, stiffness, damping = lin.minv, lin.stiffness, lin.damping
    flags, params, phis = shk.flags, shk.params, shk.phis
    tiny = MACHINE_EPS * 1.0e5
    best = np.inf
    for s in range(flags.shape[0]):
        nodes = 2 if flags[s, C.F_TWO_NODES] else 1
        for pair in range(2):
            k = params[s, C.P_KN] if pair == 0 else params[s, C.P_KT]
            c_shock = params[s, C.P_CN] if pair == 0 else params[s, C.P_CT]
            if abs(c_shock) <= tiny:
                continue
            for node in range(nodes):
                for j in range(minv.shape[0]):
                    inverse = minv[j, j]
                    if not (inverse > 0.0 and inverse < 1.0 / tiny):
                        continue
                    w2 = max(abs(stiffness[j, j] * inverse), 1.0e-12)
                    own = damping[j, j] * inverse if modal else 0.0
                    for c in range(3):
                        share = phis[s, node, c, j] ** 2 * inverse
                        if share <= 0.0:
                            continue
                        step = (
                            0.5 * radius * explicit_step(w2 + abs(k) * share, own + c_shock * share)
                        )
                        if step < best:
                            best = step
    return best
