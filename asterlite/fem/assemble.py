"""Sparse assembly of element blocks and nodal terms on a DOF numbering."""

from __future__ import annotations

from functools import lru_cache

import numpy as np
import scipy.sparse as sp

from asterlite.concepts.assembly import DofNumbering, ElementBlock
from asterlite.concepts.element_block import upper_indices


def build_numbering_dofs(node_components: dict[int, tuple[str, ...]]) -> list[tuple[int, str]]:
    """DOF list ordered node by node (mesh order), components in code_aster order."""
    return [(node, comp) for node in sorted(node_components) for comp in node_components[node]]


def dof_table(numbering: DofNumbering) -> tuple[np.ndarray, dict[str, int]]:
    """(n_nodes, n_components) array of DOF indices (-1 where a node lacks the
    component) and the column of each component: a vectorised lookup, kept on
    the numbering while its DOF list is unchanged."""
    cached = getattr(numbering, "_dof_table", None)
    if cached is not None and cached[0] == len(numbering.dofs):
        return cached[1], cached[2]
    columns: dict[str, int] = {}
    for _, comp in numbering.dofs:
        columns.setdefault(comp, len(columns))
    table = -np.ones((numbering.mesh.n_nodes, max(len(columns), 1)), dtype=np.int64)
    if numbering.dofs:
        nodes = np.fromiter((n for n, _ in numbering.dofs), dtype=np.int64)
        cols = np.fromiter((columns[c] for _, c in numbering.dofs), dtype=np.int64)
        table[nodes, cols] = np.arange(len(numbering.dofs))
    numbering._dof_table = (len(numbering.dofs), table, columns)
    return table, columns


def block_dof_indices(block: ElementBlock, numbering: DofNumbering) -> np.ndarray:
    """(n_elements, d) numbering indices of each element's DOFs (-1 if absent)."""
    n_el = block.nodes.shape[0]
    table, columns = dof_table(numbering)
    if any(c not in columns for c in block.components):
        # a component no DOF carries: absent everywhere
        cols = [columns.get(c, -1) for c in block.components]
        out = table[block.nodes[:, :, None], np.maximum(cols, 0)[None, None, :]]
        out[:, :, np.asarray(cols) < 0] = -1
        return out.reshape(n_el, -1)
    cols = np.array([columns[c] for c in block.components], dtype=np.int64)
    return table[block.nodes[:, :, None], cols[None, None, :]].reshape(n_el, -1)


#: raw element terms summed at once: the assembled matrix is built chunk by
#: chunk so that the coordinate arrays of a large solid model (tens of
#: millions of terms, complex for RIGI_MECA_HYST) never exist whole
CHUNK_TERMS = 2_000_000


def assemble_blocks(
    blocks: list[ElementBlock], numbering: DofNumbering, consume: bool = False
) -> sp.csr_matrix:
    """Sum the element matrices into an (n_dofs, n_dofs) CSR matrix (a
    block kept as upper triangles gives each off-diagonal term to both
    halves: the matrix is symmetric up to the order of its sums, a term
    summed from three elements or more possibly differing from its
    transpose in its last bit). ``consume``: the list is the caller's to
    give up (element matrices made again for this assembly): each block
    leaves it, and memory, once its terms are summed."""
    n = numbering.n_dofs
    matrix = None
    pending = blocks if consume else list(blocks)
    while pending:
        block = pending.pop(0)
        if not len(block):
            continue
        idx = block_dof_indices(block, numbering)
        if np.any(idx < 0):
            raise KeyError("element DOF missing from the numbering")
        # 32-bit indices halve the memory of large solid models
        idx = idx.astype(np.int32 if n < 2**31 - 1 else np.int64)
        summed = _node_pair_matrix(block, idx, n) if block.symmetric else None
        if summed is not None:
            matrix = summed if matrix is None else matrix + summed
            del summed
        else:
            for chunk in _block_chunks(block, idx, n):
                matrix = chunk if matrix is None else matrix + chunk
                del chunk  # not held while the next one is built
        del block, idx
    if matrix is None:
        return sp.csr_matrix((n, n))
    matrix = sp.csr_matrix(matrix)
    matrix.sum_duplicates()
    matrix.eliminate_zeros()
    return compacted(matrix)


def compacted(matrix: sp.csr_matrix) -> sp.csr_matrix:
    """The matrix with arrays of its own size: a sparse sum allocates room
    for the terms of both operands, and scipy keeps the result as views of
    that room while it is half used or more (sdlv126h's hysteretic
    stiffness: 16 MB unused beside its 79 MB, for as long as the matrix
    lives)."""
    for name in ("indices", "data"):
        array = getattr(matrix, name)
        if array.base is not None and array.base.nbytes > array.nbytes:
            setattr(matrix, name, array.copy())
    return matrix


@lru_cache(maxsize=16)
def _packed_positions(nodes: int, components: int) -> np.ndarray:
    """(nodes, components, nodes, components) position in a packed upper
    triangle of each term of a symmetric element matrix (the transposed
    term's below the diagonal)."""
    d = nodes * components
    rows, cols = upper_indices(d)
    table = np.empty((d, d), dtype=np.intp)
    table[rows, cols] = table[cols, rows] = np.arange(rows.size)
    table = table.reshape(nodes, components, nodes, components)
    table.flags.writeable = False
    return table


def _summed(where: np.ndarray, values: np.ndarray, size: int) -> np.ndarray:
    """``values`` summed by ``where`` into ``size`` slots, in their order."""
    if np.iscomplexobj(values):
        out = np.empty(size, dtype=values.dtype)
        out.real = np.bincount(where, values.real, size)
        out.imag = np.bincount(where, values.imag, size)
        return out
    return np.bincount(where, values, size)


def _node_pair_matrix(block: ElementBlock, idx: np.ndarray, n: int) -> sp.csr_matrix | None:
    """The (n, n) CSR matrix of a symmetric block, built as code_aster's
    assembly is: the pattern first, node pair by node pair (every component
    of a node couples with every one of its neighbours': a ninth of the
    sorting of a 3D solid's terms), then each term of the element matrices
    summed into its place, element after element (both halves of the
    matrix from the same packed terms in the same order: exactly symmetric
    unless a cell repeats a node).
    None when the block's DOFs are not numbered node after node, components
    in the block's order (the caller then sums the terms chunk by chunk)."""
    nodes = np.asarray(block.nodes)
    count, per_cell = nodes.shape
    c = len(block.components)
    if not count or not c or idx.shape[1] != per_cell * c:
        return None
    unique_nodes, local = np.unique(nodes, return_inverse=True)
    local = local.reshape(count, per_cell)
    u = len(unique_nodes)
    dofs = np.empty((u, c), dtype=np.int64)
    dofs[local.ravel()] = idx.reshape(count * per_cell, c)
    flat = dofs.ravel()
    if np.any(flat[1:] <= flat[:-1]):
        return None
    # the pattern: node pairs of every cell, sorted (first node, second node)
    keys = local[:, :, None] * np.int64(u) + local[:, None, :]
    pairs, where = np.unique(keys.ravel(), return_inverse=True)
    del keys
    where = where.ravel()
    first, second = np.divmod(pairs, u)
    degree = np.bincount(first, minlength=u)
    start = np.zeros(u, dtype=np.int64)
    np.cumsum(degree[:-1], out=start[1:])
    # a pair's place within its first node's rows, components of the second after each other
    offset = (np.arange(len(pairs), dtype=np.int64) - start[first]) * c
    counts = np.zeros(n, dtype=np.int64)
    counts[flat] = np.repeat(degree * c, c)
    index_type = np.int32 if int(counts.sum()) < 2**31 - 1 and n < 2**31 - 1 else np.int64
    indptr = np.zeros(n + 1, dtype=index_type)
    np.cumsum(counts, out=indptr[1:])
    del counts
    data = np.zeros(int(indptr[-1]), dtype=block.dtype)
    indices = np.empty(int(indptr[-1]), dtype=index_type)
    columns = dofs[second]
    positions = _packed_positions(per_cell, c)
    for i in range(c):
        place = (indptr[dofs[first, i]] + offset)[:, None] + np.arange(c)
        indices[place] = columns
        for j in range(c):
            values = block.packed[:, positions[:, i, :, j].ravel()]
            if values.any():  # a mass couples no two directions: its zeros stay
                data[place[:, j]] = _summed(where, values.ravel(), len(pairs))
            del values
    return sp.csr_matrix((data, indices, indptr), shape=(n, n))


def _block_chunks(block: ElementBlock, idx: np.ndarray, n: int):
    """The block's terms as (n, n) CSR matrices of about ``CHUNK_TERMS`` terms each."""
    d = idx.shape[1]
    if block.symmetric:
        upper_rows, upper_cols = upper_indices(d)
        off = upper_rows != upper_cols
        local_rows = np.concatenate([upper_rows, upper_cols[off]])
        local_cols = np.concatenate([upper_cols, upper_rows[off]])
        terms = np.concatenate([np.arange(upper_rows.size), np.flatnonzero(off)])
    step = max(1, CHUNK_TERMS // (d * d))
    for start in range(0, len(idx), step):
        part = idx[start : start + step]
        if block.symmetric:
            rows = part[:, local_rows].ravel()
            cols = part[:, local_cols].ravel()
            vals = block.packed[start : start + step][:, terms].ravel()
        else:
            rows = np.repeat(part, d, axis=1).ravel()
            cols = np.tile(part, (1, d)).ravel()
            vals = block.chunk(start, start + step).reshape(len(part), -1).ravel()
        summed = sp.coo_matrix((vals, (rows, cols)), shape=(n, n)).tocsr()
        del rows, cols, vals  # the triplets are not held while the caller adds
        yield summed
        del summed


def assemble_terms(terms, numbering: DofNumbering) -> np.ndarray:
    """Nodal (node, component, value) terms summed into a vector on the numbering."""
    values = np.array([t[2] for t in terms])
    vector = np.zeros(numbering.n_dofs, dtype=complex if np.iscomplexobj(values) else float)
    if not terms:
        return vector
    nodes = [t[0] for t in terms]
    comps = [t[1] for t in terms]
    idx = numbering.dof_indices(nodes, comps)
    if np.any(idx < 0):
        names = numbering.mesh.node_names
        missing = [f"{names[n]} {c}" for n, c, i in zip(nodes, comps, idx, strict=True) if i < 0]
        raise KeyError(", ".join(missing[:5]))
    np.add.at(vector, idx, values.astype(vector.dtype))
    return vector
