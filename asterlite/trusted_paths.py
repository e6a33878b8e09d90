"""Folders whose files asterlite may load code-bearing data from.

numba's kernel cache and the deck parser's tables are pickles: loading one
that someone else wrote runs their code. A folder is trusted when it and
every folder above it belong to this user or to root and nobody else may
add, replace or rename entries in it: not writable by group or others,
unless it is a sticky folder of root's (``/tmp``), where others may add
entries but not rename ours.
"""

from __future__ import annotations

import os
import stat
from pathlib import Path


def safe_ancestor(info: os.stat_result) -> bool:
    """A folder above a trusted one: this user's or root's, and nobody else
    may rename its entries."""
    if info.st_uid not in (os.geteuid(), 0):
        return False
    shared = info.st_mode & (stat.S_IWGRP | stat.S_IWOTH)
    return not shared or bool(info.st_mode & stat.S_ISVTX and info.st_uid == 0)


def trusted_folder(folder: Path) -> bool:
    """``folder`` is a real folder (not a symlink) of this user or root,
    writable by nobody else, below folders that let nobody else rename it."""
    try:
        info = os.lstat(folder)
        if not stat.S_ISDIR(info.st_mode) or info.st_uid not in (os.geteuid(), 0):
            return False
        if info.st_mode & (stat.S_IWGRP | stat.S_IWOTH):
            return False
        return all(
            safe_ancestor(os.stat(above)) for above in Path(os.path.realpath(folder)).parents
        )
    except OSError:
        return False
