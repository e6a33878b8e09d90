"""Uniform refinement of a mesh, as HOMARD's RAFFINEMENT_UNIFORME does it for
segments, triangles and quadrangles, linear or quadratic.

Every edge is cut at its middle (the existing middle node of a quadratic
edge, else a new node), every quadrangle also at its centre; a segment
becomes 2 segments, a triangle 4 triangles (three at its corners and the
middle one), a quadrangle 4 quadrangles, each child oriented as its parent.
A quadratic child has middle nodes on its edges: new nodes at the middle of
the straight sub-edge. The centre of a QUAD8 is its isoparametric centre.
Points (POI1) are kept. The old nodes keep their names, the new nodes and
all cells are named N<number> and M<number> after the last numbers in use.
Each cell group holds the children of its cells; node groups keep their nodes.
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


class _Builder:
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


def _children(builder: _Builder, kind: str, nodes: tuple[int, ...]):
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
        corners = np.array([builder.coords[n] for n in v])
        if quadratic:
            mids = np.array([builder.coords[n] for n in nodes[4:8]])
            centre = 0.5 * mids.sum(axis=0) - 0.25 * corners.sum(axis=0)
        else:
            centre = corners.mean(axis=0)
        local.append(builder.node(centre))
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


def _next_number(names: list[str], prefix: str) -> int:
    numbers = [int(m.group(1)) for n in names if (m := re.fullmatch(prefix + r"(\d+)", n))]
    return max(numbers, default=0) + 1


def refine_uniformly(mesh: Mesh) -> Mesh:
    """The mesh with every cell split once (see the module's docstring)."""
    unknown = sorted({k for k in mesh.cell_types if k not in REFINED})
    if unknown:
        raise RefinementError(
            f"uniform refinement of {', '.join(unknown)} cells "
            f"(asterlite refines {', '.join(REFINED)})"
        )
    builder = _Builder(mesh)
    cell_types, cell_nodes, parent = [], [], []
    for cell in range(mesh.n_cells):
        for kind, nodes in _children(builder, mesh.cell_types[cell], mesh.cell_nodes[cell]):
            cell_types.append(kind)
            cell_nodes.append(nodes)
            parent.append(cell)
    parent = np.asarray(parent, dtype=int)
    n_old = mesh.n_nodes
    first = _next_number(mesh.node_names, "N")
    node_names = list(mesh.node_names) + [
        f"N{first + k}" for k in range(len(builder.coords) - n_old)
    ]
    cell_names = [f"M{k + 1}" for k in range(len(cell_types))]
    children = {}
    for child, cell in enumerate(parent):
        children.setdefault(int(cell), []).append(child)
    cell_groups = {
        name: np.array([c for cell in cells for c in children[int(cell)]], dtype=int)
        for name, cells in mesh.cell_groups.items()
    }
    return Mesh(
        coords=np.array(builder.coords),
        node_names=node_names,
        cell_names=cell_names,
        cell_types=cell_types,
        cell_nodes=cell_nodes,
        node_groups={k: v.copy() for k, v in mesh.node_groups.items()},
        cell_groups=cell_groups,
        dim=mesh.dim,
        title=mesh.title,
    )
