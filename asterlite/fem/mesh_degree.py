"""Changing the degree of mesh cells (CREA_MAILLAGE LINE_QUAD, MODI_MAILLE
OPTION='SEG3_4').

LINE_QUAD turns linear cells into their quadratic serendipity twins with a
node in the middle of each edge, shared by the cells around the edge, in
code_aster's node order (vertices, then the edge midpoints in the order of
its reference element). SEG3_4 turns a SEG3 into a SEG4 as code_aster does:
its middle node moves to a third of the arc through its nodes (of its chord
when straight) and a new node takes the other third. New nodes take
code_aster 17's positional names ``N<i>`` (LINE_QUAD of a code_aster 15 deck:
that version's ``NS1``, ``NS2``...); node groups keep their nodes.
"""

from __future__ import annotations

from functools import cache

import numpy as np

from asterlite.fem.solid_reference import REFERENCE_ELEMENTS

#: linear cell -> (quadratic cell, its reference element, number of vertices)
QUADRATIC = {
    "SEG2": ("SEG3", None, 2),
    "TRIA3": ("TRIA6", "TR6", 3),
    "QUAD4": ("QUAD8", "QU8", 4),
    "TETRA4": ("TETRA10", "T10", 4),
    "HEXA8": ("HEXA20", "H20", 8),
    "PENTA6": ("PENTA15", "P15", 6),
    "PYRAM5": ("PYRAM13", "P13", 5),
}


@cache
def edge_vertices(linear: str) -> tuple[tuple[int, int], ...]:
    """The vertex pair of each mid-edge node of the quadratic twin, in order:
    the pair whose midpoint is the node on the reference element."""
    quadratic, reference, n_vertices = QUADRATIC[linear]
    if reference is None:
        return ((0, 1),)
    nodes = REFERENCE_ELEMENTS[reference].nodes
    pairs = []
    for middle in nodes[n_vertices:]:
        found = [
            (i, j)
            for i in range(n_vertices)
            for j in range(i + 1, n_vertices)
            if np.allclose((nodes[i] + nodes[j]) / 2.0, middle)
        ]
        if len(found) != 1:
            raise AssertionError(f"{quadratic}: no single edge for the node at {middle}")
        pairs.append(found[0])
    return tuple(pairs)


class DuplicateNodeName(ValueError):
    """A new node would take the name of a node the mesh has."""


class _NewNodes:
    """Nodes appended to a mesh, with code_aster 17's positional names, or
    (``prefix``: (text, first number)) code_aster 15's prefixed ones."""

    def __init__(self, mesh, prefix: tuple[str, int] | None = None):
        self.mesh = mesh
        self.coords: list[np.ndarray] = []
        self.names: list[str] = []
        self.taken = set(mesh.node_names)
        self.prefix = prefix

    def add(self, point) -> int:
        index = self.mesh.n_nodes + len(self.coords)
        if self.prefix is not None:
            text, first = self.prefix
            name = f"{text}{first + len(self.coords)}"
            if name in self.taken:  # code_aster stops there too
                raise DuplicateNodeName(f"the mesh already has a node named {name!r}")
        else:
            name, k = f"N{index + 1}", 1
            while name in self.taken:
                name, k = f"NS{index + 1}_{k}", k + 1
        self.taken.add(name)
        self.coords.append(np.asarray(point, dtype=float))
        self.names.append(name)
        return index

    def commit(self) -> None:
        if self.coords:
            self.mesh.coords = np.vstack([self.mesh.coords, np.array(self.coords)])
            self.mesh.node_names.extend(self.names)
            self.mesh.refresh_indices()


def line_quad(mesh, cells, prefix: tuple[str, int] | None = None) -> int:
    """Make the linear ``cells`` of ``mesh`` (changed in place) quadratic;
    POI1 and quadratic cells stay. Returns the number of nodes added
    (``prefix``: see :class:`_NewNodes`)."""
    new = _NewNodes(mesh, prefix)
    middles: dict[tuple[int, int], int] = {}
    for cell in np.asarray(cells, dtype=int):
        kind = mesh.cell_types[cell]
        if kind not in QUADRATIC:
            continue
        quadratic, _, n_vertices = QUADRATIC[kind]
        vertices = list(mesh.cell_nodes[cell][:n_vertices])
        extra = []
        for i, j in edge_vertices(kind):
            a, b = vertices[i], vertices[j]
            key = (min(a, b), max(a, b))
            if key not in middles:
                middles[key] = new.add((mesh.coords[a] + mesh.coords[b]) / 2.0)
            extra.append(middles[key])
        mesh.cell_types[cell] = quadratic
        mesh.cell_nodes[cell] = tuple(vertices + extra)
    new.commit()
    return len(new.names)


class MeshDegreeError(ValueError):
    """A cell that cannot be changed (SEG3_4 of a SEG3 whose middle node is
    not halfway)."""


def _arc_thirds(xa, xb, xm):
    """Points at a third and two thirds of the arc through xa, xm, xb (its
    chord's thirds when straight), as code_aster's cmmoma."""
    t1, t2 = xm - xa, xb - xm
    n1, n2 = np.linalg.norm(t1), np.linalg.norm(t2)
    if abs(n2 - n1) > 1e-4 * n1:
        raise MeshDegreeError("its middle node is not halfway between its ends")
    normal = np.cross(t2 / n2, t1 / n1)
    sine = np.linalg.norm(normal)
    if sine <= 1e-4 * n1:
        return xa + (xb - xa) / 3.0, xa + 2.0 * (xb - xa) / 3.0
    theta = 2.0 * np.arctan2(sine, np.dot(t1 / n1, t2 / n2))
    # the centre on the perpendicular bisector through the middle node, the
    # thirds at theta/6 on either side of the bisector (cmmoma's construction)
    c2, c6 = np.cos(theta / 2.0), np.cos(theta / 6.0)
    ratio = np.tan(theta / 6.0) / np.tan(theta / 2.0)
    chord_middle = (xa + xb) / 2.0
    to_centre = (chord_middle - xm) * c2 / (1.0 - c2)
    centre = chord_middle + to_centre
    first = centre + ((xa - chord_middle) * ratio - to_centre) * c6 / c2
    second = centre + ((xb - chord_middle) * ratio - to_centre) * c6 / c2
    return first, second


def seg3_to_seg4(mesh, cells) -> int:
    """SEG3 cells (ends, middle) -> SEG4 as code_aster's MODI_MAILLE
    SEG3_4: the middle node moves to a third of the cell, a new node takes
    the other third (of the arc through the three nodes, or of the chord when
    they are aligned). Returns the number of nodes added."""
    new = _NewNodes(mesh)
    for cell in np.asarray(cells, dtype=int):
        if mesh.cell_types[cell] != "SEG3":
            continue
        a, b, m = mesh.cell_nodes[cell][:3]
        try:
            first, second = _arc_thirds(mesh.coords[a], mesh.coords[b], mesh.coords[m])
        except MeshDegreeError as exc:
            raise MeshDegreeError(f"SEG3_4 of cell {mesh.cell_names[cell]}: {exc}") from None
        mesh.coords[m] = first
        mesh.cell_types[cell] = "SEG4"
        mesh.cell_nodes[cell] = (a, b, m, new.add(second))
    new.commit()
    return len(new.names)
