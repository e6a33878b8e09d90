"""DEFI_CONSTANTE: a constant function (one point, constant on both sides)."""

from __future__ import annotations

from asterlite.concepts.function import Function


def run(ctx, kw):
    return Function(
        [1.0],
        [float(kw["VALE"])],
        NOM_PARA="TOUTPARA",
        NOM_RESU=kw.get("NOM_RESU", "TOUTRESU"),
        PROL_GAUCHE="CONSTANT",
        PROL_DROITE="CONSTANT",
    )
