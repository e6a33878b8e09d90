"""Resource limits of deck evaluation and the guards that enforce them.

Each guard runs *before* the operation it protects, so a deck can never make
the process allocate a huge list, string, integer or array, or loop forever:
it gets a DeckRuntimeError naming the limit instead. Guards raise without a
location; the evaluator attaches the location of the expression.
"""

from __future__ import annotations

import _string
import functools
import itertools
import math
import re
import string
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
    max_tree_depth: int = 200  # levels of a syntax tree: deck code, a FORMULE's expression
    max_work: int = 10_000_000_000  # arithmetic of one numpy call (matrix products, solvers)
    max_seconds: float | None = None  # wall-clock bound on deck-level steps (None: no bound)

    @property
    def max_int_bits(self) -> int:
        return int(self.max_int_digits * math.log2(10)) + 1


class DeckMemoryError(DeckRuntimeError):
    """An allocation of deck code failed (MemoryError under the run's cap)."""

    kind = "memory limit exceeded"
    fatal = True


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


# %-format and str.format fields: their widths and precisions, which pad the
# text, count towards the result's length before anything is formatted
_PERCENT_FIELD = re.compile(r"%(?:\(([^)]*)\))?[-#0 +]*(\*|\d+)?(?:\.(\*|\d*))?[hlL]?([a-zA-Z%])?")
_FORMAT_NUMBERS = re.compile(r"\d+")
_NUMBER_TEXT = 400  # characters of a float or int formatted without a width ('%f' of 1e308: 316)
_FIELD_ATTRIBUTES = frozenset({"real", "imag"})  # what a format field may read of a number


def check_percent_format(template: str, limits: Limits, arguments=()) -> None:
    """``template % arguments``: refused when the result could pass the string
    limit, counting every field's width and precision and its value's text."""
    values = arguments if isinstance(arguments, tuple) else (arguments,)
    mapping = arguments if isinstance(arguments, dict) else None
    total, position = len(template), 0
    for match in _PERCENT_FIELD.finditer(template):
        key, width, precision, conversion = match.groups()
        if "*" in (width, precision):
            raise DeckRuntimeError("'*' widths are not supported in % formatting")
        total += int(width or 0) + int(precision or 0)
        if conversion == "%" or conversion is None:
            continue
        as_repr = conversion in ("r", "a")
        if key is not None and mapping is not None:
            total += text_length_bound(mapping.get(key, ""), as_repr)
        elif position < len(values):
            total += text_length_bound(values[position], as_repr)
            position += 1
        if total > limits.max_string_length:
            raise exceeded("string length", limits.max_string_length)
    if total > limits.max_string_length:
        raise exceeded("string length", limits.max_string_length)


def check_format_template(template: str, limits: Limits, args=(), kwargs=None) -> None:
    """str.format: every accessor of every field checked (no name with '_',
    attributes only ``real``/``imag`` of numbers, indexes only into lists,
    tuples, dicts and strings: on an engine object, '{0[0].x}' would reach
    any public attribute), and the result's length bounded before formatting
    (each field's width and precision plus its value's text)."""

    try:
        fields = list(string.Formatter().parse(template))
    except ValueError as error:
        raise DeckRuntimeError(f"bad format string: {error}") from None
    kwargs = kwargs or {}
    automatic, total = 0, 0
    for literal, field_name, spec, conversion in fields:
        total += len(literal)
        if field_name is None:
            continue
        for part in (field_name, spec or ""):
            if "{" in part:
                raise DeckRuntimeError("nested format fields are not supported")
        if re.search(r"(\.|\[)\s*_", field_name):
            raise DeckRuntimeError("format fields may not access names starting with '_'")
        value = _format_field_value(field_name, automatic, args, kwargs)
        automatic += not field_name or field_name[0] in ".["
        total += sum(int(number) for number in _FORMAT_NUMBERS.findall(spec or ""))
        total += text_length_bound(value, as_repr=conversion in ("r", "a"))
        if total > limits.max_string_length:
            raise exceeded("string length", limits.max_string_length)


def _format_field_value(field_name: str, automatic: int, args, kwargs):
    """The value a format field shows, each accessor of its chain checked
    the way a deck may use it (None when the chain fails: format reports it)."""

    first, accessors = _string.formatter_field_name_split(field_name)
    root = automatic if first == "" else first
    try:
        value = args[root] if isinstance(root, int) else kwargs[root]
    except (IndexError, KeyError):
        return None
    for is_attribute, key in accessors:
        if is_attribute:
            plain = isinstance(value, (int, float, complex)) and not isinstance(value, bool)
            if not (plain and key in _FIELD_ATTRIBUTES):
                raise DeckRuntimeError(
                    "format fields may read attributes of numbers only (.real, .imag) "
                    f"('{{{field_name}}}'): format the value itself"
                )
            value = getattr(value, key)
            continue
        if not isinstance(value, (list, tuple, dict, str)):
            raise DeckRuntimeError(
                "format fields may index lists, tuples, dicts and strings only "
                f"('{{{field_name}}}'): format the value itself"
            )
        try:
            value = value[key]
        except (IndexError, KeyError, TypeError):
            return None
    return value


def text_length_bound(value, as_repr: bool = False, budget: int = 10_000_000) -> int:
    """An upper bound on the characters of ``str(value)`` (``repr`` when
    ``as_repr``) formatted with any type code, from sizes alone: a float
    alone may take ``%f``'s 316 digits, in a container its repr's 24; numpy
    prints at most about a thousand elements."""
    if isinstance(value, str) and not as_repr:
        return len(value)
    if isinstance(value, (float, complex)):
        return 2 * _NUMBER_TEXT
    np = numpy_or_none()
    if np is not None and isinstance(value, np.generic):
        return 2 * _NUMBER_TEXT + value.dtype.itemsize
    pending, total, seen = [value], 0, 0
    while pending:
        item = pending.pop()
        seen += 1
        if seen > budget:
            return budget * 10  # beyond any limit: refused
        if isinstance(item, str):  # repr: quotes, escapes of 2 to 10 characters
            total += (2 if item.isprintable() else 10) * len(item) + 2
        elif isinstance(item, bool) or item is None:
            total += 5
        elif isinstance(item, int):
            total += item.bit_length() // 3 + 2
        elif isinstance(item, (float, complex)):
            total += 54  # two reprs of at most 24 characters, a sign, 'j', brackets
        elif isinstance(item, (list, tuple, set, frozenset)):
            total += 2 * len(item) + 2
            pending.extend(item)
        elif isinstance(item, dict):
            total += 4 * len(item) + 2
            pending.extend(item.keys())
            pending.extend(item.values())
        elif np is not None and isinstance(item, (np.ndarray, np.generic)):
            shown = min(int(item.size), 1000)
            total += shown * (item.dtype.itemsize + 40) + 20 * item.ndim + 100
        else:
            total += 200  # an engine object's stand-in, a concept's short representation
    return total


def numpy_or_none():
    """numpy, if a deck (or anything else) already imported it; never imports it."""
    return sys.modules.get("numpy")


# Python ints numpy stores without falling back to an array of objects
_NUMPY_INT_RANGE = (-(2**63), 2**64)


def object_array_error() -> DeckRuntimeError:
    # numpy loops over Python objects in C, where a CPU time limit cannot stop them
    return DeckRuntimeError(
        "numpy arrays of Python objects (dtype=object, integers beyond 64 bits, "
        "None or mixed values) are not available in decks: use numbers"
    )


def check_no_object_arrays(values, dtype=None) -> None:
    """Refuse numpy arguments numpy would turn into an array of Python
    objects: integers beyond 64 bits, lists holding them, None or any other
    object (converted as the call would, with its ``dtype``)."""
    np = numpy_or_none()
    for value in values:
        if type(value) is int and not _NUMPY_INT_RANGE[0] <= value < _NUMPY_INT_RANGE[1]:
            raise object_array_error()
        if not isinstance(value, (list, tuple)) or all(
            isinstance(item, (np.ndarray, np.generic, float)) for item in value
        ):
            continue
        try:
            converted = np.asarray(value, dtype=dtype)
        except (ValueError, TypeError, OverflowError):
            continue  # ragged or invalid: the call itself reports it
        if converted.dtype.hasobject:
            raise object_array_error()


def check_array_result(result) -> None:
    """An array of objects made anyway (``np.full(n, None)``) never reaches the deck."""
    np = numpy_or_none()
    if np is not None and isinstance(result, np.ndarray) and result.dtype.hasobject:
        raise object_array_error()


def check_binary(op: str, left, right, limits: Limits) -> bool:
    """Refuse a binary operation whose result would exceed a limit; True when
    numpy arrays take part (the caller checks the result's type)."""
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
        check_nested_size((right,), limits)
        check_percent_format(left, limits, right)
    np = numpy_or_none()
    if np is not None and (
        isinstance(left, (np.ndarray, np.generic)) or isinstance(right, (np.ndarray, np.generic))
    ):
        check_broadcast((left, right), limits)
        check_no_object_arrays((left, right))
        return True
    return False


def bounded_items(items, room: int, limits: Limits) -> list:
    """The items of an iterable about to extend a list (``+=``, ``extend``)
    that holds ``room`` fewer than the limit: read no further than that."""
    if isinstance(items, (list, tuple, str, range, dict, set, frozenset)):
        if len(items) > room:
            raise exceeded("sequence length", limits.max_sequence_length)
        return list(items)
    taken = list(itertools.islice(items, max(room, 0) + 1))
    if len(taken) > room:
        raise exceeded("sequence length", limits.max_sequence_length)
    return taken


def check_literal(value, limits: Limits) -> None:
    """A number written in the deck: hexadecimal, octal and binary literals
    are not bounded by Python's 4300-digit rule, decimal ones are."""
    if _is_int(value) and value.bit_length() > limits.max_int_bits:
        raise exceeded("integer size in digits", limits.max_int_digits)


def check_int_text(text, base: int, limits: Limits) -> None:
    """``int(text, base)``: Python bounds decimal text only (4300 digits); a
    power-of-two base turns two million hexadecimal digits into one integer."""
    if not isinstance(text, (str, bytes, bytearray)):
        return
    digits_per_character = math.log10(min(max(int(base), 2), 36) if base else 16)
    if (len(text) - 2) * digits_per_character > limits.max_int_digits:  # 2: a prefix, a sign
        raise exceeded("integer size in digits", limits.max_int_digits)


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
