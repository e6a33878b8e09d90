"""Damped (complex) modes: quadratic eigenvalues against analytic ones,
code_aster's FREQ / AMOR_REDUIT, normalisations, sparse vs dense solvers."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp

from asterlite.concepts.assembly import AssembledMatrix, ComplexAssembledMatrix
from asterlite.concepts.modes import ComplexModeResult
from asterlite.fem.constraints import Elimination
from asterlite.modal import quadratic
from tests.test_fem_support import chain_matrices, run

TWO_PI = 2.0 * np.pi


def free_pencil(k, c, m) -> quadratic.QuadraticPencil:
    n = np.asarray(k).shape[0]
    identity = Elimination(
        sp.identity(n, format="csr"), np.zeros(n), np.arange(n), np.array([], dtype=int)
    )
    return quadratic.QuadraticPencil(np.asarray(k), np.asarray(c), np.asarray(m), identity)


def characteristic_roots(k, c, m) -> np.ndarray:
    """Roots of det(λ²M + λC + K) for a 2 × 2 system (a quartic in λ)."""
    p = {(i, j): np.poly1d([m[i][j], c[i][j], k[i][j]]) for i in range(2) for j in range(2)}
    det = p[0, 0] * p[1, 1] - p[0, 1] * p[1, 0]
    return np.roots(det.coeffs)


def test_two_dof_nonproportional_damping_matches_the_characteristic_polynomial():
    k = np.array([[3.0e4, -1.0e4], [-1.0e4, 1.0e4]])
    m = np.diag([2.0, 1.0])
    c = np.array([[5.0, 0.0], [0.0, 1.0]])  # not proportional to K or M
    pencil = free_pencil(k, c, m)
    lam, vecs = quadratic.select(pencil, "TOUT")
    expected = characteristic_roots(k, c, m)
    expected = np.sort_complex(expected[expected.imag > 0])
    order = np.argsort(lam.imag)
    np.testing.assert_allclose(lam[order], expected[np.argsort(expected.imag)], rtol=1e-10)
    # each pair solves the quadratic problem
    for j in range(lam.size):
        residual = (lam[j] ** 2 * m + lam[j] * c + k) @ vecs[:, j]
        assert np.linalg.norm(residual) < 1e-8 * np.linalg.norm(k @ vecs[:, j])
    # presentation order: increasing Im(λ)
    assert np.all(np.diff(lam.imag) > 0)


def test_two_dof_proportional_damping_gives_classical_modal_damping():
    k = np.array([[2.0e4, -1.0e4], [-1.0e4, 1.0e4]])
    m = np.eye(2)
    alpha, beta = 0.5, 1.0e-4
    c = alpha * m + beta * k
    omega = np.sqrt(np.linalg.eigvalsh(k))
    zeta = alpha / (2 * omega) + beta * omega / 2
    lam, _ = quadratic.select(free_pencil(k, c, m), "PLUS_PETITE", nmax=2)
    q = quadratic.modal_quantities(lam)
    np.testing.assert_allclose(q["AMOR_REDUIT"], zeta, rtol=1e-10)
    np.testing.assert_allclose(q["FREQ"], omega * np.sqrt(1 - zeta**2) / TWO_PI, rtol=1e-10)
    np.testing.assert_allclose(q["OMEGA2"], (TWO_PI * q["FREQ"]) ** 2, rtol=1e-12)


def test_hysteretic_single_dof():
    """m λ² + k (1 + iη) = 0: λ = iω₀√(1 + iη), the root with Im(λ) > 0."""
    mass, stiff, eta = 2.0, 8.0e3, 0.02
    omega0 = np.sqrt(stiff / mass)
    pencil = free_pencil(np.array([[stiff * (1 + 1j * eta)]]), np.zeros((1, 1)), np.array([[mass]]))
    lam, _ = quadratic.select(pencil, "CENTRE", freq=omega0 / TWO_PI, nmax=1)
    expected = 1j * omega0 * np.sqrt(1 + 1j * eta)
    np.testing.assert_allclose(lam, [expected], rtol=1e-12)
    q = quadratic.modal_quantities(lam)
    np.testing.assert_allclose(q["FREQ"], expected.imag / TWO_PI, rtol=1e-12)
    np.testing.assert_allclose(q["AMOR_REDUIT"], -expected.real / abs(expected), rtol=1e-12)
    # |λ|² = ω₀² √(1 + η²) and 2ζ ≈ η for small η
    np.testing.assert_allclose(abs(lam[0]) ** 2, omega0**2 * np.sqrt(1 + eta**2), rtol=1e-12)
    assert abs(2 * q["AMOR_REDUIT"][0] / eta - 1) < 1e-3


def test_centre_shift_with_reduced_damping():
    sigma = quadratic.frequency_shift(10.0, 0.6)
    np.testing.assert_allclose(sigma, TWO_PI * 10.0 * (-0.6 / 0.8 + 1j))
    assert quadratic.frequency_shift(10.0) == pytest.approx(TWO_PI * 10.0j)


def test_shift_invert_matches_dense(monkeypatch):
    n = 40
    main = 2.0e4 * np.ones(n)
    k = sp.diags([main, -1.0e4 * np.ones(n - 1), -1.0e4 * np.ones(n - 1)], [0, 1, -1])
    m = sp.identity(n) * 1.5
    rng = np.random.default_rng(0)
    c = sp.diags(rng.uniform(0.0, 3.0, n))
    identity = Elimination(
        sp.identity(n, format="csr"), np.zeros(n), np.arange(n), np.array([], dtype=int)
    )
    dense = quadratic.QuadraticPencil(k, c, m, identity)
    expected, _ = quadratic.select(dense, "CENTRE", freq=12.0, nmax=4)
    monkeypatch.setattr(quadratic, "DENSE_LIMIT", 5)
    sparse = quadratic.QuadraticPencil(k, c, m, identity)
    assert not sparse.dense
    for option, kwargs in (("CENTRE", {"freq": 12.0, "nmax": 4}), ("PLUS_PETITE", {"nmax": 3})):
        lam, vecs = quadratic.select(sparse, option, **kwargs)
        ref, _ = quadratic.select(dense, option, **kwargs)
        np.testing.assert_allclose(lam, ref, rtol=1e-9)
        assert np.all(sparse.residuals(lam, vecs) < 1e-10)
    np.testing.assert_allclose(quadratic.select(sparse, "CENTRE", freq=12.0, nmax=4)[0], expected)


# --- through CALC_MODES ----------------------------------------------------

K, M = 1.0e4, 2.0


@pytest.fixture
def axial_chain():
    return chain_matrices(
        8,
        (K, K, K),
        M,
        ddl_impo=[{"GROUP_NO": "ENDS", "DX": 0.0}, {"TOUT": "OUI", "DY": 0.0, "DZ": 0.0}],
    )


def _undamped(n_free: int) -> np.ndarray:
    j = np.arange(1, n_free + 1)
    return 2.0 * np.sqrt(K / M) * np.sin(j * np.pi / (2 * (n_free + 1)))


def test_calc_modes_with_proportional_damping(axial_chain):
    session, _model, k, m = axial_chain
    alpha, beta = 2.0, 2.0e-4
    c = AssembledMatrix(numbering=k.numbering, matrix=alpha * m.matrix + beta * k.matrix)
    c.kind = "AMOR"
    modes = run(
        session,
        "CALC_MODES",
        MATR_RIGI=k,
        MATR_MASS=m,
        MATR_AMOR=c,
        OPTION="PLUS_PETITE",
        CALC_FREQ={"NMAX_FREQ": 3},
        SOLVEUR_MODAL={"METHODE": "SORENSEN", "APPROCHE": "REEL"},
    )
    assert isinstance(modes, ComplexModeResult) and modes.satisfies("mode_meca_c")
    omega = _undamped(6)[:3]
    zeta = alpha / (2 * omega) + beta * omega / 2
    np.testing.assert_allclose(modes.parameters["AMOR_REDUIT"], zeta, rtol=1e-9)
    np.testing.assert_allclose(modes.frequencies, omega * np.sqrt(1 - zeta**2) / TWO_PI, rtol=1e-9)
    # constrained DOFs stay zero, the largest component is exactly 1 + 0i
    assert np.all(modes.shapes[modes.numbering.dof_indices([0, 7], "DX")] == 0.0)
    pivots = modes.shapes[np.argmax(np.abs(modes.shapes), axis=0), np.arange(3)]
    np.testing.assert_allclose(pivots, 1.0)
    # RECU_TABLE reads FREQ and AMOR_REDUIT
    table = run(session, "RECU_TABLE", CO=modes, NOM_PARA=("FREQ", "AMOR_REDUIT"))
    assert table is not None


def test_calc_modes_with_hysteretic_stiffness(axial_chain):
    session, _model, k, m = axial_chain
    eta = 0.01
    k_hyst = ComplexAssembledMatrix(numbering=k.numbering, matrix=(1 + 1j * eta) * k.matrix)
    modes = run(
        session,
        "CALC_MODES",
        MATR_RIGI=k_hyst,
        MATR_MASS=m,
        OPTION="CENTRE",
        CALC_FREQ={"FREQ": 20.0, "NMAX_FREQ": 2},
    )
    omega = _undamped(6)
    expected = 1j * omega * np.sqrt(1 + 1j * eta)
    nearest = expected[np.argsort(np.abs(expected - 2j * np.pi * 20.0))[:2]]
    nearest = nearest[np.argsort(nearest.imag)]
    np.testing.assert_allclose(modes.eigenvalues, nearest, rtol=1e-10)
    # a complex stiffness without damping is code_aster's generalized problem
    # K phi = sigma M phi: FREQ = |sqrt(sigma)| / 2 pi (its vppara), not Im(lambda) / 2 pi
    np.testing.assert_allclose(modes.frequencies, np.abs(nearest) / TWO_PI, rtol=1e-10)


def test_complex_normalisations(axial_chain):
    session, _model, k, m = axial_chain
    c = AssembledMatrix(numbering=k.numbering, matrix=0.3 * m.matrix + 1e-4 * k.matrix)
    common = dict(MATR_RIGI=k, MATR_MASS=m, MATR_AMOR=c, CALC_FREQ={"NMAX_FREQ": 2})
    modes = run(session, "CALC_MODES", NORM_MODE={"NORME": "MASS_GENE"}, **common)
    lam, phi = modes.eigenvalues, modes.shapes
    value = 2 * lam * np.einsum("ij,ij->j", phi, m.matrix @ phi) + np.einsum(
        "ij,ij->j", phi, c.matrix @ phi
    )
    np.testing.assert_allclose(value, 1.0, rtol=1e-10)
    np.testing.assert_allclose(
        modes.parameters["MASS_GENE"], np.einsum("ij,ij->j", phi.conj(), m.matrix @ phi).real
    )
    again = run(session, "NORM_MODE", MODE=modes, NORME="RIGI_GENE")
    lam, phi = again.eigenvalues, again.shapes
    value = lam**2 * np.einsum("ij,ij->j", phi, m.matrix @ phi) - np.einsum(
        "ij,ij->j", phi, k.matrix @ phi
    )
    np.testing.assert_allclose(value, 1.0, rtol=1e-10)
    eucl = run(session, "NORM_MODE", MODE=modes, NORME="EUCL")
    np.testing.assert_allclose(np.linalg.norm(eucl.shapes, axis=0), 1.0)
    tran = run(session, "NORM_MODE", MODE=modes, NORME="TRAN")
    np.testing.assert_allclose(np.abs(tran.shapes).max(axis=0), 1.0)
    # the source basis is left untouched and the eigenvalues follow a selection
    assert isinstance(tran, ComplexModeResult)
    np.testing.assert_allclose(tran.eigenvalues, modes.eigenvalues)


def test_massless_dof_is_condensed_not_spurious():
    """M singular: the infinite eigenvalues are dropped; the finite pair is the
    condensed oscillator k_eff = k1 k2 / (k1 + k2) on the mass."""
    k = np.array([[2.0e4, -1.0e4], [-1.0e4, 1.0e4]])
    m = np.diag([1.0, 0.0])
    lam, vecs = quadratic.select(free_pencil(k, np.zeros((2, 2)), m), "TOUT")
    np.testing.assert_allclose(lam, [100.0j], rtol=1e-10)
    np.testing.assert_allclose(vecs[1, 0] / vecs[0, 0], 1.0, rtol=1e-10)


def test_generalized_matrices_with_damping(axial_chain):
    """Projected on the 3 lowest real modes, a proportional damping keeps the
    3 lowest complex eigenvalues of the physical problem."""
    from asterlite.concepts.modes import GeneralizedMatrix, GeneralizedModes, GeneralizedNumbering

    session, _model, k, m = axial_chain
    c_phys = 2.0 * m.matrix + 2.0e-4 * k.matrix
    basis = run(session, "CALC_MODES", MATR_RIGI=k, MATR_MASS=m, CALC_FREQ={"NMAX_FREQ": 3})
    numbering = GeneralizedNumbering(basis=basis)
    phi = basis.shapes

    def gene(a, kind):
        return GeneralizedMatrix(numbering=numbering, matrix=phi.T @ (a @ phi), kind=kind)

    modes = run(
        session,
        "CALC_MODES",
        MATR_RIGI=gene(k.matrix, "RIGI"),
        MATR_MASS=gene(m.matrix, "MASS"),
        MATR_AMOR=gene(c_phys, "AMOR"),
        CALC_FREQ={"NMAX_FREQ": 3},
    )
    assert isinstance(modes, GeneralizedModes)
    physical = run(
        session,
        "CALC_MODES",
        MATR_RIGI=k,
        MATR_MASS=m,
        MATR_AMOR=AssembledMatrix(numbering=k.numbering, matrix=c_phys),
        CALC_FREQ={"NMAX_FREQ": 3},
    )
    np.testing.assert_allclose(modes.parameters["EIGENVALUE"], physical.eigenvalues, rtol=1e-9)
    np.testing.assert_allclose(
        modes.parameters["AMOR_REDUIT"], physical.parameters["AMOR_REDUIT"], rtol=1e-9
    )
