"""INFO_FONCTION: characteristic values of functions in a table (MAX, RMS,
ECART_TYPE). Numerics: asterlite.post.functions."""

from __future__ import annotations

from asterlite.concepts.function import Nappe
from asterlite.concepts.table import Table
from asterlite.errors import CommandError
from asterlite.post import functions as fops
from asterlite.post.restitution import as_tuple


def run(ctx, kw):
    table = Table()
    try:
        if kw.get("MAX") is not None:
            maxima(ctx, kw.factor("MAX")[0], table)
        elif kw.get("RMS") is not None:
            for occ in kw.factor("RMS"):
                windowed(occ, table, "RMS", fops.rms)
        elif kw.get("ECART_TYPE") is not None:
            windowed(kw.factor("ECART_TYPE")[0], table, "ECART_TYPE", fops.standard_deviation)
        else:
            which = next(k for k in ("NOCI_SEISME", "NORME") if kw.get(k) is not None)
            ctx.unsupported(f"INFO_FONCTION/{which}", which, kw)
    except CommandError as exc:
        if exc.location is None:
            ctx.error(exc.message, None, kw)
        raise
    return table


def maxima(ctx, occ, table):
    functions = as_tuple(occ["FONCTION"])
    intervals = as_tuple(occ.get("INTERVALLE"))
    for func in functions:
        if isinstance(func, Nappe):
            ctx.unsupported("INFO_FONCTION/MAX of a nappe", "FONCTION", occ)
    table.add_column("FONCTION", "K24")
    table.add_column("TYPE", "K8")
    for func in functions:
        table.add_column(func.NOM_PARA, "R")
        table.add_column(func.NOM_RESU, "R")
    for func in functions:
        for kind, x, y in fops.extrema(func, intervals or None):
            table.add_row(
                {"FONCTION": func.name or "", "TYPE": kind, func.NOM_PARA: x, func.NOM_RESU: y}
            )


def windowed(occ, table, name, statistic):
    func = occ["FONCTION"]
    start, stop = occ.get("INST_INIT"), occ.get("INST_FIN")
    precision, criterion = occ.get("PRECISION", 1e-6), occ.get("CRITERE", "RELATIF")
    value = statistic(func, occ.get("METHODE", "TRAPEZE"), start, stop, precision, criterion)
    table.add_row(
        {
            "FONCTION": func.name or "",
            "METHODE": occ.get("METHODE", "TRAPEZE"),
            "INST_INIT": float(func.abscissas[0] if start is None else start),
            "INST_FIN": float(func.abscissas[-1] if stop is None else stop),
            name: value,
        },
        types={"FONCTION": "K24", "METHODE": "K8"},
    )
