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


def test_cholmod_takes_the_lower_triangle_in_csc_without_a_coo_copy(monkeypatch):
    """CHOLMOD is given the CSC arrays of the step matrix's lower triangle,
    which is all it reads (no COO copy of the whole matrix held beside its
    factor), with the solution of the whole COO matrix it was given before,
    bit for bit."""
    from cholespy import CholeskySolverD, MatrixType

    from asterlite.fem import factorization

    given = []

    def recording(n_rows, first, second, values, kind):
        given.append((first, second, values, kind))
        return CholeskySolverD(n_rows, first, second, values, kind)

    csr = sp.csr_matrix(laplacian(20))  # the schemes' matrices are CSR sums
    monkeypatch.setattr(factorization, "CholeskySolverD", recording)
    solve = definite_solver(csr)
    ((first, second, values, kind),) = given
    assert kind == MatrixType.CSC and first.dtype == np.int32 and len(first) == csr.shape[0] + 1
    csc = sp.csc_matrix((values, second, first), shape=csr.shape)
    assert (csc != sp.tril(csr)).nnz == 0
    coo = csr.tocoo()
    reference = CholeskySolverD(
        csr.shape[0], coo.row.astype(np.int32), coo.col.astype(np.int32), coo.data, MatrixType.COO
    )
    rhs = np.random.default_rng(2).standard_normal(csr.shape[0])
    expected = np.zeros_like(rhs)
    reference.solve(rhs, expected)
    assert np.array_equal(solve(rhs), expected)


def test_duplicate_entries_are_summed_before_cholmod():
    matrix = laplacian(8).tocoo()
    doubled = sp.coo_matrix(
        (np.concatenate([matrix.data, matrix.data]) / 2.0,
         (np.concatenate([matrix.row, matrix.row]), np.concatenate([matrix.col, matrix.col]))),
        shape=matrix.shape,
    )  # fmt: skip
    rhs = np.linspace(0.0, 1.0, matrix.shape[0])
    solve = definite_solver(doubled)
    assert solve.__qualname__.startswith("_cholmod_solver")
    np.testing.assert_allclose(matrix @ solve(rhs), rhs, atol=1e-12)
