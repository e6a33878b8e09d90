"""Discrete element with isotropic or kinematic hardening (DIS_ECRO_TRAC),
as rates for ``rk54`` (code_aster's disc_isotr).

The force–displacement curve (0, 0), (dx0, fx0), (x2, y2), ... gives the
elastic stiffness k = fx0/dx0 and, read against the plastic displacement
p_i = x_i - y_i/k, the threshold R(p) (piecewise linear). Unknowns, in
code_aster's order (14): force F (3), displacement u (3), dissipated
energy W, cumulated plastic displacement p, plastic displacement up (3),
back force X (3).

    F − X beyond the threshold and loading (f·u̇ > 0 with f = F − X):
        ṗ = k (f·u̇) / (|f| (k + H)),  u̇p = ṗ f/|f|
    F' = k (u̇ − u̇p),  Ẇ = ṗ |f|
    isotropic:  threshold R(p), H = R'(p), X = 0
    kinematic:  threshold fx0,  H = slope of the first hardening segment,
                Ẋ = H u̇p

Only the components the law drives are non-zero (x for the axial law, y and
z for the transverse one).
"""

from __future__ import annotations

import math

from asterlite.dynamics.jit import njit

Y_F = 0  # force (3)
Y_U = 3  # displacement (3)
Y_W = 6  # dissipated energy
Y_P = 7  # cumulated plastic displacement
Y_UP = 8  # plastic displacement (3)
Y_X = 11  # back force (3)
N_Y = 14

# Curve parameters (a view on the law's parameter array)
C_KINEMATIC = 0  # 1.0: kinematic hardening, else isotropic
C_FX0, C_DX0 = 1, 2
C_N = 3  # number of points, then abscissas, then ordinates
C_POINTS = 4


@njit(cache=True)
def threshold(curve, p):
    """(R(p), R'(p)) read on the curve against the plastic displacement;
    NaN beyond the last point (code_aster stops there)."""
    n = int(curve[C_N])
    xs = C_POINTS
    ys = C_POINTS + n
    k = curve[ys + 1] / curve[xs + 1]
    for i in range(2, n):
        if p < curve[xs + i] - curve[ys + i] / k:
            f0, f1 = curve[ys + i - 1], curve[ys + i]
            p0 = curve[xs + i - 1] - f0 / k
            p1 = curve[xs + i] - f1 / k
            slope = (f1 - f0) / (p1 - p0)
            return f0 + slope * (p - p0), slope
    return math.nan, math.nan


@njit(cache=True)
def hardening_rates(curve, y, rate, dy):
    """dy = d/dt of the 14 unknowns for the imposed displacement rates
    ``rate`` (3); returns False when the curve is exhausted."""
    k = curve[C_FX0] / curve[C_DX0]
    kinematic = curve[C_KINEMATIC] == 1.0
    if kinematic:
        radius, hardening = threshold(curve, 0.0)
        radius = curve[C_FX0]
    else:
        radius, hardening = threshold(curve, y[Y_P])
    if math.isnan(radius):
        return False
    fx = y[Y_F] - y[Y_X]
    fy = y[Y_F + 1] - y[Y_X + 1]
    fz = y[Y_F + 2] - y[Y_X + 2]
    feq = math.sqrt(fx * fx + fy * fy + fz * fz)
    for i in range(N_Y):
        dy[i] = 0.0
    for i in range(3):
        dy[Y_U + i] = rate[i]
    if feq - radius > 0.0:
        loading = fx * rate[0] + fy * rate[1] + fz * rate[2]
        if loading > 0.0:
            dp = k * loading / (feq * (k + hardening))
            dy[Y_P] = dp
            dy[Y_UP] = dp * fx / feq
            dy[Y_UP + 1] = dp * fy / feq
            dy[Y_UP + 2] = dp * fz / feq
            if kinematic:
                for i in range(3):
                    dy[Y_X + i] = hardening * dy[Y_UP + i]
    for i in range(3):
        dy[Y_F + i] = k * (dy[Y_U + i] - dy[Y_UP + i])
    dy[Y_W] = dy[Y_P] * feq
    return True
