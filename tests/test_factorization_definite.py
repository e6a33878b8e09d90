"""The implicit physical step's solver (fem.factorization.definite_solver):
CHOLMOD for symmetric positive definite matrices, SuperLU otherwise, the
same solution either way."""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from asterlite.fem.factorization import definite_solver


def laplacian(n: int) -> sp.csc_matrix:
    """A 2D Laplacian plus a mass-like shift (symmetric positive definite)."""
    line = sp.diags([-1.0, 2.0, -1.0], [-1, 0, 1], shape=(n, n))
    eye = sp.identity(n)
    return sp.csc_matrix(sp.kron(line, eye) + sp.kron(eye, line) + 0.1 * sp.identity(n * n))


def test_positive_definite_matrices_solve_through_cholmod():
    matrix = laplacian(30)
    rhs = np.random.default_rng(1).standard_normal((matrix.shape[0], 3))
    solve = definite_solver(matrix)
    assert solve.__name__ == "solve" and solve.__qualname__.startswith("_cholmod_solver")
    np.testing.assert_allclose(matrix @ solve(rhs), rhs, atol=1e-10)
    np.testing.assert_allclose(solve(rhs[:, 0]), np.linalg.solve(matrix.toarray(), rhs[:, 0]))


def test_indefinite_and_asymmetric_matrices_fall_back_to_superlu():
    indefinite = laplacian(10) - 3.0 * sp.identity(100)
    asymmetric = laplacian(10) + sp.csc_matrix(([0.5], ([0], [1])), shape=(100, 100))
    rhs = np.arange(100.0)
    for matrix in (indefinite, asymmetric):
        solve = definite_solver(matrix)
        assert not solve.__qualname__.startswith("_cholmod_solver")
        np.testing.assert_allclose(matrix @ solve(rhs), rhs, atol=1e-9)
