"""Per-mode quantities code_aster stores with a modal basis."""

from __future__ import annotations

import numpy as np

from asterlite.modal.eigen import TWO_PI


def modal_parameters(shapes, stiffness, mass, components, omega2=None) -> dict[str, np.ndarray]:
    """Generalized mass/stiffness, participation factors and effective masses.

    ``FACT_PARTICI_Dx`` = φᵀ M Δx / μ and ``MASS_EFFE_Dx`` = (φᵀ M Δx)² / μ with
    Δx the unit rigid translation along x (1 on every Dx DOF) and μ = φᵀ M φ;
    ``MASS_EFFE_UN_Dx`` divides by the total mass Δxᵀ M Δx.
    """
    shapes = np.asarray(shapes, dtype=float)
    n_modes = shapes.shape[1]
    out: dict[str, np.ndarray] = {}
    mphi = mass @ shapes if mass is not None else None
    if mass is not None:
        out["MASS_GENE"] = np.einsum("ij,ij->j", shapes, mphi)
    if stiffness is not None:
        out["RIGI_GENE"] = np.einsum("ij,ij->j", shapes, stiffness @ shapes)
    if omega2 is not None:
        omega2 = np.asarray(omega2, dtype=float)
        out["OMEGA2"] = omega2
        out["FREQ"] = np.sign(omega2) * np.sqrt(np.abs(omega2)) / TWO_PI
    out["NUME_MODE"] = np.arange(1, n_modes + 1)
    if mass is None:
        return out
    comps = np.asarray(components, dtype=object)
    mu = out["MASS_GENE"]
    safe_mu = np.where(mu != 0, mu, 1.0)
    for c in ("DX", "DY", "DZ"):
        rigid = (comps == c).astype(float)
        fact = rigid @ mphi
        total = float(rigid @ (mass @ rigid))
        out[f"FACT_PARTICI_{c}"] = np.where(mu != 0, fact / safe_mu, 0.0)
        out[f"MASS_EFFE_{c}"] = np.where(mu != 0, fact**2 / safe_mu, 0.0)
        out[f"MASS_EFFE_UN_{c}"] = out[f"MASS_EFFE_{c}"] / total if total > 0 else 0.0 * fact
    return out
