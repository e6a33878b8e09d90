"""code_aster 16-17's ``toNumpy()``/``fromNumpy()`` of matrices, for decks.

A deck gets a dense copy of the values (never the concept's own array), of
at most the evaluator's element limit; ``fromNumpy`` replaces a
generalized matrix's values by a deck's array of the same shape and kind,
finite. An assembled matrix whose numbering has constraints is refused:
code_aster's holds Lagrange multiplier rows and columns for them, which
asterlite does not build (it keeps constraints as relations).
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


def assembled_to_numpy(assembled) -> np.ndarray:
    numbering = assembled.numbering
    if numbering.relations:
        raise UnsupportedError(
            f"{assembled.name or 'matrix'}.toNumpy(): code_aster's matrix holds Lagrange "
            f"multiplier rows and columns for the {len(numbering.relations)} constraints of "
            "its numbering (AFFE_CHAR_MECA's DDL_IMPO, LIAISON_*), which asterlite keeps as "
            "relations and does not build"
        )
    return dense_copy(assembled.matrix, assembled.name or "matrix")


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
