"""Tabulated functions y(x) packed in flat float64 arrays, evaluated in compiled code.

A function enters a law's parameter array as one packed block::

    [n, prol_left, prol_right, x_0 .. x_{n-1}, y_0 .. y_{n-1}]

with linear interpolation (code_aster's INTERPOL=('LIN', 'LIN')) and
code_aster's prolongations outside [x_0, x_{n-1}]: CONSTANT repeats the end
value, LINEAIRE extends the end segment, EXCLU has no value there: the
compiled evaluators return NaN, which the time loop must treat as an error
("function evaluated outside its domain"), as code_aster stops there.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from asterlite.dynamics.jit import njit

CONSTANT, LINEAIRE, EXCLU = 0, 1, 2
PROLONGATIONS = {"CONSTANT": CONSTANT, "LINEAIRE": LINEAIRE, "EXCLU": EXCLU}
HEADER = 3  # n, prol_left, prol_right


class LawError(ValueError):
    """A relation's data that cannot define its law."""


# ----------------------------------------------------------------------------
# Packing (plain Python, once)
# ----------------------------------------------------------------------------


def pack(x, y, left: str = "EXCLU", right: str = "EXCLU", label: str = "function") -> np.ndarray:
    """Packed block of a tabulated function; abscissas must increase strictly."""
    xs = np.asarray(x, dtype=float).ravel()
    ys = np.asarray(y, dtype=float).ravel()
    if xs.size == 0 or xs.size != ys.size:
        raise LawError(f"{label}: {xs.size} abscissas for {ys.size} ordinates")
    if not (np.all(np.isfinite(xs)) and np.all(np.isfinite(ys))):
        raise LawError(f"{label}: abscissas and ordinates must be finite numbers")
    if xs.size > 1 and np.any(np.diff(xs) <= 0.0):
        raise LawError(f"{label}: abscissas must increase strictly")
    try:
        codes = (PROLONGATIONS[left], PROLONGATIONS[right])
    except KeyError as exc:
        raise LawError(f"{label}: unknown prolongation {exc.args[0]!r}") from None
    return np.concatenate([[float(xs.size), float(codes[0]), float(codes[1])], xs, ys])


@dataclass(frozen=True)
class Curve:
    """A tabulated function built by the laws themselves (same attributes as a
    DEFI_FONCTION concept, so ``function_table`` takes either)."""

    abscissas: np.ndarray
    ordinates: np.ndarray
    PROL_GAUCHE: str = "EXCLU"
    PROL_DROITE: str = "EXCLU"
    INTERPOL: tuple[str, str] = ("LIN", "LIN")


def packed_size(n_points: int) -> int:
    return HEADER + 2 * n_points


def function_table(func, label: str, sample=None, para: str | None = None) -> np.ndarray:
    """Pack a deck function for the compiled laws.

    ``func`` is a ``Function`` concept (abscissas, ordinates, INTERPOL,
    PROL_GAUCHE, PROL_DROITE), a pair ``(x, y)`` (EXCLU both sides), or a
    one-parameter formula, which is tabulated on ``sample`` (an array of
    abscissas the caller chooses; CONSTANT outside). ``para``: when given,
    the parameter name a formula must have.
    """
    if hasattr(func, "abscissas") and hasattr(func, "ordinates"):
        ordinates = np.asarray(func.ordinates)
        if np.iscomplexobj(ordinates):
            raise LawError(f"{label}: a real function is expected, not a complex one")
        interpol = tuple(getattr(func, "INTERPOL", ("LIN", "LIN")))
        if any(kind != "LIN" for kind in interpol):
            raise LawError(
                f"{label}: only INTERPOL='LIN' functions can be used here (got {interpol})"
            )
        return pack(
            func.abscissas,
            ordinates,
            getattr(func, "PROL_GAUCHE", "EXCLU"),
            getattr(func, "PROL_DROITE", "EXCLU"),
            label,
        )
    if hasattr(func, "VALE") and hasattr(func, "evaluate"):  # a formula
        names = tuple(getattr(func, "NOM_PARA", ()))
        if len(names) != 1:
            raise LawError(f"{label}: a formula of one parameter is expected, not {names}")
        if para is not None and names[0] != para:
            raise LawError(f"{label}: the formula's parameter must be {para}, not {names[0]}")
        if sample is None:
            raise LawError(
                f"{label}: a formula needs a sampling grid here; give a DEFI_FONCTION instead"
            )
        xs = np.asarray(sample, dtype=float)
        return pack(xs, func.evaluate(xs), "CONSTANT", "CONSTANT", label)
    if isinstance(func, (tuple, list)) and len(func) == 2:
        return pack(func[0], func[1], label=label)
    raise LawError(f"{label}: a function (DEFI_FONCTION) is expected, got {type(func).__name__}")


def unpack(block: np.ndarray) -> tuple[np.ndarray, np.ndarray, int, int]:
    """(x, y, prol_left, prol_right) of a packed block (for messages and tests)."""
    n = int(block[0])
    xs = block[HEADER : HEADER + n]
    ys = block[HEADER + n : HEADER + 2 * n]
    return xs, ys, int(block[1]), int(block[2])


# ----------------------------------------------------------------------------
# Compiled evaluation
# ----------------------------------------------------------------------------


@njit(cache=True)
def table_size(table, start):
    """Number of floats of the packed block starting at ``start``."""
    return HEADER + 2 * int(table[start])


@njit(cache=True)
def segment_of(table, start, n, x):
    """Index i of the segment [x_i, x_{i+1}] holding x (bisection), clipped to the end segments."""
    xs = start + HEADER
    lo, hi = 0, n - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if table[xs + mid] <= x:
            lo = mid
        else:
            hi = mid
    return lo


@njit(cache=True)
def value_and_slope(table, start, x):
    """(y(x), dy/dx) of the packed function at ``start``; NaN outside an EXCLU side."""
    n = int(table[start])
    xs = start + HEADER
    ys = xs + n
    if n == 1:
        if x != table[xs] and (
            (x < table[xs] and int(table[start + 1]) == EXCLU)
            or (x > table[xs] and int(table[start + 2]) == EXCLU)
        ):
            return math.nan, math.nan
        return table[ys], 0.0
    if x < table[xs]:
        side = int(table[start + 1])
        if side == EXCLU:
            return math.nan, math.nan
        if side == CONSTANT:
            return table[ys], 0.0
    elif x > table[xs + n - 1]:
        side = int(table[start + 2])
        if side == EXCLU:
            return math.nan, math.nan
        if side == CONSTANT:
            return table[ys + n - 1], 0.0
    i = segment_of(table, start, n, x)
    x0, x1 = table[xs + i], table[xs + i + 1]
    y0, y1 = table[ys + i], table[ys + i + 1]
    slope = (y1 - y0) / (x1 - x0)
    return y0 + slope * (x - x0), slope


@njit(cache=True)
def value(table, start, x):
    """y(x) of the packed function at ``start`` (NaN outside an EXCLU side)."""
    return value_and_slope(table, start, x)[0]
