"""Optional dependencies: which extra of asterlite brings each one.

The core install runs decks, reads and writes meshes (ASTER, MED) and HDF5
results. Parameter studies need ``asterlite[sweep]`` (Dask, pyarrow) and
pictures need ``asterlite[plot]`` (matplotlib). :func:`require` imports an
optional module or raises :class:`MissingExtraError`, whose message names
what needed it and the command that installs it. Nothing here imports numpy.
"""

from __future__ import annotations

import importlib

from asterlite.errors import AsterliteError

# top-level module -> the extra that installs it
EXTRA_OF = {
    "matplotlib": "plot",
    "dask": "sweep",
    "distributed": "sweep",
    "pyarrow": "sweep",
    "mumps": "large",
}


class MissingExtraError(AsterliteError):
    """An optional dependency is not installed (exit status 2, like any error)."""

    kind = "missing optional dependency"


def install_hint(extra: str) -> str:
    return f"pip install 'asterlite[{extra}]'"


def require(module: str, purpose: str):
    """Import ``module`` (e.g. ``"pyarrow.parquet"``) or raise MissingExtraError
    saying that ``purpose`` (e.g. "asterlite sweep") needs it and how to get it."""
    try:
        return importlib.import_module(module)
    except ImportError as error:
        top = module.partition(".")[0]
        missing = getattr(error, "name", None) or top
        state = "is not installed"
        if missing.partition(".")[0] != top:  # installed, but one of its own imports fails
            state = f"cannot be imported (module {missing} is missing)"
        extra = EXTRA_OF.get(top)
        how = f": {install_hint(extra)} (or 'asterlite[all]')" if extra else ""
        raise MissingExtraError(f"{purpose} needs {top}, which {state}{how}") from None


__all__ = ["EXTRA_OF", "MissingExtraError", "install_hint", "require"]
