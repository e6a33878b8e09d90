"""Elimination of kinematic relations group by group: relations that share
no DOF are eliminated apart (a LIAISON_GROUP pairs thousands of nodes one by
one), with the same affine set {u : B u = b} as one elimination of them all,
and sparse factors whatever their number."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp

from asterlite.fem.constraints import ConstraintError, eliminate


def _relations(n_pairs: int):
    """DOF 0 fixed to 0.5; pairs u[2k+1] - u[2k+2] = k / n; a block of three
    relations on DOFs a..a+3, one of them redundant; a relation between the
    fixed DOF 0 and DOF a+4 (u[a+4] = 0.5 + 1)."""
    a = 2 * n_pairs + 1
    n = a + 6
    rows, cols, vals, rhs = [0], [0], [2.0], [1.0]
    for k in range(n_pairs):
        r = len(rhs)
        rows += [r, r]
        cols += [2 * k + 1, 2 * k + 2]
        vals += [1.0, -1.0]
        rhs.append(k / n_pairs)
    block = [([a, a + 1, a + 2], [1.0, 2.0, -1.0], 0.3), ([a + 1, a + 3], [1.0, 1.0], -0.2)]
    block.append(([a, a + 1, a + 2, a + 3], [1.0, 3.0, -1.0, 1.0], 0.1))  # sum of the two
    block.append(([0, a + 4], [-1.0, 1.0], 1.0))
    for dofs, coefs, value in block:
        r = len(rhs)
        rows += [r] * len(dofs)
        cols += dofs
        vals += coefs
        rhs.append(value)
    b_matrix = sp.csr_matrix((vals, (rows, cols)), shape=(len(rhs), n))
    return b_matrix, np.array(rhs), n


@pytest.mark.parametrize("n_pairs", [1, 7, 3000])
def test_groups_give_the_affine_set_of_all_the_relations(n_pairs):
    b_matrix, rhs, n = _relations(n_pairs)
    elim = eliminate(b_matrix, rhs, n)
    rank = 1 + n_pairs + 2 + 1  # the fixed DOF, the pairs, the block (rank 2), the last
    assert elim.n_free == n - rank
    assert np.abs(b_matrix @ elim.T).max() < 1e-12
    assert np.abs(b_matrix @ elim.u0 - rhs).max() < 1e-12
    # T's columns are independent: T q = 0 only for q = 0 (T has an identity on the free DOFs)
    assert np.array_equal(elim.T[elim.free].toarray(), np.eye(elim.n_free))
    # every pair keeps one unknown, and the factors stay sparse
    assert elim.slave_solve.nnz <= n_pairs + 12
    assert elim.T.nnz <= n + 4 * 12


def test_particular_solutions_for_other_right_hand_sides():
    b_matrix, rhs, n = _relations(5)
    elim = eliminate(b_matrix, np.zeros_like(rhs), n)
    other = np.column_stack([rhs, -3.0 * rhs])
    u0 = elim.particular(other)
    assert u0.shape == (n, 2)
    assert np.abs(b_matrix @ u0 - other).max() < 1e-12


def test_incompatible_relations_are_refused():
    b_matrix, rhs, n = _relations(5)
    rhs[-2] += 1.0  # the redundant relation no longer the sum of the two
    with pytest.raises(ConstraintError, match="incompatible"):
        eliminate(b_matrix, rhs, n)


def test_fixed_dofs_reduce_a_matrix_by_selection_to_the_same_bits():
    """DOFs fixed, no relation between DOFs: Tᵀ A T is A's free rows and
    columns, taken as such, bit for bit what the products give (a -0.0 and an
    explicit zero dropped as they drop them); with a relation between DOFs,
    or a complex A, the products."""
    rng = np.random.default_rng(2)
    n = 40
    a = sp.random(n, n, density=0.2, random_state=3, format="csr") * 1e3
    a = sp.csr_matrix(a + a.T + sp.identity(n))
    a.data[3], a.data[5] = -0.0, 0.0  # kept as stored terms
    fixed = np.sort(rng.choice(np.arange(3, n), 7, replace=False))  # DOFs 1 and 2 free
    b_fixed = sp.csr_matrix((np.ones(7), (np.arange(7), fixed)), shape=(7, n))
    selection = eliminate(b_fixed, np.zeros(7), n)
    assert selection._selects_free
    reduced = selection.reduce(a)
    products = sp.csr_matrix(selection.T.T @ (a @ selection.T))
    assert np.array_equal(reduced.indptr, products.indptr)
    assert np.array_equal(reduced.indices, products.indices)
    assert np.array_equal(reduced.data.view(np.uint64), products.data.view(np.uint64))
    assert reduced.indices.dtype == products.indices.dtype and type(reduced) is type(products)
    # the input is not changed (its zeros stay stored)
    assert a.data[3] == 0.0 and np.signbit(a.data[3])
    # a relation between two DOFs: T is no selection
    b_tied = sp.vstack([b_fixed, sp.csr_matrix(([1.0, -1.0], ([0, 0], [1, 2])), shape=(1, n))])
    tied = eliminate(sp.csr_matrix(b_tied), np.zeros(8), n)
    assert not tied._selects_free
    np.testing.assert_allclose(
        tied.reduce(a).toarray(), (tied.T.T @ a @ tied.T).toarray(), rtol=1e-15, atol=0
    )
    complex_a = a.astype(complex)
    assert np.array_equal(
        selection.reduce(complex_a).toarray(),
        (selection.T.T @ (complex_a @ selection.T)).toarray(),
    )
