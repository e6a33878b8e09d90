"""DEFI_SQUELETTE: the skeleton mesh of a generalized model.

The chosen cells of each substructure (SOUS_STRUC: TOUT or GROUP_MA) are
copied in the global frame; nodes are renamed N1, N2... and cells MA1,
MA2... in substructure order (interface nodes are not merged), each
substructure's cells forming a group named after it, as code_aster's
classical skeleton does."""

from __future__ import annotations

import numpy as np

from asterlite.fem.selection import select_cells
from asterlite.substructure.restitution import build_skeleton

_REFUSED = ("CYCLIQUE", "MAILLAGE", "SQUELETTE", "RECO_GLOBAL", "NOM_GROUP_MA", "SECTEUR")


def run(ctx, kw):
    for keyword in _REFUSED:
        if keyword in kw:
            ctx.unsupported(f"DEFI_SQUELETTE {keyword}", keyword, kw)
    if kw.get("EXCLUSIF", "NON") != "NON":
        ctx.unsupported("DEFI_SQUELETTE EXCLUSIF='OUI'", "EXCLUSIF", kw)
    model = kw["MODELE_GENE"]
    selections = []
    occurrences = kw.factor("SOUS_STRUC")
    if not occurrences:
        ctx.unsupported("DEFI_SQUELETTE without SOUS_STRUC", "MODELE_GENE", kw)
    for occ in occurrences:
        sub = model.find(occ["NOM"])
        if sub is None:
            ctx.error(f"no substructure {occ['NOM']!r} in the generalized model", "NOM", occ)
        mesh = sub.macro.mesh
        cells = np.sort(select_cells(ctx, occ, mesh, all_cells=np.arange(mesh.n_cells)))
        selections.append((sub, cells))
    skeleton = build_skeleton(model, selections)
    ctx.log(f"skeleton: {skeleton.n_nodes} nodes, {skeleton.n_cells} cells")
    return skeleton
