"""Readers of a large CSR matrix by blocks of rows (asterlite.fem.matrix_rows):
the results of the whole-matrix operations, bit for bit, with the pages of a
matrix on disk given back after each block."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp

from asterlite.fem import lagrange_layout, matrix_rows
from asterlite.io import disk_rows
from asterlite.runtime.result_paging import to_disk


def _paged(matrix: sp.csr_matrix) -> sp.csr_matrix:
    """The matrix with its terms and columns on disk, as result_paging leaves them."""
    paged = sp.csr_matrix(matrix, copy=True)
    paged.data, paged.indices = to_disk(paged.data), to_disk(paged.indices)
    return paged


@pytest.fixture
def given_back(monkeypatch):
    calls = []
    release = disk_rows.release_pages
    monkeypatch.setattr(disk_rows, "release_pages", lambda: calls.append(1) or release())
    monkeypatch.setattr(matrix_rows, "BLOCK_TERMS", 64)
    return calls


def _matrix(seed: int) -> sp.csr_matrix:
    rng = np.random.default_rng(seed)
    a = sp.random(300, 300, density=0.05, random_state=rng, format="csr")
    a = a + 1j * sp.random(300, 300, density=0.05, random_state=rng, format="csr")
    a.setdiag(np.arange(300.0))
    return sp.csr_matrix(a)


def test_blocks_cover_the_rows_once_in_order():
    indptr = np.array([0, 5, 5, 10, 200, 201])
    blocks = list(matrix_rows.blocks(indptr, 6))
    assert blocks == [(0, 2), (2, 3), (3, 4), (4, 5)]  # a row past the size is a block alone


def test_products_and_diagonals_by_blocks_are_the_whole_ones(given_back):
    a = _matrix(1)
    paged = _paged(a)
    x = np.random.default_rng(2).standard_normal((300, 3))
    np.testing.assert_array_equal(matrix_rows.product(paged, x), a @ x)
    np.testing.assert_array_equal(matrix_rows.product(paged.real, x[:, 0]), a.real @ x[:, 0])
    np.testing.assert_array_equal(matrix_rows.diagonal(paged), a.diagonal())
    blocks = len(list(matrix_rows.blocks(a.indptr)))
    assert blocks > 10 and len(given_back) == 3 * blocks  # the pages went back after each block


def test_the_lagrange_coefficient_reads_the_diagonal_by_blocks(given_back):
    a = _matrix(3)
    expected = np.abs(a.diagonal())
    expected = 0.5 * (expected[expected > np.finfo(float).eps].min() + expected.max())
    assert lagrange_layout.lagrange_coefficient(_paged(a)) == expected
    assert given_back
    assert lagrange_layout.lagrange_coefficient(a.toarray()) == expected  # a dense one as before
