"""Tables (``table_sdaster``): named, typed columns, sparse cells.

Owner: post-processing. A table keeps its parameters (columns) in order with
code_aster's type codes (``R``, ``I``, ``C``, ``K8``, ``K16``, ``K24``...) and
its cells column by column: reals and integers in typed arrays (8 bytes a
cell, plus one byte saying whether the cell is present), complexes and texts
in lists; a row may lack some parameters (code_aster tables are sparse, e.g.
POST_DYNA_MODA_T mixes IMPACT, GLOBAL and PROBA rows). Rows as dicts are
built only when a reader asks for them (``row(i)``, ``iter_rows()``,
``rows``: a fresh list, which changing does not change the table).

Build one with ``Table()`` then ``add_row({...})`` (types are inferred for new
parameters unless given with ``add_column``), or many rows at once with
``extend``. Filter with ``filtered(...)`` (FILTRE semantics), project with
``select(params)``, sort with ``sorted_by``, pick rows with ``take``.
"""

from __future__ import annotations

import re
from array import array
from dataclasses import dataclass
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
    return COERCIONS.get(type_code, str)(value)


# _coerce by type code: integers, reals, complexes; text otherwise (K8, K16...)
COERCIONS = {"I": int, "R": float, "C": complex}

# the typed storage of a column by type code (array's code, numpy's dtype)
TYPED = {"R": ("d", np.float64), "I": ("q", np.int64)}


def close_to(value: Any, reference: Any, precision: float, criterion: str) -> bool:
    """|value - reference| within PRECISION (RELATIF: scaled by |reference|,
    absolute when the reference is zero)."""
    diff = abs(value - reference)
    if criterion == "RELATIF" and reference != 0:
        return diff <= precision * abs(reference)
    return diff <= precision


class Column:
    """The cells of one parameter. Reals and integers: an ``array`` of the
    values (0 where absent) and a ``bytearray`` of presence flags; other
    types (and integers past 64 bits): a list holding None where absent.
    Cells are stored coerced to the column's type (``COERCIONS``)."""

    __slots__ = ("code", "data", "present")

    def __init__(self, code: str, absent: int = 0):
        self.code = code
        typed = TYPED.get(code)
        if typed is None:
            self.data: Any = [None] * absent
            self.present: bytearray | None = None
        else:
            self.data = array(typed[0], bytes(8 * absent))
            self.present = bytearray(absent)

    def __len__(self) -> int:
        return len(self.data)

    def _as_list(self) -> None:
        """Leave typed storage (an integer past 64 bits)."""
        self.data = self.values()
        self.present = None

    def append(self, value: Any) -> None:
        """One cell, already coerced (None: absent)."""
        if self.present is None:
            self.data.append(value)
        elif value is None:
            self.data.append(0)
            self.present.append(0)
        else:
            try:
                self.data.append(value)
            except OverflowError:
                self._as_list()
                self.data.append(value)
                return
            self.present.append(1)

    def extend(self, values, present=None) -> None:
        """Cells of ``values`` (a numpy array or a list, coerced), absent
        where ``present`` (booleans) is False."""
        count = len(values)
        if self.present is not None:
            dtype = TYPED[self.code][1]
            try:
                block = np.asarray(values, dtype=dtype)
            except OverflowError:
                self._as_list()
                block = None
            if block is not None:
                if present is not None:
                    block = np.where(present, block, 0).astype(dtype, copy=False)
                    flags = np.asarray(present, dtype=np.uint8)
                else:
                    flags = np.ones(count, dtype=np.uint8)
                self.data.frombytes(np.ascontiguousarray(block).tobytes())
                self.present.extend(flags.tobytes())
                return
        if present is None:
            self.data.extend(values)
        else:
            self.data.extend(v if p else None for v, p in zip(values, present, strict=True))

    def get(self, index: int) -> Any:
        if self.present is None or self.present[index]:
            return self.data[index]
        return None

    def set(self, index: int, value: Any) -> None:
        """Replace one cell (value coerced, None: absent)."""
        if self.present is None:
            self.data[index] = value
        elif value is None:
            self.data[index] = 0
            self.present[index] = 0
        else:
            try:
                self.data[index] = value
            except OverflowError:
                self._as_list()
                self.data[index] = value
                return
            self.present[index] = 1

    def values(self) -> list:
        """Every cell, None where absent (Python int / float / str...)."""
        if self.present is None:
            return list(self.data)
        values = self.data.tolist()
        if all(self.present):
            return values
        return [v if p else None for v, p in zip(values, self.present, strict=True)]

    def present_mask(self) -> np.ndarray:
        if self.present is None:
            return np.array([v is not None for v in self.data], dtype=bool)
        return np.frombuffer(bytes(self.present), dtype=np.uint8).astype(bool)

    def take(self, indices) -> Column:
        """A new column of the cells at ``indices`` (in that order)."""
        out = Column.__new__(Column)
        out.code = self.code
        indices = np.asarray(indices, dtype=np.intp)
        if self.present is None:
            data = self.data
            out.data = [data[i] for i in indices.tolist()]
            out.present = None
            return out
        kind, dtype = TYPED[self.code]
        values = np.frombuffer(self.data, dtype=dtype) if len(self.data) else np.zeros(0, dtype)
        flags = np.frombuffer(bytes(self.present), dtype=np.uint8)
        out.data = array(kind, values[indices].tobytes())
        out.present = bytearray(flags[indices].tobytes())
        return out

    def copy(self) -> Column:
        out = Column.__new__(Column)
        out.code = self.code
        out.data = self.data[:]
        out.present = None if self.present is None else bytearray(self.present)
        return out


class Table(Concept):
    """An ordered set of typed columns holding sparse rows."""

    aster_types = ("table_sdaster", "table_fonction", "table_container")
    deck_methods = frozenset({"getName", "EXTR_TABLE", "get_nom_para", "getParameters"})

    def __init__(
        self,
        columns: list[str] | None = None,
        types: dict[str, str] | None = None,
        rows: list[dict[str, Any]] | None = None,
        title: str = "",
        name: str | None = None,
    ):
        self.name = name
        self.title = title
        self.columns: list[str] = []
        self.types: dict[str, str] = {}
        self._cells: dict[str, Column] = {}
        self._count = 0
        types = types or {}
        for column in columns or ():
            self.add_column(column, types[column])
        for row in rows or ():
            self.add_row(row)

    def __repr__(self) -> str:
        return (
            f"Table(columns={self.columns!r}, types={self.types!r}, rows={self.rows!r}, "
            f"title={self.title!r})"
        )

    def printed_fields(self) -> dict[str, Any]:
        """What IMPR_CO shows of a table (its parameters, types, rows, title)."""
        return {
            "columns": self.columns,
            "types": self.types,
            "rows": self.rows,
            "title": self.title,
        }

    # building -----------------------------------------------------------
    def add_column(self, name: str, type_code: str) -> None:
        if name not in self.types:
            self.columns.append(name)
            self.types[name] = type_code
            self._cells[name] = Column(type_code, self._count)

    def add_row(self, values: dict[str, Any], types: dict[str, str] | None = None) -> None:
        known = self.types
        row = {}
        for name, value in values.items():
            if value is None:
                continue
            code = known.get(name)
            if code is None:
                self.add_column(name, (types or {}).get(name) or infer_type(value))
                code = known[name]
            row[name] = COERCIONS.get(code, str)(value)
        for name, column in self._cells.items():
            column.append(row.get(name))
        self._count += 1

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
        count = len(next(iter(columns.values())))
        cells: dict[str, Any] = {k: v for k, v in common.items() if v is not None}
        cells.update(columns)
        self.extend(count, cells)

    def extend(self, count: int, cells: dict[str, Any], nan_absent=()) -> None:
        """``count`` rows at once: ``cells[name]`` is one value for every row
        (a scalar; None leaves the cells empty) or a sequence (list, numpy
        array) of ``count`` values, None where a row lacks it; in the columns
        named in ``nan_absent``, a NaN leaves the cell empty too. Parameters
        not yet in the table are added with the type of their first value.
        The cells are those ``add_row`` of each row would store."""
        for name, values in cells.items():
            if name in self.types or values is None:
                continue
            if isinstance(values, list | tuple | np.ndarray):
                first = next((v for v in values if v is not None), None)
                if first is None:
                    continue
            else:
                first = values
            self.add_column(name, infer_type(first))
        for name, column in self._cells.items():
            values = cells.get(name)
            if values is None:
                column.extend([None] * count) if column.present is None else column.extend(
                    np.zeros(count), np.zeros(count, dtype=bool)
                )
                continue
            if not isinstance(values, list | tuple | np.ndarray):
                values = [values] * count
            if len(values) != count:
                raise ValueError(f"{len(values)} values of {name} for {count} rows")
            column.extend(*_coerced(values, column.code, name in nan_absent))
        self._count += count

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
        return self._count

    def column(self, name: str) -> list[Any]:
        """Values of one parameter, None where a row lacks it."""
        self.require(name)
        return self._cells[name].values()

    def nbytes(self) -> int:
        """Bytes of the cells' storage (typed columns: 8 a value and 1 a
        presence flag; list columns: 8 a reference, the objects apart)."""
        total = 0
        for column in self._cells.values():
            if column.present is None:
                total += 8 * len(column.data)
            else:
                total += column.data.itemsize * len(column.data) + len(column.present)
        return total

    def present(self, name: str) -> np.ndarray:
        """Whether each row holds the parameter (booleans)."""
        self.require(name)
        return self._cells[name].present_mask()

    def require(self, name: str) -> None:
        if name not in self.types:
            raise CommandError(
                f"table {self.name or ''} has no parameter {name!r} "
                f"(it has {', '.join(self.columns) or 'none'})"
            )

    def value(self, name: str, row: int) -> Any:
        """Value at (parameter, 1-based row number), as code_aster's tab[para, i]."""
        self.require(name)
        if not 1 <= row <= self._count:
            raise CommandError(f"table {self.name or ''} has {self._count} rows, not {row}")
        return self._cells[name].get(row - 1)

    def row(self, index: int) -> dict[str, Any]:
        """The 0-based row ``index`` as a dict of its present cells (a copy)."""
        if index < 0:
            index += self._count
        if not 0 <= index < self._count:
            raise IndexError(f"table row {index} out of {self._count}")
        cells = ((name, column.get(index)) for name, column in self._cells.items())
        return {name: value for name, value in cells if value is not None}

    def iter_rows(self, columns=None):
        """The rows as dicts of their present cells, one at a time (only
        ``columns`` when given)."""
        names = list(self.columns if columns is None else columns)
        if not names:
            for _ in range(self._count):
                yield {}
            return
        for cells in zip(*(self._cells[n].values() for n in names), strict=True):
            yield {n: v for n, v in zip(names, cells, strict=True) if v is not None}

    @property
    def rows(self) -> list[dict[str, Any]]:
        """Every row as a dict of its present cells: a fresh list (changing
        it leaves the table as it is; ``rows = [...]`` replaces the cells)."""
        return list(self.iter_rows())

    @rows.setter
    def rows(self, rows: list[dict[str, Any]]) -> None:
        self._cells = {name: Column(self.types[name]) for name in self.columns}
        self._count = 0
        for row in rows:
            self.add_row(row)

    def __getitem__(self, key):
        if isinstance(key, tuple) and len(key) == 2:
            return self.value(key[0], int(key[1]))
        raise CommandError("a table is indexed as TABLE['PARAMETER', row_number]")

    # changing in place --------------------------------------------------
    def set_cell(self, name: str, index: int, value: Any) -> None:
        """Replace the cell of parameter ``name`` in 0-based row ``index``
        (None empties it)."""
        self.require(name)
        self._cells[name].set(index, _coerce(value, self.types[name]))

    def rename_column(self, old: str, new: str) -> None:
        """Parameter ``old`` is called ``new`` (same place, type and cells)."""
        self.require(old)
        self.columns = [new if c == old else c for c in self.columns]
        self.types = {(new if c == old else c): t for c, t in self.types.items()}
        self._cells = {(new if c == old else c): v for c, v in self._cells.items()}

    def keep_rows(self, indices) -> None:
        """Keep only the rows at 0-based ``indices``, in that order."""
        taken = self.take(indices)
        self._cells, self._count = taken._cells, taken._count

    def assign(self, other: Table) -> None:
        """Become ``other`` (its parameters, cells and title; reuse=)."""
        self.columns, self.types = list(other.columns), dict(other.types)
        self._cells = {name: other._cells[name].copy() for name in other.columns}
        self._count = other._count
        self.title = other.title

    # transforming -------------------------------------------------------
    def copy(self) -> Table:
        out = Table(title=self.title)
        out.columns, out.types = list(self.columns), dict(self.types)
        out._cells = {name: column.copy() for name, column in self._cells.items()}
        out._count = self._count
        return out

    def take(self, indices, columns: list[str] | None = None) -> Table:
        """A new table of the rows at 0-based ``indices`` (in that order), of
        ``columns`` (all by default)."""
        columns = list(self.columns if columns is None else columns)
        indices = np.asarray(indices, dtype=np.intp).reshape(-1)
        out = Table(title=self.title)
        out.columns = columns
        out.types = {c: self.types[c] for c in columns}
        out._cells = {c: self._cells[c].take(indices) for c in columns}
        out._count = int(indices.size)
        return out

    def first_rows(self, count: int) -> Table:
        return self.take(np.arange(min(count, self._count)))

    def select(self, names) -> Table:
        """Only the given parameters (in that order); rows left empty are dropped."""
        for name in names:
            self.require(name)
        held = np.zeros(self._count, dtype=bool)
        for name in names:
            held |= self._cells[name].present_mask()
        return self.take(np.flatnonzero(held), list(names))

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
        kept = select_rows(
            self._cells[name].values(), self.types[name], crit_comp, value, precision, criterion
        )
        return self.take(kept)

    def sorted_by(self, names, descending: bool = False) -> Table:
        for name in names:
            self.require(name)
        columns = [self._cells[n].values() for n in names]

        def key(i):
            return tuple((c[i] is None, _sort_value(c[i])) for c in columns)

        return self.take(sorted(range(self._count), key=key, reverse=descending))

    # deck API -----------------------------------------------------------
    def EXTR_TABLE(self):  # noqa: N802
        return TableView(self)

    def get_nom_para(self):
        return list(self.columns)

    def getParameters(self):  # noqa: N802
        return list(self.columns)


def _coerced(values, code: str, nan_absent: bool):
    """(values, present or None) of a sequence for a column of type ``code``:
    the cells ``add_row`` would store."""
    typed = TYPED.get(code)
    if isinstance(values, np.ndarray) and typed is not None and values.dtype.kind in "fiub":
        if code == "I" and values.dtype.kind == "f":
            values = np.trunc(values)  # int() of a float
        present = ~np.isnan(values) if nan_absent and values.dtype.kind == "f" else None
        return values, present
    values = list(values)
    absent = [v is None or (nan_absent and v != v) for v in values]
    coerce = COERCIONS.get(code, str)
    cells = [None if a else coerce(v) for v, a in zip(values, absent, strict=True)]
    if not any(absent):
        return cells, None
    if typed is not None:
        cells = [0 if c is None else c for c in cells]
    return cells, [not a for a in absent]


def _base_type(type_code: str) -> str:
    return "K" if type_code.startswith("K") else type_code


def _sort_value(value):
    if isinstance(value, complex):
        return (abs(value), value.real)
    return value if value is not None else 0


def select_rows(cells, type_code, crit_comp, value, precision, criterion) -> list[int]:
    """The 0-based indices of the ``cells`` (a column's values, None where
    absent) that pass a FILTRE test, in order."""
    present = [i for i, v in enumerate(cells) if v is not None]
    if crit_comp == "VIDE":
        return [i for i, v in enumerate(cells) if v is None]
    if crit_comp == "NON_VIDE":
        return present
    if crit_comp in ("MAXI", "MAXI_ABS", "MINI", "MINI_ABS"):
        if not present:
            return []
        measure = abs if crit_comp.endswith("_ABS") else (lambda v: v)
        pick = max if crit_comp.startswith("MAXI") else min
        target = pick(measure(cells[i]) for i in present)
        return [i for i in present if measure(cells[i]) == target]
    values = value if isinstance(value, list | tuple) else (value,)
    if crit_comp == "INTERVALLE":
        low, high = values[0], values[-1]
        return [i for i in present if low <= cells[i] <= high]
    if crit_comp == "REGEXP":
        pattern = re.compile(str(values[0]))
        return [i for i in present if pattern.search(str(cells[i]))]
    if crit_comp in ("EQ", "NE"):
        base = _base_type(type_code)

        def equal(v):
            if base == "K":
                return any(str(v).strip() == str(ref).strip() for ref in values)
            if base == "I" and all(isinstance(ref, int | np.integer) for ref in values):
                return any(int(v) == int(ref) for ref in values)
            return any(close_to(v, ref, precision, criterion) for ref in values)

        wanted = crit_comp == "EQ"
        return [i for i in present if equal(cells[i]) == wanted]
    compare = {
        "GT": lambda v, ref: v > ref,
        "GE": lambda v, ref: v >= ref,
        "LT": lambda v, ref: v < ref,
        "LE": lambda v, ref: v <= ref,
    }.get(crit_comp)
    if compare is None:
        raise CommandError(f"CRIT_COMP={crit_comp!r} is not supported")
    return [i for i in present if compare(cells[i], values[0])]


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
    ``view[i]`` (a row), ``len(view)``. It reads the table's columns as they
    were at ``EXTR_TABLE`` (a copy sharing nothing the table changes later);
    rows are made as they are read.
    """

    def __init__(self, table: Table):
        self._table = table.copy()
        self._table.name = table.name
        self.para = list(table.columns)
        self.type = [table.types[c] for c in table.columns]
        self.titr = table.title

    @property
    def rows(self) -> list[dict]:
        return self._table.rows

    def values(self) -> dict[str, list]:
        return {p: self._table.column(p) for p in self.para}

    def __len__(self) -> int:
        return len(self._table)

    def __iter__(self):
        return self._table.iter_rows()

    def Array(self, para: str, champ: str) -> np.ndarray:  # noqa: N802 - code_aster's name
        """code_aster's Table.Array: the rows' (para, champ) values as an
        (n_rows, 2) float array, in row order."""
        for name in (para, champ):
            if name not in self.para:
                raise CommandError(
                    f"the extracted table has no parameter {name!r} (it has {', '.join(self.para)})"
                )
        pairs = zip(self._table.column(para), self._table.column(champ), strict=True)
        return np.array([[x, y] for x, y in pairs], dtype=float).reshape(-1, 2)

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
            return self._table.row(key)
        raise CommandError("an extracted table is indexed as tab['PARAMETER', row_number]")


@dataclass
class TableNotComputed:
    """A table a command could produce but asterlite computes only on demand,
    and cannot compute yet: reading it (RECU_TABLE) is refused, naming the
    keyword that asked for it. Until then nothing the deck uses differs."""

    reason: str
    location: Any = None
    path: str = ""
