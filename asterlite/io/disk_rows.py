"""Rows of a large array kept on disk rather than in memory: appended to an
unnamed file (no name in any folder, gone with the process) and read back
as a copy-on-write memory map, whose pages the system loads as they are
read and may drop again. A transient's archive past the run's memory
budget lives there (:mod:`asterlite.dynamics.physical.archive`)."""

from __future__ import annotations

import tempfile
from pathlib import Path

import numpy as np


class DiskRows:
    """float64 rows of ``n_cols`` values, appended one or a block at a time."""

    def __init__(self, n_cols: int, folder: Path | None = None):
        self.n_cols = int(n_cols)
        self.count = 0
        # TemporaryFile: unlinked at once (O_TMPFILE where the system has it)
        self._file = tempfile.TemporaryFile(dir=folder)

    def append(self, rows: np.ndarray) -> None:
        rows = np.ascontiguousarray(rows, dtype=np.float64).reshape(-1, self.n_cols)
        self._file.write(rows.tobytes())
        self.count += rows.shape[0]

    def array(self) -> np.ndarray:
        """The rows written, (count, n_cols): a copy-on-write map of the file
        (writing into it changes this process's copy only)."""
        self._file.flush()
        if self.count == 0 or self.n_cols == 0:
            return np.zeros((self.count, self.n_cols))
        return np.memmap(self._file, dtype=np.float64, mode="c", shape=(self.count, self.n_cols))
