"""FORMULE expressions evaluated on arrays: the vectorised back end of
:mod:`asterlite.lang.formula`.

``FORMULE(VALE="...")`` is parsed and checked once by the formula front end
(the deck's parser, one whitelist, one checked tree; nothing is ever passed
to ``eval``). This back end walks that tree with numpy arrays, so a whole
list of abscissas is computed in one pass (CALC_FONC_INTERP over long
instant lists); the names a formula may call and what they compute here are
the ``vector`` column of :mod:`asterlite.lang.numeric`.

code_aster evaluates formulas as Python on Python numbers, so integers keep
Python's semantics here: arithmetic between two Python integers is exact
(``10**19`` is not wrapped to 64 bits), ``/`` between them is Python's true
division, and an integer meeting a float or an array is converted to a
float the way Python converts it (an error when it exceeds the float
range). A conditional expression on a scalar test evaluates only the branch
taken, as Python does.
"""

from __future__ import annotations

import operator
from typing import Any

import numpy as np

from asterlite.errors import DeckRuntimeError
from asterlite.lang import limits as guards
from asterlite.lang import numeric
from asterlite.lang.formula import (
    Binary,
    Call,
    Compare,
    Conditional,
    ExpressionError,
    Logical,
    Name,
    Number,
    Unary,
    parse_formula,
)

__all__ = ["CompiledExpression", "ExpressionError", "MATH_CONSTANTS", "MATH_FUNCTIONS"]

MATH_FUNCTIONS = numeric.VECTOR_FUNCTIONS
MATH_CONSTANTS = numeric.CONSTANTS

_INTEGER_LIMITS = guards.Limits()  # the deck language's bound on integer sizes
_VECTOR_FUNCTION_IDS = frozenset(id(f) for f in MATH_FUNCTIONS.values())


class CompiledExpression:
    """An expression parsed and checked once, evaluated on arrays many times."""

    def __init__(self, text: str):
        self.text = text
        self.tree = parse_formula(text)
        self.names = list(self.tree.names)

    def evaluate(self, namespace: dict[str, Any]) -> Any:
        return self.as_float(self._eval(self.tree.body, namespace))

    def evaluate_node(self, node, namespace: dict[str, Any]) -> Any:
        """One sub-expression with Python's number semantics (integers stay exact)."""
        return self._eval(node, namespace)

    def as_float(self, value: Any) -> Any:
        """A Python integer as the float Python would convert it to; anything else as is."""
        if not _is_python_int(value):
            return value
        try:
            return float(value)
        except OverflowError:
            raise ExpressionError(
                f"formula {self.text!r}: integer too large to convert to a float "
                f"({value.bit_length()} bits)"
            ) from None

    def _integer_binary(self, symbol: str, left: int, right: int) -> Any:
        try:
            guards.check_binary(symbol, left, right, _INTEGER_LIMITS)
            return PYTHON_BINARY[symbol](left, right)
        except DeckRuntimeError as exc:
            raise ExpressionError(f"formula {self.text!r}: {exc.message}") from None
        except (ZeroDivisionError, OverflowError) as exc:
            raise ExpressionError(f"formula {self.text!r}: integer {symbol}: {exc}") from None

    def _binary(self, symbol: str, left: Any, right: Any) -> Any:
        if _is_python_int(left) and _is_python_int(right):
            return self._integer_binary(symbol, left, right)
        function = numeric.BINARY_OPERATORS[symbol][0]
        return function(self.as_float(left), self.as_float(right))

    def _unary(self, symbol: str, operand: Any) -> Any:
        if _is_python_int(operand) and symbol != "not":
            return -operand if symbol == "-" else +operand
        return numeric.UNARY_OPERATORS[symbol][0](self.as_float(operand))

    def _conditional(self, test, body, orelse, ns: dict[str, Any]) -> Any:
        cond = self._eval(test, ns)
        if np.ndim(cond) == 0:  # Python: only the branch taken is evaluated
            return self._eval(body if cond else orelse, ns)
        taken = np.asarray(cond, dtype=bool)
        branches = []
        for branch, used in ((body, taken.any()), (orelse, not taken.all())):
            try:
                branches.append(self.as_float(self._eval(branch, ns)))
            except ExpressionError:
                if used:  # Python would raise at the points taking this branch
                    raise
                branches.append(0.0)
        return np.where(cond, *branches)

    def _call(self, name: str, args: tuple, ns: dict[str, Any]) -> Any:
        func = self._lookup(name, ns)
        values = [self._eval(arg, ns) for arg in args]
        row = numeric.FUNCTIONS.get(name)
        if row is not None and row.integer is not None and func is row.vector and values:
            if all(_is_python_int(v) for v in values):
                if name == "pow" and len(values) == 2:
                    return self._integer_binary("**", *values)
                if name != "pow":
                    return row.integer(*values)
        return call_vectorised(func, [self.as_float(v) for v in values], self.text)

    def _lookup(self, name: str, namespace: dict[str, Any]) -> Any:
        if name in namespace:
            return namespace[name]
        if name in MATH_CONSTANTS:
            return MATH_CONSTANTS[name]
        if name in MATH_FUNCTIONS:
            return MATH_FUNCTIONS[name]
        raise ExpressionError(f"formula {self.text!r}: unknown name {name!r}")

    def _eval(self, node, ns: dict[str, Any]) -> Any:
        match node:
            case Number(value=value):
                return value
            case Name(id=name):
                return self._lookup(name, ns)
            case Binary(op=op, left=left, right=right):
                return self._binary(op, self._eval(left, ns), self._eval(right, ns))
            case Unary(op=op, operand=operand):
                return self._unary(op, self._eval(operand, ns))
            case Compare(left=left, ops=ops, comparators=comparators):
                result, current = True, self._eval(left, ns)
                for op, comp in zip(ops, comparators, strict=True):
                    nxt = self.as_float(self._eval(comp, ns))
                    current = self.as_float(current)
                    compare = numeric.COMPARISONS[op][0]
                    result = np.logical_and(result, compare(current, nxt))
                    current = nxt
                return result
            case Logical(op=op, operands=operands):
                combine = numeric.LOGICAL[op][0]
                result = self._eval(operands[0], ns)
                for value in operands[1:]:
                    result = combine(result, self._eval(value, ns))
                return result
            case Conditional(test=test, body=body, orelse=orelse):
                return self._conditional(test, body, orelse, ns)
            case Call(name=name, args=args):
                return self._call(name, args, ns)
        raise ExpressionError(f"formula {self.text!r}: unsupported construct")  # pragma: no cover


# the operators on two Python integers, as Python computes them
PYTHON_BINARY = {
    "+": operator.add, "-": operator.sub, "*": operator.mul, "/": operator.truediv,
    "**": operator.pow, "%": operator.mod, "//": operator.floordiv,
}  # fmt: skip


def _is_python_int(value: Any) -> bool:
    """A Python integer (bool included, as in Python arithmetic), not a numpy one."""
    return isinstance(value, int)


def call_vectorised(func: Any, args: list, text: str = "") -> Any:
    """Call a function on array arguments: numpy ufuncs and asterlite functions
    directly, anything else (a deck ``def``) once per point."""
    evaluate = getattr(func, "evaluate_many", None)
    if evaluate is not None:
        return evaluate(*args)
    if id(func) in _VECTOR_FUNCTION_IDS:
        return func(*args)
    deck_call = getattr(func, "deck_call", None)
    if deck_call is None and not callable(func):
        raise ExpressionError(f"formula {text!r}: {func!r} is not callable")
    arrays = np.broadcast_arrays(*[np.asarray(a, dtype=float) for a in args])
    if arrays and arrays[0].ndim == 0:
        return _call_scalar(func, [float(a) for a in arrays])
    shape = arrays[0].shape if arrays else ()
    flat = [a.ravel() for a in arrays]
    out = [_call_scalar(func, [float(a[i]) for a in flat]) for i in range(flat[0].size)]
    return np.asarray(out).reshape(shape)


def _call_scalar(func: Any, args: list[float]) -> Any:
    deck_call = getattr(func, "deck_call", None)
    if deck_call is not None:
        from asterlite.lang.values import CallSite

        return deck_call(args, {}, CallSite())
    return func(*args)
