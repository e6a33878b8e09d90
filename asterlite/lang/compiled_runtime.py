"""What compiled deck functions call besides their own inline code: the slow
paths of each operation, with the interpreter's semantics (Unknown, limits,
messages), and the conversion of an exception into a located deck error.

One :class:`CompiledRuntime` per Evaluator; :mod:`asterlite.lang.compiler`
passes its members to the code it generates as closure variables, never as
Python globals (generated code runs with empty builtins).
"""

from __future__ import annotations

import itertools
import types

from asterlite.errors import AsterliteError, DeckRuntimeError, did_you_mean
from asterlite.lang import library
from asterlite.lang import limits as guards
from asterlite.lang.deck_function import DeckFunction
from asterlite.lang.exceptions import python_error
from asterlite.lang.operators import COMPARISONS, CONVERTED_ERRORS, INPLACE_OPERATORS
from asterlite.lang.values import Unknown

# Python callables the compiled code calls directly when every argument is a
# plain scalar: the interpreter's _call_python does nothing else for them
# (no Unknown to look for, nothing nested to check). DeckCallables never.
PLAIN_CALLABLES = frozenset({types.BuiltinFunctionType, types.FunctionType, type})
PLAIN_SCALARS = frozenset({float, int, str, bool, complex, type(None)})


class Unbound:
    """The value of a local name not assigned yet (reads fall back to the
    deck's names, as the interpreter's frame lookup does)."""

    __slots__ = ()

    def __repr__(self) -> str:
        return "<unbound>"


UNBOUND = Unbound()


class AlwaysTrue:
    """Compared with ``is not`` to chain operand evaluations in one test."""

    __slots__ = ()


CHAIN = AlwaysTrue()


class CompiledRuntime:
    """The helpers compiled functions of one evaluator share."""

    def __init__(self, evaluator):
        self.evaluator = evaluator
        self.limits = evaluator.limits
        self.comparisons = COMPARISONS
        self.inplace = INPLACE_OPERATORS
        self.converted = (AsterliteError, *CONVERTED_ERRORS)
        self.deck_function_type = DeckFunction

    # ---------------------------------------------------------- operations

    def binary(self, op: str, left, right):
        return self.evaluator._binary(op, left, right)

    def augmented(self, op: str, left, right):
        symbol, function = self.inplace[op]
        return self.evaluator._binary(symbol, left, right, function)

    def compare(self, op: str, left, right):
        """One link of a comparison chain, as Evaluator._comparison computes it."""
        if left is Unknown or right is Unknown:
            return Unknown
        guards.check_binary("==", left, right, self.limits)
        if op in ("in", "notin"):
            self.evaluator._key(left)
        return self.comparisons[op](left, right)

    def attribute(self, value, name: str):
        if type(value) is library.DeckModule:  # NU.pi: a module's members, as attribute() reads
            members = value.members
            if name in members:
                return members[name]
        if value is Unknown:
            return Unknown
        return library.get_attribute(value, name, self.limits)

    def key(self, value):
        return self.evaluator._key(value)

    def item(self, container, index):
        """``container[index]`` once the index is ready (keyed or a slice)."""
        if container is Unknown or index is Unknown:
            return Unknown
        return container[index]

    def keyed_item(self, container, index):
        self.evaluator._key(index)
        if container is Unknown or index is Unknown:
            return Unknown
        return container[index]

    def slice(self, *bounds):
        return Unknown if Unknown in bounds else slice(*bounds)

    def index_tuple(self, *parts):
        if any(part is Unknown for part in parts):
            return Unknown
        return self.evaluator._key(parts)

    def store_item(self, container, index, value) -> bool:
        """``container[index] = value``; True when the container's name must
        become Unknown (a list or array cannot hold Unknown)."""
        if container is Unknown:
            return False
        if (value is Unknown or index is Unknown) and not isinstance(container, dict):
            return True
        container[index] = value
        if isinstance(container, list):
            guards.check_length(len(container), self.limits)
        return False

    def augmented_item(self, op: str, container, index, value) -> bool:
        if container is Unknown:
            return False
        current = Unknown if index is Unknown else container[index]
        return self.store_item(container, index, self.augmented(op, current, value))

    def unpack(self, value, count: int) -> tuple:
        if value is Unknown:
            return (Unknown,) * count
        items = list(itertools.islice(iter(value), count + 1))
        if len(items) != count:
            raise DeckRuntimeError(
                f"cannot unpack {'more' if len(items) > count else len(items)} "
                f"values into {count} names"
            )
        return tuple(items)

    # --------------------------------------------------------------- calls

    def call(self, site, callee, args, assigned_name):
        """A call outside the fast paths; ``site`` is (call node, frame)."""
        node, frame = site
        return self.evaluator.invoke(callee, list(args), {}, {}, node, frame, assigned_name)

    def call_with_keywords(self, site, callee, pieces, assigned_name):
        """A call with keyword, ``*`` or ``**`` arguments: ``pieces`` holds one
        (kind, name, value) per argument, evaluated in order."""
        node, frame = site
        evaluator = self.evaluator
        args, kwargs, keyword_locations = [], {}, {}
        spread_unknown = False
        arguments = node.children[1].children
        for (kind, name, value), argument in zip(pieces, arguments, strict=True):
            if kind == "kwarg":
                kwargs[name] = value
                keyword_locations[name] = evaluator.location(argument.children[0], frame.module)
            elif kind == "star_arg":
                if value is Unknown:
                    spread_unknown = True
                else:
                    args.extend(value)
            elif kind == "double_star_arg":
                if value is Unknown:
                    spread_unknown = True
                    continue
                location = evaluator.location(argument, frame.module)
                for key in value:
                    if not isinstance(key, str):
                        raise DeckRuntimeError("keywords must be strings")
                    if key in kwargs:
                        raise DeckRuntimeError(f"got multiple values for keyword argument '{key}'")
                    kwargs[key] = value[key]
                    keyword_locations[key] = location
            else:
                args.append(value)
        if spread_unknown:
            return Unknown
        return evaluator.invoke(callee, args, kwargs, keyword_locations, node, frame, assigned_name)

    # -------------------------------------------------------------- errors

    def locate(self, error: BaseException, code, nodes, frame, global_reads) -> None:
        """Raise ``error`` as the interpreter would have: located at the deck
        node whose code raised it (the line number of the innermost
        instruction of ``code`` in the traceback is the node's index + 1)."""
        line = None
        trace = error.__traceback__  # starts at the frame handling it: the compiled function
        while trace is not None:
            if trace.tb_frame.f_code is code:
                line = trace.tb_lineno
                break
            trace = trace.tb_next
        node = nodes[line - 1] if line is not None and 0 < line <= len(nodes) else nodes[0]
        if isinstance(error, KeyError) and line in global_reads:
            name = global_reads[line]
            near = did_you_mean(name, self.evaluator.namespace)
            error = python_error(NameError, f"name '{name}' is not defined{near}")
            error.__cause__ = None
            error.__suppress_context__ = True
        self.evaluator._fail(error, node, frame)
