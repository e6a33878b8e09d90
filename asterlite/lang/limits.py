"""Resource limits of deck evaluation and the guards that enforce them.

Each guard runs *before* the operation it protects, so a deck can never make
the process allocate a huge list, string, integer or array, or loop forever:
it gets a DeckRuntimeError naming the limit instead. Guards raise without a
location; the evaluator attaches the location of the expression.
"""

from __future__ import annotations

import functools
import math
import re
import sys
import types
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
    max_nesting: int = 100  # levels of containers inside containers (tuples in tuples...)
    max_work: int = 10_000_000_000  # arithmetic of one numpy call (matrix products, solvers)
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


def check_format_template(template: str, limits: Limits, args=(), kwargs=None) -> None:
    """str.format: no index or attribute with '_', attributes only of plain
    numbers and strings (on an engine object, '{0.x}' would reach any public
    attribute), no huge widths."""
    import string

    try:
        fields = list(string.Formatter().parse(template))
    except ValueError as error:
        raise DeckRuntimeError(f"bad format string: {error}") from None
    automatic = 0
    for _, field_name, spec, _ in fields:
        if field_name is None:
            continue
        if re.search(r"(\.|\[)\s*_", field_name):
            raise DeckRuntimeError("format fields may not access names starting with '_'")
        root, attribute = re.match(r"([^.\[]*)(\.)?", field_name).groups()
        if root == "":
            root, automatic = automatic, automatic + 1
        if attribute and not _plain_format_argument(root, args, kwargs or {}):
            raise DeckRuntimeError(
                "format fields may read attributes of numbers and strings only "
                f"('{{{field_name}}}'): format the value itself"
            )
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


def _plain_format_argument(root, args, kwargs) -> bool:
    if isinstance(root, int) or str(root).isdigit():
        index = int(root)
        value = args[index] if index < len(args) else None
    else:
        value = kwargs.get(root)
    return isinstance(value, (int, float, complex, str))


# ----------------------------------------------------------------- nesting
# CPython hashes a tuple by hashing its items recursively in C, without any
# depth check: hashing a tuple nested a million deep overflows the C stack.
# Every place where a deck value may be hashed checks its depth first.


def check_hash_depth(value, limits: Limits) -> None:
    """Refuse a tuple (dict key, set item, index) nested beyond the limit."""
    if type(value) is not tuple:
        return
    _check_depth(value, limits, (tuple, frozenset))


def check_nesting(values, limits: Limits) -> None:
    """Refuse containers (lists, tuples, dicts, sets) nested beyond the limit:
    what a command receives, which may hash or walk it recursively."""
    _check_depth(values, limits, (list, tuple, dict, set, frozenset))


def _check_depth(root, limits: Limits, kinds) -> None:
    limit = limits.max_nesting
    seen = set()
    pending = [(root, 0)]
    while pending:
        value, depth = pending.pop()
        if depth > limit:
            raise exceeded("levels of nested containers", limit)
        if id(value) in seen:
            continue
        seen.add(id(value))
        items = value.values() if isinstance(value, dict) else value
        if isinstance(value, dict) and dict in kinds:
            pending.extend((key, depth + 1) for key in value if isinstance(key, kinds))
        pending.extend((item, depth + 1) for item in items if isinstance(item, kinds))


def hashable_items(values, limits: Limits) -> list:
    """The items of an iterable that will be hashed (set(), dict(), update...),
    read once into a list, each checked."""
    items = list(values)
    check_length(len(items), limits)
    for item in items:
        check_hash_depth(item, limits)
    return items


def check_lcm(arguments, limits: Limits) -> None:
    """math.lcm: the result has up to the sum of the arguments' digits."""
    bits = sum(abs(int(a)).bit_length() for a in arguments if _is_int(a))
    if bits > limits.max_int_bits:
        raise exceeded("integer size in digits", limits.max_int_digits)


# ------------------------------------------------------------------- text
# Objects of the engine a deck holds (commands, concepts' bound methods,
# builtins) must not show their memory address or internals when printed.

_PLAIN_TEXT = (int, float, complex, bool, str, type(None))


def deck_text_value(value, budget: list | None = None):
    """``value`` ready for str/repr/format: plain data as is, containers with
    their items converted, any other object replaced by a neutral stand-in
    unless it has a representation of its own (concepts, numpy values)."""
    budget = budget if budget is not None else [100_000]
    budget[0] -= 1
    if isinstance(value, _PLAIN_TEXT) or budget[0] < 0:
        return value
    kind = type(value)
    if kind in (list, tuple, set, frozenset):
        return kind(deck_text_value(item, budget) for item in value)
    if kind is dict:
        return {deck_text_value(k, budget): deck_text_value(v, budget) for k, v in value.items()}
    np = numpy_or_none()
    if np is not None and isinstance(value, (np.ndarray, np.generic)):
        return value if value.dtype != object else _Opaque("array of objects")
    if isinstance(value, _FUNCTION_TYPES):
        name = getattr(value, "__name__", "")
        return _Opaque(f"function {name}" if name and not name.startswith("_") else "function")
    if kind.__repr__ is object.__repr__:
        return _Opaque(kind.__name__.lstrip("_") or "object")
    return value


_FUNCTION_TYPES = (
    types.FunctionType,
    types.BuiltinFunctionType,
    types.MethodType,
    types.MethodWrapperType,
    functools.partial,
)


class _Opaque:
    """Prints as ``<what>``."""

    __slots__ = ("text",)

    def __init__(self, text: str):
        self.text = text

    def __repr__(self) -> str:
        return f"<{self.text}>"

    __str__ = __repr__

    def __format__(self, spec: str) -> str:
        return format(repr(self), spec)
