"""Quadratic eigenproblem (λ² M + λ C + K) φ = 0: damped (complex) modes.

CALC_MODES with MATR_AMOR and/or a complex stiffness (RIGI_MECA_HYST,
K (1 + iη)). The numbering's relations are eliminated as for real modes
(u = T q) and the reduced problem is linearised on z = [φ; λφ]:

    [ 0   I ] z = λ [ I  0 ] z
    [-K  -C ]       [ 0  M ]

- small problems are solved densely (``scipy.linalg.eig`` on the pencil);
  a singular mass only adds infinite eigenvalues, which are dropped;
- larger ones by ARPACK (``eigs``) in shift-invert mode on the linearised
  pencil: (A - σB)⁻¹ B needs only the factorisation of the n × n dynamic
  matrix Q(σ) = σ² M + σ C + K.

code_aster's conventions (R5.01.02, CALC_MODES):

- the shift of a frequency f with reduced damping a (CALC_FREQ/AMOR_REDUIT)
  is σ = 2πf (-a / √(1 - a²) + i); CENTRE keeps the modes nearest σ in the
  complex plane, PLUS_PETITE those nearest 0, PLUS_GRANDE the farthest;
- only eigenvalues with a positive imaginary part are kept (for real
  matrices the other member of each conjugate pair carries nothing new);
- modes are presented by increasing Im(λ);
- FREQ = Im(λ) / 2π (the damped frequency), OMEGA2 = Im(λ)², AMOR_REDUIT
  = -Re(λ) / |λ|;
- MASS_GENE = Re(φᴴ M φ), AMOR_GENE = Re(φᴴ C φ) and RIGI_GENE = Re(φᵀ K φ)
  (code_aster's generalized parameters of complex vectors: the stiffness
  one uses the plain transpose);
- NORM_MODE MASS_GENE makes φᵀ (2λ M + C) φ = 1 and RIGI_GENE
  φᵀ (λ² M - K) φ = 1 (the norms of the linearised pencil), EUCL the
  Hermitian norm 1 and the largest-component norms the largest modulus 1.

APPROCHE (REEL / IMAG / COMPLEXE) only chooses, in code_aster, which real or
complex operator ARPACK iterates on; the eigenpairs do not depend on it, so
its catalogue marks it as changing no result.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from asterlite.fem.constraints import Elimination

DENSE_LIMIT = 400
TWO_PI = 2.0 * np.pi
# relative size of Im(λ) below which an eigenvalue counts as real
IMAG_TOL = 1e-10


class QuadraticError(ValueError):
    """The quadratic problem cannot be solved as asked."""


def _dense(matrix) -> np.ndarray:
    return matrix.toarray() if sp.issparse(matrix) else np.asarray(matrix)


def linearize(k, c, m) -> tuple[np.ndarray, np.ndarray]:
    """Dense (A, B) of the first-order pencil A z = λ B z, z = [φ; λφ]."""
    kd, cd, md = _dense(k), _dense(c), _dense(m)
    n = kd.shape[0]
    dtype = np.result_type(kd, cd, md, float)
    eye, zero = np.eye(n, dtype=dtype), np.zeros((n, n), dtype=dtype)
    a = np.block([[zero, eye], [-kd, -cd]])
    b = np.block([[eye, zero], [zero, md]])
    return a, b


def dense_eigenpairs(k, c, m) -> tuple[np.ndarray, np.ndarray]:
    """Every finite eigenpair (λ, φ) of the quadratic problem.

    A singular mass gives infinite eigenvalues whose vectors are z = [0; v]
    (M v = 0): they are dropped, whether LAPACK returns them as inf or as
    huge finite numbers (then the φ part of z is at round-off level)."""
    n = k.shape[0]
    a, b = linearize(k, c, m)
    lam, z = sla.eig(a, b)
    phi_part = np.linalg.norm(z[:n], axis=0) / np.maximum(np.linalg.norm(z, axis=0), 1e-300)
    finite = np.isfinite(lam) & (phi_part > 1e-12)
    return lam[finite], z[:n, finite]


def dynamic_matrix(k, c, m, s: complex):
    """Q(s) = s² M + s C + K (sparse, complex)."""
    return sp.csc_matrix(s * s * m + s * c + k, dtype=complex)


def shift_invert_eigenpairs(k, c, m, sigma: complex, count: int):
    """``count`` eigenpairs nearest σ with ARPACK on (A - σB)⁻¹ B."""
    n = k.shape[0]
    count = min(count, 2 * n - 2)
    if count <= 0:
        return np.zeros(0, dtype=complex), np.zeros((n, 0), dtype=complex)
    try:
        lu = spla.splu(dynamic_matrix(k, c, m, sigma))
    except RuntimeError as exc:
        raise QuadraticError(f"the dynamic matrix is singular at σ = {sigma:g} ({exc})") from None
    mc = sp.csr_matrix(m, dtype=complex)
    cs = sp.csr_matrix(c + sigma * m, dtype=complex)

    def matvec(x):
        x = np.asarray(x, dtype=complex).ravel()
        x1, x2 = x[:n], x[n:]
        # (A - σB) y = B x with z = [φ; v]: v-part of B is M, φ-part identity
        # rows: -σ y1 + y2 = x1 ; -K y1 - (C + σM) y2 = M x2
        y1 = -lu.solve(mc @ x2 + cs @ x1)
        y2 = x1 + sigma * y1
        return np.concatenate([y1, y2])

    op = spla.LinearOperator((2 * n, 2 * n), matvec=matvec, dtype=complex)
    mu, z = spla.eigs(op, k=count, which="LM")
    return sigma + 1.0 / mu, z[:n, :]


def frequency_shift(freq: float, amor: float = 0.0) -> complex:
    """code_aster's shift for a frequency and a reduced damping."""
    amor = float(amor or 0.0)
    if abs(amor) >= 1.0:
        amor = 0.95
    omega = TWO_PI * float(freq)
    return complex(-amor * omega / np.sqrt(1.0 - amor * amor), omega)


def upper_half(lam: np.ndarray, vecs: np.ndarray):
    """The eigenpairs with Im(λ) > 0."""
    keep = lam.imag > IMAG_TOL * np.maximum(np.abs(lam), 1e-300)
    return lam[keep], vecs[:, keep]


class QuadraticPencil:
    """Reduced (K, C, M) = Tᵀ(·)T with the selections CALC_MODES needs."""

    def __init__(self, stiffness, damping, mass, elimination: Elimination):
        self.elimination = elimination
        n_dofs = elimination.T.shape[0]
        self.k = elimination.reduce(sp.csr_matrix(stiffness))
        self.m = elimination.reduce(sp.csr_matrix(mass))
        if damping is None:
            damping = sp.csr_matrix((n_dofs, n_dofs))
        self.c = elimination.reduce(sp.csr_matrix(damping))
        self.n = self.k.shape[0]
        self._all = None

    @property
    def dense(self) -> bool:
        return self.n <= DENSE_LIMIT

    def all_modes(self):
        """Every eigenpair with Im(λ) > 0 (dense)."""
        if self._all is None:
            lam, vecs = dense_eigenpairs(self.k, self.c, self.m)
            self._all = upper_half(lam, vecs)
        return self._all

    def nearest(self, sigma: complex, count: int):
        """``count`` upper-half eigenpairs nearest σ, by distance."""
        if self.dense:
            lam, vecs = self.all_modes()
        else:
            asked = 2 * count + 2
            while True:
                lam, vecs = upper_half(
                    *shift_invert_eigenpairs(self.k, self.c, self.m, sigma, asked)
                )
                if lam.size >= count or asked >= 2 * self.n - 2:
                    break
                asked = min(2 * asked, 2 * self.n - 2)
        order = np.argsort(np.abs(lam - sigma), kind="stable")[:count]
        return lam[order], vecs[:, order]

    def farthest(self, count: int):
        if not self.dense:
            raise QuadraticError("PLUS_GRANDE with MATR_AMOR is only available on small models")
        lam, vecs = self.all_modes()
        order = np.argsort(-np.abs(lam), kind="stable")[:count]
        return lam[order], vecs[:, order]

    def band(self, f_low: float, f_high: float):
        """Every upper-half eigenpair with f_low <= Im(λ)/2π <= f_high."""
        if self.dense:
            lam, vecs = self.all_modes()
        else:
            centre = 0.5j * TWO_PI * (f_low + f_high)
            radius = 0.5 * TWO_PI * (f_high - f_low)
            count = 12
            while True:
                lam, vecs = self.nearest(centre, count)
                if lam.size < count or np.max(np.abs(lam - centre), initial=0.0) > radius:
                    break
                if count >= 2 * self.n - 2:
                    break
                count *= 2
        f = lam.imag / TWO_PI
        keep = (f >= f_low) & (f <= f_high)
        return lam[keep], vecs[:, keep]

    def expand(self, vecs: np.ndarray) -> np.ndarray:
        return np.asarray(self.elimination.T @ vecs)

    def residuals(self, lam: np.ndarray, vecs: np.ndarray) -> np.ndarray:
        """||Q(λ) φ|| / (|λ|² ||M φ|| + |λ| ||C φ|| + ||K φ||) per eigenpair."""
        kv, cv, mv = self.k @ vecs, self.c @ vecs, self.m @ vecs
        r = kv + cv * lam[None, :] + mv * (lam**2)[None, :]
        nrm = lambda x: np.linalg.norm(x, axis=0)  # noqa: E731
        scale = np.abs(lam) ** 2 * nrm(mv) + np.abs(lam) * nrm(cv) + nrm(kv)
        return nrm(r) / np.maximum(scale, 1e-300)


def select(pencil: QuadraticPencil, option: str, freq=(), nmax: int = 10, amor=0.0):
    """(λ, reduced shapes) for a CALC_MODES OPTION, by increasing Im(λ)."""
    freq = np.atleast_1d(np.asarray(freq if freq is not None else (), dtype=float))
    if pencil.n == 0:
        raise QuadraticError("every DOF is constrained: there is no mode")
    if option == "PLUS_PETITE":
        lam, vecs = pencil.nearest(0.0 if pencil.dense else _small_shift(pencil), nmax)
    elif option == "PLUS_GRANDE":
        lam, vecs = pencil.farthest(nmax)
    elif option == "CENTRE":
        lam, vecs = pencil.nearest(frequency_shift(freq[0], amor), nmax)
    elif option in ("BANDE", "AJUSTE", "SEPARE") and freq.size >= 2:
        lam, vecs = pencil.band(float(freq.min()), float(freq.max()))
    elif option in ("PROCHE", "AJUSTE", "SEPARE"):
        lam, vecs = _nearest_each(pencil, freq, amor)
    elif option == "TOUT":
        if not pencil.dense:
            raise QuadraticError("OPTION='TOUT' with MATR_AMOR is only available on small models")
        lam, vecs = pencil.all_modes()
    else:
        raise QuadraticError(f"OPTION={option!r} is not available for complex modes")
    order = np.argsort(lam.imag, kind="stable")
    return lam[order], vecs[:, order]


def _small_shift(pencil: QuadraticPencil) -> complex:
    """σ = 0 unless K is singular (free structure): then a tiny imaginary shift."""
    try:
        spla.splu(sp.csc_matrix(pencil.k, dtype=complex))
        return 0.0
    except RuntimeError:
        kd, md = np.abs(pencil.k.diagonal()), np.abs(pencil.m.diagonal())
        ok = (kd > 0) & (md > 0)
        scale = np.sqrt(np.median(kd[ok] / md[ok])) if np.any(ok) else 1.0
        return 1e-4j * scale


def _nearest_each(pencil: QuadraticPencil, freq, amor):
    """One eigenpair nearest each frequency's shift, without repeats."""
    amors = np.atleast_1d(np.asarray(amor if amor is not None else 0.0, dtype=float))
    picked, cols = [], []
    for i, f in enumerate(freq):
        sigma = frequency_shift(f, amors[min(i, amors.size - 1)])
        lam, vecs = pencil.nearest(sigma, min(len(freq) + 1, 2 * pencil.n))
        for j in range(lam.size):
            if not any(np.isclose(lam[j], p, rtol=1e-10, atol=0) for p in picked):
                picked.append(lam[j])
                cols.append(vecs[:, j])
                break
    vecs = np.column_stack(cols) if cols else np.zeros((pencil.n, 0), dtype=complex)
    return np.asarray(picked, dtype=complex), vecs


# --- per-mode quantities -------------------------------------------------


def modal_quantities(lam, complex_stiffness_only: bool = False) -> dict[str, np.ndarray]:
    """FREQ, OMEGA2 and AMOR_REDUIT of eigenvalues λ (code_aster's definitions).

    With a complex stiffness and no damping matrix code_aster solves the
    generalized problem K φ = σ M φ (σ = -λ²) and stores FREQ = |√σ|/2π and
    OMEGA2 = Re σ (its vppara); a quadratic problem stores FREQ = Im λ/2π.
    AMOR_REDUIT = -Re λ/|λ| (= Im √σ/|√σ|) in both."""
    lam = np.asarray(lam, dtype=complex)
    modulus = np.abs(lam)
    if complex_stiffness_only:
        frequency, omega2 = modulus / TWO_PI, (-(lam**2)).real
    else:
        frequency, omega2 = lam.imag / TWO_PI, lam.imag**2
    return {
        "FREQ": frequency,
        "OMEGA2": omega2,
        "AMOR_REDUIT": np.where(modulus > 0, -lam.real / np.where(modulus > 0, modulus, 1), 0.0),
    }


def generalized_parameters(shapes, stiffness, damping, mass) -> dict[str, np.ndarray]:
    """MASS_GENE, AMOR_GENE, RIGI_GENE of complex shapes (module docstring)."""
    shapes = np.asarray(shapes, dtype=complex)
    out = {"MASS_GENE": np.einsum("ij,ij->j", shapes.conj(), mass @ shapes).real}
    if damping is not None:
        out["AMOR_GENE"] = np.einsum("ij,ij->j", shapes.conj(), damping @ shapes).real
    else:
        out["AMOR_GENE"] = np.zeros(shapes.shape[1])
    out["RIGI_GENE"] = np.einsum("ij,ij->j", shapes, stiffness @ shapes).real
    return out


# --- normalisations (one complex factor per mode) ------------------------


def largest_modulus(shapes, mask=None) -> np.ndarray:
    """Make the component of largest modulus (first on ties) exactly 1 + 0i.

    code_aster divides by that modulus, leaving the phase ARPACK produced;
    dividing by the complex component itself gives the same modulus and a
    reproducible phase."""
    shapes = np.asarray(shapes, dtype=complex)
    masked = shapes if mask is None else shapes * mask[:, None]
    if masked.shape[0] == 0:
        return np.ones(shapes.shape[1], dtype=complex)
    rows = np.argmax(np.abs(masked), axis=0)
    pivot = masked[rows, np.arange(shapes.shape[1])]
    safe = np.where(pivot != 0, pivot, 1.0)
    return np.where(pivot != 0, 1.0 / safe, 1.0).astype(complex)


def hermitian(shapes, mask=None) -> np.ndarray:
    """Unit Hermitian 2-norm (EUCL): a real factor."""
    shapes = np.asarray(shapes, dtype=complex)
    masked = shapes if mask is None else shapes * mask[:, None]
    norm = np.linalg.norm(masked, axis=0)
    return np.where(norm > 0, 1.0 / np.where(norm > 0, norm, 1.0), 1.0).astype(complex)


def _unit_bilinear(shapes, values) -> np.ndarray:
    values = np.asarray(values, dtype=complex)
    safe = np.where(values != 0, values, 1.0)
    return np.where(values != 0, 1.0 / np.sqrt(safe), 1.0)


def mass_gene(shapes, lam, mass, damping=None) -> np.ndarray:
    """Factors making φᵀ (2λ M + C) φ = 1."""
    shapes = np.asarray(shapes, dtype=complex)
    value = 2.0 * np.asarray(lam) * np.einsum("ij,ij->j", shapes, mass @ shapes)
    if damping is not None:
        value = value + np.einsum("ij,ij->j", shapes, damping @ shapes)
    return _unit_bilinear(shapes, value)


def rigi_gene(shapes, lam, stiffness, mass) -> np.ndarray:
    """Factors making φᵀ (λ² M - K) φ = 1."""
    shapes = np.asarray(shapes, dtype=complex)
    lam = np.asarray(lam)
    value = lam**2 * np.einsum("ij,ij->j", shapes, mass @ shapes) - np.einsum(
        "ij,ij->j", shapes, stiffness @ shapes
    )
    return _unit_bilinear(shapes, value)
