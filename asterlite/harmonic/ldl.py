"""Sparse LDLᵀ of complex symmetric matrices with one symbolic analysis for
a whole sweep (the up-looking algorithm of T. A. Davis, "Algorithm 849: a
concise sparse Cholesky factorization package", ACM TOMS 31(4), 2005;
written here for complex values and Lᵀ, not Lᴴ).

K + iωC - ω²M keeps one sparsity pattern over the frequencies: the
elimination tree and the column counts of L are computed once
(:func:`analyse`), each frequency then costs one numeric factorisation
(:func:`factorise`) and two triangular solves (:func:`solve`): C++
compiled at install (asterlite.dynamics.native._ldl, the same bits), else
the numba kernels below (``ASTERLITE_NATIVE=0``, or a checkout whose
modules were not built). There is no pivoting, as in code_aster's LDLT
and MULT_FRONT solvers: the caller checks each solution's residual and
factorises with pivoting (SuperLU) when a pivot vanishes or the residual
is not that of a stable solve.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

# numba's cache in asterlite's trusted kernel folder (asterlite.dynamics sets
# it when imported: numba's index files are pickles, see docs/safety.md)
import asterlite.dynamics  # noqa: F401
from asterlite.dynamics import native
from asterlite.dynamics.jit import njit

try:
    from asterlite.dynamics.native import _ldl
except ImportError:  # not built: the numba kernels serve
    _ldl = None

# ----------------------------------------------------------------------------- kernels


@njit(cache=True)
def _symbolic(n, ap, ai, limit):
    """Elimination tree and column counts of L from the upper triangle of a
    (CSC ``ap``, ``ai``) symmetric pattern; stops (total -1) once the fill
    exceeds ``limit`` (counting costs as much as the fill)."""
    parent = np.empty(n, np.int64)
    lnz = np.zeros(n, np.int64)
    flag = np.empty(n, np.int64)
    total = 0
    for k in range(n):
        if total > limit:
            return parent, lnz, -1
        parent[k] = -1
        flag[k] = k
        for p in range(ap[k], ap[k + 1]):
            i = ai[p]
            if i < k:
                while flag[i] != k:
                    if parent[i] == -1:
                        parent[i] = k
                    lnz[i] += 1
                    total += 1
                    flag[i] = k
                    i = parent[i]
    return parent, lnz, total


@njit(cache=True)
def _numeric(n, ap, ai, ax, lp, parent, li, lx, d):
    """L (CSC: ``lp``, ``li``, ``lx``, unit diagonal not stored) and D of
    A = L D Lᵀ from the upper triangle of A. Returns -1, or the column whose
    pivot vanished."""
    y = np.zeros(n, np.complex128)
    flag = np.empty(n, np.int64)
    pattern = np.empty(n, np.int64)
    lnz = np.zeros(n, np.int64)
    for k in range(n):
        y[k] = 0.0
        top = n
        flag[k] = k
        for p in range(ap[k], ap[k + 1]):
            i = ai[p]
            if i <= k:
                y[i] += ax[p]
                length = 0
                while flag[i] != k:
                    pattern[length] = i
                    length += 1
                    flag[i] = k
                    i = parent[i]
                while length > 0:
                    top -= 1
                    length -= 1
                    pattern[top] = pattern[length]
        d[k] = y[k]
        y[k] = 0.0
        while top < n:
            i = pattern[top]
            top += 1
            yi = y[i]
            y[i] = 0.0
            p2 = lp[i] + lnz[i]
            for p in range(lp[i], p2):
                y[li[p]] -= lx[p] * yi
            l_ki = yi / d[i]
            d[k] -= l_ki * yi
            li[p2] = k
            lx[p2] = l_ki
            lnz[i] += 1
        if d[k] == 0.0:
            return k
    return -1


@njit(cache=True)
def _solve(n, lp, li, lx, d, x):
    """x := A⁻¹ x with A = L D Lᵀ (in place)."""
    for j in range(n):
        xj = x[j]
        for p in range(lp[j], lp[j + 1]):
            x[li[p]] -= lx[p] * xj
    for j in range(n):
        x[j] /= d[j]
    for j in range(n - 1, -1, -1):
        s = x[j]
        for p in range(lp[j], lp[j + 1]):
            s -= lx[p] * x[li[p]]
        x[j] = s


# ----------------------------------------------------------------------------- python side


def _compiled() -> bool:
    """Whether the C++ kernels serve (built, and not switched off by
    ``ASTERLITE_NATIVE=0``): they take the same arguments and give the
    same bits as the numba kernels above."""
    return _ldl is not None and native.available()


@dataclass
class Analysis:
    """The symbolic factorisation of one symmetric pattern under a
    fill-reducing permutation ``perm`` (A[perm][:, perm] is factorised)."""

    n: int
    perm: np.ndarray
    upper_ptr: np.ndarray  # CSC of the permuted upper triangle
    upper_idx: np.ndarray
    # position in the caller's data array of each upper entry (None: the
    # caller's data are in this order already)
    source: np.ndarray | None
    parent: np.ndarray
    lp: np.ndarray

    @property
    def fill(self) -> int:
        return int(self.lp[-1])


def analyse(
    indptr, indices, n, perm, limit: int | None = None, upper: bool = False
) -> Analysis | None:
    """Symbolic analysis of a square CSC pattern (``indptr``, ``indices``,
    symmetric; ``upper``: only its upper triangle) permuted by ``perm``.
    Data arrays aligned on the caller's pattern are later mapped through
    ``source``. None when the fill of L would exceed ``limit``. Indices are
    32-bit where they fit (half the memory of a large model's pattern and
    factor)."""
    nnz = int(indptr[-1])
    index_type = _index_type(max(n, nnz))
    inverse = np.empty(n, dtype=index_type)
    inverse[perm] = np.arange(n, dtype=index_type)
    new_rows = inverse[indices]
    new_cols = np.repeat(inverse, np.diff(indptr))
    del inverse
    if upper:  # each term goes to the upper triangle of the permuted matrix
        keep = np.arange(nnz, dtype=index_type)
        new_rows, new_cols = np.minimum(new_rows, new_cols), np.maximum(new_rows, new_cols)
    else:
        keep = np.flatnonzero(new_rows <= new_cols).astype(index_type, copy=False)
        new_rows, new_cols = new_rows[keep], new_cols[keep]
    # column-major order of the kept terms (one sort of a 64-bit key)
    key = new_cols.astype(np.int64) * n + new_rows
    order = np.argsort(key, kind="stable").astype(index_type, copy=False)
    del key
    upper_ptr = np.zeros(n + 1, dtype=index_type)
    np.cumsum(np.bincount(new_cols, minlength=n), out=upper_ptr[1:])
    del new_cols
    upper_idx = new_rows[order]
    source = keep[order]
    del keep, order, new_rows
    bound = np.iinfo(np.int64).max if limit is None else int(limit)
    symbolic = _ldl.symbolic if _compiled() else _symbolic
    parent, lnz, total = symbolic(n, upper_ptr, upper_idx, bound)
    if total < 0:
        return None
    lp = np.zeros(n + 1, dtype=np.int64)
    np.cumsum(lnz, out=lp[1:])
    return Analysis(n, np.asarray(perm), upper_ptr, upper_idx, source, parent, lp)


def _index_type(largest: int):
    return np.int32 if largest < 2**31 - 1 else np.int64


@dataclass
class Factor:
    analysis: Analysis
    li: np.ndarray
    lx: np.ndarray
    d: np.ndarray

    def solve(self, b: np.ndarray) -> np.ndarray:
        a = self.analysis
        x = np.ascontiguousarray(np.asarray(b, dtype=complex)[a.perm])
        (_ldl.solve if _compiled() else _solve)(a.n, a.lp, self.li, self.lx, self.d, x)
        out = np.empty_like(x)
        out[a.perm] = x
        return out


class ZeroPivot(ArithmeticError):
    pass


def factorise(analysis: Analysis, data: np.ndarray) -> Factor:
    """L D Lᵀ of the matrix whose values on the analysed pattern are ``data``."""
    a = analysis
    values = np.asarray(data, dtype=complex)
    values = np.ascontiguousarray(values if a.source is None else values[a.source])
    li = np.empty(a.fill, dtype=_index_type(a.n))
    lx = np.empty(a.fill, dtype=np.complex128)
    d = np.empty(a.n, dtype=np.complex128)
    numeric = _ldl.numeric if _compiled() else _numeric
    failed = numeric(a.n, a.upper_ptr, a.upper_idx, values, a.lp, a.parent, li, lx, d)
    if failed >= 0:
        raise ZeroPivot(int(failed))
    return Factor(a, li, lx, d)


def warm() -> None:
    """Load (or compile) the numba kernels on a 2 x 2 system, so that
    timing a first factorisation measures the factorisation; nothing to do
    when the C++ kernels serve."""
    if _compiled():
        return
    pattern = sp.csc_matrix(np.array([[2.0, 1.0], [1.0, 2.0]]))
    analysis = analyse(pattern.indptr, pattern.indices, 2, np.arange(2))
    factorise(analysis, pattern.data.astype(complex)).solve(np.ones(2))


def is_symmetric(matrix: sp.spmatrix, tolerance: float = 0.0) -> bool:
    """Structural and numerical symmetry of a sparse matrix."""
    difference = (matrix - matrix.T).tocsr()
    if difference.nnz == 0:
        return True
    scale = abs(matrix).max() if matrix.nnz else 0.0
    return bool(abs(difference).max() <= tolerance * scale)
