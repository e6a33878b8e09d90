"""A small, safe, vectorised compiler for FORMULE expressions.

``FORMULE(VALE="...")`` holds a Python-looking arithmetic expression. It is
parsed once with :mod:`ast` and checked against a whitelist (numbers, names,
arithmetic, comparisons, conditional expressions, calls of whitelisted math
functions and of functions the deck handed over); nothing is ever passed to
``eval``. Evaluation walks the tree with numpy arrays, so a whole list of
abscissas is computed in one pass.

This compiler is independent of the deck evaluator (``asterlite.lang``): a
formula's text is a tiny language of its own, and vectorising it matters for
CALC_FONC_INTERP over long instant lists.

code_aster evaluates formulas as Python on Python numbers, so integers keep
Python's semantics here: arithmetic between two Python integers is exact
(``10**19`` is not wrapped to 64 bits), ``/`` between them is Python's true
division, and an integer meeting a float or an array is converted to a
float the way Python converts it (an error when it exceeds the float
range). A conditional expression on a scalar test evaluates only the branch
taken, as Python does.
"""

from __future__ import annotations

import ast
import math
import operator
from collections.abc import Callable
from typing import Any

import numpy as np

from asterlite.errors import CommandError, DeckRuntimeError
from asterlite.lang import limits as guards


class ExpressionError(CommandError):
    """A formula uses a construct outside the whitelist or an unknown name."""


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


MATH_FUNCTIONS: dict[str, Callable] = {
    "sin": np.sin, "cos": np.cos, "tan": np.tan,
    "asin": np.arcsin, "acos": np.arccos, "atan": np.arctan, "atan2": np.arctan2,
    "sinh": np.sinh, "cosh": np.cosh, "tanh": np.tanh,
    "asinh": np.arcsinh, "acosh": np.arccosh, "atanh": np.arctanh,
    "exp": np.exp, "log": np.log, "log10": np.log10, "sqrt": np.sqrt,
    "abs": np.abs, "fabs": np.abs, "floor": np.floor, "ceil": np.ceil,
    "pow": np.power, "hypot": np.hypot, "degrees": np.degrees, "radians": np.radians,
    "min": _elementwise_reduce(np.minimum), "max": _elementwise_reduce(np.maximum),
    "sign": _sign, "heaviside": lambda x, h0=1.0: np.heaviside(x, h0),
    "float": lambda x: np.asarray(x, dtype=float), "int": np.trunc,
}  # fmt: skip

MATH_CONSTANTS = {"pi": math.pi, "e": math.e, "inf": math.inf}

_BINARY = {
    ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
    ast.Div: np.true_divide, ast.Pow: np.power, ast.Mod: np.mod,
    ast.FloorDiv: np.floor_divide,
}  # fmt: skip
_UNARY = {ast.USub: operator.neg, ast.UAdd: operator.pos, ast.Not: np.logical_not}
_COMPARE = {
    ast.Lt: np.less, ast.LtE: np.less_equal, ast.Gt: np.greater,
    ast.GtE: np.greater_equal, ast.Eq: np.equal, ast.NotEq: np.not_equal,
}  # fmt: skip
# the same operators on two Python integers, as Python computes them
_PYTHON_BINARY = {
    ast.Add: ("+", operator.add), ast.Sub: ("-", operator.sub), ast.Mult: ("*", operator.mul),
    ast.Div: ("/", operator.truediv), ast.Pow: ("**", operator.pow),
    ast.Mod: ("%", operator.mod), ast.FloorDiv: ("//", operator.floordiv),
}  # fmt: skip
_INTEGER_LIMITS = guards.Limits()  # the deck language's bound on integer sizes
# builtins that keep Python integers integers (the math functions take floats)
_PYTHON_INTEGER_FUNCTIONS = {"abs": abs, "min": min, "max": max, "pow": pow}
_ALLOWED = (
    ast.Expression, ast.BinOp, ast.UnaryOp, ast.Compare, ast.BoolOp, ast.IfExp,
    ast.Call, ast.Name, ast.Constant, ast.Load, ast.And, ast.Or,
    *_BINARY, *_UNARY, *_COMPARE,
)  # fmt: skip


class CompiledExpression:
    """An expression parsed and checked once, evaluated on arrays many times."""

    def __init__(self, text: str):
        self.text = text
        source = " ".join(line.strip() for line in text.strip().splitlines())
        try:
            self.tree = ast.parse(source, mode="eval")
        except SyntaxError as exc:
            raise ExpressionError(f"formula {text!r} does not parse: {exc.msg}") from None
        except (MemoryError, RecursionError):  # Python's parser on very deep nesting
            shown = text if len(text) <= 80 else text[:77] + "..."
            raise ExpressionError(f"formula {shown!r} is nested too deeply to parse") from None
        for node in ast.walk(self.tree):
            if not isinstance(node, _ALLOWED):
                raise ExpressionError(
                    f"formula {text!r}: {type(node).__name__} is not allowed in a FORMULE"
                )
            if isinstance(node, ast.Call):
                if not isinstance(node.func, ast.Name) or node.keywords:
                    raise ExpressionError(
                        f"formula {text!r}: only calls like f(x, y) of named functions are allowed"
                    )
            if isinstance(node, ast.Constant) and not isinstance(node.value, int | float | complex):
                raise ExpressionError(f"formula {text!r}: constant {node.value!r} is not a number")
        self.names = sorted(
            {n.id for n in ast.walk(self.tree) if isinstance(n, ast.Name)}
            - {
                n.func.id
                for n in ast.walk(self.tree)
                if isinstance(n, ast.Call) and isinstance(n.func, ast.Name)
            }
        )

    def evaluate(self, namespace: dict[str, Any]) -> Any:
        return self.as_float(self._eval(self.tree.body, namespace))

    def evaluate_node(self, node: ast.AST, namespace: dict[str, Any]) -> Any:
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

    def _integer_binary(self, op: ast.operator, left: int, right: int) -> Any:
        symbol, function = _PYTHON_BINARY[type(op)]
        try:
            guards.check_binary(symbol, left, right, _INTEGER_LIMITS)
            return function(left, right)
        except DeckRuntimeError as exc:
            raise ExpressionError(f"formula {self.text!r}: {exc.message}") from None
        except (ZeroDivisionError, OverflowError) as exc:
            raise ExpressionError(f"formula {self.text!r}: integer {symbol}: {exc}") from None

    def _binary(self, op: ast.operator, left: Any, right: Any) -> Any:
        if _is_python_int(left) and _is_python_int(right):
            return self._integer_binary(op, left, right)
        return _BINARY[type(op)](self.as_float(left), self.as_float(right))

    def _unary(self, op: ast.unaryop, operand: Any) -> Any:
        if _is_python_int(operand) and not isinstance(op, ast.Not):
            return -operand if isinstance(op, ast.USub) else +operand
        return _UNARY[type(op)](self.as_float(operand))

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

    def _call(self, name: str, args: list, ns: dict[str, Any]) -> Any:
        func = self._lookup(name, ns)
        values = [self._eval(arg, ns) for arg in args]
        integer_function = _PYTHON_INTEGER_FUNCTIONS.get(name)
        if func is MATH_FUNCTIONS.get(name) and integer_function and values:
            if all(_is_python_int(v) for v in values):
                if name == "pow" and len(values) == 2:
                    return self._integer_binary(ast.Pow(), *values)
                if name != "pow":
                    return integer_function(*values)
        return call_vectorised(func, [self.as_float(v) for v in values], self.text)

    def _lookup(self, name: str, namespace: dict[str, Any]) -> Any:
        if name in namespace:
            return namespace[name]
        if name in MATH_CONSTANTS:
            return MATH_CONSTANTS[name]
        if name in MATH_FUNCTIONS:
            return MATH_FUNCTIONS[name]
        raise ExpressionError(f"formula {self.text!r}: unknown name {name!r}")

    def _eval(self, node: ast.AST, ns: dict[str, Any]) -> Any:
        match node:
            case ast.Constant(value=value):
                return value
            case ast.Name(id=name):
                return self._lookup(name, ns)
            case ast.BinOp(left=left, op=op, right=right):
                return self._binary(op, self._eval(left, ns), self._eval(right, ns))
            case ast.UnaryOp(op=op, operand=operand):
                return self._unary(op, self._eval(operand, ns))
            case ast.Compare(left=left, ops=ops, comparators=comparators):
                result, current = True, self._eval(left, ns)
                for op, comp in zip(ops, comparators, strict=True):
                    nxt = self.as_float(self._eval(comp, ns))
                    current = self.as_float(current)
                    result = np.logical_and(result, _COMPARE[type(op)](current, nxt))
                    current = nxt
                return result
            case ast.BoolOp(op=op, values=values):
                combine = np.logical_and if isinstance(op, ast.And) else np.logical_or
                result = self._eval(values[0], ns)
                for value in values[1:]:
                    result = combine(result, self._eval(value, ns))
                return result
            case ast.IfExp(test=test, body=body, orelse=orelse):
                return self._conditional(test, body, orelse, ns)
            case ast.Call(func=ast.Name(id=name), args=args):
                return self._call(name, args, ns)
        raise ExpressionError(f"formula {self.text!r}: unsupported construct")  # pragma: no cover


def _is_python_int(value: Any) -> bool:
    """A Python integer (bool included, as in Python arithmetic), not a numpy one."""
    return isinstance(value, int)


def call_vectorised(func: Any, args: list, text: str = "") -> Any:
    """Call a function on array arguments: numpy ufuncs and asterlite functions
    directly, anything else (a deck ``def``) once per point."""
    evaluate = getattr(func, "evaluate_many", None)
    if evaluate is not None:
        return evaluate(*args)
    if func in MATH_FUNCTIONS.values():
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
