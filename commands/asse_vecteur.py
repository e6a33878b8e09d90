"""ASSE_VECTEUR: assemble nodal load terms on a DOF numbering; the field
keeps the values the loads' relations impose (RESOUDRE reads them)."""

from __future__ import annotations

from asterlite.concepts.assembly import NodalField
from asterlite.fem.assemble import assemble_terms
from asterlite.fem.selection import as_tuple


def run(ctx, kw):
    numbering = kw["NUME_DDL"]
    terms = [t for v in as_tuple(kw["VECT_ELEM"]) for t in v.terms]
    try:
        values = assemble_terms(terms, numbering)
    except KeyError as exc:
        ctx.error(f"load on DOFs the numbering does not have: {exc.args[0]}", "VECT_ELEM", kw)
    # the Lagrange terms of the second member: the values its loads impose
    imposed = {
        id(r): r.rhs for v in as_tuple(kw["VECT_ELEM"]) for load in v.loads for r in load.relations
    }
    return NodalField(numbering=numbering, values=values, relation_values=imposed)
