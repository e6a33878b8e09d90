"""Sparse assembly of element blocks and nodal terms on a DOF numbering."""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
from scipy.sparse import _sparsetools

from asterlite import watchdog
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
    leaves it, and memory, once its terms are summed.

    The pattern comes first, from the elements' DOFs alone (code_aster's
    MORSE storage, made by NUME_DDL); each chunk of element terms is then
    added in place to the values on it, so that the matrix's values exist
    once, never beside a partial sum of the same size. Terms whose sum is
    exactly zero are not stored."""
    n = numbering.n_dofs
    # 32-bit indices halve the memory of large solid models
    index_type = np.int32 if n < 2**31 - 1 else np.int64
    pending = blocks if consume else list(blocks)
    dofs = []
    for block in pending:
        idx = block_dof_indices(block, numbering) if len(block) else None
        if idx is not None and np.any(idx < 0):
            raise KeyError("element DOF missing from the numbering")
        dofs.append(None if idx is None else idx.astype(index_type))
    if all(idx is None for idx in dofs):
        pending.clear()
        return sp.csr_matrix((n, n))
    pattern = _pattern([idx for idx in dofs if idx is not None], n)
    dtype = np.result_type(*(block.dtype for block in pending if len(block)))
    data = np.zeros(pattern.nnz, dtype=dtype)
    while pending:
        block, idx = pending.pop(0), dofs.pop(0)
        if idx is None:
            continue
        for chunk in _block_chunks(block, idx, n):
            places = _places(pattern, chunk)
            np.add.at(data, places, chunk.data)  # no gathered copy of the values
            del chunk, places  # not held while the next one is built
            watchdog.trim_allocator()  # the piece's freed temporaries leave the heap
        del block, idx
    indptr, indices = pattern.indptr, pattern.indices
    del pattern
    if indices.base is not None:
        indices = indices.copy()
    # zero sums out, in place; the arrays then shrink where they are (no copy)
    _sparsetools.csr_eliminate_zeros(n, n, indptr, indices, data)
    size = int(indptr[-1])
    if size < data.size:
        data.resize(size, refcheck=False)  # the function's own arrays: no view of them exists
        indices.resize(size, refcheck=False)
    return sp.csr_matrix((data, indices, indptr), shape=(n, n))


def _places(pattern: sp.csr_matrix, chunk: sp.csr_matrix) -> np.ndarray:
    """Where each stored term of ``chunk`` is among the terms of ``pattern``
    (canonical CSR, holding the chunk's pattern): scipy's own look-up of the
    terms of a CSR matrix by (row, column), as its item assignment does."""
    index_type = pattern.indices.dtype
    filled = np.flatnonzero(np.diff(chunk.indptr))
    if not filled.size:
        return np.zeros(0, dtype=index_type)
    # the pattern's rows the chunk has terms in (scipy searches each row's
    # sorted columns when there are many terms to look up among them)
    first, stop = int(filled[0]), int(filled[-1]) + 1
    lo, hi = int(pattern.indptr[first]), int(pattern.indptr[stop])
    indptr = (pattern.indptr[first : stop + 1] - lo).astype(index_type)
    counts = np.diff(chunk.indptr[first : stop + 1])
    rows = np.repeat(np.arange(stop - first, dtype=index_type), counts)
    cols = np.asarray(chunk.indices, dtype=index_type)
    places = np.empty(rows.size, dtype=index_type)
    _sparsetools.csr_sample_offsets(
        stop - first,
        pattern.shape[1],
        indptr,
        pattern.indices[lo:hi],
        rows.size,
        rows,
        cols,
        places,
    )
    if places.min() < 0:
        raise ValueError("a term outside the assembled pattern")
    places += lo
    return places


def _pattern(dofs: list[np.ndarray], n: int) -> sp.csr_matrix:
    """The (n, n) CSR pattern (canonical) of the terms that elements of DOFs
    ``dofs`` (one (n_elements, d) array a block) couple, a chunk of elements
    at a time."""
    pattern = None
    for idx in dofs:
        d = idx.shape[1]
        step = max(1, CHUNK_TERMS // (d * d))
        for start in range(0, len(idx), step):
            part = idx[start : start + step]
            rows = np.repeat(part, d, axis=1).ravel()
            cols = np.tile(part, (1, d)).ravel()
            ones = np.ones(rows.size, dtype=np.int8)
            chunk = sp.coo_matrix((ones, (rows, cols)), shape=(n, n)).tocsr()
            del rows, cols, ones
            chunk.data[:] = 1  # duplicates summed: back to ones
            if pattern is None:
                pattern = chunk
            else:
                pattern = pattern + chunk
                pattern.data[:] = 1  # no count grows past int8
            del chunk
    pattern.sum_duplicates()
    return compacted(pattern)


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


#: terms of a chunk turned into a CSR matrix at once: a chunk's terms are
#: summed by ranges of rows, each row's terms in the chunk's order (the sums
#: are those of the whole chunk's, bit for bit), a range of about this many
PIECE_TERMS = 125_000


def _block_chunks(block: ElementBlock, idx: np.ndarray, n: int):
    """The block's terms as (n, n) CSR matrices: chunks of about
    ``CHUNK_TERMS`` element terms (the grouping of the sums), each yielded
    as ranges of rows of about ``PIECE_TERMS`` terms."""
    d = idx.shape[1]
    if block.symmetric:
        upper_rows, upper_cols = upper_indices(d)
        off = upper_rows != upper_cols
        local_rows = np.concatenate([upper_rows, upper_cols[off]])
        local_cols = np.concatenate([upper_cols, upper_rows[off]])
        terms = np.concatenate([np.arange(upper_rows.size), np.flatnonzero(off)])
    else:
        local_rows, local_cols = np.repeat(np.arange(d), d), np.tile(np.arange(d), d)
        terms = np.arange(d * d)
    step = max(1, CHUNK_TERMS // (d * d))
    for start in range(0, len(idx), step):
        part = idx[start : start + step]
        if block.symmetric:
            values = block.packed[start : start + step]
        else:
            values = block.chunk(start, start + step).reshape(len(part), -1)
        # each (element, local row) gives d terms to its row: ranges of rows
        # of about PIECE_TERMS terms
        per_row = np.cumsum(np.bincount(part.ravel(), minlength=n)) * d
        pieces = max(1, -(-int(per_row[-1]) // PIECE_TERMS))
        bounds = np.searchsorted(per_row, np.arange(1, pieces) * (per_row[-1] / pieces))
        bounds = np.unique(np.concatenate([[0], bounds, [n]]))
        for first, stop in zip(bounds[:-1], bounds[1:], strict=True):
            inside = (part >= first) & (part < stop)
            elements = np.flatnonzero(inside.any(axis=1))
            # the piece's terms in the chunk's order (element, then term)
            element, term = np.nonzero(inside[elements][:, local_rows])
            element = elements[element]
            del inside, elements
            rows = part[element, local_rows[term]]
            cols = part[element, local_cols[term]]
            vals = values[element, terms[term]]
            del element, term
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
