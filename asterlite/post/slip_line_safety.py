"""Safety factors along a slip line and the critical acceleration derived
from them (code_aster's POST_NEWMARK with RESULTAT_PESANTEUR).

The pieces are those of post_newmark_ops.py, written from its algorithm:

* on each segment of the slip line, the stress tensor (the mean of its
  nodal values) is turned into the line's frame as CALC_CHAMP's SIRO_ELEM
  does it in plane models (te0554): tangent ``t`` along the mean of
  ``dx/dxi`` at the nodes (the chord, from the first node to the second,
  for SEG2 and SEG3 alike), normal ``n = t x e_z``; ``SIG_N = n.sigma.n`` and
  ``SIG_TN = t.sigma.n``;
* Mohr-Coulomb sums over the segments: available shear
  ``sum(SIG_N tan(phi) - c)`` and mobilised shear ``sum(SIG_TN)``; the static
  safety factor is their ratio (times -1 with POSITION='AMONT');
* the dynamic safety factor at each instant removes the dynamic normal
  part's friction ``sum(SIG_N_dyn tan(phi))`` from the static available shear
  and the dynamic shear ``sum(SIG_TN_dyn)`` from the static one;
* the critical acceleration: a straight line fitted by least squares to the
  (mean acceleration, dynamic safety factor) pairs whose factor lies in
  (0.8, 1.2), both coefficients lowered by ``nstd`` standard deviations of
  the fit (scipy's curve_fit covariance, scaled by the residual variance),
  and the acceleration where that line reaches 1; KY is it over 9.81.
"""

from __future__ import annotations

import numpy as np

GRAVITY = 9.81  # code_aster's value in POST_NEWMARK
_BAND = (0.8, 1.2)  # safety factors kept for the fit, exclusive bounds


def line_frames(first: np.ndarray, last: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Unit tangents (first -> last vertex) and normals ``t x e_z`` of
    segments given by the (n, 2) coordinates of their two vertices."""
    chord = np.asarray(last, dtype=float)[:, :2] - np.asarray(first, dtype=float)[:, :2]
    length = np.linalg.norm(chord, axis=1)
    if np.any(length <= 0.0):
        raise ValueError("a segment of the slip line has zero length")
    tangent = chord / length[:, None]
    normal = np.column_stack([tangent[:, 1], -tangent[:, 0]])
    return tangent, normal


def line_tractions(
    sigma: np.ndarray, tangent: np.ndarray, normal: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """SIG_N and SIG_TN of plane stresses ``sigma`` (n, >=4: SIXX, SIYY,
    SIZZ, SIXY) on segments of the given frames."""
    sigma = np.asarray(sigma, dtype=float)
    sxx, syy, sxy = sigma[:, 0], sigma[:, 1], sigma[:, 3]
    # traction sigma.n, then its normal and tangential parts
    tx = sxx * normal[:, 0] + sxy * normal[:, 1]
    ty = sxy * normal[:, 0] + syy * normal[:, 1]
    sig_n = tx * normal[:, 0] + ty * normal[:, 1]
    sig_tn = tx * tangent[:, 0] + ty * tangent[:, 1]
    return sig_n, sig_tn


def static_shears(sig_n, sig_tn, phi_degrees, cohesion) -> tuple[float, float]:
    """Available ``sum(SIG_N tan(phi) - c)`` and mobilised ``sum(SIG_TN)``."""
    tan_phi = np.tan(np.radians(np.asarray(phi_degrees, dtype=float)))
    available = float(np.sum(np.asarray(sig_n) * tan_phi - np.asarray(cohesion)))
    return available, float(np.sum(sig_tn))


def static_safety_factor(sig_n, sig_tn, phi_degrees, cohesion, sign: float = 1.0) -> float:
    """Global static safety factor of the slip line (sign -1 for 'AMONT')."""
    available, mobilised = static_shears(sig_n, sig_tn, phi_degrees, cohesion)
    return sign * available / mobilised


def dynamic_safety_factors(
    static: tuple[np.ndarray, np.ndarray],
    dynamic: tuple[np.ndarray, np.ndarray],
    phi_degrees,
    cohesion,
    sign: float = 1.0,
) -> np.ndarray:
    """Safety factor at each instant: static (SIG_N, SIG_TN) on the segments,
    dynamic (SIG_N, SIG_TN) as (instants, segments) arrays. The dynamic part
    carries no cohesion, as in code_aster."""
    available, mobilised = static_shears(*static, phi_degrees, cohesion)
    tan_phi = np.tan(np.radians(np.asarray(phi_degrees, dtype=float)))
    dyn_n = np.atleast_2d(np.asarray(dynamic[0], dtype=float))
    dyn_tn = np.atleast_2d(np.asarray(dynamic[1], dtype=float))
    available_dyn = np.sum(dyn_n * tan_phi, axis=1)
    mobilised_dyn = np.sum(dyn_tn, axis=1)
    return sign * (available - available_dyn) / (mobilised - mobilised_dyn)


def critical_acceleration(safety, acceleration, nstd: float = 3.0) -> float:
    """Critical acceleration a_y (not KY: divide by GRAVITY) from the dynamic
    safety factors and the zone's mean acceleration at the same instants."""
    safety = np.asarray(safety, dtype=float)
    acceleration = np.asarray(acceleration, dtype=float)
    kept = (safety > _BAND[0]) & (safety < _BAND[1])
    if not np.any(kept):
        if safety.min() > 1.0:
            return 1.1 * float(acceleration.max())
        if safety.max() < 1.0:
            return 0.0
        raise ValueError(
            "the dynamic safety factor crosses 1 without any value in (0.8, 1.2): "
            "no regression for the critical acceleration"
        )
    x, y = acceleration[kept], safety[kept]
    if x.size < 3:
        # curve_fit's covariance needs more points than the 2 coefficients
        raise ValueError(
            f"{x.size} dynamic safety factors in (0.8, 1.2): the regression "
            "of the critical acceleration needs at least 3"
        )
    design = np.column_stack([x, np.ones_like(x)])
    coefficients, *_ = np.linalg.lstsq(design, y, rcond=None)
    residual = y - design @ coefficients
    variance = float(residual @ residual) / (x.size - 2)
    covariance = np.linalg.inv(design.T @ design) * variance
    slope, intercept = coefficients - nstd * np.sqrt(np.diag(covariance))
    return float((1.0 - intercept) / slope)
