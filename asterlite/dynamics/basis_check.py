"""The shock check of the basis: can the modal basis represent the static deflection of each
shock node under its own contact force?

For a unit force along the obstacle direction n at a shock node, the exact
static flexibility is s = nᵀ K⁻¹ n (K: the basis's assembled stiffness,
constraints included) and the modal one Σ_j (φ_jᵀ n)² / k_j. Their ratio r
(the "restitution rate") tends to 1 for a rich basis. code_aster's
criterion is s·K_N·(1 − r): the share of the shock's compliance the basis
misses, scaled by the shock stiffness; above the threshold it warns, or
stops the run when asked to.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

COMPONENTS = ("DX", "DY", "DZ")


@dataclass
class NodeCheck:
    shock: str
    node: str
    static_flexibility: float
    restitution: float
    criterion: float


def node_checks(specs, basis, generalized_stiffness: np.ndarray) -> list[NodeCheck]:
    """One check per node of each DIS_CHOC connection."""
    from asterlite.modal.static_modes import response_modes

    numbering = basis.numbering
    stiffness = basis.stiffness.matrix
    k_modal = np.asarray(generalized_stiffness, dtype=float)
    inverse_k = np.where(k_modal > 0.0, 1.0 / np.where(k_modal > 0.0, k_modal, 1.0), 0.0)
    checks = []
    for spec in specs:
        if spec.relation != "DIS_CHOC":
            continue
        direction = np.asarray(spec.norm_obst, dtype=float)
        for node in (spec.node_1, spec.node_2):
            if node is None:
                continue
            load = np.zeros(numbering.n_dofs)
            for component, value in zip(COMPONENTS, direction, strict=True):
                try:
                    load[numbering.dof_index(node, component)] = value
                except KeyError:
                    pass
            static = response_modes(stiffness, numbering, load[:, None])[:, 0]
            flexibility = float(load @ static)
            modal = np.array([basis.shape_at(node, c) for c in COMPONENTS]).T @ direction
            modal_flexibility = float(np.sum(modal**2 * inverse_k[: modal.size]))
            ratio = modal_flexibility / flexibility if abs(flexibility) > 1e-300 else 0.0
            criterion = flexibility * spec.k_n * (1.0 - ratio)
            checks.append(NodeCheck(spec.name, node, flexibility, ratio, criterion))
    return checks
