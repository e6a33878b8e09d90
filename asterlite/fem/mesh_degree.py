"""Changing the degree of mesh cells (CREA_MAILLAGE LINE_QUAD, MODI_MAILLE
OPTION='SEG3_4') and the place of their middle nodes (MODI_MAILLAGE
MODI_MAILLE OPTION='NOEUD_QUART': quarter-point cells at a crack front).

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


#: quadratic cells whose mid-edge nodes NOEUD_QUART moves, and their linear twins
_QUARTER_CELLS = {
    **{"TRIA6": "TRIA3", "TRIA7": "TRIA3", "QUAD8": "QUAD4", "QUAD9": "QUAD4"},
    **{"TETRA10": "TETRA4", "PENTA15": "PENTA6", "PENTA18": "PENTA6"},
    **{"PYRAM13": "PYRAM5", "HEXA20": "HEXA8", "HEXA27": "HEXA8"},
}


class QuarterPointError(ValueError):
    """A crack front NOEUD_QUART cannot treat."""


def quarter_points(mesh, front) -> int:
    """MODI_MAILLE OPTION='NOEUD_QUART' with a front of nodes (code_aster's
    momaba): in every quadratic cell having a front node as a vertex, the
    middle node of each edge from that vertex moves to the quarter of the
    edge from it (Barsoum's singular elements). Front nodes that are no
    vertex of such a cell (the middles of the front's own edges, in 3D) keep
    their place. A 2D front is one node, a 3D one alternates vertices and
    middles. Returns the number of cells modified; the mesh's coordinates
    change in place."""
    front = [int(n) for n in front]
    if mesh.dim == 2 and len(front) > 1:
        raise QuarterPointError("a 2D crack front is one node (GROUP_NO_FOND / NOEUD_FOND)")
    if mesh.dim == 3 and len(front) < 2:
        raise QuarterPointError("a 3D crack front needs at least two nodes")
    original = mesh.coords.copy()
    cells_of: dict[int, list[int]] = {}
    for cell, nodes in enumerate(mesh.cell_nodes):
        if mesh.cell_types[cell] in _QUARTER_CELLS:
            for node in nodes:
                cells_of.setdefault(int(node), []).append(cell)
    modified: set[int] = set()
    vertices, middles = 0, []
    for tip in front:
        at_vertex = False
        for cell in cells_of.get(tip, ()):
            linear = _QUARTER_CELLS[mesh.cell_types[cell]]
            nodes = mesh.cell_nodes[cell]
            n_vertices = QUADRATIC[linear][2]
            if tip not in nodes[:n_vertices]:
                continue
            at_vertex = True
            modified.add(cell)
            for k, (i, j) in enumerate(edge_vertices(linear)):
                if tip in (nodes[i], nodes[j]):
                    other = nodes[j] if nodes[i] == tip else nodes[i]
                    middle = nodes[n_vertices + k]
                    mesh.coords[middle] = mesh.coords[tip] + 0.25 * (
                        mesh.coords[other] - mesh.coords[tip]
                    )
        if at_vertex:
            vertices += 1
        else:
            middles.append(tip)
    for tip in middles:
        mesh.coords[tip] = original[tip]
    if not modified:
        mesh.coords[:] = original
        raise QuarterPointError("no quadratic cell has a front node as a vertex")
    if len(front) > 1 and len(middles) != vertices - 1:
        mesh.coords[:] = original
        raise QuarterPointError(
            f"the front's {vertices} vertex nodes need {vertices - 1} middle nodes between "
            f"them, it has {len(middles)}"
        )
    return len(modified)
