"""Archived states of a physical transient, grown by blocks."""

from __future__ import annotations

import numpy as np


class Archive:
    """Times and reduced (q, v, a) at the archived instants. ``capacity``:
    the number of states to hold, exact when the scheme knows it (fixed
    steps): the storage then never grows by copies."""

    def __init__(self, n_free: int, capacity: int = 64):
        capacity = max(int(capacity), 1)
        self.count = 0
        self.times = np.zeros(capacity)
        self.states = np.zeros((3, capacity, n_free))

    def add(self, t: float, q, v, a) -> None:
        if self.count == self.times.size:
            self.times = np.concatenate([self.times, np.zeros_like(self.times)])
            self.states = np.concatenate([self.states, np.zeros_like(self.states)], axis=1)
        self.times[self.count] = t
        self.states[0, self.count] = q
        self.states[1, self.count] = v
        self.states[2, self.count] = a
        self.count += 1

    def arrays(self):
        """Times and (q, v, a) of the archived states: views of the archive's
        own storage, not copies (a transient's archive is its largest array)."""
        n = self.count
        return self.times[:n], self.states[0, :n], self.states[1, :n], self.states[2, :n]


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
