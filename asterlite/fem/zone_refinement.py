"""Refinement of a mesh by zones, as HOMARD does it for MACR_ADAP_MAIL
ADAPTATION='RAFF_DERA_ZONE' (segments, triangles and quadrangles, linear or
quadratic; HOMARD's default, conforming adaptation).

HOMARD's steps, on a mesh that no adaptation has touched yet:

1. A node is in a zone by its coordinates (bounds included; a plane mesh,
   2D or in 3D space with a constant z, is tested in its plane, where a
   CYLINDRE or TUYAU zone is refused). An edge is to be cut when both its
   end vertices are in the same zone.
2. The rule of the two neighbours, until nothing changes: a face with at
   most one edge left uncut is split in four, and that edge is cut too. A
   triangle with two cut edges, a quadrangle with three, are split in four.
3. Standard splitting: an edge in two, a triangle in four (three at its
   corners and the middle one), a quadrangle in four about its centre (the
   mean of its vertices).
4. Conformity splitting of the faces left with cut edges: a triangle with
   one cut edge becomes two triangles (the edge's middle joined to the
   opposite vertex), a quadrangle with one cut edge three triangles (the
   middle joined to both opposite vertices), with two opposite cut edges two
   quadrangles (the middles joined), with two adjacent cut edges three
   quadrangles about a new node at its centre, joined to the two middles
   and to the opposite vertex.

A quadratic child has middle nodes on its edges: the given middle of an
uncut edge, else a new node at the middle of the straight edge. Children
keep their parent's orientation and groups (see refinement.refined_mesh for
the names). Points (POI1) are kept.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.concepts.mesh import Mesh
from asterlite.fem.refinement import (
    REFINED,
    NodeBuilder,
    RefinementError,
    _children,
    refined_mesh,
)

#: code_aster's ZONE types and the keywords each one reads
ZONE_KEYWORDS = {
    "RECTANGLE": ("X_MINI", "X_MAXI", "Y_MINI", "Y_MAXI"),
    "BOITE": ("X_MINI", "X_MAXI", "Y_MINI", "Y_MAXI", "Z_MINI", "Z_MAXI"),
    "DISQUE": ("X_CENTRE", "Y_CENTRE", "RAYON"),
    "DISQUE_PERCE": ("X_CENTRE", "Y_CENTRE", "RAYON_INT", "RAYON_EXT"),
    "SPHERE": ("X_CENTRE", "Y_CENTRE", "Z_CENTRE", "RAYON"),
    "CYLINDRE": ("X_AXE", "Y_AXE", "Z_AXE", "X_BASE", "Y_BASE", "Z_BASE", "HAUTEUR", "RAYON"),
    "TUYAU": ("X_AXE", "Y_AXE", "Z_AXE", "X_BASE", "Y_BASE", "Z_BASE", "HAUTEUR")
    + ("RAYON_INT", "RAYON_EXT"),
}

_VERTICES = {"SEG2": 2, "SEG3": 2, "TRIA3": 3, "TRIA6": 3, "QUAD4": 4, "QUAD8": 4}
_QUADRATIC = ("SEG3", "TRIA6", "QUAD8")


@dataclass(frozen=True)
class Zone:
    """One ZONE occurrence: its TYPE and the values of its keywords."""

    kind: str
    values: dict

    def contains(self, coords: np.ndarray, plane_z: float | None) -> np.ndarray:
        """Which nodes are in the zone, as HOMARD tests them (bounds
        included). ``plane_z``: the z of a plane mesh (HOMARD then tests the
        zone in the plane), None for a mesh in 3D space."""
        v = self.values
        x, y = coords[:, 0], coords[:, 1]
        dim = 3 if plane_z is None else 2
        z = coords[:, 2] if dim == 3 else np.full(len(coords), plane_z)
        if self.kind == "RECTANGLE":
            return (x >= v["X_MINI"]) & (x <= v["X_MAXI"]) & (y >= v["Y_MINI"]) & (y <= v["Y_MAXI"])
        if self.kind == "BOITE":
            inside = (x >= v["X_MINI"]) & (x <= v["X_MAXI"]) & (y >= v["Y_MINI"])
            inside &= y <= v["Y_MAXI"]
            if dim == 3:
                return inside & (z >= v["Z_MINI"]) & (z <= v["Z_MAXI"])
            # a plane mesh is in the box when its z is, within 1e-4 of its extent
            extent = max(np.ptp(x), np.ptp(y)) if len(coords) else 0.0
            tolerance = 1.0e-4 * extent
            if v["Z_MINI"] > plane_z + tolerance or v["Z_MAXI"] < plane_z - tolerance:
                return np.zeros(len(coords), dtype=bool)
            return inside
        if self.kind in ("DISQUE", "DISQUE_PERCE"):
            d2 = (x - v["X_CENTRE"]) ** 2 + (y - v["Y_CENTRE"]) ** 2
            if self.kind == "DISQUE":
                return d2 <= v["RAYON"] ** 2
            return (d2 >= v["RAYON_INT"] ** 2) & (d2 <= v["RAYON_EXT"] ** 2)
        if self.kind == "SPHERE":
            d2 = (x - v["X_CENTRE"]) ** 2 + (y - v["Y_CENTRE"]) ** 2 + (z - v["Z_CENTRE"]) ** 2
            return d2 <= v["RAYON"] ** 2
        # CYLINDRE, TUYAU: HOMARD tests them in 3D space only
        if dim != 3:
            raise RefinementError(f"a {self.kind} zone on a plane mesh (HOMARD refuses it too)")
        axis = np.array([v["X_AXE"], v["Y_AXE"], v["Z_AXE"]], dtype=float)
        norm = float(np.linalg.norm(axis))
        if norm * norm <= 1.0e-14:
            raise RefinementError(f"the axis of a {self.kind} zone is zero")
        axis /= norm
        rel = coords[:, :3] - np.array([v["X_BASE"], v["Y_BASE"], v["Z_BASE"]], dtype=float)
        along = rel @ axis
        d2 = np.sum(np.cross(rel, axis) ** 2, axis=1)
        inside = (along >= 0.0) & (along <= v["HAUTEUR"])
        if self.kind == "CYLINDRE":
            return inside & (d2 <= v["RAYON"] ** 2)
        return inside & (d2 >= v["RAYON_INT"] ** 2) & (d2 <= v["RAYON_EXT"] ** 2)


class _Edges:
    """The mesh's edges between vertices: an id per vertex pair, the given
    middle node of a quadratic edge, the faces on each edge."""

    def __init__(self, mesh: Mesh):
        self.ids: dict[tuple[int, int], int] = {}
        self.ends: list[tuple[int, int]] = []
        self.middle: list[int | None] = []
        self.faces: list[list[int]] = []
        self.of_cell: dict[int, list[int]] = {}
        for cell, (kind, nodes) in enumerate(zip(mesh.cell_types, mesh.cell_nodes, strict=True)):
            n = _VERTICES.get(kind)
            if n is None:
                continue
            pairs = [(0, 1)] if n == 2 else [(k, (k + 1) % n) for k in range(n)]
            mids = nodes[n:] if kind in _QUADRATIC else (None,) * len(pairs)
            self.of_cell[cell] = [
                self._edge(nodes[a], nodes[b], mid) for (a, b), mid in zip(pairs, mids, strict=True)
            ]
            if n > 2:
                for e in self.of_cell[cell]:
                    self.faces[e].append(cell)

    def _edge(self, a: int, b: int, mid: int | None) -> int:
        key = (min(a, b), max(a, b))
        found = self.ids.get(key)
        if found is None:
            found = self.ids[key] = len(self.ends)
            self.ends.append(key)
            self.middle.append(mid)
            self.faces.append([])
        return found


def plane_height(mesh: Mesh) -> float | None:
    """The z of a plane mesh (a 2D mesh: 0; a mesh in 3D space whose z is
    constant: that z), None for a mesh in 3D space. HOMARD takes a mesh
    whose x or y is constant as a plane mesh in that plane: refused."""
    if mesh.dim == 2:
        return 0.0
    spans = np.ptp(mesh.coords, axis=0) if mesh.n_nodes else np.zeros(3)
    flat = [axis for axis in range(3) if spans[axis] == 0.0]
    if flat == [2]:
        return float(mesh.coords[0, 2])
    if flat:
        names = ", ".join("XYZ"[axis] for axis in flat)
        raise RefinementError(
            f"zone refinement of a mesh whose {names} is constant "
            "(HOMARD tests the zones in that plane; asterlite in the plane z = constant)"
        )
    return None


def _cut_edges(mesh: Mesh, edges: _Edges, zones: list[Zone]) -> np.ndarray:
    """Step 1: the edges with both ends in one zone."""
    ends = np.array(edges.ends, dtype=int).reshape(-1, 2)
    cut = np.zeros(len(ends), dtype=bool)
    height = plane_height(mesh)
    for zone in zones:
        inside = zone.contains(mesh.coords, height)
        cut |= inside[ends[:, 0]] & inside[ends[:, 1]]
    return cut


def _two_neighbours(mesh: Mesh, edges: _Edges, cut: np.ndarray) -> set[int]:
    """Step 2: the faces split in four (``cut`` is completed in place)."""
    split: set[int] = set()
    pending = [c for c in edges.of_cell if _VERTICES[mesh.cell_types[c]] > 2]
    while pending:
        face = pending.pop()
        if face in split:
            continue
        uncut = [e for e in edges.of_cell[face] if not cut[e]]
        if len(uncut) > 1:
            continue
        split.add(face)
        for e in uncut:
            cut[e] = True
            pending.extend(f for f in edges.faces[e] if f not in split)
    return split


def _conformity(kind: str, v: tuple[int, ...], mids: list[int | None], builder: NodeBuilder):
    """Step 4: the children's vertices of a face whose cut edges have the
    given middles (None: uncut)."""
    n = len(v)
    cut = [k for k in range(n) if mids[k] is not None]
    if n == 3:
        (k,) = cut
        return [(v[k], mids[k], v[(k + 2) % 3]), (mids[k], v[(k + 1) % 3], v[(k + 2) % 3])]
    if len(cut) == 1:
        (k,) = cut
        a, b, c, d = (v[(k + i) % 4] for i in range(4))
        m = mids[k]
        return [(a, m, d), (m, b, c), (m, c, d)]
    k, j = cut
    if j - k == 2:  # opposite edges (k, k+1) and (k+2, k+3)
        a, b, c, d = (v[(k + i) % 4] for i in range(4))
        return [(a, mids[k], mids[j], d), (mids[k], b, c, mids[j])]
    if (k, j) == (0, 3):  # adjacent edges meeting at vertex 0
        k, j = 3, 0
    # edges k = (a, b) and k+1 = (b, c) meet at b; d is the opposite vertex
    a, b, c, d = (v[(k + i) % 4] for i in range(4))
    centre = builder.node(np.mean([builder.coords[i] for i in v], axis=0))
    mk, mj = mids[k], mids[(k + 1) % 4]
    return [(a, mk, centre, d), (mk, b, mj, centre), (centre, mj, c, d)]


@dataclass
class ZoneRefinement:
    """The refined mesh, the parent (cell of the given mesh) of each of its
    cells, and the counts: edges in the zones, edges cut, faces split in
    four, faces split for conformity."""

    mesh: Mesh
    parent: np.ndarray
    counts: dict[str, int]


def refine_zones(mesh: Mesh, zones: list[Zone], max_level: int | None = None) -> ZoneRefinement:
    """The mesh refined in the zones (see the module's docstring).
    ``max_level`` (NIVE_MAX): the zones cut no edge of a cell at that level
    of refinement or deeper."""
    unknown = sorted({k for k in mesh.cell_types if k not in REFINED})
    if unknown:
        raise RefinementError(
            f"zone refinement of {', '.join(unknown)} cells "
            f"(asterlite refines {', '.join(REFINED)})"
        )
    degrees = {k in _QUADRATIC for k in mesh.cell_types if k != "POI1"}
    if len(degrees) > 1:
        raise RefinementError("a mesh mixing linear and quadratic cells (HOMARD refuses it too)")
    if mesh.zone_adapted:
        # HOMARD would undo the conformity cells of the earlier adaptation
        # and weigh the levels of the cells: that history is not kept here
        raise RefinementError(
            "zone refinement of a mesh that MACR_ADAP_MAIL already adapted by zones "
            "(HOMARD's refinement history is not kept)"
        )
    edges = _Edges(mesh)
    cut = _cut_edges(mesh, edges, zones)
    if max_level is not None and mesh.uniform_level >= max_level:
        # HOMARD takes an edge's level from a face on it: an edge of no face
        # (a lone segment) is not filtered
        cut &= np.array([not faces for faces in edges.faces], dtype=bool)
    zone_cut = int(cut.sum())
    split = _two_neighbours(mesh, edges, cut)

    builder = NodeBuilder(mesh)
    for e, mid in enumerate(edges.middle):
        if mid is not None:
            builder.middles[edges.ends[e]] = mid
    # the middle vertex of every cut edge, in the order of the edges
    middles: list[int | None] = [
        builder.middle(*edges.ends[e]) if cut[e] else None for e in range(len(cut))
    ]
    children, conforming = [], 0
    for cell in range(mesh.n_cells):
        kind, nodes = mesh.cell_types[cell], mesh.cell_nodes[cell]
        cell_edges = edges.of_cell.get(cell)
        if cell_edges is None or not any(cut[e] for e in cell_edges):
            children.append([(kind, tuple(nodes))])
            continue
        if cell in split or _VERTICES[kind] == 2:
            children.append(_children(builder, kind, nodes))
            continue
        conforming += 1
        vertices = tuple(nodes[: _VERTICES[kind]])
        pieces = _conformity(kind, vertices, [middles[e] for e in cell_edges], builder)
        children.append([_typed(kind, piece, builder) for piece in pieces])
    refined, parent = refined_mesh(mesh, builder, children)
    refined.uniform_level = mesh.uniform_level
    refined.zone_adapted = bool(cut.any())
    counts = {
        "zone_edges": zone_cut,
        "cut_edges": int(cut.sum()),
        "split": len(split),
        "conformity": conforming,
    }
    return ZoneRefinement(refined, parent, counts)


def _typed(parent_kind: str, vertices: tuple[int, ...], builder: NodeBuilder):
    """A conformity child of a face: its type (of its vertex count and the
    parent's degree) and its nodes, with middle nodes when quadratic."""
    quadratic = parent_kind in _QUADRATIC
    n = len(vertices)
    kind = ("TRIA6" if quadratic else "TRIA3") if n == 3 else ("QUAD8" if quadratic else "QUAD4")
    if not quadratic:
        return kind, vertices
    extra = tuple(builder.middle(vertices[k], vertices[(k + 1) % n]) for k in range(n))
    return kind, vertices + extra
