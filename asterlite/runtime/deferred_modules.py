"""numpy's tools a run never uses, loaded only if something reads them.

scipy's array-API layer (``scipy._lib.array_api_compat.numpy``, imported by
every scipy module a run uses) copies numpy's namespace name by name, which
imports each submodule numpy loads on first access: among them ``numpy.f2py``
(the Fortran wrapper generator, ~60 regular expressions compiled at import)
and ``numpy.testing`` (unittest and its kin). On this machine they were 85 of
the 250 ms that ``import numpy, scipy.linalg, scipy.sparse.linalg`` took, for
modules no deck uses. Before scipy loads, a run registers them as lazy
modules (the standard library's ``importlib.util.LazyLoader``): the names
exist, and a module's code runs the first time one of its attributes is read,
so anything that does use them gets the whole module.

Only the commands that run decks in their own process call this: the Python
API leaves the caller's modules as they are.
"""

from __future__ import annotations

import importlib.util
import sys

#: numpy's submodules no run uses (each is still complete on first use)
NUMPY_TOOLS = ("f2py", "testing")


def defer_numpy_tools() -> list[str]:
    """Register NUMPY_TOOLS as lazy modules, unless scipy is loaded already
    (too late to matter) or a module is; returns the names deferred."""
    if "scipy" in sys.modules:
        return []
    import numpy

    deferred = []
    for name in NUMPY_TOOLS:
        full = f"{numpy.__name__}.{name}"
        if full in sys.modules:
            continue
        spec = importlib.util.find_spec(full)
        if spec is None or spec.loader is None or not hasattr(spec.loader, "exec_module"):
            continue
        spec.loader = importlib.util.LazyLoader(spec.loader)
        module = importlib.util.module_from_spec(spec)
        sys.modules[full] = module
        spec.loader.exec_module(module)
        # as the import system does for a loaded submodule: numpy's own
        # lazy attribute lookup then finds it without importing it again
        setattr(numpy, name, module)
        deferred.append(full)
    return deferred
