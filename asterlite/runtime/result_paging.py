"""Fields of the results a deck holds, moved to disk past a share of the run's
memory limit.

A deck keeps every result it names until its end: a chain of physical
transients, field projections and converted loads (sdlv127c: sixteen
results of 151 instants) holds them all, where code_aster's JEVEUX writes
them out and reads them back as they are used. After each command the
session calls :func:`page_out`: while the nodal fields of the results the
deck's names hold in memory pass :data:`RESULT_MEMORY_SHARE` of the run's
memory limit, the fields of the newest result go to an unnamed file and
are read back as a copy-on-write map (:mod:`asterlite.io.disk_rows`: the
same values, bit for bit, read like any array), whose pages go back to the
system after each command (:func:`asterlite.io.disk_rows.release_pages`).
A run without a memory limit keeps its results in memory.
"""

from __future__ import annotations

import mmap
import resource

import numpy as np

from asterlite import watchdog
from asterlite.concepts.base import Concept
from asterlite.io import disk_rows
from asterlite.io.disk_rows import DiskRows

# share of the run's memory limit the results' fields may hold in memory
RESULT_MEMORY_SHARE = 0.25
# smaller fields stay in memory (a file and a map each are not worth it)
MIN_FIELD_BYTES = 1024 * 1024


def on_disk(values: np.ndarray) -> bool:
    """Whether ``values`` are (a view of) a memory map."""
    base = values
    while base is not None:
        if isinstance(base, (np.memmap, mmap.mmap)):
            return True
        base = getattr(base, "base", None)
    return False


def paged_fields(concept) -> dict | None:
    """The dict of nodal fields (name: array) of a result, else None."""
    fields = getattr(concept, "fields", None)
    if not isinstance(concept, Concept) or not isinstance(fields, dict):
        return None
    return fields


def _large(fields: dict) -> list[str]:
    return [
        name
        for name, values in fields.items()
        if isinstance(values, np.ndarray)
        and values.nbytes >= MIN_FIELD_BYTES
        and values.ndim >= 1
        and not on_disk(values)
    ]


def _file_cap() -> float:
    """The size a file of the run may reach (its output limit: RLIMIT_FSIZE)."""
    cap = resource.getrlimit(resource.RLIMIT_FSIZE)[0]
    return float("inf") if cap == resource.RLIM_INFINITY else cap


def held_in_memory(namespace: dict) -> int:
    """Bytes of the large in-memory fields of the results ``namespace`` names."""
    seen, total = set(), 0
    for value in list(namespace.values()):
        fields = paged_fields(value)
        if fields is None or id(value) in seen:
            continue
        seen.add(id(value))
        total += sum(fields[name].nbytes for name in _large(fields))
    return total


def to_disk(values: np.ndarray, folder=None) -> np.ndarray:
    """``values`` written to an unnamed file, as a map of it (same shape, dtype, values)."""
    rows = DiskRows(int(np.prod(values.shape[1:], dtype=np.int64)), folder, values.dtype)
    rows.append(values.reshape(values.shape[0], -1))
    return rows.array().reshape(values.shape)


def page_out(namespace: dict, concept, limit_mb: float | None = None, folder=None) -> list[str]:
    """Move the large fields of ``concept`` to unnamed files in ``folder``
    (None: the system's temporary folder) when the results the deck holds
    (``namespace``, ``concept`` included) pass their share of the memory
    limit (``limit_mb``, else the run's); the names of the fields moved. A
    field past the run's file size limit, or a disk that cannot take it,
    leaves it in memory (paging saves memory; it is never needed)."""
    limit_mb = watchdog.memory_limit_mb() if limit_mb is None else limit_mb
    fields = paged_fields(concept)
    if not limit_mb or fields is None:
        return []
    names = _large(fields)
    if not names:
        return []
    held = held_in_memory(namespace)
    if not any(value is concept for value in namespace.values()):
        held += sum(fields[name].nbytes for name in names)
    if held <= RESULT_MEMORY_SHARE * limit_mb * watchdog.MEGABYTE:
        return []
    moved = []
    for name in names:
        if fields[name].nbytes > _file_cap():
            continue
        try:
            fields[name] = to_disk(fields[name], folder)
        except OSError:  # a full disk, a folder gone: the field stays in memory
            continue
        moved.append(name)
    return moved


def after_command(namespace: dict, concept, folder=None) -> None:
    """What the session does after each command: :func:`page_out` its
    result (to ``folder``, the run's output folder, as the archives), then
    give back the pages of the maps the command read."""
    page_out(namespace, concept, folder=folder)
    disk_rows.release_pages()
