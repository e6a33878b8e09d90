"""Rows of a large array kept on disk rather than in memory: appended to an
unnamed file (no name in any folder, gone with the process) and read back
as a copy-on-write memory map, whose pages the system loads as they are
read. A transient's archive past the run's memory budget lives there
(:mod:`asterlite.dynamics.physical.archive`, the modal loop's
:mod:`asterlite.dynamics.archive_store`).

The pages a command read stay in the process (its resident size, which a
run's memory limit counts) until the map is gone: :func:`release_pages`
gives them back after each command (the session calls it), so an archive
on disk costs memory only while a command streams through it, as
code_aster's JEVEUX pages its objects in and out.
"""

from __future__ import annotations

import mmap
import sys
import tempfile
import weakref
from pathlib import Path

import numpy as np

# Linux's madvise(MADV_PAGEOUT) (kernel 5.4 and later): take the pages of a
# range out of the process; unlike MADV_DONTNEED it keeps what was written
# into a copy-on-write map, so no array loses a value (Python names it from 3.13)
MADV_PAGEOUT = getattr(mmap, "MADV_PAGEOUT", 21 if sys.platform.startswith("linux") else None)

# the maps DiskRows.array made that an array still uses
_MAPS: weakref.WeakSet = weakref.WeakSet()


def release_pages() -> int:
    """Take the pages of every live map out of the process (they are read
    again from the file, or the system's cache, when an array is next
    read); the number of bytes mapped. Nothing where the system cannot."""
    mapped = 0
    for region in list(_MAPS):
        mapped += len(region)
        if MADV_PAGEOUT is None:
            continue
        try:
            region.madvise(MADV_PAGEOUT)
        except (OSError, ValueError):  # a kernel before 5.4, a closed map
            continue
    return mapped


class DiskRows:
    """Rows of ``n_cols`` values of ``dtype`` (float64 unless given),
    appended one or a block at a time."""

    def __init__(self, n_cols: int, folder: Path | None = None, dtype=np.float64):
        self.n_cols = int(n_cols)
        self.dtype = np.dtype(dtype)
        self.count = 0
        # TemporaryFile: unlinked at once (O_TMPFILE where the system has it)
        self._file = tempfile.TemporaryFile(dir=folder)

    def append(self, rows: np.ndarray) -> None:
        rows = np.ascontiguousarray(rows, dtype=self.dtype)
        if self.n_cols == 0:  # rows of nothing: only their count (first axis, or one row)
            self.count += rows.shape[0] if rows.ndim > 1 else 1
            return
        rows = rows.reshape(-1, self.n_cols)
        if rows.size:
            self._file.write(memoryview(rows).cast("B"))  # the rows' own bytes, no copy
        self.count += rows.shape[0]

    @property
    def nbytes(self) -> int:
        return self.count * self.n_cols * self.dtype.itemsize

    def array(self) -> np.ndarray:
        """The rows written, (count, n_cols): a copy-on-write map of the file
        (writing into it changes this process's copy only), whose pages
        :func:`release_pages` gives back."""
        self._file.flush()
        if self.count == 0 or self.n_cols == 0:
            return np.zeros((self.count, self.n_cols), dtype=self.dtype)
        mapped = np.memmap(self._file, dtype=self.dtype, mode="c", shape=(self.count, self.n_cols))
        region = getattr(mapped, "_mmap", None)  # numpy's mmap.mmap object
        if isinstance(region, mmap.mmap):
            _MAPS.add(region)
        return mapped
