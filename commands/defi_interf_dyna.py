"""DEFI_INTERF_DYNA: name the interfaces of a substructure and their type."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.substructure import DynamicInterfaces, Interface
from asterlite.fem.selection import as_tuple, select_nodes
from asterlite.substructure.interfaces import interface_dofs


def run(ctx, kw):
    numbering = kw["NUME_DDL"]
    interfaces = []
    for occ in kw.factor("INTERFACE"):
        name = occ["NOM"]
        if any(i.name == name for i in interfaces):
            ctx.error(f"interface {name!r} is defined twice", "NOM", occ)
        nodes = np.sort(select_nodes(ctx, occ, numbering.mesh))
        masked = as_tuple(occ.get("MASQUE"))
        dofs, owners = interface_dofs(numbering, nodes, masked)
        if dofs.size == 0 and occ["TYPE"] != "AUCUN":
            ctx.error(f"interface {name!r} holds no DOF of the numbering", "GROUP_NO", occ)
        interfaces.append(Interface(name, occ["TYPE"], nodes, masked, dofs, owners))
        ctx.log(f"interface {name} ({occ['TYPE']}): {nodes.size} node(s), {dofs.size} DOF(s)")
    return DynamicInterfaces(numbering, interfaces, float(kw.get("FREQ", 1.0)))
