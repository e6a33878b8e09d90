"""CALC_MATR_ELEM: element matrices (RIGI_MECA, MASS_MECA[_DIAG], AMOR_MECA)."""

from __future__ import annotations

from asterlite.concepts.assembly import ElementaryMatrices
from asterlite.fem.elements import ElementError, element_blocks
from asterlite.fem.selection import as_tuple

_MATRIX_OF_OPTION = {
    "RIGI_MECA": "K",
    "MASS_MECA": "M",
    "MASS_MECA_DIAG": "M",  # discrete masses are used as given
    "AMOR_MECA": "A",
}


def run(ctx, kw):
    option = kw["OPTION"]
    if option not in _MATRIX_OF_OPTION:
        ctx.unsupported(f"CALC_MATR_ELEM OPTION={option!r}", "OPTION", kw)
    model = kw["MODELE"]
    characteristics = kw.get("CARA_ELEM")
    loads = list(as_tuple(kw.get("CHARGE")))
    if characteristics is not None and characteristics.model is not model:
        ctx.error("CARA_ELEM was built on another model", "CARA_ELEM", kw)
    try:
        blocks = element_blocks(model, characteristics, _MATRIX_OF_OPTION[option])
    except NotImplementedError as exc:
        ctx.unsupported(str(exc), "MODELE", kw)
    except (ElementError, ValueError) as exc:
        ctx.error(str(exc), "CARA_ELEM", kw)
    if option == "AMOR_MECA" and kw.get("CHAM_MATER") is not None:
        ctx.log("AMOR_MECA: Rayleigh damping of materials is not applied to discrete elements")
    return ElementaryMatrices(
        model=model, option=option, blocks=blocks, loads=loads, characteristics=characteristics
    )
