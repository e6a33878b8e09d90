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
from asterlite.fem import matrix_rows
from asterlite.fem.matrix_rows import give_back
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

    def data(self, frequency: float, out: np.ndarray | None = None) -> np.ndarray:
        """The values of K + iωC - ω²M on the pattern (written into ``out``,
        complex, when given: a solver's own input array)."""
        if out is not None:  # a block of terms at a time: no whole temporary
            w2, w = omega2(frequency), 1j * TWO_PI * frequency
            for lo in range(0, out.size, matrix_rows.BLOCK_TERMS):
                hi = min(lo + matrix_rows.BLOCK_TERMS, out.size)
                np.subtract(self.stiffness[lo:hi], w2 * self.mass[lo:hi], out=out[lo:hi])
                if self.damping is not None:
                    np.add(out[lo:hi], w * self.damping[lo:hi], out=out[lo:hi])
            return out
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
        n, indptr, indices = self.n, self.indptr, self.indices
        sums = np.zeros(n)
        lower = np.zeros(n) if self.upper else None  # the lower triangle's terms: the upper's rows
        diagonal = np.zeros(n) if self.upper else None
        # a block of whole columns at a time (each column's sum in the order
        # of its terms; np.add.at sums the rows' terms in the order of all
        # terms, as one bincount over them would)
        for first, stop in matrix_rows.blocks(indptr):
            lo, hi = int(indptr[first]), int(indptr[stop])
            magnitude = np.abs(values[lo:hi])
            columns = np.repeat(np.arange(stop - first), np.diff(indptr[first : stop + 1]))
            sums[first:stop] = np.bincount(columns, weights=magnitude, minlength=stop - first)
            if self.upper:
                np.add.at(lower, indices[lo:hi], magnitude)
                on_diagonal = indices[lo:hi] == columns + first
                diagonal[first:stop] = np.bincount(
                    columns, weights=np.where(on_diagonal, magnitude, 0.0), minlength=stop - first
                )
        if self.upper:
            sums += lower
            sums -= diagonal
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
    if upper:
        return aligned_triangles(
            *(None if m is None else sp.triu(m, format="csc") for m in (stiffness, mass, damping))
        )
    mats = [sp.coo_matrix(m) for m in (stiffness, mass, damping) if m is not None]
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
        upper=False,
    )


def aligned_triangles(stiffness, mass, damping, owned: bool = False) -> ReducedPencil:
    """An upper pencil from the upper triangles (CSC) of symmetric reduced
    matrices, on the union of their patterns. Each triangle is read column
    by column: no coordinate copy of a whole matrix; a triangle whose
    pattern is the union (the stiffness, as a rule) gives its own indices,
    and with ``owned`` (the caller's copies, consumed) its own values."""
    triangles = [None if m is None else sp.csc_matrix(m) for m in (stiffness, mass, damping)]
    present = [m for m in triangles if m is not None]
    for m in present:
        m.sum_duplicates()  # sorted rows in each column, as the keys below
    n = present[0].shape[0]

    def keys(m):  # column-major keys of the stored terms, sorted
        columns = np.repeat(np.arange(n, dtype=np.int64), np.diff(m.indptr))
        columns *= n
        columns += m.indices
        return columns

    widest = max(present, key=lambda m: m.nnz)
    pattern = keys(widest)
    for m in present:
        if m is not widest:
            pattern = sorted_unique(np.concatenate([pattern, keys(m)]))
    if pattern.size == widest.nnz:  # the widest's pattern holds the others'
        del pattern
        indptr, indices, pattern = widest.indptr, widest.indices, None
    else:
        indptr = np.zeros(n + 1, dtype=np.int64)
        np.cumsum(np.bincount(pattern // n, minlength=n), out=indptr[1:])
        indices = pattern % n
    size = indices.size
    values = []
    for m in triangles:
        if m is None:
            values.append(None)
            continue
        dtype = np.result_type(m.data.dtype, float)
        if m.nnz == size:  # its pattern is the union: its values in place
            # 0 + v, as the scattered values below (a zero's sign included)
            data = m.data if owned and m.data.dtype == dtype else np.zeros(size, dtype)
            data += 0.0 if data is m.data else m.data
        else:
            where = np.searchsorted(pattern if pattern is not None else keys(widest), keys(m))
            data = np.zeros(size, dtype)
            data[where] += m.data
            del where
        values.append(data)
    index_type = np.int32 if n < 2**31 else np.int64
    return ReducedPencil(
        n=n,
        indices=np.asarray(indices, dtype=index_type),
        indptr=np.asarray(indptr, dtype=np.int32 if size < 2**31 else np.int64),
        stiffness=values[0],
        mass=values[1],
        damping=values[2],
        upper=True,
    )


def selected_dofs(t) -> np.ndarray | None:
    """The DOFs T keeps when u = T q only selects them (each column of T a
    single 1 on its own row, in the DOFs' order: constraints that fix DOFs,
    no relation between DOFs), else None. Tᵀ A T is then A[kept][:, kept]
    exactly: each term of the products is one term of A times 1."""
    t = sp.csr_matrix(t)
    n_free = t.shape[1]
    if t.nnz != n_free or not np.all(t.data == 1.0):
        return None
    counts = np.diff(t.indptr)
    if counts.size and counts.max() > 1:
        return None
    kept = np.flatnonzero(counts)
    if not np.array_equal(t.indices[t.indptr[kept]], np.arange(n_free)):
        return None
    return kept


def selected_upper(matrix, kept: np.ndarray, tolerance: float | None = None):
    """The upper triangle (CSC) of A[kept][:, kept], ``kept`` increasing,
    without its zero terms (as Tᵀ A T by sparse products keeps none). With
    ``tolerance``: None unless A[kept][:, kept] is symmetric to it (its
    largest |A - Aᵀ| at most ``tolerance`` times its largest |A|), or when A
    has duplicate or unsorted terms (the caller then reduces and compares
    whole matrices).

    A (CSR) is read a block of rows at a time, in order: the terms of each
    column of the triangle counted, then each block's terms written to their
    place (rows increase within each column, as the blocks come in order of
    rows), then each block of the triangle's columns compared with the lower
    terms of the same rows of A (a term without its transpose differs by its
    own value). Nothing but the triangle has the size of the matrix, and the
    pages of a matrix on disk go back to the system after each block."""
    a = sp.csr_matrix(matrix)
    if not a.has_canonical_format:
        if tolerance is not None:
            return None
        a = a.copy()
        a.sum_duplicates()
    n, n_kept = a.shape[0], kept.size
    index_type = np.int32 if n < 2**31 else np.int64
    renumbered = np.full(n, -1, dtype=index_type)
    renumbered[kept] = np.arange(n_kept, dtype=index_type)

    def block_terms(first, stop, upper=True):
        """(rows, columns, values) of the kept nonzero terms of A's rows
        first:stop in the upper (else lower) triangle, renumbered, in A's order."""
        lo, hi = int(a.indptr[first]), int(a.indptr[stop])
        counts = np.diff(a.indptr[first : stop + 1])
        rows = renumbered[np.repeat(np.arange(first, stop, dtype=index_type), counts)]
        cols = renumbered[a.indices[lo:hi]]
        values = a.data[lo:hi]
        keep = rows >= 0
        if upper:
            keep &= cols >= rows
        else:
            keep &= cols >= 0
            keep &= cols <= rows
        keep &= values != 0
        return rows[keep], cols[keep], values[keep]

    counts = np.zeros(n_kept, dtype=np.int64)
    for first, stop in matrix_rows.blocks(a.indptr):
        counts += np.bincount(block_terms(first, stop)[1], minlength=n_kept)
        give_back()
    size = int(counts.sum())
    indptr = np.zeros(n_kept + 1, dtype=np.int32 if size < 2**31 else np.int64)
    np.cumsum(counts, out=indptr[1:])
    del counts
    indices = np.empty(size, dtype=index_type)
    data = np.empty(size, dtype=a.dtype)
    filled = indptr[:-1].astype(np.int64)  # the next free place of each column
    for first, stop in matrix_rows.blocks(a.indptr):
        rows, cols, values = block_terms(first, stop)
        order = np.argsort(cols, kind="stable")  # by column, rows increasing in each
        cols = cols[order]
        rank = np.arange(cols.size) - np.searchsorted(cols, cols)  # place within its column
        places = filled[cols] + rank
        indices[places] = rows[order]
        data[places] = values[order]
        filled += np.bincount(cols, minlength=n_kept)
        del rows, cols, values, order, rank, places
        give_back()
    del filled
    upper = sp.csc_matrix((data, indices, indptr), shape=(n_kept, n_kept))
    if tolerance is None:
        return upper
    worst = scale = 0.0
    for first, stop in matrix_rows.blocks(a.indptr):
        # A's rows first:stop, lower terms (row c, column r), and the same
        # columns c of the triangle (terms (r, c)), c increasing, r in each
        rows, cols, l_values = block_terms(first, stop, upper=False)
        l_keys = rows.astype(np.int64) * n_kept
        l_keys += cols
        del rows, cols
        c0, c1 = np.searchsorted(kept, [first, stop])
        lo, hi = int(indptr[c0]), int(indptr[c1])
        counts = np.diff(indptr[c0 : c1 + 1])
        u_keys = np.repeat(np.arange(c0, c1, dtype=np.int64), counts) * n_kept
        u_keys += indices[lo:hi]
        u_values = data[lo:hi]
        for values in (u_values, l_values):
            if values.size:
                scale = max(scale, float(np.abs(values).max()))
        worst = max(worst, _largest_difference(u_keys, u_values, l_keys, l_values))
        worst = max(worst, _largest_difference(l_keys, l_values, u_keys, u_values))
        del u_keys, u_values, l_keys, l_values
        give_back()
    return upper if worst <= tolerance * scale else None


def _largest_difference(keys, values, other_keys, other_values) -> float:
    """The largest |v - w| of the terms (``keys``, ``values``) and the terms of
    the same keys among the others (sorted keys), w = 0 where they have none."""
    if not keys.size:
        return 0.0
    if not other_keys.size:
        return float(np.abs(values).max())
    where = np.minimum(np.searchsorted(other_keys, keys), other_keys.size - 1)
    matched = np.where(other_keys[where] == keys, other_values[where], 0)
    return float(np.abs(values - matched).max())
