"""Nodal forces of the DIS_CHOC relation on discrete elements (code_aster's
FONL_NOEU option of te0039, for CALC_FORC_NONL): what the contact law of the
material's DIS_CONTACT adds to the linear element at a displacement.

On an element in its local frame (ORIENTATION, else x along the segment),
with K the element's stiffness (AFFE_CARA_ELEM K_T_D_*) and u its local
displacements:

- a segment: the penetration is ``d = L + (u2x - u1x) - (DIST_1 + DIST_2) - eps``
  (L the nodes' distance along local x). In contact (d <= 0) the force is
  ``F = (min(RIGI_NOR d, 0), K22 (u2y - u1y), K33 (u2z - u1z))``, the first node
  taking -F and the second +F; out of contact none;
- a point: ``d = u1x + JEU - DIST_1``, the force ``(min(RIGI_NOR d, 0), K22 u1y,
  K33 u1z)`` on its node;
- rotations (DIS_TR) take, in contact, the forces of the element's matrix
  whose diagonal springs are code_aster's (K11 replaced by RIGI_NOR);
- the result is that force (in the global frame) minus the linear element's
  K u; a force whose normal part is below machine precision counts as none.
  On a segment, code_aster then keeps the second node's values only.

RIGI_NOR defaults to K11. Friction (COULOMB > 0), the corner contact
(CONTACT='COIN_2D') and parallel springs (KP, KT...) are refused by name.
"""

from __future__ import annotations

import numpy as np

from asterlite.fem.discrete import local_matrix
from asterlite.fem.dofs import MODELISATION_COMPONENTS
from asterlite.fem.element_errors import ElementError
from asterlite.fem.elements import cell_frames
from asterlite.fem.frames import block_rotation

EPS = float(np.finfo(float).eps)
CONTACT_MODELISATIONS = ("DIS_T", "DIS_TR", "2D_DIS_T", "2D_DIS_TR")


def _contact_law(material, cell_name: str) -> dict:
    law = (material.behaviours.get("DIS_CONTACT") if material is not None else None) or None
    if law is None:
        raise ElementError(f"cell {cell_name}: DIS_CHOC needs a material with DIS_CONTACT")
    if float(law.get("COULOMB") or 0.0) > EPS:
        raise ElementError(
            f"cell {cell_name}: DIS_CONTACT COULOMB > 0 (DIS_CHOC with friction) is not "
            "computed by asterlite's CALC_FORC_NONL"
        )
    if law.get("CONTACT", "1D") != "1D":
        raise ElementError(f"cell {cell_name}: DIS_CONTACT CONTACT='COIN_2D' is not computed")
    for name in ("KP", "KT", "KT1", "KT2"):
        if float(law.get(name) or 0.0) != 0.0:
            raise ElementError(
                f"cell {cell_name}: DIS_CONTACT {name} (a parallel spring) is not computed"
            )
    return law


def dis_choc_nodal_forces(
    model, characteristics, materials, numbering, cells, values: np.ndarray
) -> np.ndarray:
    """(n_orders, n_dofs) FONL_NOEU of the DIS_CHOC cells ``cells`` for the
    displacements ``values`` (n_orders, n_dofs) on ``numbering``."""
    mesh = model.mesh
    values = np.asarray(values, dtype=float)
    out = np.zeros_like(values)
    cells = np.asarray(cells, dtype=int)
    if cells.size == 0:
        return out
    frames = cell_frames(model, cells, characteristics)
    for k, cell in enumerate(cells):
        name = mesh.cell_names[int(cell)]
        modelisation = model.cell_modelisation[int(cell)]
        if modelisation not in CONTACT_MODELISATIONS:
            raise ElementError(
                f"cell {name}: DIS_CHOC on {modelisation} is not computed by asterlite's "
                f"CALC_FORC_NONL ({', '.join(CONTACT_MODELISATIONS)})"
            )
        law = _contact_law(materials.material_of(int(cell)), name)
        dofs = MODELISATION_COMPONENTS[modelisation]
        per_node = len(dofs)
        dim = 2 if modelisation.startswith("2D_") else 3
        nodes = list(mesh.cell_nodes[int(cell)])
        n_nodes = len(nodes)
        rows = numbering.dof_indices(np.repeat(nodes, per_node), list(dofs) * n_nodes)
        if np.any(rows < 0):
            raise ElementError(f"cell {name}: its DOFs are not all in the result's numbering")
        rotation = block_rotation(frames[k : k + 1], dofs, n_nodes)[0]
        assignment = (characteristics.discrete.get(int(cell), {}) if characteristics else {}).get(
            "K"
        )
        size = per_node * n_nodes
        if assignment is None:
            stiffness = np.zeros((size, size))
        else:
            matrix = local_matrix(assignment.cara, assignment.values, dim, assignment.symmetric)
            stiffness = matrix if assignment.repere == "LOCAL" else rotation @ matrix @ rotation.T
        local = values[:, rows] @ rotation.T  # (n_orders, size)
        springs = np.diag(stiffness)[:per_node].copy()  # code_aster's raide
        normal = float(law["RIGI_NOR"]) if law.get("RIGI_NOR") is not None else springs[0]
        dist_1 = float(law.get("DIST_1") or 0.0)
        if n_nodes == 2:
            coords = np.asarray(mesh.coords[nodes], dtype=float)
            span = (coords[1] - coords[0]) @ frames[k][0][: coords.shape[1]]
            relative = local[:, per_node:] - local[:, :per_node]
            gap = span + relative[:, 0] - (dist_1 + float(law.get("DIST_2") or 0.0)) - EPS
        else:
            relative = local
            gap = relative[:, 0] + float(law.get("JEU") or 0.0) - dist_1
        force = np.zeros((values.shape[0], dim))
        force[:, 0] = np.minimum(normal * gap, 0.0)
        for c in range(1, dim):
            force[:, c] = springs[c] * relative[:, c]
        acting = (gap <= 0.0) & (np.abs(force[:, 0]) >= EPS)
        # in contact, the element's matrix with its diagonal springs (normal
        # one RIGI_NOR) gives the rotations' forces; the translations take F
        contact_matrix = stiffness.copy()
        springs[0] = normal
        for c in range(per_node):
            for a in range(n_nodes):
                contact_matrix[a * per_node + c, a * per_node + c] = springs[c]
            if n_nodes == 2:
                contact_matrix[c, per_node + c] = contact_matrix[per_node + c, c] = -springs[c]
        contact = local @ contact_matrix.T
        if n_nodes == 2:
            contact[:, :dim] = -force
            contact[:, per_node : per_node + dim] = force
        else:
            contact[:, :dim] = force
        contact[~acting] = 0.0
        nodal = (contact - local @ stiffness.T) @ rotation  # back to the global frame
        if n_nodes == 2:
            nodal[:, :per_node] = 0.0
        np.add.at(out, (slice(None), rows), nodal)
    return out
