"""The front end of FORMULE expressions: the deck's parser, one whitelist,
one checked tree.

A ``FORMULE(VALE="...")`` text is parsed by the deck language's own parser
(:func:`asterlite.lang.parser.parse_expression`: the same grammar, literal
decoding and name checks as a deck line) and its expression is checked
against the formula subset: numbers, names, ``+ - * / // % **``, unary
``- + not``, comparisons ``< <= > >= == !=``, ``and``/``or``, conditional
expressions, and calls ``f(x, y)`` of a name with positional arguments.
What passes becomes a small immutable tree (:class:`Number`, :class:`Name`,
:class:`Binary`...) with binary operations nested left to right, as Python
evaluates them. Each back end reads that tree and nothing else:

- on arrays, numpy-vectorised: :mod:`asterlite.post.expression`
  (CALC_FONC_INTERP, tables, fields, every post-processing command);
- as a postfix program run inside the compiled time loops:
  :mod:`asterlite.dynamics.formula` (FORMULE loads of DYNA_VIBRA).

Deck ``def`` functions run on the deck's own checked tree, interpreted by
:mod:`asterlite.lang.evaluator` or compiled by :mod:`asterlite.lang.compiler`;
a formula calling one goes through its ``deck_call``. The names a formula
may call and what they compute on each back end are one table,
:mod:`asterlite.lang.numeric`; the size guards on integer arithmetic are
those of the deck (:mod:`asterlite.lang.limits`), and so is the nesting
bound (``Limits.max_tree_depth``).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

from asterlite.errors import CommandError, DeckSyntaxError
from asterlite.lang.limits import Limits
from asterlite.lang.numeric import BINARY_OPERATORS, COMPARISONS
from asterlite.lang.parser import parse_expression

LIMITS = Limits()


class ExpressionError(CommandError):
    """A formula uses a construct outside the whitelist or an unknown name."""


@dataclass(frozen=True, slots=True)
class Number:
    value: int | float | complex | bool


@dataclass(frozen=True, slots=True)
class Name:
    id: str


@dataclass(frozen=True, slots=True)
class Binary:
    op: str  # a key of numeric.BINARY_OPERATORS
    left: object
    right: object


@dataclass(frozen=True, slots=True)
class Unary:
    op: str  # "-", "+" or "not"
    operand: object


@dataclass(frozen=True, slots=True)
class Compare:
    left: object
    ops: tuple[str, ...]  # keys of numeric.COMPARISONS
    comparators: tuple


@dataclass(frozen=True, slots=True)
class Logical:
    op: str  # "and" or "or"
    operands: tuple


@dataclass(frozen=True, slots=True)
class Conditional:
    test: object
    body: object
    orelse: object


@dataclass(frozen=True, slots=True)
class Call:
    name: str
    args: tuple


ARITHMETIC = (Binary, Unary)  # the nodes constant folding may replace


@dataclass(frozen=True)
class FormulaTree:
    """A formula's text, checked: ``body`` is its expression, ``names``
    the names it reads (not those it only calls), ``called`` those it calls."""

    text: str
    body: object
    names: tuple[str, ...]
    called: tuple[str, ...]

    def walk(self):
        return walk(self.body)


def walk(node):
    """Every node of a subtree, depth first (iteratively: no recursion limit)."""
    pending = [node]
    while pending:
        current = pending.pop()
        yield current
        pending.extend(reversed(children(current)))


def depth(node) -> int:
    """Levels of a subtree (a leaf is 1), computed without recursion."""
    deepest, pending = 0, [(node, 1)]
    while pending:
        current, level = pending.pop()
        deepest = max(deepest, level)
        pending.extend((child, level + 1) for child in children(current))
    return deepest


def children(node) -> tuple:
    match node:
        case Binary(left=left, right=right):
            return (left, right)
        case Unary(operand=operand):
            return (operand,)
        case Compare(left=left, comparators=comparators):
            return (left, *comparators)
        case Logical(operands=operands):
            return operands
        case Conditional(test=test, body=body, orelse=orelse):
            return (test, body, orelse)
        case Call(args=args):
            return args
    return ()


@functools.lru_cache(maxsize=256)
def parse_formula(text: str) -> FormulaTree:
    """The checked tree of a FORMULE text (immutable, so shared between the
    formulas of a run that have the same text); ExpressionError when the
    text does not parse or leaves the formula subset."""
    # code_aster joins the lines of a VALE given over several lines
    source = " ".join(line.strip() for line in text.strip().splitlines())
    try:
        module = parse_expression(source, "FORMULE", remember=False)
    except DeckSyntaxError as error:
        if "nested too deeply" in error.message:
            raise _too_deep(text) from None
        where = ""
        if "\n" not in text.strip() and error.location is not None:  # columns of the text itself
            column = error.location.column + len(text) - len(text.lstrip())
            where = f" at column {column}"
        raise ExpressionError(f"formula {text!r} does not parse{where}: {error.message}") from None
    except (MemoryError, RecursionError):
        raise _too_deep(text) from None
    try:
        body = _Lowering(text).lower(module.tree.children[0], 0)
    except RecursionError:
        raise _too_deep(text) from None
    if depth(body) > LIMITS.max_tree_depth:  # the back ends recurse on the tree
        raise _too_deep(text)
    nodes = list(walk(body))
    called = {node.name for node in nodes if isinstance(node, Call)}
    names = {node.id for node in nodes if isinstance(node, Name)} - called
    return FormulaTree(text, body, tuple(sorted(names)), tuple(sorted(called)))


def _too_deep(text: str) -> ExpressionError:
    shown = text if len(text) <= 80 else text[:77] + "..."
    return ExpressionError(f"formula {shown!r} is nested too deeply to parse")


# what the deck grammar's nodes outside the subset are, in messages
_DESCRIPTIONS = {
    "getattr": "an attribute", "getitem": "an index", "tuple": "a tuple", "list": "a list",
    "dict": "a dict", "set": "a set", "listcomp": "a comprehension",
    "dictcomp": "a comprehension", "lambdef": "a lambda", "strings": "a string",
    "fstring": "an f-string", "or_expr": "'|'", "xor_expr": "'^'", "and_expr": "'&'",
    "backquote": "a backquote",
}  # fmt: skip


class _Lowering:
    """The deck parser's checked tree of one expression to a formula tree."""

    def __init__(self, text: str):
        self.text = text

    def refuse(self, what: str) -> ExpressionError:
        return ExpressionError(f"formula {self.text!r}: {what} is not allowed in a FORMULE")

    def lower(self, node, depth: int):
        if depth > LIMITS.max_tree_depth:
            raise RecursionError
        kind = node.data
        lower = getattr(self, f"_{kind}", None)
        if lower is None:
            raise self.refuse(_DESCRIPTIONS.get(kind, kind))
        return lower(node, depth + 1)

    def _const(self, node, depth):
        value = node.children[0]
        if not isinstance(value, int | float | complex):
            raise ExpressionError(f"formula {self.text!r}: constant {value!r} is not a number")
        return Number(value)

    def _const_true(self, node, depth):
        return Number(True)

    def _const_false(self, node, depth):
        return Number(False)

    def _const_none(self, node, depth):
        raise ExpressionError(f"formula {self.text!r}: constant None is not a number")

    def _var(self, node, depth):
        return Name(node.children[0].value)

    def _chain(self, node, depth):
        """arith_expr / term: operand (op operand)*, nested left to right."""
        items = node.children
        value = self.lower(items[0], depth)
        for position in range(1, len(items), 2):
            op = items[position].value
            if op not in BINARY_OPERATORS:  # '/2', Python 2's division: never parsed here
                raise self.refuse(repr(op))
            value = Binary(op, value, self.lower(items[position + 1], depth))
        return value

    _arith_expr = _term = _chain

    def _power(self, node, depth):
        base, exponent = node.children
        return Binary("**", self.lower(base, depth), self.lower(exponent, depth))

    def _unary(self, node, depth):
        op, operand = node.children
        if op.value == "~":
            raise self.refuse("'~'")
        return Unary(op.value, self.lower(operand, depth))

    def _not_(self, node, depth):
        return Unary("not", self.lower(node.children[0], depth))

    def _comparison(self, node, depth):
        items = node.children
        ops = []
        for position in range(1, len(items), 2):
            op = "".join(token.value for token in items[position].children)
            if op not in COMPARISONS:
                raise self.refuse(repr(op))
            ops.append(op)
        operands = [self.lower(items[i], depth) for i in range(0, len(items), 2)]
        return Compare(operands[0], tuple(ops), tuple(operands[1:]))

    def _logical(self, op: str):
        def lower(node, depth):
            return Logical(op, tuple(self.lower(child, depth) for child in node.children))

        return lower

    def _and_test(self, node, depth):
        return self._logical("and")(node, depth)

    def _or_test(self, node, depth):
        return self._logical("or")(node, depth)

    def _ternary(self, node, depth):
        body, test, orelse = node.children
        return Conditional(
            self.lower(test, depth), self.lower(body, depth), self.lower(orelse, depth)
        )

    def _funccall(self, node, depth):
        callee, arguments = node.children
        plain = arguments is None or (
            arguments.data == "arguments"
            and all(arg.data not in _NOT_POSITIONAL for arg in arguments.children)
        )
        if callee.data != "var" or not plain:
            raise ExpressionError(
                f"formula {self.text!r}: only calls like f(x, y) of named functions are allowed"
            )
        args = () if arguments is None else arguments.children
        return Call(callee.children[0].value, tuple(self.lower(arg, depth) for arg in args))


_NOT_POSITIONAL = frozenset({"kwarg", "star_arg", "double_star_arg"})
