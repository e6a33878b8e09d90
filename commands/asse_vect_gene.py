"""ASSE_VECT_GENE: loads projected on the substructures' bases, Φ_kᵀ f_k,
each in its substructure's block of the generalized unknowns."""

from __future__ import annotations

import numpy as np
from asterlite.commands.proj_vect_base import on_numbering

from asterlite.concepts.modes import GeneralizedVector
from asterlite.concepts.substructure import SubstructuredNumbering


def run(ctx, kw):
    numbering = kw["NUME_DDL_GENE"]
    if not isinstance(numbering, SubstructuredNumbering):
        ctx.error("NUME_DDL_GENE must be built on a MODELE_GENE", "NUME_DDL_GENE", kw)
    values = np.zeros(numbering.n_modes)
    if kw.get("METHODE", "CLASSIQUE") == "INITIAL":
        if numbering.method == "ELIMINE":
            ctx.unsupported("METHODE='INITIAL' on an eliminated numbering", "METHODE", kw)
        # code_aster's INITIAL: a zero vector on the numbering (nothing projected)
        return GeneralizedVector(numbering=numbering, values=values, kind="FORC")
    for occ in kw.factor("CHAR_SOUS_STRUC"):
        sub = numbering.model.find(occ["SOUS_STRUC"])
        if sub is None:
            ctx.error(f"no substructure {occ['SOUS_STRUC']!r}", "SOUS_STRUC", occ)
        basis = sub.macro.basis
        field = on_numbering(ctx, occ, occ["VECT_ASSE"], basis.numbering)
        values[numbering.block(sub.name)] += basis.shapes.T @ np.asarray(field)
    return GeneralizedVector(numbering=numbering, values=values, kind="FORC")
