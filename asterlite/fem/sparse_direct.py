"""Sparse direct factorisation of a symmetric matrix, by the best library present.

Two back ends, chosen by size and by what is installed:

- ``mumps``: MUMPS (the solver code_aster uses), through ``python-mumps``
  (the ``large`` extra; it builds against Debian's ``libmumps-seq-dev``).
  Multifrontal LDLᵀ with threshold pivoting, so shifted pencils K - σM inside
  the spectrum (CENTRE, BANDE) factorise as well as positive ones; nested-
  dissection-like orderings (SCOTCH, AMF) keep the fill-in of 3D meshes low;
  blocks of right-hand sides are solved with BLAS 3. It also gives the
  inertia (the number of negative pivots).
- ``superlu``: scipy's SuperLU, always present. Its fill-in grows fast on 3D
  meshes (the 98 172-DOF HEXA8 bar: 301 s and 10.9 GB for 50 modes), so it
  serves small models and machines without MUMPS.

``factorize_symmetric`` picks MUMPS for matrices of at least ``LARGE_LIMIT``
unknowns when it imports, SuperLU otherwise; ``ASTERLITE_SPARSE_SOLVER``
(``auto``, ``mumps``, ``superlu``) overrides the choice.
"""

from __future__ import annotations

import os

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

#: from this many unknowns on, a shift-invert eigen solve factorises with MUMPS
#: (when installed) and iterates with the block Lanczos method
LARGE_LIMIT = 4000
BACKENDS = ("mumps", "superlu")


class SingularFactorError(ValueError):
    """The matrix is singular (a zero pivot, or MUMPS's numerically singular)."""


def mumps_available() -> bool:
    try:
        import mumps  # noqa: F401
    except ImportError:
        return False
    return True


def requested_backend() -> str:
    name = os.environ.get("ASTERLITE_SPARSE_SOLVER", "auto").strip().lower() or "auto"
    if name not in ("auto",) + BACKENDS:
        raise ValueError(f"ASTERLITE_SPARSE_SOLVER={name!r}: expected auto, " + ", ".join(BACKENDS))
    return name


def choose_backend(n: int) -> str:
    """The back end for a matrix of ``n`` unknowns."""
    name = requested_backend()
    if name == "superlu":
        return "superlu"
    if name == "mumps" or n >= LARGE_LIMIT:
        return "mumps" if mumps_available() else "superlu"
    return "superlu"


class SuperLUFactor:
    """scipy's SuperLU on a symmetric matrix (COLAMD ordering, as before)."""

    backend = "superlu"

    def __init__(self, matrix):
        try:
            self._lu = spla.splu(sp.csc_matrix(matrix))
        except RuntimeError as exc:
            raise SingularFactorError(str(exc)) from None
        self.n = matrix.shape[0]

    def solve(self, rhs: np.ndarray) -> np.ndarray:
        return self._lu.solve(np.asarray(rhs, dtype=float))

    @property
    def lu(self):
        return self._lu

    def close(self) -> None:
        self._lu = None

    negative_pivots = None


class MumpsFactor:
    """MUMPS LDLᵀ of a symmetric matrix (upper triangle handed over).

    ``null_pivot_threshold`` (relative to the matrix's largest row sum)
    turns MUMPS's null pivot detection on (ICNTL(24) = 1, CNTL(3)):
    ``null_pivots`` then counts the pivots below it, which mark a matrix
    singular to that precision."""

    backend = "mumps"

    def __init__(self, matrix, null_pivot_threshold: float | None = None):
        import mumps

        upper = sp.triu(sp.coo_matrix(matrix), format="coo")
        self.n = matrix.shape[0]
        self._context = mumps.Context()
        self._context.set_matrix(upper, symmetric=True)
        instance = self._context.mumps_instance
        if null_pivot_threshold is not None:
            instance.icntl[24] = 1
            instance.cntl[3] = float(null_pivot_threshold)
        try:
            self._context.factor(ordering="auto")
        except mumps.MUMPSError as exc:
            # INFOG(1) = -10: numerically singular
            raise SingularFactorError(f"MUMPS: {exc}") from None
        self.negative_pivots = int(instance.infog[12])
        self.null_pivots = int(instance.infog[28]) if null_pivot_threshold is not None else 0

    def solve(self, rhs: np.ndarray) -> np.ndarray:
        b = np.array(rhs, dtype=float, order="F", copy=True)
        return self._context.solve(b, overwrite_b=True)

    def close(self) -> None:
        """Free MUMPS's factor now. Only references are dropped: the wrapper's
        own deallocation terminates the instance (JOB = -2) once.
        ``mumps.Context.__exit__`` must not be used: in python-mumps 0.0.4 it
        sets JOB on the Python object, not on the instance, so it repeats the
        last job, a solve into the right-hand side of the last call, long
        freed (heap corruption: forma12c crashed or got wrong modes)."""
        self._context = None


def factorize_symmetric(matrix, backend: str | None = None, **options):
    """A factor of the symmetric ``matrix`` with ``.solve(b)`` for a vector or a
    block of columns, ``.backend`` and ``.negative_pivots`` (MUMPS's inertia,
    None for SuperLU); ``options`` go to MUMPS."""
    matrix = sp.csc_matrix(matrix)
    name = backend or choose_backend(matrix.shape[0])
    if name == "mumps":
        return MumpsFactor(matrix, **options)
    return SuperLUFactor(matrix)
