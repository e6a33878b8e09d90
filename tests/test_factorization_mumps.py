"""FACTORISER's factorisation (fem.factorization.factorize) of a real
symmetric matrix of sparse_direct.LARGE_LIMIT unknowns or more: MUMPS's
LDLᵀ, with its null pivots as NPREC's singularity test, the solution of
SuperLU's to rounding, and a session's saved factor rebuilt by MUMPS."""

from __future__ import annotations

import pickle

import numpy as np
import pytest
import scipy.sparse as sp

from asterlite.fem import factorization, sparse_direct
from asterlite.fem.factorization import factorize, solve

pytestmark = pytest.mark.skipif(
    not sparse_direct.mumps_available(), reason="python-mumps is not installed"
)


class Unconstrained:
    """A numbering without relations (what factorize reads of one)."""

    def __init__(self, n: int):
        self.n_dofs = n

    def constraint_matrix(self):
        return sp.csr_matrix((0, self.n_dofs)), np.zeros(0)


def grid(n: int, shift: float) -> sp.csr_matrix:
    line = sp.diags([-1.0, 2.0, -1.0], [-1, 0, 1], shape=(n, n)).tolil()
    line[0, 0] = line[n - 1, n - 1] = 1.0  # free ends: singular without the shift
    eye = sp.identity(n)
    return sp.csr_matrix(sp.kron(line, eye) + sp.kron(eye, line) + shift * sp.identity(n * n))


@pytest.fixture(autouse=True)
def automatic_backend(monkeypatch):
    monkeypatch.delenv("ASTERLITE_SPARSE_SOLVER", raising=False)


def test_a_large_symmetric_matrix_is_factorised_by_mumps_with_superlu_s_solution():
    matrix = grid(70, 0.1)
    assert matrix.shape[0] >= sparse_direct.LARGE_LIMIT
    factors = factorize(matrix, Unconstrained(matrix.shape[0]))
    assert isinstance(factors.lu, sparse_direct.MumpsFactor)
    assert factors.null_pivots == 0 and np.isnan(factors.lost_digits)
    loads = np.random.default_rng(7).standard_normal(matrix.shape[0])
    u, residual = solve(factors, matrix, Unconstrained(matrix.shape[0]), loads, np.zeros(0))
    assert residual < 1e-12
    expected = factorization._superlu(sp.csc_matrix(matrix)).solve(loads)
    np.testing.assert_allclose(u, expected, rtol=1e-10, atol=1e-12)
    # a saved session keeps the reduced matrix; the factor is made again by MUMPS
    restored = pickle.loads(pickle.dumps(factors))
    assert restored.lu is None
    np.testing.assert_allclose(restored.solve_reduced(loads), u, rtol=1e-12, atol=1e-14)
    assert isinstance(restored.lu, sparse_direct.MumpsFactor)


def test_mumps_null_pivots_mark_a_singular_matrix_and_small_ones_stay_on_superlu():
    singular = grid(70, 0.0)  # free-free: constant vectors in its kernel
    factors = factorize(singular, Unconstrained(singular.shape[0]), digits=8)
    assert factors.null_pivots >= 1
    small = grid(20, 0.1)
    factors = factorize(small, Unconstrained(small.shape[0]))
    assert factors.null_pivots is None and factors.lost_digits < 8
