"""Numbers read from a study's text files, NaN and infinities refused by name.

Python's ``float`` reads ``nan``, ``inf`` and ``infinity`` (any case) and
turns ``1.E+999`` into an infinity; other programs write non-finite values
their own way: Windows' C runtime ``1.#QNAN``, ``-1.#IND``, ``1.#INF``,
``1.#SNAN`` (also with trailing digits, ``1.#QNAN0``), ``nan(ind)`` and
``-nan(snan)``, AIX's ``NaNQ``, a spreadsheet's ``NaN%`` or ``#DIV/0!``,
Fortran's asterisks for a value that did not fit its field. Those are not
numbers for ``float``: a reader taking "lines of numbers" would end its
numeric block there and drop the rest of the file without a word.

:func:`finite_float` reads a token as a finite number, or raises
NonFiniteNumber saying what the token is (a spelling quoted is one of the
patterns below, never arbitrary text), or ValueError for any other text.
"""

from __future__ import annotations

import math
import re

_WINDOWS = r"\d*\.?\d*\#(?:q?nan|snan|ind|inf)\d*"  # 1.#QNAN, -1.#IND00, 1.#INF, 1.#SNAN
_C_STYLE = r"(?:nan[qs]?|inf(?:inity)?)(?:\((?:ind|snan|qnan|0x[0-9a-f]*|\d*)\))?%?"
_SPREADSHEET = r"\#(?:n/a|div/0!|num!|value!|null!|ref!)"
_OVERFLOW = r"\*{2,}"  # Fortran: the value did not fit its field
_NON_FINITE = re.compile(
    rf"[+-]?(?:{_WINDOWS}|{_C_STYLE}|{_SPREADSHEET}|{_OVERFLOW})|[+-]?\u221e",
    re.IGNORECASE,
)
# Fortran's double precision exponent: 1.0D+03
_FORTRAN_D = re.compile(r"([0-9.])[dD]([+-]?[0-9])")


class NonFiniteNumber(ValueError):
    """A NaN or an infinity, however spelt; the message says which token."""


def is_non_finite_spelling(token: str) -> bool:
    """``token`` is a NaN or an infinity as some program writes one."""
    return _NON_FINITE.fullmatch(token.strip()) is not None


def finite_float(token: str, fortran_exponent: bool = False) -> float:
    """The finite number ``token`` spells, else NonFiniteNumber (a NaN or an
    infinity, however spelt, or a value beyond the float range) or ValueError
    (any other text; its message does not quote it). ``fortran_exponent``:
    ``1.0D+03`` reads as ``1.0E+03``."""
    try:
        value = float(token)
    except ValueError:
        value = _unusual_number(token, fortran_exponent)
    if not math.isfinite(value):
        what = (
            _what(token)
            if is_non_finite_spelling(token)
            else "beyond the float range (read as inf)"
        )
        raise NonFiniteNumber(f"{token.strip()!r} is {what}, not a finite number")
    return value


def _unusual_number(token: str, fortran_exponent: bool) -> float:
    """A Fortran exponent read, a non-finite spelling refused, else ValueError."""
    if fortran_exponent and _FORTRAN_D.search(token):
        try:
            return float(_FORTRAN_D.sub(r"\1E\2", token))
        except ValueError:
            pass
    if is_non_finite_spelling(token):
        raise NonFiniteNumber(f"{token.strip()!r} is {_what(token)}, not a finite number")
    raise ValueError("not a number")


def _what(token: str) -> str:
    text = token.strip().lower()
    if "*" in text:
        return "a field overflow (the value did not fit its Fortran format)"
    if text.lstrip("+-").startswith("#"):
        return "a spreadsheet error value"
    if "nan" in text or "ind" in text:
        return "a NaN"
    return "an infinity"


def is_number_token(token: str) -> bool:
    """``token`` reads as a number, finite or not (however a NaN is spelt)."""
    try:
        finite_float(token, fortran_exponent=True)
    except NonFiniteNumber:
        return True
    except ValueError:
        return False
    return True
