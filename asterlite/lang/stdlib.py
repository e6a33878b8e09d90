"""The parts of Python's standard library decks may import besides ``math``:
``cmath`` and ``os.path``, and what ``os`` itself is refused for.

``cmath`` gives its functions and constants (complex arithmetic on one
number at a time: bounded). ``os.path`` gives the string functions of
paths (``join``, ``basename``, ``dirname``, ``splitext``, ``split``...),
which read no file; ``exists``, ``isfile`` and ``isdir`` answer only for a
plain file name of the run's output folder (``fort.50``: what the deck
wrote there), and refuse any other path: a deck learns nothing of the files
outside its run. ``os.sep``, ``os.pathsep``, ``os.linesep``, ``os.curdir``
are given; ``os.system`` runs the few file commands of ``lang.shell`` in the
output folder; everything else of ``os`` (``environ``, ``getcwd``,
``remove``...) is refused by name.
"""

from __future__ import annotations

import cmath
import functools
import posixpath
from collections.abc import Callable
from pathlib import Path

from asterlite.errors import DeckRuntimeError, UnsupportedError
from asterlite.lang.limits import Limits
from asterlite.lang.values import DeckModule

# ------------------------------------------------------------------ cmath


@functools.cache
def cmath_members() -> dict:
    return {name: getattr(cmath, name) for name in dir(cmath) if not name.startswith("_")}


def cmath_module() -> DeckModule:
    return DeckModule("cmath", cmath_members())


# ---------------------------------------------------------------- os.path

PATH_FUNCTIONS = (
    "join",
    "basename",
    "dirname",
    "split",
    "splitext",
    "normpath",
    "isabs",
    "commonprefix",
)


class RefusingModule(DeckModule):
    """A module whose members beyond the given ones are refused by name."""

    __slots__ = ("reason",)

    def __init__(self, name: str, members: dict, reason: str):
        super().__init__(name, members)
        self.reason = reason

    def attribute(self, name: str):
        if name in self.members:
            return self.members[name]
        raise UnsupportedError(f"{self.name}.{name}: {self.reason}")


def _text_arguments(function: Callable, name: str, limits: Limits) -> Callable:
    """A path function taking strings only, its result within the string limit."""

    def checked(*args):
        if not all(isinstance(arg, str) for arg in args):
            raise DeckRuntimeError(f"os.path.{name} takes strings in decks")
        if sum(len(arg) for arg in args) > limits.max_string_length:
            raise DeckRuntimeError(
                f"limit exceeded: string length (limit {limits.max_string_length:,})"
            )
        return function(*args)

    checked.__name__ = name
    return checked


def os_path_module(output_folder: Callable[[], Path | None], limits: Limits) -> DeckModule:
    """``os.path``; ``output_folder()`` is the run's output folder (None: none)."""
    members = {
        name: _text_arguments(getattr(posixpath, name), name, limits) for name in PATH_FUNCTIONS
    }
    members["commonprefix"] = _common_prefix(limits)
    members["sep"] = "/"
    for name, test in (("exists", Path.exists), ("isfile", Path.is_file), ("isdir", Path.is_dir)):
        members[name] = _file_test(name, test, output_folder)
    return RefusingModule(
        "os.path",
        members,
        "decks may use os.path's string functions (join, basename, splitext...) and "
        "exists/isfile/isdir of files in the run's output folder",
    )


def _common_prefix(limits: Limits):
    def commonprefix(paths):
        paths = list(paths)
        if not all(isinstance(path, str) for path in paths):
            raise DeckRuntimeError("os.path.commonprefix takes strings in decks")
        return posixpath.commonprefix(paths)

    return commonprefix


def _file_test(name: str, test, output_folder: Callable[[], Path | None]):
    def file_test(path):
        if not isinstance(path, str):
            raise DeckRuntimeError(f"os.path.{name} takes a string in decks")
        plain = path and "/" not in path and "\\" not in path and path not in (".", "..")
        if not plain:
            raise DeckRuntimeError(
                f"os.path.{name}({path[:80]!r}): decks may only ask about a file name of the "
                "run's output folder (no folder, no absolute path)"
            )
        folder = output_folder()
        if folder is None:
            return False
        return bool(test(folder / path))

    file_test.__name__ = name
    return file_test


def os_module(
    output_folder: Callable[[], Path | None],
    limits: Limits,
    say: Callable[[str], None] | None = None,
) -> DeckModule:
    """``os``: its ``path``, a few constants and ``system`` (``lang.shell``,
    its output given to ``say``); the rest refused by name."""
    from asterlite.lang import shell

    path = os_path_module(output_folder, limits)
    members = {"path": path, "sep": "/", "pathsep": ":", "linesep": "\n", "curdir": "."}
    members["extsep"] = "."

    def system(command):
        return shell.run(command, output_folder, say or _silent, limits.max_string_length)

    members["system"] = system
    return RefusingModule(
        "os",
        members,
        "decks reach no process or environment through os, and files of the run's "
        "output folder only through os.path's tests and os.system's "
        f"{', '.join(shell.COMMANDS)}",
    )


def _silent(text: str) -> None:
    pass


# ------------------------------------------------------------------- open


class _RefusedBuiltin:
    """A builtin of Python refused by name when a deck calls it."""

    deck_unknown_policy = "store"

    def __init__(self, name: str, reason: str, touches_files: bool = False):
        self.name = name
        self.reason = reason
        self.touches_files = touches_files  # the deck meant to read or write a file

    def __call__(self, *args, **kwargs):
        error = UnsupportedError(f"{self.name}(): {self.reason}")
        error.touches_files = self.touches_files
        raise error

    def __repr__(self) -> str:
        return f"<function {self.name}>"


class GlobalsView:
    """``globals()``: the deck's names, read only (``"UELAS" in globals()``)."""

    deck_methods = frozenset({"get", "keys", "values", "items"})

    def __init__(self, namespace: dict):
        self._namespace = namespace

    def _names(self):
        return [name for name in self._namespace if not name.startswith("__")]

    def __contains__(self, name) -> bool:
        return isinstance(name, str) and not name.startswith("__") and name in self._namespace

    def __getitem__(self, name):
        if name not in self:
            raise KeyError(name)
        return self._namespace[name]

    def __iter__(self):
        return iter(self._names())

    def __len__(self) -> int:
        return len(self._names())

    def get(self, name, default=None):
        return self[name] if name in self else default

    def keys(self) -> list:
        return self._names()

    def values(self) -> list:
        return [self._namespace[name] for name in self._names()]

    def items(self) -> list:
        return [(name, self._namespace[name]) for name in self._names()]

    def __repr__(self) -> str:
        return f"<globals: {len(self)} names>"


def namespace_builtins(namespace: dict) -> dict:
    """Builtins of a deck namespace beyond library's: ``globals`` (a read-only
    view of ``namespace``) and ``open``, refused by name."""
    reason = (
        "decks read and write files through commands (LIRE_*, IMPR_*, DEFI_FICHIER) "
        "and numpy.savetxt, not with open()"
    )

    def deck_globals():
        return GlobalsView(namespace)

    deck_globals.__name__ = "globals"
    deck_globals.deck_unknown_policy = "store"
    return {"open": _RefusedBuiltin("open", reason, touches_files=True), "globals": deck_globals}
