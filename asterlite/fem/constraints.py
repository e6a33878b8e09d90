"""Linear kinematic relations B u = b and their elimination.

code_aster dualises DDL_IMPO / LIAISON_DDL with Lagrange multipliers. For an
eigenproblem or a static solve this is equivalent to restricting u to the
affine set {u = T q + u0}, where the columns of T span the null space of B.
T is built sparse by master/slave elimination:

1. single-term relations (``DDL_IMPO``) fix their DOF: the column is dropped;
2. the remaining relations, restricted to the DOFs they touch, are reduced
   by a column-pivoted QR: pivot columns become slaves, expressed through
   the masters; untouched DOFs stay identity columns.

So T has one column per free DOF and only the relations' DOFs get extra
entries: K and M stay sparse after the projection Tᵀ K T.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
from scipy.sparse.csgraph import connected_components

from asterlite.arrays import sorted_unique


class ConstraintError(ValueError):
    """Incompatible relations (e.g. two different imposed values on one DOF)."""


def relation_matrix(relations, index: dict, n_dofs: int) -> tuple[sp.csr_matrix, np.ndarray]:
    """(B, b) of the relations on a numbering's ``index[(node, component)]``."""
    rows, cols, vals = [], [], []
    rhs = np.zeros(len(relations))
    for r, relation in enumerate(relations):
        for node, comp, coef in relation.terms:
            rows.append(r)
            cols.append(index[(node, comp)])
            vals.append(coef)
        rhs[r] = relation.rhs
    b_matrix = sp.coo_matrix((vals, (rows, cols)), shape=(len(relations), n_dofs)).tocsr()
    b_matrix.sum_duplicates()
    return b_matrix, rhs


@dataclass
class Elimination:
    """u = T q + u0; ``free`` lists the DOFs kept as unknowns (masters)."""

    T: sp.csr_matrix  # (n_dofs, n_free)
    u0: np.ndarray  # (n_dofs,) a particular solution of B u = b
    free: np.ndarray  # (n_free,) indices of master DOFs
    constrained: np.ndarray  # DOFs removed (fixed or slaves)
    # what particular() needs to re-solve for another right-hand side
    b_matrix: sp.csr_matrix | None = None
    single_rows: np.ndarray | None = None  # relations fixing one DOF
    multi_rows: np.ndarray | None = None
    slaves: np.ndarray | None = None
    slave_solve: np.ndarray | None = None  # pseudo-inverse of the slave columns

    def particular(self, rhs: np.ndarray) -> np.ndarray:
        """u0 for other right-hand sides: (n_relations[, k]) -> (n_dofs[, k])."""
        rhs = np.asarray(rhs, dtype=float)
        n_dofs = self.T.shape[0]
        out = np.zeros((n_dofs,) + rhs.shape[1:])
        if self.b_matrix is None or self.b_matrix.shape[0] == 0:
            return out
        bm = self.b_matrix
        rows = self.single_rows
        if rows.size:
            dof = bm.indices[bm.indptr[rows]]
            coef = bm.data[bm.indptr[rows]]
            out[dof] = rhs[rows] / (coef if rhs.ndim == 1 else coef[:, None])
        if self.multi_rows.size and self.slaves.size:
            rest = rhs[self.multi_rows] - bm[self.multi_rows] @ out
            out[self.slaves] = self.slave_solve @ rest
        return out

    @property
    def n_free(self) -> int:
        return self.T.shape[1]

    def reduce(self, matrix) -> sp.csr_matrix:
        """Tᵀ A T (a copy of A when nothing is eliminated: T is the identity,
        and the products would hold two more copies of A at once). When T
        only selects the free DOFs (DOFs fixed, no relation between DOFs),
        Tᵀ A T is A's free rows and columns, taken as such from a real
        canonical A: the same terms, bit for bit, as the products give (each
        a single term times 1, zeros dropped), for a quarter of their time."""
        if self.constrained.size == 0 and self.T.shape[0] == self.T.shape[1]:
            reduced = sp.csr_matrix(matrix, copy=True)
            reduced.sum_duplicates()
            return reduced
        if self._selects_free and sp.issparse(matrix) and np.isrealobj(matrix.data):
            matrix = sp.csr_matrix(matrix)
            if matrix.has_canonical_format:
                reduced = matrix[self.free][:, self.free]
                reduced.eliminate_zeros()
                return reduced
        return sp.csr_matrix(self.T.T @ (matrix @ self.T))

    @cached_property
    def _selects_free(self) -> bool:
        """Whether T is the selection of the free DOFs (one 1 per row of a
        free DOF, in their order, nothing else)."""
        t = sp.csr_matrix(self.T)
        n_free = t.shape[1]
        if t.nnz != n_free or len(self.free) != n_free:
            return False
        rows = np.flatnonzero(np.diff(t.indptr))
        return bool(
            np.array_equal(rows, self.free)
            and np.array_equal(t.indices, np.arange(n_free))
            and np.all(t.data == 1.0)
        )

    def expand(self, q: np.ndarray) -> np.ndarray:
        """T q (+ u0 when q is a single vector of a static solve is wanted, add it yourself)."""
        return self.T @ q


def eliminate(
    b_matrix: sp.spmatrix, rhs: np.ndarray, n_dofs: int, tol: float = 1e-10
) -> Elimination:
    """Null-space parametrisation of {u : B u = b} (see module docstring)."""
    b_matrix = sp.csr_matrix(b_matrix)
    b_matrix.eliminate_zeros()
    u0 = np.zeros(n_dofs)
    if b_matrix.shape[0] == 0:
        eye = sp.identity(n_dofs, format="csr")
        return Elimination(eye, u0, np.arange(n_dofs), np.array([], dtype=int))

    counts = np.diff(b_matrix.indptr)
    if np.any(counts == 0):
        bad = np.flatnonzero(counts == 0)
        if np.any(np.abs(rhs[bad]) > 0):
            raise ConstraintError(
                "a relation with zero coefficients has a non-zero right-hand side"
            )
    single = np.flatnonzero(counts == 1)
    fixed_dof = b_matrix.indices[b_matrix.indptr[single]]
    fixed_val = rhs[single] / b_matrix.data[b_matrix.indptr[single]]
    # the same DOF fixed twice must get the same value
    order = np.argsort(fixed_dof, kind="stable")
    fixed_dof, fixed_val = fixed_dof[order], fixed_val[order]
    if fixed_dof.size:
        same = fixed_dof[1:] == fixed_dof[:-1]
        scale = np.maximum(np.abs(fixed_val[1:]), np.abs(fixed_val[:-1])) + 1e-300
        if np.any(same & (np.abs(fixed_val[1:] - fixed_val[:-1]) > 1e-8 * scale)):
            raise ConstraintError("one DOF is given two different imposed values")
    fixed = sorted_unique(fixed_dof)
    u0[fixed_dof] = fixed_val
    is_fixed = np.zeros(n_dofs, dtype=bool)
    is_fixed[fixed] = True

    multi = np.flatnonzero(counts > 1)
    slaves = np.array([], dtype=int)
    slave_solve = sp.csr_matrix((0, multi.size))
    slave_terms = (np.array([], dtype=int), np.array([], dtype=int), np.array([]))
    if multi.size:
        sub = b_matrix[multi]
        # move fixed DOFs to the right-hand side
        rhs_multi = rhs[multi] - sub @ u0
        touched = sorted_unique(sub.indices)
        touched = touched[~is_fixed[touched]]
        slaves, values, slave_terms, slave_solve = _eliminate_relations(
            sp.csr_matrix(sub[:, touched]), rhs_multi, tol
        )
        slaves = touched[slaves]
        u0[slaves] = values
        slave_terms = (slave_terms[0], touched[slave_terms[1]], slave_terms[2])

    removed = np.zeros(n_dofs, dtype=bool)
    removed[fixed] = True
    removed[slaves] = True
    free = np.flatnonzero(~removed)
    column_of = -np.ones(n_dofs, dtype=int)
    column_of[free] = np.arange(free.size)
    rows = [free]
    cols = [np.arange(free.size)]
    vals = [np.ones(free.size)]
    slave_of, master_of, coefficient = slave_terms
    kept = coefficient != 0.0
    rows.append(slaves[slave_of[kept]])
    cols.append(column_of[master_of[kept]])
    vals.append(coefficient[kept])
    t_matrix = sp.coo_matrix(
        (np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
        shape=(n_dofs, free.size),
    ).tocsr()
    return Elimination(
        t_matrix,
        u0,
        free,
        np.flatnonzero(removed),
        b_matrix=b_matrix,
        single_rows=single,
        multi_rows=multi,
        slaves=slaves,
        slave_solve=slave_solve,
    )


def _eliminate_relations(sub: sp.csr_matrix, rhs: np.ndarray, tol: float):
    """Slaves of the relations ``sub x = rhs`` (no DOF of x is fixed), by a
    column-pivoted QR of each group of relations that share DOFs: relations
    are mostly small and independent (LIAISON_GROUP pairs nodes one by one),
    so one dense QR of them all would cost O(n³) time and O(n²) memory for
    what is a block-diagonal problem. Pivoting inside a block picks the
    columns the global QR would, and ranks use the global largest pivot.

    Returns (slave columns, their particular values, the triplets (slave
    position, master column, coefficient) of x_slave = value + sum coef
    x_master, the sparse pseudo-inverse of the slave columns (n_slaves,
    n_relations))."""

    n_rows, n_cols = sub.shape
    sub = sp.csr_matrix(sub)
    sub.sort_indices()
    coo = sub.tocoo()
    graph = sp.coo_matrix(
        (np.ones(coo.nnz), (coo.row, n_rows + coo.col)), shape=(n_rows + n_cols,) * 2
    )
    _, labels = connected_components(graph, directed=False)
    row_labels, col_labels = labels[:n_rows], labels[n_rows:]
    row_order = np.argsort(row_labels, kind="stable")
    col_order = np.argsort(col_labels, kind="stable")
    row_bounds = _group_bounds(row_labels[row_order], labels.max() + 1)
    col_bounds = _group_bounds(col_labels[col_order], labels.max() + 1)
    blocks = []  # (rows, cols, dense, pivots, |diag of R|)
    for label in np.flatnonzero(np.diff(row_bounds) > 0):
        rows = row_order[row_bounds[label] : row_bounds[label + 1]]
        cols = col_order[col_bounds[label] : col_bounds[label + 1]]
        if not cols.size:
            blocks.append((rows, cols, None, np.array([], dtype=int), np.array([])))
        elif rows.size == 1:  # one relation: the pivot is its largest coefficient
            dense = sub[rows].toarray()[:, cols]
            pivot = int(np.argmax(np.abs(dense[0])))
            perm = np.concatenate([[pivot], np.delete(np.arange(cols.size), pivot)])
            blocks.append((rows, cols, dense, perm, np.abs(dense[0, [pivot]])))
        else:
            dense = sub[rows][:, cols].toarray()
            _, r_factor, perm = sla.qr(dense, mode="economic", pivoting=True)
            blocks.append((rows, cols, dense, perm, np.abs(np.diag(r_factor))))
    largest = max((d.max(initial=0.0) for *_, d in blocks), default=0.0)
    threshold = tol * max(largest, 1e-300)
    slave_cols, slave_values = [], []
    term_slave, term_master, term_coef = [], [], []
    solve_rows, solve_cols, solve_vals = [], [], []
    residual2 = 0.0
    n_slaves = 0
    for rows, cols, dense, perm, diag in blocks:
        rank = int(np.sum(diag > threshold))
        if not rank:
            residual2 += float(rhs[rows] @ rhs[rows])
            continue
        bs, bm = dense[:, perm[:rank]], dense[:, perm[rank:]]
        # least squares is exact for consistent (possibly redundant) relations
        coef, *_ = np.linalg.lstsq(bs, np.column_stack([rhs[rows], -bm]), rcond=None)
        residual = bs @ coef[:, 0] - rhs[rows]
        residual2 += float(residual @ residual)
        positions = n_slaves + np.arange(rank)
        slave_cols.append(cols[perm[:rank]])
        slave_values.append(coef[:, 0])
        masters = cols[perm[rank:]]
        term_slave.append(np.repeat(positions, masters.size))
        term_master.append(np.tile(masters, rank))
        term_coef.append(coef[:, 1:].ravel())
        inverse = np.linalg.pinv(bs)  # (rank, rows)
        solve_rows.append(np.repeat(positions, rows.size))
        solve_cols.append(np.tile(rows, rank))
        solve_vals.append(inverse.ravel())
        n_slaves += rank
    if np.sqrt(residual2) > 1e-8 * (1 + np.linalg.norm(rhs)):
        raise ConstraintError("the linear relations are incompatible")

    def joined(parts, dtype=float):
        return np.concatenate(parts).astype(dtype) if parts else np.array([], dtype=dtype)

    slave_solve = sp.coo_matrix(
        (joined(solve_vals), (joined(solve_rows, int), joined(solve_cols, int))),
        shape=(n_slaves, n_rows),
    ).tocsr()
    terms = (joined(term_slave, int), joined(term_master, int), joined(term_coef))
    return joined(slave_cols, int), joined(slave_values), terms, slave_solve


def _group_bounds(sorted_labels: np.ndarray, n_labels: int) -> np.ndarray:
    """Start of each label's run in ``sorted_labels`` (n_labels + 1 bounds)."""
    return np.searchsorted(sorted_labels, np.arange(n_labels + 1))
