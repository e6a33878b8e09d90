"""The functions and constants a FORMULE may name, each with its numeric
semantics on every back end of :mod:`asterlite.lang.formula`: one table.

A row says what a name computes

- on arrays (``vector``, numpy: the vectorised evaluation of
  :mod:`asterlite.post.expression`, which CALC_FONC_INTERP and every
  post-processing command use),
- inside the compiled time loops (``kernel``: the operation code, per
  number of arguments, that :mod:`asterlite.dynamics.formula` runs; a name
  or an arity without one keeps the formula on the sampled path),
- on Python integers (``integer``: the builtin that keeps them exact, as
  code_aster's Python would; None: the name takes floats).

The deck's own ``math`` module is Python's (:mod:`asterlite.lang.library`):
a deck ``def`` computes as code_aster's Python does; a FORMULE computes on
arrays and then refuses any value that is not finite where Python would
have raised (:class:`asterlite.concepts.function.Formula`).

Adding a function: one row here, and, for the kernels, its code below and
its branch in ``dynamics.formula.unary_function`` or ``binary_function``.
"""

from __future__ import annotations

import math
import operator
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

# Operation codes of the kernel programs (postfix, see dynamics.formula).
# PUSH_CONSTANT takes its value from the constants row at the same position;
# every other code pops its operands and pushes one value. The ranges
# matter: codes below SIN are arithmetic, SIN..RADIANS/SIGN functions of
# one argument, from ATAN2 on functions of two arguments and comparisons.
PUSH_CONSTANT, PUSH_TIME = 0, 1
ADD, SUB, MUL, DIV, POW, MOD, FLOOR_DIV, NEG = 2, 3, 4, 5, 6, 7, 8, 9
SIN, COS, TAN, ASIN, ACOS, ATAN, SINH, COSH, TANH = 10, 11, 12, 13, 14, 15, 16, 17, 18
ASINH, ACOSH, ATANH, EXP, LOG, LOG10, SQRT, ABS = 19, 20, 21, 22, 23, 24, 25, 26
FLOOR, CEIL, TRUNC, DEGREES, RADIANS, SIGN = 27, 28, 29, 30, 31, 32
ATAN2, HYPOT, MINIMUM, MAXIMUM, COPYSIGN = 33, 34, 35, 36, 37
LESS, LESS_EQUAL, GREATER, GREATER_EQUAL, EQUAL, NOT_EQUAL = 38, 39, 40, 41, 42, 43
AND, OR, NOT, SELECT, IDENTITY = 44, 45, 46, 47, 48

# the operators of the formula language: symbol -> (on arrays, kernel code);
# + - * stay Python's operators, which numpy arrays and floats both take
BINARY_OPERATORS: dict[str, tuple[Callable, int]] = {
    "+": (operator.add, ADD), "-": (operator.sub, SUB), "*": (operator.mul, MUL),
    "/": (np.true_divide, DIV), "**": (np.power, POW), "%": (np.mod, MOD),
    "//": (np.floor_divide, FLOOR_DIV),
}  # fmt: skip
UNARY_OPERATORS: dict[str, tuple[Callable, int | None]] = {
    "-": (operator.neg, NEG), "+": (operator.pos, None), "not": (np.logical_not, NOT),
}  # fmt: skip
COMPARISONS: dict[str, tuple[Callable, int]] = {
    "<": (np.less, LESS), "<=": (np.less_equal, LESS_EQUAL), ">": (np.greater, GREATER),
    ">=": (np.greater_equal, GREATER_EQUAL), "==": (np.equal, EQUAL),
    "!=": (np.not_equal, NOT_EQUAL),
}  # fmt: skip
LOGICAL: dict[str, tuple[Callable, int]] = {
    "and": (np.logical_and, AND), "or": (np.logical_or, OR),
}  # fmt: skip


@dataclass(frozen=True)
class NumericFunction:
    """One name a formula may call (see the module's docstring)."""

    vector: Callable
    kernel: dict[int, int] = field(default_factory=dict)  # arity -> operation code
    integer: Callable | None = None
    reduces: bool = False  # min/max: any number of arguments, reduced left to right

    def kernel_code(self, arity: int) -> int | None:
        if self.reduces and arity > 2:
            return self.kernel.get(2)
        return self.kernel.get(arity)


def _elementwise_reduce(func):
    def reduce_args(*args):
        if len(args) == 1:
            return func.reduce(np.asarray(args[0]))
        out = args[0]
        for arg in args[1:]:
            out = func(out, arg)
        return out

    return reduce_args


def _sign(a, b=None):
    # Fortran SIGN(a, b) when two arguments are given, numpy sign otherwise
    if b is None:
        return np.sign(a)
    return np.copysign(np.abs(a), b)


def _unary(vector, code, integer=None) -> NumericFunction:
    return NumericFunction(vector, {1: code}, integer)


FUNCTIONS: dict[str, NumericFunction] = {
    "sin": _unary(np.sin, SIN), "cos": _unary(np.cos, COS), "tan": _unary(np.tan, TAN),
    "asin": _unary(np.arcsin, ASIN), "acos": _unary(np.arccos, ACOS),
    "atan": _unary(np.arctan, ATAN), "atan2": NumericFunction(np.arctan2, {2: ATAN2}),
    "sinh": _unary(np.sinh, SINH), "cosh": _unary(np.cosh, COSH), "tanh": _unary(np.tanh, TANH),
    "asinh": _unary(np.arcsinh, ASINH), "acosh": _unary(np.arccosh, ACOSH),
    "atanh": _unary(np.arctanh, ATANH), "exp": _unary(np.exp, EXP), "log": _unary(np.log, LOG),
    "log10": _unary(np.log10, LOG10), "sqrt": _unary(np.sqrt, SQRT),
    "abs": _unary(np.abs, ABS, abs), "fabs": _unary(np.abs, ABS),
    "floor": _unary(np.floor, FLOOR), "ceil": _unary(np.ceil, CEIL),
    "pow": NumericFunction(np.power, {2: POW}, pow), "hypot": NumericFunction(np.hypot, {2: HYPOT}),
    "degrees": _unary(np.degrees, DEGREES), "radians": _unary(np.radians, RADIANS),
    "min": NumericFunction(_elementwise_reduce(np.minimum), {2: MINIMUM}, min, reduces=True),
    "max": NumericFunction(_elementwise_reduce(np.maximum), {2: MAXIMUM}, max, reduces=True),
    "sign": NumericFunction(_sign, {1: SIGN, 2: COPYSIGN}),
    "heaviside": NumericFunction(lambda x, h0=1.0: np.heaviside(x, h0)),
    "float": _unary(lambda x: np.asarray(x, dtype=float), IDENTITY), "int": _unary(np.trunc, TRUNC),
}  # fmt: skip

CONSTANTS: dict[str, float] = {"pi": math.pi, "e": math.e, "inf": math.inf}

# the numpy callables of the table, by identity (a FORMULE's own function
# may shadow a name: only these are called as ufuncs)
VECTOR_FUNCTIONS: dict[str, Callable] = {name: row.vector for name, row in FUNCTIONS.items()}
