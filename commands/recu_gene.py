"""RECU_GENE: the generalized coordinates of a tran_gene at one instant, as a
generalized vector (vect_asse_gene)."""

from __future__ import annotations

from asterlite.concepts.modes import GeneralizedNumbering, GeneralizedVector
from asterlite.concepts.transient import TranGene
from asterlite.post.restitution import selection_from_keywords


def run(ctx, kw):
    result = kw["RESU_GENE"]
    if not isinstance(result, TranGene):
        ctx.unsupported(f"RECU_GENE from a {result.aster_type}", "RESU_GENE", kw)
    field = kw.get("NOM_CHAM", "DEPL")
    if field not in ("DEPL", "VITE", "ACCE"):
        ctx.unsupported(f"NOM_CHAM={field!r}", "NOM_CHAM", kw)
    selection = selection_from_keywords(ctx, kw, result.times, result.order, "LIN")
    if selection.times.size != 1:
        ctx.error("RECU_GENE extracts one instant: give INST or NUME_ORDRE", "INST", kw)
    values = selection.apply(getattr(result, field.lower()))[0]
    numbering = result.info.get("numbering") or GeneralizedNumbering(result.basis)
    return GeneralizedVector(numbering, values, kind=field)
