"""f-strings of decks: splitting their text into literal parts and fields
(for the parser), and formatting a field's value (for the evaluator).

A field's expression is an ordinary deck expression: the parser parses and
checks it like any other (names, attributes, literals), so it reaches only
what the evaluator's whitelists let any expression reach. Its value is shown
as ``print`` shows values (engine objects neutrally, never a memory
address), and the field's width, precision and value text count towards the
string limit before anything is formatted, as for ``str.format``.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from asterlite.lang import limits as guards
from asterlite.lang.limits import Limits


@dataclass
class Field:
    """One ``{expression!conversion:spec}`` of an f-string."""

    expression: str
    offset: int  # of the expression in the literal's body
    conversion: str | None  # "r", "s", "a" or None
    spec: list  # the format spec's own parts: str and Field
    debug: str | None  # f"{x=}": the text shown before the value


class FStringError(ValueError):
    def __init__(self, message: str, offset: int):
        super().__init__(message)
        self.offset = offset


_CLOSERS = {"(": ")", "[": "]", "{": "}"}


def split(body: str, start: int = 0, in_spec: bool = False, raw: bool = False) -> tuple[list, int]:
    """The parts of an f-string body (text as written, escapes not decoded):
    str and :class:`Field`, and the position where scanning stopped (the
    closing brace of a spec when ``in_spec``)."""
    parts: list = []
    text: list[str] = []
    position = start
    while position < len(body):
        char = body[position]
        if char == "\\" and not raw:  # an escape: \N{NAME} holds braces
            end = body.find("}", position) + 1 if body.startswith("\\N{", position) else 0
            end = max(end, position + 2)
            text.append(body[position:end])
            position = end
            continue
        if char == "{":
            if body.startswith("{{", position) and not in_spec:
                text.append("{")
                position += 2
                continue
            if text:
                parts.append("".join(text))
                text = []
            field, position = _field(body, position + 1, raw)
            parts.append(field)
            continue
        if char == "}":
            if in_spec:
                break
            if body.startswith("}}", position):
                text.append("}")
                position += 2
                continue
            raise FStringError("single '}' is not allowed in an f-string", position)
        text.append(char)
        position += 1
    if text:
        parts.append("".join(text))
    return parts, position


def _field(body: str, start: int, raw: bool) -> tuple[Field, int]:
    """The field starting after its '{' at ``start``; the position after its '}'."""
    depth, position, quote = [], start, None
    while position < len(body):
        char = body[position]
        if quote:
            if char == quote:
                quote = None
        elif char in "'\"":
            quote = char
        elif char in _CLOSERS:
            depth.append(_CLOSERS[char])
        elif depth and char == depth[-1]:
            depth.pop()
        elif not depth and char in "}:!=":
            if char == "!" and body.startswith("!=", position):
                position += 2
                continue
            if char == "=" and body.startswith("==", position):
                position += 2
                continue
            if char == "=" and position > start and body[position - 1] in "<>":
                position += 1
                continue
            break
        elif char == "\\":
            raise FStringError("f-string expressions may not contain a backslash", position)
        position += 1
    else:
        raise FStringError("f-string field is not closed with '}'", start - 1)
    expression = body[start:position]
    if not expression.strip():
        raise FStringError("empty expression in an f-string field", start)
    debug = None
    if body[position] == "=":
        debug = expression + "="
        position += 1
        # spaces after '=' are shown too
        while position < len(body) and body[position] == " ":
            debug += " "
            position += 1
    conversion = None
    if position < len(body) and body[position] == "!":
        conversion = body[position + 1 : position + 2]
        if conversion not in ("r", "s", "a"):
            raise FStringError("f-string conversion must be !r, !s or !a", position)
        position += 2
    spec: list = []
    if position < len(body) and body[position] == ":":
        spec, position = split(body, position + 1, in_spec=True, raw=raw)
    if position >= len(body) or body[position] != "}":
        raise FStringError("f-string field is not closed with '}'", start - 1)
    if debug is not None and conversion is None and not spec:
        conversion = "r"  # Python shows f"{x=}" with repr
    return Field(expression, start, conversion, spec, debug), position + 1


# ------------------------------------------------------------------ formatting

_SPEC_NUMBERS = re.compile(r"\d+")


def format_field(value, conversion: str | None, spec: str, limits: Limits, room: int) -> str:
    """``value`` formatted as a field: shown as print shows it, converted,
    then formatted with ``spec``; refused before formatting when the text
    could pass ``room`` characters."""
    guards.check_nested_size((value,), limits)
    value = guards.deck_text_value(value)
    bound = guards.text_length_bound(value, as_repr=conversion in ("r", "a"))
    bound += sum(int(number) for number in _SPEC_NUMBERS.findall(spec))
    if bound > room:
        raise guards.exceeded("string length", limits.max_string_length)
    if conversion == "r":
        value = repr(value)
    elif conversion == "a":
        value = ascii(value)
    elif conversion == "s":
        value = str(value)
    return format(value, spec)
