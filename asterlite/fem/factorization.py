"""Factorisation of an assembled matrix under its kinematic relations
(FACTORISER) and solves with it (RESOUDRE).

The relations of the matrix's numbering are eliminated (``u = T q + u0``,
:mod:`asterlite.fem.constraints`), the reduced matrix ``Tᵀ A T`` is factorised
once by a sparse direct method, and each solve gives the displacement with the
relations' imposed values. A real symmetric matrix of LARGE_LIMIT unknowns
or more is factorised by MUMPS (out of core past its share of the memory
limit), any other by SuperLU. A pivot that loses more than ``NPREC`` digits
against its diagonal term (SuperLU), or that is below 10^-NPREC of the
largest row sum (MUMPS's null pivots), marks the matrix singular, as
code_aster's direct solvers do (``STOP_SINGULIER='OUI'`` stops, ``'NON'``
only warns).
"""

from __future__ import annotations

import weakref
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from cholespy import CholeskySolverD, MatrixType

from asterlite import watchdog
from asterlite.fem import sparse_direct
from asterlite.fem.constraints import Elimination, eliminate
from asterlite.fem.sparse_direct import (
    LARGE_LIMIT,
    MumpsFactor,
    SingularFactorError,
    choose_backend,
)

#: iterative refinement steps of the solve phase (POSTTRAITEMENTS)
REFINEMENT_STEPS = {"SANS": 0, "MINI": 1, "AUTO": 2, "FORCE": 10}


class FactorizationError(ValueError):
    """A matrix that cannot be factorised, or a solve that misses its accuracy."""


@dataclass(eq=False)
class Factorization:
    """The reduced matrix of an assembled matrix, factorised: by SuperLU
    (``lost_digits``: the largest loss of digits over its pivots), or, for
    a real symmetric one of LARGE_LIMIT unknowns or more, by MUMPS
    (``null_pivots``: its pivots below 10^-``digits`` of the largest row
    sum, code_aster's test with MUMPS; ``lost_digits`` is then NaN)."""

    elimination: Elimination
    reduced: sp.csc_matrix
    lu: object  # scipy SuperLU or sparse_direct.MumpsFactor
    lost_digits: float
    null_pivots: int | None = None
    digits: int = 8

    def solve_reduced(self, rhs: np.ndarray) -> np.ndarray:
        if self.lu is None:  # dropped when the session was saved
            self.lu = _factor(self.reduced, self.digits)
            _closed_with(self, self.lu)
        return self.lu.solve(rhs)

    def __getstate__(self):
        # SuperLU and MUMPS factors cannot be pickled: keep the reduced matrix only
        state = dict(self.__dict__)
        state["lu"] = None
        return state


def _closed_with(owner, factor) -> None:
    """A MUMPS factor is closed (an out-of-core one's files removed) when
    its owner goes."""
    if isinstance(factor, MumpsFactor):
        weakref.finalize(owner, factor.close)


def _factor(reduced: sp.csc_matrix, digits: int):
    """MUMPS's factor of a real symmetric ``reduced`` of LARGE_LIMIT unknowns
    or more (out of core past its share of the memory limit), SuperLU's
    otherwise."""
    if not np.iscomplexobj(reduced.data) and _multifrontal(reduced.shape[0]):
        lower = _symmetric_lower(_canonical(reduced))
        if lower is not None:
            try:
                threshold = 10.0**-digits if digits >= 0 else None  # NPREC < 0: no test
                factor = MumpsFactor(lower.T, null_pivot_threshold=threshold)
            except SingularFactorError:
                raise FactorizationError("the matrix is singular (MUMPS)") from None
            return factor
    return _superlu(reduced)


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
    + a1 C: symmetric, and positive definite when the mass is). Where the
    matrix is symmetric: MUMPS's LDLᵀ, out of core, when its factor in core
    would pass what is left before half the memory limit
    (:func:`_out_of_core_solver`), else
    CHOLMOD's Cholesky (through cholespy) when the factorisation finds it
    positive definite, either a fraction of SuperLU's fill on 3D meshes
    (docs/performance.md, "Memory"); SuperLU otherwise.

    ``matrix``: the matrix, or a function building it. Given a function,
    nothing holds the whole matrix while CHOLMOD factorises: only its lower
    triangle, all CHOLMOD reads, is kept (the matrix is built again only
    when it is not positive definite and SuperLU needs it whole)."""
    build = matrix if callable(matrix) else None
    if build is not None:
        matrix = build()
    matrix = _canonical(matrix)
    lower = _symmetric_lower(matrix)
    if lower is not None:
        if build is not None:
            del matrix  # the caller holds no reference: its memory goes to the factor
        try:
            solve = _out_of_core_solver(lower)
            return solve if solve is not None else _cholmod_solver(lower)
        except (ValueError, SingularFactorError):  # LU with pivoting
            del lower
            if build is not None:
                matrix = _canonical(build())
    return spla.splu(sp.csc_matrix(matrix)).solve


def _multifrontal(n: int) -> bool:
    """Whether MUMPS may take a matrix of ``n`` unknowns: from
    sparse_direct's LARGE_LIMIT unknowns on, where it is installed (and
    ASTERLITE_SPARSE_SOLVER does not ask for another back end)."""
    return n >= LARGE_LIMIT and choose_backend(n) == "mumps"


def _out_of_core_solver(lower: sp.csc_matrix) -> Callable[[np.ndarray], np.ndarray] | None:
    """MUMPS's LDLᵀ of a step matrix, its factor out of core, when MUMPS may
    take it and its analysis finds the factor, in core, past what is left
    before half the run's memory limit (the memory a run should keep to)
    or past sparse_direct's share of the headroom; None otherwise: CHOLMOD
    then factorises it in core. In core, CHOLMOD's factor has about as many
    entries as MUMPS's (PORD) and solves 1.5 to 2 times faster (sdlv127e's
    step matrix: 14.9 M entries against 17.2 M, 25 ms a solve against 36–46
    ms; a beam's 6 000 unknowns: 0.13 ms against 1.7 ms)."""
    headroom, limit_mb = watchdog.memory_headroom(), watchdog.memory_limit_mb()
    if not _multifrontal(lower.shape[0]) or headroom is None or limit_mb is None:
        return None
    below_half = headroom - limit_mb * 2**20 / 2

    def wanted(in_core_bytes: int) -> bool:
        return in_core_bytes > below_half or sparse_direct.needs_out_of_core(in_core_bytes)

    # the CSC arrays of the lower triangle read as CSR: the upper triangle
    factor = MumpsFactor.out_of_core_if(lower.T, wanted)
    if factor is None:
        return None

    def solve(rhs: np.ndarray) -> np.ndarray:
        return factor.solve(rhs)

    # the factor and its files go when the scheme lets the solve go
    weakref.finalize(solve, factor.close)
    return solve


def _canonical(matrix):
    if not sp.issparse(matrix) or matrix.format not in ("csr", "csc"):
        matrix = sp.csc_matrix(matrix)
    matrix.sum_duplicates()  # canonical: sorted indices, one entry per position
    return matrix


def _symmetric_lower(matrix) -> sp.csc_matrix | None:
    """The lower triangle of a canonical CSR or CSC matrix, in CSC, when
    the matrix is symmetric (max |A - Aᵀ| within SYMMETRY_TOLERANCE of its
    largest entry), else None. The triangles are masks on the matrix's own
    arrays, and the upper one read the other way round (CSR as CSC, or the
    reverse) is the transpose the lower one is compared with: the test
    holds no transposed copy of the whole matrix, only its halves."""
    n = matrix.shape[0]
    scale = float(np.abs(matrix.data).max()) if matrix.nnz else 0.0
    if not n or scale <= 0.0:
        return None
    by_rows = matrix.format == "csr"
    # the row (CSR) or column (CSC) of each stored entry
    major = np.repeat(np.arange(n, dtype=matrix.indices.dtype), np.diff(matrix.indptr))
    # lower triangle of CSR: column <= row; of CSC: row >= column (and the reverse)
    lower_test, upper_test = (
        (np.less_equal, np.greater_equal) if by_rows else (np.greater_equal, np.less_equal)
    )
    mask = lower_test(matrix.indices, major)
    lower = _masked(matrix, mask)
    upper_test(matrix.indices, major, out=mask)
    del major
    upper = _masked(matrix, mask)  # diagonals in both: they cancel in the difference
    del mask
    other = sp.csc_matrix if by_rows else sp.csr_matrix
    mirrored = other((upper.data, upper.indices, upper.indptr), shape=matrix.shape)
    del upper
    lower = lower.tocsc() if by_rows else lower
    # tril(A) - triu(A)ᵀ: A - Aᵀ below the diagonal (above it, its opposite)
    difference = lower - mirrored
    del mirrored
    asymmetry = float(np.abs(difference.data).max()) if difference.nnz else 0.0
    del difference
    return lower if asymmetry <= SYMMETRY_TOLERANCE * scale else None


def _masked(matrix, keep: np.ndarray):
    """The entries of a CSR or CSC matrix where ``keep``, in its format."""
    before = np.zeros(keep.size + 1, dtype=matrix.indptr.dtype)
    np.cumsum(keep, out=before[1:])  # kept entries before each position
    kind = sp.csr_matrix if matrix.format == "csr" else sp.csc_matrix
    return kind(
        (matrix.data[keep], matrix.indices[keep], before[matrix.indptr]), shape=matrix.shape
    )


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


def factorize(matrix, numbering, digits: int = 8) -> Factorization:
    """Eliminate the numbering's relations and factorise the reduced matrix;
    ``digits``: NPREC, MUMPS's null pivot threshold 10^-digits."""
    b_matrix, rhs = numbering.constraint_matrix()
    elimination = eliminate(b_matrix, np.zeros_like(rhs), numbering.n_dofs)
    reduced = sp.csc_matrix(elimination.reduce(matrix))
    if reduced.shape[0] == 0:
        raise FactorizationError("every DOF is imposed: nothing to factorise")
    lu = _factor(reduced, digits)
    if isinstance(lu, MumpsFactor):
        result = Factorization(elimination, reduced, lu, np.nan, lu.null_pivots, digits)
        _closed_with(result, lu)
        return result
    return Factorization(elimination, reduced, lu, pivot_loss(lu, reduced), None, digits)


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
