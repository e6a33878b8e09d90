"""CREA_CHAMP: nodal displacement fields (OPERATION='AFFE', TYPE_CHAM='NOEU_DEPL_R')."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import NodalField
from asterlite.fem.selection import as_tuple, select_nodes


def _template_numbering(ctx, kw):
    for key in ("CHAM_NO", "NUME_DDL"):
        value = kw.get(key)
        if value is not None:
            return value if key == "NUME_DDL" else value.numbering
    model = kw.get("MODELE")
    if model is not None:
        from asterlite.concepts.assembly import DofNumbering
        from asterlite.fem.assemble import build_numbering_dofs

        return DofNumbering(mesh=model.mesh, dofs=build_numbering_dofs(model.node_components()))
    # MAILLAGE only: a field on exactly the (node, component) pairs affected
    from asterlite.concepts.assembly import DofNumbering
    from asterlite.fem.dofs import sort_components

    mesh = kw["MAILLAGE"]
    pairs: dict[int, set[str]] = {}
    for occ in kw.factor("AFFE"):
        for node in select_nodes(ctx, occ, mesh):
            pairs.setdefault(int(node), set()).update(as_tuple(occ.get("NOM_CMP")))
    dofs = [(n, c) for n in sorted(pairs) for c in sort_components(pairs[n])]
    return DofNumbering(mesh=mesh, dofs=dofs)


def _affe(ctx, kw):
    type_cham = kw.get("TYPE_CHAM")
    if type_cham not in ("NOEU_DEPL_R",):
        ctx.unsupported(f"CREA_CHAMP TYPE_CHAM={type_cham!r}", "TYPE_CHAM", kw)
    numbering = _template_numbering(ctx, kw)
    mesh = kw.get("MAILLAGE") or numbering.mesh
    if mesh is not numbering.mesh:
        ctx.error("the CHAM_NO template is on another mesh", "CHAM_NO", kw)
    values = np.zeros(numbering.n_dofs)
    by_node: dict[int, list[str]] = {}
    for node, comp in numbering.dofs:
        by_node.setdefault(node, []).append(comp)
    for occ in kw.factor("AFFE"):
        nodes = select_nodes(ctx, occ, mesh, all_nodes=sorted(by_node))
        comps = as_tuple(occ.get("NOM_CMP"))
        vals = as_tuple(occ.get("VALE"))
        if len(comps) != len(vals):
            ctx.error(f"NOM_CMP has {len(comps)} names but VALE {len(vals)} values", "VALE", occ)
        for comp, val in zip(comps, vals, strict=True):
            rows = numbering.dof_indices(nodes, comp)
            if np.all(rows < 0):
                ctx.error(f"no selected node carries {comp} in the numbering", "NOM_CMP", occ)
            if (
                np.any(rows < 0)
                and kw.get("PROL_ZERO", "NON") != "OUI"
                and occ.get("TOUT") != "OUI"
            ):
                missing = mesh.node_names[int(np.asarray(nodes)[rows < 0][0])]
                ctx.error(f"node {missing} has no {comp} in the numbering", "NOM_CMP", occ)
            values[rows[rows >= 0]] = float(val)
    return NodalField(numbering=numbering, values=values)


def run(ctx, kw):
    operation = kw.get("OPERATION")
    if operation == "AFFE":
        return _affe(ctx, kw)
    ctx.unsupported(f"CREA_CHAMP OPERATION={operation!r}", "OPERATION", kw)
