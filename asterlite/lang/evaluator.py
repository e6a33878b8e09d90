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
"""

from __future__ import annotations

import itertools
import operator
from collections.abc import Callable, Mapping

from asterlite.errors import AsterliteError, DeckRuntimeError, Location, did_you_mean
from asterlite.lang import library
from asterlite.lang import limits as guards
from asterlite.lang.budget import StepBudget
from asterlite.lang.calls import bind_arguments, contains_unknown
from asterlite.lang.compiler import compile_function
from asterlite.lang.deck_function import DeckFunction, Frame
from asterlite.lang.exceptions import python_error
from asterlite.lang.flow import FlowStatements
from asterlite.lang.imports import ImportStatements
from asterlite.lang.library import DEEP, DIRECT, STORE, DeckModule
from asterlite.lang.limits import Limits
from asterlite.lang.operators import (
    BINARY_OPERATORS,
    COMPARISONS,
    CONVERTED_ERRORS,
    INPLACE_OPERATORS,
    UNARY_OPERATORS,
)
from asterlite.lang.parser import Module, node_position
from asterlite.lang.python2 import DICT_METHODS as PYTHON2_DICT_METHODS
from asterlite.lang.python2 import dict_method
from asterlite.lang.values import CallSite, DeckCallable, Unknown

_DEEP_SCAN_BUDGET = 100_000  # elements inspected when looking for Unknown in arguments


class _Break(Exception):
    pass


class _Continue(Exception):
    pass


class _Return(Exception):
    def __init__(self, value):
        self.value = value


class _Escaped(Exception):
    """A non-deck exception from a DeckCallable (a bug in a command, a full
    disk): re-raised by Evaluator.run rather than disguised as a deck error,
    with the call's location as its ``deck_location`` attribute."""

    def __init__(self, original: BaseException, location: Location | None = None):
        self.original = original
        attach_location(original, location)


def attach_location(error: BaseException, location: Location | None) -> None:
    """Note where in the deck a non-deck exception arose (``deck_location``)."""
    if location is not None and getattr(error, "deck_location", None) is None:
        try:
            error.deck_location = location
        except AttributeError:  # an exception type without a __dict__
            pass


class Evaluator(ImportStatements, FlowStatements):
    """Runs parsed modules in a shared namespace.

    ``module_loader(name) -> dict | None`` provides importable modules beyond
    ``math`` and ``numpy`` (code_aster, the deck's helper files); loaded
    modules are cached per evaluator.
    """

    _FLOW = (_Break, _Continue, _Return)  # control flow, which try/with let through

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
        from asterlite.lang import python2

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
        if function.direct is not None:  # its prologue takes the step and the depth
            return function.direct(*[local_names[name] for name in function.parameters])
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
        except _Return as result:
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
        except _Escaped as escaped:
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
        raise _Break

    def _continue_stmt(self, node, frame):
        raise _Continue

    def _return_stmt(self, node, frame):
        value_node = node.children[-1]
        raise _Return(None if value_node is None else self.ev(value_node, frame))

    def _assert_stmt(self, node, frame):
        condition_node, message_node = node.children
        condition = self.ev(condition_node, frame)
        if condition is Unknown or condition:
            return
        message = "" if message_node is None else f": {self.ev(message_node, frame)}"
        raise python_error(AssertionError, f"assertion failed{message}")

    def _if_stmt(self, node, frame):
        condition, suite, *clauses = node.children
        if self._truth(self.ev(condition, frame)):
            self._exec_suite(suite, frame)
            return
        for clause in clauses:
            if clause is None:
                continue
            if clause.data == "elif_clause":
                if self._truth(self.ev(clause.children[0], frame)):
                    self._exec_suite(clause.children[1], frame)
                    return
            else:
                self._exec_suite(clause.children[0], frame)

    def _while_stmt(self, node, frame):
        condition, suite, else_clause = node.children
        while self._truth(self.ev(condition, frame)):
            self._step()
            try:
                self._exec_suite(suite, frame)
            except _Break:
                return
            except _Continue:
                continue
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
            except _Break:
                return
            except _Continue:
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

    def _const(self, node, frame):
        return node.children[0]

    def _const_none(self, node, frame):
        return None

    def _const_true(self, node, frame):
        return True

    def _const_false(self, node, frame):
        return False

    def _var(self, node, frame):
        return self._lookup(node, frame)

    def _tuple(self, node, frame):
        return tuple(self.ev(child, frame) for child in node.children)

    def _list(self, node, frame):
        return [self.ev(child, frame) for child in node.children]

    def _set(self, node, frame):
        return {self._key(self.ev(child, frame)) for child in node.children}

    def _dict(self, node, frame):
        result = {}
        for pair in node.children:
            key = self._key(self.ev(pair.children[0], frame))
            result[key] = self.ev(pair.children[1], frame)
        return result

    def _key(self, value):
        """A value about to be hashed (set item, dict key, index): its nesting checked."""
        guards.check_hash_depth(value, self.limits)
        return value

    def _listcomp(self, node, frame):
        comprehension = node.children[0]
        element, *loops = comprehension.children
        result = []
        inner = Frame({}, frame, frame.module)
        self._comprehend(loops, inner, lambda f: result.append(self.ev(element, f)), outer=True)
        return result

    def _dictcomp(self, node, frame):
        pair, *loops = node.children
        result = {}

        def add(inner):
            key = self._key(self.ev(pair.children[0], inner))
            result[key] = self.ev(pair.children[1], inner)

        self._comprehend(loops, Frame({}, frame, frame.module), add, outer=True)
        return result

    def _comprehend(self, loops, frame: Frame, emit, outer=False) -> None:
        """Run nested comprehension loops in their own frame; the outermost
        iterable is evaluated in the enclosing frame, as Python does."""
        loop, *rest = loops
        target, iterable_node, *conditions = loop.children
        for item in self.ev(iterable_node, frame.parent if outer else frame):
            self._step()
            self._assign_target(target, item, frame)
            if all(self._truth(self.ev(c.children[0], frame)) for c in conditions):
                if rest:
                    self._comprehend(rest, frame, emit)
                else:
                    emit(frame)

    def _lambdef(self, node, frame):
        parameters, body = node.children
        return self._make_function("<lambda>", parameters, body, frame, is_lambda=True)

    def _ternary(self, node, frame):
        if_true, condition, if_false = node.children
        test = self.ev(condition, frame)
        if test is Unknown:
            return Unknown
        return self.ev(if_true if self._truth(test) else if_false, frame)

    def _or_test(self, node, frame):
        value = None
        for child in node.children:
            value = self.ev(child, frame)
            if self._truth(value):
                return value
        return value

    def _and_test(self, node, frame):
        value = None
        for child in node.children:
            value = self.ev(child, frame)
            if not self._truth(value):
                return value
        return value

    def _not(self, node, frame):
        value = self.ev(node.children[0], frame)
        return Unknown if value is Unknown else not self._truth(value)

    def _comparison(self, node, frame):
        left = self.ev(node.children[0], frame)
        result = True
        for position in range(1, len(node.children), 2):
            op = "".join(token.value for token in node.children[position].children)
            right = self.ev(node.children[position + 1], frame)
            if left is Unknown or right is Unknown:
                return Unknown
            guards.check_binary("==", left, right, self.limits)
            if op in ("in", "notin"):
                self._key(left)
            result = COMPARISONS[op](left, right)
            if position + 2 < len(node.children) and not self._truth(result):
                return result
            left = right
        return result

    def _chain(self, node, frame):
        """arith_expr / term: operand (op operand)*, left to right."""
        children = node.children
        value = self.ev(children[0], frame)
        for position in range(1, len(children), 2):
            right = self.ev(children[position + 1], frame)
            value = self._binary(children[position].value, value, right)
        return value

    def _bitwise(self, op):
        def evaluate(node, frame):
            value = self.ev(node.children[0], frame)
            for child in node.children[1:]:
                value = self._binary(op, value, self.ev(child, frame))
            return value

        return evaluate

    def _power(self, node, frame):
        base = self.ev(node.children[0], frame)
        exponent = self.ev(node.children[1], frame)
        return self._binary("**", base, exponent)

    def _unary(self, node, frame):
        op, operand_node = node.children
        operand = self.ev(operand_node, frame)
        if operand is Unknown:
            return Unknown
        return UNARY_OPERATORS[op.value](operand)

    def _binary(self, op: str, left, right, function=None):
        if left is Unknown or right is Unknown:
            return Unknown
        if function is operator.iadd and type(left) is list and type(right) is not list:
            # list += any iterable extends the list: read the iterable within the limit
            room = self.limits.max_sequence_length - len(left)
            right = guards.bounded_items(right, room, self.limits)
        arrays = guards.check_binary(op, left, right, self.limits)
        if op == "%" and isinstance(left, str):  # engine objects print neutrally
            right = guards.deck_text_value(right)
        result = (function or BINARY_OPERATORS[op])(left, right)
        if arrays:
            guards.check_array_result(result)
        return result

    def _truth(self, value) -> bool:
        return bool(value)

    def _getattr(self, node, frame):
        value = self.ev(node.children[0], frame)
        if value is Unknown:
            return Unknown
        name = node.children[1].value
        if type(value) is dict and frame.module.python2 and name in PYTHON2_DICT_METHODS:
            return dict_method(value, name, self.limits)
        return library.get_attribute(value, name, self.limits)

    def _getitem(self, node, frame):
        container = self.ev(node.children[0], frame)
        index = self._index(node.children[1], frame)
        if container is Unknown or index is Unknown:
            return Unknown
        return container[index]

    def _index(self, node, frame):
        if node.data == "slice":
            bounds = [None if part is None else self.ev(part, frame) for part in node.children]
            return Unknown if Unknown in bounds else slice(*bounds)
        if node.data == "subscript_tuple":
            parts = tuple(self._index(child, frame) for child in node.children)
            return Unknown if any(part is Unknown for part in parts) else self._key(parts)
        return self._key(self.ev(node, frame))

    # ------------------------------------------------------------------ calls

    def _funccall(self, node, frame, assigned_name=None):
        callee_node, arguments = node.children
        callee = self.ev(callee_node, frame)
        args, kwargs, keyword_locations, spread_unknown = self._arguments(arguments, frame)
        if spread_unknown:
            return Unknown
        return self.invoke(callee, args, kwargs, keyword_locations, node, frame, assigned_name)

    def invoke(self, callee, args, kwargs, keyword_locations, node, frame, assigned_name=None):
        """Call an evaluated callee with evaluated arguments (``node``, the call,
        locates it for commands)."""
        if callee is Unknown:
            return Unknown
        if isinstance(callee, DeckCallable):
            location = self.location(node, frame.module)
            site = CallSite(location, keyword_locations, assigned_name)
            if not isinstance(callee, DeckFunction):  # commands may hash or recurse on it
                guards.check_nesting((args, kwargs), self.limits)
            try:
                return callee.deck_call(args, kwargs, site)
            except (AsterliteError, _Escaped, _Return, RecursionError):
                raise
            except Exception as error:  # a bug in a command, not a deck error
                raise _Escaped(error, location) from error
        if not callable(callee):
            raise python_error(TypeError, f"'{type(callee).__name__}' object is not callable")
        return self._call_python(callee, args, kwargs)

    def _call_python(self, callee, args: list, kwargs: dict):
        if hasattr(type(getattr(callee, "__self__", None)), "deck_methods"):
            guards.check_nesting((args, kwargs), self.limits)  # a concept's method
        policy = self._unknown_policy(callee)
        if policy != STORE:
            values = (*args, *kwargs.values())
            if any(value is Unknown for value in values):
                return Unknown
            if policy == DEEP and contains_unknown(values, _DEEP_SCAN_BUDGET):
                return Unknown
        return callee(*args, **kwargs)

    def _unknown_policy(self, callee) -> str:
        policy = getattr(callee, "deck_unknown_policy", None)
        if policy is not None:
            return policy
        owner = getattr(callee, "__self__", None)
        if isinstance(owner, (list, dict, set)) or hasattr(type(owner), "deck_methods"):
            return STORE
        return DIRECT if id(callee) in self._structural else DEEP

    def _arguments(self, arguments, frame: Frame):
        args, kwargs, keyword_locations, spread_unknown = [], {}, {}, False
        if arguments is None:
            return args, kwargs, keyword_locations, spread_unknown
        if arguments.data == "generator_argument":
            return [self._listcomp(arguments, frame)], kwargs, keyword_locations, False
        for argument in arguments.children:
            kind = argument.data
            if kind == "kwarg":
                key_node, value_node = argument.children
                name = key_node.children[0].value
                kwargs[name] = self.ev(value_node, frame)
                keyword_locations[name] = self.location(key_node, frame.module)
            elif kind == "star_arg":
                value = self.ev(argument.children[0], frame)
                if value is Unknown:
                    spread_unknown = True
                else:
                    args.extend(value)
            elif kind == "double_star_arg":
                value = self.ev(argument.children[0], frame)
                if value is Unknown:
                    spread_unknown = True
                    continue
                location = self.location(argument, frame.module)
                for name in value:
                    if not isinstance(name, str):
                        raise DeckRuntimeError("keywords must be strings")
                    if name in kwargs:
                        raise DeckRuntimeError(f"got multiple values for keyword argument '{name}'")
                    kwargs[name] = value[name]
                    keyword_locations[name] = location
            else:
                args.append(self.ev(argument, frame))
        return args, kwargs, keyword_locations, spread_unknown


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
