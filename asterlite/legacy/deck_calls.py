"""Reading a deck's calls as written, for the legacy layer: each call's
keywords as a tree of :class:`~asterlite.legacy.base.Src` leaves (the text
as written, its literal value when it has one, its location, the comments
around it), and the names a deck binds once to a literal. The porter
(:mod:`asterlite.legacy.port`) rewrites decks from these trees; the code_aster
15 layer (:mod:`asterlite.legacy.v15`) finds the nodes and cells decks name."""

from __future__ import annotations

from collections import Counter

from lark import Token, Tree

from asterlite.errors import Location
from asterlite.lang.values import FactorDict
from asterlite.legacy.base import NotPortable, Src

# ------------------------------------------------------------------ scanning


def _skip_string(text: str, pos: int) -> int:
    """Position after the string literal starting at ``pos`` (at its quote)."""
    for quote in ('"""', "'''"):
        if text.startswith(quote, pos):
            end = text.find(quote, pos + 3)
            return len(text) if end < 0 else end + 3
    quote = text[pos]
    pos += 1
    while pos < len(text) and text[pos] != quote:
        pos += 2 if text[pos] == "\\" else 1
    return pos + 1


def scan_value(text: str, pos: int) -> int:
    """From ``pos``, the position of the first ',' or closing bracket at depth 0."""
    depth = 0
    while pos < len(text):
        char = text[pos]
        if char in "'\"":
            pos = _skip_string(text, pos)
            continue
        if char == "#":
            end = text.find("\n", pos)
            pos = len(text) if end < 0 else end
            continue
        if char in "([{":
            depth += 1
        elif char in ")]}":
            if depth == 0:
                return pos
            depth -= 1
        elif char == "," and depth == 0:
            return pos
        pos += 1
    return pos


def _call_end(text: str, open_pos: int) -> int:
    """Position of the ')' closing the call whose '(' is at ``open_pos``."""
    pos = open_pos + 1
    while pos < len(text):
        pos = scan_value(text, pos)
        if pos >= len(text) or text[pos] != ",":
            return pos
        pos += 1
    return pos


# ------------------------------------------------------------------ reading


def _tokens(node):
    pending = [node]
    while pending:
        item = pending.pop()
        if isinstance(item, Token):
            yield item
        elif isinstance(item, Tree):
            pending.extend(reversed(item.children))


def _first_token(node):
    return next(_tokens(node), None)


def callee_name(node) -> str | None:
    target = node.children[0]
    if getattr(target, "data", None) == "var":
        return target.children[0].value
    return None


def node_literal(node):
    """The Python value of a literal node, or raise ValueError."""
    kind = getattr(node, "data", None)
    if kind == "const":
        return node.children[0]
    if kind == "unary" and len(node.children) == 2 and node.children[0] in ("-", "+"):
        value = node_literal(node.children[1])
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            return -value if node.children[0] == "-" else value
    if kind in ("tuple", "list"):
        values = tuple(node_literal(child) for child in node.children)
        return values if kind == "tuple" else list(values)
    raise ValueError("not a literal")


class CallReader:
    """Builds call trees (FactorDict of Src leaves) from the parse tree."""

    def __init__(self, text: str, filename: str, lines: list[str], constants=None):
        self.text, self.filename, self.lines = text, filename, lines
        self.constants = constants or {}
        starts, offset = [], 0
        for line in text.splitlines(keepends=True):
            starts.append(offset)
            offset += len(line)
        self.line_starts = starts or [0]

    def location(self, token) -> Location:
        line = token.line or 1
        source = self.lines[line - 1] if 0 < line <= len(self.lines) else ""
        return Location(self.filename, line, token.column or 1, source)

    def call(self, node) -> tuple[FactorDict, int, int]:
        """(keywords, start, end) of a call node: ``end`` is after its ')'."""
        name_token = node.children[0].children[0]
        start = name_token.start_pos
        open_pos = self.text.index("(", name_token.end_pos)
        end = _call_end(self.text, open_pos) + 1
        arguments = node.children[1] if len(node.children) > 1 else None
        keywords = FactorDict(location=self.location(name_token))
        previous = open_pos + 1
        for argument in getattr(arguments, "children", None) or ():
            if getattr(argument, "data", None) != "kwarg":
                raise NotPortable("the call has positional or ** arguments")
            key_token = argument.children[0].children[0]
            value_start = self.text.index("=", key_token.end_pos) + 1
            value_end = scan_value(self.text, value_start)
            value = self.value(argument.children[1], value_start, value_end)
            value = _with_comments(value, self.text, previous, key_token.start_pos, value_end)
            keywords[key_token.value] = value
            keywords.keyword_locations[key_token.value] = self.location(key_token)
            previous = value_end
        return keywords, start, end

    def value(self, node, start: int, end: int):
        if getattr(node, "data", None) == "funccall" and callee_name(node) == "_F":
            return self.call(node)[0]
        if getattr(node, "data", None) in ("tuple", "list") and node.children:
            if all(
                getattr(c, "data", None) == "funccall" and callee_name(c) == "_F"
                for c in node.children
            ):
                return tuple(self.call(child)[0] for child in node.children)
        text = self.text[start:end].strip()
        token = _first_token(node)
        location = self.location(token) if token is not None else None
        try:
            return Src(text, node_literal(node), location)
        except ValueError:
            pass
        if getattr(node, "data", None) == "var" and text in self.constants:
            return Src(text, self.constants[text], location)  # NAME bound once to a literal
        return Src(text, location=location)


def _with_comments(value, text: str, gap_start: int, key_start: int, value_end: int):
    """``value`` carrying the comment lines before its keyword and the one ending its line."""
    gap = text[gap_start:key_start]
    lead = tuple(line.strip() for line in gap.splitlines()[1:] if line.strip().startswith("#"))
    line_end = text.find("\n", value_end)
    tail = text[value_end : len(text) if line_end < 0 else line_end]
    before = tail.split("#", 1)[0]
    comment = tail[tail.index("#") :].strip() if "#" in tail and before.strip() in ("", ",") else ""
    if not lead and not comment:
        return value
    if isinstance(value, Src):
        return Src(value.text, value.value, value.location, comment, lead)
    if isinstance(value, dict):
        value.comment, value.lead = comment, lead
    return value


def deck_constants(tree) -> dict:
    """Names the deck binds exactly once, at its top level, to a literal
    (``METHOD1 = 'EULER'``), with that literal: a translation reads a keyword
    given by such a name as if the literal were written (the ported text keeps
    the name where the value does not change). Bindings in function bodies are
    local; any other binding of a name (a second assignment, a loop, an
    augmented assignment...) makes it a variable."""
    counts: Counter = Counter()
    values: dict = {}

    def names_in(node) -> list[str]:
        if isinstance(node, Token):
            return [str(node)] if node.type == "NAME" else []
        return [
            str(t) for t in node.scan_values(lambda v: isinstance(v, Token) and v.type == "NAME")
        ]

    def walk(node, top: bool) -> None:
        for child in getattr(node, "children", ()):
            kind = getattr(child, "data", None)
            if kind is None:
                continue
            if kind == "funcdef":
                counts.update(names_in(child.children[0])[:1])
                continue
            if kind in ("assign", "augassign", "for_stmt", "del_stmt"):
                targets = child.children[:-1] if kind == "assign" else child.children[:1]
                for target in targets:
                    counts.update(names_in(target))
                single = kind == "assign" and len(child.children) == 2
                if top and single and getattr(child.children[0], "data", None) == "var":
                    try:
                        values[str(child.children[0].children[0])] = node_literal(child.children[1])
                    except ValueError:
                        pass
            walk(child, False)

    walk(tree, True)
    return {name: value for name, value in values.items() if counts[name] == 1}
