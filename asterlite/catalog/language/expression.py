"""Conditions of the language data: a small expression form, and its evaluator.

code_aster writes a ``BLOC``'s condition as Python source
(``"equal_to('TYPE', 'CERCLE') and exists('RAYON')"``, sometimes plain
expressions such as ``"TYPE_CHAM[0:2] == 'EL'"``) and evaluates it with
``eval`` over the keyword values of the level. The language data keeps
each condition as a tree of JSON lists instead, and asterlite evaluates that
tree with the code below: nothing is compiled or executed.

Nodes (first item the operator)::

    ["c", value]            constant (text, number, logical, None)
    ["k", NAME]             value of keyword NAME; absent: the whole
                            condition is false (code_aster's NameError)
    ["kv", NAME]            value of keyword NAME, None when absent (sd_prod)
    ["t", name]             a code_aster type (``evol_noli``)
    ["py", name]            a Python type (``list``, ``tuple``, ``float``...)
    ["tuple", e...] / ["list", e...]
    ["and", e...] / ["or", e...] / ["not", e] / ["neg", e]
    ["cmp", left, [op, right]...]   op: == != < <= > >= in "not in" is "is not"
    ["call", f, e...]       f: exists, is_in, equal_to, value, is_type, size,
                            less_than, greater_than, AsType, len, abs, type,
                            is_typco (a CO output name), str
    ["meth", e, m, e...]    m: startswith, endswith, split, upper, lower, strip
    ["sub", e, index]       ["slice", lo, hi, step]
    ["if", test, then, else]
    ["bin", op, left, right]    op: + - * /

Values are those of the level as code_aster sees them: the deck's values
with the defaults added, lists for keywords of ``max > 1``, factor
keywords as lists of dicts. Evaluation is three-valued: a value
``asterlite check`` could not compute (``Unknown``, a concept of untold
type) makes what depends on it :data:`UNDETERMINED`, unless ``and``/``or``
decide without it.
"""

from __future__ import annotations

import ast
from collections.abc import Mapping

from asterlite.lang.values import Unknown

UNDETERMINED = type("Undetermined", (), {"__repr__": lambda self: "UNDETERMINED"})()


class Undefined(Exception):
    """A name the condition reads is not defined (code_aster: condition false)."""


class Failed(Exception):
    """Evaluating the expression raised in Python (code_aster: condition false)."""


class TypeValue:
    """A code_aster type as a value (``AsType(RESULTAT)``, ``evol_noli``)."""

    __slots__ = ("name",)

    def __init__(self, name: str):
        self.name = name

    def __eq__(self, other):
        return isinstance(other, TypeValue) and other.name == self.name

    def __hash__(self):
        return hash(("type", self.name))

    def __repr__(self):
        return self.name


class PyType(TypeValue):
    """A Python type as a value (``type(VALE_CALC) in (list, tuple)``)."""

    def __eq__(self, other):
        return isinstance(other, PyType) and other.name == self.name

    def __hash__(self):
        return hash(("py", self.name))


PY_TYPES = {"list": list, "tuple": tuple, "float": float, "int": int, "str": str, "dict": dict}


def _is_unknown(value) -> bool:
    return value is Unknown or value is UNDETERMINED


class Scope:
    """What a condition reads: keyword values (a mapping) and how to type concepts.

    ``type_of(value)`` gives the code_aster type name of a concept, or None
    when it cannot be told (the condition is then undetermined).
    """

    def __init__(self, values: Mapping, type_of=None, is_output=None):
        self.values = values
        self.type_of = type_of or (lambda value: None)
        self.is_output = is_output or (lambda value: False)


# --------------------------------------------------------------- evaluation


def evaluate(node, scope: Scope):
    """The value of ``node``: a Python value or :data:`UNDETERMINED`.

    Raises :class:`Undefined` or :class:`Failed` where code_aster's ``eval``
    raised (callers turn that into "false")."""
    op = node[0]
    handler = _HANDLERS.get(op)
    if handler is None:
        raise Failed(f"unknown expression node {op!r}")
    return handler(node, scope)


def holds(node, scope: Scope) -> bool | None:
    """A condition: True, False, or None when undetermined."""
    try:
        value = evaluate(node, scope)
    except (Undefined, Failed):
        return False
    if value is UNDETERMINED:
        return None
    return _truth(value)


def _truth(value) -> bool:
    try:
        return bool(value)
    except Exception as error:  # numpy arrays: ambiguous truth
        raise Failed(str(error)) from None


def _constant(node, scope):
    return node[1]


def _keyword(node, scope):
    name = node[1]
    if name not in scope.values:
        raise Undefined(name)
    return _value(scope.values[name])


def _keyword_or_none(node, scope):
    return _value(scope.values.get(node[1]))


def _value(value):
    return UNDETERMINED if _is_unknown(value) else value


def _type(node, scope):
    return TypeValue(node[1])


def _pytype(node, scope):
    return PyType(node[1])


def _sequence(node, scope):
    items = [evaluate(item, scope) for item in node[1:]]
    return tuple(items) if node[0] == "tuple" else items


def _and(node, scope):
    return _boolean(node, scope, stop=False)


def _or(node, scope):
    return _boolean(node, scope, stop=True)


def _boolean(node, scope, stop: bool):
    """``and`` (stop on a false operand) and ``or`` (stop on a true one), with
    Python's short circuit: an operand after an undetermined one that raises
    leaves the whole undetermined."""
    value = None
    undetermined = False
    for operand in node[1:]:
        try:
            value = evaluate(operand, scope)
        except (Undefined, Failed):
            if undetermined:
                return UNDETERMINED
            raise
        if value is UNDETERMINED:
            undetermined = True
            continue
        if _truth(value) == stop:
            return value
    return UNDETERMINED if undetermined else value


def _not(node, scope):
    value = evaluate(node[1], scope)
    return UNDETERMINED if value is UNDETERMINED else not _truth(value)


def _negative(node, scope):
    value = evaluate(node[1], scope)
    if value is UNDETERMINED:
        return value
    return _python(lambda: -value)


def _python(operation):
    try:
        return operation()
    except (Undefined, Failed):
        raise
    except Exception as error:
        raise Failed(f"{type(error).__name__}: {error}") from None


COMPARISONS = {
    "==": lambda a, b: a == b,
    "!=": lambda a, b: a != b,
    "<": lambda a, b: a < b,
    "<=": lambda a, b: a <= b,
    ">": lambda a, b: a > b,
    ">=": lambda a, b: a >= b,
    "in": lambda a, b: a in b,
    "not in": lambda a, b: a not in b,
    "is": lambda a, b: a is b,
    "is not": lambda a, b: a is not b,
}


def _compare(node, scope):
    left = evaluate(node[1], scope)
    undetermined = False
    for op, right_node in node[2:]:
        right = evaluate(right_node, scope)
        if left is UNDETERMINED or right is UNDETERMINED or _holds_unknown(right):
            undetermined = True
        else:
            if not _truth(_python(lambda a=left, b=right, f=COMPARISONS[op]: f(a, b))):
                return False
        left = right
    return UNDETERMINED if undetermined else True


def _holds_unknown(value) -> bool:
    if isinstance(value, (list, tuple)):
        return any(_is_unknown(v) for v in value)
    return False


def _subscript(node, scope):
    container = evaluate(node[1], scope)
    index = evaluate(node[2], scope)
    if container is UNDETERMINED or index is UNDETERMINED:
        return UNDETERMINED
    if isinstance(container, Mapping):  # code_aster's _F: [0] is itself, missing is None
        if index == 0 and not isinstance(index, bool):
            return container
        return _value(container.get(index))
    return _value(_python(lambda: container[index]))


def _slice(node, scope):
    parts = [evaluate(part, scope) if part is not None else None for part in node[1:4]]
    if any(p is UNDETERMINED for p in parts):
        return UNDETERMINED
    return slice(*parts)


def _if(node, scope):
    test = evaluate(node[1], scope)
    if test is UNDETERMINED:
        return UNDETERMINED
    return evaluate(node[2] if _truth(test) else node[3], scope)


BINARY = {
    "+": lambda a, b: a + b,
    "-": lambda a, b: a - b,
    "*": lambda a, b: a * b,
    "/": lambda a, b: a / b,
    "&": lambda a, b: a & b,
    "|": lambda a, b: a | b,
}


def _binary(node, scope):
    left, right = evaluate(node[2], scope), evaluate(node[3], scope)
    if left is UNDETERMINED or right is UNDETERMINED:
        return UNDETERMINED
    return _python(lambda: BINARY[node[1]](left, right))


METHODS = ("startswith", "endswith", "split", "upper", "lower", "strip")


def _method(node, scope):
    owner = evaluate(node[1], scope)
    args = [evaluate(arg, scope) for arg in node[3:]]
    if owner is UNDETERMINED or any(a is UNDETERMINED for a in args):
        return UNDETERMINED
    name = node[2]
    if name not in METHODS or not isinstance(owner, str):
        raise Failed(f"method {name} of {type(owner).__name__}")
    return _python(lambda: getattr(owner, name)(*args))


# ------------------------------------------------------------------ calls


def _force_list(value) -> list:
    if isinstance(value, (list, tuple)):
        return list(value)
    if type(value).__module__ == "numpy" and hasattr(value, "tolist"):
        value = value.tolist()
        return value if isinstance(value, list) else [value]
    return [value]


def _exists(scope, name):
    return scope.values.get(name) is not None


def _is_in(scope, names, values):
    """Some value of the keywords ``names`` is among ``values`` (code_aster's is_in)."""
    given = []
    for name in _force_list(names):
        if not _exists(scope, name):
            return False
        given.extend(_force_list(scope.values[name]))
    allowed = _force_list(values)
    unknown = False
    for value in given:
        if _is_unknown(value):
            unknown = True
        elif _python(lambda v=value: any(_same(v, a) for a in allowed)):
            return True
    return UNDETERMINED if unknown else False


def _same(value, allowed) -> bool:
    try:
        return bool(value == allowed) and hash(value) == hash(allowed)
    except TypeError:  # unhashable values: code_aster's set() raised
        raise Failed("unhashable value") from None


def _lookup(scope, name, default=""):
    return _value(scope.values.get(name, default))


def _as_type(scope, value):
    if value is UNDETERMINED:
        return UNDETERMINED
    if isinstance(value, (list, tuple)):
        return _as_type(scope, value[0]) if value else PyType(type(value).__name__)
    if _is_unknown(value):
        return UNDETERMINED
    name = scope.type_of(value)
    if name is not None:
        return TypeValue(name) if name != UNDETERMINED else UNDETERMINED
    if isinstance(value, (bool, int, float, str, complex, dict)) or value is None:
        return PyType(type(value).__name__)
    return UNDETERMINED


def _size(scope, name):
    return _python(lambda: len(scope.values.get(name)))


def _compare_value(scope, name, bound, greater: bool):
    value = _lookup(scope, name)
    if value is UNDETERMINED:
        return value
    return _python(lambda: value > bound if greater else value < bound)


def _call(node, scope):
    args = [evaluate(arg, scope) for arg in node[2:]]
    try:
        return _call_function(node[1], args, scope)
    except (Undefined, Failed):
        raise
    except Exception as error:  # a wrong call in the catalogue: Python raised there too
        raise Failed(f"{type(error).__name__}: {error}") from None


def _call_function(name: str, args: list, scope):
    if name == "exists":
        return _exists(scope, args[0])
    if name in ("is_in", "equal_to"):
        return _is_in(scope, args[0], args[1])
    if name == "value":
        return _lookup(scope, *args)
    if name == "is_type":
        return _as_type(scope, _lookup(scope, args[0]))
    if name == "AsType":
        return _as_type(scope, args[0])
    if name == "size":
        return _size(scope, args[0])
    if name in ("less_than", "greater_than"):
        return _compare_value(scope, args[0], args[1], name == "greater_than")
    if any(a is UNDETERMINED for a in args):
        return UNDETERMINED
    if name == "len":
        return _python(lambda: len(args[0]))
    if name == "abs":
        return _python(lambda: abs(args[0]))
    if name == "type":
        return PyType(type(args[0]).__name__)
    if name == "str":
        return _python(lambda: str(args[0]))
    if name == "is_typco":
        return bool(scope.is_output(args[0]))
    raise Failed(f"function {name}")


_HANDLERS = {
    "c": _constant,
    "k": _keyword,
    "kv": _keyword_or_none,
    "t": _type,
    "py": _pytype,
    "tuple": _sequence,
    "list": _sequence,
    "and": _and,
    "or": _or,
    "not": _not,
    "neg": _negative,
    "cmp": _compare,
    "sub": _subscript,
    "slice": _slice,
    "if": _if,
    "bin": _binary,
    "meth": _method,
    "call": _call,
}


# ------------------------------------------------------------------- text


def describe(node) -> str:
    """The expression in deck-like syntax, for messages."""
    op = node[0]
    if op == "c":
        return repr(node[1])
    if op in ("k", "kv", "t", "py"):
        return node[1]
    if op in ("tuple", "list"):
        items = ", ".join(describe(n) for n in node[1:])
        if op == "tuple":
            return f"({items},)" if len(node) == 2 else f"({items})"
        return f"[{items}]"
    if op in ("and", "or"):
        return f" {op} ".join(_wrap(n) for n in node[1:])
    if op == "not":
        return f"not {_wrap(node[1])}"
    if op == "neg":
        return f"-{_wrap(node[1])}"
    if op == "cmp":
        text = describe(node[1])
        for comparison, right in node[2:]:
            text += f" {comparison} {describe(right)}"
        return text
    if op == "call":
        return f"{node[1]}({', '.join(describe(n) for n in node[2:])})"
    if op == "meth":
        return f"{_wrap(node[1])}.{node[2]}({', '.join(describe(n) for n in node[3:])})"
    if op == "sub":
        return f"{_wrap(node[1])}[{describe(node[2])}]"
    if op == "slice":
        parts = ["" if p is None else describe(p) for p in node[1:3]]
        return ":".join(parts) + (f":{describe(node[3])}" if node[3] is not None else "")
    if op == "if":
        return f"{describe(node[2])} if {describe(node[1])} else {describe(node[3])}"
    if op == "bin":
        return f"{_wrap(node[2])} {node[1]} {_wrap(node[3])}"
    return repr(node)


def _wrap(node) -> str:
    text = describe(node)
    return f"({text})" if node[0] in ("and", "or", "if", "cmp", "bin") else text


def readable(node) -> str:
    """A condition as a short phrase: ``TYPE='CERCLE'``, ``RAYON given``..."""
    op = node[0]
    if op == "call" and node[1] in ("equal_to", "is_in") and len(node) == 4:
        name, values = node[2], node[3]
        if name[0] == "c" and isinstance(name[1], str):
            if values[0] in ("tuple", "list") and len(values) == 2:
                values = values[1]
            if values[0] == "c":
                return f"{name[1]}={values[1]!r}"
            return f"{name[1]} in {describe(values)}"
    if op == "call" and node[1] == "exists" and node[2][0] == "c":
        return f"{node[2][1]} given"
    if op == "not" and node[1][0] == "call" and node[1][1] == "exists" and node[1][2][0] == "c":
        return f"{node[1][2][1]} absent"
    if op in ("and", "or"):
        return f" {op} ".join(
            f"({readable(n)})" if n[0] in ("and", "or") else readable(n) for n in node[1:]
        )
    return describe(node)


# --------------------------------------------------------- from Python source


class NotExpressible(Exception):
    """Python the expression form does not hold."""


CONDITION_FUNCTIONS = frozenset(
    {
        "exists",
        "is_in",
        "equal_to",
        "value",
        "is_type",
        "size",
        "less_than",
        "greater_than",
        "AsType",
        "len",
        "abs",
        "type",
        "str",
        "is_typco",
    }
)
_COMPARE_OPS = {
    "Eq": "==",
    "NotEq": "!=",
    "Lt": "<",
    "LtE": "<=",
    "Gt": ">",
    "GtE": ">=",
    "In": "in",
    "NotIn": "not in",
    "Is": "is",
    "IsNot": "is not",
}
_BIN_OPS = {"Add": "+", "Sub": "-", "Mult": "*", "Div": "/", "BitAnd": "&", "BitOr": "|"}


def from_source(text: str, type_names) -> list:
    """A code_aster condition string as an expression tree."""

    tree = ast.parse(" ".join(text.split()), mode="eval")
    return from_ast(tree.body, type_names)


def from_ast(node, type_names, names=None) -> list:
    """An expression tree from a Python syntax tree: names are keyword values
    (``["k", NAME]``), those in ``type_names`` code_aster types. ``names``
    maps some names to trees already made (sd_prod's local variables)."""

    def convert(n):
        if isinstance(n, ast.Constant):
            if isinstance(n.value, (str, int, float, bool)) or n.value is None:
                return ["c", n.value]
            raise NotExpressible(f"constant {n.value!r}")
        if isinstance(n, ast.Name):
            if names is not None and n.id in names:
                return names[n.id]
            if n.id in ("None", "True", "False"):
                return ["c", {"None": None, "True": True, "False": False}[n.id]]
            if n.id in PY_TYPES:
                return ["py", n.id]
            if n.id in type_names:
                return ["t", n.id]
            return ["k", n.id]
        if isinstance(n, (ast.Tuple, ast.List)):
            return ["tuple" if isinstance(n, ast.Tuple) else "list", *map(convert, n.elts)]
        if isinstance(n, ast.BoolOp):
            return ["and" if isinstance(n.op, ast.And) else "or", *map(convert, n.values)]
        if isinstance(n, ast.UnaryOp):
            if isinstance(n.op, ast.Not):
                return ["not", convert(n.operand)]
            if isinstance(n.op, ast.USub):
                operand = convert(n.operand)
                if operand[0] == "c" and isinstance(operand[1], (int, float)):
                    return ["c", -operand[1]]
                return ["neg", operand]
            raise NotExpressible("unary operator")
        if isinstance(n, ast.Compare):
            ops = [_COMPARE_OPS[type(o).__name__] for o in n.ops]
            pairs = zip(ops, n.comparators, strict=True)
            return ["cmp", convert(n.left), *([o, convert(c)] for o, c in pairs)]
        if isinstance(n, ast.Call):
            if n.keywords or any(isinstance(a, ast.Starred) for a in n.args):
                raise NotExpressible("call with keyword or starred arguments")
            if isinstance(n.func, ast.Name) and n.func.id in CONDITION_FUNCTIONS:
                return ["call", n.func.id, *map(convert, n.args)]
            if isinstance(n.func, ast.Attribute) and n.func.attr in METHODS:
                return ["meth", convert(n.func.value), n.func.attr, *map(convert, n.args)]
            raise NotExpressible(f"call {ast.unparse(n.func)}")
        if isinstance(n, ast.Subscript):
            return ["sub", convert(n.value), convert(n.slice)]
        if isinstance(n, ast.Slice):
            parts = (n.lower, n.upper, n.step)
            return ["slice", *(convert(p) if p is not None else None for p in parts)]
        if isinstance(n, ast.IfExp):
            return ["if", convert(n.test), convert(n.body), convert(n.orelse)]
        if isinstance(n, ast.BinOp) and type(n.op).__name__ in _BIN_OPS:
            return ["bin", _BIN_OPS[type(n.op).__name__], convert(n.left), convert(n.right)]
        raise NotExpressible(f"{type(n).__name__}")

    return convert(node)
