"""CALC_MATR_ELEM: element matrices (RIGI_MECA, MASS_MECA[_DIAG], AMOR_MECA,
MECA_GYRO, RIGI_GYRO, RIGI_MECA_HYST).

AMOR_MECA is code_aster's: the A_* characteristics of discrete elements plus
the Rayleigh damping AMOR_ALPHA K_e + AMOR_BETA M_e of the other elements.
K_e and M_e are recomputed from MODELE / CARA_ELEM / CHAM_MATER; the
RIGI_MECA / MASS_MECA element matrices a deck passes must come from the same
model (they would be the same matrices). MECA_GYRO / RIGI_GYRO are the
gyroscopic matrices of beams and disks (non-symmetric); RIGI_MECA_HYST the
complex stiffness K_e (1 + i AMOR_HYST) (its RIGI_MECA matrices must come from
the same model and are recomputed).

Element matrices of more than ``ElementaryMatrices.RELEASE_BYTES`` are not
held between commands: computed here (where their errors are reported),
then made again from the same concepts by the ASSE_MATRICE that reads them.
"""

from __future__ import annotations

from functools import partial

from asterlite.concepts.assembly import ComplexElementaryMatrices, ElementaryMatrices
from asterlite.fem.elements import ElementError
from asterlite.fem.options import COMPLEX_OPTIONS, OPTIONS, option_blocks
from asterlite.fem.selection import as_tuple, select_cells


def run(ctx, kw):
    option = kw["OPTION"]
    if option not in OPTIONS:
        ctx.unsupported(f"CALC_MATR_ELEM OPTION={option!r}", "OPTION", kw)
    model = kw["MODELE"]
    characteristics = kw.get("CARA_ELEM")
    materials = kw.get("CHAM_MATER")
    loads = list(as_tuple(kw.get("CHARGE")))
    stiffness = kw.get("RIGI_MECA")
    if option == "RIGI_MECA_HYST" and stiffness is not None:
        # code_aster builds it from the given RIGI_MECA element matrices
        characteristics = characteristics or stiffness.characteristics
        materials = materials or stiffness.materials
        loads = loads or list(stiffness.loads)
    if characteristics is not None and characteristics.model is not model:
        ctx.error("CARA_ELEM was built on another model", "CARA_ELEM", kw)
    for keyword in ("RIGI_MECA", "MASS_MECA"):
        given = kw.get(keyword)
        if given is not None and given.model is not model:
            ctx.error(f"{keyword} was computed on another model", keyword, kw)
    cells = select_cells(ctx, kw, model.mesh) if kw.get("GROUP_MA") else None
    try:
        blocks = option_blocks(model, characteristics, option, materials=materials, cells=cells)
    except NotImplementedError as exc:
        ctx.unsupported(str(exc), "MODELE", kw)
    except (ElementError, ValueError) as exc:
        ctx.error(str(exc), "CHAM_MATER" if "material" in str(exc) else "CARA_ELEM", kw)
    cls = ComplexElementaryMatrices if option in COMPLEX_OPTIONS else ElementaryMatrices
    result = cls(
        model=model,
        option=option,
        blocks=blocks,
        loads=loads,
        characteristics=characteristics,
        materials=materials,
        # the same computation from the same (unchanging) concepts
        recompute=partial(option_blocks, model, characteristics, option, materials, cells),
    )
    result.release()  # large matrices are made again by the command that reads them
    return result
