"""CREA_TABLE: a table from lists (LISTE: PARA + LISTE_R / LISTE_I / LISTE_K
/ LISTE_CO), from a function (FONCTION: its abscissas and ordinates) or from
a result's field (RESU: fields on the DOFs, element fields and ``*_NOEU`` fields, with
code_aster's columns RESULTAT NOM_CHAM [INST] NUME_ORDRE MAILLE NOEUD|POINT
SOUS_POINT COOR_X COOR_Y COOR_Z <components>) or from a field given alone
(RESU/CHAM_GD: an element field or a carte, columns CHAM_GD MAILLE ...)."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import NodalComponentField
from asterlite.concepts.mesh import CellConstantField
from asterlite.concepts.modes import FieldOnElements
from asterlite.concepts.table import Table
from asterlite.fem.selection import select_cells, select_nodes
from asterlite.io.result_store import nodal_field_names, nodal_series
from asterlite.post import table_ops
from asterlite.post.restitution import as_tuple, computed_fields, selection_from_keywords


def run(ctx, kw):
    table = Table(title=kw.get("TITRE") or "")
    if kw.factor("LISTE"):
        columns = {}
        for occ in kw.factor("LISTE"):
            given = [
                (key, code)
                for key, code in (("LISTE_R", "R"), ("LISTE_I", "I"), ("LISTE_K", "K24"))
                if occ.get(key) is not None
            ]
            if not given:
                ctx.unsupported("LISTE without LISTE_R, LISTE_I or LISTE_K", None, occ)
            key, code = given[0]
            values = list(as_tuple(occ[key]))
            if key == "LISTE_K":
                # code_aster reads the texts into strings of TYPE_K's length
                # (K8 by default), cutting longer ones
                code = occ.get("TYPE_K", "K8")
                width = int(code[1:])
                values = [str(v)[:width] for v in values]
            if occ.get("NUME_LIGN") is not None:
                lines = [int(n) - 1 for n in as_tuple(occ["NUME_LIGN"])]
                if len(lines) != len(values):
                    ctx.error("NUME_LIGN and the values differ in length", "NUME_LIGN", occ)
                spread = [None] * (max(lines) + 1)
                for line, value in zip(lines, values, strict=True):
                    spread[line] = value
                values = spread
            columns[occ["PARA"]] = (values, code)
        for name, (_, code) in columns.items():
            table.add_column(name, code)
        n_rows = max(len(v) for v, _ in columns.values())
        for i in range(n_rows):
            table.add_row({n: (v[i] if i < len(v) else None) for n, (v, _) in columns.items()})
        return table
    if kw.factor("FONCTION"):
        occ = kw.factor("FONCTION")[0]
        func = occ["FONCTION"]
        para = as_tuple(occ.get("PARA")) or (func.NOM_PARA, func.NOM_RESU)
        if para[0] == para[1]:
            ctx.error(f"the two parameters are both {para[0]!r}", "PARA", occ)
        if func.is_complex:
            # a fonction_c gives three real columns: the abscissa, then the
            # value's real and imaginary parts as <name>_R, <name>_I (op0036)
            names = (para[0], f"{para[1]}_R", f"{para[1]}_I")
            for name in names:
                table.add_column(name, "R")
            for x, y in zip(func.abscissas, func.ordinates, strict=True):
                y = complex(y)
                table.add_row(dict(zip(names, (float(x), y.real, y.imag), strict=True)))
            return table
        table.add_column(para[0], "R")
        table.add_column(para[1], "R")
        for x, y in zip(func.abscissas, func.ordinates, strict=True):
            table.add_row({para[0]: float(x), para[1]: y})
        return table
    if kw.factor("RESU"):
        table = from_result(ctx, kw.factor("RESU")[0])
        table.title = kw.get("TITRE") or ""
        return table
    which = next((k for k in ("TITRE",) if kw.get(k)), "source")
    ctx.unsupported(f"CREA_TABLE from {which}", which, kw)


def dof_field_by_node(result, name: str) -> NodalComponentField:
    """A field of the result on its DOFs (DEPL, VITE, ACCE, REAC_NODA...) as
    values per node and component, NaN where a node has no such DOF (code_aster
    leaves that cell of the table empty)."""
    nodes, components, values = nodal_series(result, name)
    present = np.zeros((len(nodes), len(components)), dtype=bool)
    row = {int(n): k for k, n in enumerate(nodes)}
    for node, component in result.numbering.dofs:
        if int(node) in row and component in components:
            present[row[int(node)], components.index(component)] = True
    values = np.where(present[None], values, np.nan)
    return NodalComponentField(name, nodes, tuple(components), values)


def from_result(ctx, occ):
    """RESU: the values of an element field (``*_ELNO``, ``*_ELGA``), a
    smoothed nodal field (``*_NOEU``) that CALC_CHAMP stored on RESULTAT, or
    a field on the result's DOFs (DEPL, VITE, ACCE...)."""
    if occ.get("RESULTAT") is None:
        return from_field(ctx, occ)
    result, name = occ["RESULTAT"], occ["NOM_CHAM"]
    field = computed_fields(result).get(name)
    if field is None and name in nodal_field_names(result):
        field = dof_field_by_node(result, name)
    if field is None:
        known = ", ".join([*nodal_field_names(result), *computed_fields(result)]) or "none"
        # code_aster stores some fields on its own (MECA_STATIQUE's SIEF_ELGA)
        ctx.unsupported(f"CREA_TABLE RESU on {name}: the result holds {known}", "NOM_CHAM", occ)
    # TOUT_CMP='OUI' (its only value): every component, as without NOM_CMP
    occ.mark_used("TOUT_CMP")
    components = tuple(as_tuple(occ.get("NOM_CMP"))) or tuple(field.components)
    absent = [c for c in components if c not in field.components]
    if absent:
        ctx.error(
            f"{name} has no component {absent[0]!r} (it has {', '.join(field.components)})",
            "NOM_CMP",
            occ,
        )
    mesh = result.numbering.mesh
    n_orders = field.values.shape[0]
    times = getattr(result, "times", None)
    order = np.asarray(getattr(result, "order", np.arange(1, n_orders + 1)))
    grid = np.arange(n_orders, dtype=float) if times is None else np.asarray(times, dtype=float)
    picked = np.asarray(selection_from_keywords(ctx, occ, grid, order).lower, dtype=int)
    with_time = times is not None or occ.get("INST") is not None or occ.get("LIST_INST") is not None
    steps = [(order[i], float(grid[i]) if with_time else None) for i in picked]
    cmp_index = [field.components.index(c) for c in components]
    head = {"RESULTAT": result.name or "", "NOM_CHAM": name}
    if hasattr(field, "cells"):
        if occ.get("TOUT") != "OUI" and not (occ.get("GROUP_MA") or occ.get("MAILLE")):
            ctx.unsupported(
                "CREA_TABLE RESU on an element field by GROUP_NO / NOEUD", "GROUP_NO", occ
            )
        chosen = select_cells(ctx, occ, mesh, all_cells=field.cells)
        cells = np.intersect1d(np.asarray(chosen, dtype=int), np.asarray(field.cells, dtype=int))
        position = {int(c): i for i, c in enumerate(field.cells)}
        values = field.values[picked][:, [position[int(c)] for c in cells]][..., cmp_index]
        n_points = values.shape[2]
        by_node = name.endswith("_ELNO")
        supports = table_ops.field_support_labels(mesh, cells, n_points, by_node)
        flat = values.reshape(len(steps), len(cells) * n_points, len(components))
        kind = "ELNO" if by_node else "ELGA"
        return table_ops.field_value_table(head, steps, supports, flat, components, kind)
    chosen = select_nodes(ctx, occ, mesh, all_nodes=field.nodes)
    nodes = np.intersect1d(np.asarray(chosen, dtype=int), np.asarray(field.nodes, dtype=int))
    position = {int(n): i for i, n in enumerate(field.nodes)}
    values = field.values[picked][:, [position[int(n)] for n in nodes]][..., cmp_index]
    supports = table_ops.node_support_labels(mesh, nodes)
    return table_ops.field_value_table(head, steps, supports, values, components, "NOEU")


def _field_components(ctx, occ, available) -> tuple[str, ...]:
    """NOM_CMP's components (each checked), or all of them (TOUT_CMP='OUI')."""
    occ.mark_used("TOUT_CMP")
    components = tuple(as_tuple(occ.get("NOM_CMP"))) or tuple(available)
    absent = [c for c in components if c not in available]
    if absent:
        ctx.error(
            f"the field has no component {absent[0]!r} (it has {', '.join(available)})",
            "NOM_CMP",
            occ,
        )
    return components


def from_field(ctx, occ):
    """RESU/CHAM_GD: the values of an element field (CREA_CHAMP EXTR of an
    ELNO/ELGA field) or of a carte (a value set per cell, MAILLE then its
    components), on the cells of TOUT / GROUP_MA / MAILLE."""
    field = occ["CHAM_GD"]
    if not isinstance(field, (FieldOnElements, CellConstantField)):
        ctx.unsupported(
            f"CREA_TABLE RESU/CHAM_GD on a {field.aster_type} (element fields and cartes only)",
            "CHAM_GD",
            occ,
        )
    if occ.get("TOUT") != "OUI" and not (occ.get("GROUP_MA") or occ.get("MAILLE")):
        ctx.unsupported("CREA_TABLE RESU/CHAM_GD by GROUP_NO / NOEUD", "GROUP_NO", occ)
    mesh = field.mesh
    head = {"CHAM_GD": field.name or ""}
    if isinstance(field, CellConstantField):
        carried = sorted(field.values)
        width = max((len(v) for v in field.values.values()), default=0)
        components = _field_components(ctx, occ, field.components[:width])
        cells = np.intersect1d(select_cells(ctx, occ, mesh, all_cells=carried), carried)
        values = np.full((1, len(cells), len(components)), np.nan)
        for row, cell in enumerate(cells):
            given = dict(zip(field.components, field.values[int(cell)], strict=False))
            values[0, row] = [given.get(c, np.nan) for c in components]
        present = ~np.all(np.isnan(values[0]), axis=1)  # a cell without them has no row
        supports = [{"MAILLE": str(int(c) + 1)} for c in cells[present]]
        return table_ops.field_value_table(
            head, [(None, None)], supports, values[:, present], components, "CART"
        )
    components = _field_components(ctx, occ, field.components)
    chosen = select_cells(ctx, occ, mesh, all_cells=field.cells)
    cells = np.intersect1d(np.asarray(chosen, dtype=int), np.asarray(field.cells, dtype=int))
    position = {int(c): i for i, c in enumerate(field.cells)}
    cmp_index = [field.components.index(c) for c in components]
    values = np.asarray(field.values)[[position[int(c)] for c in cells]][..., cmp_index]
    by_node = field.field_type.startswith("ELNO")
    n_points = values.shape[1]
    supports = table_ops.field_support_labels(mesh, cells, n_points, by_node)
    flat = values.reshape(1, len(cells) * n_points, len(components))
    kind = "ELNO" if by_node else "ELGA"
    return table_ops.field_value_table(head, [(None, None)], supports, flat, components, kind)
