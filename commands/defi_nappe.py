"""DEFI_NAPPE: a :class:`Nappe` from PARA and one function per value, given
as FONCTION (functions of one parameter) or DEFI_FONCTION (value lists of
NOM_PARA_FONC)."""

from __future__ import annotations

import numpy as np
from asterlite.commands.defi_fonction import check_abscissas

from asterlite.concepts.function import ComplexFunction, Function, Nappe
from asterlite.post.restitution import values_of


def run(ctx, kw):
    kw.mark_used("INFO")  # the listing's detail only
    parameters = values_of(kw["PARA"])
    if np.any(np.diff(parameters) <= 0):
        # code_aster sorts the functions by increasing parameter and refuses repeats
        ctx.error("PARA must increase strictly", "PARA", kw)
    if kw.get("FONCTION") is not None:
        functions = (
            list(kw["FONCTION"]) if isinstance(kw["FONCTION"], list | tuple) else [kw["FONCTION"]]
        )
        for function in functions:
            if isinstance(function, ComplexFunction) or not isinstance(function, Function):
                ctx.error("a nappe takes real functions of one parameter", "FONCTION", kw)
        names = {function.NOM_PARA for function in functions}
        if len(names) > 1:
            ctx.error(
                f"the functions have different parameters: {', '.join(sorted(names))}",
                "FONCTION",
                kw,
            )
        para_fonc = names.pop()
    else:
        functions = []
        para_fonc = kw["NOM_PARA_FONC"]
        for occ in kw.factor("DEFI_FONCTION"):
            values = values_of(occ["VALE"])
            if values.size % 2:
                ctx.error("VALE holds (abscissa, value) pairs: an odd count", "VALE", occ)
            x, y = values[0::2], values[1::2]
            check_abscissas(ctx, kw, x)
            functions.append(
                Function(
                    x,
                    y,
                    NOM_PARA=para_fonc,
                    NOM_RESU=kw.get("NOM_RESU", "TOUTRESU"),
                    INTERPOL=occ.get("INTERPOL", ("LIN", "LIN")),
                    PROL_GAUCHE=occ.get("PROL_GAUCHE", "EXCLU"),
                    PROL_DROITE=occ.get("PROL_DROITE", "EXCLU"),
                )
            )
    if len(functions) != parameters.size:
        ctx.error(f"{parameters.size} values of PARA but {len(functions)} functions", "PARA", kw)
    return Nappe(
        parameters,
        functions,
        NOM_PARA=kw["NOM_PARA"],
        NOM_RESU=kw.get("NOM_RESU", "TOUTRESU"),
        NOM_PARA_FONC=para_fonc,
        INTERPOL=kw.get("INTERPOL", ("LIN", "LIN")),
        PROL_GAUCHE=kw.get("PROL_GAUCHE", "EXCLU"),
        PROL_DROITE=kw.get("PROL_DROITE", "EXCLU"),
        title=kw.get("TITRE") or "",
    )
