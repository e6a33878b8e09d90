"""Building blocks of the code :mod:`asterlite.lang.compiler` generates:
small ``ast`` constructors, the operand and guard descriptions, and the
statements every compiled function shares (its step of the budget)."""

from __future__ import annotations

import ast


class Refused(Exception):
    """The body uses a construct the compiler leaves to the interpreter."""


BINARY = {
    "+": ast.Add,
    "-": ast.Sub,
    "*": ast.Mult,
    "/": ast.Div,
    "//": ast.FloorDiv,
    "%": ast.Mod,
    "**": ast.Pow,
}
COMPARE = {"<": ast.Lt, ">": ast.Gt, "==": ast.Eq, ">=": ast.GtE, "<=": ast.LtE, "!=": ast.NotEq}
UNARY = {"-": ast.USub, "+": ast.UAdd, "~": ast.Invert}
# constant operand types after which an operation needs no guard (see _binary_guard)
NUMBERS = (float, int)


def _name(identifier: str, store: bool = False) -> ast.Name:
    return ast.Name(identifier, ast.Store() if store else ast.Load())


def _call(function: str, *args) -> ast.Call:
    return ast.Call(_name(function), list(args), [])


def _type_of(value: ast.expr) -> ast.Call:
    return _call("__T", value)


def _is(left: ast.expr, right: ast.expr) -> ast.Compare:
    return ast.Compare(left, [ast.Is()], [right])


def _type_is(value: ast.expr, kind: str) -> ast.Compare:
    return _is(_type_of(value), _name(kind))


def _type_in(value: ast.expr, kinds: str) -> ast.Compare:
    return ast.Compare(_type_of(value), [ast.In()], [_name(kinds)])


def _all(tests: list) -> ast.expr:
    return tests[0] if len(tests) == 1 else ast.BoolOp(ast.And(), tests)


def _stamp(tree, line: int):
    """Give ``line`` to every node of ``tree`` not located yet (the nodes of
    inner deck nodes already carry their own)."""
    pending = [tree] if isinstance(tree, ast.AST) else list(tree)
    while pending:
        node = pending.pop()
        if "lineno" in node._attributes:
            if getattr(node, "lineno", None) is not None:
                continue
            node.lineno = node.end_lineno = line
            node.col_offset = node.end_col_offset = 0
        pending.extend(ast.iter_child_nodes(node))
    return tree


class Either:
    """A guard: native when the operand on ``side`` ("left", "right" or
    "either") has a type in ``kinds`` (a closure name: "__FL" float, "__IF"
    int or float, "__CM" int, float or str)."""

    def __init__(self, kinds: str, side: str = "either"):
        self.kinds = kinds
        self.side = side


class Operand:
    """An evaluated-once operand: inline when simple (a constant, a bound
    local), else bound to a temporary by a walrus in the guard's test."""

    def __init__(self, expression: ast.expr, static=None, simple=False, temp=None):
        self.expression = expression
        self.static = static  # the Python type of a constant operand
        self.simple = simple
        self.temp = temp

    def ref(self) -> ast.expr:
        if self.simple:
            return _copy(self.expression)
        return _name(self.temp)

    def binding(self) -> ast.expr:
        return ast.NamedExpr(_name(self.temp, store=True), self.expression)


def _copy(expression: ast.expr) -> ast.expr:
    if isinstance(expression, ast.Constant):
        return ast.Constant(expression.value)
    return _name(expression.id)


def _float_constant(node) -> bool:
    """A float literal, signed or not."""
    if node.data == "unary" and node.children[0].value in "+-":
        node = node.children[1]
    return node.data == "const" and type(node.children[0]) is float


def _chain(bindings: list) -> ast.Compare:
    """``b0 is not _S is not b1 is not _S ...``: true, and evaluates every
    binding in order (a chained comparison stops only at a false link)."""
    ops, comparators = [ast.IsNot()], [_name("__S")]
    for binding in bindings[1:]:
        ops += [ast.IsNot(), ast.IsNot()]
        comparators += [binding, _name("__S")]
    return ast.Compare(bindings[0], ops, comparators)


def _tick() -> list:
    """One step of the budget: count it, check the limits when due."""
    steps = ast.Attribute(_name("__b"), "steps", ast.Load())
    due = ast.Compare(steps, [ast.GtE()], [ast.Attribute(_name("__b"), "next_check", ast.Load())])
    check = ast.Expr(ast.Call(ast.Attribute(_name("__b"), "check", ast.Load()), [], []))
    return [_add_to(ast.Attribute(_name("__b"), "steps", ast.Store()), 1), ast.If(due, [check], [])]


def _add_to(target: ast.Attribute, amount: int) -> ast.AugAssign:
    return ast.AugAssign(target, ast.Add(), ast.Constant(amount))


def _arguments(names) -> ast.arguments:
    return ast.arguments(
        posonlyargs=[],
        args=[ast.arg(name) for name in names],
        vararg=None,
        kwonlyargs=[],
        kw_defaults=[],
        kwarg=None,
        defaults=[],
    )


def if_branches(node) -> tuple[list, object]:
    """An ``if_stmt`` tree's (condition, suite) pairs, ``if`` then each
    ``elif`` in order, and its ``else`` suite (None without one)."""
    condition, suite, *clauses = node.children
    branches = [(condition, suite)]
    otherwise = None
    for clause in clauses:
        if clause is None:
            continue
        if clause.data == "elif_clause":
            branches.append((clause.children[0], clause.children[1]))
        else:
            otherwise = clause.children[0]
    return branches, otherwise
