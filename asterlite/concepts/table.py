"""Tables (``table_sdaster``): named, typed columns and sparse rows.

Owner: post-processing. A table keeps its parameters (columns) in order with
code_aster's type codes (``R``, ``I``, ``C``, ``K8``, ``K16``, ``K24``...) and
its rows as dicts; a row may lack some parameters (code_aster tables are
sparse, e.g. POST_DYNA_MODA_T mixes IMPACT, GLOBAL and PROBA rows).

Build one with ``Table()`` then ``add_row({...})`` (types are inferred for new
parameters unless given with ``add_column``). Filter with ``filtered(...)``
(FILTRE semantics), project with ``select(params)``, sort with ``sorted_by``.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from asterlite.concepts.base import Concept
from asterlite.errors import CommandError


def infer_type(value: Any) -> str:
    """code_aster type code of a Python value."""
    if isinstance(value, bool | np.bool_ | int | np.integer):
        return "I"
    if isinstance(value, float | np.floating):
        return "R"
    if isinstance(value, complex | np.complexfloating):
        return "C"
    text = str(value)
    return "K8" if len(text) <= 8 else ("K16" if len(text) <= 16 else "K24")


def _coerce(value: Any, type_code: str) -> Any:
    if value is None:
        return None
    if type_code == "I":
        return int(value)
    if type_code == "R":
        return float(value)
    if type_code == "C":
        return complex(value)
    return str(value)


# _coerce by type code: integers, reals, complexes; text otherwise (K8, K16...)
COERCIONS = {"I": int, "R": float, "C": complex}


def close_to(value: Any, reference: Any, precision: float, criterion: str) -> bool:
    """|value - reference| within PRECISION (RELATIF: scaled by |reference|,
    absolute when the reference is zero)."""
    diff = abs(value - reference)
    if criterion == "RELATIF" and reference != 0:
        return diff <= precision * abs(reference)
    return diff <= precision


@dataclass(eq=False)
class Table(Concept):
    """An ordered set of typed columns holding sparse rows."""

    aster_types = ("table_sdaster", "table_fonction", "table_container")
    deck_methods = frozenset({"getName", "EXTR_TABLE", "get_nom_para", "getParameters"})

    columns: list[str] = field(default_factory=list)
    types: dict[str, str] = field(default_factory=dict)
    rows: list[dict[str, Any]] = field(default_factory=list)
    title: str = ""

    # building -----------------------------------------------------------
    def add_column(self, name: str, type_code: str) -> None:
        if name not in self.types:
            self.columns.append(name)
            self.types[name] = type_code

    def add_row(self, values: dict[str, Any], types: dict[str, str] | None = None) -> None:
        row = {}
        known = self.types
        for name, value in values.items():
            if value is None:
                continue
            code = known.get(name)
            if code is None:
                self.add_column(name, (types or {}).get(name) or infer_type(value))
                code = known[name]
            # _coerce inlined (tables of impacts have thousands of rows)
            row[name] = COERCIONS.get(code, str)(value)
        self.rows.append(row)

    def add_rows(self, common: dict[str, Any], columns: dict[str, list]) -> None:
        """Rows holding ``common``'s values, then the k-th value of each list of
        ``columns`` (lists of one length, no None): what ``add_row`` of each
        would make, coerced column by column (a table of impacts has thousands
        of rows)."""
        if not columns or not len(next(iter(columns.values()))):
            return  # no row, as add_row of none
        if set(common) & set(columns) or any(None in values for values in columns.values()):
            for cells in zip(*columns.values(), strict=True):
                self.add_row({**common, **dict(zip(columns, cells, strict=True))})
            return
        for name, values in {**common, **columns}.items():
            if name not in self.types and values is not None:
                self.add_column(name, infer_type(values[0] if name in columns else values))
        shared = {
            k: COERCIONS.get(self.types[k], str)(v) for k, v in common.items() if v is not None
        }
        names = (*shared, *columns)
        coerced = []
        for name, values in columns.items():
            coerce = COERCIONS.get(self.types[name], str)
            coerced.append(values if _already(values, coerce) else [coerce(v) for v in values])
        head = tuple(shared.values())
        for cells in zip(*coerced, strict=True):
            self.rows.append(dict(zip(names, head + cells, strict=True)))

    @classmethod
    def from_columns(cls, data: dict[str, list], types: dict[str, str] | None = None) -> Table:
        table = cls()
        n_rows = max((len(v) for v in data.values()), default=0)
        for name, values in data.items():
            first = next((v for v in values if v is not None), 0.0)
            table.add_column(name, (types or {}).get(name) or infer_type(first))
        for i in range(n_rows):
            table.add_row({k: (v[i] if i < len(v) else None) for k, v in data.items()})
        return table

    # reading ------------------------------------------------------------
    def __len__(self) -> int:
        return len(self.rows)

    def column(self, name: str) -> list[Any]:
        """Values of one parameter, None where a row lacks it."""
        self.require(name)
        return [row.get(name) for row in self.rows]

    def require(self, name: str) -> None:
        if name not in self.types:
            raise CommandError(
                f"table {self.name or ''} has no parameter {name!r} "
                f"(it has {', '.join(self.columns) or 'none'})"
            )

    def value(self, name: str, row: int) -> Any:
        """Value at (parameter, 1-based row number), as code_aster's tab[para, i]."""
        self.require(name)
        if not 1 <= row <= len(self.rows):
            raise CommandError(f"table {self.name or ''} has {len(self.rows)} rows, not {row}")
        return self.rows[row - 1].get(name)

    def __getitem__(self, key):
        if isinstance(key, tuple) and len(key) == 2:
            return self.value(key[0], int(key[1]))
        raise CommandError("a table is indexed as TABLE['PARAMETER', row_number]")

    # transforming -------------------------------------------------------
    def _copy_with(self, rows: list[dict[str, Any]], columns: list[str] | None = None) -> Table:
        columns = list(self.columns if columns is None else columns)
        return Table(columns, {c: self.types[c] for c in columns}, rows, self.title)

    def first_rows(self, count: int) -> Table:
        return self._copy_with([dict(r) for r in self.rows[:count]])

    def select(self, names) -> Table:
        """Only the given parameters (in that order); rows left empty are dropped."""
        for name in names:
            self.require(name)
        rows = [{n: r[n] for n in names if n in r} for r in self.rows]
        return self._copy_with([r for r in rows if r], list(names))

    def filtered(
        self,
        name: str,
        crit_comp: str = "EQ",
        value: Any = None,
        precision: float = 1e-3,
        criterion: str = "RELATIF",
    ) -> Table:
        """Rows satisfying one FILTRE condition."""
        self.require(name)
        return self._copy_with(
            select_rows(self.rows, name, self.types[name], crit_comp, value, precision, criterion)
        )

    def sorted_by(self, names, descending: bool = False) -> Table:
        for name in names:
            self.require(name)

        def key(row):
            return tuple((row.get(n) is None, _sort_value(row.get(n))) for n in names)

        return self._copy_with(sorted(self.rows, key=key, reverse=descending))

    # deck API -----------------------------------------------------------
    def EXTR_TABLE(self):  # noqa: N802
        return TableView(self)

    def get_nom_para(self):
        return list(self.columns)

    def getParameters(self):  # noqa: N802
        return list(self.columns)


def _already(values: list, coerce) -> bool:
    """Whether every value is already of the type ``coerce`` makes (a float
    list for ``float``...): its coercion would change nothing."""
    return set(map(type, values)) <= {coerce}


def _base_type(type_code: str) -> str:
    return "K" if type_code.startswith("K") else type_code


def _sort_value(value):
    if isinstance(value, complex):
        return (abs(value), value.real)
    return value if value is not None else 0


def select_rows(rows, name, type_code, crit_comp, value, precision, criterion):
    """The rows of ``rows`` whose parameter ``name`` passes a FILTRE test."""
    present = [r for r in rows if r.get(name) is not None]
    if crit_comp == "VIDE":
        return [r for r in rows if r.get(name) is None]
    if crit_comp == "NON_VIDE":
        return present
    if crit_comp in ("MAXI", "MAXI_ABS", "MINI", "MINI_ABS"):
        if not present:
            return []
        measure = abs if crit_comp.endswith("_ABS") else (lambda v: v)
        pick = max if crit_comp.startswith("MAXI") else min
        target = pick(measure(r[name]) for r in present)
        return [r for r in present if measure(r[name]) == target]
    values = value if isinstance(value, list | tuple) else (value,)
    if crit_comp == "INTERVALLE":
        low, high = values[0], values[-1]
        return [r for r in present if low <= r[name] <= high]
    if crit_comp == "REGEXP":
        pattern = re.compile(str(values[0]))
        return [r for r in present if pattern.search(str(r[name]))]
    if crit_comp in ("EQ", "NE"):
        base = _base_type(type_code)

        def equal(v):
            if base == "K":
                return any(str(v).strip() == str(ref).strip() for ref in values)
            if base == "I" and all(isinstance(ref, int | np.integer) for ref in values):
                return any(int(v) == int(ref) for ref in values)
            return any(close_to(v, ref, precision, criterion) for ref in values)

        keep = (lambda v: equal(v)) if crit_comp == "EQ" else (lambda v: not equal(v))
        return [r for r in present if keep(r[name])]
    compare = {
        "GT": lambda v, ref: v > ref,
        "GE": lambda v, ref: v >= ref,
        "LT": lambda v, ref: v < ref,
        "LE": lambda v, ref: v <= ref,
    }.get(crit_comp)
    if compare is None:
        raise CommandError(f"CRIT_COMP={crit_comp!r} is not supported")
    return [r for r in present if compare(r[name], values[0])]


class TableColumn(list):
    """``tab.PARA`` of an extracted table: the column's values, None where a
    row lacks the parameter, with code_aster's Colonne methods ``values()``
    and ``not_none_values()``."""

    deck_methods = frozenset({"values", "not_none_values"})

    def values(self) -> list:
        return list(self)

    def not_none_values(self) -> list:
        return [value for value in self if value is not None]


class TableView:
    """What ``EXTR_TABLE()`` returns: code_aster's Python table object.

    ``rows`` (list of dicts), ``para`` (parameter names), ``type``,
    ``values()`` (dict parameter -> list of values, None where absent),
    ``view[param, i]`` (1-based row), ``view[param]`` (a column as list),
    ``len(view)``.
    """

    def __init__(self, table: Table):
        self.rows = [dict(r) for r in table.rows]
        self.para = list(table.columns)
        self.type = [table.types[c] for c in table.columns]
        self.titr = table.title
        self._table = table

    def values(self) -> dict[str, list]:
        return {p: [r.get(p) for r in self.rows] for p in self.para}

    def __len__(self) -> int:
        return len(self.rows)

    def __iter__(self):
        return iter(self.rows)

    def Array(self, para: str, champ: str) -> np.ndarray:  # noqa: N802 - code_aster's name
        """code_aster's Table.Array: the rows' (para, champ) values as an
        (n_rows, 2) float array, in row order."""
        for name in (para, champ):
            if name not in self.para:
                raise CommandError(
                    f"the extracted table has no parameter {name!r} (it has {', '.join(self.para)})"
                )
        return np.array([[r.get(para), r.get(champ)] for r in self.rows], dtype=float).reshape(
            -1, 2
        )

    def deck_getattr(self, name: str):
        """``tab.PARA``: the column of a parameter (code_aster's Colonne, here
        the list of its values: len(), iteration, indexing, ``values()``); ``tab.Array``
        and ``tab.values`` are code_aster's methods of those names."""
        if name == "Array":
            return self.Array
        if name == "values" and name not in self.para:
            return self.values
        if name in self.para:
            return TableColumn(self._table.column(name))
        raise CommandError(
            f"the extracted table has no parameter {name!r} (it has {', '.join(self.para)})"
        )

    def __getitem__(self, key):
        if isinstance(key, tuple) and len(key) == 2:
            return self._table.value(key[0], int(key[1]))
        if isinstance(key, str):
            return self._table.column(key)
        if isinstance(key, int):
            return self.rows[key]
        raise CommandError("an extracted table is indexed as tab['PARAMETER', row_number]")


@dataclass
class TableNotComputed:
    """A table a command could produce but asterlite computes only on demand,
    and cannot compute yet: reading it (RECU_TABLE) is refused, naming the
    keyword that asked for it. Until then nothing the deck uses differs."""

    reason: str
    location: Any = None
    path: str = ""
