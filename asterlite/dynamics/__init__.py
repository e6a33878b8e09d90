"""Transient dynamics on a modal basis: shock/friction forces, schemes, compiled loop.

numba's cache (``cache=True``) checks a compiled kernel against its own
source file only: a kernel whose file did not change is loaded as it was
compiled even when a helper it inlines from another file of this package
changed (an upgrade, a ``git pull``), and it would then run the old helper.
So the kernels are kept in a folder named after a digest of every source
of this package (:func:`kernel_cache_folder`): a change of any of them
starts an empty cache, which ``asterlite warmup --numba`` (or the first run,
with its compile notice) fills. So :func:`use_kernel_cache` sets numba's cache
folder for the process and its children (``NUMBA_CACHE_DIR``) before numba
is imported (:func:`asterlite.dynamics.jit.load`, the one place that imports
it): under the one the user gave, else this package's ``__pycache__``, else
the user's cache folder when the package is read-only. A run on the C++ loops
never imports numba, and never reads the sources for their digest.
"""

from __future__ import annotations

import functools
import hashlib
import json
import os
import sys
import tempfile
from pathlib import Path

from asterlite.trusted_paths import trusted_folder

PACKAGE = Path(__file__).resolve().parent
CACHE_PREFIX = "kernels-"


# compiled by pip, not numba: no kernel of the cache inlines anything there
NOT_NUMBA = ("native",)


def source_digest(folder: Path = PACKAGE) -> str:
    """A digest of every Python source below ``folder`` (names and bytes)
    but those of :data:`NOT_NUMBA`."""
    digest = hashlib.sha256()
    for path in sorted(folder.rglob("*.py")):
        if path.relative_to(folder).parts[0] in NOT_NUMBA:
            continue
        digest.update(path.relative_to(folder).as_posix().encode())
        digest.update(b"\0")
        digest.update(path.read_bytes())
    return digest.hexdigest()[:16]


def _writable(folder: Path) -> bool:
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError:
        return False
    return os.access(folder, os.W_OK)


def kernel_cache_roots(user_folder: str | None) -> list[Path]:
    """Where the digest folders may live, in order: the user's
    NUMBA_CACHE_DIR, this package's ``__pycache__``, ``$XDG_CACHE_HOME/asterlite``."""
    roots = [Path(user_folder)] if user_folder else []
    in_tree = PACKAGE / "__pycache__"
    if _writable(in_tree):
        roots.append(in_tree)
    home = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    roots.append(Path(home) / "asterlite")
    return roots


def kernel_cache_folder() -> Path:
    """This package's numba cache folder, ``<root>/kernels-<digest>``, in the
    first root where it is trusted (:mod:`asterlite.trusted_paths`: numba's
    index files are pickles, so a folder another user may write could make
    this process run their code); a NUMBA_CACHE_DIR that already names it
    (set for a parent process) is its root. None trusted: a new private
    temporary folder (kernels compile in every process, nothing foreign is
    loaded)."""
    name = CACHE_PREFIX + source_digest()
    given = os.environ.get("NUMBA_CACHE_DIR")
    if given and Path(given).name == name:
        given = str(Path(given).parent)
    for root in kernel_cache_roots(given):
        folder = root / name
        try:
            folder.mkdir(mode=0o700, parents=True, exist_ok=True)
        except OSError:
            continue
        if trusted_folder(root) and trusted_folder(folder):
            return folder
    return Path(tempfile.mkdtemp(prefix="asterlite-kernels-")) / name


def use_kernel_cache() -> None:
    """numba's cache folder (:func:`kernel_cache_folder`) for this process
    and its children; called before numba is imported, and again by a test
    that changes the environment."""
    folder = str(kernel_cache_folder())
    os.environ["NUMBA_CACHE_DIR"] = folder  # numba reads it when imported, children too
    config = sys.modules.get("numba.core.config")
    if config is not None:  # numba already imported: its locators read the config
        config.CACHE_DIR = folder


@functools.cache
def _compile_seconds() -> dict[str, float]:
    return json.loads((PACKAGE / "compile_seconds.json").read_text())["cpu_seconds"]


def compile_estimate(name: str) -> float | None:
    """About what compiling the kernel ``name`` takes (CPU seconds measured
    by ``asterlite warmup -v``, kept as data in compile_seconds.json): the
    compile notice's "~N s" and the warmup's longest-first order; nothing
    else depends on it."""
    return _compile_seconds().get(name)
