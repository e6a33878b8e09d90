"""Critical loads (CALC_MODES TYPE_RESU='MODE_FLAMB' / 'GENERAL').

code_aster writes these problems (A + λ B) φ = 0 and stores λ as CHAR_CRIT:
for A = K and B = M, λ = -ω². The constrained pencil is solved densely: with
B positive definite as A φ = μ B φ (λ = -μ), otherwise with A positive
definite as B φ = ν A φ (λ = -1/ν, ν = 0 giving no critical load).
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla

from asterlite.modal.eigen import EigenError

DENSE_LIMIT = 3000


def _dense(matrix) -> np.ndarray:
    d = matrix.toarray() if hasattr(matrix, "toarray") else np.asarray(matrix, dtype=float)
    return 0.5 * (d + d.T)


def _positive_definite(d: np.ndarray) -> bool:
    try:
        sla.cholesky(d)
        return True
    except sla.LinAlgError:
        return False


def critical_loads(a_reduced, b_reduced):
    """(λ, reduced vectors) of (A + λ B) φ = 0, every finite pair."""
    if a_reduced.shape[0] > DENSE_LIMIT:
        raise EigenError(f"critical loads of more than {DENSE_LIMIT} unknowns")
    a, b = _dense(a_reduced), _dense(b_reduced)
    if _positive_definite(b):
        mu, vecs = sla.eigh(a, b)
        return -mu, vecs
    if _positive_definite(a):
        nu, vecs = sla.eigh(b, a)
        keep = np.abs(nu) > 1e-12 * max(np.abs(nu).max(initial=0.0), 1e-300)
        return -1.0 / nu[keep], vecs[:, keep]
    raise EigenError("neither matrix of the pencil is positive definite")


def select_critical(loads: np.ndarray, vecs: np.ndarray, option: str, window=(), nmax=10):
    """CALC_CHAR_CRIT selections: PLUS_PETITE (smallest |λ|), CENTRE (nearest
    CHAR_CRIT), BANDE (λ in [a, b]), TOUT; sorted by increasing λ."""
    window = np.atleast_1d(np.asarray(window if window is not None else (), dtype=float))
    if option == "PLUS_PETITE":
        order = np.argsort(np.abs(loads), kind="stable")[:nmax]
    elif option == "CENTRE":
        order = np.argsort(np.abs(loads - window[0]), kind="stable")[:nmax]
    elif option == "BANDE":
        lo, hi = window.min(), window.max()
        order = np.flatnonzero((loads >= lo) & (loads <= hi))
    elif option == "TOUT":
        order = np.arange(loads.size)
    else:
        raise EigenError(f"OPTION={option!r} for critical loads")
    order = order[np.argsort(loads[order], kind="stable")]
    return loads[order], vecs[:, order]
