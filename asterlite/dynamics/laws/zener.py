"""Generalized Zener model of DIS_VISC (rates only; integrated by ``rk54``).

A spring k1 in series with [a spring k2 in parallel with (a spring k3 in
series with a power-law dashpot σ3 = C sign(ε̇v) |ε̇v|^α)]. Unknowns, in
code_aster's order: the force σ, the dashpot deformation εv, the total
deformation ε and the dissipated energy W. Parameters are flexibilities
s1 = 1/k1, s3 = 1/k3 (either may be 0: rigid spring) and the stiffness k2.

    σ3   = σ (1 + k2 s1) - k2 ε          force carried by the viscous branch
    ε̇v   = sign(σ3) |σ3 / C|^(1/α)
    σ̇    = ((1 + k2 s3) ε̇ - ε̇v) / (s1 + s3 + k2 s1 s3)
    Ẇ    = σ3 ε̇v >= 0
"""

from __future__ import annotations

import math

from asterlite.dynamics.jit import njit

# Unknowns
Y_FORCE, Y_EPS_VISC, Y_EPS, Y_DISSIP = range(4)
N_Y = 4

# Model parameters (a view on the law's parameter array)
M_S1, M_K2, M_S3, M_C, M_ALPHA = range(5)

OVERFLOW_GUARD = 1.0e10  # beyond, check that |σ3/C|^(1/α) stays representable


@njit(cache=True)
def zener_rates(model, y, strain_rate, dy):
    """dy = d/dt of (σ, εv, ε, W) for an imposed total strain rate; returns
    False when the dashpot rate would overflow (the step must be cut)."""
    s1, k2, s3 = model[M_S1], model[M_K2], model[M_S3]
    c, alpha = model[M_C], model[M_ALPHA]
    x = (y[Y_FORCE] * (1.0 + k2 * s1) - k2 * y[Y_EPS]) / c
    ax = abs(x)
    if ax > OVERFLOW_GUARD and math.log10(ax) > 200.0 * alpha:
        return False
    rate_visc = ax ** (1.0 / alpha)
    if x < 0.0:
        rate_visc = -rate_visc
    dy[Y_EPS] = strain_rate
    dy[Y_EPS_VISC] = rate_visc
    dy[Y_DISSIP] = c * abs(x * rate_visc)
    dy[Y_FORCE] = ((1.0 + k2 * s3) * strain_rate - rate_visc) / (s1 + s3 + k2 * s1 * s3)
    return True
