"""Archived states of a physical transient, grown by blocks."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from asterlite import watchdog
from asterlite.dynamics.archive_store import memory_budget
from asterlite.io.disk_rows import DiskRows


def archive_on_disk(n_rows: int, n_free: int, n_dofs: int) -> bool:
    """Whether an archive of ``n_rows`` states goes to disk: under a memory
    limit, when its states and fields would take more than an archive's
    share of the run's headroom (asterlite.dynamics.archive_store)."""
    if watchdog.memory_limit_mb() is None:
        return False
    size = 3 * n_rows * (n_free + n_dofs) * 8
    return size > memory_budget(None)


class Archive:
    """Times and reduced (q, v, a) at the archived instants. ``capacity``:
    the number of states to hold, exact when the scheme knows it (fixed
    steps): the storage then never grows by copies. q, v and a are three
    arrays, so that each can be let go of once expanded (:meth:`take`).
    ``disk``: the states go to unnamed files in that folder (None: the
    system's temporary folder) instead of memory; False: in memory."""

    def __init__(self, n_free: int, capacity: int = 64, disk: Path | None | bool = False):
        capacity = max(int(capacity), 1)
        self.count = 0
        self.times = np.zeros(capacity)
        self.on_disk = disk is not False
        if self.on_disk:
            self.states = [DiskRows(n_free, disk or None) for _ in range(3)]
        else:
            self.states = [np.zeros((capacity, n_free)) for _ in range(3)]

    def add(self, t: float, q, v, a) -> None:
        if self.count == self.times.size:
            self.times = np.concatenate([self.times, np.zeros_like(self.times)])
            if not self.on_disk:
                self.states = [np.concatenate([s, np.zeros_like(s)]) for s in self.states]
        self.times[self.count] = t
        for storage, value in zip(self.states, (q, v, a), strict=True):
            if self.on_disk:
                storage.append(value)
            else:
                storage[self.count] = value
        self.count += 1

    def arrays(self):
        """Times and (q, v, a) of the archived states: views of the archive's
        own storage, not copies (a transient's archive is its largest array)."""
        n = self.count
        return (self.times[:n], *(self._stored(k) for k in range(3)))

    def take(self, k: int) -> np.ndarray:
        """The archived states of quantity ``k`` (0 q, 1 v, 2 a), which the
        archive lets go of: their memory goes with the caller's last view."""
        states, self.states[k] = self._stored(k), None
        return states

    def _stored(self, k: int) -> np.ndarray:
        storage = self.states[k]
        return storage.array() if self.on_disk else storage[: self.count]


def archived_steps(times: np.ndarray, pas_arch: int, instants, precision: float, relative: bool):
    """Boolean mask over the step instants ``times`` (index 0 is the initial
    state): every ``pas_arch``-th step, the requested instants (within
    precision), the first and the last instant."""
    n = times.size
    mask = np.zeros(n, dtype=bool)
    mask[0] = mask[-1] = True
    if pas_arch > 0:
        mask[::pas_arch] = True
    for t in np.atleast_1d(np.asarray(instants, dtype=float)):
        k = int(np.argmin(np.abs(times - t)))
        tol = precision * (abs(t) if relative else 1.0)
        if abs(times[k] - t) <= max(tol, 1e-300):
            mask[k] = True
    return mask
