"""Restitution of generalized vectors on the substructures and the skeleton.

A generalized vector q of the coupled model holds each substructure's
coordinates in its block; the substructure's displacement is Φ_k q_k in
its own frame (REST_SOUS_STRUC SOUS_STRUC), R_k Φ_k q_k in the global
frame (on the skeleton mesh, and for the shocks of DYNA_VIBRA)."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import DofNumbering
from asterlite.concepts.modes import ModeResult
from asterlite.concepts.substructure import Skeleton
from asterlite.fem.dofs import ROTATIONS, TRANSLATIONS


def substructure_shapes(numbering_gene, vectors, name: str) -> np.ndarray:
    """(n_dofs of the substructure, n_vectors) Φ_k q_k, local frame."""
    sub = numbering_gene.model.find(name)
    block = numbering_gene.block(name)
    return sub.macro.basis.shapes @ np.asarray(vectors)[block]


def rotate_shapes(numbering: DofNumbering, shapes: np.ndarray, rotation) -> np.ndarray:
    """Node-wise rotation of the translation and rotation components."""
    if np.allclose(rotation, np.eye(3)):
        return np.array(shapes, copy=True)
    out = np.array(shapes, dtype=float, copy=True)
    for node in np.unique(numbering.dof_nodes):
        for group in (TRANSLATIONS, ROTATIONS):
            rows = numbering.dof_indices([node] * 3, list(group))
            present = rows >= 0
            if not present.any():
                continue
            block = np.zeros((3, shapes.shape[1]))
            block[present] = shapes[rows[present]]
            rotated = rotation @ block
            out[rows[present]] = rotated[present]
    return out


def global_view(modes, name: str) -> ModeResult:
    """The coupled modes seen on one substructure in the global frame: its
    mesh moved to its place, Φ_k q_k rotated (what DYNA_VIBRA's shocks on
    SOUS_STRUC_1/2 read)."""
    numbering_gene = modes.numbering
    sub = numbering_gene.model.find(name)
    basis = sub.macro.basis
    local = basis.numbering
    mesh = local.mesh.copy()
    mesh.coords = sub.to_global(mesh.coords)
    numbering = DofNumbering(mesh, list(local.dofs), list(local.relations))
    shapes = rotate_shapes(
        local, substructure_shapes(numbering_gene, modes.vectors, name), sub.rotation
    )
    return _modes_on(numbering, shapes, modes)


def _modes_on(numbering, shapes, modes, idx=None) -> ModeResult:
    """A ModeResult of ``shapes`` carrying the per-mode data of ``modes``
    (of the modes at 0-based ``idx`` when given)."""
    idx = np.arange(modes.n_modes) if idx is None else np.asarray(idx, dtype=int)
    params = {k: np.asarray(v)[idx] for k, v in modes.parameters.items() if np.ndim(v) == 1}
    return ModeResult(
        numbering=numbering,
        shapes=shapes,
        frequencies=np.asarray(modes.frequencies)[idx].copy(),
        generalized_mass=np.asarray(modes.generalized_mass)[idx].copy(),
        generalized_stiffness=np.asarray(modes.generalized_stiffness)[idx].copy(),
        kind="dynamic",
        parameters=params,
        norm=modes.norm,
    )


def substructure_modes(modes, name: str, indices) -> ModeResult:
    """REST_SOUS_STRUC(SOUS_STRUC=name) of a mode_gene: the selected modes on
    the substructure's numbering, in its own frame."""
    basis = modes.numbering.model.find(name).macro.basis
    idx = np.asarray(indices, dtype=int)
    shapes = substructure_shapes(modes.numbering, modes.vectors[:, idx], name)
    out = _modes_on(basis.numbering, shapes, modes, idx)
    out.mass, out.stiffness = basis.mass, basis.stiffness
    return out


def skeleton_modes(modes, skeleton: Skeleton, indices) -> ModeResult:
    """REST_SOUS_STRUC(SQUELETTE=...) of a mode_gene: R_k Φ_k q_k of every
    substructure on its skeleton nodes (interface nodes appear once per
    substructure, as the skeleton keeps them)."""
    idx = np.asarray(indices, dtype=int)
    model = modes.numbering.model
    per_sub = {}
    for sub in model.substructures:
        local = sub.macro.basis.numbering
        shapes = substructure_shapes(modes.numbering, modes.vectors[:, idx], sub.name)
        per_sub[sub.name] = (local, rotate_shapes(local, shapes, sub.rotation))
    dofs, rows = [], []
    for node, (name, original) in enumerate(skeleton.origin):
        local, shapes = per_sub[name]
        for i, (n, comp) in enumerate(local.dofs):
            if n == original:
                dofs.append((node, comp))
                rows.append(shapes[i])
    numbering = DofNumbering(skeleton, dofs)
    values = np.array(rows).reshape(len(rows), idx.size)
    return _modes_on(numbering, values, modes, idx)


def build_skeleton(model, selections) -> Skeleton:
    """The skeleton mesh of ``selections`` [(substructure, cell indices)]:
    nodes N1.. and cells MA1.. numbered in order, one cell group per
    substructure named after it, coordinates in the global frame."""
    coords, names, origin = [], [], []
    cell_names, cell_types, cell_nodes = [], [], []
    cell_groups = {}
    for sub, cells in selections:
        mesh = sub.macro.mesh
        nodes = np.unique(np.concatenate([np.asarray(mesh.cell_nodes[c]) for c in cells]))
        new_index = {}
        for node in nodes:
            new_index[int(node)] = len(names)
            names.append(f"N{len(names) + 1}")
            origin.append((sub.name, int(node)))
        coords.append(sub.to_global(mesh.coords[nodes]))
        members = []
        for c in cells:
            members.append(len(cell_names))
            cell_names.append(f"MA{len(cell_names) + 1}")
            cell_types.append(mesh.cell_types[c])
            cell_nodes.append(tuple(new_index[int(n)] for n in mesh.cell_nodes[c]))
        cell_groups[sub.name] = np.array(members, dtype=int)
    return Skeleton(
        coords=np.vstack(coords) if coords else np.zeros((0, 3)),
        node_names=names,
        cell_names=cell_names,
        cell_types=cell_types,
        cell_nodes=cell_nodes,
        cell_groups=cell_groups,
        origin=origin,
        model=model,
    )
