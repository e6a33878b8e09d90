"""code_aster 16-17's ``toNumpy()``/``fromNumpy()`` of matrices, for decks.

A deck gets a dense copy of the values (never the concept's own array), of
at most the evaluator's element limit; ``fromNumpy`` replaces a
generalized matrix's values by a deck's array of the same shape and kind,
finite. An assembled matrix is shown as code_aster's toNumpy shows it: on
its numbering with the Lagrange multipliers of the dualised constraints
(AFFE_CHAR_MECA, see asterlite.fem.lagrange_layout), the DOFs its kinematic
loads (ASSE_MATRICE CHAR_CINE) impose with zero rows and columns and a unit
diagonal term.
"""

from __future__ import annotations

import numpy as np

from asterlite.errors import DeckRuntimeError
from asterlite.fem.lagrange_layout import full_matrix, lagrange_layout
from asterlite.lang.limits import Limits


def dense_copy(matrix, what: str) -> np.ndarray:
    """A dense copy of a (sparse or dense) square matrix, within the limit."""
    rows, columns = matrix.shape
    limit = Limits().max_sequence_length
    if rows * columns > limit:
        raise DeckRuntimeError(
            f"limit exceeded: {what}.toNumpy() would make {rows} x {columns} values "
            f"(limit {limit:,})"
        )
    if hasattr(matrix, "toarray"):
        return matrix.toarray()
    return np.array(matrix, copy=True)


def _eliminated_dofs(assembled) -> np.ndarray:
    """Rows (physical numbering) of the DOFs the matrix's kinematic loads impose."""
    numbering = assembled.numbering
    rows = {
        numbering.index[(node, comp)]
        for load in numbering.kinematic_loads
        for relation in load.relations
        for node, comp, _coef in relation.terms
    }
    return np.array(sorted(rows), dtype=int)


def assembled_to_numpy(assembled) -> np.ndarray:
    """code_aster's toNumpy(): with dualised constraints, the matrix on its
    numbering with Lagrange multipliers (asterlite.fem.lagrange_layout: the
    stiffness carries the double-Lagrange terms, the other matrices zeros);
    the DOFs the kinematic loads impose eliminated (zero rows and columns,
    unit diagonal)."""
    numbering = assembled.numbering
    layout = lagrange_layout(numbering)
    limit = Limits().max_sequence_length
    if layout.size**2 > limit:
        raise DeckRuntimeError(
            f"limit exceeded: {assembled.name or 'matrix'}.toNumpy() would make "
            f"{layout.size} x {layout.size} values (limit {limit:,})"
        )
    dense = dense_copy(assembled.matrix, assembled.name or "matrix")
    if layout.relations:
        dense = full_matrix(assembled, dense, with_load_terms=assembled.kind == "RIGI")
    eliminated = layout.physical[_eliminated_dofs(assembled)]
    if eliminated.size:
        dense[eliminated, :] = 0.0
        dense[:, eliminated] = 0.0
        dense[eliminated, eliminated] = 1.0
    return dense


def assembled_triplets(assembled, epsilon=None):
    """code_aster's getValuesWithDescription: (values, rows, columns, size) of
    the stored terms of toNumpy()'s matrix, the terms of magnitude below
    ``epsilon`` left out, the eliminated DOFs' unit diagonal terms first."""
    dense = assembled_to_numpy(assembled)
    eliminated = lagrange_layout(assembled.numbering).physical[_eliminated_dofs(assembled)]
    keep = dense != 0.0
    if epsilon is not None:
        keep &= np.abs(dense) >= float(epsilon)
    keep[eliminated, :] = False
    keep[:, eliminated] = False
    rows, cols = np.nonzero(keep)
    data = dense[rows, cols]
    if eliminated.size:
        rows = np.concatenate([eliminated, rows])
        cols = np.concatenate([eliminated, cols])
        data = np.concatenate([np.ones(eliminated.size, dtype=data.dtype), data])
    return data, rows, cols, dense.shape[0]


def replaced_values(matrix, values, what: str) -> np.ndarray:
    """``values`` checked to replace the dense array ``matrix`` (fromNumpy)."""
    if not isinstance(values, np.ndarray):
        raise DeckRuntimeError(f"{what}.fromNumpy takes a numpy array")
    if values.shape != matrix.shape:
        raise DeckRuntimeError(
            f"{what}.fromNumpy: a {values.shape} array for a {matrix.shape} matrix"
        )
    if values.dtype.kind not in "biufc" or (values.dtype.kind == "c" and matrix.dtype.kind != "c"):
        raise DeckRuntimeError(f"{what}.fromNumpy: {values.dtype} values for a real matrix")
    if not np.all(np.isfinite(values)):
        raise DeckRuntimeError(f"{what}.fromNumpy: the array holds non-finite values")
    return np.array(values, dtype=matrix.dtype, copy=True)
