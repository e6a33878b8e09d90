"""Compile a deck function's checked tree into a Python function.

The tree-walking evaluator costs microseconds per node; a FORMULE that
calls a deck ``def`` at every instant of a long list spends its time there.
This module turns the body of a ``def`` (or ``lambda``) into a Python
``ast`` built here, node by node, from the parser's checked tree only —
never from deck text — and compiles it with :func:`compile`; the code runs
with empty builtins and reaches nothing but its own locals and the closure
variables passed to it below.

The guarantees of the interpreter hold on this path, with the same
semantics and messages:

- names: locals are Python locals; any other name is read from the deck
  namespace (``_G[name]``), so only what the deck may see is reachable; a
  local read before it is assigned falls back to the namespace, as the
  interpreter's frame lookup does;
- attributes go through :func:`asterlite.lang.library.get_attribute` (its
  whitelists), never through Python attribute access on deck values;
- every loop iteration and call takes a step of the evaluator's
  :class:`~asterlite.lang.budget.StepBudget` (shared with the interpreter),
  and calls are bounded in depth;
- an operation runs natively only when its operand types make every size
  guard moot (two floats, a float constant, an int index...); anything else
  goes to the interpreter's own code for that operation (Unknown,
  :func:`asterlite.lang.limits.check_binary`, ``_key``, ``invoke``...);
- errors are located at the deck node whose code raised them: each node's
  code carries the node's index as its Python line number.

A ``for`` loop doing float arithmetic gets a second, unguarded version
beside the guarded one, entered when a test before the loop proves the
types it relies on (:mod:`asterlite.lang.compiled_loops`).

A body using a construct outside the compiled subset (``del``, ``assert``,
``import``, ``try``, ``raise``, ``with``, f-strings, nested ``def`` or
``lambda``, comprehensions, ``*args`` before other arguments), or a
function of a Python 2 deck using its '/' or the dict methods that gave
lists, is not compiled: the interpreter runs it, unchanged.
"""

from __future__ import annotations

import ast
import types

from asterlite.lang.compiled_ast import (
    BINARY,
    Refused,
    _add_to,
    _all,
    _arguments,
    _call,
    _copy,
    _float_constant,
    _name,
    _stamp,
    _tick,
    _type_is,
    if_branches,
)
from asterlite.lang.compiled_expressions import ExpressionCompiler
from asterlite.lang.compiled_loops import FastLoop
from asterlite.lang.compiled_runtime import (
    CHAIN,
    PLAIN_CALLABLES,
    PLAIN_SCALARS,
    UNBOUND,
    CompiledRuntime,
)
from asterlite.lang.deck_function import Frame
from asterlite.lang.python2 import DICT_METHODS
from asterlite.lang.values import Unknown

INT_OR_FLOAT = frozenset({int, float})
COMPARABLE = frozenset({int, float, str})  # compared with anything, never broadcast or grown


# closure variables of the generated code, by name; internal names (these,
# temporaries) start with "__", which deck names never do
RUNTIME_NAMES = (
    "__b", "__G", "__T", "__U", "__UNB", "__S", "__DF", "__PC", "__SC", "__IF", "__CM", "__FL",
    "__IN", "__TU", "__LI", "__LEN", "__sites", "__code", "__nodes", "__frame", "__reads",
    "__CONV", "__rt_binary", "__rt_augmented", "__rt_compare", "__rt_attribute", "__rt_key",
    "__rt_item", "__rt_keyed_item", "__rt_slice", "__rt_index_tuple", "__rt_store_item",
    "__rt_augmented_item", "__rt_unpack", "__rt_call", "__rt_call_kw", "__rt_locate",
)  # fmt: skip


def compile_function(function, evaluator):
    """The compiled body of a module-level deck function, or None (refused)."""
    if function.closure.locals is not None:  # defined inside a function or comprehension
        return None
    if function.closure.module.python2 and _python2_meaning(function.body):
        return None  # Python 2's division or dict methods: interpreted
    runtime = evaluator._compiled_runtime
    if runtime is None:
        runtime = evaluator._compiled_runtime = CompiledRuntime(evaluator)
    try:
        return FunctionCompiler(function, evaluator, runtime).build()
    except Refused:
        return None
    except (RecursionError, SyntaxError, ValueError, MemoryError):
        return None  # an expression nested beyond what compile() takes: interpreted


def _python2_meaning(body) -> bool:
    """A Python 2 body using what the compiled code would read as Python 3:
    '/' (classic division) and the dict methods that gave lists."""

    pending = [body]
    while pending:
        node = pending.pop()
        for child in getattr(node, "children", ()):
            if getattr(child, "value", None) in ("/2", "/2="):
                return True
            if hasattr(child, "data"):
                if child.data == "getattr" and child.children[1].value in DICT_METHODS:
                    return True
                pending.append(child)
    return False


def _float_value(node) -> float:
    """The value of a float literal, signed or not (see _float_constant)."""
    if node.data == "unary":
        value = node.children[1].children[0]
        return -value if node.children[0].value == "-" else +value
    return node.children[0]


class FunctionCompiler(ExpressionCompiler):
    """Builds one deck function's Python code."""

    def __init__(self, function, evaluator, runtime: CompiledRuntime):
        self.function = function
        self.evaluator = evaluator
        self.runtime = runtime
        self.frame = Frame(None, None, function.closure.module)
        self.nodes: list = []  # deck node of each line (line = index + 1)
        self.sites: list = []  # (call node, frame) of each call site
        self.global_reads: dict[int, str] = {}  # line -> name read from the namespace
        self.temps = 0
        self.parameters = list(function.parameters)
        self.local_names = set(self.parameters)
        self.definite = set(self.parameters)  # locals surely bound at this point
        self.float_locals: set[str] = set()  # locals only ever given float constants
        self.constants: dict[int, tuple[str, object]] = {}  # id -> (closure name, object)
        self.float_lists: dict[str, tuple[int, tuple]] = {}  # see _float_lists
        self.namespace_get = evaluator.namespace.get  # one bound method for all reads

    # ------------------------------------------------------------- building

    def build(self):
        function = self.function
        head_line = self.line(function.body)
        if function.is_lambda:
            body = [_stamp(ast.Return(self.expr(function.body)), head_line)]
        else:
            self._collect_locals(function.body)
            self.float_lists = self._float_lists(function.body)
            body = self.suite(function.body)
        initial = [
            ast.Assign([_name(name, store=True)], _name("__UNB"))
            for name in sorted(self.local_names - set(self.parameters))
        ]
        inner = self._wrap(initial + body, head_line)
        factory = ast.FunctionDef(
            name="__factory",
            args=_arguments([*RUNTIME_NAMES, *(name for name, _ in self.constants.values())]),
            body=[inner, ast.Return(_name("__deck_function"))],
            decorator_list=[],
        )
        module = ast.Module([_stamp(factory, head_line)], type_ignores=[])
        label = f"<deck function {function.name}>"
        code = compile(module, label, "exec", dont_inherit=True)
        factory_code = next(c for c in code.co_consts if isinstance(c, types.CodeType))
        make = types.FunctionType(factory_code, {"__builtins__": {}})
        code_holder: list = []
        constants = [value for _, value in self.constants.values()]
        compiled = make(*self._runtime_values(code_holder), *constants)
        code_holder.append(compiled.__code__)
        return compiled

    def _wrap(self, body: list, line: int) -> ast.FunctionDef:
        """The deck function: its step and depth, its body, its error locating."""
        budget = _name("__b")
        prologue = [
            *_tick(),
            ast.If(
                ast.Compare(
                    ast.Attribute(budget, "depth", ast.Load()),
                    [ast.GtE()],
                    [ast.Constant(self.evaluator.budget.max_depth)],
                ),
                [ast.Expr(ast.Call(ast.Attribute(_name("__b"), "too_deep", ast.Load()), [], []))],
                [],
            ),
            _add_to(ast.Attribute(_name("__b"), "depth", ast.Store()), 1),
        ]
        locate = ast.Expr(
            _call(
                "__rt_locate",
                _name("__e"),
                ast.Subscript(_name("__code"), ast.Constant(0), ast.Load()),
                _name("__nodes"),
                _name("__frame"),
                _name("__reads"),
            )
        )
        guarded = ast.Try(
            body=body or [ast.Pass()],
            handlers=[ast.ExceptHandler(_name("__CONV"), "__e", [locate, ast.Raise()])],
            orelse=[],
            finalbody=[_add_to(ast.Attribute(_name("__b"), "depth", ast.Store()), -1)],
        )
        return _stamp(
            ast.FunctionDef(
                name="__deck_function",
                args=_arguments(self.parameters),
                body=prologue + [guarded],
                decorator_list=[],
            ),
            line,
        )

    def _runtime_values(self, code_holder: list) -> list:
        rt = self.runtime
        values = {
            "__b": self.evaluator.budget,
            "__G": self.evaluator.namespace,
            "__T": type,
            "__U": Unknown,
            "__UNB": UNBOUND,
            "__S": CHAIN,
            "__DF": rt.deck_function_type,
            "__PC": PLAIN_CALLABLES,
            "__SC": PLAIN_SCALARS,
            "__IF": INT_OR_FLOAT,
            "__CM": COMPARABLE,
            "__FL": float,
            "__IN": int,
            "__TU": tuple,
            "__LI": list,
            "__LEN": len,
            "__sites": self.sites,
            "__code": code_holder,
            "__nodes": self.nodes,
            "__frame": self.frame,
            "__reads": self.global_reads,
            "__CONV": rt.converted,
            "__rt_binary": rt.binary,
            "__rt_augmented": rt.augmented,
            "__rt_compare": rt.compare,
            "__rt_attribute": rt.attribute,
            "__rt_key": rt.key,
            "__rt_item": rt.item,
            "__rt_keyed_item": rt.keyed_item,
            "__rt_slice": rt.slice,
            "__rt_index_tuple": rt.index_tuple,
            "__rt_store_item": rt.store_item,
            "__rt_augmented_item": rt.augmented_item,
            "__rt_unpack": rt.unpack,
            "__rt_call": rt.call,
            "__rt_call_kw": rt.call_with_keywords,
            "__rt_locate": rt.locate,
        }
        return [values[name] for name in RUNTIME_NAMES]

    def constant(self, value) -> str:
        """The closure name under which the generated code reaches ``value``
        (an object seen when compiling: a callee, Exception...)."""
        key = id(value)
        if key not in self.constants:
            self.constants[key] = (f"__K{len(self.constants)}", value)
        return self.constants[key][0]

    def line(self, node) -> int:
        self.nodes.append(node)
        return len(self.nodes)

    def temp(self) -> str:
        self.temps += 1
        return f"__t{self.temps}"

    # --------------------------------------------------------------- locals

    def _collect_locals(self, suite) -> None:
        """Every name the body may bind: assignment, augmented assignment and
        loop targets, and names of containers stored into (which become
        Unknown when a list is given Unknown, as the interpreter does)."""
        pending = [suite]
        constant, other = set(), set()
        while pending:
            node = pending.pop()
            if not hasattr(node, "data"):
                continue
            kind = node.data
            if kind in ("funcdef", "lambdef", "listcomp", "dictcomp", "generator_argument"):
                raise Refused(kind)
            if kind == "assign":
                value = node.children[-1]
                for target in node.children[:-1]:
                    names = self._target_names(target)
                    if target.data == "var" and _float_constant(value):
                        constant.update(names)
                    else:
                        other.update(names)
            elif kind in ("augassign", "for_stmt"):
                other.update(self._target_names(node.children[0]))
            pending.extend(child for child in node.children if hasattr(child, "data"))
        self.float_locals = constant - other - set(self.parameters)

    def _float_lists(self, suite) -> dict[str, tuple[int, tuple]]:
        """Locals given a list or tuple of float constants once, by a statement
        of the body's top level, and read nowhere but as what a ``for``
        iterates over (itself or an argument of ``zip``): nothing can change
        them, their items are floats. {name: (statement index, items)}."""
        assigned: dict[str, list] = {}
        for index, statement in enumerate(suite.children):
            if getattr(statement, "data", None) != "assign" or len(statement.children) != 2:
                continue
            target, value = statement.children
            if (
                target.data == "var"
                and value.data in ("list", "tuple")
                and value.children
                and all(_float_constant(item) for item in value.children)
            ):
                items = tuple(_float_value(item) for item in value.children)
                assigned.setdefault(target.children[0].value, []).append((index, items))
        occurrences: dict[str, int] = {}
        iterated: dict[str, int] = {}
        pending = [suite]
        while pending:
            node = pending.pop()
            if not hasattr(node, "data"):
                continue
            if node.data == "var":
                name = node.children[0].value
                occurrences[name] = occurrences.get(name, 0) + 1
            elif node.data == "for_stmt":
                iterable = node.children[1]
                read = []
                if iterable.data == "var":
                    read = [iterable]
                elif (
                    iterable.data == "funccall"
                    and iterable.children[0].data == "var"
                    and iterable.children[0].children[0].value == "zip"
                    and iterable.children[1] is not None
                    and iterable.children[1].data == "arguments"
                ):
                    read = [a for a in iterable.children[1].children if a.data == "var"]
                for argument in read:
                    name = argument.children[0].value
                    iterated[name] = iterated.get(name, 0) + 1
            pending.extend(child for child in node.children if hasattr(child, "data"))
        return {
            name: places[0]
            for name, places in assigned.items()
            if len(places) == 1
            and name not in self.parameters
            and occurrences.get(name, 0) == 1 + iterated.get(name, 0)
        }

    def _target_names(self, target) -> set[str]:
        """The names ``target`` binds, added to the locals."""
        names = set()
        if target.data == "var":
            names.add(target.children[0].value)
        elif target.data in ("tuple", "list"):
            for child in target.children:
                names |= self._target_names(child)
        elif target.data == "getitem" and target.children[0].data == "var":
            names.add(target.children[0].children[0].value)
        self.local_names |= names
        return names

    # ----------------------------------------------------------- statements

    def suite(self, suite) -> list:
        statements = []
        for child in suite.children:
            statements.extend(self.statement(child))
        return statements

    def statement(self, node) -> list:
        if not hasattr(node, "data"):
            return []
        method = getattr(self, f"_s_{node.data}", None)
        if method is None:
            raise Refused(node.data)
        line = self.line(node)
        return _stamp(method(node, line), line)

    def _s_simple_stmt(self, node, line):
        return [s for child in node.children for s in self.statement(child)]

    def _s_expr_stmt(self, node, line):
        return [ast.Expr(self.expr(node.children[0]))]

    def _s_pass_stmt(self, node, line):
        return [ast.Pass()]

    def _s_break_stmt(self, node, line):
        return [ast.Break()]

    def _s_continue_stmt(self, node, line):
        return [ast.Continue()]

    def _s_return_stmt(self, node, line):
        value = node.children[-1]
        return [ast.Return(ast.Constant(None) if value is None else self.expr(value))]

    def _s_assign(self, node, line):
        *targets, value_node = node.children
        assigned = None
        if len(targets) == 1 and targets[0].data == "var" and value_node.data == "funccall":
            assigned = targets[0].children[0].value
        value = self.expr(value_node, assigned_name=assigned)
        if len(targets) == 1 and targets[0].data == "var":
            return self._bind(targets[0].children[0].value, value)
        target = targets[0]
        if (
            len(targets) == 1
            and isinstance(value, (ast.Tuple, ast.List))
            and target.data in ("tuple", "list")
            and len(target.children) == len(value.elts)
            and all(t.data == "var" for t in target.children)
        ):  # a, b = x, y: every value first, then the names, as Python does
            names = [t.children[0].value for t in target.children]
            self.definite.update(names)
            store = ast.Tuple([_name(n, store=True) for n in names], ast.Store())
            return [ast.Assign([store], ast.Tuple(value.elts, ast.Load()))]
        held = self.temp()
        statements = [ast.Assign([_name(held, store=True)], value)]
        for target in targets:
            statements.extend(self.assign_target(target, held, line))
        return statements

    def _bind(self, name: str, value: ast.expr) -> list:
        self.definite.add(name)
        return [ast.Assign([_name(name, store=True)], value)]

    def assign_target(self, target, held: str, line: int) -> list:
        """Statements binding ``target`` to the value in the temporary ``held``."""
        kind = target.data
        if kind == "var":
            return self._bind(target.children[0].value, _name(held))
        if kind in ("tuple", "list"):
            return self._unpack(target.children, held, line)
        return self._store_item(target, _name(held), line)

    def _unpack(self, targets, held: str, line: int) -> list:
        count = len(targets)
        items = self.temp()
        exact = _all(  # a tuple of the right size unpacks natively
            [
                _type_is(_name(held), "__TU"),
                ast.Compare(_call("__LEN", _name(held)), [ast.Eq()], [ast.Constant(count)]),
            ]
        )
        statements = [
            ast.Assign(
                [_name(items, store=True)],
                ast.IfExp(
                    exact,
                    _name(held),
                    _stamp(_call("__rt_unpack", _name(held), ast.Constant(count)), line),
                ),
            )
        ]
        if all(t.data == "var" for t in targets):
            names = [t.children[0].value for t in targets]
            self.definite.update(names)
            store = ast.Tuple([_name(n, store=True) for n in names], ast.Store())
            return statements + [ast.Assign([store], _name(items))]
        for position, target in enumerate(targets):
            element = self.temp()
            statements.append(
                ast.Assign(
                    [_name(element, store=True)],
                    ast.Subscript(_name(items), ast.Constant(position), ast.Load()),
                )
            )
            statements.extend(self.assign_target(target, element, line))
        return statements

    def _store_item(self, target, value: ast.expr, line: int) -> list:
        container_node, index_node = target.children
        container, index = self.temp(), self.temp()
        statements = [
            ast.Assign([_name(container, store=True)], self.expr(container_node)),
            ast.Assign([_name(index, store=True)], self.index(index_node, keyed=False)),
        ]
        plain = index_node.data not in ("slice", "subscript_tuple")
        checked_index = _call("__rt_key", _name(index)) if plain else _name(index)
        slow = ast.If(
            _stamp(_call("__rt_store_item", _name(container), checked_index, value), line),
            self._becomes_unknown(container_node),
            [],
        )
        if not plain:
            return statements + [slow]
        fast_test = _all(
            [
                _type_is(_name(index), "__IN"),
                _type_is(_name(container), "__LI"),
                ast.Compare(_copy(value), [ast.IsNot()], [_name("__U")]),
            ]
        )
        store = ast.Assign(
            [ast.Subscript(_name(container), _name(index), ast.Store())], _copy(value)
        )
        return statements + [ast.If(fast_test, [store], [slow])]

    def _becomes_unknown(self, container_node) -> list:
        if container_node.data != "var":
            return [ast.Pass()]
        return [ast.Assign([_name(container_node.children[0].value, store=True)], _name("__U"))]

    def _s_augassign(self, node, line):
        target, op_token, value_node = node.children
        op = op_token.value
        symbol = op[:-1]
        if target.data == "var":
            name = target.children[0].value
            current = self.operand_ast(self.read(target))
            value = self.operand(value_node)
            if name in self.definite and value.static is float and symbol in BINARY:
                return [ast.AugAssign(_name(name, store=True), BINARY[symbol](), value.expression)]
            result = self.guarded(
                [current, value],
                self._binary_guard(symbol, current, value),
                lambda refs: ast.BinOp(refs[0], BINARY[symbol](), refs[1]),
                lambda refs: _call("__rt_augmented", ast.Constant(op), *refs),
            )
            return self._bind(name, result)
        container_node, index_node = target.children
        container, index = self.temp(), self.temp()
        plain = index_node.data not in ("slice", "subscript_tuple")
        index_value = self.index(index_node, keyed=False)
        if plain:
            index_value = _stamp(_call("__rt_key", index_value), line)
        statements = [
            ast.Assign([_name(container, store=True)], self.expr(container_node)),
            ast.Assign([_name(index, store=True)], index_value),
        ]
        update = _call(
            "__rt_augmented_item",
            ast.Constant(op),
            _name(container),
            _name(index),
            self.expr(value_node),
        )
        return statements + [ast.If(update, self._becomes_unknown(container_node), [])]

    def _s_if_stmt(self, node, line):
        branches, otherwise = if_branches(node)
        entry = set(self.definite)
        outcomes = []
        built = []
        for test_node, body_node in branches:
            self.definite = set(entry)  # the tests run before any branch
            test = self.expr(test_node)
            entry = set(self.definite)
            body = self.suite(body_node) or [ast.Pass()]
            outcomes.append(self.definite)
            built.append((test, body))
        self.definite = set(entry)
        orelse = self.suite(otherwise) if otherwise is not None else []
        outcomes.append(self.definite)
        self.definite = set.intersection(*outcomes)
        for test, body in reversed(built):
            orelse = [ast.If(test, body, orelse)]
        return orelse

    def _s_while_stmt(self, node, line):
        condition, suite, else_clause = node.children
        entry = set(self.definite)
        test = self.expr(condition)
        body = _stamp(_tick(), line) + self.suite(suite)
        self.definite = set(entry)
        orelse = self.suite(else_clause.children[0]) if else_clause is not None else []
        self.definite = entry
        return [ast.While(test, body, orelse)]

    def _s_for_stmt(self, node, line):
        target, iterable_node, suite, else_clause = node.children
        iterable = self.expr(iterable_node)
        entry = set(self.definite)
        if target.data == "var":
            name = target.children[0].value
            variable = name
            self.definite.add(name)
            binding = []
        else:
            variable = self.temp()
            binding = self.assign_target(target, variable, line)
        body = _stamp(_tick(), line) + binding + self.suite(suite)
        self.definite = set(entry)
        orelse = self.suite(else_clause.children[0]) if else_clause is not None else []
        self.definite = entry
        try:
            typed = FastLoop(self, node, line)
            return typed.build(iterable, variable, body, orelse)
        except Refused:
            return [ast.For(_name(variable, store=True), iterable, body, orelse)]

    # ---------------------------------------------------------- expressions
