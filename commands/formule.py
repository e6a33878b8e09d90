"""FORMULE: an expression of NOM_PARA names and of the extra keyword values
(constants, functions) the deck passes along; see asterlite.concepts.function.

The runtime hands the extra keyword arguments as ``kw["_extra"]``.
"""

from __future__ import annotations

import cmath
import numbers

from asterlite.concepts.function import Formula
from asterlite.errors import CommandError
from asterlite.post.restitution import as_tuple


def run(ctx, kw):
    complex_result = kw.get("VALE_C") is not None
    text = kw["VALE_C"] if complex_result else kw.get("VALE")
    if text is None:
        ctx.error("VALE (or VALE_C) is required", "VALE", kw)
    extra = dict(kw.get("_extra") or {})
    check_extra_numbers(ctx, kw, extra)
    try:
        return Formula(
            VALE=text,
            NOM_PARA=as_tuple(kw["NOM_PARA"]),
            extra=extra,
            complex_result=complex_result,
        )
    except CommandError as exc:
        ctx.error(exc.message, "VALE_C" if complex_result else "VALE", kw)


def check_extra_numbers(ctx, kw, extra: dict) -> None:
    """The numbers handed to the formula (``FORMULE(..., A=2.0)``) escape the
    catalogue's checks: refuse a NaN or an infinity among them here."""
    for name, value in extra.items():
        if isinstance(value, numbers.Integral) or not isinstance(value, numbers.Number):
            continue  # integers are finite; functions are checked where they are built
        if not cmath.isfinite(complex(value)):
            ctx.error(f"{name}={value!r}: a finite number is expected", name, kw)
