"""CALC_FONC_INTERP: tabulate a function or a formula on a list of values."""

from __future__ import annotations

from asterlite.concepts.function import ComplexFunction, Formula, Function
from asterlite.errors import CommandError
from asterlite.post.restitution import values_of


def run(ctx, kw):
    source = kw["FONCTION"]
    if kw.get("LIST_PARA") is not None:
        x = values_of(kw["LIST_PARA"])
    elif kw.get("VALE_PARA") is not None:
        x = values_of(kw["VALE_PARA"])
    else:
        ctx.error("LIST_PARA or VALE_PARA is required", "LIST_PARA", kw)
    if isinstance(source, Formula) and len(source.NOM_PARA) != 1:
        ctx.unsupported(
            f"CALC_FONC_INTERP of a formula of {len(source.NOM_PARA)} parameters (a nappe)",
            "FONCTION",
            kw,
        )
    try:
        y = source.evaluate(x)
    except CommandError as exc:
        ctx.error(exc.message, "FONCTION", kw)
    default_para = source.NOM_PARA if isinstance(source, Function) else source.NOM_PARA[0]
    cls = ComplexFunction if y.dtype.kind == "c" else Function
    return cls(
        x,
        y,
        NOM_PARA=kw.get("NOM_PARA") or default_para,
        NOM_RESU=kw.get("NOM_RESU") or getattr(source, "NOM_RESU", "TOUTRESU"),
        INTERPOL=kw.get("INTERPOL", ("LIN", "LIN")),
        PROL_GAUCHE=kw.get("PROL_GAUCHE", "EXCLU"),
        PROL_DROITE=kw.get("PROL_DROITE", "EXCLU"),
    )
