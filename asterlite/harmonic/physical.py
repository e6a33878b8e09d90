"""Harmonic solve on assembled physical matrices: one sparse complex
factorisation per frequency.

The kinematic relations B u = 0 of the numbering (DDL_IMPO, LIAISON_DDL of
the loads given to the matrices) are eliminated as for the real problems
(``asterlite.fem.constraints``): u = T q, and at each frequency

    Tᵀ (K + iωC - ω²M) T q = Tᵀ F(f).

code_aster dualises the same relations with Lagrange multipliers, whose
right-hand side is zero unless an EXCIT CHARGE imposes values: the relations
are homogeneous here, the values an EXCIT CHARGE imposes (constant or
functions of FREQ) being lifted into the right-hand side by the command.
The reduced matrices share one sparsity pattern, computed once; each
frequency combines their values and factorises them. Symmetric matrices
(the usual K, M, C) use a sparse LDLᵀ whose ordering and symbolic analysis
are done once for the sweep (:mod:`asterlite.harmonic.ldl`: the fill-reducing
ordering is the least-fill of reverse Cuthill-McKee and SuperLU's minimum
degree on AᵀA + A and COLAMD orderings, read without a complete LU); its
solution is accepted when its backward error is that of a stable solve,
after one step of iterative refinement if needed, else that frequency (and
non-symmetric matrices, e.g. gyroscopic damping) is factorised by SuperLU
with partial pivoting (``scipy.sparse.linalg.splu``).
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from scipy.sparse.csgraph import reverse_cuthill_mckee
from scipy.sparse.linalg import spilu, splu

from asterlite.fem.constraints import Elimination
from asterlite.harmonic import ldl
from asterlite.harmonic.fields import TWO_PI, omega2
from asterlite.harmonic.modal import SingularSystem

# backward error |A x - b| / (|A| |x| + |b|) (max norms) a solution must reach
BACKWARD_TOLERANCE = 1.0e-13
# smaller systems go to SuperLU directly: loading the LDLT kernels and
# choosing an ordering (~0.2 s) would cost more than the sweep
LDL_MIN_SIZE = 1000
# LDLᵀ fill (factor terms) past which SuperLU's partial-pivoting LU is not
# timed against it: its fill on 3D solid meshes is many times LDLᵀ's
SUPERLU_MAX_FILL = 2_000_000


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
    _norms: tuple | None = None

    def data(self, frequency: float) -> np.ndarray:
        """The values of K + iωC - ω²M on the pattern."""
        data = self.stiffness - omega2(frequency) * self.mass
        if self.damping is not None:
            data = data + (1j * TWO_PI * frequency) * self.damping
        return data.astype(complex, copy=False)

    def norm_bound(self, frequency: float) -> float:
        """|K| + ω²|M| + ω|C| ≥ |K + iωC - ω²M| (max column sums)."""
        if self._norms is None:

            def column_norm(values):
                sums = np.add.reduceat(np.abs(values), self.indptr[:-1]) if values.size else [0]
                return float(np.max(sums))

            self._norms = tuple(
                column_norm(v) if v is not None else 0.0
                for v in (self.stiffness, self.mass, self.damping)
            )
        k, m, c = self._norms
        w = TWO_PI * abs(frequency)
        return k + w * w * m + w * c

    def at(self, frequency: float) -> sp.csc_matrix:
        """K + iωC - ω²M at one frequency (CSC, complex)."""
        return sp.csc_matrix(
            (self.data(frequency), self.indices, self.indptr), shape=(self.n, self.n)
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
    """What a physical sweep needs: the elimination u = T q, the reduced
    pencil and, for symmetric matrices, the LDLᵀ analysis of its pattern
    (made at the first frequency solved)."""

    elimination: Elimination
    pencil: ReducedPencil
    symmetric: bool = False
    analysis: ldl.Analysis | None = None
    # seconds of one factorisation by each method, measured at the first
    # frequency: the faster one factorises the others
    timings: dict | None = None

    @property
    def use_ldl(self) -> bool:
        if not self.symmetric or self.pencil.n < LDL_MIN_SIZE:
            return False
        if not self.timings or "ldl" not in self.timings:
            return True
        return self.timings["ldl"] <= self.timings.get("superlu", np.inf)

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

    matrices = [reduced(stiffness), reduced(mass), reduced(damping)]
    symmetric = all(m is None or ldl.is_symmetric(m, 1e-13) for m in matrices)
    return PhysicalSweep(elimination, aligned_pencil(*matrices), symmetric)


def _column_ordering(matrix, spec: str) -> np.ndarray | None:
    """SuperLU's column ordering ``spec`` of the matrix's pattern, read from
    an incomplete factorisation that drops nearly every term: the ordering
    is computed before any elimination, and the ILU costs a fraction of a
    second where a complete LU of a 3D solid model takes minutes."""
    try:
        lu = spilu(
            matrix,
            drop_tol=0.9,
            fill_factor=1.0,
            permc_spec=spec,
            diag_pivot_thresh=0.0,
            options={"SymmetricMode": True},
        )
    except RuntimeError:
        return None
    return np.argsort(lu.perm_c)


def ordering(sweep: PhysicalSweep, frequency: float) -> ldl.Analysis:
    """The LDLᵀ analysis of the pencil's pattern under the fill-reducing
    ordering of least fill: reverse Cuthill-McKee (banded models: beam
    lines), SuperLU's minimum degree on AᵀA + A or its COLAMD column order
    (two- and three-dimensional meshes). SuperLU's complete factorisation is
    timed against LDLᵀ at the first frequency when the fill is small enough
    for it to compete; past ``SUPERLU_MAX_FILL`` LDLᵀ factorises every
    frequency."""

    pencil = sweep.pencil
    pattern = sp.csr_matrix(
        (np.ones(pencil.indices.size), pencil.indices, pencil.indptr), shape=(pencil.n, pencil.n)
    )
    candidates = [np.asarray(reverse_cuthill_mckee(pattern, symmetric_mode=True))]
    sweep.timings = {}
    ldl.warm()
    matrix = pencil.at(frequency)
    for spec in ("MMD_AT_PLUS_A", "COLAMD"):
        permutation = _column_ordering(matrix, spec)
        if permutation is not None:
            candidates.append(permutation)
    best = None
    for permutation in candidates:
        limit = None if best is None else best.fill
        found = ldl.analyse(pencil.indptr, pencil.indices, pencil.n, permutation, limit)
        if found is not None and (best is None or found.fill < best.fill):
            best = found
    if best is not None and best.fill <= SUPERLU_MAX_FILL:
        try:
            started = time.perf_counter()  # the factorisation the fallback makes
            splu(matrix)
            sweep.timings["superlu"] = time.perf_counter() - started
        except RuntimeError:
            pass
    return best


def _backward_error(matrix, x, b, norm) -> float:
    residual = matrix @ x - b
    scale = norm * np.abs(x).max() + np.abs(b).max()
    return float(np.abs(residual).max() / scale) if scale > 0 else 0.0


def _solve_one(sweep: PhysicalSweep, frequency: float, rhs: np.ndarray, counts: dict):
    """One frequency: LDLᵀ (checked, refined once) or SuperLU."""
    pencil = sweep.pencil
    matrix = pencil.at(frequency)
    if sweep.use_ldl:
        first = sweep.analysis is None
        if first:
            sweep.analysis = ordering(sweep, frequency)
        norm = pencil.norm_bound(frequency)
        try:
            started = time.perf_counter()
            factor = ldl.factorise(sweep.analysis, matrix.data)
            if first:
                sweep.timings["ldl"] = time.perf_counter() - started
            x = factor.solve(rhs)
            if _backward_error(matrix, x, rhs, norm) > BACKWARD_TOLERANCE:
                x = x + factor.solve(rhs - matrix @ x)
                counts["refined"] += 1
                if _backward_error(matrix, x, rhs, norm) > BACKWARD_TOLERANCE:
                    raise ldl.ZeroPivot(-1)  # not a stable solve: pivot
            counts["ldl"] += 1
            return x
        except ldl.ZeroPivot:
            pass
    try:
        lu = splu(matrix)
    except RuntimeError:  # SuperLU: "Factor is exactly singular"
        raise SingularSystem(float(frequency)) from None
    counts["superlu"] += 1
    return lu.solve(rhs)


def solve(
    sweep: PhysicalSweep,
    frequencies,
    vectors: np.ndarray,
    coefficients: np.ndarray,
    progress=None,
    per_frequency: np.ndarray | None = None,
) -> tuple[np.ndarray, dict]:
    """Amplitudes u (n_freq, n_dofs) on the numbering's DOFs.

    ``vectors`` (n_loads, n_dofs): the load vectors; ``coefficients``
    (n_freq, n_loads): their complex multipliers at each frequency;
    ``per_frequency`` (n_freq, n_dofs): forces added at each frequency.
    ``progress(k)`` is called after each frequency when given.
    """
    f = np.atleast_1d(np.asarray(frequencies, dtype=float))
    vectors = np.atleast_2d(np.asarray(vectors))
    # complex and contiguous once: each frequency's product is then a plain gemv
    reduced = np.ascontiguousarray(sweep.reduce(vectors.T).T, dtype=complex)
    coefficients = np.asarray(coefficients, dtype=complex)
    t_matrix = sweep.elimination.T
    out = np.empty((f.size, sweep.n_dofs), dtype=complex)
    started = time.perf_counter()
    counts = {"ldl": 0, "refined": 0, "superlu": 0}
    for k, frequency in enumerate(f):
        rhs = np.ascontiguousarray(coefficients[k] @ reduced)
        if per_frequency is not None:
            rhs = rhs + sweep.reduce(np.asarray(per_frequency[k], dtype=complex))
        q = _solve_one(sweep, float(frequency), rhs, counts)
        if not np.all(np.isfinite(q)):
            raise SingularSystem(float(frequency))
        out[k] = t_matrix @ q
        if progress is not None:
            progress(k)
    info = {"seconds": time.perf_counter() - started, "n_free": sweep.n_free, **counts}
    if sweep.analysis is not None:
        info["fill"] = sweep.analysis.fill
        info["timings"] = dict(sweep.timings or {})
    return out, info


def constraint_reactions(
    rows: np.ndarray, depl: np.ndarray, forces: np.ndarray, frequencies, stiffness, mass, damping
) -> np.ndarray:
    """F - (K + iωC - ω²M) u on the DOFs ``rows`` (n_freq, n_rows): the
    reactions of the constraints acting there, which code_aster's dualised
    solve holds in its Lagrange multipliers (asterlite.fem.lagrange_layout).
    ``forces`` (n_freq, n_rows) are the loads applied on those DOFs; the
    coefficients follow comdlh's dynamic matrix (-omega2(f), iω)."""
    f = np.asarray(frequencies, dtype=float)
    states = np.asarray(depl).T  # (n_dofs, n_freq)
    response = (sp.csr_matrix(stiffness)[rows] @ states).T
    response = response - omega2(f)[:, None] * (sp.csr_matrix(mass)[rows] @ states).T
    if damping is not None:
        velocity = (sp.csr_matrix(damping)[rows] @ states).T
        response = response + (1j * TWO_PI * f)[:, None] * velocity
    return np.asarray(forces) - response
