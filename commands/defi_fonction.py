"""DEFI_FONCTION: a tabulated function of one parameter (real or complex)."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.function import ComplexFunction, Function
from asterlite.post.restitution import values_of


def _pairs(ctx, kw, key: str, width: int) -> np.ndarray:
    flat = values_of(kw[key])
    if flat.size == 0 or flat.size % width:
        ctx.error(f"{key} holds {flat.size} numbers: a multiple of {width} expected", key, kw)
    return flat.reshape(-1, width)


def run(ctx, kw):
    if kw.get("VALE") is not None:
        table = _pairs(ctx, kw, "VALE", 2)
        x, y = table[:, 0], table[:, 1]
    elif kw.get("VALE_C") is not None:
        table = _pairs(ctx, kw, "VALE_C", 3)
        x, y = table[:, 0], table[:, 1] + 1j * table[:, 2]
    elif kw.get("ABSCISSE") is not None:
        x, y = values_of(kw["ABSCISSE"]), values_of(kw["ORDONNEE"])
    elif kw.get("VALE_PARA") is not None:
        x, y = values_of(kw["VALE_PARA"]), values_of(kw["VALE_FONC"])
    else:
        ctx.unsupported("DEFI_FONCTION without VALE, VALE_C, ABSCISSE or VALE_PARA", None, kw)
    if x.size != y.size:
        ctx.error(f"{x.size} abscissas but {y.size} ordinates", None, kw)
    check_abscissas(ctx, kw, x)
    cls = ComplexFunction if np.iscomplexobj(y) else Function
    return cls(
        x,
        y,
        NOM_PARA=kw.get("NOM_PARA", "TOUTPARA"),
        NOM_RESU=kw.get("NOM_RESU", "TOUTRESU"),
        INTERPOL=kw.get("INTERPOL", ("LIN", "LIN")),
        PROL_GAUCHE=kw.get("PROL_GAUCHE", "EXCLU"),
        PROL_DROITE=kw.get("PROL_DROITE", "EXCLU"),
        title=kw.get("TITRE") or "",
    )


def check_abscissas(ctx, kw, x: np.ndarray) -> None:
    """VERIF='CROISSANT' (default): strictly increasing abscissas."""
    if kw.get("VERIF", "CROISSANT") == "CROISSANT" and np.any(np.diff(x) <= 0):
        i = int(np.argmax(np.diff(x) <= 0))
        ctx.error(
            f"abscissas must increase strictly: {x[i]:g} then {x[i + 1]:g} (points {i + 1}, "
            f"{i + 2})",
            None,
            kw,
        )
