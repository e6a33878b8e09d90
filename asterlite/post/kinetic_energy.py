"""Kinetic energy of element groups (POST_ELEM ENER_CIN).

For a transient result code_aster sums, over the cells, ½ vₑᵀ Mₑ vₑ with the
element mass matrices (MASS_MECA, or the lumped MASS_MECA_DIAG) and the VITE
field; for modes it uses ½ ω² φₑᵀ Mₑ φₑ with the DEPL field."""

from __future__ import annotations

import numpy as np

from asterlite.fem.options import option_blocks


def kinetic_energy(
    model, characteristics, materials, numbering, fields, cells=None, option="MASS_MECA"
):
    """(n_orders,) ½ Σₑ uₑᵀ Mₑ uₑ over ``cells`` (every cell: None) for the
    nodal fields (n_orders, n_dofs) on ``numbering``."""
    fields = np.atleast_2d(np.asarray(fields, dtype=float))
    total = np.zeros(fields.shape[0])
    for block in option_blocks(model, characteristics, option, materials=materials, cells=cells):
        n_elements, per_element = block.nodes.shape
        comps = list(block.components)
        nodes = np.repeat(block.nodes, len(comps), axis=1).ravel()
        rows = numbering.dof_indices(nodes, comps * (per_element * n_elements))
        gathered = np.zeros((fields.shape[0], rows.size))
        present = rows >= 0
        gathered[:, present] = fields[:, rows[present]]
        local = gathered.reshape(fields.shape[0], n_elements, -1)
        total += 0.5 * np.einsum("oei,eij,oej->o", local, block.matrices, local)
    return total
