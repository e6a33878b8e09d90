"""Generalized coordinates identified from measured data (PROJ_MESU_MODAL).

Measured values y (one per sensor: a node and a translation component of
the measurement mesh) are explained by a modal basis Φ seen at the sensors
(the observation matrix H, n_sensors × n_modes): for each measured state
(an instant, a frequency or an identified mode) η solves the normal
equations

    (HᵀH + diag(α)) η = Hᵀ y  (+ diag(α) η_previous with TIK_RELA)

as code_aster's op0193 (mpinvr, mpinv2, mpinvc) does: α are the weights of
the regularisation (COEF_PONDER, zero without REGUL); the system is solved
by LU, or by SVD keeping the singular values σ_j with σ_j / σ_1 ≥ EPS. With
fewer sensors than modes and no weight, REGUL='NON' takes the
minimum-norm solution η = Hᵀ (H Hᵀ)⁺ y.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla

# a measured mode component counts as a sensor above this magnitude
# (100 times the machine precision, as code_aster's mpmod3 reads it)
SENSOR_THRESHOLD = 100.0 * np.finfo(float).eps


class MeasuredProjectionError(ValueError):
    """A system the identification cannot solve (singular, no rank)."""


@dataclass
class Resolution:
    """RESOLUTION: METHODE ('LU' or 'SVD'), EPS (SVD's relative threshold),
    REGUL ('NON', 'NORM_MIN', 'TIK_RELA') and the weights α, one per mode
    (shape (n_modes,)) or one per mode and state (shape (n_states, n_modes))."""

    method: str = "LU"
    eps: float = 0.0
    regul: str = "NON"
    weights: np.ndarray | None = None

    def weights_at(self, state: int, n_modes: int) -> np.ndarray:
        if self.weights is None or self.regul == "NON":
            return np.zeros(n_modes)
        w = np.asarray(self.weights, dtype=float)
        return w[state] if w.ndim == 2 else w


def svd_solve(matrix: np.ndarray, rhs: np.ndarray, eps: float) -> np.ndarray:
    """Least-squares solution of matrix x = rhs keeping the singular values
    σ_j with σ_j / σ_1 ≥ eps (at least the largest); rhs may hold several
    columns."""
    u, s, vt = np.linalg.svd(matrix, full_matrices=False)
    if s.size == 0 or s[0] == 0.0:
        raise MeasuredProjectionError("the system has no non-zero singular value")
    # code_aster keeps the values down to the first ratio below EPS
    below = np.nonzero(s[1:] / s[0] < eps)[0]
    rank = int(below[0]) + 1 if below.size else s.size
    coefficients = (u[:, :rank].T @ rhs) / (s[:rank] if rhs.ndim == 1 else s[:rank, None])
    return vt[:rank].T @ coefficients


def lu_solve(matrix: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    """matrix x = rhs by LU with partial pivoting; a zero pivot (relative to
    the largest entry, at machine precision) is a singular system."""
    lu, piv = sla.lu_factor(matrix, check_finite=True)
    pivots = np.abs(np.diag(lu))
    scale = np.abs(matrix).max() if matrix.size else 0.0
    if scale == 0.0 or pivots.min() <= np.finfo(float).eps * scale:
        raise MeasuredProjectionError("the normal equations are singular (use METHODE='SVD')")
    return sla.lu_solve((lu, piv), rhs)


def _solve(matrix, rhs, resolution: Resolution):
    if resolution.method == "SVD":
        return svd_solve(matrix, rhs, resolution.eps)
    return lu_solve(matrix, rhs)


def identify(observation: np.ndarray, measured: np.ndarray, resolution: Resolution) -> np.ndarray:
    """Generalized coordinates (n_states, n_modes) of measured values
    (n_states, n_sensors, real or complex) seen through ``observation``
    (n_sensors, n_modes)."""
    h = np.asarray(observation, dtype=float)
    y = np.asarray(measured)
    n_sensors, n_modes = h.shape
    normal = h.T @ h
    out = np.zeros((y.shape[0], n_modes), dtype=np.result_type(y, float))
    for state in range(y.shape[0]):
        alpha = resolution.weights_at(state, n_modes)
        if np.any(alpha < 0.0):
            raise MeasuredProjectionError(
                f"negative weight COEF_PONDER at measured state {state + 1}"
            )
        unweighted = not np.any(alpha > np.finfo(float).eps)
        if n_sensors < n_modes and unweighted and resolution.regul == "NON":
            # fewer sensors than modes: the coordinates of least norm
            gram = h @ h.T
            out[state] = h.T @ _solve_any(gram, y[state], resolution)
            continue
        rhs = h.T @ y[state]
        if resolution.regul == "TIK_RELA" and state > 0:
            rhs = rhs + alpha * out[state - 1]
        out[state] = _solve_any(normal + np.diag(alpha), rhs, resolution)
    return out


def _solve_any(matrix, rhs, resolution):
    """Real matrix, real or complex right-hand side (solved part by part)."""
    if np.iscomplexobj(rhs):
        both = _solve(matrix, np.column_stack([rhs.real, rhs.imag]), resolution)
        return both[:, 0] + 1j * both[:, 1]
    return _solve(matrix, rhs, resolution)


def time_derivatives(depl: np.ndarray, times: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Velocity and acceleration of identified displacements by forward
    differences, the last state repeating the one before (code_aster's
    mpinv2)."""
    dt = np.diff(times)[:, None]
    vite = np.empty_like(depl)
    vite[:-1] = np.diff(depl, axis=0) / dt
    vite[-1] = vite[-2]
    acce = np.empty_like(depl)
    acce[:-1] = np.diff(vite, axis=0) / dt
    acce[-1] = acce[-2]
    return vite, acce


def time_integral(rate: np.ndarray, times: np.ndarray) -> np.ndarray:
    """x(t_0) = 0, x(t_i) = x(t_{i-1}) + rate(t_i) (t_i - t_{i-1}): the
    integration mpinv2 uses for measured velocities and accelerations."""
    out = np.zeros_like(rate)
    dt = np.diff(times)[:, None]
    out[1:] = np.cumsum(rate[1:] * dt, axis=0)
    return out
