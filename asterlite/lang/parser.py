"""Parse deck text into a checked lark tree.

Positions are not propagated to tree nodes (that doubles parse time); a
node's location is its first token's, see
:func:`asterlite.lang.tree_checks.node_position`.

The LALR parser is built once per process, on first use (importing this
module stays cheap), from ``deck.lark``; its tables are kept in a private
folder so later processes start fast (:mod:`asterlite.lang.parser_cache`).

After parsing, one iterative pass over the tree (deep nesting cannot
overflow the stack) refuses what the grammar accepts but decks may not do
(``__`` names, attributes starting with ``_``, assignments to calls or
attributes, ``return`` outside a function...) and turns number and string
literals into Python values, stored as ``const`` nodes so the evaluator never
decodes text; an f-string becomes an ``fstring`` node whose fields are
parsed and checked as any expression. That pass is
:mod:`asterlite.lang.tree_checks`.

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
from asterlite.lang import parser_cache
from asterlite.lang.tree_checks import (
    LocatedSyntaxError,
    check_tree,
)

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


def parse_expression(text: str, filename: str, *, remember: bool = True) -> Module:
    """Parse one expression (a FORMULE's ``VALE``, say); its tree is an ``eval_input``
    node whose only child is the expression. Run it with ``Evaluator.evaluate``.
    ``remember=False`` keeps it out of the trees kept for the deck's next
    parse (a caller keeping its own, such as :mod:`asterlite.lang.formula`)."""
    if not remember:
        return _parse_text(text.strip(), filename, "eval_input", False)
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
    # a whole file's tree is kept on disk too (an expression parses faster than
    # its file would be written)
    folder = parser_cache.cache_folder() if start == "file_input" else None
    stored = _stored_tree(folder, text, start, python2) if folder else None
    if stored is not None:
        tree, future = stored
        module = Module(tree, text.splitlines(), filename, study_file, python2, future=future)
    else:
        module = _parse_text(text, filename, start, study_file, python2)
        if folder:
            _store_tree(folder, text, start, python2, module)
    if len(_RECENT_TREES) >= _RECENT_LIMIT:
        _RECENT_TREES.pop(next(iter(_RECENT_TREES)))
    _RECENT_TREES[key] = (module.tree, module.future)
    return module


def _tree_key(text: str, start: str, python2: bool) -> str:
    tables = parser_cache.cache_key(GRAMMAR_PATH.read_text(encoding="utf-8"))
    return parser_cache.tree_key(tables, text, start, python2)


def _stored_tree(folder: Path, text: str, start: str, python2: bool):
    """(tree, future) of ``text`` as a process parsed and checked it before, or None."""
    data = parser_cache.load_tree(folder, _tree_key(text, start, python2))
    if data is None:
        return None
    try:
        encoded, future = data
        return _decode_node(encoded), frozenset(future)
    except (TypeError, ValueError, IndexError, RecursionError):  # not a tree of ours
        return None


def _store_tree(folder: Path, text: str, start: str, python2: bool, module: Module) -> None:
    try:
        encoded = _encode_node(module.tree)
    except (TypeError, RecursionError):  # a node that is not plain data: parsed next time
        return
    key = _tree_key(text, start, python2)
    parser_cache.store_tree(folder, key, (encoded, tuple(sorted(module.future))))


# a checked tree as plain data (lark pickles a Token without its end position)
_TREE, _TOKEN, _VALUE = 0, 1, 2
_PLAIN = (str, int, float, bool, type(None))


def _encode_node(node):
    from lark import Token, Tree

    if isinstance(node, Token):
        return (_TOKEN, node.type, str(node), node.start_pos, node.line, node.column,
                node.end_line, node.end_column, node.end_pos)  # fmt: skip
    if isinstance(node, Tree):
        return (_TREE, _encode_node(node.data), tuple(_encode_node(c) for c in node.children))
    if type(node) in _PLAIN:
        return (_VALUE, node)
    raise TypeError(f"{type(node).__name__} in a deck tree")


def _decode_node(data):
    from lark import Token, Tree

    kind = data[0]
    if kind == _TOKEN:
        return Token(*data[1:])
    if kind == _TREE:
        return Tree(_decode_node(data[1]), [_decode_node(c) for c in data[2]])
    if kind == _VALUE and type(data[1]) in _PLAIN:
        return data[1]
    raise ValueError("not a deck tree")


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
        check_tree(module, _parser().parse)
    except LocatedSyntaxError as error:
        raise DeckSyntaxError(error.message, module.location(error.line, error.column)) from None
    except UnexpectedInput as error:
        raise _describe_syntax_error(error, module) from None
    except RecursionError:
        raise DeckSyntaxError("expression nested too deeply", module.location(1, 1)) from None
    return module


@functools.cache
def _parser():
    """The LALR parser: its tables loaded from the private cache, else built
    and stored there (lark's own ``cache=True`` trusts a file in $TMPDIR)."""
    from lark import Lark

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
        # one scanner for every state: the contextual lexer compiles a regex per
        # parser state on first use, ~15 ms of each process's first parse
        lexer="basic",
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
                raise LocatedSyntaxError(
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
                        raise LocatedSyntaxError(
                            f"unmatched {token.value!r}", token.line, token.column
                        )
                yield token

    return DeckIndenter


def _refuse_keyword(token):
    what = UNSUPPORTED_KEYWORDS.get(token.value)
    if what:
        raise LocatedSyntaxError(f"{what} not supported in decks", token.line, token.column)
    return token


# tokens after which a statement starts (a colon only outside brackets)
_STATEMENT_STARTS = frozenset({"_NEWLINE", "_INDENT", "_DEDENT", "SEMICOLON"})


def _print_statements(tokens):
    """Python 2: a statement starting with the name ``print`` is the print
    statement (its token becomes PRINT2). ``print`` is a keyword there, so no
    lookahead is needed (the token stream is filtered as it goes)."""
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
        raise LocatedSyntaxError(message, token.line, token.column)
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
