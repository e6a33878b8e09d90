"""Resource limits of deck evaluation and the guards that enforce them.

Each guard runs *before* the operation it protects, so a deck can never make
the process allocate a huge list, string, integer or array, or loop forever:
it gets a DeckRuntimeError naming the limit instead. Guards raise without a
location; the evaluator attaches the location of the expression.
"""

from __future__ import annotations

import math
import re
import sys
from dataclasses import dataclass

from asterlite.errors import DeckRuntimeError


@dataclass(frozen=True)
class Limits:
    """Bounds on what a deck may compute (per Evaluator)."""

    max_loop_iterations: int = 10_000_000  # loop, comprehension and function-call steps, in total
    max_sequence_length: int = 10_000_000  # elements of a list, tuple, range or numpy array
    max_int_digits: int = 10_000  # decimal digits of an integer result
    max_string_length: int = 10_000_000  # characters of a string
    max_call_depth: int = 64  # nested calls of deck functions
    max_seconds: float | None = None  # wall-clock bound on deck-level steps (None: no bound)

    @property
    def max_int_bits(self) -> int:
        return int(self.max_int_digits * math.log2(10)) + 1


def exceeded(what: str, limit: int) -> DeckRuntimeError:
    return DeckRuntimeError(f"limit exceeded: {what} (limit {limit:,})")


def check_length(length: int, limits: Limits, what: str = "sequence length") -> None:
    if length > limits.max_sequence_length:
        raise exceeded(what, limits.max_sequence_length)


def check_string_length(length: int, limits: Limits) -> None:
    if length > limits.max_string_length:
        raise exceeded("string length", limits.max_string_length)


def _is_int(value) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def _sized_sequence(value) -> bool:
    return isinstance(value, (str, list, tuple))


def check_repeat(sequence, count, limits: Limits) -> None:
    """``sequence * count`` for a str, list or tuple."""
    if count <= 0:
        return
    size = len(sequence) * count
    if isinstance(sequence, str):
        check_string_length(size, limits)
    else:
        check_length(size, limits)


def check_concat(left, right, limits: Limits) -> None:
    size = len(left) + len(right)
    if isinstance(left, str):
        check_string_length(size, limits)
    else:
        check_length(size, limits)


def check_int_product(left: int, right: int, limits: Limits) -> None:
    if left.bit_length() + right.bit_length() > limits.max_int_bits:
        raise exceeded("integer size in digits", limits.max_int_digits)


def check_int_power(base: int, exponent: int, limits: Limits) -> None:
    if exponent <= 1 or abs(base) <= 1:
        return
    if exponent * (abs(base).bit_length() - 1) > limits.max_int_bits:
        raise exceeded("integer size in digits", limits.max_int_digits)


# %-format and str.format fields whose width or precision would build a huge string
_PERCENT_FIELD = re.compile(r"%(?:\([^)]*\))?[-#0 +]*(\*|\d+)?(?:\.(\*|\d+))?")
_FORMAT_NUMBERS = re.compile(r"\d+")


def check_percent_format(template: str, limits: Limits) -> None:
    for match in _PERCENT_FIELD.finditer(template):
        for group in match.groups():
            if group == "*":
                raise DeckRuntimeError("'*' widths are not supported in % formatting")
            if group and int(group) > limits.max_string_length:
                raise exceeded("string length", limits.max_string_length)


def check_format_template(template: str, limits: Limits) -> None:
    """str.format: no attribute or index access with '_', no huge widths."""
    import string

    try:
        fields = list(string.Formatter().parse(template))
    except ValueError as error:
        raise DeckRuntimeError(f"bad format string: {error}") from None
    for _, field_name, spec, _ in fields:
        if field_name and re.search(r"(\.|\[)\s*_", field_name):
            raise DeckRuntimeError("format fields may not access names starting with '_'")
        for part in (field_name or "", spec or ""):
            if "{" in part:
                raise DeckRuntimeError("nested format fields are not supported")
        for number in _FORMAT_NUMBERS.findall(spec or ""):
            if int(number) > limits.max_string_length:
                raise exceeded("string length", limits.max_string_length)


def numpy_or_none():
    """numpy, if a deck (or anything else) already imported it; never imports it."""
    return sys.modules.get("numpy")


def check_binary(op: str, left, right, limits: Limits) -> None:
    """Refuse a binary operation whose result would exceed a limit."""
    if op == "*":
        if _sized_sequence(left) and _is_int(right):
            check_repeat(left, right, limits)
        elif _sized_sequence(right) and _is_int(left):
            check_repeat(right, left, limits)
        elif _is_int(left) and _is_int(right):
            check_int_product(left, right, limits)
    elif op == "+":
        if _sized_sequence(left) and type(left) is type(right):
            check_concat(left, right, limits)
    elif op == "**":
        if _is_int(left) and _is_int(right):
            check_int_power(left, right, limits)
    elif op == "%" and isinstance(left, str):
        check_percent_format(left, limits)
        check_nested_size((right,), limits)
    np = numpy_or_none()
    if np is not None and (isinstance(left, np.ndarray) or isinstance(right, np.ndarray)):
        check_broadcast((left, right), limits)


def check_broadcast(operands, limits: Limits) -> None:
    """Elementwise numpy operations: the broadcast result must stay within limits."""
    np = numpy_or_none()
    shapes = [operand.shape for operand in operands if isinstance(operand, np.ndarray)]
    if len(shapes) < 2:
        return
    try:
        shape = np.broadcast_shapes(*shapes)
    except ValueError:
        return  # numpy itself reports the mismatch
    check_length(math.prod(shape), limits, "numpy array size")


def check_nested_size(values, limits: Limits) -> None:
    """Refuse to render (str, repr, print, format) nested containers whose total
    element count exceeds the sequence limit: ``[[0] * 10**6] * 10**6`` is small
    in memory but its text is not."""
    budget = limits.max_sequence_length
    pending = list(values)
    while pending:
        value = pending.pop()
        if isinstance(value, (list, tuple, set, frozenset, dict)):
            budget -= len(value)
            if budget < 0:
                raise exceeded("elements to convert to text", limits.max_sequence_length)
            items = value.values() if isinstance(value, dict) else value
            pending.extend(item for item in items if isinstance(item, (list, tuple, dict, set)))
