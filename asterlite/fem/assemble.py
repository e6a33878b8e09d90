"""Sparse assembly of element blocks and nodal terms on a DOF numbering."""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from asterlite.concepts.assembly import DofNumbering, ElementBlock


def build_numbering_dofs(node_components: dict[int, tuple[str, ...]]) -> list[tuple[int, str]]:
    """DOF list ordered node by node (mesh order), components in code_aster order."""
    return [(node, comp) for node in sorted(node_components) for comp in node_components[node]]


def block_dof_indices(block: ElementBlock, numbering: DofNumbering) -> np.ndarray:
    """(n_elements, d) numbering indices of each element's DOFs (-1 if absent)."""
    n_el, per_el = block.nodes.shape
    nodes = np.repeat(block.nodes, len(block.components), axis=1).ravel()
    comps = list(block.components) * (per_el * n_el)
    return numbering.dof_indices(nodes, comps).reshape(n_el, -1)


def assemble_blocks(blocks: list[ElementBlock], numbering: DofNumbering) -> sp.csr_matrix:
    """Sum the element matrices into an (n_dofs, n_dofs) CSR matrix."""
    n = numbering.n_dofs
    rows, cols, vals = [], [], []
    for block in blocks:
        if not len(block.matrices):
            continue
        idx = block_dof_indices(block, numbering)
        if np.any(idx < 0):
            raise KeyError("element DOF missing from the numbering")
        d = idx.shape[1]
        rows.append(np.repeat(idx, d, axis=1).ravel())
        cols.append(np.tile(idx, (1, d)).ravel())
        vals.append(block.matrices.reshape(len(idx), -1).ravel())
    if not rows:
        return sp.csr_matrix((n, n))
    matrix = sp.coo_matrix(
        (np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(n, n)
    ).tocsr()
    matrix.sum_duplicates()
    matrix.eliminate_zeros()
    return matrix


def assemble_terms(terms, numbering: DofNumbering) -> np.ndarray:
    """Nodal (node, component, value) terms summed into a vector on the numbering."""
    vector = np.zeros(numbering.n_dofs)
    if not terms:
        return vector
    nodes = [t[0] for t in terms]
    comps = [t[1] for t in terms]
    idx = numbering.dof_indices(nodes, comps)
    if np.any(idx < 0):
        names = numbering.mesh.node_names
        missing = [f"{names[n]} {c}" for n, c, i in zip(nodes, comps, idx, strict=True) if i < 0]
        raise KeyError(", ".join(missing[:5]))
    np.add.at(vector, idx, np.array([t[2] for t in terms], dtype=float))
    return vector
