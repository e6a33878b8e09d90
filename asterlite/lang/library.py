"""What a deck can reach besides its own names: whitelisted builtins, the
``math`` module, a curated numpy subset, and the attributes allowed on values.

Everything here is an explicit whitelist. numpy is imported only when a deck
imports it. Functions that could allocate without bound are wrapped with a
guard from :mod:`asterlite.lang.limits`.
"""

from __future__ import annotations

import functools
import math
import sys
import types

from asterlite.errors import DeckRuntimeError, UnsupportedError
from asterlite.lang import exceptions, stdlib
from asterlite.lang import limits as guards
from asterlite.lang.limits import Limits
from asterlite.lang.savetxt import make_savetxt
from asterlite.lang.stdlib import cmath_module
from asterlite.lang.values import COBuilder, DeckModule, FactorBuilder

# How a plain Python callable treats Unknown arguments (see Evaluator._call_python):
STORE = "store"  # receives Unknown as any value (print, list.append, concept methods)
DIRECT = "direct"  # Unknown result when an argument itself is Unknown (len, list, zip...)
DEEP = "deep"  # Unknown result when Unknown appears anywhere in the arguments (math, numpy)


def _is_array(value) -> bool:
    np = sys.modules.get("numpy")  # a deck that made an array imported it
    return np is not None and isinstance(value, np.ndarray)


def _one_element_arrays_as_scalars(args):
    """int(), float() and complex() of a one-element array of any shape give
    its element, as numpy 1 did (numpy 2 takes 0-dimensional arrays only):
    decks written for code_aster index arrays as ``A[i]`` of an (n, 1) array
    and convert the result."""
    return tuple(
        arg.item() if _is_array(arg) and arg.ndim and arg.size == 1 else arg for arg in args
    )


def _policy(policy: str):
    def mark(function):
        function.deck_unknown_policy = policy
        return function

    return mark


# ------------------------------------------------------------------- builtins


def _make_print(print_hook, limits: Limits):
    hook = print_hook or sys.stdout.write

    @_policy(STORE)
    def deck_print(*values, sep=" ", end="\n"):
        guards.check_nested_size(values, limits)
        values = guards.deck_text_value(values)
        hook(str(sep).join(str(value) for value in values) + str(end))

    deck_print.__name__ = "print"
    return deck_print


def _make_builtins(limits: Limits) -> dict:
    def deck_range(*args):
        span = range(*args)
        try:
            size = len(span)
        except OverflowError:
            size = limits.max_sequence_length + 1
        guards.check_length(size, limits, "range length")
        return span

    def deck_sum(iterable, start=0):
        if not isinstance(start, (int, float, complex)):
            raise DeckRuntimeError("sum() start value must be a number in decks")
        return sum(iterable, start)

    def deck_pow(base, exponent, modulo=None):
        if modulo is None:
            guards.check_binary("**", base, exponent, limits)
            return pow(base, exponent)
        return pow(base, exponent, modulo)

    def as_text(convert):
        def deck_text(*args, **kwargs):
            guards.check_nested_size(args, limits)
            return convert(*guards.deck_text_value(args), **kwargs)

        deck_text.__name__ = convert.__name__
        return deck_text

    def deck_set(*args):
        if args and not isinstance(args[0], (set, frozenset, dict)):
            args = (guards.hashable_items(args[0], limits),)
        return set(*args)

    def deck_dict(*args, **kwargs):
        if args and not isinstance(args[0], dict):
            pairs = guards.hashable_items(args[0], limits)
            args = (pairs,)
        return dict(*args, **kwargs)

    def deck_int(*args, **kwargs):
        if len(args) > 1 or "base" in kwargs:
            base = args[1] if len(args) > 1 else kwargs["base"]
            guards.check_int_text(args[0] if args else kwargs.get("x", ""), base, limits)
        return int(*_one_element_arrays_as_scalars(args), **kwargs)

    def deck_float(*args):
        return float(*_one_element_arrays_as_scalars(args))

    def deck_complex(*args, **kwargs):
        return complex(*_one_element_arrays_as_scalars(args), **kwargs)

    deck_range.__name__, deck_sum.__name__, deck_pow.__name__ = "range", "sum", "pow"
    deck_int.__name__, deck_float.__name__, deck_complex.__name__ = "int", "float", "complex"
    # np.zeros(3, dtype=int) still means Python's int
    deck_int.numpy_type, deck_float.numpy_type, deck_complex.numpy_type = int, float, complex
    deck_set.__name__, deck_dict.__name__ = "set", "dict"
    return {
        "abs": abs,
        "min": min,
        "max": max,
        "sum": deck_sum,
        "len": len,
        "range": deck_range,
        "enumerate": enumerate,
        "zip": zip,
        "map": map,
        "sorted": sorted,
        "reversed": reversed,
        "list": list,
        "tuple": tuple,
        "dict": deck_dict,
        "set": deck_set,
        "int": deck_int,
        "float": deck_float,
        "complex": deck_complex,
        "str": as_text(str),
        "bool": bool,
        "round": round,
        "pow": deck_pow,
        "divmod": divmod,
        "any": any,
        "all": all,
        "repr": as_text(repr),
        "chr": chr,
        "ord": ord,
    }


# builtins whose result is Unknown only when an argument itself is Unknown
STRUCTURAL_BUILTINS = frozenset(
    {"len", "enumerate", "zip", "map", "reversed", "list", "tuple", "dict", "set", "str", "repr"}
)


def base_namespace(print_hook=None, limits: Limits | None = None) -> dict:
    """A fresh namespace holding the builtins a deck may use, ``_F``, ``CO`` and
    the ``math`` names (code_aster runs decks after ``from math import *``, and
    decks rely on it: ``pow`` is therefore math.pow).

    ``print_hook(text)`` receives what ``print`` would write, end included
    (like ``file.write``); the default writes to sys.stdout.
    """
    limits = limits or Limits()
    namespace = _make_builtins(limits)
    namespace.update(math_members())
    namespace["print"] = _make_print(print_hook, limits)
    namespace["_F"] = FactorBuilder()
    namespace["CO"] = COBuilder()
    # ValueError..., globals(), open refused
    namespace.update(exceptions.deck_exception_names())
    namespace.update(stdlib.namespace_builtins(namespace))
    return namespace


def structural_ids(namespace: dict) -> frozenset[int]:
    """ids of the structural builtins in a namespace (see STRUCTURAL_BUILTINS)."""
    ids = {id(namespace[name]) for name in STRUCTURAL_BUILTINS if name in namespace}
    ids.update(id(builtin) for builtin in (len, enumerate, zip, map, reversed, list, tuple))
    ids.update(id(builtin) for builtin in (dict, set, str, repr))
    # the guarded versions in the namespace are structural too (above, by name)
    return frozenset(ids)


# --------------------------------------------------------------------- math

# integer functions whose cost grows without bound with their argument
_MATH_EXCLUDED = frozenset({"factorial", "comb", "perm", "prod"})


@functools.cache
def math_members() -> dict:
    members = {
        name: getattr(math, name)
        for name in dir(math)
        if not name.startswith("_") and name not in _MATH_EXCLUDED
    }
    if "lcm" in members:
        members["lcm"] = _guarded_lcm
    return members


def _guarded_lcm(*integers):
    """math.lcm, refused when its result could pass the integer size limit
    (one C call: it could not be stopped once started)."""
    guards.check_lcm(integers, Limits())
    return math.lcm(*integers)


_guarded_lcm.__name__ = "lcm"


# -------------------------------------------------------------------- numpy

NUMPY_FUNCTIONS = """
array asarray zeros ones empty full zeros_like ones_like empty_like full_like
linspace arange logspace eye identity diag diagonal trace
sqrt sin cos tan arcsin arccos arctan arctan2 sinh cosh tanh exp expm1 log log10 log2 log1p
abs absolute fabs sign floor ceil round around rint trunc fix square power hypot mod fmod
sum prod cumsum cumprod diff gradient dot vdot outer cross inner matmul
allclose isclose array_equal nonzero flatnonzero argwhere count_nonzero where
sort argsort unique searchsorted concatenate hstack vstack stack column_stack
insert append delete tile repeat max min amax amin maximum minimum argmax argmin
nanmax nanmin nanargmax nanargmin nansum nanmean
mean average std var median percentile interp reshape transpose ravel flip fliplr flipud roll
squeeze expand_dims atleast_1d atleast_2d clip any all isnan isinf isfinite nan_to_num
radians degrees deg2rad rad2deg polyfit polyval trapezoid trapz copy take shape size ndim
real imag conj conjugate angle logical_and logical_or logical_not logical_xor meshgrid convolve
floor_divide true_divide multiply add subtract divide negative reciprocal
""".split()
NUMPY_CONSTANTS = "pi e inf nan newaxis".split()
NUMPY_TYPES = (
    "float64 float32 int64 int32 int16 int8 uint8 complex128 complex64 bool_ float_ int_".split()
)
NUMPY_LINALG = (
    "norm solve inv det eig eigh eigvals eigvalsh lstsq pinv matrix_rank cond "
    "qr svd cholesky slogdet matrix_power multi_dot"
).split()

# attributes of numpy arrays and scalars a deck may use
NUMPY_ARRAY_ATTRIBUTES = frozenset(
    """
shape T size ndim dtype real imag reshape astype tolist dot sum max min copy flatten ravel
mean std var prod cumsum cumprod argmax argmin argsort sort nonzero transpose squeeze
any all clip round conj conjugate item fill trace diagonal swapaxes
""".split()
)


def _size(value) -> int:
    np = guards.numpy_or_none()
    if isinstance(value, np.ndarray):
        return value.size
    if isinstance(value, (list, tuple)):
        return len(value)
    return 1


def _shape_size(shape) -> int:
    if isinstance(shape, (list, tuple)):
        return math.prod(int(n) for n in shape) if shape else 1
    return int(shape)


def _argument(args, kwargs, position: int, name: str, default=None):
    if len(args) > position:
        return args[position]
    return kwargs.get(name, default)


def _estimate_shape_arg(args, kwargs) -> int:
    return _shape_size(_argument(args, kwargs, 0, "shape", 1))


def _estimate_like(args, kwargs) -> int:
    """zeros_like & co: the prototype's size, or the ``shape=`` asked instead."""
    if kwargs.get("shape") is not None:
        return _shape_size(kwargs["shape"])
    return _size(_argument(args, kwargs, 0, "a"))


def _estimate_eye(args, kwargs) -> int:
    rows = int(_argument(args, kwargs, 0, "N", 1))
    columns = _argument(args, kwargs, 1, "M", None)
    return rows * (rows if columns is None else int(columns))


def _estimate_arange(args, kwargs) -> int:
    values = list(args) + [kwargs[k] for k in ("start", "stop", "step") if k in kwargs]
    if len(values) == 1:
        start, stop, step = 0, values[0], 1
    else:
        start, stop, step = (list(values) + [1])[:3]
    if step == 0:
        return 0
    return max(math.ceil((float(stop) - float(start)) / float(step)), 0)


def _estimate_linspace(args, kwargs) -> int:
    return int(_argument(args, kwargs, 2, "num", 50))


def _estimate_tile(args, kwargs) -> int:
    return _size(_argument(args, kwargs, 0, "A")) * _shape_size(_argument(args, kwargs, 1, "reps"))


def _estimate_repeat(args, kwargs) -> int:
    repeats = _argument(args, kwargs, 1, "repeats", 1)
    total = sum(int(r) for r in repeats) if isinstance(repeats, (list, tuple)) else None
    np = guards.numpy_or_none()
    if isinstance(repeats, np.ndarray):
        total = int(repeats.sum())
    return total if total is not None else _size(args[0] if args else 1) * int(repeats)


def _estimate_outer(args, kwargs) -> int:
    return math.prod(_size(a) for a in args[:2])


def _product_shapes(args):
    """The shapes of the two operands of dot / matmul / inner (None if not arrays)."""
    np = guards.numpy_or_none()
    if len(args) < 2:
        return None
    shapes = [np.shape(a) if isinstance(a, (list, tuple, np.ndarray)) else () for a in args[:2]]
    return shapes


def _estimate_product(args, kwargs, name: str = "dot") -> tuple[int, int]:
    """(result size, multiply-adds) of dot / matmul / inner, from the shapes
    alone (numpy's rules: dot sums over a's last and b's second-to-last axis,
    matmul broadcasts the leading axes, inner sums over both last axes)."""
    shapes = _product_shapes(args)
    if shapes is None:
        return 0, 0
    left, right = shapes
    if not left or not right:  # a scalar factor: elementwise
        size = math.prod(left or right)
        return size, size
    inner = left[-1]
    if name == "inner":
        result = left[:-1] + right[:-1]
    elif len(right) == 1:
        result = left[:-1]
    elif name == "matmul" and len(left) > 1:
        batch = _broadcast_batch(left[:-2], right[:-2])
        result = batch + left[-2:-1] + right[-1:]
    else:  # dot (and matmul of a vector by a matrix)
        result = left[:-1] + right[:-2] + right[-1:]
    size = math.prod(result)
    return size, size * max(int(inner), 1)


def _broadcast_batch(left: tuple, right: tuple) -> tuple:
    length = max(len(left), len(right))
    left = (1,) * (length - len(left)) + tuple(left)
    right = (1,) * (length - len(right)) + tuple(right)
    return tuple(max(a, b) for a, b in zip(left, right, strict=True))


def _estimate_meshgrid(args, kwargs) -> int:
    return math.prod(_size(a) for a in args) * len(args)


def _estimate_diag(args, kwargs) -> int:
    vector = args[0] if args else kwargs.get("v")
    np = guards.numpy_or_none()
    size = _size(vector)
    flat = isinstance(vector, (list, tuple))
    flat = flat or (isinstance(vector, np.ndarray) and vector.ndim == 1)
    return size * size if flat else size


def _estimate_diff(args, kwargs) -> int:
    """np.diff loops n times in Python: n beyond the axis length is refused."""
    np = guards.numpy_or_none()
    order = int(_argument(args, kwargs, 1, "n", 1))
    array = _argument(args, kwargs, 0, "a")
    shape = np.shape(array) if isinstance(array, (list, tuple, np.ndarray)) else ()
    axis = int(_argument(args, kwargs, 2, "axis", -1))
    length = shape[axis] if shape and -len(shape) <= axis < len(shape) else 0
    if order > max(length, 1):
        raise DeckRuntimeError(f"numpy.diff: order n={order} exceeds the axis length {length}")
    return _size(array)


def _estimate_pairwise(args, kwargs) -> int:
    """convolve / polyval: each element of one meets each of the other."""
    return math.prod(_size(a) for a in args[:2])


def _estimate_polyfit(args, kwargs) -> int:
    """polyfit builds a Vandermonde matrix: points times (degree + 1)."""
    degree = int(_argument(args, kwargs, 2, "deg", 1))
    return _size(_argument(args, kwargs, 0, "x")) * max(degree + 1, 1)


# linear algebra on an n x n matrix costs about n**3
_CUBIC = frozenset("solve inv det eig eigh eigvals eigvalsh lstsq pinv matrix_rank cond".split())


def _cubic_work(args) -> int:
    np = guards.numpy_or_none()
    if not args or not isinstance(args[0], (list, tuple, np.ndarray)):
        return 0
    shape = np.shape(args[0])
    if len(shape) < 2:
        return 0
    n, m = shape[-2], shape[-1]
    return math.prod(shape[:-2]) * max(n, m) * min(n, m) ** 2


_ESTIMATORS = {
    "diff": _estimate_diff,
    "convolve": _estimate_pairwise,
    "polyval": _estimate_pairwise,
    "polyfit": _estimate_polyfit,
    "zeros": _estimate_shape_arg,
    "ones": _estimate_shape_arg,
    "empty": _estimate_shape_arg,
    "full": _estimate_shape_arg,
    "zeros_like": _estimate_like,
    "ones_like": _estimate_like,
    "empty_like": _estimate_like,
    "full_like": _estimate_like,
    "eye": _estimate_eye,
    "identity": _estimate_eye,
    "arange": _estimate_arange,
    "linspace": _estimate_linspace,
    "logspace": _estimate_linspace,
    "tile": _estimate_tile,
    "repeat": _estimate_repeat,
    "outer": _estimate_outer,
    "meshgrid": _estimate_meshgrid,
    "diag": _estimate_diag,
    "kron": _estimate_outer,
}

_MAX_ITEMSIZE = 1024  # bytes per element: refuses dtypes like "U100000000"


def _check_dtypes(args, kwargs) -> int:
    """Refuse object dtypes and huge items; the largest item size asked (0: none)."""
    np = guards.numpy_or_none()
    candidates = [a for a in args if isinstance(a, (str, type, np.dtype))]
    if "dtype" in kwargs:
        candidates.append(kwargs["dtype"])
    largest = 0
    for candidate in candidates:
        try:
            dtype = np.dtype(candidate)
        except (TypeError, ValueError):
            continue
        if dtype.hasobject:
            raise guards.object_array_error()
        if dtype.itemsize > _MAX_ITEMSIZE:
            raise DeckRuntimeError(f"numpy dtype {candidate!r} is too large for decks")
        largest = max(largest, dtype.itemsize)
    return largest


def _plain_types(args, kwargs):
    """The deck's guarded ``int`` given as a dtype stands for Python's int."""
    if any(hasattr(a, "numpy_type") for a in args if isinstance(a, types.FunctionType)):
        args = tuple(getattr(a, "numpy_type", a) for a in args)
    if hasattr(kwargs.get("dtype"), "numpy_type"):
        kwargs = dict(kwargs, dtype=kwargs["dtype"].numpy_type)
    return args, kwargs


def _check_result(result, name: str, limits: Limits) -> None:
    """What a numpy call made: no array of objects, sizes within the limits
    (the arrays of a short tuple or list too: meshgrid, gradient)."""
    np = guards.numpy_or_none()
    several = isinstance(result, (tuple, list)) and len(result) <= 64
    for array in result if several else (result,):
        if isinstance(array, np.ndarray):
            guards.check_array_result(array)
            guards.check_length(array.size, limits, f"numpy.{name} size")


def _input_size(args) -> int:
    """Total size of the numpy arrays among the arguments and in lists of
    them: what concatenate, stack, append... put together."""
    np = guards.numpy_or_none()
    total = 0
    for arg in args:
        if isinstance(arg, np.ndarray):
            total += arg.size
        elif isinstance(arg, (list, tuple)):
            total += len(arg) + sum(a.size for a in arg if isinstance(a, np.ndarray))
    return total


def guard_numpy(function, name: str, limits: Limits, bound_to=None):
    """Wrap a numpy callable so it refuses results beyond the limits; for an
    array method, ``bound_to`` is the array (the estimators' first argument)."""
    estimator = _ESTIMATORS.get(name)

    @_policy(DEEP)
    @functools.wraps(function)
    def guarded(*args, **kwargs):
        args, kwargs = _plain_types(args, kwargs)
        itemsize = _check_dtypes(args, kwargs)
        guards.check_no_object_arrays((*args, *kwargs.values()), kwargs.get("dtype"))
        full_args = args if bound_to is None else (bound_to, *args)
        size = _input_size(full_args)
        if estimator is not None:
            size = max(size, estimator(full_args, kwargs))
            guards.check_length(size, limits, f"numpy.{name} size")
        if itemsize > 16:  # strings of many characters: the bytes count
            guards.check_length(size * itemsize // 16, limits, f"numpy.{name} size (16-byte items)")
        _check_work(name, full_args, kwargs, limits)
        guards.check_length(_input_size(args), limits, f"numpy.{name} size")
        guards.check_broadcast(args, limits)
        result = function(*args, **kwargs)
        _check_result(result, name, limits)
        return result

    return guarded


def _check_work(name: str, args, kwargs, limits: Limits) -> None:
    """Products and solvers: refuse a result or an amount of arithmetic
    beyond the limits before numpy starts (it cannot be stopped midway)."""
    work = 0
    if name in ("dot", "matmul", "inner"):
        size, work = _estimate_product(args, kwargs, name)
        guards.check_length(size, limits, f"numpy.{name} size")
    elif name in _CUBIC:
        work = _cubic_work(args)
    elif name in ("convolve", "polyval"):
        work = _estimate_pairwise(args, kwargs)
    if work > limits.max_work:
        raise guards.exceeded(f"numpy.{name} arithmetic (operations)", limits.max_work)


def numpy_module(limits: Limits) -> DeckModule:
    return DeckModule("numpy", loader=functools.partial(_numpy_members, limits))


def _numpy_members(limits: Limits) -> dict:
    import numpy as np

    members = {}
    for name in NUMPY_FUNCTIONS:
        if hasattr(np, name):
            members[name] = guard_numpy(getattr(np, name), name, limits)
    for name in NUMPY_CONSTANTS + NUMPY_TYPES:
        if hasattr(np, name):
            members[name] = getattr(np, name)
    members["savetxt"] = make_savetxt(limits)  # into the run's output folder only
    members["linalg"] = DeckModule(
        "numpy.linalg",
        {
            name: guard_numpy(getattr(np.linalg, name), name, limits)
            for name in NUMPY_LINALG
            if hasattr(np.linalg, name)
        },
    )
    return members


def builtin_modules(limits: Limits) -> dict:
    """Modules every deck may import, by name: a factory for each."""
    return {
        "math": lambda: DeckModule("math", math_members()),
        "numpy": lambda: numpy_module(limits),
        "numpy.linalg": lambda: numpy_module(limits).attribute("linalg"),
        "cmath": _cmath_module,
    }


def _cmath_module() -> DeckModule:
    return cmath_module()


# ----------------------------------------------------------------- attributes

STR_METHODS = frozenset(
    """capitalize count endswith find format index isalnum isalpha isdigit islower isspace
    isupper join ljust lower lstrip replace rfind rjust rsplit rstrip split splitlines
    startswith strip title upper zfill center""".split()
)
LIST_METHODS = frozenset(
    "append clear copy count extend index insert pop remove reverse sort".split()
)
TUPLE_METHODS = frozenset({"count", "index"})
DICT_METHODS = frozenset("clear copy get items keys pop setdefault update values".split())
SET_METHODS = frozenset(
    """add discard remove union intersection difference symmetric_difference issubset
    issuperset isdisjoint copy""".split()
)
NUMBER_ATTRIBUTES = frozenset({"real", "imag", "conjugate", "is_integer"})


def get_attribute(value, name: str, limits: Limits):
    """``value.name`` as a deck may see it, or DeckRuntimeError."""
    if isinstance(value, DeckModule):
        return value.attribute(name)
    cls = type(value)
    methods = getattr(cls, "deck_methods", None)
    attributes = getattr(cls, "deck_attributes", None)
    if (methods and name in methods) or (attributes and name in attributes):
        return getattr(value, name)
    if hasattr(cls, "deck_getattr"):
        return value.deck_getattr(name)
    found = _builtin_attribute(value, name, limits)
    if found is not _MISSING:
        return found
    if methods is not None or attributes is not None:
        # one of code_aster's objects (a mesh, a result...): code_aster's has
        # far more methods than asterlite provides, so this is asterlite's limit
        raise UnsupportedError(
            f"'{cls.__name__}' object: asterlite does not provide code_aster's '{name}'"
        )
    raise DeckRuntimeError(f"'{cls.__name__}' object has no attribute '{name}' usable in decks")


_MISSING = object()


def _builtin_attribute(value, name: str, limits: Limits):
    if isinstance(value, str):
        return _str_method(value, name, limits) if name in STR_METHODS else _MISSING
    if isinstance(value, list):
        if name == "extend":
            return _guarded_extend(value, limits)
        return getattr(value, name) if name in LIST_METHODS else _MISSING
    if isinstance(value, tuple):
        return getattr(value, name) if name in TUPLE_METHODS else _MISSING
    if isinstance(value, dict):
        return _hashing(getattr(value, name), limits) if name in DICT_METHODS else _MISSING
    if isinstance(value, (set, frozenset)):
        return _hashing(getattr(value, name), limits) if name in SET_METHODS else _MISSING
    if isinstance(value, (int, float, complex)) and not isinstance(value, bool):
        allowed = name in NUMBER_ATTRIBUTES and hasattr(value, name)
        return getattr(value, name) if allowed else _MISSING
    np = guards.numpy_or_none()
    if np is not None and isinstance(value, (np.ndarray, np.generic)):
        if name in NUMPY_ARRAY_ATTRIBUTES and hasattr(value, name):
            found = getattr(value, name)
            return guard_numpy(found, name, limits, value) if callable(found) else found
    return _MISSING


def _hashing(method, limits: Limits):
    """A dict or set method with its arguments checked before they are hashed
    (a key, or an iterable of keys or pairs, read once)."""

    @_policy(STORE)
    @functools.wraps(method)
    def checked(*args, **kwargs):
        checked_args = []
        for arg in args:
            guards.check_hash_depth(arg, limits)
            if not isinstance(arg, (str, tuple, dict, set, frozenset)) and _iterable(arg):
                arg = guards.hashable_items(arg, limits)
            checked_args.append(arg)
        return method(*checked_args, **kwargs)

    return checked


def _iterable(value) -> bool:
    np = guards.numpy_or_none()
    if np is not None and isinstance(value, (np.ndarray, np.generic)):
        return False
    return (
        isinstance(value, (list, range))
        or type(value).__name__.endswith("iterator")
        or (type(value).__name__ in ("zip", "map", "enumerate", "generator", "dict_items"))
    )


def _guarded_extend(target: list, limits: Limits):
    @_policy(STORE)
    def extend(items):
        target.extend(guards.bounded_items(items, limits.max_sequence_length - len(target), limits))

    return extend


def _str_method(text: str, name: str, limits: Limits):
    method = getattr(text, name)
    if name not in ("format", "join", "replace", "ljust", "rjust", "center", "zfill"):
        return method

    @_policy(DEEP)
    def checked(*args, **kwargs):
        if name == "join" and args:
            args = (list(args[0]),) + args[1:]  # a generator must be read only once
        guards.check_nested_size((*args, *kwargs.values()), limits)
        if name == "format":
            guards.check_format_template(text, limits, args, kwargs)
            args = guards.deck_text_value(tuple(args))
            kwargs = {key: guards.deck_text_value(value) for key, value in kwargs.items()}
        guards.check_string_length(_str_result_length(text, name, args, kwargs), limits)
        return method(*args, **kwargs)

    return checked


def _str_result_length(text: str, name: str, args, kwargs) -> int:
    if name == "join":
        parts = args[0] if args else []
        return sum(len(p) for p in parts if isinstance(p, str)) + len(text) * len(parts)
    if name == "format":
        longest = max((len(a) for a in (*args, *kwargs.values()) if isinstance(a, str)), default=0)
        return len(text) + text.count("{") * max(longest, 32)
    if name == "replace" and len(args) >= 2 and isinstance(args[0], str):
        old, new = args[0], args[1]
        occurrences = text.count(old) if old else len(text) + 1
        return len(text) + occurrences * max(len(new) - len(old), 0)
    if name in ("ljust", "rjust", "center", "zfill") and args and isinstance(args[0], int):
        return max(len(text), args[0])
    return len(text)
