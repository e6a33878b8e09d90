"""Reading a large sparse matrix (CSR) a block of rows at a time.

An assembled matrix the run moved to disk (:mod:`asterlite.runtime.result_paging`)
is a memory map whose pages the system loads as they are read and which stay
in the process until given back: a reader of the whole matrix (a product,
its diagonal, its reduced triangles) would hold all of it in memory. The
readers here take a block of rows of about :data:`BLOCK_TERMS` stored terms
at a time and give the pages read (:func:`asterlite.io.disk_rows.release_pages`)
and the allocator's free pages back after each block, as code_aster's JEVEUX
reads the blocks of a MORSE matrix in and out. Each row's terms are read in
their order: the results are those of the whole-matrix operations, bit for bit.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from asterlite import watchdog
from asterlite.io import disk_rows

#: stored terms read at once (a block of whole rows, or columns of a CSC):
#: the readers' temporaries are a few MB whatever the matrix's size
BLOCK_TERMS = 1 << 20


def blocks(indptr, terms: int | None = None):
    """(first, stop) of consecutive blocks of rows (CSR ``indptr``, or
    columns of a CSC) of about ``terms`` (:data:`BLOCK_TERMS`) stored terms
    each (at least one row)."""
    terms = BLOCK_TERMS if terms is None else terms
    n = len(indptr) - 1
    first = 0
    while first < n:
        stop = int(np.searchsorted(indptr, indptr[first] + terms, side="right")) - 1
        stop = min(max(stop, first + 1), n)
        yield first, stop
        first = stop


def give_back() -> None:
    """The pages a block read from matrices on disk, and the allocator's
    free pages, back to the system."""
    disk_rows.release_pages()
    watchdog.trim_allocator()


def product(matrix, x: np.ndarray) -> np.ndarray:
    """``matrix @ x`` (x a vector or an (n, k) array), a block of rows at a time."""
    a = sp.csr_matrix(matrix)
    x = np.asarray(x)
    out = np.empty((a.shape[0], *x.shape[1:]), dtype=np.result_type(a.dtype, x.dtype))
    for first, stop in blocks(a.indptr):
        out[first:stop] = a[first:stop] @ x
        give_back()
    return out


def diagonal(matrix) -> np.ndarray:
    """The diagonal of a square matrix, a block of rows at a time."""
    a = sp.csr_matrix(matrix)
    out = np.empty(min(a.shape), dtype=a.dtype)
    for first, stop in blocks(a.indptr[: out.size + 1]):
        out[first:stop] = a[first:stop].diagonal(k=first)
        give_back()
    return out
