"""The reduced pencil of a physical harmonic sweep read from the assembled
matrices without their whole reduced copies (asterlite.harmonic.pencil:
selected_dofs, selected_upper with its symmetry check, aligned_triangles): the same
pencil, term for term, as Tᵀ A T by sparse products."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp

from asterlite.fem.constraints import eliminate
from asterlite.harmonic import ldl, pencil, physical


def _symmetric(n: int, seed: int, complex_values: bool = False) -> sp.csr_matrix:
    """A random sparse symmetric matrix, its upper terms summed in another
    order than its lower ones (as an assembly gives them)."""
    rng = np.random.default_rng(seed)
    a = sp.random(n, n, density=8.0 / n, random_state=rng, format="csr")
    if complex_values:
        a = a + 1j * sp.random(n, n, density=8.0 / n, random_state=rng, format="csr")
    a = sp.csr_matrix(a + a.T + sp.identity(n) * 10.0)
    a.sum_duplicates()
    return a


def _fixing(n: int, dofs) -> sp.csr_matrix:
    """Relations u[dof] = 0."""
    dofs = np.asarray(dofs)
    return sp.csr_matrix((np.ones(dofs.size), (np.arange(dofs.size), dofs)), shape=(dofs.size, n))


def _reduced(elimination, matrix):
    t = elimination.T
    return sp.csr_matrix(t.T @ (sp.csr_matrix(matrix) @ t))


def test_fixed_dofs_are_a_selection_and_relations_are_not():
    n = 30
    fixed = eliminate(_fixing(n, [0, 7, 29]), np.zeros(3), n)
    kept = pencil.selected_dofs(fixed.T)
    np.testing.assert_array_equal(kept, np.setdiff1d(np.arange(n), [0, 7, 29]))
    tied = sp.csr_matrix(([1.0, -1.0], ([0, 0], [3, 4])), shape=(1, n))  # u3 = u4
    assert pencil.selected_dofs(eliminate(tied, np.zeros(1), n).T) is None


@pytest.mark.parametrize("complex_values", [False, True])
def test_the_upper_triangle_of_a_selection_is_that_of_the_products(complex_values):
    n = 200
    a = _symmetric(n, 3, complex_values)
    elimination = eliminate(_fixing(n, [0, 50, 51, 199]), np.zeros(4), n)
    kept = pencil.selected_dofs(elimination.T)
    upper = pencil.selected_upper(a, kept)
    expected = sp.triu(_reduced(elimination, a), format="csc")
    expected.sum_duplicates()
    np.testing.assert_array_equal(upper.indptr, expected.indptr)
    np.testing.assert_array_equal(upper.indices, expected.indices)
    np.testing.assert_array_equal(upper.data, expected.data)  # bit for bit


def test_symmetry_is_judged_on_the_kept_dofs_as_on_the_reduced_matrix():
    n = 120
    a = _symmetric(n, 5).tolil()
    elimination = eliminate(_fixing(n, [10]), np.zeros(1), n)
    kept = pencil.selected_dofs(elimination.T)
    a[10, 11] += 1.0  # asymmetric on an eliminated row only: the reduced one is symmetric
    a[30, 40] += 1e-15 * abs(a[30, 40])  # within the tolerance
    a = sp.csr_matrix(a)
    assert pencil.selected_upper(a, kept, 1e-13) is not None
    assert ldl.is_symmetric(_reduced(elimination, a), 1e-13)
    b = a.tolil()
    b[30, 41] = 5.0  # a term without its transpose
    b = sp.csr_matrix(b)
    assert pencil.selected_upper(b, kept, 1e-13) is None
    assert not ldl.is_symmetric(_reduced(elimination, b), 1e-13)


def test_a_sweep_under_fixed_dofs_builds_the_products_pencil_without_them(monkeypatch):
    n = 1500  # physical.LDL_MIN_SIZE and more: the pencil is kept as upper triangles
    stiffness = _symmetric(n, 7, complex_values=True)
    mass = sp.csr_matrix(sp.diags(np.linspace(1.0, 2.0, n)) + sp.eye(n, k=3) * 0.1)
    mass = sp.csr_matrix(mass + mass.T)
    elimination = eliminate(_fixing(n, [0, 1, 700]), np.zeros(3), n)
    expected = physical.aligned_pencil(
        _reduced(elimination, stiffness), _reduced(elimination, mass), None, upper=True
    )

    def refused(*args, **kwargs):
        raise AssertionError("a whole reduced matrix was built")

    # neither the products Tᵀ A T nor the symmetry test of their result
    monkeypatch.setattr(physical.ldl, "is_symmetric", refused)
    monkeypatch.setattr(physical, "aligned_pencil", refused)
    sweep = physical.prepare(elimination, stiffness, mass)
    got = sweep.pencil
    assert got.upper and sweep.symmetric
    for name in ("indptr", "indices", "stiffness", "mass"):
        np.testing.assert_array_equal(getattr(got, name), getattr(expected, name), err_msg=name)
    assert got.damping is None


def test_the_values_of_a_frequency_are_written_into_the_solvers_array():
    n = 1200
    stiffness = _symmetric(n, 11, complex_values=True)
    damping = _symmetric(n, 12)
    built = physical.aligned_pencil(stiffness, sp.identity(n), damping, upper=True)
    into = np.empty(built.indices.size, dtype=complex)
    assert built.data(7.5, out=into) is into
    np.testing.assert_array_equal(into, built.data(7.5))


@pytest.mark.parametrize("complex_values", [False, True])
def test_the_triangle_read_by_blocks_of_rows_from_disk_is_the_same(complex_values, monkeypatch):
    from asterlite.fem import matrix_rows
    from asterlite.io import disk_rows
    from asterlite.runtime.result_paging import to_disk

    n = 300
    a = _symmetric(n, 11, complex_values)
    kept = pencil.selected_dofs(eliminate(_fixing(n, [0, 150, 299]), np.zeros(3), n).T)
    whole = pencil.selected_upper(a, kept, 1e-13)
    paged = sp.csr_matrix(a, copy=True)
    paged.data, paged.indices = to_disk(paged.data), to_disk(paged.indices)
    released = []
    release = disk_rows.release_pages
    monkeypatch.setattr(disk_rows, "release_pages", lambda: released.append(1) or release())
    monkeypatch.setattr(matrix_rows, "BLOCK_TERMS", 100)
    blocks = pencil.selected_upper(paged, kept, 1e-13)
    for name in ("indptr", "indices", "data"):
        np.testing.assert_array_equal(getattr(blocks, name), getattr(whole, name))
    # three passes over the matrix (count, place, compare), the pages given back after each block
    assert len(released) == 3 * len(list(matrix_rows.blocks(a.indptr)))
    b = a.tolil()
    b[20, 250] += 1e-6 * abs(a).max()  # far from the diagonal: another block of rows
    assert pencil.selected_upper(sp.csr_matrix(b), kept, 1e-13) is None
    assert pencil.selected_upper(sp.csr_matrix(b), kept, 1e-6) is not None
