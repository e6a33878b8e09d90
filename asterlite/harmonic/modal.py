"""Harmonic solve on a generalized (modal) basis: small dense matrices, all
frequencies at once.

(K + iω C - ω² M) q = F(f) for every frequency, with

- diagonal matrices (a modal basis stored DIAG, or modal damping on a
  diagonal basis): one element-wise division for the whole sweep;
- dense matrices: batched LU solves (numpy's stacked ``solve``, one LAPACK
  call per frequency, as code_aster factorises the full matrix at each
  frequency), or, for long sweeps of larger bases, the eigen-decomposition
  of the first-order (state-space) operator computed once, after which
  every frequency costs two matrix products. Each frequency's backward error
  is then measured, and the frequencies whose error exceeds what an LU
  solve gives are solved again directly.

Coupled generalized models (substructures linked by interface relations
B q = 0) are solved on an orthonormal basis T of the null space of B:
Tᵀ A T r = Tᵀ F, q = T r (what code_aster's dualised relations compute).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from asterlite.harmonic.fields import TWO_PI, omega2
from asterlite.harmonic.loads import SweepLoads

# below this many multiply-adds (n_freq · n³) the sweep is solved by LU directly
DIRECT_BUDGET = 2.0e7
# backward error an LU solve reaches; the state-space answer at a frequency
# above it is replaced by a direct solve
BACKWARD_TOLERANCE = 1.0e-13
# complex entries per batch of stacked matrices (64 MB)
BATCH_ENTRIES = 4_000_000


class SingularSystem(ValueError):
    """The dynamic matrix is singular at a frequency (an undamped resonance)."""

    def __init__(self, frequency: float):
        super().__init__(
            f"the dynamic matrix K + iωC - ω²M is singular at {frequency:g} Hz "
            "(an undamped eigenfrequency)"
        )
        self.frequency = frequency


@dataclass
class SolveInfo:
    """How a sweep was solved (for the log and the benchmark)."""

    method: str = ""  # diagonal, direct, state-space
    redone: int = 0  # frequencies solved again directly after the state-space pass
    notes: list[str] = field(default_factory=list)


def is_diagonal(matrix) -> bool:
    matrix = np.asarray(matrix)
    return not np.any(matrix - np.diag(np.diagonal(matrix)))


def solve(
    mass: np.ndarray,
    stiffness: np.ndarray,
    damping: np.ndarray | None,
    frequencies,
    rhs,
    constraints: np.ndarray | None = None,
    method: str = "auto",
) -> tuple[np.ndarray, SolveInfo]:
    """Amplitudes q (n_freq, n) for the right-hand sides ``rhs``: an
    (n_freq, n) array or a :class:`SweepLoads` (load vectors times their
    coefficients, projected once on the state-space basis).

    ``constraints``: an (n, r) orthonormal basis of the admissible
    coordinates (coupled generalized models), or None. ``method``: ``auto``,
    ``direct`` or ``state-space`` (the last two for tests and benchmarks).
    """
    f = np.atleast_1d(np.asarray(frequencies, dtype=float))
    if not isinstance(rhs, SweepLoads):
        rhs = SweepLoads(np.zeros((0, np.shape(rhs)[1])), np.zeros((f.size, 0)), np.asarray(rhs))
    mass = np.asarray(mass)
    stiffness = np.asarray(stiffness)
    damping = None if damping is None else np.asarray(damping)
    if constraints is not None:
        t = np.asarray(constraints)
        reduced = SweepLoads(
            rhs.vectors @ t, rhs.coefficients, None if rhs.extra is None else rhs.extra @ t
        )
        q, info = solve(
            t.T @ mass @ t,
            t.T @ stiffness @ t,
            None if damping is None else t.T @ damping @ t,
            f,
            reduced,
            method=method,
        )
        return q @ t.T, info
    info = SolveInfo()
    matrices = [mass, stiffness] + ([damping] if damping is not None else [])
    if method == "auto" and all(is_diagonal(m) for m in matrices):
        info.method = "diagonal"
        return _diagonal(mass, stiffness, damping, f, rhs.dense()), info
    n = mass.shape[0]
    if method == "direct" or (method == "auto" and f.size * n**3 <= DIRECT_BUDGET):
        info.method = "direct"
        return _direct(mass, stiffness, damping, f, rhs.dense()), info
    info.method = "state-space"
    q = _state_space(mass, stiffness, damping, f, rhs, info)
    return q, info


def dynamic_diagonal(mass, stiffness, damping, f) -> np.ndarray:
    """(n_freq, n) diagonals of K + iωC - ω²M."""
    a = np.diagonal(stiffness)[None, :] - omega2(f)[:, None] * np.diagonal(mass)[None, :]
    if damping is not None:
        a = a + (1j * TWO_PI * f)[:, None] * np.diagonal(damping)[None, :]
    return a.astype(complex)


def _diagonal(mass, stiffness, damping, f, rhs) -> np.ndarray:
    a = dynamic_diagonal(mass, stiffness, damping, f)
    singular = np.any(a == 0, axis=1)
    if singular.any():
        raise SingularSystem(float(f[np.argmax(singular)]))
    return rhs / a


def dynamic_matrices(mass, stiffness, damping, f) -> np.ndarray:
    """(n_freq, n, n) stack of K + iωC - ω²M."""
    a = stiffness[None, :, :] - omega2(f)[:, None, None] * mass[None, :, :]
    if damping is not None:
        a = a + (1j * TWO_PI * f)[:, None, None] * damping[None, :, :]
    return a.astype(complex)


def _direct(mass, stiffness, damping, f, rhs) -> np.ndarray:
    n = mass.shape[0]
    out = np.empty((f.size, n), dtype=complex)
    batch = max(1, BATCH_ENTRIES // max(n * n, 1))
    for start in range(0, f.size, batch):
        stop = min(start + batch, f.size)
        a = dynamic_matrices(mass, stiffness, damping, f[start:stop])
        try:
            out[start:stop] = np.linalg.solve(a, rhs[start:stop, :, None])[:, :, 0]
        except np.linalg.LinAlgError:
            for k in range(start, stop):
                try:
                    out[k] = np.linalg.solve(a[k - start], rhs[k])
                except np.linalg.LinAlgError:
                    raise SingularSystem(float(f[k])) from None
    bad = ~np.all(np.isfinite(out), axis=1)
    if bad.any():
        raise SingularSystem(float(f[np.argmax(bad)]))
    return out


def _times(matrix, q) -> np.ndarray:
    """q @ matrixᵀ (rows of q are states), element-wise for a diagonal
    matrix, real and imaginary parts apart for a real one (real BLAS)."""
    if is_diagonal(matrix):
        return q * np.diagonal(matrix)[None, :]
    if np.iscomplexobj(matrix):
        return q @ matrix.T
    return (q.real @ matrix.T) + 1j * (q.imag @ matrix.T)


def _residual(mass, stiffness, damping, f, q, rhs) -> np.ndarray:
    """A(f) q - F row by row."""
    out = _times(stiffness, q) - omega2(f)[:, None] * _times(mass, q) - rhs
    if damping is not None:
        out += (1j * TWO_PI * f)[:, None] * _times(damping, q)
    return out


def _norm(matrix) -> float:
    return float(np.abs(matrix).sum(axis=1).max())


def _state_space(mass, stiffness, damping, f, loads: SweepLoads, info: SolveInfo) -> np.ndarray:
    """z = (iω I - S)⁻¹ [0; M⁻¹F], S = [[0, I], [-M⁻¹K, -M⁻¹C]], with S = V Λ V⁻¹
    computed once (real arithmetic when K and C are real); q is the first
    half of z. One step of iterative refinement with the same operator, then
    the frequencies whose backward error still exceeds an LU solve's are
    solved directly."""
    n = mass.shape[0]
    try:
        m_inv = np.linalg.inv(mass)
    except np.linalg.LinAlgError:
        info.notes.append("singular mass: solved directly")
        info.method = "direct"
        return _direct(mass, stiffness, damping, f, loads.dense())
    real = not np.iscomplexobj(stiffness) and (damping is None or not np.iscomplexobj(damping))
    s = np.zeros((2 * n, 2 * n), dtype=float if real else complex)
    s[:n, n:] = np.eye(n)
    s[n:, :n] = -m_inv @ stiffness
    if damping is not None:
        s[n:, n:] = -m_inv @ damping
    eigenvalues, vectors = np.linalg.eig(s)
    try:
        inverse = np.linalg.inv(vectors)
    except np.linalg.LinAlgError:
        info.notes.append("defective first-order operator: solved directly")
        info.method = "direct"
        return _direct(mass, stiffness, damping, f, loads.dense())
    w = inverse[:, n:] @ m_inv  # (2n, n): V⁻¹ [0; M⁻¹ ·]
    top = np.ascontiguousarray(vectors[:n, :].T)  # (2n, n)
    with np.errstate(divide="ignore", invalid="ignore"):
        gain = 1.0 / ((1j * TWO_PI * f)[:, None] - eigenvalues[None, :])
    q = (loads.project(w) * gain) @ top
    rhs = loads.dense()
    scale = _norm(stiffness) + omega2(np.abs(f)) * _norm(mass)
    if damping is not None:
        scale = scale + TWO_PI * np.abs(f) * _norm(damping)

    def backward_error(rows):
        residual = _residual(mass, stiffness, damping, f[rows], q[rows], rhs[rows])
        with np.errstate(invalid="ignore"):
            error = np.abs(residual).max(axis=1) / (
                scale[rows] * np.abs(q[rows]).max(axis=1) + np.abs(rhs[rows]).max(axis=1) + 1e-300
            )
        return residual, error

    rows = np.arange(f.size)
    residual, error = backward_error(rows)
    refine = ~(error <= BACKWARD_TOLERANCE)
    if refine.any():  # q -= Ã⁻¹ (A q - F) with the same operator
        rows = np.flatnonzero(refine)
        q[rows] -= ((residual[refine] @ w.T) * gain[rows]) @ top
        _, error = backward_error(rows)
        redo = rows[~(error <= BACKWARD_TOLERANCE)]
        if redo.size:
            q[redo] = _direct(mass, stiffness, damping, f[redo], rhs[redo])
            info.redone = int(redo.size)
    return q
