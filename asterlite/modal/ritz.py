"""Ritz bases (DEFI_BASE_MODALE): concatenation and orthonormalisation.

code_aster's RITZ copies the vectors of each source basis onto the reference
numbering (dynamic modes first, capped by NMAX_MODE, then the interface /
static modes) without changing them. With ORTHO='OUI' (or ORTHO_BASE) the
family is orthonormalised with respect to MATRICE by iterated Gram-Schmidt
in the Kahan-Parlett variant (a vector is re-orthogonalised once when its
norm drops below α = 0.717 of its previous norm, and zeroed if it drops
again), then vectors whose normalised inner products with an earlier one
exceed 1e-8 are zeroed, and -- for RITZ only -- the zero vectors dropped.
asterlite also zeroes a vector whose norm falls below 1e-10 of its initial
norm (only round-off is left), where the plain algorithm could keep
normalised noise.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.modes import MultElasResult
from asterlite.modal.renumber import transfer

KAHAN_PARLETT_ALPHA = 0.717
DEPENDENT_RATIO = 1e-10  # asterlite's guard: relative norm left by a dependent vector
_TINY = np.finfo(float).tiny ** (2.0 / 3.0)


def _inner(matrix, a: np.ndarray, b: np.ndarray) -> float:
    return float(a @ (matrix @ b)) if matrix is not None else float(a @ b)


def gram_schmidt(
    vectors: np.ndarray, matrix=None, alpha: float = KAHAN_PARLETT_ALPHA
) -> np.ndarray:
    """Columns orthonormal for ⟨a, b⟩ = aᵀ A b (Euclidean when ``matrix`` is
    None); a column found dependent on the previous ones becomes zero."""
    q = np.array(vectors, dtype=float, copy=True)
    n = q.shape[1]
    for i in range(n):
        v = q[:, i]
        start = np.sqrt(abs(_inner(matrix, v, v)))
        for j in range(i):
            before = _inner(matrix, v, v)
            for attempt in range(2):
                v = v - _inner(matrix, q[:, j], v) * q[:, j]
                after = _inner(matrix, v, v)
                if np.sqrt(abs(after)) > alpha * np.sqrt(abs(before)) - _TINY:
                    break
                if attempt == 1:
                    v = np.zeros_like(v)
                before = after
        norm = np.sqrt(abs(_inner(matrix, v, v)))
        if norm <= DEPENDENT_RATIO * start:
            norm = 0.0  # only round-off is left: the vector depends on the previous ones
        q[:, i] = v / max(norm, _TINY) if norm > 0 else 0.0
    return q


def dependent_columns(vectors: np.ndarray, matrix=None, tol: float = 1e-8) -> np.ndarray:
    """Boolean mask of the columns to zero: each column j whose inner product
    with an earlier kept column i, over ⟨v_i, v_i⟩ (vectors scaled to unit
    norm first), exceeds ``tol``."""
    v = np.asarray(vectors, dtype=float)
    gram_in = v.T @ (matrix @ v) if matrix is not None else v.T @ v
    norms = np.sqrt(np.clip(np.diag(gram_in), 0.0, None))
    scale = np.where(norms > 1e-16, 1.0 / np.where(norms > 1e-16, norms, 1.0), 0.0)
    gram = gram_in * scale[:, None] * scale[None, :]
    n = gram.shape[0]
    zeroed = np.zeros(n, dtype=bool)
    for i in range(n):
        if zeroed[i] or gram[i, i] <= 1e-16:
            continue
        for j in range(i + 1, n):
            if not zeroed[j] and abs(gram[i, j]) / gram[i, i] > tol:
                zeroed[j] = True
    zeroed |= np.diag(gram) <= 1e-16
    return zeroed


def orthonormalise(vectors: np.ndarray, matrix=None, drop_zero: bool = True):
    """(basis, kept): the orthonormalised family and the indices of the input
    columns that survive (all of them when ``drop_zero`` is False)."""
    q = gram_schmidt(vectors, matrix)
    zeroed = dependent_columns(q, matrix)
    q[:, zeroed] = 0.0
    kept = np.flatnonzero(~zeroed) if drop_zero else np.arange(q.shape[1])
    return q[:, kept], kept


def stacked_fields(families, numbering):
    """One ``MultElasResult`` holding the vectors of several static families
    (mode_meca or mult_elas) on ``numbering``, named CHAMP_1, CHAMP_2... (as
    DYNA_LINE gathers its interface modes before DEFI_BASE_MODALE)."""

    blocks = [transfer(np.asarray(f.shapes, dtype=float), f.numbering, numbering) for f in families]
    fields = np.hstack(blocks) if blocks else np.zeros((numbering.n_dofs, 0))
    names = [f"CHAMP_{k + 1}" for k in range(fields.shape[1])]
    return MultElasResult(numbering=numbering, fields=fields, case_names=names)
