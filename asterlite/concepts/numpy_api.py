"""code_aster 16-17's ``toNumpy()``/``fromNumpy()`` of matrices, for decks.

A deck gets a dense copy of the values (never the concept's own array), of
at most the evaluator's element limit; ``fromNumpy`` replaces a
generalized matrix's values by a deck's array of the same shape and kind,
finite. An assembled matrix shows the DOFs its kinematic loads
(ASSE_MATRICE CHAR_CINE) impose as code_aster's toNumpy does: their rows and
columns zero, their diagonal term one. A numbering with dualised constraints
(AFFE_CHAR_MECA) is refused: code_aster's matrix holds Lagrange multiplier
rows and columns for them, which asterlite does not build (it keeps those
constraints as relations).
"""

from __future__ import annotations

import numpy as np

from asterlite.errors import DeckRuntimeError, UnsupportedError
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
    """Rows of the DOFs the matrix's kinematic loads impose; refused when the
    numbering also has dualised constraints (Lagrange multipliers)."""
    numbering = assembled.numbering
    kinematic = {id(relation) for load in numbering.kinematic_loads for relation in load.relations}
    dualised = [r for r in numbering.relations if id(r) not in kinematic]
    if dualised:
        raise UnsupportedError(
            f"{assembled.name or 'matrix'}.toNumpy(): code_aster's matrix holds Lagrange "
            f"multiplier rows and columns for the {len(dualised)} constraints of "
            "its numbering (AFFE_CHAR_MECA's DDL_IMPO, LIAISON_*), which asterlite keeps as "
            "relations and does not build"
        )
    rows = {
        numbering.index[(node, comp)]
        for load in numbering.kinematic_loads
        for relation in load.relations
        for node, comp, _coef in relation.terms
    }
    return np.array(sorted(rows), dtype=int)


def assembled_to_numpy(assembled) -> np.ndarray:
    eliminated = _eliminated_dofs(assembled)
    dense = dense_copy(assembled.matrix, assembled.name or "matrix")
    if eliminated.size:
        dense[eliminated, :] = 0.0
        dense[:, eliminated] = 0.0
        dense[eliminated, eliminated] = 1.0
    return dense


def assembled_triplets(assembled, epsilon=None):
    """code_aster's getValuesWithDescription: (values, rows, columns, size) of
    the stored terms, the terms of magnitude below ``epsilon`` left out, the
    eliminated DOFs' rows and columns dropped and their unit diagonal terms
    first."""
    eliminated = _eliminated_dofs(assembled)
    matrix = assembled.matrix
    coo = matrix.tocoo() if hasattr(matrix, "tocoo") else None
    if coo is None:
        dense = np.asarray(matrix)
        rows, cols = np.nonzero(np.ones(dense.shape, dtype=bool))
        data = dense[rows, cols]
    else:
        rows, cols, data = coo.row.astype(int), coo.col.astype(int), coo.data
    limit = Limits().max_sequence_length
    if data.size > limit:
        raise DeckRuntimeError(
            f"limit exceeded: {assembled.name or 'matrix'} has {data.size} terms (limit {limit:,})"
        )
    if epsilon is not None:
        kept = np.abs(data) >= float(epsilon)
        rows, cols, data = rows[kept], cols[kept], data[kept]
    if eliminated.size:
        kept = ~np.isin(rows, eliminated) & ~np.isin(cols, eliminated)
        rows = np.concatenate([eliminated, rows[kept]])
        cols = np.concatenate([eliminated, cols[kept]])
        data = np.concatenate([np.ones(eliminated.size, dtype=data.dtype), data[kept]])
    return data, rows, cols, matrix.shape[0]


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
