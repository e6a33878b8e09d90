"""Sparse direct factorisation of a symmetric matrix, by the best library present.

Three back ends, chosen by size, by what is installed and by whether the
matrix is expected positive definite:

- ``mumps``: MUMPS (the solver code_aster uses), through ``python-mumps``
  (the ``large`` extra; it builds against Debian's ``libmumps-seq-dev``).
  Multifrontal LDLᵀ with threshold pivoting, so shifted pencils K - σM inside
  the spectrum (CENTRE, BANDE) factorise as well as positive ones; nested-
  dissection ordering (PORD: MUMPS_ORDERING) keeps the fill-in of 3D meshes low;
  blocks of right-hand sides are solved with BLAS 3. It also gives the
  inertia (the number of negative pivots).
- ``cholmod``: CHOLMOD's Cholesky through ``cholespy`` (a core dependency:
  wheels, no compiler). Positive definite matrices only (K - σM with σ below
  the spectrum: PLUS_PETITE, the common case); nested-dissection ordering,
  so its fill-in on 3D meshes is MUMPS's, but cholespy factorises
  column by column (simplicial), several times slower than MUMPS's fronts.
  A matrix that is not positive definite raises
  :class:`NotPositiveDefiniteError` and the caller falls back on SuperLU.
- ``superlu``: scipy's SuperLU, always present. Its fill-in grows fast on 3D
  meshes (the 98 172-DOF HEXA8 bar: 301 s and 10.9 GB for 50 modes), so it
  serves small models and indefinite shifts on machines without MUMPS.

``choose_backend`` picks MUMPS for matrices of at least ``LARGE_LIMIT``
unknowns when it imports, else CHOLMOD when the matrix should be positive
definite, SuperLU otherwise; ``ASTERLITE_SPARSE_SOLVER`` (``auto``,
``mumps``, ``cholmod``, ``superlu``) overrides the choice.
"""

from __future__ import annotations

import contextlib
import gc
import os
import shutil
import sys
import tempfile
from collections.abc import Callable

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from cholespy import CholeskySolverD, MatrixType

from asterlite import watchdog
from asterlite.fem import system_openblas

#: from this many unknowns on, a shift-invert eigen solve factorises with MUMPS
#: (when installed) and iterates with the block Lanczos method
LARGE_LIMIT = 4000
BACKENDS = ("mumps", "cholmod", "superlu")
#: relative residual ||A x - b|| / ||b|| of one solve above which a Cholesky
#: factor is taken as singular: a backward-stable solve leaves about
#: eps · cond(A), so this flags cond(A) beyond ~1e10, where MUMPS's null
#: pivot test (pivots below 1e-11 of the row sums) flags it
SINGULAR_RESIDUAL = 1e-6


class SingularFactorError(ValueError):
    """The matrix is singular (a zero pivot, or MUMPS's numerically singular)."""


class NotPositiveDefiniteError(ValueError):
    """CHOLMOD met a pivot that is not positive: the matrix is indefinite (or
    singular), a factorisation with pivoting is needed."""


def load_mumps():
    """python-mumps, loaded with the system OpenBLAS's kernels named from the
    CPU (system_openblas); ImportError when the ``large`` extra is missing.
    The kernels are chosen once, when the library loads: once loaded, the
    module is returned as it is (no reading of the CPU's features again)."""
    loaded = sys.modules.get("mumps")
    if loaded is not None:
        return loaded
    with system_openblas.named_core():
        import mumps
    return mumps


def mumps_available() -> bool:
    try:
        load_mumps()
    except ImportError:
        return False
    return True


def requested_backend() -> str:
    name = os.environ.get("ASTERLITE_SPARSE_SOLVER", "auto").strip().lower() or "auto"
    if name not in ("auto",) + BACKENDS:
        raise ValueError(f"ASTERLITE_SPARSE_SOLVER={name!r}: expected auto, " + ", ".join(BACKENDS))
    return name


def choose_backend(n: int, definite: bool = False) -> str:
    """The back end for a matrix of ``n`` unknowns; ``definite``: the caller
    expects it positive definite (K - σM with σ <= 0), so CHOLMOD may take it."""
    name = requested_backend()
    if name == "superlu":
        return "superlu"
    if name == "auto" and n < LARGE_LIMIT:
        return "superlu"
    if name in ("auto", "mumps") and mumps_available():
        return "mumps"
    return "cholmod" if definite else "superlu"


class SuperLUFactor:
    """scipy's SuperLU on a symmetric matrix (COLAMD ordering, as before)."""

    backend = "superlu"

    def __init__(self, matrix):
        try:
            self._lu = spla.splu(sp.csc_matrix(matrix))
        except RuntimeError as exc:
            raise SingularFactorError(str(exc)) from None
        self.n = matrix.shape[0]

    def solve(self, rhs: np.ndarray) -> np.ndarray:
        return self._lu.solve(np.asarray(rhs, dtype=float))

    @property
    def lu(self):
        return self._lu

    def close(self) -> None:
        self._lu = None

    negative_pivots = None


class MumpsFactor:
    """MUMPS LDLᵀ of a symmetric matrix (upper triangle handed over).

    ``null_pivot_threshold`` (relative to the matrix's largest row sum)
    turns MUMPS's null pivot detection on (ICNTL(24) = 1, CNTL(3)):
    ``null_pivots`` then counts the pivots below it, which mark a matrix
    singular to that precision.

    Memory, as code_aster's ``GESTION_MEMOIRE='AUTO'`` decides it: after the
    analysis, a factor whose in-core estimate (INFOG(17)) passes
    OUT_OF_CORE_SHARE of what the run may still add before its memory limit
    is written to disk (ICNTL(22) = 1, files in a folder of its own, removed
    when the factor is closed). The input triplets are released once
    factorised: the solves read only the factor (no iterative refinement,
    no error analysis: ICNTL(10) = ICNTL(11) = 0)."""

    backend = "mumps"

    def __init__(self, matrix, null_pivot_threshold: float | None = None):
        self._analyse(matrix, null_pivot_threshold)
        self._factorise(needs_out_of_core(self.in_core_bytes))

    @classmethod
    def out_of_core_if(cls, matrix, wanted: Callable[[int], bool]) -> MumpsFactor | None:
        """The factor of ``matrix`` out of core when ``wanted`` says so of its
        in-core estimate (bytes, after the analysis); None when it does not,
        or when MUMPS fails (the caller's other solver then says why)."""
        factor = cls.__new__(cls)
        try:
            factor._analyse(matrix, None)
            if not wanted(factor.in_core_bytes):
                factor.close()
                return None
            factor._factorise(True)
        except SingularFactorError:
            return None
        return factor

    def _analyse(self, matrix, null_pivot_threshold: float | None) -> None:
        mumps = load_mumps()

        self.n = matrix.shape[0]
        self.out_of_core = False
        self._folder = None
        self._threshold = null_pivot_threshold
        self._context = mumps.Context()
        _set_upper_triangle(self._context, matrix)
        instance = self._context.mumps_instance
        if null_pivot_threshold is not None:
            instance.icntl[24] = 1
            instance.cntl[3] = float(null_pivot_threshold)
        try:
            self._context.analyze(ordering=MUMPS_ORDERING)
        except mumps.MUMPSError as exc:
            self.close()
            raise SingularFactorError(f"MUMPS: {exc}") from None
        self.in_core_bytes = int(instance.infog[17]) * 1024**2

    def _factorise(self, out_of_core: bool) -> None:
        mumps = load_mumps()

        instance = self._context.mumps_instance
        try:
            if out_of_core:
                self._folder = _out_of_core_folder()
                self.out_of_core = True
            watchdog.trim_allocator()  # see MumpsPatternFactor.factorise
            self._context.factor(ooc=self.out_of_core, reuse_analysis=True)
        except mumps.MUMPSError as exc:
            self.close()
            # INFOG(1) = -10: numerically singular
            raise SingularFactorError(f"MUMPS: {exc}") from None
        # the solves need the values' type only
        self._context.row = self._context.col = None
        self._context.data = np.zeros(1, dtype=self._context.data.dtype)
        self.negative_pivots = int(instance.infog[12])
        self.null_pivots = int(instance.infog[28]) if self._threshold is not None else 0

    def solve(self, rhs: np.ndarray) -> np.ndarray:
        b = np.array(rhs, dtype=float, order="F", copy=True)
        return self._context.solve(b, overwrite_b=True)

    def close(self) -> None:
        """Free MUMPS's factor now. Only references are dropped: the wrapper's
        own deallocation terminates the instance (JOB = -2) once, which
        deletes an out-of-core factor's files.
        ``mumps.Context.__exit__`` must not be used: in python-mumps 0.0.4 it
        sets JOB on the Python object, not on the instance, so it repeats the
        last job, a solve into the right-hand side of the last call, long
        freed (heap corruption: forma12c crashed or got wrong modes)."""
        self._context = None
        if self._folder is not None:
            gc.collect()  # the instance, hence its files, goes with its last reference
            shutil.rmtree(self._folder, ignore_errors=True)
            self._folder = None


class MumpsPatternFactor:
    """MUMPS LDLᵀ of symmetric matrices (real or complex: symmetric, not
    Hermitian) that share one pattern, as a harmonic sweep's K + iωC - ω²M:
    the pattern (the upper triangle, CSC ``indptr``/``indices``) is analysed
    once (ordering, symbolic factorisation, and whether the factor goes out
    of core, as :class:`MumpsFactor` decides it), then each set of values is
    factorised on that analysis (JOB = 2) with MUMPS's threshold pivoting.
    MUMPS reads the values from the array it was handed, so each
    ``factorise`` copies the new values into it."""

    backend = "mumps"

    def __init__(self, n: int, indptr: np.ndarray, indices: np.ndarray, dtype=complex):
        mumps = load_mumps()
        _mumps = mumps.mumps._mumps

        int_dtype = _mumps.int_dtype
        self.n = n
        self.out_of_core = False
        self._folder = None
        self._context = mumps.Context()
        row = np.array(indices, dtype=int_dtype, order="F")  # a copy: the caller's stays 0-based
        row += 1
        col = np.repeat(np.arange(1, n + 1, dtype=int_dtype), np.diff(indptr))
        data = np.zeros(indices.size, dtype=dtype)
        # set_matrix only picks the arithmetic (zmumps, dmumps) and the symmetry
        self._context.set_matrix(
            sp.coo_matrix((np.zeros(1, dtype), ([0], [0])), shape=(n, n)), symmetric=True
        )
        self._context.row, self._context.col, self._context.data = row, np.asfortranarray(col), data
        self._context.mumps_instance.set_assembled_matrix(n, row, self._context.col, data)
        self._analysed = False
        self._mumps_error = mumps.MUMPSError

    @property
    def values(self) -> np.ndarray:
        """The array MUMPS reads the values from: a caller may write them
        there and call :meth:`analyse` or :meth:`factorise` without any."""
        return self._context.data

    def analyse(self, values: np.ndarray | None = None) -> int:
        """Order the pattern and plan the factorisation (MUMPS's JOB = 1,
        with these values for its scaling), and decide whether the factor goes
        out of core; returns MUMPS's estimate of the factor's entries
        (INFOG(20))."""
        if values is not None:
            self._context.data[:] = values
        try:
            self._context.analyze(ordering=MUMPS_ORDERING)
        except self._mumps_error as exc:
            raise SingularFactorError(f"MUMPS: {exc}") from None
        self._analysed = True
        instance = self._context.mumps_instance
        self.out_of_core = needs_out_of_core(int(instance.infog[17]) * 1024**2)
        self._folder = _out_of_core_folder() if self.out_of_core else None
        entries = int(instance.infog[20])
        return entries if entries >= 0 else -entries * 1_000_000  # < 0: millions

    def factorise(self, values: np.ndarray | None = None) -> None:
        """Factorise the matrix of these values (None: those already in
        :attr:`values`) on the pattern (analysed first if it was not);
        raises :class:`SingularFactorError` when MUMPS finds it singular."""
        if not self._analysed:
            self.analyse(values)
        if values is not None:
            self._context.data[:] = values
        # the allocator's free pages (the analysis's workspace, the values
        # built before) go back first: the factor's memory does not come on
        # top of them (47-71 MB at each factorisation of sdlv126h)
        watchdog.trim_allocator()
        try:
            self._context.factor(ooc=self.out_of_core, reuse_analysis=True)
        except self._mumps_error as exc:
            raise SingularFactorError(f"MUMPS: {exc}") from None

    def solve(self, rhs: np.ndarray) -> np.ndarray:
        b = np.array(rhs, dtype=self._context.data.dtype, order="F", copy=True)
        return self._context.solve(b, overwrite_b=True)

    close = MumpsFactor.close


#: MUMPS's fill-reducing ordering: PORD, a nested dissection of its own, run
#: to run the same. Debian's MUMPS has no METIS (code_aster's default) and its
#: "auto" choice, SCOTCH, draws random numbers: the same deck's modes moved
#: in their last digits from run to run. On a 3D solid's stiffness (37 125
#: unknowns) PORD's factor has 17.0 M entries against SCOTCH's 19.1 M (1.5
#: against 1.9 s), on sdlv126h's complex pencil 12.3 M against 13.8 M.
MUMPS_ORDERING = "pord"

#: a MUMPS factor goes out of core when its in-core estimate passes this
#: share of what the run may still add before its memory limit (the rest
#: serves the eigen solver's vectors and the commands after it)
OUT_OF_CORE_SHARE = 0.5


def needs_out_of_core(in_core_bytes: int) -> bool:
    """Whether a factor of ``in_core_bytes`` in core passes OUT_OF_CORE_SHARE
    of what the run may still add before its memory limit."""
    headroom = watchdog.memory_headroom()
    return headroom is not None and in_core_bytes > OUT_OF_CORE_SHARE * headroom


def _out_of_core_folder() -> str:
    """A folder of its own for an out-of-core factor's files, named to MUMPS."""
    folder = tempfile.mkdtemp(prefix="asterlite-mumps-")
    os.environ["MUMPS_OOC_TMPDIR"] = folder  # read by MUMPS at JOB = 2
    return folder


def _set_upper_triangle(context, matrix) -> None:
    """Hand MUMPS the upper triangle of the symmetric ``matrix`` (CSR or CSC,
    any other format converted) as 1-based int32 triplets, made once:
    python-mumps's ``set_matrix`` would copy the whole matrix three times."""
    int_dtype = load_mumps().mumps._mumps.int_dtype
    if not (sp.isspmatrix_csr(matrix) or sp.isspmatrix_csc(matrix)):
        matrix = sp.csr_matrix(matrix)
    counts = np.diff(matrix.indptr)
    outer = np.repeat(np.arange(matrix.shape[0], dtype=np.int32), counts)
    inner = matrix.indices.astype(np.int32, copy=False)
    # CSR rows are the outer index, CSC columns: upper means row <= column
    keep = inner >= outer if sp.isspmatrix_csr(matrix) else inner <= outer
    rows, cols = (outer, inner) if sp.isspmatrix_csr(matrix) else (inner, outer)
    row = np.asfortranarray(rows[keep], dtype=int_dtype)
    row += 1
    col = np.asfortranarray(cols[keep], dtype=int_dtype)
    col += 1
    data = np.asfortranarray(matrix.data[keep], dtype=np.float64)
    del keep
    context.set_matrix(sp.coo_matrix((np.zeros(1), ([0], [0])), shape=matrix.shape), symmetric=True)
    context.row, context.col, context.data = row, col, data
    context.mumps_instance.set_assembled_matrix(matrix.shape[0], row, col, data)


class CholmodFactor:
    """CHOLMOD's LLᵀ of a symmetric positive definite matrix (cholespy).

    Raises :class:`NotPositiveDefiniteError` when a pivot is not positive.
    A successful factorisation proves the matrix positive definite, so the
    inertia is known: no negative pivot."""

    backend = "cholmod"
    negative_pivots = 0

    def __init__(self, matrix):
        csc = sp.csc_matrix(matrix)
        self.n = csc.shape[0]
        try:
            # CHOLMOD prints a warning on an indefinite matrix before
            # cholespy raises: the caller decides what that means
            with _c_output_silenced():
                self._factor = CholeskySolverD(
                    self.n,
                    csc.indptr.astype(np.int32),
                    csc.indices.astype(np.int32),
                    csc.data.astype(np.float64),
                    MatrixType.CSC,
                )
        except ValueError as exc:
            raise NotPositiveDefiniteError(f"CHOLMOD: {exc}") from None

    def solve(self, rhs: np.ndarray) -> np.ndarray:
        b = np.ascontiguousarray(rhs, dtype=np.float64)
        x = np.empty_like(b)
        self._factor.solve(b, x)
        return x

    def nearly_singular(self, matrix) -> bool:
        """Whether one solve with ``matrix`` (the factorised one) leaves a
        relative residual above SINGULAR_RESIDUAL: a positive pivot that is
        round-off of a zero one (a free structure's K) passes CHOLMOD's
        test but gives solutions dominated by the null space."""
        b = np.random.default_rng(0).uniform(-1.0, 1.0, self.n)
        residual = matrix @ self.solve(b) - b
        return bool(np.linalg.norm(residual) > SINGULAR_RESIDUAL * np.linalg.norm(b))

    def close(self) -> None:
        self._factor = None


@contextlib.contextmanager
def _c_output_silenced():
    """File descriptors 1 and 2 sent to /dev/null for the block: CHOLMOD
    prints its warnings with C's printf, past sys.stdout."""
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(AttributeError, OSError, ValueError):
            stream.flush()
    try:
        saved = [os.dup(1), os.dup(2)]
    except OSError:  # no usable descriptors: nothing to silence
        yield
        return
    try:
        with open(os.devnull, "wb") as null:
            os.dup2(null.fileno(), 1)
            os.dup2(null.fileno(), 2)
        yield
    finally:
        for fd, copy in enumerate(saved, start=1):
            os.dup2(copy, fd)
            os.close(copy)


def factorize_symmetric(matrix, backend: str | None = None, **options):
    """A factor of the symmetric ``matrix`` with ``.solve(b)`` for a vector or a
    block of columns, ``.backend`` and ``.negative_pivots`` (the inertia: MUMPS's
    count, 0 for a CHOLMOD factor, None for SuperLU); ``options`` go to MUMPS."""
    name = backend or choose_backend(matrix.shape[0])
    if name == "mumps":
        return MumpsFactor(matrix, **options)  # CSR or CSC as given: no copy
    matrix = sp.csc_matrix(matrix)
    if name == "cholmod":
        return CholmodFactor(matrix)
    return SuperLUFactor(matrix)
