"""Factorisation of an assembled matrix under its kinematic relations
(FACTORISER) and solves with it (RESOUDRE).

The relations of the matrix's numbering are eliminated (``u = T q + u0``,
:mod:`asterlite.fem.constraints`), the reduced matrix ``Tᵀ A T`` is factorised
once by a sparse direct method, and each solve gives the displacement with the
relations' imposed values. A pivot that loses more than ``NPREC`` digits
against its diagonal term marks the matrix singular, as code_aster's direct
solvers do (``STOP_SINGULIER='OUI'`` stops, ``'NON'`` only warns).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from cholespy import CholeskySolverD, MatrixType

from asterlite.fem.constraints import Elimination, eliminate

#: iterative refinement steps of the solve phase (POSTTRAITEMENTS)
REFINEMENT_STEPS = {"SANS": 0, "MINI": 1, "AUTO": 2, "FORCE": 10}


class FactorizationError(ValueError):
    """A matrix that cannot be factorised, or a solve that misses its accuracy."""


@dataclass(eq=False)
class Factorization:
    """The reduced matrix of an assembled matrix, factorised."""

    elimination: Elimination
    reduced: sp.csc_matrix
    lu: object  # scipy SuperLU
    lost_digits: float  # largest loss of digits over the pivots

    def solve_reduced(self, rhs: np.ndarray) -> np.ndarray:
        if self.lu is None:  # dropped when the session was saved
            self.lu = _superlu(self.reduced)
        return self.lu.solve(rhs)

    def __getstate__(self):
        # SuperLU objects cannot be pickled: keep the reduced matrix only
        state = dict(self.__dict__)
        state["lu"] = None
        return state


def _superlu(reduced: sp.csc_matrix):
    try:
        return spla.splu(
            reduced,
            permc_spec="MMD_AT_PLUS_A",
            diag_pivot_thresh=0.0,
            options={"SymmetricMode": True},
        )
    except RuntimeError:
        raise FactorizationError("the matrix is singular (exactly zero pivot)") from None


# relative asymmetry under which a matrix is taken as symmetric (rounding
# of assembled sums of symmetric element matrices)
SYMMETRY_TOLERANCE = 1.0e-12


def definite_solver(matrix) -> Callable[[np.ndarray], np.ndarray]:
    """A solve with the sparse matrix of an implicit scheme's step (K + a0 M
    + a1 C: symmetric, and positive definite when the mass is): CHOLMOD's
    supernodal Cholesky (through cholespy) where the matrix is symmetric and
    the factorisation finds it positive definite, a fraction of SuperLU's
    fill on 3D meshes (docs/performance.md, "Memory"); SuperLU otherwise."""
    if not sp.issparse(matrix) or matrix.format not in ("csr", "csc"):
        matrix = sp.csc_matrix(matrix)
    matrix.sum_duplicates()  # canonical: sorted indices, one entry per position
    scale = float(np.abs(matrix.data).max()) if matrix.nnz else 0.0
    if matrix.shape[0] and scale > 0.0 and _asymmetry(matrix) <= SYMMETRY_TOLERANCE * scale:
        try:
            # CHOLMOD reads the lower triangle only (its symmetric storage):
            # half a copy of the matrix beside its factor, not a whole one
            return _cholmod_solver(sp.tril(matrix, format="csc"))
        except ValueError:  # not positive definite: LU with pivoting
            pass
    return spla.splu(sp.csc_matrix(matrix)).solve


def _asymmetry(matrix: sp.csc_matrix) -> float:
    """max |A - Aᵀ|, with one temporary of the difference's size."""
    difference = matrix - matrix.T
    if not difference.nnz:
        return 0.0
    np.abs(difference.data, out=difference.data)
    return float(difference.data.max())


def _cholmod_solver(matrix: sp.csc_matrix) -> Callable[[np.ndarray], np.ndarray]:
    # the CSC arrays as they are (32-bit indices, float64): no COO copy of the
    # matrix is held beside CHOLMOD's own while it factorises
    matrix.sum_duplicates()
    factor = CholeskySolverD(
        matrix.shape[0],
        matrix.indptr.astype(np.int32, copy=False),
        matrix.indices.astype(np.int32, copy=False),
        matrix.data.astype(np.float64, copy=False),
        MatrixType.CSC,
    )

    def solve(rhs: np.ndarray) -> np.ndarray:
        rhs = np.ascontiguousarray(rhs, dtype=np.float64)
        out = np.zeros_like(rhs)
        factor.solve(rhs, out)
        return out

    return solve


def pivot_loss(lu, reduced: sp.csc_matrix) -> float:
    """Largest number of decimal digits lost by a pivot against the diagonal
    term of its column (symmetric ordering: U's diagonal follows perm_c)."""
    pivots = np.abs(lu.U.diagonal())
    diagonal = np.abs(reduced.diagonal()[lu.perm_c])
    scale = np.where(diagonal > 0.0, diagonal, 1.0)
    ratio = np.where(pivots > 0.0, pivots / scale, 0.0)
    smallest = float(ratio.min(initial=1.0))
    return np.inf if smallest <= 0.0 else max(0.0, -np.log10(smallest))


def factorize(matrix, numbering) -> Factorization:
    """Eliminate the numbering's relations and factorise the reduced matrix."""
    b_matrix, rhs = numbering.constraint_matrix()
    elimination = eliminate(b_matrix, np.zeros_like(rhs), numbering.n_dofs)
    reduced = sp.csc_matrix(elimination.reduce(matrix))
    if reduced.shape[0] == 0:
        raise FactorizationError("every DOF is imposed: nothing to factorise")
    lu = _superlu(reduced)
    return Factorization(elimination, reduced, lu, pivot_loss(lu, reduced))


def solve(
    factorization: Factorization,
    matrix,
    numbering,
    loads: np.ndarray,
    relation_rhs: np.ndarray,
    refinement: int = 0,
) -> tuple[np.ndarray, float]:
    """(u, relative residual) of ``A u = f + reactions`` with the relations'
    right-hand sides ``relation_rhs``; ``refinement`` steps of iterative
    refinement on the reduced system. Complex matrices and right-hand sides
    (a harmonic system) are solved as they are."""
    elim = factorization.elimination
    relation_rhs = np.asarray(relation_rhs)
    u0 = elim.particular(relation_rhs.real)
    if np.iscomplexobj(relation_rhs):
        u0 = u0 + 1j * elim.particular(relation_rhs.imag)
    loads = np.asarray(loads)
    b = np.asarray(elim.T.T @ (loads - matrix @ u0))
    q = factorization.solve_reduced(b)
    for _ in range(refinement):
        q = q + factorization.solve_reduced(b - factorization.reduced @ q)
    residual = b - factorization.reduced @ q
    norm_b = float(np.linalg.norm(b))
    relative = float(np.linalg.norm(residual)) / norm_b if norm_b > 0.0 else 0.0
    return u0 + elim.T @ q, relative
