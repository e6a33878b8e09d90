"""A command's result type as data: ``sd_prod`` functions read as decision tables.

code_aster gives the type of a command's result (``sd_prod``) either as a
type or as a function of the keyword values, e.g.::

    def defi_fonction_prod(VALE, VALE_C, **args):
        if args.get("__all__"):
            return (fonction_sdaster, fonction_c)
        if VALE is not None:
            return fonction_sdaster
        if VALE_C is not None:
            return fonction_c
        raise CataError("...")

The function is never run. Its syntax tree is walked path by path: each
``if`` splits a path, local assignments are substituted, and every
``return`` becomes a row ``[condition, result]`` of the table, in the
order Python would try them (the first row whose condition holds gives
the result; a result may itself be an expression such as
``AsType(RESULTAT)``). A ``raise`` ends its path as an error row.
``self.type_sdprod(NAME, type)`` (a macro typing a ``CO`` output) is kept
with the rows it belongs to. ``args.get("__all__")`` (code_aster's request
for every possible type) gives the table's ``types``.

A function using anything else (loops that do more than check, calls of
other functions...) is recorded as ``{"depends": types}``: its result is
one of ``types``, which a check cannot narrow.
"""

from __future__ import annotations

import ast

from asterlite.catalog.language.expression import NotExpressible, from_ast


class Unreadable(Exception):
    """A construct the decision-table reader does not follow."""


MAX_ROWS = 200


def read_sd_prod(function: ast.FunctionDef, type_names, all_types=None) -> dict:
    """The data of an ``sd_prod`` function: ``{"table": rows, "types": [...]}``
    or ``{"depends": [...]}``."""
    reader = _TableReader(function, type_names)
    types = reader.all_types() or all_types
    try:
        rows = reader.rows()
    except (Unreadable, NotExpressible, RecursionError) as error:
        found = types or reader.returned_type_names()
        return {"depends": sorted(found), "why": str(error)}
    result = {"table": rows}
    result["types"] = sorted(types or reader.returned_type_names())
    return result


class _TableReader:
    def __init__(self, function: ast.FunctionDef, type_names):
        self.function = function
        self.type_names = frozenset(type_names)
        spec = function.args
        self.params = [a.arg for a in spec.posonlyargs + spec.args + spec.kwonlyargs]
        self.self_name = self.params[0] if self.params and self.params[0] == "self" else None
        self.kwargs_name = spec.kwarg.arg if spec.kwarg else None
        self.rows_out: list = []

    # ------------------------------------------------------------ the type set
    def all_types(self) -> list[str] | None:
        """Types returned under ``args.get("__all__")``, if the function says."""
        for statement in self.function.body:
            if isinstance(statement, ast.If) and self._is_all_request(statement.test):
                for inner in statement.body:
                    if isinstance(inner, ast.Return) and inner.value is not None:
                        return sorted(self._type_names_in(inner.value))
        return None

    def returned_type_names(self) -> set[str]:
        found = set()
        for node in ast.walk(self.function):
            if isinstance(node, ast.Return) and node.value is not None:
                found |= self._type_names_in(node.value)
        return found

    def _type_names_in(self, node) -> set[str]:
        return {n.id for n in ast.walk(node) if isinstance(n, ast.Name) and n.id in self.type_names}

    def _is_all_request(self, test) -> bool:
        """``args.get("__all__")``, ``args.get("__only_type__")``: code_aster's
        own requests, never a deck's."""
        return any(
            isinstance(n, ast.Constant) and isinstance(n.value, str) and n.value.startswith("__")
            for n in ast.walk(test)
        )

    # --------------------------------------------------------------- the rows
    def rows(self) -> list:
        names = {p: ["kv", p] for p in self.params if p != self.self_name}
        self._walk(self.function.body, [], names, [])
        return fix_kv(self.rows_out)

    def _expression(self, node, names):
        return from_ast(self._rewrite(node), self.type_names, names)

    def _rewrite(self, node):
        """``args.get("X")`` / ``args["X"]`` / ``X.is_typco()`` / ``X is not None``
        into names and calls the expression form has."""
        kwargs_name = self.kwargs_name
        reader = self

        class Rewrite(ast.NodeTransformer):
            def visit_Call(self, call):
                func = call.func
                if (
                    isinstance(func, ast.Attribute)
                    and func.attr == "get"
                    and isinstance(func.value, ast.Name)
                    and func.value.id == kwargs_name
                    and call.args
                    and isinstance(call.args[0], ast.Constant)
                ):
                    if len(call.args) > 1 and not (
                        isinstance(call.args[1], ast.Constant) and call.args[1].value is None
                    ):
                        raise Unreadable("args.get with a default")
                    return ast.Name(id=f"{KV}{call.args[0].value}", ctx=ast.Load())
                self.generic_visit(call)
                if isinstance(func, ast.Attribute) and func.attr == "is_typco" and not call.args:
                    return ast.Call(
                        func=ast.Name(id="is_typco", ctx=ast.Load()), args=[func.value], keywords=[]
                    )
                return call

            def visit_Subscript(self, sub):
                if (
                    isinstance(sub.value, ast.Name)
                    and sub.value.id == kwargs_name
                    and isinstance(sub.slice, ast.Constant)
                ):
                    return ast.Name(id=f"{KV}{sub.slice.value}", ctx=ast.Load())
                self.generic_visit(sub)
                return sub

            def visit_Name(self, name):
                if name.id == kwargs_name or name.id == reader.self_name:
                    raise Unreadable(f"use of {name.id}")
                return name

        tree = ast.fix_missing_locations(Rewrite().visit(_copy(node)))
        return tree

    def _walk(self, statements, conditions, names, outputs) -> None:
        """Follow one path through ``statements`` (a block followed by what
        runs after it), adding a row where it returns, raises or ends."""
        for index, statement in enumerate(statements):
            if isinstance(statement, ast.Expr) and isinstance(statement.value, ast.Constant):
                continue  # docstring
            if isinstance(statement, ast.If):
                if self._is_all_request(statement.test):
                    continue
                test = self._expression(statement.test, names)
                if self._only_outputs(statement):
                    for inner in statement.body:
                        self._type_output(inner.value, names, outputs, [*conditions, test])
                    continue
                rest = statements[index + 1 :]
                self._walk(statement.body + rest, [*conditions, test], dict(names), list(outputs))
                # the rows of the branch above cover every case where ``test``
                # holds (each path ends in a row) and come first: the rows of
                # the other branch need not repeat "not test"
                self._walk(statement.orelse + rest, conditions, dict(names), list(outputs))
                return
            if isinstance(statement, ast.Return):
                result = ["c", None] if statement.value is None else None
                if result is None:
                    result = self._expression(statement.value, names)
                self._row(conditions, result, outputs)
                return
            if isinstance(statement, ast.Raise):
                self._row(conditions, {"error": True}, outputs)
                return
            if isinstance(statement, ast.Assign):
                self._assign(statement, names)
                continue
            if isinstance(statement, ast.Expr) and self._type_output(
                statement.value, names, outputs, conditions
            ):
                continue
            if isinstance(statement, ast.For) and self._only_checks(statement):
                continue  # a loop that only raises on inconsistent inputs
            if isinstance(statement, (ast.Pass, ast.Assert)):
                continue
            raise Unreadable(f"{type(statement).__name__} at line {statement.lineno}")
        self._row(conditions, ["c", None], outputs)  # falls off the end: None

    def _only_outputs(self, statement: ast.If) -> bool:
        """An ``if`` without ``else`` that only types CO outputs."""
        return not statement.orelse and all(
            isinstance(inner, ast.Expr) and self._is_type_output(inner.value)
            for inner in statement.body
        )

    def _row(self, conditions, result, outputs) -> None:
        if len(self.rows_out) >= MAX_ROWS:
            raise Unreadable("too many paths")
        row = [_conjunction(conditions), result]
        if outputs:
            row.append(outputs)
        self.rows_out.append(row)

    def _assign(self, statement: ast.Assign, names) -> None:
        if len(statement.targets) != 1:
            raise Unreadable("chained assignment")
        target = statement.targets[0]
        value = self._expression(statement.value, names)
        if isinstance(target, ast.Name):
            names[target.id] = value
        elif isinstance(target, ast.Tuple) and all(isinstance(e, ast.Name) for e in target.elts):
            for position, element in enumerate(target.elts):
                names[element.id] = ["sub", value, ["c", position]]
        else:
            raise Unreadable("assignment to something else than names")

    def _is_type_output(self, call) -> bool:
        return (
            isinstance(call, ast.Call)
            and isinstance(call.func, ast.Attribute)
            and call.func.attr == "type_sdprod"
            and isinstance(call.func.value, ast.Name)
            and call.func.value.id == self.self_name
            and len(call.args) == 2
        )

    def _type_output(self, call, names, outputs, conditions) -> bool:
        """``self.type_sdprod(NAME, type)``: a CO output the macro types, as
        ``[condition, output, type]``."""
        if not self._is_type_output(call):
            return False
        condition = _conjunction(conditions)
        outputs.append([condition, *(self._expression(a, names) for a in call.args)])
        return True

    def _only_checks(self, loop: ast.For) -> bool:
        for node in ast.walk(loop):
            if isinstance(node, (ast.Return, ast.Assign, ast.AugAssign)):
                return False
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute):
                if node.func.attr == "type_sdprod":
                    return False
        return True


def _conjunction(conditions) -> list:
    if not conditions:
        return ["c", True]
    return conditions[0] if len(conditions) == 1 else ["and", *conditions]


KV = "\x00kv:"  # marks names rewritten from args.get("X")


def _copy(node):
    return ast.parse(ast.unparse(node), mode="eval").body if isinstance(node, ast.expr) else node


def fix_kv(tree):
    """Turn the marked names of :meth:`_TableReader._rewrite` into ``["kv", X]``."""
    if isinstance(tree, list):
        if (
            len(tree) == 2
            and tree[0] == "k"
            and isinstance(tree[1], str)
            and tree[1].startswith(KV)
        ):
            return ["kv", tree[1][len(KV) :]]
        if len(tree) == 2 and tree[0] == "k":
            raise Unreadable(f"name {tree[1]} (a global of the catalogue)")
        return [fix_kv(item) for item in tree]
    if isinstance(tree, dict):
        return {k: fix_kv(v) for k, v in tree.items()}
    return tree
