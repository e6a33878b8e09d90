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
ordering is the least-fill of reverse Cuthill-McKee, SuperLU's minimum
degree on AᵀA + A and COLAMD orderings (read without a complete LU) and
METIS's nested dissection); symmetric matrices are kept as their upper
triangles (:mod:`asterlite.harmonic.pencil`); its
solution is accepted when its backward error is that of a stable solve,
after one step of iterative refinement if needed, else that frequency (and
non-symmetric matrices, e.g. gyroscopic damping) is factorised by SuperLU
with partial pivoting (``scipy.sparse.linalg.splu``). Symmetric systems of
``sparse_direct.LARGE_LIMIT`` unknowns and more go to MUMPS where it is
installed (``sparse_direct.choose_backend``, as the modal solves) when its
analysis plans a factor of ``MUMPS_MIN_MEAN_COLUMN`` entries a column or
more: its fronts with threshold pivoting factorise 3D models several times
faster than the column-by-column LDLᵀ, with the pattern analysed once, and
out of core when the factor would crowd the run's memory limit.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from scipy.sparse.csgraph import reverse_cuthill_mckee
from scipy.sparse.linalg import spilu, splu

from asterlite.fem import sparse_direct
from asterlite.fem.constraints import Elimination
from asterlite.harmonic import ldl
from asterlite.harmonic.fields import TWO_PI, omega2
from asterlite.harmonic.modal import SingularSystem
from asterlite.harmonic.pencil import (
    ReducedPencil,
    aligned_pencil,
    aligned_triangles,
    selected_dofs,
    selected_upper,
)

# backward error |A x - b| / (|A| |x| + |b|) (max norms) a solution must reach
BACKWARD_TOLERANCE = 1.0e-13
# smaller systems go to SuperLU directly: loading the LDLT kernels and
# choosing an ordering (~0.2 s) would cost more than the sweep
LDL_MIN_SIZE = 1000
# MUMPS factorises a sweep whose factor holds on average this many entries a
# column or more (its estimate at the analysis), the LDLᵀ one of sparser
# factors: per frequency, 20 000-DOF beam line (2 a column) LDLᵀ 7.6 ms
# against MUMPS 30 ms, plate-like grid of beams (43) 414 against 297 ms,
# HEXA20 solid of 26 700 unknowns (about 500) 7.5 against 4.3 s
# (2026-11-29, single-threaded OpenBLAS, load 3)
MUMPS_MIN_MEAN_COLUMN = 16
# LDLᵀ fill (factor terms) past which SuperLU's partial-pivoting LU is not
# timed against it: its fill on 3D solid meshes is many times LDLᵀ's
SUPERLU_MAX_FILL = 2_000_000


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
    # "mumps" (symmetric, large, MUMPS installed), else "ldl": the LDLᵀ above
    backend: str = "ldl"
    mumps: sparse_direct.MumpsPatternFactor | None = None

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
    """Reduce the assembled matrices (n_dofs × n_dofs, sparse) once; symmetric
    ones are kept as their upper triangles.

    When T only selects DOFs (constraints that fix them, the usual case),
    the upper triangles of A[kept][:, kept] are read from each matrix by
    blocks of rows, with its symmetry checked on them: no reduced nor
    transposed whole copy, and no matrix on disk whole in memory."""
    given = (stiffness, mass, damping)
    n = elimination.T.shape[1]
    kept = selected_dofs(elimination.T) if n >= LDL_MIN_SIZE else None
    if kept is not None:
        triangles = []
        for matrix in given:  # each read once, by blocks of rows
            upper = None if matrix is None else selected_upper(matrix, kept, 1e-13)
            if matrix is not None and upper is None:  # not symmetric (or not canonical)
                break
            triangles.append(upper)
        else:
            pencil = aligned_triangles(*triangles, owned=True)
            del triangles
            return PhysicalSweep(elimination, pencil, True, backend=_backend(n))
        del triangles
    t = elimination.T

    def reduced(matrix):
        return None if matrix is None else sp.csr_matrix(t.T @ (sp.csr_matrix(matrix) @ t))

    matrices = [reduced(m) for m in given]
    symmetric = all(m is None or ldl.is_symmetric(m, 1e-13) for m in matrices)
    upper = symmetric and n >= LDL_MIN_SIZE
    backend = _backend(n) if upper else "ldl"
    return PhysicalSweep(
        elimination, aligned_pencil(*matrices, upper=upper), symmetric, backend=backend
    )


def _backend(n: int) -> str:
    """MUMPS for a symmetric pencil of n unknowns where it is chosen, else the LDLᵀ."""
    return "mumps" if sparse_direct.choose_backend(n) == "mumps" else "ldl"


def _column_ordering(pattern: sp.csr_matrix, spec: str) -> np.ndarray | None:
    """SuperLU's column ordering ``spec`` of a symmetric pattern, read from an
    incomplete factorisation that drops nearly every term: the ordering is
    computed from the pattern before any elimination, so the ILU runs on a
    real, diagonally dominant matrix of that pattern (degree + 1 on the
    diagonal, -1 elsewhere: no vanishing pivot, half the memory of the
    complex values), in a fraction of a second where a complete LU of a 3D
    solid model takes minutes."""
    dominant = sp.csr_matrix(pattern, dtype=float)
    dominant.data[:] = -1.0
    dominant.setdiag(np.diff(dominant.indptr) + 1.0)
    try:
        lu = spilu(
            dominant.tocsc(),
            drop_tol=0.9,
            fill_factor=1.0,
            permc_spec=spec,
            diag_pivot_thresh=0.0,
            options={"SymmetricMode": True},
        )
    except RuntimeError:
        return None
    return np.argsort(lu.perm_c)


def nested_dissection(indptr, indices, n: int) -> np.ndarray | None:
    """METIS's nested-dissection ordering (``pymetis``) of a symmetric CSC
    pattern, the order code_aster's MUMPS takes on 3D meshes; None without
    pymetis or on a pattern with no off-diagonal term."""
    try:
        import pymetis
    except ImportError:
        return None
    index_type = np.int32 if indices.size < 2**31 else np.int64
    columns = np.repeat(np.arange(n, dtype=index_type), np.diff(indptr))
    off_diagonal = indices != columns
    if not off_diagonal.any():
        return None
    starts = np.zeros(n + 1, dtype=index_type)
    np.cumsum(np.bincount(columns[off_diagonal], minlength=n), out=starts[1:])
    del columns
    adjacent = np.asarray(indices[off_diagonal], dtype=index_type)
    permutation, _ = pymetis.nested_dissection(pymetis.CSRAdjacency(starts, adjacent))
    return np.frombuffer(permutation, dtype=np.int64).copy()


def ordering(sweep: PhysicalSweep, frequency: float) -> ldl.Analysis:
    """The LDLᵀ analysis of the pencil's pattern under the fill-reducing
    ordering of least fill among reverse Cuthill-McKee (banded models: beam
    lines), SuperLU's minimum degree on AᵀA + A and its COLAMD column order,
    and METIS's nested dissection (taken only where it fills strictly less;
    on the 3D HEXA20 model of sdlv126h COLAMD fills 2 % less and factorises
    in half the time). SuperLU's complete factorisation is timed against
    LDLᵀ at the first frequency when the fill is small enough for it to
    compete; past ``SUPERLU_MAX_FILL`` LDLᵀ factorises every frequency."""

    pencil = sweep.pencil
    counts = np.diff(pencil.indptr)
    known = _known_ordering(pencil.upper, counts)
    if known is not None:
        # the same model solved again (its values changed, and with them a
        # few terms that cancel exactly): the ordering that the first solve
        # chose, and its timings, instead of trying every ordering again
        permutation, sweep.timings = known[0], dict(known[1])
        ldl.warm()
        return ldl.analyse(
            pencil.indptr, pencil.indices, pencil.n, permutation, None, upper=pencil.upper
        )
    pattern = pencil.full_pattern()
    candidates = [np.asarray(reverse_cuthill_mckee(pattern, symmetric_mode=True))]
    for spec in ("MMD_AT_PLUS_A", "COLAMD"):
        permutation = _column_ordering(pattern, spec)
        if permutation is not None:
            candidates.append(permutation)
    dissection = nested_dissection(pattern.indptr, pattern.indices, pencil.n)
    if dissection is not None:
        candidates.append(dissection)
    del pattern
    sweep.timings = {}
    ldl.warm()
    best = None
    for permutation in candidates:
        limit = None if best is None else best.fill
        found = ldl.analyse(
            pencil.indptr, pencil.indices, pencil.n, permutation, limit, upper=pencil.upper
        )
        if found is not None and (best is None or found.fill < best.fill):
            best = found
    if best is not None and best.fill <= SUPERLU_MAX_FILL:
        try:
            started = time.perf_counter()  # the factorisation the fallback makes
            splu(pencil.at(frequency))
            sweep.timings["superlu"] = time.perf_counter() - started
        except RuntimeError:
            pass
    if best is not None:
        _KNOWN_ORDERINGS.append((pencil.upper, counts, best.perm.copy(), dict(sweep.timings)))
        del _KNOWN_ORDERINGS[:-KNOWN_ORDERINGS]
    return best


#: how many patterns keep the ordering chosen for them: a deck that solves
#: the same model again (a loop over materials, load cases or single
#: frequencies) skips trying every ordering
KNOWN_ORDERINGS = 4
#: a pattern is that of a known model when its terms per column differ by
#: at most this share of its terms, or this many (terms whose values cancel
#: exactly are not stored, and which do depends on the values)
SAME_PATTERN_SHARE = 1.0e-4
SAME_PATTERN_TERMS = 16
_KNOWN_ORDERINGS: list[tuple[bool, np.ndarray, np.ndarray, dict]] = []


def _known_ordering(upper: bool, counts: np.ndarray):
    """(permutation, timings) chosen for a pattern of the same model, or None."""
    for known_upper, known_counts, permutation, timings in reversed(_KNOWN_ORDERINGS):
        if known_upper != upper or known_counts.size != counts.size:
            continue
        changed = np.abs(known_counts - counts).sum()
        if changed <= max(SAME_PATTERN_TERMS, SAME_PATTERN_SHARE * int(counts.sum())):
            return permutation, timings
    return None


def _backward_error(residual, x, b, norm) -> float:
    scale = norm * np.abs(x).max() + np.abs(b).max()
    return float(np.abs(residual).max() / scale) if scale > 0 else 0.0


def _solve_one(
    sweep: PhysicalSweep, frequency: float, rhs: np.ndarray, counts: dict, last: bool = False
):
    """One frequency: MUMPS or LDLᵀ (checked, refined once), else SuperLU.
    At the ``last`` frequency the pencil's K, M, C are dropped once the
    values of K + iωC - ω²M are built: nothing reads them afterwards."""
    if sweep.backend == "mumps" and sweep.mumps is None:
        _start_mumps(sweep, frequency)
    if sweep.backend == "ldl" and sweep.use_ldl and sweep.analysis is None:
        sweep.analysis = ordering(sweep, frequency)
        if sweep.pencil.upper:
            # the pencil in the factor's order: each frequency's values are
            # the factorisation's input as built
            a = sweep.analysis
            sweep.pencil = sweep.pencil.in_order(a.perm, a.upper_ptr, a.upper_idx, a.source)
            a.source = None
    pencil = sweep.pencil
    norm = pencil.norm_bound(frequency)
    # MUMPS's values are built in its own input array (MUMPS only reads it)
    into = sweep.mumps.values if sweep.backend == "mumps" else None
    data = pencil.data(frequency, out=into)
    if last:
        pencil.release_values()
    if sweep.backend == "mumps":
        factor = sweep.mumps
        stops = last
        try:
            try:
                factor.factorise()
            except sparse_direct.SingularFactorError:
                stops = True  # the sweep ends here: its factor and folder go
                raise SingularSystem(float(frequency)) from None
            x = _stable_solution(factor.solve, pencil, frequency, data, rhs, norm, counts)
        finally:
            if stops:
                factor.close()
                sweep.mumps = None
        if x is not None:
            counts["mumps"] += 1
            counts["out_of_core"] += factor.out_of_core
            return x
    elif sweep.use_ldl:
        try:
            started = time.perf_counter()
            factor = ldl.factorise(sweep.analysis, data)
            if "ldl" not in sweep.timings:
                sweep.timings["ldl"] = time.perf_counter() - started
            x = _stable_solution(factor.solve, pencil, frequency, data, rhs, norm, counts)
            if x is not None:
                counts["ldl"] += 1
                return x
        except ldl.ZeroPivot:
            pass
        factor = None  # the SuperLU fallback needs its memory
    return _solve_superlu(pencil, frequency, data, rhs, counts)


def _start_mumps(sweep: PhysicalSweep, frequency: float) -> None:
    """MUMPS's analysis of the sweep's pattern (with the first frequency's
    values); a factor of small fronts (a line of beams) goes back to the
    LDLᵀ, whose column loop is faster there."""
    pencil = sweep.pencil
    factor = sparse_direct.MumpsPatternFactor(pencil.n, pencil.indptr, pencil.indices)
    try:
        entries = factor.analyse(pencil.data(frequency, out=factor.values))
    except sparse_direct.SingularFactorError:
        entries = 0  # the LDLᵀ path then finds the singular frequency
    if entries < MUMPS_MIN_MEAN_COLUMN * pencil.n:
        factor.close()
        sweep.backend = "ldl"
    else:
        sweep.mumps = factor


def _stable_solution(solve, pencil, frequency, data, rhs, norm, counts):
    """``solve(rhs)``, refined once when its backward error is not that of a
    stable solve; None when it still is not."""
    x = solve(rhs)
    residual = rhs - pencil.product(frequency, x, data)
    if _backward_error(residual, x, rhs, norm) <= BACKWARD_TOLERANCE:
        return x
    x = x + solve(residual)
    counts["refined"] += 1
    residual = rhs - pencil.product(frequency, x, data)
    return x if _backward_error(residual, x, rhs, norm) <= BACKWARD_TOLERANCE else None


def _solve_superlu(pencil, frequency: float, data: np.ndarray, rhs: np.ndarray, counts: dict):
    """SuperLU's LU with partial pivoting of the pencil's values ``data``."""
    try:
        lu = splu(pencil.at(frequency, data))
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
    counts = {"ldl": 0, "mumps": 0, "out_of_core": 0, "refined": 0, "superlu": 0}
    for k, frequency in enumerate(f):
        rhs = np.ascontiguousarray(coefficients[k] @ reduced)
        if per_frequency is not None:
            rhs = rhs + sweep.reduce(np.asarray(per_frequency[k], dtype=complex))
        q = _solve_one(sweep, float(frequency), rhs, counts, last=k == f.size - 1)
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
