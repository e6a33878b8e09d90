"""Projection on a modal basis (PROJ_MATR_BASE, PROJ_VECT_BASE, PROJ_BASE)."""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla


class ProjectionError(ValueError):
    """Projection impossible (e.g. a basis with dependent vectors)."""


def project_matrix(shapes: np.ndarray, matrix, storage: str = "PLEIN") -> np.ndarray:
    """Φᵀ A Φ (dense); only its diagonal for STOCKAGE='DIAG' (code_aster's storage)."""
    projected = shapes.T @ np.asarray(matrix @ shapes)
    projected = 0.5 * (projected + projected.T) if _is_symmetric(matrix) else projected
    if storage == "DIAG":
        return np.diag(np.diag(projected))
    return projected


def _is_symmetric(matrix) -> bool:
    try:
        diff = matrix - matrix.T
        return abs(diff).max() <= 1e-12 * max(abs(matrix).max(), 1e-300)
    except (TypeError, ValueError):
        return False


def project_force(shapes: np.ndarray, vector: np.ndarray) -> np.ndarray:
    """Φᵀ f (TYPE_VECT='FORC')."""
    return shapes.T @ vector


def fit_coordinates(shapes: np.ndarray, vector: np.ndarray) -> np.ndarray:
    """Generalized coordinates q minimising ||Φ q - u|| (TYPE_VECT DEPL/VITE/ACCE):
    q = (ΦᵀΦ)⁻¹ Φᵀ u, solved by Cholesky of the Gram matrix as code_aster does."""
    gram = shapes.T @ shapes
    try:
        factor = sla.cho_factor(gram)
    except sla.LinAlgError:
        raise ProjectionError("the basis vectors are linearly dependent") from None
    return sla.cho_solve(factor, shapes.T @ vector)
