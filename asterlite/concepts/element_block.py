"""Element matrices of a set of cells, kept half when they are symmetric.

Most options give symmetric element matrices (stiffness, mass, damping);
code_aster stores those as their upper triangle (``MATR_ELEM`` of a
symmetric option). A block here does the same: given whole matrices that
are symmetric to round-off, it keeps the upper triangle of each, packed row
by row (d (d + 1) / 2 values instead of d²), which halves what a large
solid model holds between ``CALC_MATR_ELEM`` and its assembly. Blocks of
less than ``PACK_BYTES`` and other matrices (gyroscopic, non-symmetric
discrete elements) are kept whole.
Readers that need whole matrices get them from :attr:`ElementBlock.matrices`
(a new array for a packed block) or, a few elements at a time, from
:meth:`ElementBlock.chunk`; the assembly reads the packed terms directly.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

#: |A - Aᵀ| below this fraction of max |A| (per element) is round-off: the
#: block is symmetric and kept as its upper triangle
SYMMETRY_TOLERANCE = 1.0e-12
#: elements compared, packed or unpacked at once (bounds the temporaries)
CHUNK_ELEMENTS = 256
#: whole matrices of a block above this size are kept half when symmetric;
#: smaller blocks stay whole (they cost little, and their assembly keeps
#: the round-off of both triangles, as before: some decks' results are
#: sensitive to it)
PACK_BYTES = 16 * 1024 * 1024


@lru_cache(maxsize=64)
def upper_indices(d: int) -> tuple[np.ndarray, np.ndarray]:
    """Row and column of each packed term (upper triangle, row by row)."""
    rows, cols = np.triu_indices(d)
    rows.flags.writeable = cols.flags.writeable = False
    return rows, cols


def is_symmetric(matrices: np.ndarray, tolerance: float = SYMMETRY_TOLERANCE) -> bool:
    """Whether every (d, d) matrix of ``matrices`` is symmetric to
    ``tolerance`` times its own largest magnitude."""
    if matrices.ndim != 3 or matrices.shape[1] != matrices.shape[2]:
        return False
    for start in range(0, len(matrices), CHUNK_ELEMENTS):
        part = matrices[start : start + CHUNK_ELEMENTS]
        asymmetry = np.abs(part - part.transpose(0, 2, 1)).max(axis=(1, 2))
        if np.any(asymmetry > tolerance * np.abs(part).max(axis=(1, 2))):
            return False
    return True


def pack(matrices: np.ndarray) -> np.ndarray:
    """(n, d, d) symmetric matrices -> (n, d (d + 1) / 2) upper triangles."""
    rows, cols = upper_indices(matrices.shape[1])
    return np.ascontiguousarray(matrices[:, rows, cols])


def unpack(packed: np.ndarray, d: int) -> np.ndarray:
    """(n, d (d + 1) / 2) upper triangles -> (n, d, d) symmetric matrices."""
    rows, cols = upper_indices(d)
    out = np.empty((len(packed), d, d), dtype=packed.dtype)
    out[:, rows, cols] = packed
    out[:, cols, rows] = packed
    return out


class ElementBlock:
    """Matrices of a set of cells sharing nodes-per-cell and components, in the
    global frame: ``matrices[e]`` acts on the DOFs of ``nodes[e]`` ordered
    node by node, ``components`` within each node.

    Symmetric matrices are stored as packed upper triangles (``packed``,
    (n_elements, d (d + 1) / 2)); ``matrices`` then builds the whole ones.
    """

    __slots__ = ("nodes", "components", "size", "packed", "_whole")

    def __init__(self, nodes, components, matrices=None, *, packed=None):
        self.nodes = nodes  # (n_elements, nodes_per_element) node indices
        self.components = tuple(components)
        if (matrices is None) == (packed is None):
            raise ValueError("an element block takes either matrices or packed upper triangles")
        if packed is not None:
            self.size = int(np.shape(nodes)[1]) * len(self.components)
            expected = self.size * (self.size + 1) // 2
            packed = np.asarray(packed)
            if packed.ndim != 2 or packed.shape[1] != expected:
                raise ValueError(
                    f"packed element matrices of {self.size} DOFs need {expected} terms"
                )
            self.packed, self._whole = packed, None
            return
        matrices = np.asarray(matrices)
        self.size = int(matrices.shape[1]) if matrices.ndim == 3 else 0
        if matrices.nbytes > PACK_BYTES and is_symmetric(matrices):
            self.packed, self._whole = pack(matrices), None
        else:
            self.packed, self._whole = None, matrices

    def __len__(self) -> int:
        return len(self.packed) if self.packed is not None else len(self._whole)

    @property
    def symmetric(self) -> bool:
        return self.packed is not None

    @property
    def dtype(self):
        return (self.packed if self.packed is not None else self._whole).dtype

    @property
    def nbytes(self) -> int:
        return (self.packed if self.packed is not None else self._whole).nbytes

    @property
    def matrices(self) -> np.ndarray:
        """(n_elements, d, d) whole matrices (built anew for a packed block)."""
        if self.packed is None:
            return self._whole
        return unpack(self.packed, self.size)

    def chunk(self, start: int, stop: int) -> np.ndarray:
        """The whole matrices of elements ``start:stop``."""
        if self.packed is None:
            return self._whole[start:stop]
        return unpack(self.packed[start:stop], self.size)

    def scaled(self, factor) -> ElementBlock:
        """The same cells with every matrix times ``factor`` (kept packed)."""
        if self.packed is not None:
            return ElementBlock(self.nodes, self.components, packed=self.packed * factor)
        return ElementBlock(self.nodes, self.components, self._whole * factor)

    def __repr__(self) -> str:
        storage = "packed upper triangles" if self.symmetric else "whole"
        return f"ElementBlock({len(self)} elements of {self.size} DOFs, {storage})"


def computed_block(nodes, components, compute, chunk: int = CHUNK_ELEMENTS) -> ElementBlock:
    """The block of the cells ``nodes`` whose matrices ``compute(start, stop)``
    gives a few cells at a time: whole matrices of a large model never exist
    at once when they are symmetric (each chunk is packed as it comes)."""
    n_elements = len(nodes)
    parts, symmetric = [], True
    for start in range(0, n_elements, chunk):
        part = np.asarray(compute(start, min(start + chunk, n_elements)))
        if start == 0:  # the whole block's size decides whether it is kept half
            symmetric = part[:1].nbytes * n_elements > PACK_BYTES
        if symmetric and is_symmetric(part):
            parts.append(pack(part))
            continue
        if symmetric:  # unpack what was kept half: the block is kept whole
            size = part.shape[1]
            parts = [unpack(p, size) for p in parts]
            symmetric = False
        parts.append(part)
    if not parts:
        return ElementBlock(nodes, components, np.asarray(compute(0, 0)))
    if symmetric:
        return ElementBlock(nodes, components, packed=np.concatenate(parts))
    return ElementBlock(nodes, components, np.concatenate(parts))
