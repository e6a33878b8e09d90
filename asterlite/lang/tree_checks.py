"""The checks of the deck parser's tree: what the grammar accepts but decks
may not do, and the decoding of number, string and f-string literals into
``const`` nodes (see :mod:`asterlite.lang.parser`, which runs
:func:`check_tree` on every tree it builds).

One iterative pass (deep nesting cannot overflow the stack), bounded by
``Limits.max_tree_depth`` of :mod:`asterlite.lang.limits`.
"""

from __future__ import annotations

import re
import unicodedata
from typing import TYPE_CHECKING

from asterlite.errors import DeckSyntaxError
from asterlite.lang import fstrings
from asterlite.lang.limits import Limits

if TYPE_CHECKING:
    from asterlite.lang.parser import Module

# levels of the syntax tree a deck may nest (the evaluator recurses on them;
# real decks stay under 30)
MAX_TREE_DEPTH = Limits().max_tree_depth
# features a deck may import from __future__ (none changes a Python 3 deck)
FUTURE_FEATURES = frozenset(
    {
        "division",
        "print_function",
        "absolute_import",
        "with_statement",
        "unicode_literals",
        "generators",
        "nested_scopes",
        "generator_stop",
        "annotations",
    }
)


class LocatedSyntaxError(Exception):
    """Raised from inside lark's lexer pipeline, converted by parse_deck."""

    def __init__(self, message: str, line: int, column: int):
        super().__init__(message)
        self.message, self.line, self.column = message, line, column


def check_tree(module: Module, parse, root=None) -> None:
    """Refuse what the grammar accepts but decks may not do; fold literals
    (``root``: a subtree, an f-string field's expression; ``parse``: the
    deck parser's ``parse(text, start=...)``, for f-string fields)."""
    from lark import Token, Tree

    # (node, inside_loop, inside_function, depth); explicit stack, no recursion
    stack = [(module.tree if root is None else root, False, False, 0)]
    while stack:
        node, in_loop, in_function, depth = stack.pop()
        if depth > MAX_TREE_DEPTH:  # the evaluator walks the tree recursively
            raise _error(
                f"expression or statements nested too deeply (more than {MAX_TREE_DEPTH} levels)",
                node,
                module,
            )
        if isinstance(node, Token):
            if node.type == "NAME":
                _check_name(node, module)
            continue
        if not isinstance(node, Tree):
            continue
        kind = node.data
        if kind == "number":
            _fold_number(node, module)
            continue
        if kind == "strings":
            _fold_strings(node, module, parse)
            continue
        _CHECKS.get(kind, _no_check)(node, module, in_loop, in_function)
        child_loop = (in_loop or kind in ("for_stmt", "while_stmt")) and kind not in (
            "funcdef",
            "lambdef",
        )
        child_function = in_function or kind in ("funcdef", "lambdef")
        for child in reversed(node.children):
            stack.append((child, child_loop, child_function, depth + 1))


def _no_check(node, module, in_loop, in_function) -> None:
    return None


def _error(message: str, node, module: Module) -> DeckSyntaxError:
    line, column = node_position(node)
    return DeckSyntaxError(message, module.location(line, column))


def node_position(node) -> tuple[int, int]:
    """(line, column) of a node: those of its first token in text order (lark
    tracks no tree spans here, which halves parse time)."""
    from lark import Token, Tree

    pending = [node]
    while pending:
        item = pending.pop()
        if isinstance(item, Token):
            return item.line or 1, item.column or 1
        if isinstance(item, Tree):
            pending.extend(reversed(item.children))
    return 1, 1


def _check_name(token, module: Module) -> None:
    """Deck names may start with one underscore (``_OMEGA``, ``for _ in``),
    never with two (``__builtins__``); attributes are checked apart."""
    if token.value.startswith("__"):
        message = f"names starting with '__' are not allowed in decks: {token.value}"
        raise _error(message, token, module)


def _check_attribute_name(token, module: Module) -> None:
    if token.value.startswith("_"):
        message = f"attributes starting with '_' are not available in decks: {token.value}"
        raise _error(message, token, module)


def _check_getattr(node, module, in_loop, in_function) -> None:
    _check_attribute_name(node.children[1], module)


def _check_import_from(node, module, in_loop, in_function) -> None:
    dotted, names = node.children
    parts = [token.value for token in dotted.children]
    if parts == ["__future__"]:
        if names.data == "import_star":
            raise _error("'from __future__ import *' is not allowed", names, module)
        features = set()
        for import_as_name in names.children:
            name = import_as_name.children[0]
            if name.value not in FUTURE_FEATURES:
                raise _error(f"future feature {name.value} is not defined", name, module)
            features.add(name.value)
        module.future = module.future | frozenset(features)
        dotted.children = []  # checked: the evaluator skips it
        return
    _check_module_names(dotted, module)
    if names.data != "import_star":
        for import_as_name in names.children:
            _check_attribute_name(import_as_name.children[0], module)


def _check_import_name(node, module, in_loop, in_function) -> None:
    for dotted_as_name in node.children:
        _check_module_names(dotted_as_name.children[0], module)


def _check_module_names(dotted, module: Module) -> None:
    for token in dotted.children:
        _check_attribute_name(token, module)


def _check_targets(node, module: Module, what: str = "assign to") -> None:
    if node.data in ("var", "getitem"):
        return
    if node.data in ("tuple", "list") and node.children:
        for child in node.children:
            _check_targets(child, module, what)
        return
    if node.data == "getattr":
        raise _error(f"cannot {what} an attribute in a deck", node, module)
    raise _error(f"cannot {what} {_describe(node)}", node, module)


def _describe(node) -> str:
    return {
        "funccall": "a function call",
        "const": "a literal",
        "number": "a literal",
        "strings": "a literal",
        "tuple": "an empty tuple",
        "list": "an empty list",
    }.get(node.data, "an expression")


def _check_assign(node, module, in_loop, in_function) -> None:
    for target in node.children[:-1]:
        _check_targets(target, module)


def _check_augassign(node, module, in_loop, in_function) -> None:
    target = node.children[0]
    if target.data not in ("var", "getitem"):
        raise _error(f"cannot use {node.children[1]} on {_describe(target)}", target, module)


def _check_del(node, module, in_loop, in_function) -> None:
    _check_targets(node.children[0], module, "delete")


def _check_for(node, module, in_loop, in_function) -> None:
    _check_targets(node.children[0], module)


def _check_comp_for(node, module, in_loop, in_function) -> None:
    _check_targets(node.children[0], module)


def _check_loop_flow(node, module, in_loop, in_function) -> None:
    if not in_loop:
        word = "break" if node.data == "break_stmt" else "continue"
        raise _error(f"'{word}' outside a loop", node, module)


def _check_return(node, module, in_loop, in_function) -> None:
    if not in_function:
        raise _error("'return' outside a function", node, module)


def _check_parameters(node, module, in_loop, in_function) -> None:
    seen, has_default = set(), False
    for param in node.children:
        name, default = param.children
        if name.value in seen:
            raise _error(f"duplicate parameter {name.value!r}", name, module)
        seen.add(name.value)
        if default is None and has_default:
            raise _error("a parameter without a default follows one with a default", name, module)
        has_default = has_default or default is not None


def _check_arguments(node, module, in_loop, in_function) -> None:
    seen_keyword, seen_double_star, names = False, False, set()
    for argument in node.children:
        kind = argument.data
        if kind == "kwarg":
            key = argument.children[0]
            if key.data != "var":
                raise _error("a keyword argument must be a plain name", key, module)
            name = key.children[0].value
            if name in names:
                raise _error(f"keyword argument repeated: {name}", key, module)
            names.add(name)
            seen_keyword = True
        elif kind == "double_star_arg":
            seen_double_star = True
        elif kind == "star_arg":
            if seen_double_star:
                raise _error("*arguments after **keywords", argument, module)
        elif seen_keyword or seen_double_star:
            raise _error("positional argument follows keyword argument", argument, module)


def _python2_only(what: str):
    def check(node, module, in_loop, in_function) -> None:
        if not module.python2:
            raise _error(f"{what} is Python 2 (code_aster 13 and older decks)", node, module)

    return check


def _check_comp_op(node, module, in_loop, in_function) -> None:
    if node.children[0].value == "<>" and not module.python2:
        raise _error("'<>' is Python 2 (code_aster 13 and older decks): write '!='", node, module)


def _check_term(node, module, in_loop, in_function) -> None:
    """Python 2's division: '/' of two integers is their floor division."""
    if not module.python2 or "division" in module.future:
        return
    from lark import Token

    for position in range(1, len(node.children), 2):
        op = node.children[position]
        if op.value == "/":
            node.children[position] = Token.new_borrow_pos(op.type, "/2", op)


def _check_augassign_python2(node, module, in_loop, in_function) -> None:
    _check_augassign(node, module, in_loop, in_function)
    op = node.children[1]
    if op.value == "/=" and module.python2 and "division" not in module.future:
        from lark import Token

        node.children[1] = Token.new_borrow_pos(op.type, "/2=", op)


def _check_print_to(node, module, in_loop, in_function) -> None:
    raise _error(
        "'print >>file' is not supported: decks write files through commands", node, module
    )


def _check_with_item(node, module, in_loop, in_function) -> None:
    if node.children[1] is not None:
        _check_targets(node.children[1], module)


def _check_except(node, module, in_loop, in_function) -> None:
    if node.data == "except_py2" and not module.python2:
        raise _error(
            "'except E, name' is Python 2 (code_aster 13 and older decks): "
            "write 'except E as name'",
            node,
            module,
        )


def _check_try(node, module, in_loop, in_function) -> None:
    """A bare 'except:' must be the last handler, as in Python."""
    handlers = [c for c in node.children[1:] if getattr(c, "data", "").startswith("except")]
    for handler in handlers[:-1]:
        if handler.data == "except_clause" and handler.children[1] is None:
            raise _error("default 'except:' must be last", handler, module)


_CHECKS = {
    "getattr": _check_getattr,
    "import_from": _check_import_from,
    "import_name": _check_import_name,
    "comp_op": _check_comp_op,
    "term": _check_term,
    "raise_py2": _python2_only("'raise E, message'"),
    "except_py2": _check_except,
    "backquote": _python2_only("a backquoted expression (`x`)"),
    "print_to": _check_print_to,
    "with_item": _check_with_item,
    "try_stmt": _check_try,
    "assign": _check_assign,
    "augassign": _check_augassign_python2,
    "del_stmt": _check_del,
    "for_stmt": _check_for,
    "comp_for": _check_comp_for,
    "break_stmt": _check_loop_flow,
    "continue_stmt": _check_loop_flow,
    "return_stmt": _check_return,
    "parameters": _check_parameters,
    "arguments": _check_arguments,
}


# ------------------------------------------------------------------- literals


def _fold_number(node, module: Module) -> None:
    token = node.children[0]
    text = token.value.replace("_", "")
    try:
        if token.type == "IMAG_NUMBER":
            value = complex(0, float(text[:-1]))
        elif token.type == "FLOAT_NUMBER" or "." in text:
            value = float(text)
        elif token.type == "HEX_NUMBER":
            value = int(text, 16)
        elif token.type == "OCT_NUMBER":
            value = int(text[2:], 8)
        elif token.type == "BIN_NUMBER":
            value = int(text[2:], 2)
        elif token.type in ("OLD_OCT_NUMBER", "LONG_NUMBER"):
            if not module.python2:
                words = "octal literal" if token.type == "OLD_OCT_NUMBER" else "long literal"
                raise _error(
                    f"Python 2 {words} {token.value[:20]} (code_aster 13 and older decks): "
                    + ("write 0o" + text[1:] if token.type == "OLD_OCT_NUMBER" else "drop the L"),
                    token,
                    module,
                )
            text = text.rstrip("lL")
            if text.lower().startswith("0x"):
                value = int(text[2:], 16)
            elif text.startswith("0") and len(text) > 1:
                value = int(text[1:], 8)
            else:
                value = int(text)
        else:
            value = int(text)
    except ValueError:
        raise _error(f"number literal too large: {token.value[:20]}...", token, module) from None
    _make_const(node, value, token)


def _fold_strings(node, module: Module, parse) -> None:
    tokens = [string.children[0] for string in node.children]
    if any("f" in _prefix(token.value) for token in tokens):
        _fold_fstring(node, tokens, module, parse)
        return
    parts = []
    for token in tokens:
        try:
            parts.append(decode_string_literal(token.value))
        except ValueError as error:
            raise _error(str(error), token, module) from None
    _make_const(node, "".join(parts), tokens[0])


def _prefix(text: str) -> str:
    return re.match(r"[a-zA-Z]*", text).group().lower()


def _fold_fstring(node, tokens, module: Module, parse) -> None:
    """Adjacent literals, one an f-string at least: an ``fstring`` node
    [first token, parts...], each part ``fstring_text`` [text] or
    ``fstring_field`` [expression, conversion, spec fstring or None, debug text]."""
    from lark import Tree

    parts = []
    for token in tokens:
        match = _QUOTE_RE.match(token.value)
        if match is None:
            raise _error("malformed string literal", token, module)
        prefix, quote, body = match.groups()
        raw = "r" in prefix.lower()
        if "f" not in prefix.lower():
            parts.append(Tree("fstring_text", [_decoded(body, raw, token, module)]))
            continue
        body_offset = len(prefix) + len(quote)
        try:
            pieces, _ = fstrings.split(body, raw=raw)
        except fstrings.FStringError as error:
            raise _error_at(str(error), token, body_offset + error.offset, module) from None
        parts.extend(_fstring_parts(pieces, token, body_offset, raw, module, parse))
    node.data = "fstring"
    node.children = [tokens[0], *parts]


def _fstring_parts(pieces, token, body_offset: int, raw: bool, module: Module, parse) -> list:
    from lark import Tree

    parts = []
    for piece in pieces:
        if isinstance(piece, str):
            parts.append(Tree("fstring_text", [_decoded(piece, raw, token, module)]))
            continue
        expression = _field_expression(piece, token, body_offset, module, parse)
        spec = None
        if piece.spec:
            spec_parts = _fstring_parts(piece.spec, token, body_offset, raw, module, parse)
            spec = Tree("fstring", [token, *spec_parts])
        parts.append(Tree("fstring_field", [expression, piece.conversion, spec, piece.debug]))
    return parts


def _decoded(text: str, raw: bool, token, module: Module) -> str:
    if raw:
        return text
    try:
        return _ESCAPE_RE.sub(_unescape, text)
    except ValueError as error:
        raise _error(str(error), token, module) from None


def _field_expression(piece, token, body_offset: int, module: Module, parse):
    """An f-string field's expression, parsed and checked as any expression,
    its tokens placed where they stand in the deck."""
    from lark import Token
    from lark.exceptions import UnexpectedInput

    line, column = _position_in(token, body_offset + piece.offset)
    text = piece.expression
    try:
        tree = parse(f"({text})\n", start="eval_input")
    except UnexpectedInput:
        raise LocatedSyntaxError("invalid expression in an f-string field", line, column) from None
    for item in tree.scan_values(lambda value: isinstance(value, Token)):
        if item.line == 1:
            item.line, item.column = line, column + item.column - 2  # '(' added
        else:
            item.line = line + item.line - 1
    expression = tree.children[0]
    check_tree(module, parse, expression)
    return expression


def _position_in(token, offset: int) -> tuple[int, int]:
    """(line, column) of the character ``offset`` characters into ``token``."""
    before = token.value[:offset]
    newlines = before.count("\n")
    if not newlines:
        return token.line, token.column + offset
    return token.line + newlines, offset - before.rfind("\n")


def _error_at(message: str, token, offset: int, module: Module) -> DeckSyntaxError:
    line, column = _position_in(token, offset)
    return DeckSyntaxError(message, module.location(line, column))


def _make_const(node, value, token) -> None:
    # keep the token: it locates the literal in error messages
    node.data = "const"
    node.children = [value, token]


_QUOTE_RE = re.compile(r"^([a-zA-Z]*)('''|\"\"\"|'|\")(.*)\2$", re.DOTALL)
_ESCAPE_RE = re.compile(
    r"\\(\n|[\\'\"abfnrtv]|x[0-9a-fA-F]{2}|u[0-9a-fA-F]{4}|U[0-9a-fA-F]{8}|[0-7]{1,3}|N\{[^}]*\}|.)",
    re.DOTALL,
)
_SIMPLE_ESCAPES = {
    "\n": "",
    "\\": "\\",
    "'": "'",
    '"': '"',
    "a": "\a",
    "b": "\b",
    "f": "\f",
    "n": "\n",
    "r": "\r",
    "t": "\t",
    "v": "\v",
}


def decode_string_literal(text: str) -> str:
    """The value of a Python string literal token (prefixes r and u only)."""
    match = _QUOTE_RE.match(text)
    if match is None:
        raise ValueError("malformed string literal")
    prefix, _, body = match.groups()
    if "r" in prefix.lower():
        return body
    return _ESCAPE_RE.sub(_unescape, body)


def _unescape(match: re.Match) -> str:
    code = match.group(1)
    if code in _SIMPLE_ESCAPES:
        return _SIMPLE_ESCAPES[code]
    if code[0] in "xuU":
        return chr(int(code[1:], 16)) if int(code[1:], 16) <= 0x10FFFF else _bad_escape(code)
    if code[0] in "01234567":
        return chr(int(code, 8))
    if code[0] == "N":
        try:
            return unicodedata.lookup(code[2:-1])
        except KeyError:
            raise ValueError(f"unknown unicode character name {code[2:-1]!r}") from None
    return "\\" + code  # Python keeps unknown escapes as written


def _bad_escape(code: str) -> str:
    raise ValueError(f"invalid escape \\{code}")
