"""The checks of one value against its keyword's entry, and of a level's rules.

The pieces :mod:`asterlite.catalog.language.validate` applies to each value
given (its type, ``into``, ``val_min``/``val_max``, the validators
``NoRepeat``, ``LongStr``, ``OrdList``... of code_aster's
``SyntaxObjects.py``) and to each level (the rules ``AU_MOINS_UN``,
``EXCLUS``, ``ENSEMBLE``... of ``SyntaxChecker.py``): each returns the
problem as a message, or None.
"""

from __future__ import annotations

import cmath
import difflib
import math

from asterlite.lang.values import CO, Unknown


def _plain(value):
    """numpy scalars and arrays as Python values; other values unchanged."""
    if type(value).__module__ == "numpy" and hasattr(value, "tolist"):
        return value.tolist()
    return value


def is_undefined(value) -> bool:
    """code_aster's "keyword not given": None, an empty list, ``[None]``."""
    value = _plain(value)
    if value is None:
        return True
    if isinstance(value, (list, tuple)):
        return len(value) == 0 or (len(value) == 1 and value[0] is None)
    return False


def decode(value):
    """A value of the data as Python (tagged complex, non-finite floats, dicts)."""
    if isinstance(value, dict):
        if "complex" in value:
            real, imag = (decode(v) for v in value["complex"])
            return complex(real, imag)
        if "float" in value:
            return float(value["float"])
        if "dict" in value:
            return {decode(k): decode(v) for k, v in value["dict"]}
        if "type" in value:
            return value
    if isinstance(value, list):
        return [decode(v) for v in value]
    return value


def _is_int(item) -> bool:
    if isinstance(item, int):  # bool too, as code_aster (issubclass(bool, int))
        return True
    return isinstance(item, float) and math.isfinite(item) and int(item) == item


def _is_real(item) -> bool:
    return isinstance(item, (int, float))


def _unit_number(item):
    if isinstance(item, int) and not isinstance(item, bool):
        return item
    if isinstance(item, bool):
        return int(item)
    if (
        isinstance(item, dict)
        and len(item) == 1
        and isinstance(next(iter(item)), int)
        and isinstance(next(iter(item.values())), str)
    ):
        return next(iter(item))
    return None


def _in_choices(item, into) -> bool:
    choices = [decode(c) for c in into]
    try:
        return item in choices
    except TypeError:
        return False


def _into_message(item, into) -> str:
    choices = [decode(c) for c in into]
    shown = ", ".join(map(repr, choices[:30])) + (", ..." if len(choices) > 30 else "")
    message = f"{item!r} is not one of: {shown}"
    texts = [c for c in choices if isinstance(c, str)]
    if isinstance(item, str):
        close = difflib.get_close_matches(item, texts, n=1, cutoff=0.6)
        if not close:
            close = [c for c in texts if c.upper() == item.upper()]
        if close:
            message += f", did you mean {close[0]!r}?"
    return message


def _bounds_problem(entry: dict, item) -> str | None:
    low, high = entry.get("val_min"), entry.get("val_max")
    if low is None and high is None:
        return None
    low, high = decode(low), decode(high)
    if isinstance(item, bool) or not isinstance(item, (int, float, complex)):
        return None
    if isinstance(item, complex) or isinstance(low, complex) or isinstance(high, complex):
        return _complex_bounds(entry, item, low, high)
    if high is not None:
        included = entry.get("val_max_included", True)
        if item > high or (item == high and not included):
            sign = "<=" if included else "<"
            return f"expected a value {sign} {high!r}, got {item!r}"
    if low is not None:
        included = entry.get("val_min_included", True)
        if item < low or (item == low and not included):
            sign = ">=" if included else ">"
            return f"expected a value {sign} {low!r}, got {item!r}"
    return None


def _complex_bounds(entry, item, low, high) -> str | None:
    item = complex(item)
    if high is not None:
        high = complex(high)
        included = entry.get("val_max_included", True)
        for part, bound in ((item.real, high.real), (item.imag, high.imag)):
            if part > bound or (part == bound and not included):
                return f"real and imaginary parts must be at most those of {high!r}, got {item!r}"
    if low is not None:
        low = complex(low)
        included = entry.get("val_min_included", True)
        for part, bound in ((item.real, low.real), (item.imag, low.imag)):
            if part < bound or (part == bound and not included):
                return f"real and imaginary parts must be at least those of {low!r}, got {item!r}"
    return None


def _finite(item) -> bool:
    if isinstance(item, complex):
        return cmath.isfinite(item)
    return not isinstance(item, float) or math.isfinite(item)


def _validator_problem(validator: list, items: list) -> str | None:
    """code_aster's validators (Language/Validators.py) over the values given."""
    kind, args = validator[0], validator[1:]
    values = [v for v in items if v is not Unknown]
    if len(values) != len(items) and kind in ("Compulsory", "Together", "OrdList", "NoRepeat"):
        return None
    try:
        if kind == "NoRepeat":
            if len(set(values)) != len(values):
                return f"all the values must be different, got {values!r}"
        elif kind == "LongStr":
            for text in values:
                if isinstance(text, str) and not args[0] <= len(text) <= args[1]:
                    return f"text length must be in [{args[0]}, {args[1]}]: {text!r}"
        elif kind == "OrdList":
            reverse = args and args[0] == "decreasing"
            for a, b in zip(values, values[1:], strict=False):
                if a is not None and b is not None and (a < b if reverse else a > b):
                    order = "decreasing" if reverse else "increasing"
                    return f"the values must be in {order} order: {a!r} followed by {b!r}"
        elif kind == "Compulsory":
            missing = [v for v in decode(args[0]) if v not in values]
            if missing:
                return f"values required: {', '.join(map(str, missing))}"
        elif kind == "Together":
            expected = decode(args[0])
            missing = [v for v in expected if v not in values]
            if missing and len(missing) != len(expected):
                return f"values that go together are missing: {', '.join(map(str, missing))}"
        elif kind == "Absent":
            present = [v for v in decode(args[0]) if v in values]
            if present:
                return f"values not allowed: {', '.join(map(str, present))}"
        elif kind == "NotEqualTo":
            if any(v == decode(args[0]) for v in values):
                return f"value {decode(args[0])!r} is not allowed"
        elif kind == "AtMostOneStartsWith":
            found = {v for v in values if isinstance(v, str) and v.startswith(args[0])}
            if len(found) > 1:
                return f"at most one value may start with {args[0]!r}, got {sorted(found)}"
        elif kind == "AndVal":
            for inner in args:
                message = _validator_problem(inner, items)
                if message:
                    return message
        elif kind == "OrVal":
            messages = [_validator_problem(inner, items) for inner in args]
            if all(messages):
                return " or ".join(messages)
    except TypeError:  # values code_aster's validator could not compare either
        return f"values cannot be checked by {kind}"
    return None


RULE_TEXT = {
    "UN_PARMI": "exactly one of {names} must be given",
    "AU_MOINS_UN": "at least one of {names} must be given",
    "EXCLUS": "at most one of {names} may be given",
    "PRESENT_PRESENT": "{first} requires {others}",
    "PRESENT_ABSENT": "{first} excludes {others}",
    "ENSEMBLE": "{names} go together: all or none",
    "NON_VIDE": "at least one keyword must be given",
}


def _rule_message(rule: list, user: dict) -> str | None:
    """None when ``rule`` holds on ``user`` (code_aster's Rules.py), else a message.
    UN_PARMI and AU_MOINS_UN with defaults insert them when none is given."""
    kind = rule[0]
    names = [n for n in rule[1:] if isinstance(n, str)]
    defaults = next((r["defaults"] for r in rule[1:] if isinstance(r, dict)), None)
    given = [n for n in names if not is_undefined(user.get(n))]
    count = len(given)
    if kind in ("UN_PARMI", "AU_MOINS_UN") and count == 0 and defaults:
        for key, value in defaults.items():
            user[key] = decode(value)
        given = [n for n in names if not is_undefined(user.get(n))]
        count = len(given)
    if kind == "UN_PARMI":
        holds_ = count == 1
    elif kind == "AU_MOINS_UN":
        holds_ = count >= 1
    elif kind == "EXCLUS":
        holds_ = count <= 1
    elif kind == "PRESENT_PRESENT":
        holds_ = not names or names[0] not in user or count == len(names)
    elif kind == "PRESENT_ABSENT":
        holds_ = not names or names[0] not in user or count == 1
    elif kind == "ENSEMBLE":
        holds_ = count in (0, len(names))
    elif kind == "NON_VIDE":
        holds_ = bool(user)
    else:
        holds_ = True
    if holds_:
        return None
    text = RULE_TEXT.get(kind, kind + " {names}").format(
        names=", ".join(names), first=names[0] if names else "", others=", ".join(names[1:])
    )
    if given and kind in ("UN_PARMI", "EXCLUS", "ENSEMBLE", "PRESENT_ABSENT"):
        text += f", got {', '.join(given)}"
    elif kind == "PRESENT_PRESENT":
        text += f", missing {', '.join(n for n in names[1:] if n not in given)}"
    return f"{text} ({kind})"


def _is_output(value) -> bool:
    return isinstance(value, CO)


def _names(rule: list) -> list[str]:
    return [n for n in rule[1:] if isinstance(n, str)]
