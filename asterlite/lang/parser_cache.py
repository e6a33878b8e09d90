"""The deck parser's LALR tables and the trees of the decks parsed last,
kept between processes in a private folder.

Building the tables from ``deck.lark`` takes about 0.3 s, loading them
about 15 ms: without a cache every ``asterlite check`` would pay the build.
A deck's checked tree, stored as plain data under a digest of its text,
comes back in ~2 ms where loading the tables and parsing took ~35 ms of a
run's start (a deck run again, an included file shared by several decks);
the :data:`TREES_KEPT` newest are kept.
lark's own ``cache=True`` is unsafe: it pickles the tables into the shared
temporary folder under a name anyone can compute, and unpickles whatever
file has that name, so any local user could plant a pickle that runs their
code in the next ``asterlite check``. Here:

- the folder is ``$XDG_CACHE_HOME/asterlite/parser`` (by default
  ``~/.cache/asterlite/parser``), created with mode 0700, and used only when it
  and every folder above it belong to this user or to root and nobody else
  may rename its entries: not writable by group or others, unless sticky and
  root's (``/tmp``). Otherwise nothing is cached (the tables are built);
- the file is read through ``O_NOFOLLOW`` and only if it is a regular file
  of this user that nobody else may write;
- the tables and trees are plain data (dicts, lists, tuples, strings,
  numbers); they are unpickled by an Unpickler that refuses every global, so
  even a file planted there could not run code, only fail to load;
- a file is written under a temporary name and renamed: a process reading
  concurrently gets a whole file or none.
"""

from __future__ import annotations

import hashlib
import io
import os
import pickle
import stat
import sys
import tempfile
from pathlib import Path

from asterlite.trusted_paths import safe_ancestor

CACHE_NAME = ("asterlite", "parser")
PREFIX = "deck-parser-"
TREE_PREFIX = "deck-tree-"
TREES_KEPT = 256
# the tables are ~0.15 MB; a larger file is not ours
MAX_BYTES = 16 * 1024 * 1024
# bump when what is stored changes
FORMAT = "2"


class _DataOnlyUnpickler(pickle.Unpickler):
    """Unpickles builtin data only: any class or function reference (how a
    pickle runs code) is refused."""

    def find_class(self, module, name):
        raise pickle.UnpicklingError(f"refused: {module}.{name} in the parser cache")


def cache_folder() -> Path | None:
    """The private folder (created 0700 if missing), or None when it cannot
    be made or is not private."""
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    if not os.path.isabs(base):
        return None
    folder = Path(base).joinpath(*CACHE_NAME)
    try:
        folder.mkdir(mode=0o700, parents=True, exist_ok=True)
        if not _is_private_folder(folder):
            return None
    except OSError:
        return None
    return folder


def _is_private_folder(folder: Path) -> bool:
    """The folder is a real folder of this user, writable by nobody else, and
    no folder above it lets another user rename it."""
    info = os.lstat(folder)
    if not stat.S_ISDIR(info.st_mode) or info.st_uid != os.geteuid():
        return False
    if info.st_mode & 0o077:  # 0700: others may not even list it
        return False
    return all(safe_ancestor(os.stat(above)) for above in Path(os.path.realpath(folder)).parents)


def cache_key(grammar: str) -> str:
    """Names the tables of ``grammar`` for this lark and this Python."""
    import lark

    text = "\0".join((FORMAT, lark.__version__, sys.version, grammar))
    return hashlib.sha256(text.encode()).hexdigest()[:24]


def load_tables(folder: Path, key: str) -> dict | None:
    """The stored tables for ``key``, or None (absent, not ours, not data)."""
    tables = _read_data(folder / f"{PREFIX}{key}.pickle")
    if not (isinstance(tables, dict) and {"data", "memo"} <= tables.keys()):
        return None
    return tables


def _read_data(path: Path):
    """The plain data pickled in ``path``, or None (absent, not ours, not data)."""
    try:
        descriptor = os.open(path, os.O_RDONLY | os.O_NOFOLLOW)
    except OSError:
        return None
    with os.fdopen(descriptor, "rb") as stream:
        info = os.fstat(descriptor)
        if not (
            stat.S_ISREG(info.st_mode)
            and info.st_uid == os.geteuid()
            and not info.st_mode & (stat.S_IWGRP | stat.S_IWOTH)
            and info.st_size <= MAX_BYTES
        ):
            return None
        try:
            return _DataOnlyUnpickler(io.BytesIO(stream.read())).load()
        except Exception:  # damaged or foreign: built again
            return None


def store_tables(folder: Path, key: str, parser) -> None:
    """Store ``parser``'s tables for ``key`` (written aside, then renamed) and
    drop the tables of older grammars; a failure only means no cache."""
    buffer = io.BytesIO()
    parser.save(buffer, exclude_options=("postlex",))  # the indenter is given when loading
    if not _write(folder, f"{PREFIX}{key}.pickle", buffer.getvalue()):
        return
    for older in folder.glob(f"{PREFIX}*.pickle"):
        if older.name != f"{PREFIX}{key}.pickle":
            older.unlink(missing_ok=True)


def _write(folder: Path, name: str, data: bytes) -> bool:
    """Write ``data`` as ``folder/name``: aside, then renamed (a process
    reading concurrently gets a whole file or none)."""
    try:
        descriptor, part = tempfile.mkstemp(prefix=f".{name}", suffix=".part", dir=folder)
    except OSError:
        return False
    try:
        with os.fdopen(descriptor, "wb") as stream:
            stream.write(data)
        os.replace(part, folder / name)
    except OSError:  # a full disk, say
        Path(part).unlink(missing_ok=True)
        return False
    return True


def tree_key(tables_key: str, text: str, start: str, python2: bool) -> str:
    """Names the tree of ``text`` parsed from rule ``start`` by the parser of
    ``tables_key`` (:func:`cache_key`)."""
    text = "\0".join((tables_key, start, "2" if python2 else "3", text))
    return hashlib.sha256(text.encode("utf-8", "surrogatepass")).hexdigest()[:32]


def load_tree(folder: Path, key: str):
    """The stored tree data for ``key`` (:func:`store_tree`), or None."""
    path = folder / f"{TREE_PREFIX}{key}.pickle"
    data = _read_data(path)
    if not (isinstance(data, tuple) and len(data) == 2):
        return None
    try:
        os.utime(path)  # the newest kept first
    except OSError:
        pass
    return data


def store_tree(folder: Path, key: str, data: tuple) -> None:
    """Store a tree's plain data for ``key``; beyond :data:`TREES_KEPT`
    trees, the least recently used go."""
    try:
        blob = pickle.dumps(data, protocol=pickle.HIGHEST_PROTOCOL)
    except RecursionError:  # a tree too deep to pickle: parsed again next time
        return
    if len(blob) > MAX_BYTES or not _write(folder, f"{TREE_PREFIX}{key}.pickle", blob):
        return
    trees = list(folder.glob(f"{TREE_PREFIX}*.pickle"))
    if len(trees) <= TREES_KEPT:
        return
    by_age = []
    for path in trees:
        try:
            by_age.append((path.stat().st_mtime, path))
        except OSError:
            continue
    for _, path in sorted(by_age)[: len(by_age) - TREES_KEPT]:
        path.unlink(missing_ok=True)
