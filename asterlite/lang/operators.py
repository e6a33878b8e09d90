"""The operators of the deck language as Python callables, shared by the
tree-walking evaluator and the code the compiler generates (one table, so
both give the same result and the same errors)."""

from __future__ import annotations

import operator

from asterlite.lang.python2 import classic_divide, classic_divide_inplace

# Python exceptions an operation or a whitelisted callable may raise on bad
# deck input; they become located DeckRuntimeErrors.
CONVERTED_ERRORS = (
    ArithmeticError,
    LookupError,
    ValueError,
    TypeError,
    AttributeError,
    MemoryError,
)

BINARY_OPERATORS = {
    "+": operator.add,
    "-": operator.sub,
    "*": operator.mul,
    "/": operator.truediv,
    "//": operator.floordiv,
    "%": operator.mod,
    "**": operator.pow,
    "|": operator.or_,
    "^": operator.xor,
    "&": operator.and_,
    "/2": classic_divide,  # Python 2's '/' (the parser marks it so in Python 2 decks)
}
INPLACE_OPERATORS = {
    "+=": ("+", operator.iadd),
    "-=": ("-", operator.isub),
    "*=": ("*", operator.imul),
    "/=": ("/", operator.itruediv),
    "//=": ("//", operator.ifloordiv),
    "%=": ("%", operator.imod),
    "**=": ("**", operator.ipow),
    "/2=": ("/2", classic_divide_inplace),
}
COMPARISONS = {
    "<": operator.lt,
    ">": operator.gt,
    "==": operator.eq,
    ">=": operator.ge,
    "<=": operator.le,
    "!=": operator.ne,
    "<>": operator.ne,  # Python 2
    "in": lambda a, b: a in b,
    "notin": lambda a, b: a not in b,
    "is": operator.is_,
    "isnot": operator.is_not,
}
UNARY_OPERATORS = {"-": operator.neg, "+": operator.pos, "~": operator.invert}
