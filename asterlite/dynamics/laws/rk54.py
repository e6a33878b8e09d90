"""Adaptive embedded Runge–Kutta 5(4) (Cash–Karp) for the rate-form laws.

DIS_VISC and DIS_ECRO_TRAC integrate their constitutive rates over each
time step of the transient, for a relative velocity held constant over
the step (code_aster's rk5adp): sub-steps are adapted to the tolerance
the tolerance on the embedded error, normalised per unknown (by given scales,
or by |y| with 1 below 1e-8), and an iteration bound limits the consecutive
attempts of one sub-step. Step control constants are code_aster's.

Systems are dispatched by an integer so every function stays cacheable.
"""

from __future__ import annotations

import math

from asterlite.dynamics.jit import njit
from asterlite.dynamics.laws.discrete_hardening import hardening_rates
from asterlite.dynamics.laws.zener import zener_rates

ZENER, HARDENING = 1, 2

# Cash–Karp tableau
C2, C3, C4, C5, C6 = 0.2, 0.3, 0.6, 1.0, 0.875
A21 = 0.2
A31, A32 = 3.0 / 40.0, 9.0 / 40.0
A41, A42, A43 = 0.3, -0.9, 1.2
A51, A52, A53, A54 = -11.0 / 54.0, 2.5, -70.0 / 27.0, 35.0 / 27.0
A61, A62, A63, A64, A65 = (
    1631.0 / 55296.0,
    175.0 / 512.0,
    575.0 / 13824.0,
    44275.0 / 110592.0,
    253.0 / 4096.0,
)
B1, B3, B4, B6 = 37.0 / 378.0, 250.0 / 621.0, 125.0 / 594.0, 512.0 / 1771.0
# fifth minus fourth order weights: the embedded error estimate
E1 = B1 - 2825.0 / 27648.0
E3 = B3 - 18575.0 / 48384.0
E4 = B4 - 13525.0 / 55296.0
E5 = -277.0 / 14336.0
E6 = B6 - 0.25

# step control (code_aster's values)
GROW_POWER, SHRINK_POWER = -0.20, -0.25
SAFETY, FORCED_CUT, MAX_GROWTH = 0.90, 0.30, 5.0
GROWTH_THRESHOLD = (MAX_GROWTH / SAFETY) ** (1.0 / GROW_POWER)
TINY_SCALE = 1.0e-8
# a converged sub-step ending this close to the end of the step (seconds,
# absolute: code_aster's rk5adp) ends the integration there
END_PRECISION = 1.0e-8
HUGE_ERROR = 1.0e8
SMALLEST_STEP = 1.0e-10  # relative to dt: below, sub-steps would creep towards a wall
N_WORK = 9  # rows of the scratch array


@njit(cache=True)
def rates(system, model, y, rate, dy):
    if system == ZENER:
        return zener_rates(model, y, rate[0], dy)
    return hardening_rates(model, y, rate, dy)


@njit(cache=True)
def stage(y, h, n, out, ka, a, kb, b, kc, c, kd, d, ke, e):
    for i in range(n):
        out[i] = y[i] + h * (a * ka[i] + b * kb[i] + c * kc[i] + d * kd[i] + e * ke[i])


@njit(cache=True)
def cash_karp_step(system, model, y, rate, h, n, work):
    """One embedded step from y: work[7] <- 5th-order solution, work[8] <- error.
    False when the rates ask for a smaller step."""
    k1, k2, k3, k4, k5, k6 = work[0], work[1], work[2], work[3], work[4], work[5]
    ys, y5, err = work[6], work[7], work[8]
    if not rates(system, model, y, rate, k1):
        return False
    stage(y, h, n, ys, k1, A21, k1, 0.0, k1, 0.0, k1, 0.0, k1, 0.0)
    if not rates(system, model, ys, rate, k2):
        return False
    stage(y, h, n, ys, k1, A31, k2, A32, k1, 0.0, k1, 0.0, k1, 0.0)
    if not rates(system, model, ys, rate, k3):
        return False
    stage(y, h, n, ys, k1, A41, k2, A42, k3, A43, k1, 0.0, k1, 0.0)
    if not rates(system, model, ys, rate, k4):
        return False
    stage(y, h, n, ys, k1, A51, k2, A52, k3, A53, k4, A54, k1, 0.0)
    if not rates(system, model, ys, rate, k5):
        return False
    stage(y, h, n, ys, k1, A61, k2, A62, k3, A63, k4, A64, k5, A65)
    if not rates(system, model, ys, rate, k6):
        return False
    for i in range(n):
        y5[i] = y[i] + h * (B1 * k1[i] + B3 * k3[i] + B4 * k4[i] + B6 * k6[i])
        err[i] = h * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i])
    return True


@njit(cache=True)
def adaptive_integrate(system, model, y_in, rate, dt, max_attempts, tolerance, scales, y_out, work):
    """Integrate the system from y_in over dt (rates held fixed) into y_out
    (may be y_in). ``scales``: per-unknown error scales, or empty to scale
    by |y|. As in code_aster, a converged sub-step that ends within
    END_PRECISION (1e-8 s) of dt ends the integration, even short of dt
    (a step below 1e-8 s whose first try failed is integrated over the
    first converged sub-step only). Returns False when a sub-step failed ``max_attempts`` times in a
    row, or sub-steps shrink below 1e-10 dt (e.g. a hardening curve is
    exhausted); y_out then holds the state reached so far (time not completed)."""
    n = y_out.shape[0]
    for i in range(n):
        y_out[i] = y_in[i]
    if dt <= 0.0:
        return True
    t, h = 0.0, dt
    attempts = 0
    while True:
        if attempts > max_attempts or h < SMALLEST_STEP * dt:
            return False
        attempts += 1
        if not cash_karp_step(system, model, y_out, rate, h, n, work):
            h *= FORCED_CUT
            continue
        error = 0.0
        blown = False
        for i in range(n):
            if scales.shape[0] == n:
                scale = scales[i]
            else:
                scale = abs(y_out[i]) if abs(y_out[i]) > TINY_SCALE else 1.0
            e = abs(work[8, i] / scale)
            if e > HUGE_ERROR and math.log10(e) > 100.0:
                blown = True
            error += e * e
        if blown:
            h *= FORCED_CUT
            continue
        error = math.sqrt(error) / tolerance
        if error > 1.0:
            h = max(0.1 * h, SAFETY * h * error**SHRINK_POWER)
            continue
        for i in range(n):
            y_out[i] = work[7, i]
        if abs(t + h - dt) <= END_PRECISION:  # rk5adp: within 1e-8 s of the end is the end
            return True
        t += h
        attempts = 0
        h = SAFETY * h * error**GROW_POWER if error > GROWTH_THRESHOLD else MAX_GROWTH * h
        if t + h > dt:
            h = dt - t
