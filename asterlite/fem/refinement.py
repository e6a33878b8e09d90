"""Uniform refinement of a mesh, as HOMARD's RAFFINEMENT_UNIFORME does it for
segments, triangles and quadrangles, linear or quadratic.

Every edge is cut at its middle (the existing middle node of a quadratic
edge, else a new node), every quadrangle also at its centre; a segment
becomes 2 segments, a triangle 4 triangles (three at its corners and the
middle one), a quadrangle 4 quadrangles, each child oriented as its parent.
A quadratic child has middle nodes on its edges: new nodes at the middle of
the straight sub-edge (HOMARD takes every new edge as straight). The
centre of a quadrangle, QUAD8 too, is the mean of its four vertices.
Points (POI1) are kept. The old nodes keep their names, the new nodes and
all cells are named N<number> and M<number> after the last numbers in use.
Each cell group holds the children of its cells; node groups keep their
nodes (HOMARD puts the nodes it creates in no group).
"""

from __future__ import annotations

import re

import numpy as np

from asterlite.concepts.mesh import Mesh

REFINED = ("POI1", "SEG2", "SEG3", "TRIA3", "TRIA6", "QUAD4", "QUAD8")

# children of a triangle and a quadrangle, in local indices: vertices 0..2,
# edge middles 3..5 (01, 12, 20) / vertices 0..3, middles 4..7, centre 8
_TRIANGLE_CHILDREN = ((0, 3, 5), (3, 1, 4), (5, 4, 2), (4, 5, 3))
_QUADRANGLE_CHILDREN = ((0, 4, 8, 7), (4, 1, 5, 8), (8, 5, 2, 6), (7, 8, 6, 3))


class RefinementError(ValueError):
    """A cell type uniform refinement does not cover."""


class NodeBuilder:
    """The refined mesh's node coordinates and the middle node of each edge."""

    def __init__(self, mesh: Mesh):
        self.coords = [np.asarray(x, dtype=float) for x in mesh.coords]
        self.middles: dict[tuple[int, int], int] = {}

    def node(self, point) -> int:
        self.coords.append(np.asarray(point, dtype=float))
        return len(self.coords) - 1

    def middle(self, a: int, b: int, given: int | None = None) -> int:
        """The node at the middle of edge (a, b), shared by both cells of the edge."""
        key = (min(a, b), max(a, b))
        found = self.middles.get(key)
        if found is None:
            found = (
                given if given is not None else self.node(0.5 * (self.coords[a] + self.coords[b]))
            )
            self.middles[key] = found
        return found


def _children(builder: NodeBuilder, kind: str, nodes: tuple[int, ...]):
    """(child type, child nodes) of one cell."""
    quadratic = kind in ("SEG3", "TRIA6", "QUAD8")
    if kind == "POI1":
        return [(kind, nodes)]
    if kind in ("SEG2", "SEG3"):
        a, b = nodes[:2]
        m = builder.middle(a, b, nodes[2] if quadratic else None)
        halves = [(a, m), (m, b)]
    elif kind in ("TRIA3", "TRIA6"):
        v = nodes[:3]
        given = nodes[3:6] if quadratic else (None,) * 3
        local = list(v) + [builder.middle(v[k], v[(k + 1) % 3], given[k]) for k in range(3)]
        halves = [tuple(local[i] for i in child) for child in _TRIANGLE_CHILDREN]
    elif kind in ("QUAD4", "QUAD8"):
        v = nodes[:4]
        given = nodes[4:8] if quadratic else (None,) * 4
        local = list(v) + [builder.middle(v[k], v[(k + 1) % 4], given[k]) for k in range(4)]
        # HOMARD puts the centre at the mean of the vertices, QUAD8 too
        local.append(builder.node(np.mean([builder.coords[n] for n in v], axis=0)))
        halves = [tuple(local[i] for i in child) for child in _QUADRANGLE_CHILDREN]
    else:
        raise RefinementError(
            f"uniform refinement of {kind} cells (asterlite refines {', '.join(REFINED)})"
        )
    if not quadratic:
        return [(kind, child) for child in halves]
    out = []
    for child in halves:
        n = len(child)
        extra = [builder.middle(child[k], child[(k + 1) % n]) for k in range(n if n > 2 else 1)]
        out.append((kind, tuple(child) + tuple(extra)))
    return out


def next_number(names: list[str], prefix: str) -> int:
    numbers = [int(m.group(1)) for n in names if (m := re.fullmatch(prefix + r"(\d+)", n))]
    return max(numbers, default=0) + 1


def refine_uniformly(mesh: Mesh) -> Mesh:
    """The mesh with every cell split once (see the module's docstring)."""
    return uniform_refinement(mesh)[0]


def uniform_refinement(mesh: Mesh) -> tuple[Mesh, np.ndarray]:
    """The mesh with every cell split once and the parent of each new cell."""
    unknown = sorted({k for k in mesh.cell_types if k not in REFINED})
    if unknown:
        raise RefinementError(
            f"uniform refinement of {', '.join(unknown)} cells "
            f"(asterlite refines {', '.join(REFINED)})"
        )
    if mesh.zone_adapted:
        # HOMARD would first remove the conformity cells of the earlier
        # adaptation and refine their parents: that history is not kept here
        raise RefinementError(
            "uniform refinement of a mesh that MACR_ADAP_MAIL adapted by zones "
            "(HOMARD's refinement history of its conformity cells is not kept)"
        )
    builder = NodeBuilder(mesh)
    children = [
        _children(builder, mesh.cell_types[c], mesh.cell_nodes[c]) for c in range(mesh.n_cells)
    ]
    refined, parent = refined_mesh(mesh, builder, children)
    refined.uniform_level = mesh.uniform_level + 1
    return refined, parent


def refined_mesh(mesh: Mesh, builder: NodeBuilder, children) -> tuple[Mesh, np.ndarray]:
    """The mesh (and the parent of each of its cells) whose cell k of
    ``mesh`` is replaced by ``children[k]``, a list of (type, nodes) on the
    builder's nodes: old nodes keep their names,
    new nodes are N<number> after the last number in use, cells are
    M1..Mn in order, each cell group holds the children of its cells and
    node groups keep their nodes."""
    cell_types, cell_nodes, parent = [], [], []
    for cell, split in enumerate(children):
        for kind, nodes in split:
            cell_types.append(kind)
            cell_nodes.append(tuple(nodes))
            parent.append(cell)
    n_old = mesh.n_nodes
    first = next_number(mesh.node_names, "N")
    node_names = list(mesh.node_names) + [
        f"N{first + k}" for k in range(len(builder.coords) - n_old)
    ]
    cell_names = [f"M{k + 1}" for k in range(len(cell_types))]
    of_parent: dict[int, list[int]] = {}
    for child, cell in enumerate(parent):
        of_parent.setdefault(cell, []).append(child)
    cell_groups = {
        name: np.array([c for cell in cells for c in of_parent[int(cell)]], dtype=int)
        for name, cells in mesh.cell_groups.items()
    }
    refined = Mesh(
        coords=np.array(builder.coords),
        node_names=node_names,
        cell_names=cell_names,
        cell_types=cell_types,
        cell_nodes=cell_nodes,
        node_groups={k: v.copy() for k, v in mesh.node_groups.items()},
        cell_groups=cell_groups,
        dim=mesh.dim,
        title=mesh.title,
        names_kept=mesh.names_kept,
    )
    return refined, np.asarray(parent, dtype=int)
