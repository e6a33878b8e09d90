"""Generalized eigenproblem K φ = ω² M φ on the constrained space.

The relations of the numbering are eliminated (``asterlite.fem.constraints``)
and the reduced pencil (Tᵀ K T, Tᵀ M T) is solved:

- small problems (``n <= DENSE_LIMIT``) densely, through a Cholesky factor
  of K - σM so that a singular mass (massless DOFs) is harmless;
- larger ones with ARPACK in shift-invert mode (``scipy.sparse.linalg.eigsh``),
  so only K - σM is factorised (SuperLU) and the matrices stay sparse;
- large ones (``asterlite.fem.sparse_direct.LARGE_LIMIT`` unknowns and more)
  factorise K - σM with MUMPS when it is installed (the ``large`` extra),
  else with CHOLMOD when K - σM should be positive definite (σ <= 0), and
  iterate with the block Lanczos method (``asterlite.modal.block_lanczos``),
  which solves blocks of right-hand sides at once; ARPACK on the same factor
  takes over if the Lanczos basis would grow past its bound. Without MUMPS,
  the modes nearest a shift inside the spectrum (CENTRE, BANDE) come from the
  lowest modes up, on CHOLMOD's factor of K, while at most
  ``BOTTOM_UP_LIMIT`` modes lie below them; beyond, or when K is indefinite,
  SuperLU and ARPACK factorise K - σM as smaller models do.

Selections mirror CALC_MODES: the smallest / largest n, the n nearest a
frequency (CENTRE), one mode nearest each given frequency (PROCHE), every
mode in a band (BANDE) or all modes (TOUT). Frequencies are returned sorted.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from asterlite.fem import sparse_direct
from asterlite.fem.constraints import Elimination
from asterlite.modal import block_lanczos, slepc_mpi

DENSE_LIMIT = 400
#: without MUMPS, the modes nearest a positive shift of a large model are
#: computed from the lowest up on CHOLMOD's factor of K while they are among
#: this many lowest modes (the Lanczos basis holds about 5 vectors per mode,
#: and its small eigen problem grows with it)
BOTTOM_UP_LIMIT = 128
TWO_PI = 2.0 * np.pi
# matrices whose largest entry lies outside [2**-SAFE_EXPONENT, 2**SAFE_EXPONENT]
# are scaled by a power of two before solving: a stiffness of 1e-310 (a
# denormal) against a unit mass overflows L⁻¹ M L⁻ᵀ to inf
SAFE_EXPONENT = 100


class EigenError(ValueError):
    """The pencil cannot be solved as asked (singular, too few modes...)."""


def omega2_from_freq(freq):
    f = np.asarray(freq, dtype=float)
    return np.sign(f) * (TWO_PI * f) ** 2


def freq_from_omega2(omega2):
    w2 = np.asarray(omega2, dtype=float)
    return np.sign(w2) * np.sqrt(np.abs(w2)) / TWO_PI


@dataclass
class EigenSolution:
    omega2: np.ndarray  # (n_modes,)
    shapes: np.ndarray  # (n_dofs, n_modes) on the full numbering

    @property
    def frequencies(self) -> np.ndarray:
        return freq_from_omega2(self.omega2)


def _default_shift(k: sp.spmatrix, m: sp.spmatrix, factor: float = 1e-4) -> float:
    """A small negative shift: below every eigenvalue of a positive pencil, so
    rigid-body modes do not make K - σM singular."""
    kd, md = k.diagonal(), m.diagonal()
    ok = (kd > 0) & (md > 0)
    scale = np.median(kd[ok] / md[ok]) if np.any(ok) else 1.0
    return -factor * scale


def _smallest_shift(k: sp.spmatrix, m: sp.spmatrix):
    """(σ, LU of K - σM) for the lowest modes: σ = 0 when K is safely
    invertible (fastest convergence: the low spectrum is well separated after
    inversion), else a tiny negative shift that steps over rigid-body modes."""
    try:
        lu = spla.splu(k.tocsc())
        pivots = np.abs(lu.U.diagonal())
        if pivots.min() > 1e-11 * pivots.max():
            return 0.0, lu
    except RuntimeError:
        pass
    sigma = _default_shift(k, m, 1e-8)
    try:
        return sigma, spla.splu((k - sigma * m).tocsc())
    except RuntimeError as exc:
        raise EigenError(f"K - σM is singular at σ = {sigma:g} ({exc})") from None


def _dense_pencil(k, m, sigma):
    """All finite eigenpairs of (k, m) via the Cholesky factor of k - σm."""
    kd = k.toarray() if sp.issparse(k) else np.asarray(k)
    md = m.toarray() if sp.issparse(m) else np.asarray(m)
    shifted = kd - sigma * md
    try:
        chol = sla.cholesky(0.5 * (shifted + shifted.T), lower=True)
    except sla.LinAlgError:
        # indefinite stiffness: fall back on the general solver
        vals, vecs = sla.eig(kd, md)
        finite = np.isfinite(vals) & (np.abs(vals.imag) <= 1e-8 * (1 + np.abs(vals.real)))
        return vals.real[finite], vecs.real[:, finite]
    # M φ = μ (K - σM) φ  with  μ = 1 / (λ - σ): symmetric in ψ = Lᵀ φ
    c = sla.solve_triangular(chol, md, lower=True)
    c = sla.solve_triangular(chol, c.T, lower=True)
    mu, psi = sla.eigh(0.5 * (c + c.T))
    keep = mu > 1e-12 * max(mu.max(initial=0.0), 1e-300)
    mu, psi = mu[keep], psi[:, keep]
    phi = sla.solve_triangular(chol.T, psi, lower=False)
    return sigma + 1.0 / mu, phi


def start_vector(n: int) -> np.ndarray:
    """ARPACK's starting vector, the same on every run: without one, scipy
    draws it from fresh entropy and the modes differ from run to run within
    the solver's tolerance (code_aster's ARPACK seeds its generator with
    fixed values too)."""
    return np.random.default_rng(0).uniform(-1.0, 1.0, n)


def _shift_invert(k, m, sigma: float, count: int, lu=None):
    """``count`` eigenpairs nearest σ with ARPACK shift-invert."""
    n = k.shape[0]
    count = min(count, n - 1)
    if count <= 0:
        return np.zeros(0), np.zeros((n, 0))
    if lu is None:
        try:
            lu = spla.splu((k - sigma * m).tocsc())
        except RuntimeError as exc:
            raise EigenError(f"K - σM is singular at σ = {sigma:g} ({exc})") from None
    op_inv = spla.LinearOperator((n, n), matvec=lu.solve, dtype=float)
    vals, vecs = spla.eigsh(
        k, k=count, M=m, sigma=sigma, which="LM", OPinv=op_inv, v0=start_vector(n)
    )
    return vals, vecs


def _large_factor(k, m, sigma: float, backend: str):
    """MUMPS or CHOLMOD factor of K - σM (sparse_direct), or an EigenError
    (CHOLMOD's NotPositiveDefiniteError passes through: the caller falls
    back on SuperLU)."""
    try:
        return sparse_direct.factorize_symmetric(k - sigma * m, backend=backend)
    except sparse_direct.SingularFactorError as exc:
        raise EigenError(f"K - σM is singular at σ = {sigma:g} ({exc})") from None


def _large_smallest_shift(k, m, backend: str):
    """(σ, factor of K - σM) for the lowest modes, as ``_smallest_shift``
    decides: σ = 0 when K factorises and is not numerically singular (K
    itself, not a rounded K - σM: the lowest eigenvalues keep every digit),
    else a tiny negative shift over the rigid-body modes. MUMPS tells a
    singular K by its null pivots (below 1e-11 of the scale), CHOLMOD by a
    non-positive pivot or by the residual of one solve."""
    try:
        if backend == "mumps":
            factor = sparse_direct.factorize_symmetric(
                k, backend="mumps", null_pivot_threshold=1e-11
            )
            singular = factor.null_pivots > 0
        else:
            factor = sparse_direct.factorize_symmetric(k, backend="cholmod")
            singular = factor.nearly_singular(k)
        if not singular:
            return 0.0, factor
        factor.close()
    except (sparse_direct.SingularFactorError, sparse_direct.NotPositiveDefiniteError):
        pass
    sigma = _default_shift(k, m, 1e-8)
    return sigma, _large_factor(k, m, sigma, backend)


def _large_shift_invert(
    k,
    m,
    sigma: float,
    count: int,
    factor=None,
    factor_seconds=0.0,
    backend: str = "mumps",
    keep_factor: bool = False,
):
    """``count`` eigenpairs nearest σ: block Lanczos on a MUMPS or CHOLMOD
    factor of K - σM (``factor``, else one made with ``backend``), ARPACK on
    the same factor when the Lanczos basis reaches its bound. Returns
    (values, vectors, how: a dict for the log, with the wall seconds of the
    factorisation and of the iterations)."""
    n = k.shape[0]
    count = min(count, n - 1)
    if count <= 0:
        return np.zeros(0), np.zeros((n, 0)), {}
    if factor is None:
        start = time.perf_counter()
        factor = _large_factor(k, m, sigma, backend)
        factor_seconds = time.perf_counter() - start
    start = time.perf_counter()
    try:
        vals, vecs, stats = block_lanczos.shift_invert_lanczos(m, factor.solve, sigma, count)
        how = {"method": "block Lanczos", **stats}
    except block_lanczos.LanczosNotConverged:
        op_inv = spla.LinearOperator((n, n), matvec=factor.solve, dtype=float)
        vals, vecs = spla.eigsh(
            k, k=count, M=m, sigma=sigma, which="LM", OPinv=op_inv, v0=start_vector(n)
        )
        how = {"method": "ARPACK"}
    how.update(
        backend=factor.backend,
        factor_seconds=factor_seconds,
        iteration_seconds=time.perf_counter() - start,
    )
    if not keep_factor:
        factor.close()
    return vals, vecs, how


def _large_inertia(shifted, backend: str):
    """The number of negative eigenvalues of the symmetric ``shifted`` from a
    MUMPS or CHOLMOD factor: MUMPS's count of negative pivots, 0 when
    CHOLMOD factorises it (positive definite); None when it is singular,
    False when CHOLMOD finds it indefinite (SuperLU must count)."""
    try:
        factor = sparse_direct.factorize_symmetric(shifted, backend=backend)
    except sparse_direct.SingularFactorError:
        return None
    except sparse_direct.NotPositiveDefiniteError:
        return False
    count = factor.negative_pivots
    factor.close()
    return count


def _scale_exponent(matrix) -> int:
    """0, or the exponent e of a power of two 2**e bringing the matrix's
    largest entry near 1 when it is far from it."""
    data = matrix.data if sp.issparse(matrix) else np.asarray(matrix)
    largest = float(np.max(np.abs(data), initial=0.0))
    if largest == 0.0 or not np.isfinite(largest):
        return 0
    exponent = int(np.frexp(largest)[1])
    return 0 if -SAFE_EXPONENT <= exponent <= SAFE_EXPONENT else exponent


def _scaled(matrix, exponent: int):
    """``matrix / 2**exponent``, exactly (ldexp: 2**1030 itself would overflow)."""
    if exponent == 0:
        return matrix
    if sp.issparse(matrix):
        scaled = matrix.copy()
        scaled.data = np.ldexp(scaled.data, -exponent)
        return scaled
    return np.ldexp(np.asarray(matrix), -exponent)


class ReducedPencil:
    """(Tᵀ K T, Tᵀ M T) with the helpers CALC_MODES selections need.

    The solvers see ``k / 2**a`` and ``m / 2**b`` (exact, and a = b = 0 for
    any ordinary model), whose eigenvalues are ``ω² / 2**(a - b)``;
    eigenvalues come back in ω², vectors as the solver gives them (their
    scale is arbitrary)."""

    def __init__(self, stiffness, mass, elimination: Elimination):
        self.elimination = elimination
        k_full, m_full = sp.csr_matrix(stiffness), sp.csr_matrix(mass)
        # diagonals on the full numbering: where code_aster's JACOBI starts from
        self.full_diagonals = (k_full.diagonal(), m_full.diagonal())
        self.k = elimination.reduce(k_full)
        self.m = elimination.reduce(m_full)
        self.k = 0.5 * (self.k + self.k.T)
        self.m = 0.5 * (self.m + self.m.T)
        self.n = self.k.shape[0]
        k_exponent, m_exponent = _scale_exponent(self.k), _scale_exponent(self.m)
        self._solver_k = _scaled(self.k, k_exponent)
        self._solver_m = _scaled(self.m, m_exponent)
        self._omega2_exponent = k_exponent - m_exponent  # ω² = solver's eigenvalue * 2**this
        # (ω², shapes) -> shapes: the basis inside groups of equal eigenvalues,
        # for a method that decides it (None: the solver's own)
        self.equal_eigenvalue_basis = None
        self._all = None
        # how the last sparse solve went (method, factorisation back end, ...)
        self.last_solve: dict = {}
        # (σ, CHOLMOD factor of K - σM, its seconds) for the modes nearest
        # positive shifts without MUMPS; False once K proved indefinite
        self._lowest_factor = None

    @property
    def dense(self) -> bool:
        return self.n <= DENSE_LIMIT

    def sparse_backend(self, sigma: float) -> str:
        """The factorisation of K - σM (σ in ω²) a sparse solve uses:
        sparse_direct decides by size, by what is installed and by whether
        K - σM should be positive definite (σ <= 0)."""
        return sparse_direct.choose_backend(self.n, definite=sigma <= 0.0)

    def all_modes(self):
        if self._all is None:
            if self.n == 0:
                self._all = (np.zeros(0), np.zeros((0, 0)))
            else:
                k, m = self._solver_k, self._solver_m
                vals, vecs = _dense_pencil(k, m, _default_shift(k, m))
                vals = self._omega2(vals)
                order = np.argsort(vals)
                self._all = self._settled(vals[order], vecs[:, order])
        return self._all

    def _omega2(self, solver_values):
        """The solver's eigenvalues in ω²."""
        if self._omega2_exponent == 0:
            return solver_values
        return np.ldexp(np.asarray(solver_values, dtype=float), self._omega2_exponent)

    def _solver_shift(self, omega2: float) -> float:
        return float(np.ldexp(omega2, -self._omega2_exponent))

    def _settled(self, vals, vecs):
        """(ω², shapes) with the basis rule applied to groups of equal ω²."""
        if self.equal_eigenvalue_basis is None or len(vals) < 2:
            return vals, vecs
        return vals, self.equal_eigenvalue_basis(vals, vecs)

    def nearest(self, sigma: float, count: int):
        """``count`` eigenpairs nearest σ (ω² units), sorted by distance."""
        if self.dense or count >= self.n - 1:
            vals, vecs = self.all_modes()
            order = np.argsort(np.abs(vals - sigma), kind="stable")[:count]
            return vals[order], vecs[:, order]
        k, m = self._solver_k, self._solver_m
        shift = self._solver_shift(sigma)
        if slepc_mpi.launcher() is not None:
            vals, vecs = self._mpi_nearest(shift, count)
            order = np.argsort(np.abs(vals - sigma), kind="stable")
            return self._settled(vals[order], vecs[:, order])
        backend = self.sparse_backend(sigma)
        self.last_solve = {}
        if backend != "superlu":
            try:
                vals, vecs, self.last_solve = _large_shift_invert(
                    k, m, shift, count, backend=backend
                )
            except sparse_direct.NotPositiveDefiniteError:
                backend = "superlu"  # K itself is indefinite (a prestressed K)
        if backend == "superlu" and self._bottom_up_possible():
            found = self._nearest_from_lowest(shift, count)
            if found is not None:
                vals, vecs, self.last_solve = found
                backend = "cholmod"
        if backend == "superlu":
            vals, vecs = _shift_invert(k, m, shift, count)
        vals = self._omega2(vals)
        order = np.argsort(np.abs(vals - sigma), kind="stable")
        return self._settled(vals[order], vecs[:, order])

    def _mpi_nearest(self, shift: float, count: int):
        """(ω², vectors) of the ``count`` eigenpairs nearest the solver's
        ``shift`` from the PETSc/SLEPc worker across MPI ranks."""
        try:
            vals, vecs, self.last_solve = slepc_mpi.nearest(
                self._solver_k, self._solver_m, shift, min(count, self.n - 1)
            )
        except slepc_mpi.MpiSolveError as exc:
            raise EigenError(str(exc)) from None
        return self._omega2(vals), vecs

    def _bottom_up_possible(self) -> bool:
        """A large model without MUMPS, whose K CHOLMOD may factorise."""
        return (
            self._lowest_factor is not False
            and sparse_direct.choose_backend(self.n, definite=True) == "cholmod"
        )

    def _nearest_from_lowest(self, shift: float, count: int):
        """(values, vectors, how) of the ``count`` eigenpairs nearest the
        solver's ``shift``, found among the lowest modes: the block Lanczos
        method on one CHOLMOD factor of K (kept for the next calls of this
        pencil, BANDE's growing counts) asks for twice as many lowest modes
        until the highest found lies beyond the farthest of the ``count``
        nearest, so that no mode nearer the shift is left out. None when K is
        indefinite or more than BOTTOM_UP_LIMIT modes would be needed."""
        k, m = self._solver_k, self._solver_m
        if self._lowest_factor is None:
            start = time.perf_counter()
            try:
                sigma, factor = _large_smallest_shift(k, m, "cholmod")
            except sparse_direct.NotPositiveDefiniteError:
                self._lowest_factor = False
                return None
            self._lowest_factor = (sigma, factor, time.perf_counter() - start)
        bound = min(BOTTOM_UP_LIMIT, self.n - 1)
        if count > bound:
            return None
        sigma, factor, seconds = self._lowest_factor
        wanted = count
        while True:
            vals, vecs, how = _large_shift_invert(
                k, m, sigma, wanted, factor, seconds, keep_factor=True
            )
            seconds = 0.0  # the factorisation is counted once
            order = np.argsort(np.abs(vals - shift), kind="stable")[:count]
            farthest = float(np.abs(vals[order[-1]] - shift))
            if vals.max() >= shift + farthest or wanted >= self.n - 1:
                how["method"] = f"block Lanczos ({wanted} lowest modes)"
                return vals[order], vecs[:, order], how
            if wanted >= bound:
                return None
            wanted = min(2 * wanted, bound)

    def smallest(self, count: int):
        if self.dense or count >= self.n - 1:
            vals, vecs = self.all_modes()
            return vals[:count], vecs[:, :count]
        k, m = self._solver_k, self._solver_m
        if slepc_mpi.launcher() is not None:
            # a tiny negative shift steps over rigid-body modes, as on one machine
            vals, vecs = self._mpi_nearest(_default_shift(k, m, 1e-8), count)
            order = np.argsort(vals, kind="stable")
            return self._settled(vals[order], vecs[:, order])
        backend = self.sparse_backend(0.0)
        self.last_solve = {}
        if backend != "superlu":
            start = time.perf_counter()
            try:
                sigma, factor = _large_smallest_shift(k, m, backend)
                vals, vecs, self.last_solve = _large_shift_invert(
                    k, m, sigma, count, factor, time.perf_counter() - start
                )
            except sparse_direct.NotPositiveDefiniteError:
                backend = "superlu"  # K is indefinite (a prestressed K)
        if backend == "superlu":
            sigma, lu = _smallest_shift(k, m)
            vals, vecs = _shift_invert(k, m, sigma, count, lu)
        vals = self._omega2(vals)
        order = np.argsort(vals, kind="stable")
        return self._settled(vals[order], vecs[:, order])

    def largest(self, count: int):
        if self.dense or count >= self.n - 1:
            vals, vecs = self.all_modes()
            return vals[-count:], vecs[:, -count:]
        if slepc_mpi.launcher() is not None:
            raise EigenError(
                "PLUS_GRANDE is not computed by the MPI solver (asterlite run --mpi): "
                "run without --mpi"
            )
        # ARPACK regular mode needs an invertible M
        k, m = self._solver_k, self._solver_m
        try:
            lu = spla.splu(m.tocsc())
        except RuntimeError:
            raise EigenError("PLUS_GRANDE on a large model needs a non-singular mass") from None
        minv = spla.LinearOperator(m.shape, matvec=lu.solve, dtype=float)
        vals, vecs = spla.eigsh(k, k=count, M=m, Minv=minv, which="LA", v0=start_vector(self.n))
        return self._settled(self._omega2(vals), vecs)

    def band(self, lower: float, upper: float, limit: int | None = None):
        """Every eigenpair with lower <= ω² <= upper (ω² units)."""
        if self.dense:
            vals, vecs = self.all_modes()
            keep = (vals >= lower) & (vals <= upper)
            return vals[keep], vecs[:, keep]
        centre = 0.5 * (lower + upper)
        radius = 0.5 * (upper - lower)
        count = 12
        while True:
            vals, vecs = self.nearest(centre, count)
            if np.max(np.abs(vals - centre), initial=0.0) > radius or count >= self.n - 1:
                break
            if limit is not None and count > limit + 12:
                break
            count = min(2 * count, self.n - 1)
        keep = (vals >= lower) & (vals <= upper)
        return vals[keep], vecs[:, keep]

    def count_below(self, omega2: float) -> int | None:
        """How many eigenvalues lie below ω² (the Sturm count code_aster
        numbers modes with), or None when it cannot be read: the inertia of
        K - ω² M (Sylvester's law) from a factorisation that pivots on the
        diagonal only, so that its U is D Lᵀ."""
        if self.dense:
            return int(np.count_nonzero(self.all_modes()[0] < omega2))
        shifted = self._solver_k - self._solver_shift(omega2) * self._solver_m
        backend = self.sparse_backend(omega2)
        if backend != "superlu":  # a large model: not SuperLU's fill-in
            count = _large_inertia(shifted, backend)
            if count is not False:
                return count
        try:
            lu = spla.splu(
                shifted.tocsc(),
                permc_spec="MMD_AT_PLUS_A",
                diag_pivot_thresh=0.0,
                options={"SymmetricMode": True},
            )
        except RuntimeError:  # singular: ω² is an eigenvalue
            return None
        if not np.array_equal(lu.perm_r, lu.perm_c):  # an off-diagonal pivot was taken
            return None
        return int(np.count_nonzero(lu.U.diagonal() < 0.0))

    def expand(self, vecs: np.ndarray) -> np.ndarray:
        return np.asarray(self.elimination.T @ vecs)


def sort_modes(omega2: np.ndarray, vecs: np.ndarray):
    order = np.argsort(omega2, kind="stable")
    return omega2[order], vecs[:, order]
