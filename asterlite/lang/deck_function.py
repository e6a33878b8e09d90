"""A ``def`` or ``lambda`` of a deck, as a value: callable from the deck, from
Python (``map(f, values)``) and from FORMULE expressions (``evaluate_many``)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from asterlite.lang.library import STORE
from asterlite.lang.values import CallSite, DeckCallable, Unknown

if TYPE_CHECKING:
    from asterlite.lang.parser import Module


class Frame:
    """Where names live while running code: a function's locals (None at module
    level, where names go to the shared namespace) and the enclosing frame."""

    __slots__ = ("locals", "parent", "module")

    def __init__(self, local_names: dict | None, parent: Frame | None, module: Module):
        self.locals = local_names
        self.parent = parent
        self.module = module


class DeckFunction(DeckCallable):
    """A ``def`` or ``lambda`` of the deck; callable from the deck and from Python
    (``map(f, values)``).

    On its first call the body is compiled (:mod:`asterlite.lang.compiler`)
    when it stays within the compiled subset: ``direct`` is then a Python
    function taking exactly ``arity`` positional arguments, with the same
    guards as the interpreter; otherwise ``arity`` stays -1 and the tree is
    interpreted."""

    deck_unknown_policy = STORE  # the body itself handles Unknown arguments

    def __init__(self, name, parameters, defaults, body, closure, evaluator, is_lambda=False):
        self.name = name
        self.parameters = parameters  # [str]
        self.defaults = defaults  # {name: value}
        self.body = body
        self.closure = closure  # defining Frame
        self.evaluator = evaluator
        self.is_lambda = is_lambda
        self.direct = None  # the compiled body, once compiled
        self.arity = -1  # len(parameters) once compiled, -1 before or when refused
        self.compile_tried = False

    def deck_call(self, args: list, kwargs: dict, site: CallSite):
        if self.arity == len(args) and not kwargs and all(a is not Unknown for a in args):
            return self.direct(*args)
        return self.evaluator.call_function(self, args, kwargs)

    def __call__(self, *args, **kwargs):
        if self.arity == len(args) and not kwargs and all(a is not Unknown for a in args):
            return self.direct(*args)
        return self.evaluator.call_function(self, list(args), kwargs)

    def evaluate_many(self, *arrays):
        """The function at each point of its (broadcast) array arguments, as a
        FORMULE calling it computes them: one call per point with Python floats."""
        import numpy as np

        arrays = np.broadcast_arrays(*[np.asarray(a, dtype=float) for a in arrays])
        if arrays and arrays[0].ndim == 0:
            return self.deck_call([float(a) for a in arrays], {}, CallSite())
        shape = arrays[0].shape if arrays else ()
        columns = [a.ravel().tolist() for a in arrays]
        columns[0]  # noqa: B018 - IndexError without arguments, as call_vectorised gives
        if self.arity == len(columns):  # compiled: one Python call per point
            out = list(map(self.direct, *columns))
        else:
            call, site = self.deck_call, CallSite()
            out = [call(list(point), {}, site) for point in zip(*columns, strict=True)]
        return np.asarray(out).reshape(shape)

    def __repr__(self) -> str:
        return f"<function {self.name}>"
