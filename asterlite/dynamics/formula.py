"""FORMULE load multipliers evaluated inside the compiled time loops.

A ``FORMULE`` of one parameter (``NOM_PARA='INST'``) whose expression uses
only numbers, the parameter, numeric extra values, arithmetic, comparisons,
conditional expressions and the math functions of
:mod:`asterlite.post.expression` is translated once into a small postfix
program (operation codes and constants, plain arrays), which the kernels
run at the exact instants the scheme needs: no tabulation, no
interpolation, nothing that grows with the run. Anything else (a formula
calling another function, a deck ``def``, a complex result) keeps the
sampled path of :mod:`asterlite.dynamics.model`.

The program follows the vectorised evaluation of
:class:`asterlite.concepts.function.Formula` (numpy's semantics: division
by zero gives inf or nan, comparisons give 1.0/0.0), with the C library's
math functions where numpy may use its own vectorised ones (a last-bit
difference at most). Arithmetic that does not involve the parameter is
folded once by that evaluation, with Python's exact integers, as code_aster
computes it (``(2**53 + 1) - 2**53`` is 1, not the 0.0 of float steps); a
folded or literal integer that no float holds exactly, a folded value that
is not finite, or one that raises leaves the formula to the sampled path,
which reports it.
"""

from __future__ import annotations

import ast
import copy
import math
import numbers

import numpy as np
from numba import njit

from asterlite.errors import CommandError

# Operation codes. PUSH_CONSTANT takes its value from the constants row at
# the same position; every other code pops its operands and pushes one value.
PUSH_CONSTANT, PUSH_TIME = 0, 1
ADD, SUB, MUL, DIV, POW, MOD, FLOOR_DIV, NEG = 2, 3, 4, 5, 6, 7, 8, 9
SIN, COS, TAN, ASIN, ACOS, ATAN, SINH, COSH, TANH = 10, 11, 12, 13, 14, 15, 16, 17, 18
ASINH, ACOSH, ATANH, EXP, LOG, LOG10, SQRT, ABS = 19, 20, 21, 22, 23, 24, 25, 26
FLOOR, CEIL, TRUNC, DEGREES, RADIANS, SIGN = 27, 28, 29, 30, 31, 32
ATAN2, HYPOT, MINIMUM, MAXIMUM, COPYSIGN = 33, 34, 35, 36, 37
LESS, LESS_EQUAL, GREATER, GREATER_EQUAL, EQUAL, NOT_EQUAL = 38, 39, 40, 41, 42, 43
AND, OR, NOT, SELECT, IDENTITY = 44, 45, 46, 47, 48

STACK_DEPTH = 32  # deepest expression accepted (operands pending at once)

UNARY_FUNCTIONS = {
    "sin": SIN, "cos": COS, "tan": TAN, "asin": ASIN, "acos": ACOS, "atan": ATAN,
    "sinh": SINH, "cosh": COSH, "tanh": TANH, "asinh": ASINH, "acosh": ACOSH,
    "atanh": ATANH, "exp": EXP, "log": LOG, "log10": LOG10, "sqrt": SQRT,
    "abs": ABS, "fabs": ABS, "floor": FLOOR, "ceil": CEIL, "int": TRUNC,
    "degrees": DEGREES, "radians": RADIANS, "sign": SIGN, "float": IDENTITY,
}  # fmt: skip
BINARY_FUNCTIONS = {
    "atan2": ATAN2, "hypot": HYPOT, "pow": POW, "min": MINIMUM, "max": MAXIMUM,
    "sign": COPYSIGN,
}  # fmt: skip
BINARY_OPERATORS = {
    ast.Add: ADD, ast.Sub: SUB, ast.Mult: MUL, ast.Div: DIV, ast.Pow: POW,
    ast.Mod: MOD, ast.FloorDiv: FLOOR_DIV,
}  # fmt: skip
COMPARISONS = {
    ast.Lt: LESS, ast.LtE: LESS_EQUAL, ast.Gt: GREATER, ast.GtE: GREATER_EQUAL,
    ast.Eq: EQUAL, ast.NotEq: NOT_EQUAL,
}  # fmt: skip


class NotCompilable(Exception):
    """The formula uses something the kernel programs do not offer."""


def formula_program(mult) -> tuple[list[int], list[float]] | None:
    """(codes, constants) of a one-parameter real FORMULE, or None when it
    cannot run in the kernels (then it is sampled)."""
    compiled = getattr(mult, "compiled", None)
    parameters = tuple(getattr(mult, "NOM_PARA", ()) or ())
    if compiled is None or len(parameters) != 1 or getattr(mult, "complex_result", False):
        return None
    from asterlite.post.expression import MATH_CONSTANTS

    constants = dict(MATH_CONSTANTS)
    extra = getattr(mult, "extra", None) or {}
    for name in extra:
        constants.pop(name, None)  # an extra value shadows a math constant
    for name, value in extra.items():
        if isinstance(value, int) and not isinstance(value, bool):
            constants[name] = value  # kept exact for folding, as Python would
        elif isinstance(value, numbers.Real) and not isinstance(value, bool):
            constants[name] = float(value)
        elif isinstance(value, np.ndarray) and value.ndim == 0 and np.isrealobj(value):
            constants[name] = float(value)
    codes: list[int] = []
    values: list[float] = []
    try:
        shadowed = set(extra) | {parameters[0]}
        body = fold_constants(compiled, parameters[0], constants)
        depth = emit(body, parameters[0], constants, shadowed, codes, values, 0)
    except (NotCompilable, RecursionError):
        return None
    if depth > STACK_DEPTH:
        return None
    return codes, values


_FOLDABLE = (ast.BinOp, ast.UnaryOp, ast.Constant, ast.Name, ast.operator, ast.unaryop, ast.Load)


def fold_constants(compiled, parameter: str, constants: dict):
    """The expression tree with each largest arithmetic subtree free of the
    parameter (numbers, numeric extra values, math constants, + - * / ** %
    //) replaced by its value, computed by the formula's own evaluator."""

    def foldable(node) -> bool:
        return all(
            isinstance(n, _FOLDABLE)
            and not (isinstance(n, ast.Name) and (n.id == parameter or n.id not in constants))
            for n in ast.walk(node)
        )

    class Folder(ast.NodeTransformer):
        def visit(self, node):
            if isinstance(node, (ast.BinOp, ast.UnaryOp)) and foldable(node):
                return ast.Constant(value=folded_value(compiled, node, constants))
            return super().visit(node)

    return Folder().visit(copy.deepcopy(compiled.tree.body))


def folded_value(compiled, node, constants: dict) -> float:
    """The value of a parameter-free subtree as the kernels can hold it."""
    try:
        with np.errstate(all="ignore"):
            value = compiled.evaluate_node(node, constants)
    except (ArithmeticError, ValueError, CommandError) as exc:  # e.g. an integer overflow
        raise NotCompilable(str(exc)) from None
    if isinstance(value, (bool, np.bool_)):  # a folded 'not': 1 or 0 in arithmetic
        return float(value)
    if not isinstance(value, numbers.Real):
        raise NotCompilable(repr(value))
    if isinstance(value, int):
        return value  # left exact: emit converts it as Python would, where it is used
    if not math.isfinite(value):  # numpy's inf or nan where Python raises (1.0/0.0)
        raise NotCompilable(repr(value))
    return float(value)


def kernel_float(value) -> float:
    """A number as the float Python converts it to when it meets a float."""
    try:
        return float(value)
    except OverflowError:  # Python raises too: the sampled path reports it
        raise NotCompilable(f"integer of {value.bit_length()} bits") from None


def exact_operand(node, constants: dict) -> None:
    """Python compares an integer with a float exactly: refuse an integer
    operand that no float holds (beyond 2**53), which the kernels would round."""
    value = None
    if isinstance(node, ast.Constant):
        value = node.value
    elif isinstance(node, ast.Name):
        value = constants.get(node.id)
    if isinstance(value, int) and not isinstance(value, bool):
        if kernel_float(value) != value:
            raise NotCompilable(f"integer {value.bit_length()} bits wide in a comparison")


def emit(node, parameter, constants, shadowed, codes, values, depth: int) -> int:
    """Append the postfix code of ``node``; returns the deepest stack use.
    ``shadowed``: names that are not the math functions (extra values)."""

    def op(code: int, value: float = 0.0) -> None:
        codes.append(code)
        values.append(value)

    def sub(child, extra_depth: int) -> int:
        return emit(child, parameter, constants, shadowed, codes, values, depth + extra_depth)

    match node:
        case ast.Constant(value=value) if isinstance(value, int | float) and not isinstance(
            value, bool
        ):
            op(PUSH_CONSTANT, kernel_float(value))
            return depth + 1
        case ast.Name(id=name):
            if name == parameter:
                op(PUSH_TIME)
            elif name in constants:
                op(PUSH_CONSTANT, kernel_float(constants[name]))
            else:
                raise NotCompilable(name)
            return depth + 1
        case ast.BinOp(left=left, op=operator, right=right) if type(operator) in BINARY_OPERATORS:
            deepest = max(sub(left, 0), sub(right, 1))
            op(BINARY_OPERATORS[type(operator)])
            return deepest
        case ast.UnaryOp(op=ast.USub(), operand=operand):
            deepest = sub(operand, 0)
            op(NEG)
            return deepest
        case ast.UnaryOp(op=ast.UAdd(), operand=operand):
            return sub(operand, 0)
        case ast.UnaryOp(op=ast.Not(), operand=operand):
            deepest = sub(operand, 0)
            op(NOT)
            return deepest
        case ast.Compare(left=left, ops=[comparison], comparators=[right]) if (
            type(comparison) in COMPARISONS
        ):
            exact_operand(left, constants)
            exact_operand(right, constants)
            deepest = max(sub(left, 0), sub(right, 1))
            op(COMPARISONS[type(comparison)])
            return deepest
        case ast.BoolOp(op=operator, values=operands):
            code = AND if isinstance(operator, ast.And) else OR
            deepest = sub(operands[0], 0)
            for operand in operands[1:]:
                deepest = max(deepest, sub(operand, 1))
                op(code)
            return deepest
        case ast.IfExp(test=test, body=body, orelse=orelse):
            deepest = max(sub(test, 0), sub(body, 1), sub(orelse, 2))
            op(SELECT)
            return deepest
        case ast.Call(func=ast.Name(id=name), args=args, keywords=[]) if name not in shadowed:
            if len(args) == 1 and name in UNARY_FUNCTIONS:
                deepest = sub(args[0], 0)
                op(UNARY_FUNCTIONS[name])
                return deepest
            if len(args) == 2 and name in BINARY_FUNCTIONS:
                deepest = max(sub(args[0], 0), sub(args[1], 1))
                op(BINARY_FUNCTIONS[name])
                return deepest
            if len(args) > 2 and name in ("min", "max"):  # reduce left to right
                code = MINIMUM if name == "min" else MAXIMUM
                deepest = sub(args[0], 0)
                for arg in args[1:]:
                    deepest = max(deepest, sub(arg, 1))
                    op(code)
                return deepest
    raise NotCompilable(ast.dump(node))


def program_tables(programs) -> tuple[np.ndarray, np.ndarray]:
    """Pack one program per row (None: the row has none) into (codes,
    constants) arrays; ``codes[row, 0]`` is the program's length."""
    width = 1 + max([0] + [len(p[0]) for p in programs if p is not None])
    codes = np.zeros((len(programs), width), dtype=np.int64)
    constants = np.zeros((len(programs), width))
    for row, program in enumerate(programs):
        if program is None:
            continue
        ops, values = program
        codes[row, 0] = len(ops)
        codes[row, 1 : 1 + len(ops)] = ops
        constants[row, 1 : 1 + len(ops)] = values
    return codes, constants


@njit(cache=True, inline="always")
def true_divide(a, b):
    """a / b with numpy's semantics (inf or nan for b == 0, no exception)."""
    if b != 0.0:
        return a / b
    if a != a or a == 0.0:
        return math.nan
    return math.copysign(math.inf, a) * math.copysign(1.0, b)


@njit(cache=True, inline="always")
def run_program(codes, constants, row, t, stack):
    """Value of row ``row``'s program at time t; ``stack``: STACK_DEPTH scratch."""
    top = -1
    for pc in range(1, codes[row, 0] + 1):
        code = codes[row, pc]
        if code == PUSH_TIME:
            top += 1
            stack[top] = t
        elif code == PUSH_CONSTANT:
            top += 1
            stack[top] = constants[row, pc]
        elif code < SIN:  # arithmetic
            if code == NEG:
                stack[top] = -stack[top]
                continue
            b = stack[top]
            top -= 1
            a = stack[top]
            if code == ADD:
                stack[top] = a + b
            elif code == SUB:
                stack[top] = a - b
            elif code == MUL:
                stack[top] = a * b
            elif code == DIV:
                stack[top] = true_divide(a, b)
            elif code == POW:
                stack[top] = math.pow(a, b)
            elif code == MOD:
                stack[top] = remainder(a, b)
            else:  # FLOOR_DIV
                stack[top] = (a - remainder(a, b)) / b if b != 0.0 else true_divide(a, b)
        elif code < ATAN2:  # functions of one argument
            stack[top] = unary_function(code, stack[top])
        elif code == SELECT:
            otherwise = stack[top]
            chosen = stack[top - 1]
            top -= 2
            stack[top] = chosen if stack[top] != 0.0 else otherwise
        elif code == NOT:
            stack[top] = 1.0 if stack[top] == 0.0 else 0.0
        elif code == IDENTITY:
            pass
        else:  # functions of two arguments, comparisons, logic
            b = stack[top]
            top -= 1
            stack[top] = binary_function(code, stack[top], b)
    return stack[0]


@njit(cache=True, inline="always")
def program_value(codes, constants, row, t, stack):
    """:func:`run_program` with the top of the stack kept in a local
    variable (``stack`` holds only the operands below it) and the codes a
    load formula is made of (numbers, the parameter, ``*``, ``+``, ``sin``,
    ``cos``) tested first: the same operations on the same operands in the
    same order, so the same value to the last bit, with fewer loads and
    stores per code (the specialised DIFF_CENTRE loop runs each FORMULE
    load at every step)."""
    top = -1  # stack depth - 1; the value at that depth is ``x``
    x = 0.0
    for pc in range(1, codes[row, 0] + 1):
        code = codes[row, pc]
        if code == PUSH_CONSTANT or code == PUSH_TIME:
            if top >= 0:
                stack[top] = x
            top += 1
            x = t if code == PUSH_TIME else constants[row, pc]
        elif code == SIN:
            x = math.sin(x)
        elif code == COS:
            x = math.cos(x)
        elif code < SIN:  # arithmetic
            if code == NEG:
                x = -x
                continue
            top -= 1
            a = stack[top]
            if code == MUL:
                x = a * x
            elif code == ADD:
                x = a + x
            elif code == SUB:
                x = a - x
            elif code == DIV:
                x = true_divide(a, x)
            elif code == POW:
                x = math.pow(a, x)
            elif code == MOD:
                x = remainder(a, x)
            else:  # FLOOR_DIV
                x = (a - remainder(a, x)) / x if x != 0.0 else true_divide(a, x)
        elif code < ATAN2:  # the other functions of one argument
            x = unary_function(code, x)
        elif code == SELECT:  # condition, chosen, otherwise (x)
            top -= 2
            x = stack[top + 1] if stack[top] != 0.0 else x
        elif code == NOT:
            x = 1.0 if x == 0.0 else 0.0
        elif code != IDENTITY:  # functions of two arguments, comparisons, logic
            top -= 1
            x = binary_function(code, stack[top], x)
    return x


@njit(cache=True, inline="always")
def remainder(a, b):
    """numpy.mod for floats: fmod, moved to the sign of the divisor."""
    if b == 0.0:
        return math.nan
    r = np.fmod(a, b)
    if r != 0.0 and ((b < 0.0) != (r < 0.0)):
        r += b
    return r


@njit(cache=True)
def unary_function(code, x):
    if code == SIN:
        return math.sin(x)
    if code == COS:
        return math.cos(x)
    if code == EXP:
        return math.exp(x)
    if code == SQRT:
        return math.sqrt(x) if x >= 0.0 else math.nan
    if code == ABS:
        return abs(x)
    if code == TAN:
        return math.tan(x)
    if code == ASIN:
        return math.asin(x) if abs(x) <= 1.0 else math.nan
    if code == ACOS:
        return math.acos(x) if abs(x) <= 1.0 else math.nan
    if code == ATAN:
        return math.atan(x)
    if code == SINH:
        return math.sinh(x)
    if code == COSH:
        return math.cosh(x)
    if code == TANH:
        return math.tanh(x)
    if code == ASINH:
        return math.asinh(x)
    if code == ACOSH:
        return math.acosh(x) if x >= 1.0 else math.nan
    if code == ATANH:
        return (
            math.atanh(x)
            if abs(x) < 1.0
            else (math.copysign(math.inf, x) if abs(x) == 1.0 else math.nan)
        )
    if code == LOG:
        return math.log(x) if x > 0.0 else (-math.inf if x == 0.0 else math.nan)
    if code == LOG10:
        return math.log10(x) if x > 0.0 else (-math.inf if x == 0.0 else math.nan)
    if code == FLOOR:
        return float(math.floor(x)) if abs(x) < 1.0e300 else x
    if code == CEIL:
        return float(math.ceil(x)) if abs(x) < 1.0e300 else x
    if code == TRUNC:
        return float(math.trunc(x)) if abs(x) < 1.0e300 else x
    if code == DEGREES:
        return math.degrees(x)
    if code == RADIANS:
        return math.radians(x)
    # SIGN (numpy's sign of one argument)
    if x > 0.0:
        return 1.0
    if x < 0.0:
        return -1.0
    return x


@njit(cache=True)
def binary_function(code, a, b):
    if code == ATAN2:
        return math.atan2(a, b)
    if code == HYPOT:
        return math.hypot(a, b)
    if code == MINIMUM:  # numpy.minimum: nan wins
        return a if (a < b or a != a) else b
    if code == MAXIMUM:
        return a if (a > b or a != a) else b
    if code == COPYSIGN:
        return math.copysign(abs(a), b)
    if code == LESS:
        return 1.0 if a < b else 0.0
    if code == LESS_EQUAL:
        return 1.0 if a <= b else 0.0
    if code == GREATER:
        return 1.0 if a > b else 0.0
    if code == GREATER_EQUAL:
        return 1.0 if a >= b else 0.0
    if code == EQUAL:
        return 1.0 if a == b else 0.0
    if code == NOT_EQUAL:
        return 1.0 if a != b else 0.0
    if code == AND:
        return 1.0 if (a != 0.0 and b != 0.0) else 0.0
    # OR
    return 1.0 if (a != 0.0 or b != 0.0) else 0.0
