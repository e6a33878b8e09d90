"""Fill-reducing orderings and the LDLᵀ of physical harmonic sweeps
(asterlite.harmonic.physical.ordering, asterlite.harmonic.ldl)."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp
from scipy.sparse.csgraph import reverse_cuthill_mckee

from asterlite.harmonic import ldl
from asterlite.harmonic.physical import aligned_pencil, nested_dissection


def _grid_laplacian(k: int) -> sp.csc_matrix:
    """The 7-point Laplacian of a k x k x k grid (a 3D mesh's pattern)."""
    one = sp.diags([-np.ones(k - 1), 2 * np.ones(k), -np.ones(k - 1)], [-1, 0, 1])
    eye = sp.identity(k)
    lap = (sp.kron(sp.kron(one, eye), eye) + sp.kron(sp.kron(eye, one), eye)) + sp.kron(
        sp.kron(eye, eye), one
    )
    return sp.csc_matrix(lap)


def test_nested_dissection_fills_far_less_than_rcm_on_a_3d_grid():
    pytest.importorskip("pymetis")
    a = _grid_laplacian(14)
    n = a.shape[0]
    perm = nested_dissection(a.indptr, a.indices, n)
    assert sorted(perm.tolist()) == list(range(n))
    rcm = np.asarray(reverse_cuthill_mckee(sp.csr_matrix(a), symmetric_mode=True))
    nd_fill = ldl.analyse(a.indptr, a.indices, n, perm).fill
    rcm_fill = ldl.analyse(a.indptr, a.indices, n, rcm).fill
    assert nd_fill < 0.6 * rcm_fill


def test_nested_dissection_of_a_diagonal_pattern_is_none():
    a = sp.csc_matrix(sp.identity(5))
    assert nested_dissection(a.indptr, a.indices, 5) is None


def test_ldl_with_nested_dissection_solves_a_complex_symmetric_pencil():
    pytest.importorskip("pymetis")
    k_matrix = _grid_laplacian(8) * 1.0e3
    m_matrix = sp.csc_matrix(sp.identity(k_matrix.shape[0]) * 2.0)
    pencil = aligned_pencil(k_matrix * complex(1.0, 0.05), m_matrix, None)
    assert pencil.indices.dtype == np.int32
    perm = nested_dissection(pencil.indptr, pencil.indices, pencil.n)
    analysis = ldl.analyse(pencil.indptr, pencil.indices, pencil.n, perm)
    assert analysis.upper_idx.dtype == np.int32 and analysis.source.dtype == np.int32
    matrix = pencil.at(3.0)
    factor = ldl.factorise(analysis, matrix.data)
    assert factor.li.dtype == np.int32
    rhs = np.random.default_rng(0).standard_normal(pencil.n) + 0j
    x = factor.solve(rhs)
    dense = matrix.toarray()
    np.testing.assert_allclose(dense @ x, rhs, atol=1e-10 * np.abs(rhs).max())
    np.testing.assert_allclose(x, np.linalg.solve(dense, rhs), rtol=1e-10, atol=1e-14)


def test_physical_sweep_on_upper_pencil_matches_a_direct_solve():
    """A 1331-DOF complex symmetric sweep (LDLᵀ path: upper-triangle pencil in
    the factor's order) against SuperLU on the whole reduced matrix."""
    from scipy.sparse.linalg import spsolve

    from asterlite.fem.constraints import eliminate
    from asterlite.harmonic import physical
    from asterlite.harmonic.fields import omega2

    k_matrix = _grid_laplacian(11) * complex(1.0e4, 5.0e2)
    n = k_matrix.shape[0]
    m_matrix = sp.csc_matrix(sp.identity(n) * 2.0 + sp.eye(n, k=1) * 0.1 + sp.eye(n, k=-1) * 0.1)
    clamped = sp.csr_matrix(([1.0], ([0], [0])), shape=(1, n))
    elimination = eliminate(clamped, np.zeros(1), n)
    sweep = physical.prepare(elimination, k_matrix, m_matrix)
    assert sweep.symmetric and sweep.pencil.upper
    force = np.random.default_rng(1).standard_normal((1, n))
    frequencies = np.array([3.0, 11.0])
    depl, info = physical.solve(sweep, frequencies, force, np.ones((2, 1), dtype=complex))
    assert info["ldl"] == 2 and info["superlu"] == 0
    assert sweep.pencil.perm is not None  # laid out in the factor's order
    for row, frequency in zip(depl, frequencies, strict=True):
        whole = sp.csc_matrix(k_matrix - omega2(frequency) * m_matrix)[1:, 1:]
        expected = spsolve(whole, force[0, 1:].astype(complex))
        assert row[0] == 0.0
        np.testing.assert_allclose(row[1:], expected, rtol=1e-9, atol=1e-12 * abs(expected).max())
    # the last frequency's K, M, C are dropped once its values are built
    assert sweep.pencil.stiffness is None and sweep.pencil.mass is None
    # the whole matrix rebuilt from the permuted upper triangle, in the caller's order
    fresh = physical.prepare(elimination, k_matrix, m_matrix)
    a = physical.ordering(fresh, 3.0)
    laid_out = fresh.pencil.in_order(a.perm, a.upper_ptr, a.upper_idx, a.source)
    whole = sp.csc_matrix(k_matrix - omega2(3.0) * m_matrix)[1:, 1:].toarray()
    np.testing.assert_allclose(laid_out.at(3.0).toarray(), whole, rtol=1e-14, atol=1e-10)
    x = np.random.default_rng(2).standard_normal(n - 1) + 0j
    np.testing.assert_allclose(laid_out.product(3.0, x), whole @ x, rtol=1e-12)


def test_a_model_solved_again_keeps_its_ordering(monkeypatch):
    """A second sweep of the same model (other values, a few terms that now
    cancel) takes the ordering chosen for the first, without trying the
    orderings again, and solves as accurately."""
    pytest.importorskip("pymetis")
    from asterlite.fem.constraints import Elimination
    from asterlite.harmonic import physical

    monkeypatch.setattr(physical, "_KNOWN_ORDERINGS", [])
    k_matrix = _grid_laplacian(11) * 1.0e3
    n = k_matrix.shape[0]
    mass = sp.csc_matrix(sp.identity(n) * 2.0)
    elimination = Elimination(
        sp.identity(n, format="csr"), np.zeros(n), np.arange(n), np.array([], int)
    )
    rhs = np.ones((1, n))
    first = physical.prepare(elimination, k_matrix * complex(1.0, 0.05), mass)
    physical.solve(first, [3.0], rhs, np.ones((1, 1)))
    tried = []
    monkeypatch.setattr(physical, "nested_dissection", lambda *a: tried.append(a))
    changed = sp.lil_matrix(k_matrix * complex(1.0, 0.08))
    changed[0, 1] = changed[1, 0] = 0.0  # a pair of terms cancel: one term fewer
    changed = sp.csc_matrix(changed)
    changed.eliminate_zeros()
    second = physical.prepare(elimination, changed, mass)
    u, _ = physical.solve(second, [3.0], rhs, np.ones((1, 1)))
    assert not tried
    assert np.array_equal(second.analysis.perm, first.analysis.perm)
    dense = (changed - (2 * np.pi * 3.0) ** 2 * mass).toarray()
    np.testing.assert_allclose(dense @ u[0], rhs[0], atol=1e-9)
