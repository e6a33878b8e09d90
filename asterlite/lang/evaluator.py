"""A tree-walking evaluator for parsed decks.

It runs the checked lark tree of :mod:`asterlite.lang.parser` statement by
statement in a namespace shared by every module of a session (code_aster's
DEBUT/POURSUITE: a second deck file continues with the same names). Nothing
reaches Python's ``exec``/``eval``/``getattr``: names come from the namespace,
attributes from the whitelists of :mod:`asterlite.lang.library`, and every
loop, call and allocation is bounded by :class:`Limits`.

``Unknown`` (the value of what ``asterlite check`` does not compute) flows
through: operations on it give Unknown, it is falsy, iterating it yields
nothing, storing it into a numpy array makes the array Unknown.

``overrides`` (``asterlite sweep --set NAME=value``) replace deck-level
variables: when a plain ``NAME = expression`` statement outside any ``def``
assigns a name in ``overrides``, the expression is still evaluated (it may
call a command whose side effects later statements rely on), then the
override value is bound instead. Tuple unpacking, augmented assignment,
``for`` targets and names local to deck functions are left alone.
``overrides_used`` records the names that were replaced.

This module runs statements; expressions and calls are computed by
:mod:`asterlite.lang.expressions`, ``try``/``raise``/``with`` by
:mod:`asterlite.lang.flow`, imports by :mod:`asterlite.lang.imports`
(mixins of :class:`Evaluator`).
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Mapping

from asterlite.errors import AsterliteError, DeckRuntimeError, Location, did_you_mean
from asterlite.lang import library, python2
from asterlite.lang import limits as guards
from asterlite.lang.bindings import method_receivers, statement_outputs
from asterlite.lang.budget import StepBudget
from asterlite.lang.calls import bind_arguments
from asterlite.lang.compiler import compile_function
from asterlite.lang.deck_function import DeckFunction, Frame
from asterlite.lang.exceptions import python_error
from asterlite.lang.expressions import (
    BreakSignal,
    ContinueSignal,
    Escaped,
    ExpressionEvaluation,
    ReturnSignal,
    attach_location,
)
from asterlite.lang.flow import FlowStatements
from asterlite.lang.imports import ImportStatements
from asterlite.lang.library import DeckModule
from asterlite.lang.limits import Limits
from asterlite.lang.operators import (
    CONVERTED_ERRORS,
    INPLACE_OPERATORS,
)
from asterlite.lang.parser import Module
from asterlite.lang.tree_checks import node_position
from asterlite.lang.values import Unknown


class Evaluator(ExpressionEvaluation, ImportStatements, FlowStatements):
    """Runs parsed modules in a shared namespace.

    ``module_loader(name) -> dict | None`` provides importable modules beyond
    ``math`` and ``numpy`` (code_aster, the deck's helper files); loaded
    modules are cached per evaluator.
    """

    _FLOW = (BreakSignal, ContinueSignal, ReturnSignal)  # control flow, which try/with let through

    def __init__(
        self,
        namespace: dict,
        *,
        filename_sources: dict | None = None,
        module_loader: Callable[[str], dict | None] | None = None,
        limits: Limits = Limits(),  # noqa: B008 - frozen dataclass, shared safely
        overrides: Mapping[str, object] | None = None,
        compile_functions: bool = True,
    ):
        self.namespace = namespace
        self.overrides = dict(overrides or {})
        self.overrides_used: set[str] = set()  # override names some assignment replaced
        self.sources = dict(filename_sources or {})  # filename -> text or lines, for excerpts
        self.module_loader = module_loader
        self.limits = limits
        self.budget = StepBudget(limits)  # steps and call depth, shared with compiled code
        self.compile_functions = compile_functions  # False: interpret every deck function
        self.modules: dict[str, DeckModule] = {}
        self._builtin_modules = library.builtin_modules(limits)
        self._structural = library.structural_ids(namespace)
        self._compiled_runtime = None  # helpers of compiled functions, built on first use
        self._literals_checked: dict[int, object] = {}  # id(tree) -> tree, literals checked

    @property
    def steps(self) -> int:
        """Loop iterations and function calls so far."""
        return self.budget.steps

    @property
    def depth(self) -> int:
        """Nested deck function calls under way."""
        return self.budget.depth

    # ------------------------------------------------------------ public API

    def run(self, module: Module, on_error=None) -> None:
        """Execute a parsed deck's statements, binding names in the namespace.

        ``on_error(error, statement)``, when given, receives the deck error of
        a failed top-level statement, and the run goes on with the next one
        (``asterlite check`` reports every error of a deck); it may re-raise.
        """
        self.sources.setdefault(module.filename, module.lines)
        self._check_literals(module)
        if module.python2:
            self._python2_builtins()
        frame = Frame(None, None, module)
        try:
            for statement in module.tree.children:
                try:
                    self._guarded(lambda s=statement: self._exec(s, frame), statement, module)
                except AsterliteError as error:
                    if on_error is None or getattr(error, "fatal", False):  # e.g. time limit
                        raise
                    on_error(error, statement)
        finally:
            if module.python2:
                self.flush_print()

    def _python2_builtins(self) -> None:
        """A Python 2 deck's namespace: map, zip, range... give lists (once)."""

        if not self.namespace.get("__python2__"):
            self.namespace.update(python2.builtins(self.namespace, self.limits))
            self.namespace["__python2__"] = True  # no deck name starts with '__'

    def evaluate(self, module: Module, names: dict | None = None):
        """Value of a module from :func:`parse_expression`, with extra local names."""
        frame = Frame(dict(names or {}), None, module)
        self._check_literals(module)
        expression = module.tree.children[0]
        return self._guarded(lambda: self.ev(expression, frame), expression, module)

    def call_function(self, function: DeckFunction, args: list, kwargs: dict):
        """Call a deck function (from the deck or from Python)."""
        local_names = bind_arguments(function, args, kwargs)
        if not function.compile_tried:
            self._compile(function)
        values = [local_names[name] for name in function.parameters]
        # its prologue takes the step and the depth; an Unknown argument (check)
        # runs interpreted, where a test on it leaves every branch undecided
        if function.direct is not None and all(value is not Unknown for value in values):
            return function.direct(*values)
        self._step()
        budget = self.budget
        if budget.depth >= budget.max_depth:
            budget.too_deep()
        frame = Frame(local_names, function.closure, function.closure.module)
        budget.depth += 1
        try:
            if function.is_lambda:
                return self.ev(function.body, frame)
            self._exec_suite(function.body, frame)
        except ReturnSignal as result:
            return result.value
        finally:
            budget.depth -= 1
        return None

    def _compile(self, function: DeckFunction) -> None:
        """Compile a deck function's body once, when this evaluator compiles and
        the body stays within the compiled subset."""
        function.compile_tried = True
        if not self.compile_functions or function.evaluator is not self:
            return
        direct = compile_function(function, self)
        if direct is not None:
            function.direct = direct
            function.arity = len(function.parameters)

    # ------------------------------------------------------------- machinery

    def _check_literals(self, module: Module) -> None:
        """Integer literals within the digit limit, once per module: the
        parser turns a hexadecimal literal of any length into an integer."""
        tree = module.tree
        if self._literals_checked.get(id(tree)) is tree:
            return
        for node in tree.iter_subtrees():
            if node.data == "const":
                try:
                    guards.check_literal(node.children[0], self.limits)
                except DeckRuntimeError as error:
                    error.location = self.location(node, module)
                    raise
        self._literals_checked[id(tree)] = tree  # the tree kept: its id stays its own

    def _guarded(self, action, node, module: Module):
        """Run one top-level statement: unwrap command bugs, locate stack overflows."""
        try:
            return action()
        except Escaped as escaped:
            raise escaped.original from None
        except RecursionError:
            raise DeckRuntimeError(
                "expression or calls nested too deeply", self.location(node, module)
            ) from None
        except (OSError, MemoryError) as error:  # not a deck error: keep it, located
            attach_location(error, self.location(node, module))
            raise

    def location(self, node, module: Module) -> Location:
        line, column = node_position(node)
        return module.location(line, column)

    def _step(self) -> None:
        budget = self.budget
        budget.steps += 1
        if budget.steps >= budget.next_check:
            budget.check()

    def _fail(self, error: BaseException, node, frame: Frame):
        """Attach the node's location to a deck error, or convert a Python error."""
        if isinstance(error, AsterliteError):
            if error.location is None:
                error.location = self.location(node, frame.module)
            raise error
        if isinstance(error, MemoryError):  # the address-space cap of the run's memory limit
            raise guards.DeckMemoryError(
                "an allocation failed: the run's memory is exhausted (export 'P memory_limit', "
                "or asterlite run --memory-limit to change it)",
                self.location(node, frame.module),
            ) from None
        message = str(error) or type(error).__name__
        converted = python_error(type(error), f"{type(error).__name__}: {message}")
        converted.location = self.location(node, frame.module)
        raise converted from error

    # ------------------------------------------------------------ statements

    def _exec_block(self, statements, frame: Frame) -> None:
        for statement in statements:
            self._exec(statement, frame)

    def _exec_suite(self, suite, frame: Frame) -> None:
        self._exec_block(suite.children, frame)

    def _exec(self, node, frame: Frame) -> None:
        if not hasattr(node, "data"):
            return  # a stray token, not a statement
        try:
            _STATEMENTS[node.data](self, node, frame)
        except (AsterliteError, *CONVERTED_ERRORS) as error:
            self._fail(error, node, frame)

    def _simple_stmt(self, node, frame):
        self._exec_block(node.children, frame)

    def _expr_stmt(self, node, frame):
        self.ev(node.children[0], frame)

    def _assign(self, node, frame):
        *targets, value_node = node.children
        assigned_name = None
        if len(targets) == 1 and targets[0].data == "var" and value_node.data == "funccall":
            assigned_name = targets[0].children[0].value
        if assigned_name:
            try:
                value = self._funccall(value_node, frame, assigned_name)
            except (AsterliteError, *CONVERTED_ERRORS) as error:
                self._fail(error, value_node, frame)
        else:
            value = self.ev(value_node, frame)
        for target in targets:
            self._assign_target(target, self._overridden(target, value, frame), frame)

    def _overridden(self, target, value, frame: Frame):
        """The override for a module-level ``NAME = ...`` target, else ``value``."""
        if frame.locals is not None or target.data != "var":
            return value
        name = target.children[0].value
        if name not in self.overrides:
            return value
        self.overrides_used.add(name)
        return self.overrides[name]

    def _augassign(self, node, frame):
        target, op_token, value_node = node.children
        op, inplace = INPLACE_OPERATORS[op_token.value]
        if target.data == "var":
            current = self._lookup(target, frame)
            value = self.ev(value_node, frame)
            self._store(target.children[0].value, self._binary(op, current, value, inplace), frame)
            return
        container = self.ev(target.children[0], frame)
        index = self._index(target.children[1], frame)
        value = self.ev(value_node, frame)
        if container is Unknown:
            return
        current = Unknown if index is Unknown else container[index]
        self._store_item(target, container, index, self._binary(op, current, value, inplace), frame)

    def _del_stmt(self, node, frame):
        self._delete(node.children[0], frame)

    def _delete(self, target, frame):
        if target.data in ("tuple", "list"):
            for child in target.children:
                self._delete(child, frame)
        elif target.data == "var":
            name = target.children[0].value
            scope = frame.locals if frame.locals is not None else self.namespace
            if name not in scope:
                raise python_error(NameError, f"name '{name}' is not defined")
            del scope[name]
        else:
            container = self.ev(target.children[0], frame)
            index = self._index(target.children[1], frame)
            if container is not Unknown and index is not Unknown:
                del container[index]

    def _pass_stmt(self, node, frame):
        return None

    def _break_stmt(self, node, frame):
        raise BreakSignal

    def _continue_stmt(self, node, frame):
        raise ContinueSignal

    def _return_stmt(self, node, frame):
        value_node = node.children[-1]
        raise ReturnSignal(None if value_node is None else self.ev(value_node, frame))

    def _assert_stmt(self, node, frame):
        condition_node, message_node = node.children
        condition = self.ev(condition_node, frame)
        if condition is Unknown or condition:
            return
        message = "" if message_node is None else f": {self.ev(message_node, frame)}"
        raise python_error(AssertionError, f"assertion failed{message}")

    def _if_stmt(self, node, frame):
        condition, suite, *clauses = node.children
        branches = [(condition, suite)]
        for clause in clauses:
            if clause is not None:
                if clause.data == "elif_clause":
                    branches.append((clause.children[0], clause.children[1]))
                else:
                    branches.append((None, clause.children[0]))
        for index, (test, body) in enumerate(branches):
            value = True if test is None else self.ev(test, frame)
            if value is Unknown:  # check: any branch from here on may run
                self._undecided([b for _, b in branches[index:]], frame)
                return
            if self._truth(value):
                self._exec_suite(body, frame)
                return

    def _undecided(self, bodies, frame) -> None:
        """Under check, blocks that may or may not run (their condition is not
        computed): none is run, and every name they may bind, or whose object
        a method of theirs may change, becomes Unknown."""
        for body in bodies:
            for name in statement_outputs(body) + method_receivers(body):
                self._store(name, Unknown, frame)

    def _while_stmt(self, node, frame):
        condition, suite, else_clause = node.children
        value = self.ev(condition, frame)
        if value is Unknown:
            self._undecided([suite] + ([else_clause] if else_clause is not None else []), frame)
            return
        while self._truth(value):
            self._step()
            try:
                self._exec_suite(suite, frame)
            except BreakSignal:
                return
            except ContinueSignal:
                pass
            value = self.ev(condition, frame)
        if else_clause is not None:
            self._exec_suite(else_clause.children[0], frame)

    def _for_stmt(self, node, frame):
        target, iterable_node, suite, else_clause = node.children
        iterable = self.ev(iterable_node, frame)
        for item in iterable:
            self._step()
            self._assign_target(target, item, frame)
            try:
                self._exec_suite(suite, frame)
            except BreakSignal:
                return
            except ContinueSignal:
                continue
        if else_clause is not None:
            self._exec_suite(else_clause.children[0], frame)

    def _funcdef(self, node, frame):
        name_token, parameters, suite = node.children
        function = self._make_function(name_token.value, parameters, suite, frame)
        self._store(name_token.value, function, frame)

    def _make_function(self, name, parameters, body, frame, is_lambda=False) -> DeckFunction:
        names, defaults = [], {}
        for param in parameters.children if parameters is not None else ():
            param_name, default = param.children
            names.append(param_name.value)
            if default is not None:
                defaults[param_name.value] = self.ev(default, frame)
        return DeckFunction(name, names, defaults, body, frame, self, is_lambda)

    def _lookup(self, node, frame: Frame):
        name = node.children[0].value
        scope = frame
        while scope is not None:
            if scope.locals is not None and name in scope.locals:
                return scope.locals[name]
            scope = scope.parent
        try:
            return self.namespace[name]
        except KeyError:
            near = did_you_mean(name, [*self.namespace, *(frame.locals or ())])
            raise python_error(NameError, f"name '{name}' is not defined{near}") from None

    def _store(self, name: str, value, frame: Frame) -> None:
        if frame.locals is not None:
            frame.locals[name] = value
        else:
            self.namespace[name] = value

    def _assign_target(self, target, value, frame: Frame) -> None:
        kind = target.data
        if kind == "var":
            self._store(target.children[0].value, value, frame)
        elif kind in ("tuple", "list"):
            self._unpack(target.children, value, frame)
        else:  # getitem
            container = self.ev(target.children[0], frame)
            index = self._index(target.children[1], frame)
            self._store_item(target, container, index, value, frame)

    def _unpack(self, targets, value, frame: Frame) -> None:
        if value is Unknown:
            items = [Unknown] * len(targets)
        else:
            items = list(itertools.islice(iter(value), len(targets) + 1))
            if len(items) != len(targets):
                raise python_error(
                    ValueError,
                    f"cannot unpack {'more' if len(items) > len(targets) else len(items)} "
                    f"values into {len(targets)} names",
                )
        for target, item in zip(targets, items, strict=True):
            self._assign_target(target, item, frame)

    def _store_item(self, target, container, index, value, frame: Frame) -> None:
        if container is Unknown:
            return
        if (value is Unknown or index is Unknown) and not isinstance(container, dict):
            # a list or array cannot hold Unknown meaningfully: the whole container is
            if target.children[0].data == "var":
                self._store(target.children[0].children[0].value, Unknown, frame)
            return
        container[index] = value
        if isinstance(container, list):
            guards.check_length(len(container), self.limits)

    # ------------------------------------------------------------ expressions

    def ev(self, node, frame: Frame):
        """The value of an expression node."""
        try:
            return _EXPRESSIONS[node.data](self, node, frame)
        except (AsterliteError, *CONVERTED_ERRORS) as error:
            self._fail(error, node, frame)


_STATEMENTS = {
    "simple_stmt": Evaluator._simple_stmt,
    "expr_stmt": Evaluator._expr_stmt,
    "assign": Evaluator._assign,
    "augassign": Evaluator._augassign,
    "del_stmt": Evaluator._del_stmt,
    "pass_stmt": Evaluator._pass_stmt,
    "break_stmt": Evaluator._break_stmt,
    "continue_stmt": Evaluator._continue_stmt,
    "return_stmt": Evaluator._return_stmt,
    "assert_stmt": Evaluator._assert_stmt,
    "import_name": Evaluator._import_name,
    "import_from": Evaluator._import_from,
    "if_stmt": Evaluator._if_stmt,
    "while_stmt": Evaluator._while_stmt,
    "for_stmt": Evaluator._for_stmt,
    "funcdef": Evaluator._funcdef,
    "try_stmt": Evaluator._try_stmt,
    "try_finally": Evaluator._try_finally,
    "raise_stmt": Evaluator._raise_stmt,
    "raise_py2": Evaluator._raise_py2,
    "with_stmt": Evaluator._with_stmt,
    "print_stmt": Evaluator._print_stmt,
}

_EXPRESSIONS = {
    "const": Evaluator._const,
    "const_none": Evaluator._const_none,
    "const_true": Evaluator._const_true,
    "const_false": Evaluator._const_false,
    "var": Evaluator._var,
    "tuple": Evaluator._tuple,
    "list": Evaluator._list,
    "set": Evaluator._set,
    "dict": Evaluator._dict,
    "listcomp": Evaluator._listcomp,
    "dictcomp": Evaluator._dictcomp,
    "lambdef": Evaluator._lambdef,
    "ternary": Evaluator._ternary,
    "or_test": Evaluator._or_test,
    "and_test": Evaluator._and_test,
    "not_": Evaluator._not,
    "comparison": Evaluator._comparison,
    "arith_expr": Evaluator._chain,
    "term": Evaluator._chain,
    "or_expr": lambda self, node, frame: self._bitwise("|")(node, frame),
    "xor_expr": lambda self, node, frame: self._bitwise("^")(node, frame),
    "and_expr": lambda self, node, frame: self._bitwise("&")(node, frame),
    "power": Evaluator._power,
    "unary": Evaluator._unary,
    "getattr": Evaluator._getattr,
    "getitem": Evaluator._getitem,
    "funccall": Evaluator._funccall,
    "fstring": Evaluator._fstring,
    "backquote": Evaluator._backquote,
}

__all__ = ["DeckFunction", "Evaluator", "Limits"]
