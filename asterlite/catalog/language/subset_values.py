"""The values of the Python subset a catalogue reading evaluates.

What :class:`~asterlite.catalog.language.reader.CatalogueReader` calls when a
catalogue module calls a function, a method of ``str``/``list``/``dict``/
``set``, or applies an operator: builtins that stand for Python's, bound
methods from a fixed list (:data:`METHODS`), and the arithmetic and
comparisons of the subset. Anything outside raises
:class:`~asterlite.catalog.language.cata_objects.ReadError`.
"""

from __future__ import annotations

import ast
import math
import string
from collections.abc import Callable
from dataclasses import dataclass

from asterlite.catalog.language.cata_objects import (
    CataObject,
    ClassObj,
    CommandDef,
    EnumMember,
    Function,
    Instance,
    Keyword,
    Opaque,
    OrderedSet,
    ReadError,
)

MAX_SEQUENCE = 1_000_000  # items a range or a repetition may make

# ------------------------------------------------------------------ callables


@dataclass(eq=False)
class Builtin(CataObject):
    fn: Callable
    name: str = "builtin"
    pytype: type | None = None  # the Python type it stands for in isinstance()


def _builtin(fn: Callable) -> Builtin:
    return Builtin(fn, getattr(fn, "__name__", "builtin"))


@dataclass(eq=False)
class Method(CataObject):
    """A ``@classmethod`` / ``@staticmethod`` in a class body."""

    function: Function
    kind: str  # "classmethod" or "staticmethod"

    @property
    def name(self) -> str:
        return self.function.name


@dataclass(eq=False)
class BoundMethod(CataObject):
    function: Function
    owner: object
    kind: str  # "class" or "instance"


def _bind(value, cls: ClassObj):
    if isinstance(value, Method):
        if value.kind == "classmethod":
            return BoundMethod(value.function, cls, "class")
        return Method(value.function, "static")
    return value


def _maker(cls, kind: str):
    def make(*args, **kwargs):
        return cls(kind, tuple(args), dict(kwargs))

    return make


def _keyword_maker(kind: str):
    def make(**options):
        return Keyword(kind, dict(options))

    return make


def _command_maker(kind: str):
    def make(**options):
        return CommandDef(kind, dict(options))

    return make


@dataclass(eq=False)
class BoundBuiltin(CataObject):
    owner: object
    method: str

    def call(self, args: list, kwargs: dict):
        owner, method = self.owner, self.method
        if isinstance(owner, str) and method == "format":
            return _format(owner, args, kwargs)
        if isinstance(owner, OrderedSet):
            return _set_method(owner, method, args)
        if isinstance(owner, str) and method == "join":
            return owner.join(_iterate(args[0]))
        if method == "sort" and (args or set(kwargs) - {"reverse"}):
            raise ReadError("list.sort with a key")
        if isinstance(owner, (list, dict)) and method in ("extend", "update"):
            args = [list(_iterate(args[0])) if method == "extend" else _as_mapping(args[0])]
        try:
            return getattr(owner, method)(*args, **kwargs)
        except (TypeError, ValueError, KeyError, IndexError, AttributeError) as error:
            raise ReadError(f"{type(owner).__name__}.{method}: {error}") from None


METHODS = {
    str: frozenset(
        "startswith endswith upper lower split rsplit join replace strip lstrip rstrip "
        "format zfill capitalize title find count isdigit isupper islower splitlines".split()
    ),
    list: frozenset("append extend insert pop remove index count copy reverse sort".split()),
    tuple: frozenset(("index", "count")),
    dict: frozenset("get keys values items copy update pop setdefault".split()),
    OrderedSet: frozenset(
        "add update union difference intersection isdisjoint issubset copy discard remove".split()
    ),
}


def _set_method(owner: OrderedSet, method: str, args: list):
    if method == "add":
        owner.items[args[0]] = None
        return None
    if method == "update":
        for arg in args:
            owner.items.update(dict.fromkeys(_iterate(arg)))
        return None
    if method in ("discard", "remove"):
        owner.items.pop(args[0], None)
        return None
    if method == "copy":
        return OrderedSet(owner)
    other = [list(_iterate(a)) for a in args]
    if method == "union":
        return OrderedSet([*owner, *(i for o in other for i in o)])
    if method == "difference":
        return OrderedSet(i for i in owner if not any(i in o for o in other))
    if method == "intersection":
        return OrderedSet(i for i in owner if all(i in o for o in other))
    if method == "isdisjoint":
        return not any(i in other[0] for i in owner)
    if method == "issubset":
        return all(i in other[0] for i in owner)
    raise ReadError(f"set.{method}")


# ------------------------------------------------------------------ helpers


def _iterate(value):
    if isinstance(value, (list, tuple, str, OrderedSet)):
        return iter(value)
    if isinstance(value, dict):
        return iter(list(value))
    if isinstance(value, ClassObj) and value.enum:
        return iter(value.members)
    if isinstance(value, type({}.items())) or isinstance(value, type({}.keys())):
        return iter(list(value))
    if isinstance(value, type({}.values())):
        return iter(list(value))
    raise ReadError(f"iterating over {type(value).__name__}")


def _as_mapping(value) -> dict:
    if isinstance(value, dict):
        return value
    raise ReadError(f"** of a {type(value).__name__}")


def _make_dict(*args, **kwargs):
    result = {}
    if args:
        source = args[0]
        if isinstance(source, dict):
            result.update(source)
        else:
            result.update(list(_iterate(source)))
    result.update(kwargs)
    return result


def _sorted(items, reverse=False):
    return sorted(_iterate(items), reverse=reverse)


def _range(*args):
    result = range(*args)
    if len(result) > MAX_SEQUENCE:
        raise ReadError("range too long")
    return list(result)


def _force_list(values):
    if isinstance(values, (list, tuple)):
        return list(values)
    return [values]


def _isinstance(value, kinds) -> bool:
    kinds = kinds if isinstance(kinds, tuple) else (kinds,)
    for kind in kinds:
        if isinstance(kind, ClassObj):
            if isinstance(value, EnumMember) and value.cls is kind:
                return True
            if isinstance(value, Instance) and value.cls is kind:
                return True
        elif isinstance(kind, Builtin) and kind.pytype is not None:
            if isinstance(value, kind.pytype) and not isinstance(value, bool):
                return True
        elif isinstance(kind, Opaque) and kind.name == "object":
            return True
    return False


def _str(value=""):
    return str(_plain(value))


def _plain(value):
    if isinstance(value, (str, int, float, bool, complex)) or value is None:
        return value
    if isinstance(value, EnumMember):
        return f"{value.cls.name}.{value.name}"
    if isinstance(value, (list, tuple)):
        return type(value)(_plain(v) for v in value)
    raise ReadError(f"text of a {type(value).__name__}")


def _repr(value) -> str:
    return repr(_plain(value))


def _format(text: str, args: list, kwargs: dict) -> str:
    for _, field_name, spec, _ in string.Formatter().parse(text):
        if field_name is None:
            continue
        if any(c in field_name for c in ".[") or (spec and "{" in spec):
            raise ReadError("format field with an attribute or an index")
    return text.format(*map(_plain, args), **{k: _plain(v) for k, v in kwargs.items()})


def _truth(value) -> bool:
    if isinstance(value, (CataObject,)) and not isinstance(value, OrderedSet):
        return True
    if isinstance(value, OrderedSet):
        return len(value) > 0
    return bool(value)


def _number(value):
    if isinstance(value, (int, float, complex)):
        return value
    raise ReadError(f"arithmetic on a {type(value).__name__}")


def _binary(op: ast.operator, left, right):
    if isinstance(left, OrderedSet) or isinstance(right, OrderedSet):
        if isinstance(op, ast.BitOr):
            return OrderedSet([*left, *right])
        if isinstance(op, ast.Sub):
            return OrderedSet(i for i in left if i not in right)
        if isinstance(op, ast.BitAnd):
            return OrderedSet(i for i in left if i in right)
        raise ReadError("set operator")
    if isinstance(op, ast.Add):
        if isinstance(left, (list, tuple, str)) and type(left) is type(right):
            if len(left) + len(right) > MAX_SEQUENCE:
                raise ReadError("sequence too long")
            return left + right
        if isinstance(left, dict) or isinstance(right, dict):
            raise ReadError("+ of dicts")
        return _number(left) + _number(right)
    if isinstance(op, ast.Mult):
        if isinstance(left, (list, tuple, str)) and isinstance(right, int):
            left, right = right, left
        if isinstance(right, (list, tuple, str)) and isinstance(left, int):
            if left * len(right) > MAX_SEQUENCE:
                raise ReadError("sequence too long")
            return left * right
        return _number(left) * _number(right)
    if isinstance(op, ast.Mod) and isinstance(left, str):
        if any(c in left for c in "*"):
            raise ReadError("% with a star width")
        values = right if isinstance(right, tuple) else (right,)
        return left % tuple(map(_plain, values))
    operators = {
        ast.Sub: lambda a, b: a - b,
        ast.Div: lambda a, b: a / b,
        ast.FloorDiv: lambda a, b: a // b,
        ast.Mod: lambda a, b: a % b,
        ast.Pow: _power,
    }
    for kind, function in operators.items():
        if isinstance(op, kind):
            try:
                return function(_number(left), _number(right))
            except (ZeroDivisionError, OverflowError) as error:
                raise ReadError(str(error)) from None
    if isinstance(op, ast.BitOr) and isinstance(left, dict) and isinstance(right, dict):
        return {**left, **right}
    raise ReadError(f"operator {type(op).__name__}")


def _power(a, b):
    if isinstance(b, int) and abs(b) > 1000:
        raise ReadError("exponent too large")
    return a**b


def _compare(op: ast.cmpop, left, right) -> bool:
    if isinstance(op, (ast.In, ast.NotIn)):
        if isinstance(right, ClassObj) and right.enum:
            found = left in right.members
        elif isinstance(right, (list, tuple, dict, str, OrderedSet)):
            if isinstance(right, str) and not isinstance(left, str):
                raise ReadError("'in' a text of something else than a text")
            found = left in right
        else:
            found = left in list(_iterate(right))
        return found if isinstance(op, ast.In) else not found
    if isinstance(op, ast.Is):
        return left is right
    if isinstance(op, ast.IsNot):
        return left is not right
    if isinstance(op, ast.Eq):
        return _equal(left, right)
    if isinstance(op, ast.NotEq):
        return not _equal(left, right)
    functions = {
        ast.Lt: lambda a, b: a < b,
        ast.LtE: lambda a, b: a <= b,
        ast.Gt: lambda a, b: a > b,
        ast.GtE: lambda a, b: a >= b,
    }
    try:
        return functions[type(op)](left, right)
    except TypeError as error:
        raise ReadError(str(error)) from None


def _equal(left, right) -> bool:
    if isinstance(left, CataObject) or isinstance(right, CataObject):
        return left is right
    return left == right


def _as_load(target: ast.expr) -> ast.expr:
    """An assignment target read as a value (``x += 1``)."""
    node = ast.parse(ast.unparse(target), mode="eval").body
    return ast.copy_location(node, target)


# modules catalogues import besides their own: names that exist, never evaluated
STUB_MODULES = {
    "math": {"pi": math.pi},
    "enum": {"Enum": Opaque("Enum")},
    "typing": {},
}
