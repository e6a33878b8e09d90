"""CALC_VECT_ELEM OPTION='CHAR_MECA': nodal load terms of mechanical loads
(nodal forces, gravity, distributed beam forces)."""

from __future__ import annotations

from asterlite.concepts.assembly import ElementaryVectors
from asterlite.fem.elements import ElementError
from asterlite.fem.loads import load_terms
from asterlite.fem.selection import as_tuple


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
        try:
            terms.extend(load_terms(load, characteristics, materials))
        except NotImplementedError as exc:
            ctx.unsupported(str(exc), "CHARGE", kw)
        except (ElementError, ValueError) as exc:
            # beams and discrete elements take their masses and sections from CARA_ELEM
            missing = characteristics is None and "AFFE_CARA_ELEM" in str(exc)
            ctx.error(str(exc), "CARA_ELEM" if missing else "CHARGE", kw)
    return ElementaryVectors(model=model, option=option, loads=loads, terms=terms)
