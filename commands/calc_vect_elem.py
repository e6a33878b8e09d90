"""CALC_VECT_ELEM OPTION='CHAR_MECA': nodal load terms of mechanical loads
(nodal forces, gravity, distributed beam forces)."""

from __future__ import annotations

from asterlite.concepts.assembly import ElementaryVectors
from asterlite.fem.elements import ElementError
from asterlite.fem.loads import gravity_terms, load_terms
from asterlite.fem.selection import as_tuple

__all__ = ["gravity_terms", "run"]


def run(ctx, kw):
    option = kw.get("OPTION", "CHAR_MECA")
    if option != "CHAR_MECA":
        ctx.unsupported(f"CALC_VECT_ELEM OPTION={option!r}", "OPTION", kw)
    loads = list(as_tuple(kw.get("CHARGE")))
    model = kw.get("MODELE") or (loads[0].model if loads else None)
    characteristics = kw.get("CARA_ELEM")
    materials = kw.get("CHAM_MATER")
    terms = []
    for load in loads:
        needs_cara = any(m != "3D" for m in load.model.cell_modelisation.values())
        if load.extra.get("PESANTEUR") is not None and characteristics is None and needs_cara:
            ctx.error("PESANTEUR needs CARA_ELEM to know the masses", "CARA_ELEM", kw)
        try:
            terms.extend(load_terms(load, characteristics, materials))
        except NotImplementedError as exc:
            ctx.unsupported(str(exc), "CHARGE", kw)
        except (ElementError, ValueError) as exc:
            ctx.error(str(exc), "CHARGE", kw)
    return ElementaryVectors(model=model, option=option, loads=loads, terms=terms)
