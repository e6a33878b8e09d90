"""CALC_CHAR_SEISME: the seismic load vector of a support motion.

MONO_APPUI='OUI' gives -M Δ (relative formulation); MODE_STAT + GROUP_NO gives
-M Σ d_i ψ_(node, i) from the static modes of the moving supports, zeroed on
blocked DOFs (absolute formulation). The result is a nodal field on the mass
matrix's numbering, ready for PROJ_VECT_BASE / PROJ_BASE or a physical
DYNA_VIBRA EXCIT/VECT_ASSE."""

from __future__ import annotations

from asterlite.concepts.assembly import NodalField
from asterlite.fem.selection import node_group_members
from asterlite.modal.renumber import same_dofs
from asterlite.modal.seismic import (
    COMPONENTS,
    SeismicError,
    mono_support_load,
    multi_support_load,
    static_mode_columns,
)
from asterlite.modal.static_modes import blocked_dofs


def run(ctx, kw):
    mass = kw["MATR_MASS"]
    numbering = mass.numbering
    try:
        if kw.get("MONO_APPUI") == "OUI":
            values = mono_support_load(mass.matrix, numbering.dof_components, kw["DIRECTION"])
        else:
            values = _multi(ctx, kw, mass)
    except SeismicError as exc:
        ctx.error(str(exc), "DIRECTION", kw)
    return NodalField(numbering=numbering, values=values)


def _multi(ctx, kw, mass):
    numbering = mass.numbering
    modes = kw["MODE_STAT"]
    if not same_dofs(modes.numbering, numbering):
        ctx.error("MODE_STAT and MATR_MASS use different numberings", "MODE_STAT", kw)
    mesh = numbering.mesh
    nodes = node_group_members(ctx, kw, mesh)
    names = [mesh.node_names[n] for n in nodes]
    columns, weights, missing = static_mode_columns(
        modes.mode_labels, names, COMPONENTS, kw["DIRECTION"]
    )
    if missing:
        ctx.error(
            f"MODE_STAT has no static mode for {', '.join(missing[:4])}"
            " (compute it with MODE_STATIQUE/MODE_STAT)",
            "MODE_STAT",
            kw,
        )
    defo = modes.parameters.get("TYPE_DEFO")
    if defo is not None and any(defo[c] != "DEPL_IMPO" for c in columns):
        ctx.error("MODE_STAT must hold imposed-displacement modes (MODE_STAT)", "MODE_STAT", kw)
    return multi_support_load(
        mass.matrix, modes.shapes[:, columns], weights, blocked_dofs(numbering).keys()
    )
