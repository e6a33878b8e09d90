"""Operations of CALC_TABLE on :class:`~asterlite.concepts.table.Table`.

Each function takes a table and returns a new one (the input is never
modified): rename, drop or keep columns, drop duplicated rows, merge two
tables on key columns, add a row or a column, add a column computed by a
formula, and column statistics (CALCUL).
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.table import Table, infer_type
from asterlite.errors import CommandError


def copy_table(table: Table) -> Table:
    return table.copy()


def rename(table: Table, old: str, new: str) -> Table:
    table.require(old)
    if new in table.types and new != old:
        raise CommandError(f"RENOMME: the table already has a parameter {new!r}")
    out = copy_table(table)
    out.rename_column(old, new)
    return out


def drop_columns(table: Table, names) -> Table:
    for name in names:
        table.require(name)
    kept = [c for c in table.columns if c not in names]
    return table.take(np.arange(len(table)), kept)


def _keys(table: Table, names) -> list[tuple]:
    """Each row's tuple of the values of ``names`` (None where absent)."""
    if not names:
        return [() for _ in range(len(table))]
    return list(zip(*(table.column(n) for n in names), strict=True))


def unique_rows(table: Table, names) -> Table:
    """Keep the first row of each combination of values of ``names``."""
    for name in names:
        table.require(name)
    seen, kept = set(), []
    for i, key in enumerate(_keys(table, names)):
        if key not in seen:
            seen.add(key)
            kept.append(i)
    return table.take(kept)


def merge(table: Table, other: Table, keys=(), restrict: bool = False) -> Table:
    """COMB: add the columns of ``other``. Without keys its rows are appended;
    with keys, a row of ``other`` updates the rows of ``table`` with the same
    key values, or is appended (unless RESTREINT='OUI')."""
    out = copy_table(table)
    for name in other.columns:
        out.add_column(name, other.types[name])
    if not keys:
        out.extend(len(other), {name: other.column(name) for name in other.columns})
        return out
    for name in keys:
        table.require(name)
        other.require(name)
    index: dict[tuple, list[int]] = {}
    for i, key in enumerate(_keys(out, keys)):
        index.setdefault(key, []).append(i)
    for row in other.iter_rows():
        key = tuple(row.get(k) for k in keys)
        if key in index:
            for target in index[key]:
                for name, value in row.items():
                    out.set_cell(name, target, value)
        elif not restrict:
            out.add_row(row)
    if restrict:
        keys_of_other = set(_keys(other, keys))
        out.keep_rows([i for i, key in enumerate(_keys(out, keys)) if key in keys_of_other])
    return out


def add_row(table: Table, names, values) -> Table:
    if len(names) != len(values):
        raise CommandError("AJOUT_LIGNE: NOM_PARA and VALE differ in length")
    out = copy_table(table)
    out.add_row(dict(zip(names, values, strict=True)))
    return out


def add_column(table: Table, names, values=None, column_values=None) -> Table:
    """AJOUT_COLONNE: one constant per new column (VALE), or one column of
    values (VALE_COLONNE, one per row)."""
    out = copy_table(table)
    if column_values is not None:
        if len(names) != 1:
            raise CommandError("AJOUT_COLONNE with VALE_COLONNE takes one NOM_PARA")
        if len(column_values) != len(out):
            raise CommandError(f"AJOUT_COLONNE: {len(column_values)} values for {len(out)} rows")
        out.add_column(names[0], infer_type(column_values[0]))
        for i, value in enumerate(column_values):
            out.set_cell(names[0], i, value)
        return out
    if len(names) != len(values):
        raise CommandError("AJOUT_COLONNE: NOM_PARA and VALE differ in length")
    for name, value in zip(names, values, strict=True):
        out.add_column(name, infer_type(value))
        for i in range(len(out)):
            out.set_cell(name, i, value)
    return out


def formula_column(table: Table, formula, new_name: str, columns=None) -> Table:
    """OPER: a column ``new_name`` = formula(columns), computed on the rows
    where every argument is present (the others stay empty)."""
    names = list(columns) if columns else list(formula.NOM_PARA)
    if len(names) != len(formula.NOM_PARA):
        raise CommandError(
            f"OPER: the formula takes {len(formula.NOM_PARA)} parameters, "
            f"NOM_COLONNE gives {len(names)}"
        )
    for name in names:
        table.require(name)
    out = copy_table(table)
    out.add_column(new_name, "C" if getattr(formula, "complex_result", False) else "R")
    held = np.ones(len(out), dtype=bool)
    for name in names:
        held &= out.present(name)
    complete = np.flatnonzero(held)
    if complete.size:
        args = [np.array(out.column(n), dtype=object)[complete].astype(float) for n in names]
        values = np.atleast_1d(formula.evaluate(*args))
        for i, value in zip(complete.tolist(), values, strict=True):
            out.set_cell(new_name, i, complex(value) if np.iscomplexobj(value) else float(value))
    return out


STATISTICS = {
    "MAXI": np.max,
    "MINI": np.min,
    "SOMM": np.sum,
    "MOY": np.mean,
    "MAXI_ABS": lambda v: v[np.argmax(np.abs(v))],
    "MINI_ABS": lambda v: v[np.argmin(np.abs(v))],
    "SOMM_ABS": lambda v: np.sum(np.abs(v)),
}


def statistics(table: Table, names, kinds) -> Table:
    """CALCUL: one row per TYPE_CALCUL, one column per parameter.

    MAXI_ABS / MINI_ABS keep the sign of the value of largest / smallest
    magnitude, as code_aster."""
    out = Table(title=table.title)
    out.add_column("TYPE_CALCUL", "K8")
    for name in names:
        table.require(name)
        out.add_column(name, table.types[name])
    for kind in kinds:
        row = {"TYPE_CALCUL": kind}
        for name in names:
            values = np.array([v for v in table.column(name) if v is not None])
            if values.size:
                row[name] = STATISTICS[kind](values).item()
        out.add_row(row)
    return out


# -- CREA_TABLE RESU: field values as a table ------------------------------


def field_support_labels(mesh, cells, n_points: int, by_node: bool) -> list[dict]:
    """One dict per (cell, point): MAILLE and NOEUD (by 1-based number, as
    code_aster 17 names them, with the node's COOR_X/Y/Z) for ``*_ELNO``,
    MAILLE and POINT for ``*_ELGA``; cells outer, points inner."""
    labels = []
    for cell in cells:
        nodes = mesh.cell_nodes[int(cell)]
        for point in range(n_points):
            label = {"MAILLE": str(int(cell) + 1)}
            if by_node:
                node = int(nodes[point])
                label["NOEUD"] = str(node + 1)
                label.update(coordinates(mesh, node))
            else:
                label["POINT"] = point + 1
            labels.append(label)
    return labels


def node_support_labels(mesh, nodes) -> list[dict]:
    """One dict per node: NOEUD (1-based number) and COOR_X/Y/Z."""
    return [{"NOEUD": str(int(n) + 1), **coordinates(mesh, int(n))} for n in nodes]


def coordinates(mesh, node: int) -> dict:
    """COOR_X, COOR_Y, COOR_Z of a mesh node."""
    x, y, z = (float(v) for v in mesh.coords[node][:3])
    return {"COOR_X": x, "COOR_Y": y, "COOR_Z": z}


def field_value_table(
    head: dict, steps, supports: list[dict], values: np.ndarray, components, kind: str
) -> Table:
    """CREA_TABLE RESU's table: for each step (NUME_ORDRE, INST or None) and
    each support (MAILLE / NOEUD / POINT / COOR_*), the row ``head``
    (RESULTAT, NOM_CHAM) + access + support + the components' values
    ``values[step, support, component]``. ``kind`` (ELNO, ELGA, NOEU, CART)
    fixes code_aster's columns; a field given alone (CHAM_GD) has the one
    step ``(None, None)`` and no access columns."""
    table = Table()
    for name in head:
        table.add_column(name, "K16")
    if any(time is not None for _, time in steps):
        table.add_column("INST", "R")
    if any(order is not None for order, _ in steps):
        table.add_column("NUME_ORDRE", "I")
    support_columns = {
        "ELNO": (("MAILLE", "K8"), ("NOEUD", "K8"), ("SOUS_POINT", "I")),
        "ELGA": (("MAILLE", "K8"), ("POINT", "I"), ("SOUS_POINT", "I")),
        "NOEU": (("NOEUD", "K8"),),
        "CART": (("MAILLE", "K8"),),
    }[kind]
    for name, code in support_columns + (("COOR_X", "R"), ("COOR_Y", "R"), ("COOR_Z", "R")):
        table.add_column(name, code)
    for name in components:
        table.add_column(name, "R")
    # column by column, steps outer and supports inner
    n_supports = len(supports)
    count = len(steps) * n_supports
    cells: dict = dict(head)
    cells["INST"] = [time for _, time in steps for _ in range(n_supports)]
    cells["NUME_ORDRE"] = [
        None if order is None else int(order) for order, _ in steps for _ in range(n_supports)
    ]
    for name in dict.fromkeys(key for support in supports for key in support):
        cells[name] = [support.get(name) for support in supports] * len(steps)
    values = np.asarray(values).reshape(count, len(components))
    for c, name in enumerate(components):
        cells[name] = values[:, c]
    # a support without the component (NaN) leaves its cell empty
    table.extend(count, cells, nan_absent=tuple(components))
    return table
