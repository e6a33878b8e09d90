"""REST_GENE_PHYS: physical fields of a generalized transient (tran_gene).

u(t) = Φ q(t) on the chosen DOFs, at the archived states (TOUT_ORDRE,
NUME_ORDRE) or at chosen instants (INST, LIST_INST), interpolated linearly
when INTERPOL='LIN'. The result's orders are the archived ones for
TOUT_ORDRE / NUME_ORDRE and 1..n for instant lists.

MULT_APPUI='OUI' adds the support motion Σ ψ_k s_k(t) when the tran_gene
carries it in ``info["mult_appui"]`` (a list of dicts with ``"shape"``: a
static mode on the basis DOFs, and ``"DEPL"``/``"VITE"``/``"ACCE"``:
functions of time). ACCE_MONO_APPUI adds γ(t)·DIRECTION to translations.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import DofNumbering
from asterlite.concepts.transient import DynaTrans, TranGene
from asterlite.post.restitution import (
    FIELDS,
    as_tuple,
    dof_rows,
    node_indices,
    recombine,
    recombine_element_field,
    selection_from_keywords,
    support_motion,
)

TRANSLATIONS = ("DX", "DY", "DZ")


def run(ctx, kw):
    result = kw.get("RESU_GENE")
    if not isinstance(result, TranGene):
        ctx.unsupported(
            f"REST_GENE_PHYS of a {getattr(result, 'aster_type', type(result).__name__)}",
            "RESU_GENE",
            kw,
        )
    basis = kw.get("MODE_MECA") or result.basis
    if basis.n_modes != result.n_modes:
        ctx.error(
            f"MODE_MECA has {basis.n_modes} modes, the result {result.n_modes}", "MODE_MECA", kw
        )
    fields, element_names = requested_fields(ctx, kw, basis)
    if kw.get("CORR_STAT") == "OUI":
        ctx.unsupported("CORR_STAT='OUI'", "CORR_STAT", kw)
    selection = selection_from_keywords(ctx, kw, result.times, result.order)
    numbering = basis.numbering
    nodes = node_indices(ctx, kw, numbering.mesh)
    rows = dof_rows(numbering, nodes, as_tuple(kw.get("NOM_CMP")))
    if rows.size == 0:
        ctx.error("no DOF matches the requested nodes and components", "GROUP_NO", kw)
    shapes = basis.shapes[rows, :]
    out = {}
    for name in fields:
        generalized = selection.apply(getattr(result, name.lower()))
        out[name] = recombine(shapes, generalized)
    if kw.get("MULT_APPUI") == "OUI":
        add_support_motion(ctx, kw, result, rows, selection.times, out)
    if kw.get("ACCE_MONO_APPUI") is not None and "ACCE" in out:
        add_uniform_acceleration(ctx, kw, numbering, rows, selection.times, out)
    if nodes is None and rows.size == numbering.n_dofs:
        sub = numbering
    else:
        sub = DofNumbering(numbering.mesh, [numbering.dofs[i] for i in rows])
    restored = DynaTrans(sub, selection.times, selection.order, out)
    if element_names:
        if kw.get("MULT_APPUI") == "OUI":
            ctx.unsupported("MULT_APPUI='OUI' with element fields", "MULT_APPUI", kw)
        generalized = selection.apply(result.depl)
        # stored as CALC_CHAMP stores element fields on a result
        restored.element_fields = {
            name: recombine_element_field(basis.element_fields[name], generalized)
            for name in element_names
        }
    return restored


def requested_fields(ctx, kw, basis) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """(nodal fields, element fields) to restore. Element fields (SIPO_ELNO,
    EFGE_ELNO...) recombine those CALC_CHAMP computed on the modal basis."""
    if kw.get("TOUT_CHAM") == "OUI" or kw.get("NOM_CHAM") is None:
        return FIELDS, ()
    names = tuple(dict.fromkeys(as_tuple(kw["NOM_CHAM"])))
    computed = getattr(basis, "element_fields", None) or {}
    elements = tuple(n for n in names if n not in FIELDS and n in computed)
    other = [n for n in names if n not in FIELDS and n not in computed]
    if other:
        if other[0].endswith(("_ELNO", "_ELGA")):
            ctx.error(
                f"NOM_CHAM={other[0]!r}: the modal basis {basis.name or ''} has no such field "
                "(compute it first with CALC_CHAMP on the modes)",
                "NOM_CHAM",
                kw,
            )
        ctx.unsupported(f"NOM_CHAM={other[0]!r} (DEPL, VITE, ACCE, element fields)", "NOM_CHAM", kw)
    return tuple(n for n in names if n in FIELDS), elements


def add_support_motion(ctx, kw, result, rows, times, out) -> None:
    supports = result.info.get("mult_appui")
    if not supports:
        ctx.unsupported(
            "MULT_APPUI='OUI' on a result computed without multi-support excitation",
            "MULT_APPUI",
            kw,
        )
    for name in out:
        out[name] = out[name] + support_motion(supports, rows, times, name)


def add_uniform_acceleration(ctx, kw, numbering, rows, times, out) -> None:
    direction = np.asarray(as_tuple(kw.get("DIRECTION")) or (0.0, 0.0, 0.0), dtype=float)
    gamma = kw["ACCE_MONO_APPUI"].evaluate(times)
    weights = np.array(
        [
            direction[TRANSLATIONS.index(numbering.dofs[i][1])]
            if numbering.dofs[i][1] in TRANSLATIONS
            else 0.0
            for i in rows
        ]
    )
    out["ACCE"] = out["ACCE"] + np.outer(gamma, weights)
