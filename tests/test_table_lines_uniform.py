"""table_lines writes runs of rows holding the same parameters with one ``%``
format per run (uniform_lines): the text must be the cell-by-cell layout of
format_value, and cells such a format would write differently (three-digit
exponents, non-finite reals, values not of their column's type, None) must
send the table to the cell-by-cell path. Table.add_rows must make the rows
add_row makes."""

from __future__ import annotations

import math

import numpy as np
import pytest

from asterlite.concepts.table import Table
from asterlite.io.tables import table_lines, uniform_lines
from tests.test_table_lines_columns import cell_by_cell

IMPACT = {"INTITULE": "K24", "NOEUD": "K8", "CALCUL": "K16", "CHOC": "I", "INSTANT": "R",
          "F_MAX": "R", "NB_IMPACT": "I", "F_MAX_ABS": "R", "LONG_PARAMETER_NAME": "R",
          "CLASSE": "I"}  # fmt: skip


def impact_table(reals) -> Table:
    """Impact-like sparse rows: runs of IMPACT rows, a GLOBAL row, PROBA rows."""
    table = Table()
    for name, code in IMPACT.items():
        table.add_column(name, code)
    rng = np.random.default_rng(3)
    for shock in ("SUPP1", "SUPPORT_NUMBER_2"):
        labels = {"INTITULE": shock, "NOEUD": "12" if shock == "SUPP1" else "7"}
        for k, value in enumerate(reals):
            table.add_row({**labels, "CALCUL": "IMPACT", "CHOC": k + 1, "INSTANT": k * 0.1,
                           "F_MAX": value, "NB_IMPACT": int(rng.integers(-3, 12000))})  # fmt: skip
        table.add_row({**labels, "CALCUL": "GLOBAL", "F_MAX_ABS": max(reals)})
        for k in range(3):  # keys in another order than the columns
            table.add_row({"CLASSE": k + 1, "LONG_PARAMETER_NAME": -k * 1.5, **labels})
    table.add_row({})
    return table


REALS = [1.5e-3, -2.0, 0.0, -0.0, 123456.789, 9.999995e5, 1.0e-98, -9.0e99, 1 / 3]


@pytest.mark.parametrize("real_format", ["E12.5", "E14.7", "D16.8", "E15.8"])
def test_same_text_as_cell_by_cell(real_format):
    table = impact_table(REALS)
    columns = list(table.columns)
    assert uniform_lines(table.rows, columns, table.types, real_format) is not None
    assert table_lines(table, real_format=real_format) == cell_by_cell(table, columns, real_format)
    subset = ["F_MAX", "NOEUD", "CLASSE"]
    assert uniform_lines(table.rows, subset, table.types, real_format) is not None
    expected = cell_by_cell(table, subset, real_format)
    assert table_lines(table, subset, real_format=real_format) == expected


@pytest.mark.parametrize("odd", [1.0e100, -2.5e-120, 9.9999999e99, math.inf, -math.inf, math.nan])
def test_cells_outside_the_format_go_cell_by_cell(odd):
    table = impact_table([*REALS, odd])
    columns = list(table.columns)
    assert uniform_lines(table.rows, columns, table.types, "E12.5") is None
    assert table_lines(table) == cell_by_cell(table, columns, "E12.5")


def test_values_not_of_their_type_go_cell_by_cell():
    for column, value in (
        ("CHOC", 2.5),
        ("CHOC", True),
        ("NOEUD", 12),
        ("F_MAX", None),
        ("F_MAX", np.float64(2.0)),
    ):
        table = impact_table(REALS)
        rows = table.rows  # a copy: rows made by other means than a table's typed columns
        rows[1][column] = value
        assert uniform_lines(rows, list(table.columns), table.types, "E12.5") is None
    table = impact_table(REALS)
    assert uniform_lines(table.rows, list(table.columns), table.types, "F12.3") is None


def test_add_rows_makes_the_rows_of_add_row():
    common = {"INTITULE": "SUPP1", "NOEUD": 12, "CALCUL": "IMPACT", "SKIPPED": None}
    columns = {"CHOC": [1, 2, True], "INSTANT": [0.5, 1, np.float64(2.5)], "NEW": [1.5, 2.0, 3.0],
               "TEXT": ["a", "b", "c"]}  # fmt: skip
    by_rows, at_once = Table(), Table()
    for table in (by_rows, at_once):
        table.add_column("CHOC", "I")
        table.add_column("INSTANT", "R")
        table.add_column("NOEUD", "K8")
    for k in range(3):
        by_rows.add_row({**common, **{name: values[k] for name, values in columns.items()}})
    at_once.add_rows(common, columns)
    assert at_once.columns == by_rows.columns and at_once.types == by_rows.types
    assert at_once.rows == by_rows.rows
    assert [list(r) for r in at_once.rows] == [list(r) for r in by_rows.rows]
    assert [[type(v) for v in r.values()] for r in at_once.rows] == [
        [type(v) for v in r.values()] for r in by_rows.rows
    ]
    with_none = Table()
    with_none.add_rows({"A": "x"}, {"B": [1.0, None]})
    assert with_none.rows == [{"A": "x", "B": 1.0}, {"A": "x"}]
    empty = Table()
    empty.add_rows({"A": "x"}, {"B": []})
    assert empty.rows == [] and empty.columns == []
