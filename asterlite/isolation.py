"""Python processes asterlite starts never import from the current folder.

A study someone sent may come with a ``json.py`` or ``numpy.py`` beside
the deck. A Python interpreter whose module search path holds the current
folder imports such a file instead of the real module, and runs it:
``python -m module`` and ``python -c`` (how :mod:`multiprocessing`'s spawn
starts its workers) both put the current folder first.

So every child interpreter asterlite starts is isolated:

- children asterlite starts itself (the MED reader, ``asterlite corpus``'s
  runs) get ``-I`` (no current folder, no user site folder, no ``PYTHON*``
  variables) and the parent's own search path without the current folder
  (:func:`python_command`): they import exactly the code the parent imports,
  also when asterlite is installed in the user's site folder;
- pools of worker processes (the warmup's, Dask's in ``asterlite sweep``)
  are started with ``PYTHONSAFEPATH=1`` in the environment
  (:func:`protect_spawned_workers`): ``python -c`` then adds no current
  folder, and spawn's workers take the parent's search path afterwards.
"""

from __future__ import annotations

import json
import os
import sys

# run in the isolated child: take the parent's search path (first argument),
# then run the module named by the second argument as __main__
_BOOTSTRAP = (
    "import json, runpy, sys; "
    "sys.path[:] = json.loads(sys.argv.pop(1)); "
    "runpy.run_module(sys.argv.pop(1), run_name='__main__', alter_sys=True)"
)


def search_path() -> list[str]:
    """This process's module search path without the entries that name the
    current folder: relative ones (``''`` is the current folder) and the
    current folder itself."""
    here = os.path.realpath(os.getcwd())
    return [entry for entry in sys.path if os.path.isabs(entry) and os.path.realpath(entry) != here]


def python_command(module: str, *arguments: str) -> list[str]:
    """The command line running ``python -m module arguments...`` isolated
    (``-I``), with this process's search path minus the current folder."""
    return [sys.executable, "-I", "-c", _BOOTSTRAP, json.dumps(search_path()), module, *arguments]


def protect_spawned_workers() -> None:
    """Make the Python workers started from now on (multiprocessing's spawn,
    Dask's nannies) leave the current folder off their search path."""
    os.environ["PYTHONSAFEPATH"] = "1"
