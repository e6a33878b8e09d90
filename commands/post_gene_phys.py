"""POST_GENE_PHYS: physical values at chosen nodes of a generalized transient
or harmonic result, into a table, without restituting the whole field.

A harm_gene gives complex DEPL / VITE / ACCE at the frequencies chosen by
FREQ / LIST_FREQ / NUME_ORDRE (all by default), in a table with FREQ and
VALE_C in place of INST and VALE_R (code_aster's pgpcrt); its element
fields and absolute fields are refused by name.

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

A result computed with a static correction (DYNA_VIBRA MODE_CORR, EXCIT
CORR_STAT='OUI') has the correction added to every nodal value, as
RECU_FONCTION / REST_GENE_PHYS with CORR_STAT='OUI' do (code_aster's
POST_GENE_PHYS restitutes it without a keyword); element fields are not
available on such a result (the correction modes carry none). Decks of
code_aster 13 to 15 get DEPL/VITE/ACCE without it, as those versions gave
them (asterlite.legacy.v15.OLD_BEHAVIOURS); their ``*_ABSOLU`` fields have it.

Element fields (``*_ELNO``, ``*_ELGA``) recombine, with q(t), the fields
CALC_CHAMP stored on the modes, on the cells of GROUP_MA / MAILLE.

The table follows code_aster: one row per instant, component and node (in
that nesting: components outer, nodes inner, as code_aster fills it), with
the parameters NUME_OBSE, INST, NOM_CHAM, NOM_CMP, NOEUD (node number, as
code_aster 17 names nodes; the node's name for code_aster 15 decks, as cells
in MAILLE), MAILLE, POINT (empty for nodal fields), VALE_R.
Element fields give one row per instant, component, cell and point (ELNO:
MAILLE and NOEUD, the cell's node; ELGA: MAILLE and POINT ``PT i``).
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.harmonic import HarmGene
from asterlite.concepts.table import Table
from asterlite.concepts.transient import TranGene
from asterlite.errors import missing_name
from asterlite.fem.dofs import sort_components
from asterlite.legacy.v15 import computes
from asterlite.legacy.version import tables_name_nodes
from asterlite.post.harmonic import selection_from_keywords as harmonic_selection
from asterlite.post.restitution import (
    as_tuple,
    node_indices,
    recombine,
    selection_from_keywords,
    support_motion,
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
HARMONIC_COLUMNS = {
    "NUME_OBSE": "I",
    "FREQ": "R",
    "NOM_CHAM": "K16",
    "NOM_CMP": "K8",
    "NOEUD": "K8",
    "MAILLE": "K8",
    "POINT": "K8",
    "VALE_C": "C",
}
NODAL_FIELDS = ("DEPL", "VITE", "ACCE", "DEPL_ABSOLU", "VITE_ABSOLU", "ACCE_ABSOLU")
TRANSLATIONS = ("DX", "DY", "DZ")


def run(ctx, kw):
    result = kw["RESU_GENE"]
    harmonic = isinstance(result, HarmGene)
    if not (harmonic or isinstance(result, TranGene)):
        ctx.unsupported(f"POST_GENE_PHYS of a {result.aster_type}", "RESU_GENE", kw)
    basis = kw.get("MODE_MECA") or result.basis
    if getattr(basis, "shapes", None) is None or getattr(basis, "numbering", None) is None:
        ctx.unsupported(
            "POST_GENE_PHYS of a result on a basis without physical shapes (give MODE_MECA)",
            "RESU_GENE",
            kw,
        )
    if basis.n_modes != result.n_modes:
        ctx.error(
            f"MODE_MECA has {basis.n_modes} modes, the result {result.n_modes}", "MODE_MECA", kw
        )
    table = Table(title=kw.get("TITRE") or "")
    for name, type_code in (HARMONIC_COLUMNS if harmonic else COLUMNS).items():
        table.add_column(name, type_code)
    for number, occ in enumerate(kw.factor("OBSERVATION"), start=1):
        if harmonic:
            rows = harmonic_rows(ctx, occ, result, basis, number)
        else:
            rows = observation_rows(ctx, occ, result, basis, number)
        for row in rows:
            table.add_row(row)
    return table


def harmonic_rows(ctx, occ, result, basis, number: int) -> list[dict]:
    """Rows of a harm_gene: u(f) = Φ_rows q(f) (complex) at the frequencies
    chosen (FREQ / LIST_FREQ / NUME_ORDRE / TOUT_ORDRE), components outer and
    nodes inner as for a transient; the table has FREQ and VALE_C where a
    transient's has INST and VALE_R (code_aster's pgpcrt)."""
    field = occ.get("NOM_CHAM", "DEPL")
    for key in ("INST", "LIST_INST", "TOUT_INST"):
        if occ.get(key) is not None:
            ctx.error(f"{key} applies to transient results (FREQ for a harm_gene)", key, occ)
    if field not in ("DEPL", "VITE", "ACCE"):
        ctx.unsupported(f"POST_GENE_PHYS {field} of a harm_gene", "NOM_CHAM", occ)
    if field not in result.fields:
        ctx.error(
            f"the result holds no {field} (it has {', '.join(result.fields)})", "NOM_CHAM", occ
        )
    numbering = basis.numbering
    mesh = numbering.mesh
    nodes = node_indices(ctx, occ, mesh, allow_all=False)
    comps = observed_components(ctx, occ, numbering, nodes)
    pairs = [(c, n) for c in comps for n in nodes if (int(n), c) in numbering.index]
    rows_of_dofs = np.array([numbering.index[(int(n), c)] for c, n in pairs], dtype=int)
    selection = harmonic_selection(ctx, occ, result.frequencies, result.order)
    generalized = np.asarray(result.fields[field])[selection.lower]
    values = generalized @ np.asarray(basis.shapes)[rows_of_dofs, :].T
    by_name = tables_name_nodes(ctx.session)
    rows = []
    for k, frequency in enumerate(selection.times):
        for j, (comp, node) in enumerate(pairs):
            rows.append(
                {
                    "NUME_OBSE": number,
                    "FREQ": float(frequency),
                    "NOM_CHAM": field,
                    "NOM_CMP": comp,
                    "NOEUD": node_label(mesh, node, by_name),
                    "VALE_C": complex(values[k, j]),
                }
            )
    return rows


def observation_rows(ctx, occ, result, basis, number: int) -> list[dict]:
    field = occ.get("NOM_CHAM", "DEPL")
    if occ.get("FREQ") is not None or occ.get("LIST_FREQ") is not None:
        ctx.error("FREQ / LIST_FREQ apply to harmonic results", "FREQ", occ)
    if field not in NODAL_FIELDS:
        return element_rows(ctx, occ, result, basis, number, field)
    numbering = basis.numbering
    mesh = numbering.mesh
    nodes = node_indices(ctx, occ, mesh, allow_all=False)
    comps = observed_components(ctx, occ, numbering, nodes)
    pairs = [(c, n) for c in comps for n in nodes if (int(n), c) in numbering.index]
    rows_of_dofs = np.array([numbering.index[(int(n), c)] for c, n in pairs], dtype=int)
    selection = selection_from_keywords(ctx, occ, result.times, result.order)
    generalized = selection.apply(getattr(result, field[:4].lower()))
    values = recombine(basis.shapes[rows_of_dofs, :], generalized)
    corrections = result.info.get("corr_stat")
    if corrections and (field.endswith("_ABSOLU") or not relative_without_correction(ctx)):
        values = values + support_motion(corrections, rows_of_dofs, selection.times, field[:4])
    if field.endswith("_ABSOLU"):
        values = values + absolute_part(ctx, occ, result, field, rows_of_dofs, numbering, selection)
    by_name = tables_name_nodes(ctx.session)  # code_aster 15 decks: nodes by name
    rows = []
    for k, instant in enumerate(selection.times):
        for j, (comp, node) in enumerate(pairs):
            rows.append(
                {
                    "NUME_OBSE": number,
                    "INST": float(instant),
                    "NOM_CHAM": field,
                    "NOM_CMP": comp,
                    "NOEUD": node_label(mesh, node, by_name),
                    "VALE_R": float(values[k, j]),
                }
            )
    return rows


def relative_without_correction(ctx) -> bool:
    """Whether DEPL/VITE/ACCE come without the static correction, as code_aster
    13 to 15 gave them (asterlite.legacy.v15.OLD_BEHAVIOURS)."""
    if not computes(ctx.session, "POST_GENE_PHYS_RELATIVE_WITHOUT_CORR_STAT"):
        return False
    ctx.log(
        "note: code_aster 15 deck: DEPL/VITE/ACCE without the static correction "
        "(code_aster 13 to 15 did not add it; *_ABSOLU fields have it)"
    )
    return True


def element_rows(ctx, occ, result, basis, number: int, name: str) -> list[dict]:
    """Rows of an element field of the modes (``*_ELNO``, ``*_ELGA`` stored by
    CALC_CHAMP on the basis) recombined with q(t): components outer, then
    cells, then points, as code_aster fills the table; ELNO rows name the
    cell (MAILLE) and its node (NOEUD), ELGA rows the cell and ``PT i``."""
    if result.info.get("corr_stat"):
        ctx.unsupported(
            f"{name} of a result computed with a static correction (CORR_STAT)", "NOM_CHAM", occ
        )
    modal = (getattr(basis, "element_fields", None) or {}).get(name)
    if modal is None:
        ctx.error(
            f"{name} is not computed on the modal basis (CALC_CHAMP on the modes first)",
            "NOM_CHAM",
            occ,
        )
    if modal.sub_points > 1:
        ctx.unsupported(
            f"POST_GENE_PHYS of {name} on sub-points (multifibre beams)", "NOM_CHAM", occ
        )
    mesh = basis.numbering.mesh
    cells = observed_cells(ctx, occ, mesh, modal)
    comps = tuple(as_tuple(occ.get("NOM_CMP"))) or modal.components
    absent = [c for c in comps if c not in modal.components]
    if absent:
        ctx.error(
            f"{name} has no component {absent[0]!r} (it has {', '.join(modal.components)})",
            "NOM_CMP",
            occ,
        )
    selection = selection_from_keywords(ctx, occ, result.times, result.order)
    generalized = selection.apply(result.depl)
    position = {int(c): i for i, c in enumerate(modal.cells)}
    rows_of_cells = [position[int(c)] for c in cells]
    picked = modal.values[:, rows_of_cells][..., [modal.components.index(c) for c in comps]]
    values = np.tensordot(generalized, picked, axes=(1, 0))  # (instants, cells, points, cmps)
    by_node = name.endswith("_ELNO")
    by_name = tables_name_nodes(ctx.session)  # code_aster 15 decks: entities by name
    labels = support_labels(mesh, cells, picked.shape[2], by_node, by_name)
    second_key = "NOEUD" if by_node else "POINT"
    rows = []
    for i, instant in enumerate(selection.times):
        for comp_index, comp in enumerate(comps):
            for cell_pos, point, cell_label, second in labels:
                rows.append(
                    {
                        "NUME_OBSE": number,
                        "INST": float(instant),
                        "NOM_CHAM": name,
                        "NOM_CMP": comp,
                        "MAILLE": cell_label,
                        second_key: second,
                        "VALE_R": float(values[i, cell_pos, point, comp_index]),
                    }
                )
    return rows


def observed_cells(ctx, occ, mesh, modal) -> np.ndarray:
    """Cells named by GROUP_MA / MAILLE (in order, without repeats), all
    carrying the modal element field."""
    chosen: list[int] = []
    for group in as_tuple(occ.get("GROUP_MA")):
        if group not in mesh.cell_groups:
            ctx.error(missing_name("cell group", group, mesh.cell_groups), "GROUP_MA", occ)
        chosen.extend(int(i) for i in mesh.cell_groups[group])
    for cell_name in as_tuple(occ.get("MAILLE")):
        found = mesh.find_cell(str(cell_name))
        if found is None:
            ctx.error(f"mesh has no cell {cell_name!r}", "MAILLE", occ)
        chosen.append(int(found))
    if not chosen:
        ctx.error("an element field observation needs GROUP_MA or MAILLE", "GROUP_MA", occ)
    cells = np.array(list(dict.fromkeys(chosen)), dtype=int)
    carried = set(int(c) for c in modal.cells)
    missing = [c for c in cells if int(c) not in carried]
    if missing:
        ctx.error(
            f"{modal.name} is not computed on cell {mesh.cell_names[missing[0]]}", "GROUP_MA", occ
        )
    return cells


def support_labels(mesh, cells, n_points: int, by_node: bool, by_name=False) -> list[tuple]:
    """(cell position, point, MAILLE, NOEUD or POINT) for each point of each
    cell: cells by number and nodes by number (code_aster 17; by name with
    ``by_name``, as code_aster 15 wrote them), Gauss points as ``PT i``."""
    labels = []
    for pos, cell in enumerate(cells):
        nodes = mesh.cell_nodes[int(cell)]
        cell_label = mesh.cell_names[int(cell)] if by_name else str(int(cell) + 1)
        for point in range(n_points):
            second = node_label(mesh, nodes[point], by_name) if by_node else f"PT {point + 1}"
            labels.append((pos, point, cell_label, second))
    return labels


def node_label(mesh, node, by_name: bool) -> str:
    """A node in a table: its 1-based number (code_aster 17) or its name."""
    return mesh.node_names[int(node)] if by_name else str(int(node) + 1)


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
