"""Large arrays of the concepts a deck holds, moved to disk past a share of
the run's memory limit.

A deck keeps every concept it names until its end or until the name is
bound again: a chain of physical transients, field projections and
converted loads (sdlv127c: sixteen results of 151 instants) holds them
all, a harmonic loop (sdlv126h) holds the last turn's assembled matrices
while the next turn assembles its own, where code_aster's JEVEUX writes
them out and reads them back as they are used. After each command the
session calls :func:`page_out`: while the large arrays of the concepts the
deck's names hold in memory pass :data:`RESULT_MEMORY_SHARE` of the run's
memory limit, those of the newest concept go to an unnamed file and are
read back as a copy-on-write map (:mod:`asterlite.io.disk_rows`: the same
values, bit for bit, read like any array), whose pages go back to the
system after each command (:func:`asterlite.io.disk_rows.release_pages`).
A run without a memory limit keeps its concepts in memory.

Which arrays of a concept may go is declared, not guessed: the nodal
fields of a result (its ``fields`` dict), and for other kinds the dotted
attribute paths a concept class lists in ``PAGED_ARRAYS`` (an assembled
matrix: its CSR's ``data`` and ``indices``; ``indptr``, one entry a row,
stays).
"""

from __future__ import annotations

import mmap
import resource

import numpy as np

from asterlite import watchdog
from asterlite.concepts.base import Concept
from asterlite.io import disk_rows
from asterlite.io.disk_rows import DiskRows

# share of the run's memory limit the pageable arrays the deck names (results'
# fields, assembled matrices) may hold in memory: an eighth, as the archives'
# share of the headroom (a harmonic loop's complex stiffness and mass, 120 MiB
# under a 512 MB limit, then go to disk before the next turn assembles its own)
RESULT_MEMORY_SHARE = 0.125
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


class _Slot:
    """Where one pageable array of a concept is held: an item of a dict or
    an attribute of an object (read and replaced in place)."""

    __slots__ = ("owner", "key", "item", "name")

    def __init__(self, owner, key: str, item: bool, name: str):
        self.owner, self.key, self.item, self.name = owner, key, item, name

    def get(self):
        return self.owner[self.key] if self.item else getattr(self.owner, self.key, None)

    def put(self, values: np.ndarray) -> None:
        if self.item:
            self.owner[self.key] = values
        else:
            setattr(self.owner, self.key, values)


def _slots(concept) -> list[_Slot]:
    """The pageable arrays of ``concept``: a result's fields, and the dotted
    attribute paths its class declares in ``PAGED_ARRAYS``."""
    if not isinstance(concept, Concept):
        return []
    slots = []
    fields = paged_fields(concept)
    if fields is not None:
        slots += [_Slot(fields, name, True, name) for name in list(fields)]
    for path in getattr(type(concept), "PAGED_ARRAYS", ()):
        *hops, key = path.split(".")
        owner = concept
        for hop in hops:
            owner = getattr(owner, hop, None)
        if owner is not None:
            slots.append(_Slot(owner, key, False, path))
    return slots


def _large(slots: list[_Slot]) -> list[_Slot]:
    large = []
    for slot in slots:
        values = slot.get()
        if (
            isinstance(values, np.ndarray)
            and values.nbytes >= MIN_FIELD_BYTES
            and values.ndim >= 1
            and not on_disk(values)
        ):
            large.append(slot)
    return large


def _file_cap() -> float:
    """The size a file of the run may reach (its output limit: RLIMIT_FSIZE)."""
    cap = resource.getrlimit(resource.RLIMIT_FSIZE)[0]
    return float("inf") if cap == resource.RLIM_INFINITY else cap


def held_in_memory(namespace: dict) -> int:
    """Bytes of the large in-memory pageable arrays of the concepts
    ``namespace`` names (an array two of them share counted once)."""
    seen, total = set(), 0
    for value in list(namespace.values()):
        if id(value) in seen:
            continue
        seen.add(id(value))
        for slot in _large(_slots(value)):
            values = slot.get()
            if id(values) not in seen:
                seen.add(id(values))
                total += values.nbytes
    return total


def to_disk(values: np.ndarray, folder=None) -> np.ndarray:
    """``values`` written to an unnamed file, as a map of it (same shape, dtype, values)."""
    rows = DiskRows(int(np.prod(values.shape[1:], dtype=np.int64)), folder, values.dtype)
    rows.append(values.reshape(values.shape[0], -1))
    return rows.array().reshape(values.shape)


def page_out(namespace: dict, concept, limit_mb: float | None = None, folder=None) -> list[str]:
    """Move the large pageable arrays of ``concept`` (a result's fields, the
    arrays its class declares in ``PAGED_ARRAYS``) to unnamed files in
    ``folder`` (None: the system's temporary folder) when the concepts the
    deck holds (``namespace``, ``concept`` included) pass their share of the
    memory limit (``limit_mb``, else the run's); the names of the arrays
    moved (a field's name, an attribute's path). An array past the run's
    file size limit, or a disk that cannot take it, stays in memory (paging
    saves memory; it is never needed)."""
    limit_mb = watchdog.memory_limit_mb() if limit_mb is None else limit_mb
    if not limit_mb:
        return []
    slots = _large(_slots(concept))
    if not slots:
        return []
    held = held_in_memory(namespace)
    if not any(value is concept for value in namespace.values()):
        held += held_in_memory({"": concept})
    if held <= RESULT_MEMORY_SHARE * limit_mb * watchdog.MEGABYTE:
        return []
    moved = []
    for slot in slots:
        values = slot.get()
        if values.nbytes > _file_cap():
            continue
        try:
            slot.put(to_disk(values, folder))
        except OSError:  # a full disk, a folder gone: the array stays in memory
            continue
        moved.append(slot.name)
    return moved


def after_command(namespace: dict, concept, folder=None) -> None:
    """What the session does after each command: :func:`page_out` its
    result (to ``folder``, the run's output folder, as the archives), then
    give back the pages of the maps the command read and the allocator's
    free pages (a command's freed temporaries below the allocator's mapping
    threshold stay in its heap, resident, until trimmed: 60-100 MB between
    the commands of sdlv126h's loop)."""
    page_out(namespace, concept, folder=folder)
    disk_rows.release_pages()
    watchdog.trim_allocator()
