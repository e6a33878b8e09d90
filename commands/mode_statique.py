"""MODE_STATIQUE: constrained modes (MODE_STAT), attachment modes
(FORCE_NODALE) and pseudo-modes (PSEUDO_MODE)."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.modes import ModeResult
from asterlite.fem.selection import as_tuple, select_nodes
from asterlite.modal.modal_parameters import modal_parameters
from asterlite.modal.static_modes import (
    StaticModeError,
    blocked_dofs,
    constrained_modes,
    response_modes,
)

_AXES = {"X": (1.0, 0.0, 0.0), "Y": (0.0, 1.0, 0.0), "Z": (0.0, 0.0, 1.0)}


def _selected_dofs(ctx, occ, numbering, keep) -> list[int]:
    """DOFs of the selected nodes / components for which ``keep(dof)`` holds."""
    mesh = numbering.mesh
    nodes = select_nodes(ctx, occ, mesh)
    with_cmp = as_tuple(occ.get("AVEC_CMP"))
    without = as_tuple(occ.get("SANS_CMP"))
    out = []
    wanted = set(nodes.tolist())
    for dof, (node, comp) in enumerate(numbering.dofs):
        if node not in wanted:
            continue
        if with_cmp and comp not in with_cmp:
            continue
        if comp in without:
            continue
        if keep(dof):
            out.append(dof)
    # order by the node order given, then components
    rank = {int(n): i for i, n in enumerate(nodes)}
    out.sort(key=lambda d: (rank[numbering.dofs[d][0]], d))
    return out


def run(ctx, kw):
    stiffness = kw["MATR_RIGI"]
    mass = kw.get("MATR_MASS")
    numbering = stiffness.numbering
    shapes, labels = [], []
    try:
        blocked = blocked_dofs(numbering)
        for occ in kw.factor("MODE_STAT"):
            dofs = _selected_dofs(ctx, occ, numbering, lambda d: d in blocked)
            if not dofs:
                ctx.error("no blocked DOF (DDL_IMPO) in the selection", "MODE_STAT", occ)
            shapes.append(constrained_modes(stiffness.matrix, numbering, dofs))
            labels += [numbering.label(d) for d in dofs]
        for occ in kw.factor("FORCE_NODALE"):
            dofs = _selected_dofs(ctx, occ, numbering, lambda d: d not in blocked)
            if not dofs:
                ctx.error("no free DOF in the selection", "FORCE_NODALE", occ)
            loads = np.zeros((numbering.n_dofs, len(dofs)))
            loads[dofs, np.arange(len(dofs))] = 1.0
            shapes.append(response_modes(stiffness.matrix, numbering, loads))
            labels += [numbering.label(d) for d in dofs]
        for occ in kw.factor("PSEUDO_MODE"):
            if mass is None:
                ctx.error("PSEUDO_MODE needs MATR_MASS", "MATR_MASS", kw)
            directions = [(a, _AXES[a]) for a in as_tuple(occ.get("AXE"))]
            if occ.get("DIRECTION") is not None:
                d = np.asarray(as_tuple(occ["DIRECTION"]), dtype=float)
                directions.append(("DIRECTION", tuple(d / np.linalg.norm(d))))
            if not directions:
                ctx.unsupported("PSEUDO_MODE by node and component", "PSEUDO_MODE", occ)
            comps = numbering.dof_components
            for name, d in directions:
                rigid = np.array(
                    [dict(zip(("DX", "DY", "DZ"), d, strict=True)).get(c, 0.0) for c in comps]
                )
                shapes.append(response_modes(stiffness.matrix, numbering, mass.matrix @ rigid))
                labels.append(f"ACCE {name}")
    except StaticModeError as exc:
        ctx.error(str(exc), "MATR_RIGI", kw)
    if not shapes:
        ctx.error("give MODE_STAT, FORCE_NODALE or PSEUDO_MODE", None, kw)
    if kw.factor("MODE_INTERF"):
        ctx.unsupported("MODE_STATIQUE MODE_INTERF", "MODE_INTERF", kw)
    phi = np.hstack([np.asarray(s).reshape(numbering.n_dofs, -1) for s in shapes])
    params = modal_parameters(
        phi, stiffness.matrix, mass.matrix if mass is not None else None, numbering.dof_components
    )
    params["NOEUD_CMP"] = np.array(labels, dtype=object)
    n = phi.shape[1]
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
