"""Rows of a large array kept on disk rather than in memory: appended to an
unnamed file (no name in any folder, gone with the process) and read back
as a copy-on-write memory map, whose pages the system loads as they are
read and may drop again. A transient's archive past the run's memory
budget lives there (:mod:`asterlite.dynamics.physical.archive`, the modal
loop's :mod:`asterlite.dynamics.archive_store`)."""

from __future__ import annotations

import tempfile
from pathlib import Path

import numpy as np


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
        (writing into it changes this process's copy only)."""
        self._file.flush()
        if self.count == 0 or self.n_cols == 0:
            return np.zeros((self.count, self.n_cols), dtype=self.dtype)
        return np.memmap(self._file, dtype=self.dtype, mode="c", shape=(self.count, self.n_cols))
