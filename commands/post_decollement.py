"""POST_DECOLLEMENT: at each instant of the result, the percentage of the
area of GROUP_MA where the component NOM_CMP of NOM_CHAM is positive (the
foundation has lifted off), as code_aster's post_decollement_ops measures
it: each node of the surface takes 1 where the component is positive, 0
elsewhere; that nodal field interpolated by the cells' shape functions is
integrated over the surface and divided by its area. The integral is exact:
the share of node i of a cell is the integral of its shape function (a third
of a triangle; for a quadrangle, the 2x2 Gauss rule, exact for bilinear
shape functions times their Jacobian)."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.table import Table
from asterlite.fem.selection import cell_group_members

_GAUSS = np.array([-1.0, 1.0]) / np.sqrt(3.0)


def _node_shares(coords: np.ndarray, nodes, cell_type: str) -> np.ndarray:
    """∫ N_i dA of each node of a linear surface cell."""
    p = coords[list(nodes)]
    if cell_type == "TRIA3":
        area = 0.5 * np.linalg.norm(np.cross(p[1] - p[0], p[2] - p[0]))
        return np.full(3, area / 3.0)
    shares = np.zeros(4)
    for xi in _GAUSS:
        for eta in _GAUSS:
            shape = 0.25 * np.array(
                [
                    (1 - xi) * (1 - eta),
                    (1 + xi) * (1 - eta),
                    (1 + xi) * (1 + eta),
                    (1 - xi) * (1 + eta),
                ]
            )
            d_xi = 0.25 * np.array([-(1 - eta), 1 - eta, 1 + eta, -(1 + eta)]) @ p
            d_eta = 0.25 * np.array([-(1 - xi), -(1 + xi), 1 + xi, 1 - xi]) @ p
            shares += shape * np.linalg.norm(np.cross(d_xi, d_eta))
    return shares


def run(ctx, kw):
    result = kw["RESULTAT"]
    name, component = kw["NOM_CHAM"], kw["NOM_CMP"]
    values = getattr(result, "fields", {}).get(name)
    if values is None:
        ctx.error(f"the result has no field {name}", "NOM_CHAM", kw)
    mesh = result.numbering.mesh
    coords = np.asarray(mesh.coords, dtype=float)
    if coords.shape[1] < 3:
        coords = np.pad(coords, ((0, 0), (0, 3 - coords.shape[1])))
    cells = cell_group_members(ctx, kw, mesh)
    share_of: dict[int, float] = {}
    for cell in cells:
        cell_type = mesh.cell_types[cell]
        if cell_type not in ("TRIA3", "QUAD4"):
            ctx.unsupported(f"POST_DECOLLEMENT on {cell_type} cells (TRIA3, QUAD4)", "GROUP_MA", kw)
        nodes = mesh.cell_nodes[cell]
        for node, share in zip(nodes, _node_shares(coords, nodes, cell_type), strict=True):
            share_of[int(node)] = share_of.get(int(node), 0.0) + float(share)
    nodes = np.array(sorted(share_of), dtype=int)
    shares = np.array([share_of[n] for n in nodes])
    area = shares.sum()
    if area <= 0.0:
        ctx.error("the surface has no area", "GROUP_MA", kw)
    rows = result.numbering.dof_indices(nodes, component)
    carried = rows >= 0
    if not carried.any():
        ctx.error(f"no node of the surface carries {component}", "NOM_CMP", kw)
    component_values = np.asarray(values, dtype=float)[:, rows[carried]]
    lifted = (component_values > 0.0) @ shares[carried]
    table = Table(title="POST_DECOLLEMENT")
    for t, part in zip(np.asarray(result.times, dtype=float), lifted, strict=True):
        table.add_row({"INST": float(t), "%DECOL": 100.0 * float(part) / area})
    ctx.log(f"POST_DECOLLEMENT: {nodes.size} nodes, area {area:g}, {len(table.rows)} instants")
    return table
