"""Orientation of skin faces of 3D meshes and skin edges of plane meshes
(MODI_MAILLAGE ORIE_PEAU).

A face's normal follows the order of its nodes (``dx/dxi x dx/deta``,
right-hand rule); pressure and other face loads act along it. ORIE_PEAU
turns every face of the skin so that its normal points out of the volume cell
it bounds: the volume is the one whose vertices include all the face's
vertices (among GROUP_MA_INTERNE when given), and a face is reversed when its
normal points towards that volume's centroid. On a plane mesh the skin is
made of edges, whose normal is their tangent turned clockwise ``(dy, -dx)``,
turned the same way out of the surface cell they bound.
"""

from __future__ import annotations

from collections import defaultdict

import numpy as np

from asterlite.fem.solid_reference import FACE_CELLS, REFERENCE_ELEMENTS, VOLUME_CELLS

#: node order of a reversed face (first node kept, mid-edge nodes follow)
REVERSED = {
    "TRIA3": (0, 2, 1),
    "TRIA6": (0, 2, 1, 5, 4, 3),
    "TRIA7": (0, 2, 1, 5, 4, 3, 6),
    "QUAD4": (0, 3, 2, 1),
    "QUAD8": (0, 3, 2, 1, 7, 6, 5, 4),
    "QUAD9": (0, 3, 2, 1, 7, 6, 5, 4, 8),
}
_VERTICES = {"TRIA3": 3, "TRIA6": 3, "TRIA7": 3, "QUAD4": 4, "QUAD8": 4, "QUAD9": 4}
_VOLUME_VERTICES = {
    "HEXA8": 8,
    "HEXA20": 8,
    "HEXA27": 8,
    "PENTA6": 6,
    "PENTA15": 6,
    "PENTA18": 6,
    "TETRA4": 4,
    "TETRA10": 4,
    "PYRAM5": 5,
    "PYRAM13": 5,
}


class SkinError(ValueError):
    """A skin face that cannot be oriented (no bounding volume, or two)."""


def face_normal(mesh, cell: int) -> np.ndarray:
    """Normal (not unit) of a face cell at its reference centre."""
    kind = mesh.cell_types[cell]
    spec = FACE_CELLS.get(kind) or FACE_CELLS[kind.replace("7", "6")]
    ref = REFERENCE_ELEMENTS[spec.reference]
    nodes = list(mesh.cell_nodes[cell])[: ref.n_nodes]
    centre = ref.nodes.mean(axis=0)[None, :]
    tangents = np.einsum("nj,ni->ji", ref.gradients(centre)[0], mesh.coords[nodes])
    return np.cross(tangents[0], tangents[1])


def _volumes_by_vertex(mesh, volumes) -> dict[int, list[int]]:
    out: dict[int, list[int]] = defaultdict(list)
    for cell in volumes:
        for node in mesh.cell_nodes[cell][: _VOLUME_VERTICES[mesh.cell_types[cell]]]:
            out[node].append(int(cell))
    return out


def _owners(mesh, face: int, around) -> list[int]:
    """The volume cells whose vertices include every vertex of ``face``."""
    kind = mesh.cell_types[face]
    if kind not in REVERSED:
        raise SkinError(f"cell {mesh.cell_names[face]} ({kind}) is not a face of a 3D mesh")
    corners = set(mesh.cell_nodes[face][: _VERTICES[kind]])
    first = next(iter(corners))
    return [
        v
        for v in around.get(first, [])
        if corners <= set(mesh.cell_nodes[v][: _VOLUME_VERTICES[mesh.cell_types[v]]])
    ]


def _points_inwards(mesh, face: int, volume: int) -> bool:
    inside = mesh.coords[list(mesh.cell_nodes[volume])].mean(axis=0)
    outward = mesh.coords[list(mesh.cell_nodes[face])].mean(axis=0) - inside
    return bool(face_normal(mesh, face) @ outward < 0.0)


def _all_volumes(mesh) -> list[int]:
    return [c for c, t in enumerate(mesh.cell_types) if t in _VOLUME_VERTICES]


def orient_skin(mesh, faces, volumes=None, alone: list | None = None) -> int:
    """Reverse the faces whose normal points into their volume; returns how
    many were reversed. ``volumes`` defaults to every volume cell. A face on
    no volume is left as it is, as code_aster's orilma does (listed in
    ``alone`` when given)."""
    around = _volumes_by_vertex(mesh, _all_volumes(mesh) if volumes is None else volumes)
    reversed_count = 0
    for face in faces:
        owners = _owners(mesh, face, around)
        if not owners:
            if alone is not None:
                alone.append(int(face))
            continue
        if len(owners) > 1:
            names = ", ".join(mesh.cell_names[v] for v in owners)
            raise SkinError(
                f"face {mesh.cell_names[face]} lies between the volumes {names}: "
                "give GROUP_MA_INTERNE to say which side is inside"
            )
        if _points_inwards(mesh, face, owners[0]):
            nodes = mesh.cell_nodes[face]
            mesh.cell_nodes[face] = tuple(nodes[i] for i in REVERSED[mesh.cell_types[face]])
            reversed_count += 1
    return reversed_count


def inward_faces(mesh, faces, volumes) -> list[int]:
    """The faces on the border of ``volumes`` (one volume only) whose normal
    points into it (code_aster's VERI_NORM check of pressure loads); faces
    inside the volumes or away from them are not judged here."""
    around = _volumes_by_vertex(mesh, volumes)
    out = []
    for face in faces:
        owners = _owners(mesh, face, around)
        if len(owners) == 1 and _points_inwards(mesh, face, owners[0]):
            out.append(int(face))
    return out


# -- skins of plane meshes: edges of surface cells -----------------------------------------

#: node order of a reversed edge (the middle node of a SEG3 stays last)
REVERSED_EDGE = {"SEG2": (1, 0), "SEG3": (1, 0, 2)}
_SURFACE_VERTICES = {"TRIA3": 3, "TRIA6": 3, "TRIA7": 3, "QUAD4": 4, "QUAD8": 4, "QUAD9": 4}


def is_plane(mesh, tolerance: float = 1.0e-9) -> bool:
    """A plane mesh: 2D coordinates, or 3D ones with a constant Z (code_aster's
    test for 2D skins)."""
    if mesh.dim == 2 or mesh.coords.shape[1] == 2:
        return True
    z = mesh.coords[:, 2]
    scale = max(float(np.ptp(mesh.coords[:, :2])), 1.0e-300)
    return float(np.ptp(z)) <= tolerance * scale


def _edge_normal(mesh, edge: int) -> np.ndarray:
    """(dy, -dx) of the edge's first and second node: the normal code_aster
    gives an edge (the tangent turned clockwise)."""
    a, b = mesh.cell_nodes[edge][:2]
    t = mesh.coords[b, :2] - mesh.coords[a, :2]
    return np.array([t[1], -t[0]])


def orient_edges(mesh, edges, surfaces=None, alone: list | None = None) -> int:
    """Reverse the skin edges of a plane mesh whose normal points into the
    surface cell they bound; returns how many were reversed. ``surfaces``
    defaults to every surface cell; an edge on no surface cell is left as it
    is (listed in ``alone`` when given)."""
    if surfaces is None:
        surfaces = [c for c, t in enumerate(mesh.cell_types) if t in _SURFACE_VERTICES]
    around: dict[int, list[int]] = defaultdict(list)
    for cell in surfaces:
        kind = mesh.cell_types[cell]
        if kind not in _SURFACE_VERTICES:
            raise SkinError(f"cell {mesh.cell_names[cell]} ({kind}) is not a surface cell")
        for node in mesh.cell_nodes[cell][: _SURFACE_VERTICES[kind]]:
            around[node].append(int(cell))
    count = 0
    for edge in edges:
        kind = mesh.cell_types[edge]
        if kind not in REVERSED_EDGE:
            raise SkinError(f"cell {mesh.cell_names[edge]} ({kind}) is not an edge of a plane mesh")
        a, b = mesh.cell_nodes[edge][:2]
        owners = [
            c
            for c in around.get(a, [])
            if b in mesh.cell_nodes[c][: _SURFACE_VERTICES[mesh.cell_types[c]]]
        ]
        if not owners:
            if alone is not None:
                alone.append(int(edge))
            continue
        if len(owners) > 1:
            names = ", ".join(mesh.cell_names[c] for c in owners)
            raise SkinError(
                f"edge {mesh.cell_names[edge]} lies between the surface cells {names}: "
                "give GROUP_MA_INTERNE to say which side is inside"
            )
        inside = mesh.coords[list(mesh.cell_nodes[owners[0]]), :2].mean(axis=0)
        outward = mesh.coords[[a, b], :2].mean(axis=0) - inside
        if _edge_normal(mesh, edge) @ outward < 0.0:
            nodes = mesh.cell_nodes[edge]
            mesh.cell_nodes[edge] = tuple(nodes[i] for i in REVERSED_EDGE[kind])
            count += 1
    return count


assert set(VOLUME_CELLS) <= set(_VOLUME_VERTICES)
