"""table_lines formats column by column with each column's format parsed once:
the text must be the cell-by-cell layout of format_value (widths, '-' for
missing values, non-finite reals, complex and integer cells, other formats)."""

from __future__ import annotations

import math

import pytest

from asterlite.concepts.table import Table
from asterlite.io.tables import format_value, table_lines


def cell_by_cell(table, columns, real_format):
    """The former layout: every cell through format_value."""
    cells = [
        [format_value(row.get(c), table.types[c], real_format) for c in columns]
        for row in table.rows
    ]
    widths = [max([len(c)] + [len(r[j]) for r in cells]) for j, c in enumerate(columns)]
    lines = ["#-" * 40]
    lines.append(" ".join(c.ljust(w) for c, w in zip(columns, widths, strict=True)).rstrip())
    for r in cells:
        lines.append(" ".join(v.ljust(w) for v, w in zip(r, widths, strict=True)).rstrip())
    return lines


def sample_table() -> Table:
    table = Table()
    for name, code in (
        ("NOEUD", "K8"),
        ("CHOC", "I"),
        ("F_MAX", "R"),
        ("Z", "C"),
        ("LONG_NAME_R", "R"),
    ):
        table.add_column(name, code)
    values = [1.5e-3, -2.0, 0.0, math.inf, -math.inf, math.nan, 123456.789, 1]
    for k, value in enumerate(values):
        row = {"NOEUD": f"N{k}", "CHOC": k, "F_MAX": value}
        if k % 2:
            row["Z"] = complex(k, -k)
        if k % 3 == 0:
            row["LONG_NAME_R"] = value * 1.0e10
        table.add_row(row)
    table.add_row({"NOEUD": "EMPTY"})
    return table


@pytest.mark.parametrize("real_format", ["E12.5", "E.12", "F10.3", "D16.8"])
def test_same_text_as_cell_by_cell(real_format):
    table = sample_table()
    columns = list(table.columns)
    assert table_lines(table, real_format=real_format) == cell_by_cell(table, columns, real_format)
    subset = ["F_MAX", "NOEUD"]
    expected = cell_by_cell(table, subset, real_format)
    assert table_lines(table, subset, real_format=real_format) == expected
