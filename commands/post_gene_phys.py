"""POST_GENE_PHYS: physical values at chosen nodes of a generalized transient,
into a table, without restituting the whole field.

Each OBSERVATION recombines u(t) = Φ_rows q(t) on the DOFs of its nodes
(GROUP_NO / NOEUD / GROUP_MA / MAILLE) and components (NOM_CMP; every
component the basis carries there by default), for NOM_CHAM DEPL, VITE,
ACCE (q, q̇, q̈), at the archived instants chosen by TOUT_ORDRE / TOUT_INST
(default), NUME_ORDRE, INST or LIST_INST (nearest archived instant within
PRECISION, no interpolation). ``*_ABSOLU`` adds the support motion when the
result carries a multi-support excitation (as REST_GENE_PHYS does), and
ACCE_ABSOLU with ACCE_MONO_APPUI adds γ(t)·DIRECTION to translations;
without either the absolute field equals the relative one (code_aster warns
too).

The table follows code_aster: one row per instant, component and node (in
that nesting: components outer, nodes inner, as code_aster fills it), with
the parameters NUME_OBSE, INST, NOM_CHAM, NOM_CMP, NOEUD (node number, as
code_aster 17 names nodes), MAILLE, POINT (empty for nodal fields), VALE_R.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.table import Table
from asterlite.concepts.transient import TranGene
from asterlite.fem.dofs import sort_components
from asterlite.post.restitution import (
    as_tuple,
    node_indices,
    recombine,
    selection_from_keywords,
)

COLUMNS = {
    "NUME_OBSE": "I",
    "INST": "R",
    "NOM_CHAM": "K16",
    "NOM_CMP": "K8",
    "NOEUD": "K8",
    "MAILLE": "K8",
    "POINT": "K8",
    "VALE_R": "R",
}
NODAL_FIELDS = ("DEPL", "VITE", "ACCE", "DEPL_ABSOLU", "VITE_ABSOLU", "ACCE_ABSOLU")
TRANSLATIONS = ("DX", "DY", "DZ")


def run(ctx, kw):
    result = kw["RESU_GENE"]
    if not isinstance(result, TranGene):
        ctx.unsupported(f"POST_GENE_PHYS of a {result.aster_type}", "RESU_GENE", kw)
    basis = kw.get("MODE_MECA") or result.basis
    if basis.n_modes != result.n_modes:
        ctx.error(
            f"MODE_MECA has {basis.n_modes} modes, the result {result.n_modes}", "MODE_MECA", kw
        )
    if result.info.get("corr_stat"):
        ctx.unsupported("results computed with a static correction (CORR_STAT)", "RESU_GENE", kw)
    table = Table(title=kw.get("TITRE") or "")
    for name, type_code in COLUMNS.items():
        table.add_column(name, type_code)
    for number, occ in enumerate(kw.factor("OBSERVATION"), start=1):
        for row in observation_rows(ctx, occ, result, basis, number):
            table.add_row(row)
    return table


def observation_rows(ctx, occ, result, basis, number: int) -> list[dict]:
    field = occ.get("NOM_CHAM", "DEPL")
    if field not in NODAL_FIELDS:
        ctx.unsupported(f"NOM_CHAM={field!r} (nodal DEPL/VITE/ACCE fields only)", "NOM_CHAM", occ)
    if occ.get("FREQ") is not None or occ.get("LIST_FREQ") is not None:
        ctx.error("FREQ / LIST_FREQ apply to harmonic results", "FREQ", occ)
    numbering = basis.numbering
    mesh = numbering.mesh
    nodes = node_indices(ctx, occ, mesh, allow_all=False)
    comps = observed_components(ctx, occ, numbering, nodes)
    pairs = [(c, n) for c in comps for n in nodes if (int(n), c) in numbering.index]
    rows_of_dofs = np.array([numbering.index[(int(n), c)] for c, n in pairs], dtype=int)
    selection = selection_from_keywords(ctx, occ, result.times, result.order)
    generalized = selection.apply(getattr(result, field[:4].lower()))
    values = recombine(basis.shapes[rows_of_dofs, :], generalized)
    if field.endswith("_ABSOLU"):
        values = values + absolute_part(ctx, occ, result, field, rows_of_dofs, numbering, selection)
    rows = []
    for k, instant in enumerate(selection.times):
        for j, (comp, node) in enumerate(pairs):
            rows.append(
                {
                    "NUME_OBSE": number,
                    "INST": float(instant),
                    "NOM_CHAM": field,
                    "NOM_CMP": comp,
                    "NOEUD": str(int(node) + 1),
                    "VALE_R": float(values[k, j]),
                }
            )
    return rows


def observed_components(ctx, occ, numbering, nodes) -> tuple[str, ...]:
    """NOM_CMP, or every component the basis carries (code_aster's order)."""
    carried = {c for n, c in numbering.dofs}
    asked = tuple(as_tuple(occ.get("NOM_CMP")))
    if not asked:
        return sort_components(carried)
    absent = [c for c in asked if c not in carried]
    if absent:
        ctx.error(
            f"component {absent[0]} is not in the field (it has "
            f"{', '.join(sort_components(carried))})",
            "NOM_CMP",
            occ,
        )
    return asked


def absolute_part(ctx, occ, result, field, rows, numbering, selection) -> np.ndarray:
    """What an absolute field adds to the relative one at the selected instants."""
    extra = np.zeros((selection.times.size, rows.size))
    kind = field[:4]
    supports = result.info.get("mult_appui")
    if supports:
        for support in supports:
            motion = support.get(kind)
            if motion is not None:
                shape = np.asarray(support["shape"])[rows]
                extra += np.outer(motion.evaluate(selection.times), shape)
        return extra
    if field == "ACCE_ABSOLU" and occ.get("ACCE_MONO_APPUI") is not None:
        functions = as_tuple(occ["ACCE_MONO_APPUI"])
        directions = np.asarray(as_tuple(occ.get("DIRECTION")), dtype=float).reshape(-1, 3)
        if len(functions) != len(directions):
            ctx.error(
                f"{len(functions)} ACCE_MONO_APPUI functions for {len(directions)} DIRECTION",
                "DIRECTION",
                occ,
            )
        for function, direction in zip(functions, directions, strict=True):
            gamma = function.evaluate(selection.times)
            weights = np.array(
                [
                    direction[TRANSLATIONS.index(numbering.dofs[i][1])]
                    if numbering.dofs[i][1] in TRANSLATIONS
                    else 0.0
                    for i in rows
                ]
            )
            extra += np.outer(gamma, weights)
        return extra
    ctx.log(
        f"warning: {field} requested but the result has no support motion: "
        f"values are those of {kind}"
    )
    return extra
