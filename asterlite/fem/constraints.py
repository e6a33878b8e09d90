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

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp


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
        """Tᵀ A T."""
        return sp.csr_matrix(self.T.T @ (matrix @ self.T))

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
    fixed = np.unique(fixed_dof)
    u0[fixed_dof] = fixed_val
    is_fixed = np.zeros(n_dofs, dtype=bool)
    is_fixed[fixed] = True

    multi = np.flatnonzero(counts > 1)
    slaves = np.array([], dtype=int)
    slave_solve = np.zeros((0, multi.size))
    slave_rows = None  # dense (n_slaves, n_masters_touched)
    touched_masters = np.array([], dtype=int)
    if multi.size:
        sub = b_matrix[multi]
        # move fixed DOFs to the right-hand side
        rhs_multi = rhs[multi] - sub @ u0
        touched = np.unique(sub.indices)
        touched = touched[~is_fixed[touched]]
        dense = sub[:, touched].toarray()
        if touched.size:
            _, r_factor, perm = sla.qr(dense, mode="economic", pivoting=True)
            diag = np.abs(np.diag(r_factor))
            rank = int(np.sum(diag > tol * max(diag.max(initial=0.0), 1e-300)))
        else:
            rank, perm = 0, np.array([], dtype=int)
        slave_cols, master_cols = perm[:rank], perm[rank:]
        if rank:
            bs, bm = dense[:, slave_cols], dense[:, master_cols]
            # least squares is exact for consistent (possibly redundant) relations
            coef, *_ = np.linalg.lstsq(bs, np.column_stack([rhs_multi, -bm]), rcond=None)
            residual = bs @ coef[:, 0] - rhs_multi
            if np.linalg.norm(residual) > 1e-8 * (1 + np.linalg.norm(rhs_multi)):
                raise ConstraintError("the linear relations are incompatible")
            slaves = touched[slave_cols]
            touched_masters = touched[master_cols]
            slave_solve = np.linalg.pinv(bs)
            u0[slaves] = coef[:, 0]
            slave_rows = coef[:, 1:]
        elif np.linalg.norm(rhs_multi) > 1e-8:
            raise ConstraintError("the linear relations are incompatible")

    removed = np.zeros(n_dofs, dtype=bool)
    removed[fixed] = True
    removed[slaves] = True
    free = np.flatnonzero(~removed)
    column_of = -np.ones(n_dofs, dtype=int)
    column_of[free] = np.arange(free.size)
    rows = [free]
    cols = [np.arange(free.size)]
    vals = [np.ones(free.size)]
    if slaves.size and touched_masters.size:
        nz_r, nz_c = np.nonzero(np.abs(slave_rows) > 0)
        rows.append(slaves[nz_r])
        cols.append(column_of[touched_masters[nz_c]])
        vals.append(slave_rows[nz_r, nz_c])
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
