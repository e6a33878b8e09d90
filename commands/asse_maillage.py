"""ASSE_MAILLAGE OPERATION='SOUS_STR': a mesh of superelements and cells
(code_aster's asmael).

The nodes of MAILLAGE_1, then those of MAILLAGE_2 whose name MAILLAGE_1
does not have (a node of the same name is the same node: that is how a
superelement's external nodes meet the cells of the other mesh); cells and
super-cells of both (a name in both is an error); the groups of
MAILLAGE_1, then those of MAILLAGE_2 whose name is new (code_aster warns
and keeps MAILLAGE_1's).

OPERATION='SUPERPOSE' (code_aster's asmasu): every node, cell and group of
both meshes, MAILLAGE_1's first; nodes and cells are renamed (the result
names them by position, N<i> and M<i>); a group of MAILLAGE_2 whose name
MAILLAGE_1 has takes its first 7 characters padded with '_' and a digit 0-9,
the first free. COLLAGE is not computed.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.mesh import Mesh
from asterlite.concepts.static_substructure import SuperCell, SuperMesh


def run(ctx, kw):
    operation = kw["OPERATION"]
    if operation == "SUPERPOSE":
        return superposed(ctx, kw)
    if operation != "SOUS_STR":
        ctx.unsupported(f"ASSE_MAILLAGE OPERATION={operation!r}", "OPERATION", kw)
    first, second = kw["MAILLAGE_1"], kw["MAILLAGE_2"]
    if first.dim != second.dim:
        ctx.log("warning: the two meshes have different dimensions")
    # MAILLAGE_2's nodes: the node of the same name in MAILLAGE_1, or a new one
    renumber = np.empty(second.n_nodes, dtype=int)
    # the names code_aster sees: N<i> of a mesh that keeps none
    names = [first.node_label(i) for i in range(first.n_nodes)]
    by_name = {name: i for i, name in enumerate(names)}
    coords = [first.coords]
    fresh = []
    for k in range(second.n_nodes):
        name = second.node_label(k)
        found = by_name.get(name)
        if found is None:
            found = len(names)
            names.append(name)
            fresh.append(k)
        renumber[k] = found
    coords.append(second.coords[fresh])
    twice = sorted(set(first.cell_names) & set(second.cell_names))
    if twice:
        ctx.error(f"cells named in both meshes: {', '.join(twice[:5])}", "MAILLAGE_2", kw)
    cells_1 = getattr(first, "super_cells", {})
    cells_2 = getattr(second, "super_cells", {})
    twice = sorted(set(cells_1) & set(cells_2))
    if twice:
        ctx.error(f"super-cells named in both meshes: {', '.join(twice)}", "MAILLAGE_2", kw)
    super_cells = dict(cells_1)
    for name, cell in cells_2.items():
        super_cells[name] = SuperCell(
            macro=cell.macro, nodes=renumber[cell.nodes], rotation=cell.rotation
        )
    n_cells_1 = first.n_cells
    mesh = SuperMesh(
        coords=np.vstack(coords),
        node_names=names,
        cell_names=list(first.cell_names) + list(second.cell_names),
        cell_types=list(first.cell_types) + list(second.cell_types),
        cell_nodes=list(first.cell_nodes)
        + [tuple(int(renumber[n]) for n in nodes) for nodes in second.cell_nodes],
        dim=max(first.dim, second.dim),
        super_cells=super_cells,
    )
    mesh.node_groups = {k: v.copy() for k, v in first.node_groups.items()}
    for name, members in second.node_groups.items():
        if name in mesh.node_groups:
            ctx.log(f"warning: group of nodes {name} is in both meshes: MAILLAGE_1's kept")
            continue
        mesh.node_groups[name] = renumber[members]
    mesh.cell_groups = {k: v.copy() for k, v in first.cell_groups.items()}
    for name, members in second.cell_groups.items():
        if name in mesh.cell_groups:
            ctx.log(f"warning: group of cells {name} is in both meshes: MAILLAGE_1's kept")
            continue
        mesh.cell_groups[name] = np.asarray(members, dtype=int) + n_cells_1
    ctx.log(
        f"ASSE_MAILLAGE SOUS_STR: {mesh.n_nodes} nodes ({second.n_nodes - len(fresh)} shared), "
        f"{mesh.n_cells} cells, {len(super_cells)} super-cells"
    )
    return mesh


def superposed(ctx, kw) -> Mesh:
    first, second = kw["MAILLAGE_1"], kw["MAILLAGE_2"]
    for mesh, key in ((first, "MAILLAGE_1"), (second, "MAILLAGE_2")):
        if getattr(mesh, "super_cells", None):
            ctx.unsupported("ASSE_MAILLAGE SUPERPOSE of a mesh of superelements", key, kw)
    n_nodes, n_cells = first.n_nodes + second.n_nodes, first.n_cells + second.n_cells
    mesh = Mesh(
        coords=np.vstack([first.coords, second.coords]),
        node_names=[f"N{i + 1}" for i in range(n_nodes)],
        cell_names=[f"M{i + 1}" for i in range(n_cells)],
        cell_types=list(first.cell_types) + list(second.cell_types),
        cell_nodes=list(first.cell_nodes)
        + [tuple(int(n) + first.n_nodes for n in nodes) for nodes in second.cell_nodes],
        dim=max(first.dim, second.dim),
        names_kept=False,
    )
    for kind, offset in (("node", first.n_nodes), ("cell", first.n_cells)):
        groups = {
            k: np.asarray(v, dtype=int).copy() for k, v in getattr(first, f"{kind}_groups").items()
        }
        for name, members in getattr(second, f"{kind}_groups").items():
            new_name = name if name not in groups else renamed_group(name, groups)
            if new_name != name:
                ctx.log(f"warning: group of {kind}s {name} of MAILLAGE_2 renamed {new_name}")
            groups[new_name] = np.asarray(members, dtype=int) + offset
        setattr(mesh, f"{kind}_groups", groups)
    ctx.log(f"ASSE_MAILLAGE SUPERPOSE: {mesh.n_nodes} nodes, {mesh.n_cells} cells")
    return mesh


def renamed_group(name: str, taken) -> str:
    """code_aster's new name for a group of MAILLAGE_2 that MAILLAGE_1 has:
    its first 7 characters padded with '_', then the first digit 0-9 that
    makes it free (the last tried when none does)."""
    stem = name[:7].ljust(7, "_")
    for digit in range(10):
        candidate = f"{stem}{digit}"
        if candidate not in taken:
            break
    return candidate
