"""Harmonic solve on assembled physical matrices: one sparse complex
factorisation per frequency.

The kinematic relations B u = 0 of the numbering (DDL_IMPO, LIAISON_DDL of
the loads given to the matrices) are eliminated as for the real problems
(``asterlite.fem.constraints``): u = T q, and at each frequency

    Tᵀ (K + iωC - ω²M) T q = Tᵀ F(f).

code_aster dualises the same relations with Lagrange multipliers, whose
right-hand side is zero unless an EXCIT CHARGE imposes values: the relations
are homogeneous here (the command refuses imposed values it cannot carry).
The reduced matrices share one sparsity pattern, computed once; each
frequency combines their values and factorises with SuperLU
(``scipy.sparse.linalg.splu``).
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import splu

from asterlite.fem.constraints import Elimination
from asterlite.harmonic.fields import TWO_PI, omega2
from asterlite.harmonic.modal import SingularSystem


@dataclass
class ReducedPencil:
    """Tᵀ K T, Tᵀ M T and Tᵀ C T on one CSC pattern (``indices``, ``indptr``),
    their values aligned on it."""

    n: int
    indices: np.ndarray
    indptr: np.ndarray
    stiffness: np.ndarray
    mass: np.ndarray
    damping: np.ndarray | None

    def at(self, frequency: float) -> sp.csc_matrix:
        """K + iωC - ω²M at one frequency (CSC, complex)."""
        data = self.stiffness - omega2(frequency) * self.mass
        if self.damping is not None:
            data = data + (1j * TWO_PI * frequency) * self.damping
        return sp.csc_matrix(
            (data.astype(complex, copy=False), self.indices, self.indptr), shape=(self.n, self.n)
        )


def aligned_pencil(stiffness, mass, damping) -> ReducedPencil:
    """The three reduced matrices on the union of their patterns."""
    mats = [sp.coo_matrix(m) for m in (stiffness, mass, damping) if m is not None]
    n = mats[0].shape[0]
    keys = [m.col.astype(np.int64) * n + m.row for m in mats]  # column-major keys
    pattern = np.unique(np.concatenate(keys))
    values = []
    for m, key in zip(mats, keys, strict=True):
        data = np.zeros(pattern.size, dtype=np.result_type(m.data.dtype, float))
        np.add.at(data, np.searchsorted(pattern, key), m.data)
        values.append(data)
    rows, cols = pattern % n, pattern // n
    indptr = np.zeros(n + 1, dtype=np.int64)
    np.cumsum(np.bincount(cols, minlength=n), out=indptr[1:])
    return ReducedPencil(
        n=n,
        indices=rows.astype(np.int32 if n < 2**31 else np.int64),
        indptr=indptr.astype(np.int32 if pattern.size < 2**31 else np.int64),
        stiffness=values[0],
        mass=values[1],
        damping=values[2] if damping is not None else None,
    )


@dataclass
class PhysicalSweep:
    """What a physical sweep needs: the elimination u = T q and the reduced
    pencil."""

    elimination: Elimination
    pencil: ReducedPencil

    @property
    def n_free(self) -> int:
        return self.pencil.n

    @property
    def n_dofs(self) -> int:
        return self.elimination.T.shape[0]

    def reduce(self, vectors: np.ndarray) -> np.ndarray:
        """Tᵀ F for vectors on the numbering's DOFs: (n_dofs[, k]) -> (n_free[, k])."""
        return self.elimination.T.T @ vectors


def prepare(elimination: Elimination, stiffness, mass, damping=None) -> PhysicalSweep:
    """Reduce the assembled matrices (n_dofs × n_dofs, sparse) once."""
    t = elimination.T

    def reduced(matrix):
        return None if matrix is None else sp.csr_matrix(t.T @ (sp.csr_matrix(matrix) @ t))

    return PhysicalSweep(
        elimination, aligned_pencil(reduced(stiffness), reduced(mass), reduced(damping))
    )


def solve(
    sweep: PhysicalSweep,
    frequencies,
    vectors: np.ndarray,
    coefficients: np.ndarray,
    progress=None,
) -> tuple[np.ndarray, dict]:
    """Amplitudes u (n_freq, n_dofs) on the numbering's DOFs.

    ``vectors`` (n_loads, n_dofs): the load vectors; ``coefficients``
    (n_freq, n_loads): their complex multipliers at each frequency.
    ``progress(k)`` is called after each frequency when given.
    """
    f = np.atleast_1d(np.asarray(frequencies, dtype=float))
    vectors = np.atleast_2d(np.asarray(vectors))
    reduced = sweep.reduce(vectors.T).T  # (n_loads, n_free)
    t_matrix = sweep.elimination.T
    out = np.empty((f.size, sweep.n_dofs), dtype=complex)
    started = time.perf_counter()
    for k, frequency in enumerate(f):
        rhs = coefficients[k] @ reduced
        try:
            lu = splu(sweep.pencil.at(float(frequency)))
        except RuntimeError:  # SuperLU: "Factor is exactly singular"
            raise SingularSystem(float(frequency)) from None
        q = lu.solve(np.ascontiguousarray(rhs, dtype=complex))
        if not np.all(np.isfinite(q)):
            raise SingularSystem(float(frequency))
        out[k] = t_matrix @ q
        if progress is not None:
            progress(k)
    info = {"seconds": time.perf_counter() - started, "n_free": sweep.n_free}
    return out, info
