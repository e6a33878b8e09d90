"""The implicit physical step's solver (fem.factorization.definite_solver):
CHOLMOD for symmetric positive definite matrices, SuperLU otherwise, the
same solution either way."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
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


def _old_asymmetry(matrix) -> float:
    difference = matrix - matrix.T
    return float(np.abs(difference.data).max()) if difference.nnz else 0.0


def test_the_symmetry_test_by_triangles_measures_what_a_minus_its_transpose_does():
    """The lower triangle taken with the symmetry test is sp.tril's, and the
    test accepts exactly the matrices whose max |A - Aᵀ| is within the
    tolerance, CSR and CSC, with empty rows and one-sided entries."""
    from asterlite.fem import factorization

    rng = np.random.default_rng(3)
    base = sp.random(60, 60, density=0.08, random_state=4, format="csr")
    base = base + base.T + sp.diags(rng.uniform(1.0, 2.0, 60))
    base = sp.lil_matrix(base)
    base[7, :] = 0.0  # an empty row and column
    base[:, 7] = 0.0
    base = sp.csr_matrix(base)
    base.eliminate_zeros()
    scale = float(np.abs(base.data).max())
    for noise in (0.0, 1.0e-14 * scale, 1.0e-9 * scale):
        perturbed = sp.lil_matrix(base, copy=True)
        perturbed[3, 50] = perturbed[3, 50] + noise  # one side only (may add an entry)
        for matrix in (sp.csr_matrix(perturbed), sp.csc_matrix(perturbed)):
            matrix.sum_duplicates()
            lower = factorization._symmetric_lower(matrix)
            symmetric = _old_asymmetry(matrix) <= factorization.SYMMETRY_TOLERANCE * scale
            assert (lower is not None) == symmetric
            if lower is not None:
                assert lower.format == "csc"
                expected = sp.tril(matrix, format="csc")
                assert np.array_equal(lower.indptr, expected.indptr)
                assert np.array_equal(lower.indices, expected.indices)
                assert np.array_equal(lower.data, expected.data)


def test_a_built_step_matrix_is_let_go_of_before_cholmod_factorises(monkeypatch):
    """Given a function building the step matrix, the solver keeps only its
    lower triangle: the whole matrix is gone when CHOLMOD is called, and the
    solution is the one of the matrix given whole."""
    import gc
    import weakref

    from cholespy import CholeskySolverD

    from asterlite.fem import factorization

    built, alive = [], []

    def build():
        matrix = sp.csr_matrix(laplacian(15))
        built.append(weakref.ref(matrix))
        return matrix

    def recording(*args):
        gc.collect()
        alive.append([ref() is not None for ref in built])
        return CholeskySolverD(*args)

    monkeypatch.setattr(factorization, "CholeskySolverD", recording)
    solve = definite_solver(build)
    assert alive == [[False]]
    rhs = np.linspace(-1.0, 1.0, 225)
    assert np.array_equal(solve(rhs), definite_solver(sp.csr_matrix(laplacian(15)))(rhs))


def test_a_built_indefinite_matrix_is_built_again_for_superlu():
    calls = []

    def build():
        calls.append(1)
        return sp.csr_matrix(laplacian(10) - 3.0 * sp.identity(100))

    solve = definite_solver(build)
    assert len(calls) == 2 and not solve.__qualname__.startswith("_cholmod_solver")
    rhs = np.arange(100.0)
    np.testing.assert_allclose(build() @ solve(rhs), rhs, atol=1e-9)


def test_step_factors_past_half_the_limit_go_to_mumps_out_of_core(monkeypatch):
    """A step matrix of LARGE_LIMIT unknowns or more whose factor, by
    MUMPS's analysis, would pass what is left before half the run's memory
    limit is factorised by MUMPS out of core (CHOLMOD's solution to
    rounding), and its folder goes when the scheme lets the solve go (a new
    step size, the end of the run); within it, without a memory limit,
    under LARGE_LIMIT unknowns or with ASTERLITE_SPARSE_SOLVER=cholmod it
    stays on CHOLMOD (faster solves)."""
    import gc
    import os

    from asterlite import watchdog
    from asterlite.fem import factorization, sparse_direct

    if not sparse_direct.mumps_available():
        pytest.skip("python-mumps is not installed")
    monkeypatch.delenv("ASTERLITE_SPARSE_SOLVER", raising=False)
    monkeypatch.setenv("MUMPS_OOC_TMPDIR", "")
    matrix = sp.csr_matrix(laplacian(70))
    assert matrix.shape[0] >= sparse_direct.LARGE_LIMIT
    rhs = np.random.default_rng(5).standard_normal(matrix.shape[0])
    expected = factorization._cholmod_solver(sp.tril(matrix, format="csc"))(rhs)
    cholmod = "_cholmod_solver"
    assert definite_solver(matrix).__qualname__.startswith(cholmod)  # no limit
    memory = {"limit_mb": 10.0**6, "headroom": 10**12}
    monkeypatch.setattr(watchdog, "memory_limit_mb", lambda: memory["limit_mb"])
    monkeypatch.setattr(watchdog, "memory_headroom", lambda: memory["headroom"])
    assert definite_solver(matrix).__qualname__.startswith(cholmod)  # far within
    memory.update(limit_mb=4.0, headroom=3 * 2**20)  # 1 MB left before half the limit
    solve = definite_solver(lambda: matrix)
    assert solve.__qualname__.startswith("_out_of_core_solver")
    folder = Path(os.environ["MUMPS_OOC_TMPDIR"])
    assert folder.name.startswith("asterlite-mumps-") and folder.is_dir()
    np.testing.assert_allclose(solve(rhs), expected, rtol=1e-10, atol=1e-12)
    del solve
    gc.collect()
    assert not folder.exists()
    assert definite_solver(sp.csr_matrix(laplacian(20))).__qualname__.startswith(cholmod)
    monkeypatch.setenv("ASTERLITE_SPARSE_SOLVER", "cholmod")
    assert definite_solver(matrix).__qualname__.startswith(cholmod)
