"""Expressions and calls of the deck language: the evaluator's half that
computes values (mixed into :class:`asterlite.lang.evaluator.Evaluator`),
and the signals statements and calls exchange.

Every operation goes through the deck's guards (:mod:`asterlite.lang.limits`)
and the operator table the compiler shares (:mod:`asterlite.lang.operators`);
attributes come from the whitelists of :mod:`asterlite.lang.library`; a
call of a command or a deck function goes through its ``deck_call``, with
the call's location. ``Unknown`` (what ``asterlite check`` does not
compute) flows through every operation.
"""

from __future__ import annotations

import operator

from asterlite.errors import AsterliteError, DeckRuntimeError, Location
from asterlite.lang import library
from asterlite.lang import limits as guards
from asterlite.lang.calls import contains_unknown
from asterlite.lang.deck_function import DeckFunction, Frame
from asterlite.lang.exceptions import python_error
from asterlite.lang.library import DEEP, DIRECT, STORE
from asterlite.lang.operators import (
    BINARY_OPERATORS,
    COMPARISONS,
    UNARY_OPERATORS,
)
from asterlite.lang.python2 import DICT_METHODS as PYTHON2_DICT_METHODS
from asterlite.lang.python2 import dict_method
from asterlite.lang.values import CallSite, DeckCallable, Unknown

DEEP_SCAN_BUDGET = 100_000  # elements inspected when looking for Unknown in arguments


class BreakSignal(Exception):
    """``break``: leaves the innermost loop."""


class ContinueSignal(Exception):
    """``continue``: ends the innermost loop's iteration."""


class ReturnSignal(Exception):
    """``return``: ends the deck function call with ``value``."""

    def __init__(self, value):
        self.value = value


class Escaped(Exception):
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


class ExpressionEvaluation:
    """Mixed into the Evaluator, which provides ``ev`` (the dispatch on node
    kinds), ``_lookup``, ``_fail``, ``_step``, ``_assign_target``,
    ``_make_function``, ``location``, ``limits`` and ``_structural``."""

    # ------------------------------------------------------------ expressions

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
            except (AsterliteError, Escaped, ReturnSignal, RecursionError):
                raise
            except Exception as error:  # a bug in a command, not a deck error
                raise Escaped(error, location) from error
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
            if policy == DEEP and contains_unknown(values, DEEP_SCAN_BUDGET):
                return Unknown
        if getattr(callee, "__module__", None) == "math":
            args = [_scalar_of_size_one(a) for a in args]
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


def _scalar_of_size_one(value):
    """A one-element numpy array as its scalar, for the math module's
    functions: numpy 1 (code_aster's) converts such arrays to floats, numpy 2
    refuses them; decks written for code_aster rely on it."""
    if type(value).__name__ == "ndarray" and getattr(value, "size", 0) == 1:
        return value.item()
    return value
