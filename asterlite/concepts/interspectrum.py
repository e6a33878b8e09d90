"""Spectral matrices (``interspectre``): power and cross spectral densities.

An interspectrum holds functions on one shared abscissa grid (``disc``):
frequencies for a spectral matrix (DEFI_INTE_SPEC, LIRE_INTE_SPEC,
CALC_INTE_SPEC), instants for the time signals GENE_FONC_ALEA draws. Each
function has a key:

- ``(i, j)`` order numbers (``NUME_ORDRE_I`` / ``NUME_ORDRE_J``), or
- ``(node_i, cmp_i, node_j, cmp_j)`` (``NOEUD_I`` / ``NOM_CMP_I`` ...), or
- ``k`` alone (``NUME_ORDRE``) for generated signals.

As code_aster stores them, a diagonal term (i = j) is real and an
off-diagonal term complex; only the upper triangle is kept, the lower one
being its conjugate.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from asterlite.concepts.base import Concept


@dataclass(eq=False)
class InterSpectrum(Concept):
    aster_types = ("interspectre",)

    abscissa: str  # 'FREQ' or 'INST'
    disc: np.ndarray
    keys: list = field(default_factory=list)
    values: list[np.ndarray] = field(default_factory=list)
    title: str = ""

    def __post_init__(self) -> None:
        self.disc = np.asarray(self.disc, dtype=float)

    @property
    def keyed_by_nodes(self) -> bool:
        return bool(self.keys) and isinstance(self.keys[0], tuple) and len(self.keys[0]) == 4

    def is_diagonal(self, key) -> bool:
        if not isinstance(key, tuple):
            return True
        if len(key) == 2:
            return key[0] == key[1]
        return key[0] == key[2] and key[1] == key[3]

    def lookup(self, key) -> np.ndarray:
        """The stored function of ``key`` (the conjugate of its transpose when
        only that one is stored); KeyError when neither is."""
        if key in self.keys:
            return self.values[self.keys.index(key)]
        if isinstance(key, tuple):
            swapped = key[::-1] if len(key) == 2 else (key[2], key[3], key[0], key[1])
            if swapped in self.keys:
                return np.conj(self.values[self.keys.index(swapped)])
        raise KeyError(key)

    def order_numbers(self) -> list[int]:
        """Distinct order numbers of an (i, j)-keyed matrix, ascending."""
        return sorted({k for key in self.keys for k in key})

    def matrix(self) -> np.ndarray:
        """The full Hermitian matrix at each abscissa, shape (n, dim, dim), of
        an (i, j)-keyed interspectrum (missing terms are zero)."""
        numbers = self.order_numbers()
        where = {n: k for k, n in enumerate(numbers)}
        out = np.zeros((self.disc.size, len(numbers), len(numbers)), dtype=complex)
        for (i, j), vals in zip(self.keys, self.values, strict=True):
            out[:, where[i], where[j]] = vals
            if i != j:
                out[:, where[j], where[i]] = np.conj(vals)
        return out
