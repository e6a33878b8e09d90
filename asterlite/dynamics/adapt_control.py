"""Step control shared by ADAPT_ORDRE1 and ADAPT_ORDRE2 (code_aster's
intadapt1 / intadapt2): the step follows an apparent frequency of the
motion so that a period holds about NB_POIN_PERIODE steps.

Apparent frequency of a trial step (frqapp): for each mode,
ω_i² = |a_{n+1} - a_n| / max(v_min,i dt, |q_{n+1} - q_n|), and
f = sqrt(max(ε, max_i ω_i²)) / 2π. The error is err = NB_POIN_PERIODE f dt.

err >= 1 divides the step by COEF_DIVI_PAS and retries (up to
NMAX_ITER_PAS trials, then the step is kept with a warning); a step is
multiplied by COEF_MULT_PAS only after more than four calm steps in a row
with err < 0.75. After each step the reference velocities v_min are 1 % of
the velocity norm (VITE_MIN='NORM') or the running maximum of 1 % of each
modal velocity ('MAXI').
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

S_NORM_VMIN, S_POINTS, S_MAX_TRIALS, S_MULT, S_DIVI, S_DTMIN, S_DTMAX = range(7)
S_ADAPTIVE, S_CALM_STEPS, S_FIRST_CALL, S_KEPT_AT_MAX_TRIALS = range(7, 11)
N_SCALARS = 11
EPS = 100.0 * np.finfo(np.float64).eps
TINY = np.finfo(np.float64).tiny
MACHINE_EPS = np.finfo(np.float64).eps


def control_scalars(dt, options) -> tuple[np.ndarray, bool]:
    """PAS_MAXI defaults to 1e6 PAS, PAS_MINI to PAS_LIMI_RELA PAS."""
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
    """NB_POIN_PERIODE times the apparent frequency times the step (>= ε)."""
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
