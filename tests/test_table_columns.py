"""Tables keep their cells column by column: reals and integers in typed
arrays (8 bytes a value, one presence byte), rows made only when asked. The
bulk builders (``extend``: CREA_TABLE RESU, POST_RCCM) store what ``add_row``
of each row would, and FILTRE / TRI / EXTR / UNIQUE / COMB on the columns
keep the rows a row-by-row reading keeps."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.table import Table
from asterlite.post import table_ops


def sparse_table(n=200, seed=5) -> tuple[Table, list[dict]]:
    """A table of texts, integers and reals, some cells absent, and the
    rows it was built from."""
    rng = np.random.default_rng(seed)
    rows = []
    for _ in range(n):
        row = {"NOEUD": f"N{int(rng.integers(1, 9))}", "ORDRE": int(rng.integers(0, 5))}
        if rng.random() < 0.8:
            row["X"] = float(rng.normal() * 10.0 ** rng.integers(-3, 4))
        if rng.random() < 0.5:
            row["Y"] = float(rng.integers(-3, 3))
        rows.append(row)
    table = Table()
    for row in rows:
        table.add_row(row)
    return table, rows


def test_reals_and_integers_take_nine_bytes_a_cell():
    table = Table()
    for i in range(1000):
        table.add_row({"N": i, "X": i * 0.5, "Z": None if i % 2 else 1.0})
    assert table.nbytes() == 3 * 1000 * 9
    assert table.column("Z")[:3] == [1.0, None, 1.0]
    assert [type(v) for v in table.row(0).values()] == [int, float, float]


def test_rows_are_made_on_demand_and_copies():
    table, rows = sparse_table()
    assert table.rows == rows
    table.rows[0]["X"] = "changed"  # a fresh list: the table is as it was
    assert table.rows == rows
    table.set_cell("X", 0, 2)
    assert table.row(0)["X"] == 2.0 and type(table.row(0)["X"]) is float
    table.set_cell("X", 0, None)
    assert "X" not in table.row(0)


def test_extend_stores_what_add_row_stores():
    by_rows, at_once = Table(), Table()
    for table in (by_rows, at_once):
        table.add_column("NOM", "K8")
        table.add_column("INST", "R")
        table.add_column("N", "I")
    values = np.array([1.5, np.nan, -2.0, 3.0])
    labels = ["a", "b", None, "d"]
    orders = [1, 2, 3, None]
    for k in range(4):
        by_rows.add_row(
            {
                "NOM": labels[k],
                "INST": None if np.isnan(values[k]) else values[k],
                "N": orders[k],
                "C": "const",
                "W": np.float64(k),
            }  # fmt: skip
        )
    at_once.extend(
        4, {"NOM": labels, "INST": values, "N": orders, "C": "const", "W": np.arange(4.0)},
        nan_absent=("INST",),
    )  # fmt: skip
    assert at_once.columns == by_rows.columns and at_once.types == by_rows.types
    assert at_once.rows == by_rows.rows
    assert [[type(v) for v in r.values()] for r in at_once.rows] == [
        [type(v) for v in r.values()] for r in by_rows.rows
    ]


@pytest.mark.parametrize(
    "condition",
    [
        ("NOEUD", "EQ", "N3", lambda r: r.get("NOEUD") == "N3"),
        ("X", "GT", 1.0, lambda r: r.get("X") is not None and r["X"] > 1.0),
        ("Y", "VIDE", None, lambda r: r.get("Y") is None),
        ("ORDRE", "NE", 2, lambda r: r.get("ORDRE") is not None and r["ORDRE"] != 2),
    ],
)
def test_filters_keep_the_rows_a_row_reading_keeps(condition):
    table, rows = sparse_table()
    name, crit, value, keep = condition
    assert table.filtered(name, crit, value).rows == [r for r in rows if keep(r)]


def test_extremes_sort_projection_unique_and_merge():
    table, rows = sparse_table()
    largest = max(abs(r["X"]) for r in rows if "X" in r)
    assert table.filtered("X", "MAXI_ABS").rows == [
        r for r in rows if "X" in r and abs(r["X"]) == largest
    ]

    def key(r):
        return tuple((r.get(n) is None, r.get(n) or 0) for n in ("NOEUD", "Y"))

    assert table.sorted_by(["NOEUD", "Y"], descending=True).rows == sorted(
        rows, key=key, reverse=True
    )
    projected = [{n: r[n] for n in ("Y",) if n in r} for r in rows]
    assert table.select(["Y"]).rows == [r for r in projected if r]
    seen, first = set(), []
    for r in rows:
        if (r["NOEUD"], r["ORDRE"]) not in seen:
            seen.add((r["NOEUD"], r["ORDRE"]))
            first.append(r)
    assert table_ops.unique_rows(table, ["NOEUD", "ORDRE"]).rows == first
    other = Table()
    other.add_row({"NOEUD": "N3", "Z": 7.0})
    other.add_row({"NOEUD": "NEW", "Z": 8.0})
    merged = table_ops.merge(table, other, ["NOEUD"]).rows
    expected = [{**r, "Z": 7.0} if r["NOEUD"] == "N3" else r for r in rows] + [
        {"NOEUD": "NEW", "Z": 8.0}
    ]
    assert merged == expected
    restricted = table_ops.merge(table, other, ["NOEUD"], restrict=True).rows
    assert restricted == [r for r in expected if r["NOEUD"] == "N3"]
