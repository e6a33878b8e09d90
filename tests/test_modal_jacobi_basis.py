"""METHODE='JACOBI': code_aster's basis inside groups of equal eigenvalues.

code_aster's subspace iteration starts from loads diag(M), then unit loads at
the DOFs of smallest K_ii/M_ii: inside a multiple eigenvalue it returns the
parts of those loads in the eigenspace, in order, M-orthogonalised.
"""

import numpy as np
import pytest
import scipy.sparse as sp

from asterlite.fem.constraints import eliminate
from asterlite.modal.calc import generalized_modes, select_modes
from asterlite.modal.eigen import DENSE_LIMIT, ReducedPencil
from asterlite.modal.subspace_start import code_aster_shift, equal_groups, unit_load_order

MASS = 25.0
SPRING = 98696.0  # with MASS: 10 Hz


def two_masses():
    """Two equal masses, each on its own spring: one double eigenvalue."""
    return np.diag([SPRING, SPRING]), np.diag([MASS, MASS])


def chain():
    """Three unequal masses in a chain: distinct eigenvalues."""
    k = np.array([[3.0, -1.0, 0.0], [-1.0, 2.0, -1.0], [0.0, -1.0, 1.5]]) * 1e4
    return k, np.diag([2.0, 1.0, 3.0])


def modes(k, m, method, option="PLUS_PETITE", freq=(), nmax=10):
    return generalized_modes(k, m, option, freq, nmax, method)


def parallel(a, b):
    """a and b equal up to sign."""
    return np.allclose(a, b, atol=1e-12) or np.allclose(a, -b, atol=1e-12)


def check_eigenpairs(k, m, omega2, vecs):
    residual = k @ vecs - (m @ vecs) * omega2[None, :]
    assert np.max(np.abs(residual)) <= 1e-10 * np.max(np.abs(k @ vecs))
    assert np.allclose(vecs.T @ m @ vecs, np.eye(len(omega2)), atol=1e-12)


def test_two_equal_masses_give_in_phase_then_opposite_phase_under_jacobi():
    k, m = two_masses()
    omega2, vecs = modes(k, m, "JACOBI", "BANDE", (1.0, 10.5))
    assert np.allclose(np.sqrt(omega2) / (2 * np.pi), [10.0, 10.0], rtol=1e-6)
    unit = 1.0 / np.sqrt(2 * MASS)
    assert parallel(vecs[:, 0], unit * np.array([1.0, 1.0]))
    assert parallel(vecs[:, 1], unit * np.array([1.0, -1.0]))
    check_eigenpairs(k, m, omega2, vecs)


def test_sorensen_keeps_the_solvers_basis():
    k, m = two_masses()
    before = modes(k, m, None, "BANDE", (1.0, 10.5))
    omega2, vecs = modes(k, m, "SORENSEN", "BANDE", (1.0, 10.5))
    assert np.array_equal(omega2, before[0]) and np.array_equal(vecs, before[1])
    shapes = np.abs(vecs) / np.abs(vecs).max(axis=0)  # one mode per mass
    assert np.allclose(np.sort(shapes, axis=0), [[0.0, 0.0], [1.0, 1.0]], atol=1e-12)


def test_distinct_eigenvalues_are_unchanged_under_jacobi():
    k, m = chain()
    for option, freq in (("PLUS_PETITE", ()), ("CENTRE", (12.0,)), ("TOUT", ())):
        reference = modes(k, m, "SORENSEN", option, freq)
        omega2, vecs = modes(k, m, "JACOBI", option, freq)
        assert np.array_equal(omega2, reference[0]) and np.array_equal(vecs, reference[1])


def test_start_vectors_are_loads_not_displacements():
    """K = λM with unequal masses: every vector is a mode. The first load
    diag(M) gives M⁻¹ diag(M) = (1, 1); the unit load at DOF 0 gives (1, 0),
    M-orthogonal to (1, 1): (4, -1)."""
    m = np.diag([1.0, 4.0])
    k = 1e3 * m
    omega2, vecs = modes(k, m, "JACOBI", "TOUT")
    assert parallel(vecs[:, 0], np.array([1.0, 1.0]) / np.sqrt(5.0))
    assert parallel(vecs[:, 1], np.array([4.0, -1.0]) / np.sqrt(20.0))
    check_eigenpairs(k, m, omega2, vecs)


def test_blocked_dofs_carry_no_start_load():
    """DOF 0 is blocked and has the smallest K/M: its unit load is left out,
    as sspace leaves out DOFs blocked by DDL_IMPO; the free masses are
    rebased on the full numbering and the reduced vectors stay eigenvectors."""
    k_full = np.diag([1.0, SPRING, SPRING])
    m_full = np.diag([MASS, MASS, MASS])
    b = sp.csr_matrix(np.array([[1.0, 0.0, 0.0]]))
    pencil = ReducedPencil(k_full, m_full, eliminate(b, np.zeros(1), 3))
    omega2, vecs = select_modes(pencil, "PLUS_PETITE", (), 2, "JACOBI")
    full = pencil.expand(vecs)
    unit = 1.0 / np.sqrt(2 * MASS)
    assert parallel(full[:, 0], unit * np.array([0.0, 1.0, 1.0]))
    assert parallel(full[:, 1], unit * np.array([0.0, 1.0, -1.0]))
    check_eigenpairs(pencil.k.toarray(), pencil.m.toarray(), omega2, vecs)


def test_unit_loads_follow_sstriv_order():
    k = np.array([4.0, 1.0, 9.0, -1.0, 2.0, 1.0])
    m = np.array([1.0, 1.0, 1.0, 1.0, 0.0, 1.0])
    # positive mass and stiffness by K/M (ties in numbering order), then
    # the other massive DOF, then the massless one
    assert unit_load_order(k, m, 0.0).tolist() == [1, 5, 0, 2, 3, 4]
    # shifted by σ = 5: DOFs 0, 1 and 5 now have K - σM < 0
    assert unit_load_order(k, m, 5.0).tolist() == [2, 0, 1, 3, 5, 4]


def test_shift_follows_the_option():
    assert code_aster_shift("PLUS_PETITE") == 0.0
    assert code_aster_shift("CENTRE", (10.0,)) == pytest.approx((20 * np.pi) ** 2)
    lo, hi = (2 * np.pi) ** 2, (20 * np.pi) ** 2
    assert code_aster_shift("BANDE", (1.0, 10.0)) == pytest.approx(0.5 * (lo + hi))


def test_equal_groups_use_a_relative_tolerance_and_a_floor_at_zero():
    omega2 = np.array([3.0, 0.0, 1.0, 1.0 + 1e-12, 1.0 + 1e-6, 1e-14, 3.0])
    groups = [g.tolist() for g in equal_groups(omega2, floor=1e-12)]
    assert groups == [[1, 5], [2, 3], [0, 6]]


def test_large_models_rebase_the_sparse_solvers_result():
    """Above DENSE_LIMIT the modes come from ARPACK: the rule applies to them."""
    n = DENSE_LIMIT + 50
    k = sp.diags(np.concatenate([[SPRING, SPRING], 1e5 * np.arange(2, n)])).tolil()
    for i in range(2, n - 1):  # a coupled tail above the double eigenvalue
        k[i, i + 1] = k[i + 1, i] = -1e3
    k, m = k.toarray(), np.diag(np.full(n, MASS))
    omega2, vecs = modes(k, m, "JACOBI", "PLUS_PETITE", nmax=3)
    unit = 1.0 / np.sqrt(2 * MASS)
    assert parallel(vecs[:2, 0], unit * np.array([1.0, 1.0]))
    assert parallel(vecs[:2, 1], unit * np.array([1.0, -1.0]))
    assert np.allclose(vecs[2:, :2], 0.0, atol=1e-10)
    check_eigenpairs(k, m, omega2[:2], vecs[:, :2])
