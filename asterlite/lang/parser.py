"""Parse deck text into a checked lark tree.

Positions are not propagated to tree nodes (that doubles parse time); a
node's location is its first token's, see :func:`node_position`.

The LALR parser is built once per process, on first use (importing this
module stays cheap), from ``deck.lark``; its tables are kept in a private
folder so later processes start fast (:mod:`asterlite.lang.parser_cache`).

After parsing, one iterative pass over the tree (deep nesting cannot
overflow the stack) refuses what the grammar accepts but decks may not do
(``__`` names, attributes starting with ``_``, assignments to calls or
attributes, ``return`` outside a function...) and turns number and string
literals into Python values, stored as ``const`` nodes so the evaluator never
decodes text; an f-string becomes an ``fstring`` node whose fields are
parsed and checked as any expression.

Decks of code_aster 13 and older are Python 2 (``print "x"``, ``0777``,
``except E, e``...). A deck that does not parse as Python 3 is read again
as Python 2: when that reading succeeds the module says so (``python2``)
and keeps the Python 3 error, which the run reports unless the deck's
version allows Python 2 (:mod:`asterlite.legacy.version`). In a Python 2
module ``/`` is Python 2's division (integers divide to an integer) unless
the deck imports ``division`` from ``__future__``.
"""

from __future__ import annotations

import functools
import re
from dataclasses import dataclass, field
from pathlib import Path

from asterlite.errors import DeckSyntaxError, Location, UnquotedLocation

GRAMMAR_PATH = Path(__file__).with_name("deck.lark")

# Python keywords and constructs outside the deck subset, refused by the lexer
# with a message naming them (they would otherwise be read as plain names).
UNSUPPORTED_KEYWORDS = {
    "class": "class definitions are",
    "global": "'global' declarations are",
    "nonlocal": "'nonlocal' declarations are",
    "yield": "generators ('yield') are",
    "async": "'async' is",
    "await": "'await' is",
}
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
# levels of the syntax tree a deck may nest (the evaluator recurses on them;
# real decks stay under 30)
MAX_TREE_DEPTH = 200
# characters of a source line shown in an error excerpt
EXCERPT_WIDTH = 160
# what every code_aster deck has: a command call (DEBUT(), LIRE_MAILLAGE(...))
# or code_aster named; a file without it has its text shown in no error
DECK_SIGNATURE = re.compile(r"\b[A-Z][A-Z0-9_]*\s*\(|\bcode_aster\b")


@dataclass
class Module:
    """A parsed deck file: its checked tree, its source lines and its name."""

    tree: object  # lark.Tree
    lines: list[str]
    filename: str
    # a file a study names (deck, helper module, material file): its text is
    # shown in errors only if it reads as a deck (see reads_as_deck)
    study_file: bool = False
    # the deck is Python 2 (read so after its Python 3 reading failed with
    # python3_error); future: the features it imports from __future__
    python2: bool = False
    python3_error: object = None
    future: frozenset = field(default_factory=frozenset)

    @functools.cached_property
    def reads_as_deck(self) -> bool:
        """The text calls a code_aster command (``DEBUT(``...) or names
        code_aster; else it may be any file the user can read (``F comm
        /etc/passwd``)."""
        return any(DECK_SIGNATURE.search(line) for line in self.lines)

    def location(self, line: int, column: int = 0) -> Location:
        if self.study_file and not self.reads_as_deck:
            return UnquotedLocation(self.filename, line, column)
        source = self.lines[line - 1] if 0 < line <= len(self.lines) else ""
        if len(source) <= EXCERPT_WIDTH:
            return Location(self.filename, line, column, source)
        # a very long line: show the part around the column
        start = max(0, min(column - 1 - EXCERPT_WIDTH // 2, len(source) - EXCERPT_WIDTH))
        clipped = source[start : start + EXCERPT_WIDTH]
        clipped = (
            ("..." if start else "")
            + clipped
            + ("..." if start + EXCERPT_WIDTH < len(source) else "")
        )
        return ClippedLocation(self.filename, line, column, clipped, start - (3 if start else 0))


@dataclass(frozen=True)
class ClippedLocation(Location):
    """A location whose excerpt shows only part of a long source line."""

    offset: int = 0  # columns of the line left out before the excerpt

    def excerpt(self) -> str:
        if not self.source_line:
            return ""
        caret = " " * max(self.column - 1 - self.offset, 0) + "^"
        return f"    {self.source_line.rstrip()}\n    {caret}"


def parse_deck(
    text: str,
    filename: str,
    *,
    private_names: bool = False,
    study_file: bool = False,
    python2: bool | None = None,
) -> Module:
    """Parse a deck (or a helper ``.py`` file) into a :class:`Module`.

    Raises DeckSyntaxError, located, for text that does not parse or uses a
    construct outside the deck subset. Names may start with one underscore
    (``_OMEGA``, ``for _ in``); ``__`` names are refused, and so are
    attributes starting with ``_`` (``private_names`` is kept for callers:
    it no longer changes anything). ``study_file``: the text is a file a
    study named; unless it reads as a deck, errors located in it show
    neither its lines nor their own wording. ``python2``: None reads the
    text as Python 3, then as Python 2 if that fails (see the module's
    docstring); True or False reads it so only.
    """
    if python2 is not None:
        return _parse(text, filename, "file_input", study_file, python2)
    known = _PYTHON3_ERRORS.get(text)  # a Python 2 deck read before
    if known is not None:
        module = _parse(text, filename, "file_input", study_file, True)
        message, line, column = known
        module.python3_error = DeckSyntaxError(message, module.location(line, column))
        return module
    try:
        return _parse(text, filename, "file_input", study_file, False)
    except DeckSyntaxError as error:
        if _NOT_PYTHON2.search(text):
            raise
        try:
            module = _parse(text, filename, "file_input", study_file, True)
        except DeckSyntaxError as old_error:
            # report the reading that went further into the text
            if _error_line(old_error) > _error_line(error):
                raise old_error from None
            raise error from None
        module.python3_error = error
        if len(_PYTHON3_ERRORS) >= _RECENT_LIMIT:
            _PYTHON3_ERRORS.pop(next(iter(_PYTHON3_ERRORS)))
        location = error.location
        _PYTHON3_ERRORS[text] = (error._message, location.line, location.column)
        return module


# the Python 3 errors of the Python 2 decks parsed last, by text
_PYTHON3_ERRORS: dict = {}


# Python 3 only: text with these never reads as Python 2
_NOT_PYTHON2 = re.compile(r"^\s*from\s+__future__\s+import\b.*\bprint_function\b", re.M)


def _error_line(error) -> int:
    location = getattr(error, "location", None)
    return (location.line, location.column) if location is not None else (0, 0)


def parse_expression(text: str, filename: str) -> Module:
    """Parse one expression (a FORMULE's ``VALE``, say); its tree is an ``eval_input``
    node whose only child is the expression. Run it with ``Evaluator.evaluate``."""
    return _parse(text.strip(), filename, "eval_input")


class _Dialect:
    """The reading under way: Python 2 turns statement-leading ``print`` into
    the print statement (the lexer's stream is filtered, see DeckIndenter)."""

    python2 = False


# checked trees of the texts parsed last: a run parses its deck three times
# (version detection, code_aster 15 names, the session), a third of its
# start-up; trees are read-only once checked, so callers can share them
_RECENT_TREES: dict = {}
_RECENT_LIMIT = 4


def _parse(
    text: str, filename: str, start: str, study_file: bool = False, python2: bool = False
) -> Module:
    key = (text, start, python2)
    if key in _RECENT_TREES:
        tree, future = _RECENT_TREES[key]
        return Module(tree, text.splitlines(), filename, study_file, python2, future=future)
    module = _parse_text(text, filename, start, study_file, python2)
    if len(_RECENT_TREES) >= _RECENT_LIMIT:
        _RECENT_TREES.pop(next(iter(_RECENT_TREES)))
    _RECENT_TREES[key] = (module.tree, module.future)
    return module


def _parse_text(
    text: str, filename: str, start: str, study_file: bool, python2: bool = False
) -> Module:
    from lark.exceptions import UnexpectedInput

    lines = text.splitlines()
    module = Module(None, lines, filename, study_file, python2)
    source = text if text.endswith("\n") else text + "\n"
    try:
        _Dialect.python2 = python2
        try:
            module.tree = _parser().parse(source, start=start)
        finally:
            _Dialect.python2 = False
        _check_tree(module)
    except _LocatedSyntaxError as error:
        raise DeckSyntaxError(error.message, module.location(error.line, error.column)) from None
    except UnexpectedInput as error:
        raise _describe_syntax_error(error, module) from None
    except RecursionError:
        raise DeckSyntaxError("expression nested too deeply", module.location(1, 1)) from None
    return module


class _LocatedSyntaxError(Exception):
    """Raised from inside lark's lexer pipeline, converted by parse_deck."""

    def __init__(self, message: str, line: int, column: int):
        super().__init__(message)
        self.message, self.line, self.column = message, line, column


@functools.cache
def _parser():
    """The LALR parser: its tables loaded from the private cache, else built
    and stored there (lark's own ``cache=True`` trusts a file in $TMPDIR)."""
    from lark import Lark

    from asterlite.lang import parser_cache

    grammar = GRAMMAR_PATH.read_text(encoding="utf-8")
    folder = parser_cache.cache_folder()
    key = parser_cache.cache_key(grammar)
    tables = parser_cache.load_tables(folder, key) if folder else None
    if tables is not None:
        try:
            return Lark._load_from_dict(tables["data"], tables["memo"], postlex=_indenter_class()())
        except Exception:  # tables of another shape: built again below
            pass
    parser = Lark(
        grammar,
        parser="lalr",
        start=["file_input", "eval_input"],
        postlex=_indenter_class()(),
        maybe_placeholders=True,
    )
    if folder:
        parser_cache.store_tables(folder, key, parser)
    return parser


@functools.cache
def _indenter_class():
    from lark.indenter import PythonIndenter

    class DeckIndenter(PythonIndenter):
        """PythonIndenter whose indentation errors carry the line."""

        def handle_NL(self, token):  # noqa: N802 - lark's hook name
            if self.paren_level > 0:
                return
            yield token
            indent_str = token.rsplit("\n", 1)[1]
            indent = indent_str.count(" ") + indent_str.count("\t") * self.tab_len
            if indent > self.indent_level[-1]:
                self.indent_level.append(indent)
                yield token.new_borrow_pos(self.INDENT_type, indent_str, token)
                return
            while indent < self.indent_level[-1]:
                self.indent_level.pop()
                yield token.new_borrow_pos(self.DEDENT_type, indent_str, token)
            if indent != self.indent_level[-1]:
                line = (token.end_line or token.line or 1) if "\n" in token else token.line
                raise _LocatedSyntaxError(
                    "unindent does not match any outer indentation level", line, indent + 1
                )

        def _process(self, stream):
            tokens = super()._process(self._balanced(stream))
            yield from _print_statements(tokens) if _Dialect.python2 else tokens

        def _balanced(self, stream):
            # lark's indenter asserts on an unmatched closing bracket; report it instead.
            # Keywords and string prefixes are refused here too: lark drops
            # lexer_callbacks when it loads a cached parser.
            depth = 0
            for token in stream:
                if token.type == "NAME":
                    _refuse_keyword(token)
                elif token.type in ("STRING", "LONG_STRING"):
                    _refuse_prefix(token)
                if token.type in self.OPEN_PAREN_types:
                    depth += 1
                elif token.type in self.CLOSE_PAREN_types:
                    depth -= 1
                    if depth < 0:
                        raise _LocatedSyntaxError(
                            f"unmatched {token.value!r}", token.line, token.column
                        )
                yield token

    return DeckIndenter


def _refuse_keyword(token):
    what = UNSUPPORTED_KEYWORDS.get(token.value)
    if what:
        raise _LocatedSyntaxError(f"{what} not supported in decks", token.line, token.column)
    return token


# tokens after which a statement starts (a colon only outside brackets)
_STATEMENT_STARTS = frozenset({"_NEWLINE", "_INDENT", "_DEDENT", "SEMICOLON"})


def _print_statements(tokens):
    """Python 2: a statement starting with the name ``print`` is the print
    statement (its token becomes PRINT2). ``print`` is a keyword there, so no
    lookahead is needed (the contextual lexer allows none)."""
    from lark import Token

    previous, depth = None, 0
    for token in tokens:
        kind = token.type
        starts = previous is None or previous in _STATEMENT_STARTS
        starts = starts or (previous == "COLON" and depth == 0)
        if kind == "NAME" and token.value == "print" and starts:
            token = Token.new_borrow_pos("PRINT2", token.value, token)
        elif kind in ("LPAR", "LSQB", "LBRACE"):
            depth += 1
        elif kind in ("RPAR", "RSQB", "RBRACE"):
            depth -= 1
        previous = kind
        yield token


def _refuse_prefix(token):
    prefix = re.match(r"[a-zA-Z]*", token.value).group().lower()
    if "b" in prefix:
        message = "bytes literals are not supported in decks"
        raise _LocatedSyntaxError(message, token.line, token.column)
    return token


def _describe_syntax_error(error, module: Module) -> DeckSyntaxError:
    from lark.exceptions import UnexpectedCharacters, UnexpectedEOF, UnexpectedToken

    line = getattr(error, "line", None)
    column = getattr(error, "column", None)
    if isinstance(error, UnexpectedCharacters):
        char = module.lines[line - 1][column - 1 : column] if 0 < line <= len(module.lines) else ""
        if char == "@":
            message = "decorators and '@' are not supported in decks"
        elif char in ("'", '"'):
            message = "unterminated string"
        else:
            message = f"unexpected character {char!r}" if char else "unexpected character"
    elif isinstance(error, UnexpectedEOF) or (
        isinstance(error, UnexpectedToken) and error.token.type == "$END"
    ):
        message = "unexpected end of file (unclosed bracket or missing block?)"
        line, column = _last_position(module)
    elif isinstance(error, UnexpectedToken):
        message = _unexpected_token_message(error.token)
        if error.token.type in ("_INDENT", "_DEDENT"):
            # these borrow the newline token's span: the new line starts at its end
            line, column = error.token.end_line, error.token.end_column
    else:  # pragma: no cover - lark has no other UnexpectedInput kinds
        message = "invalid syntax"
    if not isinstance(line, int) or line < 1:
        line, column = _last_position(module)
    return DeckSyntaxError(message, module.location(line, column if column and column > 0 else 1))


def _unexpected_token_message(token) -> str:
    if token.type == "_INDENT":
        return "unexpected indentation"
    if token.type == "_DEDENT":
        return "unexpected end of block"
    if token.type == "_NEWLINE":
        return "unexpected end of line"
    return f"invalid syntax: unexpected {token.value!r}"


def _last_position(module: Module) -> tuple[int, int]:
    line = max(len(module.lines), 1)
    text = module.lines[line - 1] if module.lines else ""
    return line, len(text) + 1


# --------------------------------------------------------------------- checks


def _check_tree(module: Module, root=None) -> None:
    """Refuse what the grammar accepts but decks may not do; fold literals
    (``root``: a subtree, an f-string field's expression)."""
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
            _fold_strings(node, module)
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


def _fold_strings(node, module: Module) -> None:
    tokens = [string.children[0] for string in node.children]
    if any("f" in _prefix(token.value) for token in tokens):
        _fold_fstring(node, tokens, module)
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


def _fold_fstring(node, tokens, module: Module) -> None:
    """Adjacent literals, one an f-string at least: an ``fstring`` node
    [first token, parts...], each part ``fstring_text`` [text] or
    ``fstring_field`` [expression, conversion, spec fstring or None, debug text]."""
    from lark import Tree

    from asterlite.lang import fstrings

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
        parts.extend(_fstring_parts(pieces, token, body_offset, raw, module))
    node.data = "fstring"
    node.children = [tokens[0], *parts]


def _fstring_parts(pieces, token, body_offset: int, raw: bool, module: Module) -> list:
    from lark import Tree

    parts = []
    for piece in pieces:
        if isinstance(piece, str):
            parts.append(Tree("fstring_text", [_decoded(piece, raw, token, module)]))
            continue
        expression = _field_expression(piece, token, body_offset, module)
        spec = None
        if piece.spec:
            spec_parts = _fstring_parts(piece.spec, token, body_offset, raw, module)
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


def _field_expression(piece, token, body_offset: int, module: Module):
    """An f-string field's expression, parsed and checked as any expression,
    its tokens placed where they stand in the deck."""
    from lark import Token
    from lark.exceptions import UnexpectedInput

    line, column = _position_in(token, body_offset + piece.offset)
    text = piece.expression
    try:
        tree = _parser().parse(f"({text})\n", start="eval_input")
    except UnexpectedInput:
        raise _LocatedSyntaxError("invalid expression in an f-string field", line, column) from None
    for item in tree.scan_values(lambda value: isinstance(value, Token)):
        if item.line == 1:
            item.line, item.column = line, column + item.column - 2  # '(' added
        else:
            item.line = line + item.line - 1
    expression = tree.children[0]
    _check_tree(module, expression)
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
    import unicodedata

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
