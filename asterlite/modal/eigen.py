"""Generalized eigenproblem K φ = ω² M φ on the constrained space.

The relations of the numbering are eliminated (``asterlite.fem.constraints``)
and the reduced pencil (Tᵀ K T, Tᵀ M T) is solved:

- small problems (``n <= DENSE_LIMIT``) densely, through a Cholesky factor
  of K - σM so that a singular mass (massless DOFs) is harmless;
- larger ones with ARPACK in shift-invert mode (``scipy.sparse.linalg.eigsh``),
  so only K - σM is factorised and the matrices stay sparse.

Selections mirror CALC_MODES: the smallest / largest n, the n nearest a
frequency (CENTRE), one mode nearest each given frequency (PROCHE), every
mode in a band (BANDE) or all modes (TOUT). Frequencies are returned sorted.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from asterlite.fem.constraints import Elimination

DENSE_LIMIT = 400
TWO_PI = 2.0 * np.pi


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
    vals, vecs = spla.eigsh(k, k=count, M=m, sigma=sigma, which="LM", OPinv=op_inv)
    return vals, vecs


class ReducedPencil:
    """(Tᵀ K T, Tᵀ M T) with the helpers CALC_MODES selections need."""

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
        # (ω², shapes) -> shapes: the basis inside groups of equal eigenvalues,
        # for a method that decides it (None: the solver's own)
        self.equal_eigenvalue_basis = None
        self._all = None

    @property
    def dense(self) -> bool:
        return self.n <= DENSE_LIMIT

    def all_modes(self):
        if self._all is None:
            if self.n == 0:
                self._all = (np.zeros(0), np.zeros((0, 0)))
            else:
                sigma = _default_shift(self.k, self.m)
                vals, vecs = _dense_pencil(self.k, self.m, sigma)
                order = np.argsort(vals)
                self._all = self._settled(vals[order], vecs[:, order])
        return self._all

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
        vals, vecs = _shift_invert(self.k, self.m, sigma, count)
        order = np.argsort(np.abs(vals - sigma), kind="stable")
        return self._settled(vals[order], vecs[:, order])

    def smallest(self, count: int):
        if self.dense or count >= self.n - 1:
            vals, vecs = self.all_modes()
            return vals[:count], vecs[:, :count]
        sigma, lu = _smallest_shift(self.k, self.m)
        vals, vecs = _shift_invert(self.k, self.m, sigma, count, lu)
        order = np.argsort(vals, kind="stable")
        return self._settled(vals[order], vecs[:, order])

    def largest(self, count: int):
        if self.dense or count >= self.n - 1:
            vals, vecs = self.all_modes()
            return vals[-count:], vecs[:, -count:]
        # ARPACK regular mode needs an invertible M
        try:
            lu = spla.splu(self.m.tocsc())
        except RuntimeError:
            raise EigenError("PLUS_GRANDE on a large model needs a non-singular mass") from None
        minv = spla.LinearOperator(self.m.shape, matvec=lu.solve, dtype=float)
        return self._settled(*spla.eigsh(self.k, k=count, M=self.m, Minv=minv, which="LA"))

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

    def expand(self, vecs: np.ndarray) -> np.ndarray:
        return np.asarray(self.elimination.T @ vecs)


def sort_modes(omega2: np.ndarray, vecs: np.ndarray):
    order = np.argsort(omega2, kind="stable")
    return omega2[order], vecs[:, order]
