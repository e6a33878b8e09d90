"""Checking one value of a simple keyword against its catalogue types.

``accept(types, value)`` returns the value converted to the Python type a
command expects (int -> float for ``R``, integral float -> int for ``I``,
``('RI', re, im)``/``('MP', mod, phase)`` -> complex for ``C``) or raises
:class:`TypeMismatch` whose text says what was expected and what was got.
A real or complex value must be finite: a NaN or an infinity given to an
``R`` or ``C`` keyword is refused here, at its source, rather than switching
a computation off silently downstream (a NaN gap makes every comparison
false). numpy scalars and arrays are recognised by duck typing: numpy is
never imported here.
"""

from __future__ import annotations

import cmath
import math

from asterlite.concepts.base import Concept
from asterlite.lang.values import CO, Unknown

# code_aster type names that hold plain text (mesh entity names, file names)
TEXT_TYPES = frozenset({"TXM", "TX", "K8", "K16", "K24", "grma", "grno", "ma", "no", "Fichier"})
NAME_TYPES = frozenset({"grma", "grno", "ma", "no"})
BUILTIN_DESCRIPTIONS = {
    "R": "a real number (R)",
    "I": "an integer (I)",
    "C": "a complex number (C)",
    "L": "a logical (L)",
    "CO": 'an output name CO("...") (CO)',
}


class TypeMismatch(Exception):
    """A value does not match any of a keyword's types."""


def is_numpy(value) -> bool:
    return type(value).__module__ == "numpy" and hasattr(value, "tolist")


def plain(value):
    """numpy scalars and arrays as Python numbers and lists; other values unchanged."""
    return value.tolist() if is_numpy(value) else value


def is_old_complex(value) -> bool:
    """code_aster's ``('RI', re, im)`` / ``('MP', modulus, phase in degrees)`` notation."""
    return (
        isinstance(value, (list, tuple))
        and len(value) == 3
        and value[0] in ("RI", "MP")
        and all(_is_real(v) for v in value[1:])
    )


def _is_real(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _old_complex(value) -> complex:
    kind, a, b = value
    if kind == "RI":
        return complex(a, b)
    phase = math.radians(b)
    return complex(a * math.cos(phase), a * math.sin(phase))


_TOO_LARGE = "expected a finite {kind}, got an integer beyond the floating-point range"


def _as_real(value):
    if not _is_real(value):
        return None
    try:
        return float(value)
    except OverflowError:  # a Python integer beyond the float range
        raise TypeMismatch(_TOO_LARGE.format(kind="real number (R)")) from None


def _as_int(value):
    if isinstance(value, bool):
        return None
    if isinstance(value, int):
        return value
    if isinstance(value, float) and value.is_integer():
        return int(value)
    return None


def _as_complex(value):
    try:
        if is_old_complex(value):
            return _old_complex(value)
        if _is_real(value) or isinstance(value, complex):
            return complex(value)
    except OverflowError:  # a Python integer beyond the float range
        raise TypeMismatch(_TOO_LARGE.format(kind="complex number (C)")) from None
    return None


def _as_text(value):
    return value if isinstance(value, str) else None


def _as_logical(value):
    return value if isinstance(value, bool) else None


def _as_output(value):
    # code_aster also accepts an existing concept where a CO is expected
    return value if isinstance(value, (CO, Concept)) else None


CONVERTERS = {"R": _as_real, "I": _as_int, "C": _as_complex, "L": _as_logical, "CO": _as_output}


def _convert(type_name, value):
    """The converted value, or None when ``value`` is not of ``type_name``."""
    if not isinstance(type_name, str):
        raise TypeError(f"catalogue type must be a name, got {type_name!r}")
    if type_name in NAME_TYPES:
        # mesh entity names are fixed-width identifiers in code_aster: trailing
        # blanks ("N5 ") do not count
        text = _as_text(value)
        return text.rstrip() if text is not None else None
    if type_name in TEXT_TYPES:
        return _as_text(value)
    if type_name in CONVERTERS:
        return CONVERTERS[type_name](value)
    if isinstance(value, Concept) and value.satisfies(type_name):
        return value
    return None


def accept(types: tuple[str, ...], value):
    """``value`` converted to the first of ``types`` it matches; Unknown passes."""
    if value is Unknown:
        return value
    value = plain(value)
    for type_name in types:
        converted = _convert(type_name, value)
        if converted is not None:
            _require_finite(type_name, converted)
            return converted
    raise TypeMismatch(f"expected {describe_types(types)}, got {describe_value(value)}")


def _require_finite(type_name, converted) -> None:
    """NaN and infinities are not numbers a computation can use: refuse them."""
    if type_name == "R" and not math.isfinite(converted):
        raise TypeMismatch(f"expected a finite real number (R), got {converted!r}")
    if type_name == "C" and not cmath.isfinite(converted):
        raise TypeMismatch(f"expected a finite complex number (C), got {converted!r}")


def describe_types(types: tuple[str, ...]) -> str:
    """'a real number (R) or a concept of type fonction_sdaster or nappe_sdaster'."""
    parts, concepts = [], []
    for type_name in types:
        if type_name in TEXT_TYPES:
            parts.append(f"a text ({type_name})")
        elif type_name in BUILTIN_DESCRIPTIONS:
            parts.append(BUILTIN_DESCRIPTIONS[type_name])
        else:
            concepts.append(type_name)
    if concepts:
        parts.append("a concept of type " + " or ".join(concepts))
    return " or ".join(dict.fromkeys(parts))


def describe_value(value) -> str:
    """'text 'abc'', 'integer 3', 'mode_meca MODES' for messages."""
    if isinstance(value, Concept):
        return f"{value.aster_type} {value.name}" if value.name else f"a {value.aster_type}"
    if isinstance(value, bool):
        return f"logical {value}"
    if isinstance(value, str):
        return f"text {value!r}"
    if isinstance(value, int):
        return f"integer {value}"
    if isinstance(value, float):
        return f"real {value!r}"
    if isinstance(value, complex):
        return f"complex {value!r}"
    if isinstance(value, CO):
        return f'CO("{value.name}")'
    if isinstance(value, dict):
        return "a factor occurrence _F(...)"
    if isinstance(value, (list, tuple)):
        return f"a list {_short(value)}"
    if value is None:
        return "None"
    return f"{type(value).__name__} {_short(value)}"


def _short(value, limit: int = 40) -> str:
    text = repr(value)
    return text if len(text) <= limit else text[: limit - 3] + "..."
