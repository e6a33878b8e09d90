"""numba's ``njit``, imported only when a numba kernel runs.

A run whose loops are all compiled C++ (:mod:`asterlite.dynamics.native`)
never needs numba, whose import alone costs about 0.15 s and its first
cached call 0.2 s more. So the kernels of this package are decorated with
:func:`njit` from here: until numba is needed it keeps the Python function
and its options (a :class:`Deferred`); the first call of any of them from
Python, or :func:`load`, imports numba, makes every kept function numba's
dispatcher with its options (nothing compiles yet: numba compiles or loads
from its cache at the first call, as before), and puts each dispatcher
wherever the module namespaces hold its :class:`Deferred`, so that numba,
which reads a kernel's callees from its globals when it compiles, finds
dispatchers only. Afterwards :func:`njit` is numba's.

numba's import is accounted as its compilations are
(:func:`asterlite.watchdog.compiler_work`): the memory it takes is not the
study's, and the compile notices and limits follow numba's events from then on.
"""

from __future__ import annotations

import sys

_numba = None  # the numba module once imported
_interpreting = 0  # > 0 inside interpreted(): kernels run as Python
_waiting: list[Deferred] = []
_hooks: list = []  # called once numba is imported (numba.extending registrations)


class Deferred:
    """A kernel whose numba dispatcher is not made yet."""

    def __init__(self, function, options: dict):
        self.py_func, self.options, self.dispatcher = function, options, None
        self.__name__, self.__qualname__ = function.__name__, function.__qualname__
        self.__module__ = function.__module__

    def __call__(self, *args, **kwargs):
        if _interpreting:
            return self.py_func(*args, **kwargs)
        return compiled(self)(*args, **kwargs)

    def __getattr__(self, name):  # targetoptions, signatures...: the dispatcher's
        return getattr(compiled(self), name)

    def __repr__(self):
        return f"<kernel {self.__module__}.{self.__qualname__}, numba not imported>"


def njit(*args, **options):
    """numba.njit, deferred (used as ``@njit`` or ``@njit(cache=True, ...)``)."""
    if args and callable(args[0]) and not options and len(args) == 1:
        return _kernel(args[0], {})

    def decorate(function):
        return _kernel(function, options)

    return decorate


def _kernel(function, options: dict):
    if _numba is not None:
        return _numba.njit(**options)(function)
    deferred = Deferred(function, options)
    _waiting.append(deferred)
    return deferred


def interpreted(kernel):
    """``kernel`` as a function that runs its Python, its kernel callees too,
    while numba is not imported: for a run's few evaluations outside the
    loops (a law's initial state), which the compiled C++ loops leave as the
    only reason to import numba and compile. Once numba is imported, the
    kernel's dispatcher. The same operations, so the same values."""

    def run(*args, **kwargs):
        global _interpreting
        if _numba is not None:
            return compiled(kernel)(*args, **kwargs)
        _interpreting += 1
        try:
            return kernel.py_func(*args, **kwargs)
        finally:
            _interpreting -= 1

    return run


def on_load(hook) -> None:
    """Call ``hook()`` once numba is imported (now if it is)."""
    if _numba is not None:
        hook()
    else:
        _hooks.append(hook)


def loaded() -> bool:
    return _numba is not None


def compiled(kernel):
    """The numba dispatcher of ``kernel`` (a :class:`Deferred` or already one)."""
    if isinstance(kernel, Deferred):
        load()
        return kernel.dispatcher
    return kernel


def load() -> None:
    """Import numba and make every deferred kernel its dispatcher."""
    global _numba
    if _numba is not None and not _waiting:
        return
    if _numba is None:
        from asterlite import progress, watchdog
        from asterlite.dynamics import use_kernel_cache

        use_kernel_cache()  # numba reads its cache folder when imported
        with watchdog.compiler_work():
            import numba
        _numba = numba
        watchdog.listen_to_compilation()
        progress.listen_to_compiles()
    waiting = list(_waiting)
    _waiting.clear()
    for deferred in waiting:
        deferred.dispatcher = _numba.njit(**deferred.options)(deferred.py_func)
    # where the deferred kernels are bound: their own globals (a module's, or
    # the namespace of a function made at run time) and every module of the
    # package that imported them by name
    namespaces = {id(d.py_func.__globals__): d.py_func.__globals__ for d in waiting}
    for name, module in list(sys.modules.items()):
        if name.startswith("asterlite") and module is not None:
            namespaces.setdefault(id(module.__dict__), module.__dict__)
    for namespace in namespaces.values():
        for key, value in list(namespace.items()):
            if isinstance(value, Deferred) and value.dispatcher is not None:
                namespace[key] = value.dispatcher
    hooks = list(_hooks)
    _hooks.clear()
    for hook in hooks:
        hook()
