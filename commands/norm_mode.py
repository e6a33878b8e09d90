"""NORM_MODE: renormalise a modal basis (NORME, GROUP_NO + NOM_CMP, AVEC_CMP,
SANS_CMP) and optionally impose a sign (MODE_SIGNE)."""

from __future__ import annotations

import numpy as np

from asterlite.fem.selection import as_scalar, as_tuple, named_nodes, node_group_members
from asterlite.modal import normalize
from asterlite.modal.calc import apply_norm


def _single_node(ctx, occ, mesh, keyword):
    nodes = node_group_members(ctx, occ, mesh) + named_nodes(ctx, occ, mesh)
    if len(nodes) != 1:
        ctx.error(f"{keyword} must name exactly one node (got {len(nodes)})", keyword, occ)
    return nodes[0]


def run(ctx, kw):
    source = kw["MODE"]
    modes = source if ctx.reuse is source else source.select(np.arange(source.n_modes))
    numbering = modes.numbering
    stiffness = kw["RAIDE"].matrix if kw.get("RAIDE") is not None else None
    mass = kw["MASSE"].matrix if kw.get("MASSE") is not None else None
    if kw.get("NORME") is not None:
        norme = kw["NORME"]
        if norme == "MASS_GENE" and mass is None and modes.mass is None:
            ctx.error("MASS_GENE needs the mass matrix (MASSE)", "MASSE", kw)
        if norme == "RIGI_GENE" and stiffness is None and modes.stiffness is None:
            ctx.error("RIGI_GENE needs the stiffness matrix (RAIDE)", "RAIDE", kw)
        apply_norm(modes, norme, stiffness=stiffness, mass=mass)
    elif kw.get("GROUP_NO") is not None or kw.get("NOEUD") is not None:
        node = _single_node(ctx, kw, numbering.mesh, "GROUP_NO")
        comp = as_scalar(kw["NOM_CMP"])
        row = numbering.index.get((node, comp))
        if row is None:
            ctx.error(f"node {numbering.mesh.node_names[node]} has no {comp}", "NOM_CMP", kw)
        modes.rescale(
            normalize.at_dof(modes.shapes, row), f"{numbering.mesh.node_names[node]} {comp}"
        )
    else:
        comps = numbering.dof_components
        with_cmp, without = as_tuple(kw.get("AVEC_CMP")), as_tuple(kw.get("SANS_CMP"))
        mask = normalize.component_mask(comps, with_cmp or None, without or None)
        label = (
            ("AVEC_CMP: " + " ".join(with_cmp)) if with_cmp else ("SANS_CMP: " + " ".join(without))
        )
        modes.rescale(normalize.largest_component(modes.shapes, mask), label)
    for occ in kw.factor("MODE_SIGNE"):
        node = _single_node(ctx, occ, numbering.mesh, "GROUP_NO")
        comp = as_scalar(occ["NOM_CMP"])
        row = numbering.index.get((node, comp))
        if row is None:
            ctx.error(f"node {numbering.mesh.node_names[node]} has no {comp}", "NOM_CMP", occ)
        values = modes.shapes[row]
        wanted = 1.0 if occ.get("SIGNE", "POSITIF") == "POSITIF" else -1.0
        flip = np.where(values * wanted < 0, -1.0, 1.0)
        modes.rescale(flip)
    return modes
