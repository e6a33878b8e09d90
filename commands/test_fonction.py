"""TEST_FONCTION: values of functions and formulas (VALEUR) and their
attributes (ATTRIBUT). Verdicts: ``asterlite.post.checks``."""

from __future__ import annotations

from asterlite.concepts.function import Formula
from asterlite.errors import CommandError
from asterlite.post.checks import record_check
from asterlite.post.restitution import as_tuple


def run(ctx, kw):
    for i, occ in enumerate(kw.factor("VALEUR"), start=1):
        check_value(ctx, occ, i)
    for i, occ in enumerate(kw.factor("ATTRIBUT"), start=1):
        check_attribute(ctx, occ, i)
    return None


def formula_point(ctx, occ, func, params: tuple) -> tuple:
    """VALE_PARA put in the formula's parameter order, by the names of NOM_PARA.

    As in code_aster, NOM_PARA only matters for a FORMULE (a tabulated
    function or nappe takes its parameters in their own order), and a count
    that differs from the formula's parameters is an error of the deck.
    """
    names = as_tuple(occ.get("NOM_PARA"))
    if not isinstance(func, Formula) or not names:
        return params
    expected = func.NOM_PARA
    if len(names) != len(expected) or len(params) != len(names):
        ctx.error(
            f"NOM_PARA names {len(names)} parameters and VALE_PARA gives {len(params)}; "
            f"formula {func.name or '?'} has {len(expected)} ({', '.join(expected)})",
            "NOM_PARA",
            occ,
        )
    by_name = dict(zip(names, params, strict=True))
    missing = [n for n in expected if n not in by_name]
    if missing:
        ctx.error(f"formula parameters not in NOM_PARA: {', '.join(missing)}", "NOM_PARA", occ)
    return tuple(by_name[n] for n in expected)


def check_value(ctx, occ, i):
    func = occ["FONCTION"]
    params = formula_point(ctx, occ, func, as_tuple(occ.get("VALE_PARA")))
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
