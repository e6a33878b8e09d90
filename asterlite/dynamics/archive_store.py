"""Where a modal transient's archive goes while the compiled loop fills it.

The loop writes each archived instant into buffers by index and returns
``STATUS_FULL`` when they are full (:mod:`asterlite.dynamics.kernel`). An
archive that fits the run's memory budget grows in memory, as before. Past
the budget, the buffers stay a fixed chunk: at each ``STATUS_FULL`` their
rows are appended to unnamed files on disk (:class:`asterlite.io.disk_rows.DiskRows`),
the loop's archive index goes back to 0 and the loop resumes with its whole
state (nothing else in the loop reads that index: the archiving rule counts
steps). No Python runs per step, the arithmetic is the same and so are the
numbers, bit for bit; the result's arrays are then memory maps of those
files, which the commands read like any array.

code_aster's loop likewise stops when its archive block is full and writes
it out before it goes on (dtmarch: the results go to JEVEUX, which pages
them to disk).
"""

from __future__ import annotations

import resource
import shutil
import tempfile
from pathlib import Path

import numpy as np

from asterlite import watchdog
from asterlite.dynamics import energy as E
from asterlite.dynamics.layouts import Archive
from asterlite.errors import NumericalError
from asterlite.errors import field as named
from asterlite.io.disk_rows import DiskRows

# share of what the run may still add an archive may hold in memory (the
# physical transients' archives too: dynamics.physical.archive). An eighth:
# what a deck makes of an archive (its functions, its own arrays, a second
# transient) comes on top, and a run should stay within half its limit;
# on disk, an archive costs memory only while a command reads it
# (asterlite.io.disk_rows.release_pages)
ARCHIVE_MEMORY_SHARE = 0.125
# what an archive may hold in memory in a run without a memory limit
UNLIMITED_RUN_BYTES = 512 * 1024**2
# the buffers of an archive on disk: rows written out every this many bytes
CHUNK_BYTES = 16 * 1024**2


def memory_budget(given: int | None) -> int:
    """Bytes an archive may hold in memory: ``given`` (SchemeOptions'
    ``max_archive_bytes``), else its share of what the run may still add
    before its memory limit (the results it holds already count: a deck of
    many transients does not get the whole limit for each), else
    :data:`UNLIMITED_RUN_BYTES`."""
    if given:
        return int(given)
    headroom = watchdog.memory_headroom()
    if headroom is not None:
        return int(ARCHIVE_MEMORY_SHARE * headroom)
    return UNLIMITED_RUN_BYTES


class ArchiveStore:
    """The archive of one run: ``row_bytes`` per archived instant (buffers
    and energy rows), ``budget`` bytes in memory at most; ``folder``: where
    the files of an archive on disk go (None: the system's temporary
    folder); ``resumable``: whether the loop's archive index may go back to
    0 (not code_aster 10-12's ADAPT_ORDRE2 loop, which compares it with its
    own slots: that archive grows in memory up to the budget)."""

    def __init__(self, row_bytes: int, budget: int, folder: Path | None, resumable: bool):
        self.row_bytes = int(row_bytes)
        self.budget = int(budget)
        self.folder = Path(folder) if folder is not None else None
        self.resumable = resumable
        self.files: dict[str, DiskRows] | None = None  # None: nothing written out yet
        self.chunked = False  # the buffers are a chunk: written out whenever full
        self.last_time: float | None = None  # the last instant written out

    @property
    def on_disk(self) -> bool:
        return self.files is not None

    def first_capacity(self, capacity: int, largest_part_bytes: int) -> int:
        """Rows of the first buffers for ``capacity`` expected instants: all
        of them within the budget, else a chunk (the archive goes to disk;
        ``largest_part_bytes``: a row of its largest file)."""
        if capacity * self.row_bytes <= self.budget or not self.resumable:
            return capacity
        self.check_disk(capacity, largest_part_bytes)
        self.chunked = True
        return max(1, min(CHUNK_BYTES, self.budget) // self.row_bytes)

    def write_out_when_full(self, buffers: Archive, count: int) -> bool:
        """On STATUS_FULL: whether the rows are written out (the archive is on
        disk, or doubling the buffers would pass the budget) rather than the
        buffers grown."""
        if self.chunked or self.on_disk:
            return True
        if 2 * len(buffers.times) * self.row_bytes <= self.budget or not self.resumable:
            return False
        self.check_disk(count, max(part[0].nbytes for part in buffers))
        return True

    def write_out(self, buffers: Archive, balance, count: int) -> None:
        """Append the first ``count`` rows of the buffers (and of the energy
        balance) to the files; the caller sets the loop's index back to 0."""
        if self.files is None:
            self.files = self._new_files(buffers, balance)
        for name, rows in self._parts(buffers, balance):
            self.files[name].append(rows[:count])
        if count:
            self.last_time = float(buffers.times[count - 1])

    def finish(self, buffers: Archive, balance, count: int):
        """(archive arrays, energy rows or None) of the finished run: views of
        the buffers in memory, or memory maps of the files."""
        energy = E.enabled(balance)
        if not self.on_disk:
            arrays = Archive(*(trimmed(b, count) for b in buffers))
            return arrays, balance.rows[:count].copy() if energy else None
        self.write_out(buffers, balance, count)
        stored = {name: rows.array() for name, rows in self.files.items()}
        total = self.files["times"].count
        arrays = Archive(
            stored["times"].reshape(total),
            stored["order"].reshape(total),
            stored["depl"],
            stored["vite"],
            stored["acce"],
            stored["vint"].reshape((total, *buffers.vint.shape[1:])),
            stored["info"],
        )
        return arrays, stored["energy"] if energy else None

    def check_disk(self, instants: int, largest_part_bytes: int) -> None:
        """Refuse an archive whose ``instants`` would not fit the free space
        of its folder, or whose largest file (``largest_part_bytes`` a row)
        would pass the size a file of the run may reach (its output limit:
        the runner's RLIMIT_FSIZE)."""
        folder = self.folder or Path(tempfile.gettempdir())
        existing = next((f for f in (folder, *folder.parents) if f.exists()), folder)
        needed, free = instants * self.row_bytes, shutil.disk_usage(existing).free
        file_cap = resource.getrlimit(resource.RLIMIT_FSIZE)[0]
        if file_cap != resource.RLIM_INFINITY and instants * largest_part_bytes > file_cap:
            raise NumericalError(
                f"archive file size: {instants} archived instants would write a file of "
                f"{instants * largest_part_bytes / 1024**2:.0f} MB, past the run's output "
                f"limit of {file_cap / 1024**2:.0f} MB (past {self.budget / 1024**2:.0f} MB "
                "an archive is kept on disk; asterlite run --output-limit): archive less "
                f"often ({named('archive')} {named('archive.period')} or "
                f"{named('archive.instants')})"
            )
        if needed <= free:
            return
        raise NumericalError(
            f"archive disk space: {instants} archived instants would take "
            f"{needed / 1024**3:.2f} GB on disk in {folder} ({free / 1024**3:.2f} GB free; "
            f"past {self.budget / 1024**2:.0f} MB an archive is kept on disk): archive less "
            f"often ({named('archive')} {named('archive.period')} or "
            f"{named('archive.instants')})"
        )

    def _new_files(self, buffers: Archive, balance) -> dict[str, DiskRows]:
        if self.folder is not None:
            self.folder.mkdir(parents=True, exist_ok=True)
        files = {}
        for name, rows in self._parts(buffers, balance):
            width = int(np.prod(rows.shape[1:], dtype=np.int64))
            files[name] = DiskRows(width, self.folder, rows.dtype)
        return files

    @staticmethod
    def _parts(buffers: Archive, balance):
        parts = list(zip(Archive._fields, buffers, strict=True))
        if E.enabled(balance):
            parts.append(("energy", balance.rows))
        return parts


def trimmed(buffer: np.ndarray, count: int) -> np.ndarray:
    """The first ``count`` rows of an archive buffer: a view when they fill
    most of it (a fixed step's archive is sized exactly: copying 10^5 rows
    cost as much as the loop that wrote them), a copy when the buffer is
    mostly empty (so that a grown buffer's unused half is freed)."""
    if 2 * count >= len(buffer):
        return buffer[:count]
    return buffer[:count].copy()
