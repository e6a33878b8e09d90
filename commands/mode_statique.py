"""MODE_STATIQUE: constrained modes (MODE_STAT), attachment modes
(FORCE_NODALE) and pseudo-modes (PSEUDO_MODE).

As code_aster, the modes of all occurrences of a keyword come in the DOF
numbering order; each carries NOEUD_CMP (``"N01 DX"``) and TYPE_DEFO
(``DEPL_IMPO``, ``FORC_IMPO``, ``ACCE_IMPO``). Pseudo-modes along an axis are
labelled by the axis (``"X"``, or NOM_DIR for a DIRECTION).
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.modes import ModeResult
from asterlite.fem.selection import as_tuple, select_nodes
from asterlite.modal.modal_parameters import modal_parameters
from asterlite.modal.seismic import rigid_field
from asterlite.modal.static_modes import (
    StaticModeError,
    acceleration_modes,
    blocked_dofs,
    constrained_modes,
    dof_acceleration_modes,
    response_modes,
    selection_mask,
)

_AXES = {"X": (1.0, 0.0, 0.0), "Y": (0.0, 1.0, 0.0), "Z": (0.0, 0.0, 1.0)}


def _selected(ctx, occurrences, numbering, eligible: np.ndarray) -> np.ndarray:
    """DOF indices (numbering order) selected by any occurrence, among ``eligible``."""
    mesh = numbering.mesh
    nodes, comps = numbering.dof_nodes, numbering.dof_components
    chosen = np.zeros(numbering.n_dofs, dtype=bool)
    for occ in occurrences:
        # TOUT_CMP='OUI' (its only value): every component, as without AVEC_CMP/SANS_CMP
        occ.mark_used("TOUT_CMP")
        selected_nodes = select_nodes(ctx, occ, mesh, all_nodes=np.unique(nodes))
        chosen |= selection_mask(
            comps,
            nodes,
            selected_nodes,
            as_tuple(occ.get("AVEC_CMP")),
            as_tuple(occ.get("SANS_CMP")),
        )
    return np.flatnonzero(chosen & eligible)


def _blocked_mask(numbering) -> np.ndarray:
    mask = np.zeros(numbering.n_dofs, dtype=bool)
    mask[list(blocked_dofs(numbering))] = True
    return mask


def run(ctx, kw):
    stiffness = kw["MATR_RIGI"]
    mass = kw.get("MATR_MASS")
    numbering = stiffness.numbering
    if mass is not None and mass.numbering.dofs != numbering.dofs:
        ctx.error("MATR_RIGI and MATR_MASS use different numberings", "MATR_MASS", kw)
    if kw.factor("MODE_INTERF"):
        ctx.unsupported("MODE_STATIQUE MODE_INTERF (interface modes)", "MODE_INTERF", kw)
    blocked = _blocked_mask(numbering)
    k = stiffness.matrix
    try:
        if kw.factor("MODE_STAT"):
            dofs = _selected(ctx, kw.factor("MODE_STAT"), numbering, blocked)
            if dofs.size == 0:
                ctx.error("no blocked DOF (DDL_IMPO) in the selection", "MODE_STAT", kw)
            phi = constrained_modes(k, numbering, dofs)
            labels = [numbering.label(d) for d in dofs]
            defo = "DEPL_IMPO"
        elif kw.factor("FORCE_NODALE"):
            dofs = _selected(ctx, kw.factor("FORCE_NODALE"), numbering, ~blocked)
            if dofs.size == 0:
                ctx.error("no free DOF in the selection", "FORCE_NODALE", kw)
            loads = np.zeros((numbering.n_dofs, dofs.size))
            loads[dofs, np.arange(dofs.size)] = 1.0
            phi = response_modes(k, numbering, loads)
            labels = [numbering.label(d) for d in dofs]
            defo = "FORC_IMPO"
        else:
            phi, labels = _pseudo_modes(ctx, kw, numbering, k, mass.matrix, blocked)
            defo = "ACCE_IMPO"
    except StaticModeError as exc:
        ctx.error(str(exc), "MATR_RIGI", kw)
    phi = np.asarray(phi, dtype=float).reshape(numbering.n_dofs, -1)
    n = phi.shape[1]
    params = modal_parameters(
        phi, k, mass.matrix if mass is not None else None, numbering.dof_components
    )
    params["NOEUD_CMP"] = np.array(labels, dtype=object)
    params["TYPE_DEFO"] = np.array([defo] * n, dtype=object)
    params["FREQ"] = np.zeros(n)
    for j, label in enumerate(labels):
        ctx.log(f"static mode {j + 1:4d}  {defo}  {label}")
    return ModeResult(
        numbering=numbering,
        shapes=phi,
        frequencies=np.zeros(n),
        generalized_mass=params.get("MASS_GENE", np.zeros(n)).copy(),
        generalized_stiffness=params["RIGI_GENE"].copy(),
        mass=mass,
        stiffness=stiffness,
        kind="static",
        parameters=params,
        norm="",
        mode_labels=labels,
    )


def _pseudo_modes(ctx, kw, numbering, k, m, blocked):
    shapes, labels = [], []
    comps = numbering.dof_components
    for occ in kw.factor("PSEUDO_MODE"):
        directions = [(axis, _AXES[axis]) for axis in as_tuple(occ.get("AXE"))]
        if occ.get("DIRECTION") is not None:
            directions.append((str(occ.get("NOM_DIR") or "DIRECTION"), occ["DIRECTION"]))
        if directions:
            fields = np.column_stack([rigid_field(comps, d) for _, d in directions])
            shapes.append(acceleration_modes(k, m, numbering, fields))
            labels += [name for name, _ in directions]
            continue
        dofs = _selected(ctx, [occ], numbering, blocked)
        if dofs.size == 0:
            ctx.error("no blocked DOF (DDL_IMPO) in the selection", "PSEUDO_MODE", occ)
        shapes.append(dof_acceleration_modes(k, m, numbering, dofs))
        labels += [numbering.label(d) for d in dofs]
    return np.hstack(shapes), labels
