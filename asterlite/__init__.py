"""asterlite: run Code_Aster command files for modal transient dynamics with shocks.

The package is split into single-purpose rooms:

- ``lang``      deck grammar, parser and safe evaluator (no numerical imports)
- ``catalog``   keyword model (SIMP/FACT/BLOC/rules) and validation
- ``runtime``   a deck session: namespace, logical units, dispatcher, test records
- ``concepts``  the data types commands hand to each other (Mesh, ModeResult, ...)
- ``fem``       mesh, elements, assembly, constraints
- ``modal``     eigen solver, static modes, projection
- ``dynamics``  integration schemes, nonlinear forces, compiled kernels
- ``post``      restitution, shock statistics, wear, functions, tables
- ``io``        mesh readers, MED/HDF5 writers, table and function writers

Keyword catalogues live in ``asterlite.catalogues`` (one file per command) and
command implementations in ``asterlite.commands`` (one file per command).

From Python (``docs/api.md``): ``asterlite.run(deck, output=None, **variables)``,
``asterlite.check(deck)``, ``asterlite.load("results.h5")`` and
``asterlite.sample(name)`` (a sample's folder), defined in
:mod:`asterlite.api` and imported on first use, so that ``import asterlite``
(and ``asterlite check``) stays free of numpy and numba.
"""

from asterlite.version import __version__

# the Python API, loaded from asterlite.api when first asked for
_API = ("run", "check", "load", "sample", "RunResult", "CheckResult", "Check", "DeckNotFound")


def __getattr__(name: str):
    if name in _API:
        from asterlite import api

        return getattr(api, name)
    raise AttributeError(f"module 'asterlite' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted([*globals(), *_API])


__all__ = ["__version__", *_API]
