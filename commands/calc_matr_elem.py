"""CALC_MATR_ELEM: element matrices (RIGI_MECA, MASS_MECA[_DIAG], AMOR_MECA).

AMOR_MECA is code_aster's: the A_* characteristics of discrete elements plus
the Rayleigh damping AMOR_ALPHA K_e + AMOR_BETA M_e of the other elements.
K_e and M_e are recomputed from MODELE / CARA_ELEM / CHAM_MATER; the
RIGI_MECA / MASS_MECA element matrices a deck passes must come from the same
model (they would be the same matrices).
"""

from __future__ import annotations

from asterlite.concepts.assembly import ElementaryMatrices
from asterlite.fem.elements import ElementError, element_blocks
from asterlite.fem.selection import as_tuple, select_cells

_MATRIX_OF_OPTION = {
    "RIGI_MECA": "K",
    "MASS_MECA": "M",
    "MASS_MECA_DIAG": "M",
    "AMOR_MECA": "A",
}


def run(ctx, kw):
    option = kw["OPTION"]
    if option not in _MATRIX_OF_OPTION:
        ctx.unsupported(f"CALC_MATR_ELEM OPTION={option!r}", "OPTION", kw)
    model = kw["MODELE"]
    characteristics = kw.get("CARA_ELEM")
    materials = kw.get("CHAM_MATER")
    loads = list(as_tuple(kw.get("CHARGE")))
    if characteristics is not None and characteristics.model is not model:
        ctx.error("CARA_ELEM was built on another model", "CARA_ELEM", kw)
    for keyword in ("RIGI_MECA", "MASS_MECA"):
        given = kw.get(keyword)
        if given is not None and given.model is not model:
            ctx.error(f"{keyword} was computed on another model", keyword, kw)
    cells = select_cells(ctx, kw, model.mesh) if kw.get("GROUP_MA") else None
    try:
        blocks = element_blocks(
            model,
            characteristics,
            _MATRIX_OF_OPTION[option],
            materials=materials,
            lumped=option == "MASS_MECA_DIAG",
            cells=cells,
        )
    except NotImplementedError as exc:
        ctx.unsupported(str(exc), "MODELE", kw)
    except (ElementError, ValueError) as exc:
        ctx.error(str(exc), "CHAM_MATER" if "material" in str(exc) else "CARA_ELEM", kw)
    return ElementaryMatrices(
        model=model,
        option=option,
        blocks=blocks,
        loads=loads,
        characteristics=characteristics,
        materials=materials,
    )
