"""TEST_FONCTION: values of functions and formulas (VALEUR) and their
attributes (ATTRIBUT). Verdicts: ``asterlite.post.checks``."""

from __future__ import annotations

from asterlite.errors import CommandError
from asterlite.post.checks import record_check
from asterlite.post.restitution import as_tuple


def run(ctx, kw):
    for i, occ in enumerate(kw.factor("VALEUR"), start=1):
        check_value(ctx, occ, i)
    for i, occ in enumerate(kw.factor("ATTRIBUT"), start=1):
        check_attribute(ctx, occ, i)
    for key in ("TABL_INTSP",):
        if kw.get(key):
            ctx.unsupported(f"TEST_FONCTION/{key}", key, kw)
    return None


def check_value(ctx, occ, i):
    func = occ["FONCTION"]
    params = as_tuple(occ.get("VALE_PARA"))
    try:
        value = func(*params)
    except CommandError as exc:
        ctx.error(exc.message, "VALE_PARA", occ)
    point = ", ".join(f"{p:g}" if isinstance(p, float) else str(p) for p in params)
    record_check(ctx, f"VALEUR[{i}] {func.name or '?'}({point})", value, occ)


def check_attribute(ctx, occ, i):
    func = occ["FONCTION"]
    attribute = occ["ATTR"]
    properties = func.Parametres()
    value = properties.get(attribute)
    if value is None:
        ctx.unsupported(f"ATTR={attribute!r}", "ATTR", occ)
    if isinstance(value, list):
        value = " ".join(value)
    expected = {
        "VALE_CALC_K": occ.get("ATTR_REFE"),
        "REFERENCE": occ.get("REFERENCE", "NON_REGRESSION"),
    }
    record_check(ctx, f"ATTRIBUT[{i}] {func.name or '?'} {attribute}", value, expected)
