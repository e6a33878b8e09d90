"""Formula load multipliers evaluated inside the compiled time loops: the
postfix back end of :mod:`asterlite.lang.formula`.

A deck formula of one parameter, the time (``NOM_PARA='INST'``), whose checked tree
uses only numbers, the parameter, numeric extra values, arithmetic,
comparisons, conditional expressions and the functions with a kernel code
in :mod:`asterlite.lang.numeric` is translated once into a small postfix
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

import math
import numbers

import numpy as np

from asterlite.dynamics.jit import njit
from asterlite.errors import CommandError
from asterlite.lang import numeric
from asterlite.lang.formula import (
    ARITHMETIC,
    Binary,
    Call,
    Compare,
    Conditional,
    Logical,
    Name,
    Number,
    Unary,
    walk,
)
from asterlite.lang.numeric import (  # the operation codes the kernels below run
    ABS,
    ACOS,
    ACOSH,
    ADD,
    AND,
    ASIN,
    ASINH,
    ATAN,
    ATAN2,
    ATANH,
    CEIL,
    COPYSIGN,
    COS,
    COSH,
    DEGREES,
    DIV,
    EQUAL,
    EXP,
    FLOOR,
    GREATER,
    GREATER_EQUAL,
    HYPOT,
    IDENTITY,
    LESS,
    LESS_EQUAL,
    LOG,
    LOG10,
    MAXIMUM,
    MINIMUM,
    MOD,
    MUL,
    NEG,
    NOT,
    NOT_EQUAL,
    POW,
    PUSH_CONSTANT,
    PUSH_TIME,
    RADIANS,
    SELECT,
    SIN,
    SINH,
    SQRT,
    SUB,
    TAN,
    TANH,
    TRUNC,
)

STACK_DEPTH = 32  # deepest expression accepted (operands pending at once)


class NotCompilable(Exception):
    """The formula uses something the kernel programs do not offer."""


def formula_program(mult) -> tuple[list[int], list[float]] | None:
    """(codes, constants) of a one-parameter real formula, or None when it
    cannot run in the kernels (then it is sampled)."""
    compiled = getattr(mult, "compiled", None)
    parameters = tuple(getattr(mult, "NOM_PARA", ()) or ())
    if compiled is None or len(parameters) != 1 or getattr(mult, "complex_result", False):
        return None
    constants = dict(numeric.CONSTANTS)
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
    emitter = _Emitter(compiled, parameters[0], constants, set(extra) | {parameters[0]})
    try:
        depth = emitter.emit(compiled.tree.body, 0)
    except (NotCompilable, RecursionError):
        return None
    if depth > STACK_DEPTH:
        return None
    return emitter.codes, emitter.values


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


class _Emitter:
    """Postfix code of a checked formula tree. Each largest arithmetic
    subtree free of the parameter (numbers, numeric extra values, math
    constants, + - * / ** % //, unary - + not) is folded to its value,
    computed by the formula's own evaluator; ``shadowed``: names that are
    not the table's functions (extra values, the parameter)."""

    def __init__(self, compiled, parameter: str, constants: dict, shadowed: set):
        self.compiled, self.parameter = compiled, parameter
        self.constants, self.shadowed = constants, shadowed
        self.codes: list[int] = []
        self.values: list[float] = []

    def op(self, code: int, value: float = 0.0) -> None:
        self.codes.append(code)
        self.values.append(value)

    def foldable(self, node) -> bool:
        if not isinstance(node, ARITHMETIC):
            return False
        for item in walk(node):
            if isinstance(item, Name):
                if item.id == self.parameter or item.id not in self.constants:
                    return False
            elif not isinstance(item, (Number, *ARITHMETIC)):
                return False
        return True

    def operand(self, node):
        """A leaf as the kernels see it: a folded subtree becomes its value."""
        if self.foldable(node):
            return Number(folded_value(self.compiled, node, self.constants))
        return node

    def exact_operand(self, node) -> None:
        """Python compares an integer with a float exactly: refuse an integer
        operand that no float holds (beyond 2**53), which the kernels would round."""
        value = None
        if isinstance(node, Number):
            value = node.value
        elif isinstance(node, Name):
            value = self.constants.get(node.id)
        if isinstance(value, int) and not isinstance(value, bool):
            if kernel_float(value) != value:
                raise NotCompilable(f"integer {value.bit_length()} bits wide in a comparison")

    def emit(self, node, depth: int) -> int:
        """Append the postfix code of ``node``; returns the deepest stack use."""
        node = self.operand(node)
        match node:
            case Number(value=value) if isinstance(value, int | float) and not isinstance(
                value, bool
            ):
                self.op(PUSH_CONSTANT, kernel_float(value))
                return depth + 1
            case Name(id=name):
                if name == self.parameter:
                    self.op(PUSH_TIME)
                elif name in self.constants:
                    self.op(PUSH_CONSTANT, kernel_float(self.constants[name]))
                else:
                    raise NotCompilable(name)
                return depth + 1
            case Binary(op=symbol, left=left, right=right):
                deepest = max(self.emit(left, depth), self.emit(right, depth + 1))
                self.op(numeric.BINARY_OPERATORS[symbol][1])
                return deepest
            case Unary(op="+", operand=operand):
                return self.emit(operand, depth)
            case Unary(op=symbol, operand=operand):
                deepest = self.emit(operand, depth)
                self.op(numeric.UNARY_OPERATORS[symbol][1])
                return deepest
            case Compare(left=left, ops=[symbol], comparators=[right]):
                left, right = self.operand(left), self.operand(right)
                self.exact_operand(left)
                self.exact_operand(right)
                deepest = max(self.emit(left, depth), self.emit(right, depth + 1))
                self.op(numeric.COMPARISONS[symbol][1])
                return deepest
            case Logical(op=symbol, operands=operands):
                code = numeric.LOGICAL[symbol][1]
                deepest = self.emit(operands[0], depth)
                for operand in operands[1:]:
                    deepest = max(deepest, self.emit(operand, depth + 1))
                    self.op(code)
                return deepest
            case Conditional(test=test, body=body, orelse=orelse):
                deepest = max(
                    self.emit(test, depth), self.emit(body, depth + 1), self.emit(orelse, depth + 2)
                )
                self.op(SELECT)
                return deepest
            case Call(name=name, args=args) if name not in self.shadowed:
                row = numeric.FUNCTIONS.get(name)
                code = None if row is None else row.kernel_code(len(args))
                if code is not None:
                    deepest = self.emit(args[0], depth)
                    for arg in args[1:]:  # min/max of more: reduced left to right
                        deepest = max(deepest, self.emit(arg, depth + 1))
                        self.op(code)
                    if len(args) == 1:
                        self.op(code)
                    return deepest
        raise NotCompilable(repr(node))


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
    stores per code (the specialised DIFF_CENTRE loop runs each formula
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
