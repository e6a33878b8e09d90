"""The reduced matrices of a physical harmonic sweep, Tᵀ K T, Tᵀ M T and
Tᵀ C T, on one sparsity pattern (:class:`ReducedPencil`).

Symmetric matrices (the usual K, M, C) are kept as their upper triangle
only, as code_aster keeps symmetric assembled matrices: half the memory of
a large solid model. Once the LDLᵀ analysis has chosen an ordering, the
pencil is laid out in the factor's order (:meth:`ReducedPencil.in_order`),
so that the values of K + iωC - ω²M at a frequency are the factorisation's
input as they are built, with no gathered copy.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from asterlite.arrays import sorted_unique
from asterlite.harmonic.fields import TWO_PI, omega2


@dataclass
class ReducedPencil:
    """Tᵀ K T, Tᵀ M T and Tᵀ C T on one CSC pattern (``indices``, ``indptr``),
    their values aligned on it. ``upper``: the pattern is the upper triangle
    of symmetric matrices. ``perm``: the pencil is that of A[perm][:, perm]
    (None: the caller's order)."""

    n: int
    indices: np.ndarray
    indptr: np.ndarray
    stiffness: np.ndarray
    mass: np.ndarray
    damping: np.ndarray | None
    upper: bool = False
    perm: np.ndarray | None = None
    _norms: tuple | None = None

    def data(self, frequency: float) -> np.ndarray:
        """The values of K + iωC - ω²M on the pattern."""
        data = self.stiffness - omega2(frequency) * self.mass
        if self.damping is not None:
            data = data + (1j * TWO_PI * frequency) * self.damping
        return data.astype(complex, copy=False)

    def norm_bound(self, frequency: float) -> float:
        """|K| + ω²|M| + ω|C| ≥ |K + iωC - ω²M| (max column sums)."""
        if self._norms is None:
            self._norms = tuple(
                self._column_norm(v) if v is not None else 0.0
                for v in (self.stiffness, self.mass, self.damping)
            )
        k, m, c = self._norms
        w = TWO_PI * abs(frequency)
        return k + w * w * m + w * c

    def _column_norm(self, values) -> float:
        if not values.size:
            return 0.0
        magnitude = np.abs(values)
        columns = np.repeat(np.arange(self.n), np.diff(self.indptr))
        sums = np.bincount(columns, weights=magnitude, minlength=self.n)
        if self.upper:  # the lower triangle's terms are the upper's rows
            sums += np.bincount(self.indices, weights=magnitude, minlength=self.n)
            sums -= np.bincount(
                columns, weights=np.where(self.indices == columns, magnitude, 0.0), minlength=self.n
            )
        return float(sums.max())

    def _stored(self, data) -> sp.csc_matrix:
        return sp.csc_matrix((data, self.indices, self.indptr), shape=(self.n, self.n))

    def release_values(self) -> None:
        """Drop K, M and C once the last frequency's values are built: the
        factorisation then has their memory."""
        self.stiffness = self.mass = self.damping = None

    def at(self, frequency: float, data: np.ndarray | None = None) -> sp.csc_matrix:
        """K + iωC - ω²M at one frequency (CSC, complex, whole, in the
        caller's order; ``data``: its values when the caller has them)."""
        stored = self._stored(self.data(frequency) if data is None else data)
        if self.upper:
            stored = sp.csc_matrix(stored + stored.T - sp.diags(stored.diagonal()))
        if self.perm is not None:
            inverse = np.empty(self.n, dtype=np.int64)
            inverse[self.perm] = np.arange(self.n)
            stored = sp.csc_matrix(stored[inverse][:, inverse])
        return stored

    def product(self, frequency: float, x: np.ndarray, data: np.ndarray | None = None):
        """(K + iωC - ω²M) x, x in the caller's order (``data``: the values at
        ``frequency`` when the caller has them)."""
        stored = self._stored(self.data(frequency) if data is None else data)
        if self.perm is not None:
            x = x[self.perm]
        y = stored @ x
        if self.upper:
            y += stored.T @ x - stored.diagonal() * x
        if self.perm is None:
            return y
        out = np.empty_like(y)
        out[self.perm] = y
        return out

    def full_pattern(self) -> sp.csr_matrix:
        """The whole symmetric pattern (int8 ones), for the orderings."""
        ones = sp.csc_matrix(
            (np.ones(self.indices.size, dtype=np.int8), self.indices, self.indptr),
            shape=(self.n, self.n),
        )
        if self.upper:
            ones = ones + ones.T
            ones.data[:] = 1
        return sp.csr_matrix(ones)

    def in_order(self, perm, indptr, indices, source) -> ReducedPencil:
        """The same pencil laid out as A[perm][:, perm] on the upper pattern
        (``indptr``, ``indices``) whose terms are this pencil's ``source``
        terms (an LDLᵀ analysis of this pencil)."""
        if self.perm is not None or not self.upper:
            raise ValueError("only an upper pencil in the caller's order is laid out anew")

        def gathered(values):
            return None if values is None else values[source]

        return ReducedPencil(
            n=self.n,
            indices=indices,
            indptr=indptr,
            stiffness=gathered(self.stiffness),
            mass=gathered(self.mass),
            damping=gathered(self.damping),
            upper=True,
            perm=np.asarray(perm),
            _norms=self._norms,
        )


def aligned_pencil(stiffness, mass, damping, upper: bool = False) -> ReducedPencil:
    """The three reduced matrices on the union of their patterns (``upper``:
    of their upper triangles, the matrices being symmetric)."""
    mats = [
        sp.coo_matrix(sp.triu(m) if upper else m)
        for m in (stiffness, mass, damping)
        if m is not None
    ]
    n = mats[0].shape[0]
    keys = [m.col.astype(np.int64) * n + m.row for m in mats]  # column-major keys
    pattern = sorted_unique(np.concatenate(keys))
    values = []
    for m, key in zip(mats, keys, strict=True):
        data = np.zeros(pattern.size, dtype=np.result_type(m.data.dtype, float))
        np.add.at(data, np.searchsorted(pattern, key), m.data)
        values.append(data)
    del mats, keys
    rows, cols = pattern % n, pattern // n
    del pattern
    indptr = np.zeros(n + 1, dtype=np.int64)
    np.cumsum(np.bincount(cols, minlength=n), out=indptr[1:])
    return ReducedPencil(
        n=n,
        indices=rows.astype(np.int32 if n < 2**31 else np.int64),
        indptr=indptr.astype(np.int32 if rows.size < 2**31 else np.int64),
        stiffness=values[0],
        mass=values[1],
        damping=values[2] if damping is not None else None,
        upper=upper,
    )
