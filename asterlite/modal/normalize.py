"""Mode normalisations (code_aster's NORM_MODE and CALC_MODES defaults).

Each function returns one scale factor per mode; shapes are multiplied by it.

- ``largest_component``: divide by the *signed* component of largest
  magnitude among the selected DOFs (first one in DOF order on ties), so that
  component becomes +1. CALC_MODES does this over every physical DOF when
  NORM_MODE is absent (code_aster labels it ``SANS_CMP: LAGR``); NORM_MODE
  TRAN / TRAN_ROTA / AVEC_CMP restrict the DOFs to those components.
- ``euclidean``: unit 2-norm over the selected DOFs (EUCL, EUCL_TRAN), sign kept.
- ``generalized``: unit φᵀAφ (MASS_GENE with the mass, RIGI_GENE with the
  stiffness), sign kept.
"""

from __future__ import annotations

import numpy as np

TRAN = ("DX", "DY", "DZ")
TRAN_ROTA = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")


def component_mask(components: list[str], selected=None, excluded=None) -> np.ndarray:
    """Boolean mask over DOFs whose component is selected (all when None) and not excluded."""
    comps = np.asarray(components, dtype=object)
    mask = np.ones(len(comps), dtype=bool)
    if selected is not None:
        mask &= np.isin(comps, list(selected))
    if excluded is not None:
        mask &= ~np.isin(comps, list(excluded))
    return mask


def largest_component(shapes: np.ndarray, mask: np.ndarray | None = None) -> np.ndarray:
    masked = shapes if mask is None else shapes * mask[:, None]
    if masked.shape[0] == 0:
        return np.ones(shapes.shape[1])
    rows = np.argmax(np.abs(masked), axis=0)  # first maximum on ties, as code_aster
    pivot = masked[rows, np.arange(shapes.shape[1])]
    return np.where(pivot != 0.0, 1.0 / np.where(pivot != 0.0, pivot, 1.0), 1.0)


def euclidean(shapes: np.ndarray, mask: np.ndarray | None = None) -> np.ndarray:
    masked = shapes if mask is None else shapes * mask[:, None]
    norm = np.linalg.norm(masked, axis=0)
    return np.where(norm > 0, 1.0 / np.where(norm > 0, norm, 1.0), 1.0)


def generalized(shapes: np.ndarray, matrix) -> np.ndarray:
    value = np.einsum("ij,ij->j", shapes, matrix @ shapes)
    return np.where(value > 0, 1.0 / np.sqrt(np.where(value > 0, value, 1.0)), 1.0)


def at_dof(shapes: np.ndarray, row: int) -> np.ndarray:
    """Scale making the DOF ``row`` equal to 1 (NORM_MODE GROUP_NO + NOM_CMP)."""
    pivot = shapes[row]
    return np.where(pivot != 0.0, 1.0 / np.where(pivot != 0.0, pivot, 1.0), 1.0)
