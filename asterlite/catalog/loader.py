"""Finding a command's catalogue: module ``asterlite.catalogues.<name lowercase>``."""

from __future__ import annotations

import importlib
from functools import cache

from asterlite.catalog.model import Command

CATALOGUE_PACKAGE = "asterlite.catalogues"


@cache
def load_catalogue(name: str) -> Command | None:
    """The catalogue object of command ``name``, or None if there is none."""
    if not name.isidentifier():
        return None
    module_name = f"{CATALOGUE_PACKAGE}.{name.lower()}"
    try:
        module = importlib.import_module(module_name)
    except ModuleNotFoundError as error:
        if error.name == module_name:  # only "no such catalogue", not a broken one
            return None
        raise
    catalogue = getattr(module, name, None)
    return catalogue if isinstance(catalogue, Command) else None
