"""``asterlite port`` of a Python 2 deck (code_aster 13 and older): its
Python 2 syntax written as Python 3, everything else kept byte for byte.

- ``print x, y`` -> ``print(x, y)``; ``print x,`` -> ``print(x, end=" ")``;
- ``a <> b`` -> ``a != b``; `` `x` `` -> ``repr(x)``;
- ``0777`` -> ``0o777``; ``10L`` -> ``10``; ``ur'...'`` -> ``r'...'``;
- ``except E, e:`` -> ``except E as e:``; ``raise E, m`` -> ``raise E(m)``;
- ``a / b``: Python 2 floored the quotient of two integers. Two integer
  literals become ``a // b``; a float literal on either side keeps ``/``;
  any other division is kept and noted, as its operands' types are only
  known when the deck runs.

Each change is a :class:`~asterlite.legacy.base.Note`; the result must read
as Python 3, else the deck is left as written (said in ``skipped``).
"""

from __future__ import annotations

from pathlib import Path

from lark import Token, Tree

from asterlite.errors import AsterliteError, Location
from asterlite.lang import parse_deck
from asterlite.lang.parser import _parser
from asterlite.legacy.base import Note


def to_python3(text: str, filename: str) -> tuple[str, list[Note], list[str]]:
    """(text, notes, skipped): ``text`` with its Python 2 syntax rewritten."""
    module = parse_deck(text, filename)
    if not module.python2:
        return text, [], []

    tokens = list(_parser().lex(text if text.endswith("\n") else text + "\n"))
    edits: list[tuple[int, int, str]] = []
    notes: list[Note] = []

    def note(old: str, new: str, token) -> None:
        notes.append(Note(old, new, Location(str(filename), token.line, token.column)))

    for token in tokens:
        _token_edit(token, edits, note)
    for node in module.tree.iter_subtrees_topdown():
        handler = _NODE_EDITS.get(node.data)
        if handler is not None:
            handler(node, text, tokens, edits, note)
    new_text = text
    for start, end, replacement in sorted(edits, reverse=True):
        new_text = new_text[:start] + replacement + new_text[end:]
    try:
        parse_deck(new_text, filename, python2=False)
    except AsterliteError as error:
        reason = f"{Path(filename).name}: Python 2 syntax left as written: {error.message}"
        return text, [], [reason]
    return new_text, notes, []


def _token_edit(token, edits, note) -> None:
    kind, value = token.type, token.value
    if kind == "OLD_OCT_NUMBER":
        edits.append((token.start_pos, token.end_pos, "0o" + value[1:]))
        note(value, "0o" + value[1:], token)
    elif kind == "LONG_NUMBER":
        digits = value[:-1]
        if len(digits) > 1 and digits[0] == "0" and digits[1] not in "xX":
            digits = "0o" + digits[1:]
        edits.append((token.start_pos, token.end_pos, digits))
        note(value, digits, token)
    elif kind in ("STRING", "LONG_STRING") and value[:2].lower() == "ur":
        edits.append((token.start_pos, token.start_pos + 1, ""))
        note(value[:2] + "'...'", value[1] + "'...'", token)
    elif value == "<>" and kind not in ("STRING", "LONG_STRING"):
        edits.append((token.start_pos, token.end_pos, "!="))
        note("<>", "!=", token)


def _first(node) -> Token:
    for token in _node_tokens(node):
        return token
    raise ValueError("a node without tokens")


def _last(node) -> Token:
    found = None
    for token in _node_tokens(node):
        if found is None or token.end_pos > found.end_pos:
            found = token
    return found


def _node_tokens(node):
    if isinstance(node, Token):
        yield node
        return
    if isinstance(node, Tree):
        for child in node.children:
            yield from _node_tokens(child)


def _next_token(tokens, position: int):
    """The first token starting at or after ``position``."""
    for token in tokens:
        if token.start_pos >= position:
            return token
    return None


def _statement_end(tokens, position: int):
    """The last token of the simple statement going on at ``position``."""
    depth, last = 0, None
    for token in tokens:
        if token.start_pos < position:
            continue
        if token.type in ("LPAR", "LSQB", "LBRACE"):
            depth += 1
        elif token.type in ("RPAR", "RSQB", "RBRACE"):
            depth -= 1
        elif depth == 0 and token.type in ("_NEWLINE", "SEMICOLON"):
            break
        last = token
    return last


def _print(node, text, tokens, edits, note) -> None:
    keyword, items = node.children
    if items is None:
        edits.append((keyword.end_pos, keyword.end_pos, "()"))
        note("print", "print()", keyword)
        return
    *tests, comma = items.children
    start = _next_token(tokens, keyword.end_pos).start_pos
    edits.append((keyword.end_pos, start, "("))
    last = _statement_end(tokens, start)
    if comma is not None:  # print x, : no newline
        edits.append((last.start_pos, last.end_pos, ', end=" ")'))
        note("print x,", 'print(x, end=" ")', keyword)
        return
    edits.append((last.end_pos, last.end_pos, ")"))
    note("print x", "print(x)", keyword)


def _backquote(node, text, tokens, edits, note) -> None:
    inner = node.children[0]
    start, end = _first(inner).start_pos, _last(inner).end_pos
    opening = text.rfind("`", 0, start)
    closing = text.find("`", end)
    edits.append((opening, start, "repr("))
    edits.append((end, closing + 1, ")"))
    note("`x`", "repr(x)", _first(inner))


def _except(node, text, tokens, edits, note) -> None:
    _, test, name, _ = node.children
    comma = text.rfind(",", 0, name.start_pos)
    edits.append((comma, name.start_pos, " as "))
    note("except E, name", "except E as name", name)


def _raise(node, text, tokens, edits, note) -> None:
    cls, message = node.children
    start = _first(message).start_pos
    comma = text.rfind(",", 0, start)
    first = _next_token(tokens, comma + 1)
    edits.append((comma, first.start_pos, "("))
    last = _statement_end(tokens, first.start_pos)
    edits.append((last.end_pos, last.end_pos, ")"))
    note("raise E, message", "raise E(message)", _first(cls))


def _is_int(node) -> bool:
    return isinstance(node, Tree) and node.data == "const" and type(node.children[0]) is int


def _is_float(node) -> bool:
    if isinstance(node, Tree) and node.data == "unary":
        return _is_float(node.children[1])
    return isinstance(node, Tree) and node.data == "const" and isinstance(node.children[0], float)


def _division(node, text, tokens, edits, note) -> None:
    children = node.children
    for position in range(1, len(children), 2):
        op = children[position]
        if op.value != "/2":
            continue
        left, right = children[position - 1], children[position + 1]
        if _is_int(left) and _is_int(right):
            edits.append((op.start_pos, op.end_pos, "//"))
            note(f"{left.children[1]} / {right.children[1]}", "//, as Python 2 divided", op)
        elif not (_is_float(left) or _is_float(right)):
            note(
                "a / b",
                "kept: Python 2 floored it when both are integers (write // if they are)",
                op,
            )


def _augmented_division(node, text, tokens, edits, note) -> None:
    op = node.children[1]
    if op.value == "/2=" and not _is_float(node.children[2]):
        note("a /= b", "kept: Python 2 floored it when both are integers", op)


def _dict_method(node, text, tokens, edits, note) -> None:
    name = node.children[1]
    if name.value in ("has_key", "iteritems", "iterkeys", "itervalues"):
        note(
            f"d.{name.value}()",
            "kept: Python 2's dict method, which Python 3 lacks ('k in d', d.items()...)",
            name,
        )


_NODE_EDITS = {
    "getattr": _dict_method,
    "print_stmt": _print,
    "backquote": _backquote,
    "except_py2": _except,
    "raise_py2": _raise,
    "term": _division,
    "augassign": _augmented_division,
}
