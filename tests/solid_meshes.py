"""Boxes meshed with every 3D cell type, for the solid-element tests.

A box is cut into hexahedra, then each hexahedron into 2 wedges, 6 tetrahedra
or 6 pyramids (with a node at its centre); quadratic cells get the extra nodes
of code_aster's reference element (edge midpoints, face and cell centres),
found from the reference coordinates themselves and shared between cells.
"""

from __future__ import annotations

from itertools import combinations

import numpy as np

from asterlite.concepts.assembly import Material, MaterialField, Model
from asterlite.concepts.mesh import Mesh
from asterlite.fem.solid_reference import REFERENCE_ELEMENTS, VOLUME_CELLS

LINEAR_OF = {
    "HEXA8": "HEXA8",
    "HEXA20": "HEXA8",
    "HEXA27": "HEXA8",
    "PENTA6": "PENTA6",
    "PENTA15": "PENTA6",
    "TETRA4": "TETRA4",
    "TETRA10": "TETRA4",
    "PYRAM5": "PYRAM5",
    "PYRAM13": "PYRAM5",
}

# hexahedron (code_aster order: bottom 0-3, top 4-7) split into other cells,
# each listed in the code_aster vertex order of its type (positive volume)
_WEDGES = [(0, 3, 1, 4, 7, 5), (1, 3, 2, 5, 7, 6)]
# Kuhn's six tetrahedra around the diagonal 0-6 (conforming on a grid)
_TETS = [(0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6)]


def _box_grid(n, size):
    axes = [np.linspace(0.0, length, k + 1) for k, length in zip(n, size, strict=True)]
    grid = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)
    index = np.arange(len(grid)).reshape(n[0] + 1, n[1] + 1, n[2] + 1)
    cells = []
    for i in range(n[0]):
        for j in range(n[1]):
            for k in range(n[2]):
                cells.append(
                    [
                        index[i, j, k],
                        index[i + 1, j, k],
                        index[i + 1, j + 1, k],
                        index[i, j + 1, k],
                        index[i, j, k + 1],
                        index[i + 1, j, k + 1],
                        index[i + 1, j + 1, k + 1],
                        index[i, j + 1, k + 1],
                    ]
                )
    return grid, np.array(cells)


def _signed_volume(points, cell, kind):
    ref = REFERENCE_ELEMENTS[VOLUME_CELLS[kind].reference]
    centre = ref.nodes.mean(axis=0)[None, :]
    jac = np.einsum("qnj,ni->ij", ref.gradients(centre), points[list(cell)])
    return np.linalg.det(jac)


def _orient(points, cell, kind):
    """The cell with its vertex order flipped when its Jacobian is negative
    (code_aster meshes come oriented; these generated ones may not be)."""
    if _signed_volume(points, cell, kind) > 0:
        return list(cell)
    if kind == "TETRA4":
        return [cell[0], cell[2], cell[1], cell[3]]
    if kind == "PENTA6":
        return [cell[0], cell[2], cell[1], cell[3], cell[5], cell[4]]
    if kind == "PYRAM5":
        return [cell[0], cell[3], cell[2], cell[1], cell[4]]
    return [cell[0], cell[3], cell[2], cell[1], cell[4], cell[7], cell[6], cell[5]]


def _split(points, hexes, kind):
    points = list(points)
    out = []
    for hexa in hexes:
        if kind == "HEXA8":
            out.append(list(hexa))
        elif kind == "PENTA6":
            out += [[hexa[v] for v in w] for w in _WEDGES]
        elif kind == "TETRA4":
            out += [[hexa[v] for v in t] for t in _TETS]
        else:  # pyramids on the six faces, apex at the centre
            points.append(np.mean([points[v] for v in hexa], axis=0))
            apex = len(points) - 1
            faces = [(0, 1, 2, 3), (4, 7, 6, 5), (0, 4, 5, 1)]
            faces += [(1, 5, 6, 2), (2, 6, 7, 3), (3, 7, 4, 0)]
            out += [[hexa[a], hexa[b], hexa[c], hexa[d], apex] for a, b, c, d in faces]
    points = np.array(points)
    return points, [_orient(points, cell, kind) for cell in out]


def _higher_order(points, cells, kind):
    """Add the non-vertex nodes of ``kind``, shared by the cells."""
    ref = REFERENCE_ELEMENTS[VOLUME_CELLS[kind].reference]
    linear = REFERENCE_ELEMENTS[VOLUME_CELLS[LINEAR_OF[kind]].reference]
    n_vertices = linear.n_nodes
    # each extra node: the reference vertices it is the centre of
    parents = []
    for extra in ref.nodes[n_vertices:]:
        # the union of the vertex pairs centred on it: an edge, a face, the cell
        found = set()
        for pair in combinations(range(n_vertices), 2):
            if np.allclose(linear.nodes[list(pair)].mean(axis=0), extra):
                found.update(pair)
        assert found, f"no parents for {extra} in {kind}"
        parents.append(tuple(sorted(found)))
    points = list(points)
    shared: dict[tuple, int] = {}
    out = []
    for cell in cells:
        full = list(cell)
        for group in parents:
            key = tuple(sorted(cell[v] for v in group))
            if key not in shared:
                points.append(np.mean([points[v] for v in key], axis=0))
                shared[key] = len(points) - 1
            full.append(shared[key])
        out.append(full)
    return np.array(points), out


def box_mesh(kind, n=(2, 2, 2), size=(1.0, 1.0, 1.0), jitter=0.0, seed=0):
    """A box [0, size] meshed with ``kind`` cells; interior vertices moved at
    random by ``jitter`` times the cell size (straight edges are kept)."""
    grid, hexes = _box_grid(n, size)
    if jitter:
        rng = np.random.default_rng(seed)
        h = np.array(size) / np.array(n)
        inside = np.all((grid > 1e-12) & (grid < np.array(size) - 1e-12), axis=1)
        grid = grid.copy()
        grid[inside] += jitter * h * rng.uniform(-1, 1, (int(inside.sum()), 3))
    points, cells = _split(grid, hexes, LINEAR_OF[kind])
    if kind != LINEAR_OF[kind]:
        points, cells = _higher_order(points, cells, kind)
    return Mesh(
        coords=np.asarray(points, dtype=float),
        node_names=[f"N{i + 1}" for i in range(len(points))],
        cell_names=[f"M{i + 1}" for i in range(len(cells))],
        cell_types=[kind] * len(cells),
        cell_nodes=[tuple(int(v) for v in c) for c in cells],
    )


def solid_model(mesh, young=2.0e11, poisson=0.3, density=7800.0, **extra):
    model = Model(mesh=mesh, cell_modelisation={c: "3D" for c in range(mesh.n_cells)})
    material = Material(behaviours={"ELAS": {"E": young, "NU": poisson, "RHO": density, **extra}})
    field = MaterialField(mesh=mesh, cell_material={c: material for c in range(mesh.n_cells)})
    return model, field


def with_side_faces(mesh, sides: dict[str, tuple[int, float]]):
    """The mesh plus face cells (QUAD4 / QUAD8, any orientation) on box sides:
    ``sides[group] = (axis, level)``; each group becomes a cell group and a
    node group of the same name."""
    kind = mesh.cell_types[0]
    if kind not in ("HEXA8", "HEXA20"):
        raise ValueError("side faces are made for HEXA8 and HEXA20 boxes")
    quadratic = kind == "HEXA20"
    ref = REFERENCE_ELEMENTS["H20"]
    cells, types, groups, node_groups = list(mesh.cell_nodes), list(mesh.cell_types), {}, {}
    for group, (axis, level) in sides.items():
        members = []
        for nodes in mesh.cell_nodes:
            on = [i for i in range(8) if abs(mesh.coords[nodes[i], axis] - level) < 1e-12]
            if len(on) != 4:
                continue
            # vertices around the face: sorted by angle about its centre
            others = [a for a in range(3) if a != axis]
            points = mesh.coords[[nodes[i] for i in on]][:, others]
            angles = np.arctan2(*(points - points.mean(axis=0)).T[::-1])
            cycle = [on[i] for i in np.argsort(angles)]
            face = [nodes[i] for i in cycle]
            if quadratic:
                for a, b in zip(cycle, cycle[1:] + cycle[:1], strict=True):
                    middle = (ref.nodes[a] + ref.nodes[b]) / 2.0
                    k = int(np.argmin(np.linalg.norm(ref.nodes - middle, axis=1)))
                    face.append(nodes[k])
            members.append(len(cells))
            cells.append(tuple(face))
            types.append("QUAD8" if quadratic else "QUAD4")
        groups[group] = np.array(members, dtype=int)
        node_groups[group] = np.unique([n for c in members for n in cells[c]])
    return Mesh(
        coords=mesh.coords,
        node_names=mesh.node_names,
        cell_names=[f"M{i + 1}" for i in range(len(cells))],
        cell_types=types,
        cell_nodes=cells,
        cell_groups={"VOL": np.arange(mesh.n_cells), **groups},
        node_groups=node_groups,
    )


def aster_mesh_text(mesh) -> str:
    """The mesh in code_aster's ASTER text format."""
    lines = ["TITRE", "box for the solid-element tests", "FINSF", "COOR_3D"]
    for name, (x, y, z) in zip(mesh.node_names, mesh.coords, strict=True):
        lines.append(f"{name} {x:.17e} {y:.17e} {z:.17e}")
    lines.append("FINSF")
    for kind in dict.fromkeys(mesh.cell_types):
        lines.append(kind)
        for c, (t, nodes) in enumerate(zip(mesh.cell_types, mesh.cell_nodes, strict=True)):
            if t == kind:
                lines.append(" ".join([mesh.cell_names[c]] + [mesh.node_names[n] for n in nodes]))
        lines.append("FINSF")
    for keyword, groups, names in (
        ("GROUP_MA", mesh.cell_groups, mesh.cell_names),
        ("GROUP_NO", mesh.node_groups, mesh.node_names),
    ):
        for group, members in groups.items():
            lines += [keyword, group] + [names[i] for i in members] + ["FINSF"]
    lines.append("FIN")
    return "\n".join(lines) + "\n"
