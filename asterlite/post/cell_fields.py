"""code_aster 17's object API on element fields (ELNO / ELGA) of a result:
``result.getField("EFGE_ELNO", 1)`` (a ``FieldOnCellsReal``),
``toSimpleFieldOnCells()`` with its per-cell getters and setters, and
``CA.PostProcessing(...).computeMaxResultantForPipe`` (code_aster's
PostProcessing.cxx): at each point of each cell, the largest |N|, |VY|,
|VZ| over the stored orders, and |MT|, |MFY|, |MFZ| at the order where the
moment's norm is largest.

A field's points are its cells' points: the padding of a field on cells of
several kinds (a point cell's second ELNO point) is no point of that cell.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from asterlite.errors import CommandError

PIPE_FIELDS = ("EFGE_ELNO", "EGRU_ELNO")


@dataclass(eq=False)
class FieldOnCells:
    """One order of an element field: ``values`` (n_cells, n_points, n_cmp)
    on ``cells``, NaN where a cell has no such point."""

    deck_methods: ClassVar[frozenset[str]] = frozenset(
        {"getValues", "toSimpleFieldOnCells", "getComponents", "size"}
    )

    name: str
    cells: np.ndarray
    components: tuple[str, ...]
    values: np.ndarray

    def _present(self) -> np.ndarray:
        return ~np.all(np.isnan(self.values), axis=2)

    def getValues(self) -> list[float]:  # noqa: N802 - code_aster's names
        """The values cell by cell, point by point, component by component."""
        return self.values[self._present()].ravel().tolist()

    def size(self) -> int:
        return int(self._present().sum()) * len(self.components)

    def getComponents(self) -> list[str]:  # noqa: N802
        return list(self.components)

    def toSimpleFieldOnCells(self) -> SimpleFieldOnCells:  # noqa: N802
        return SimpleFieldOnCells(self.name, self.cells, self.components, self.values.copy())


@dataclass(eq=False)
class SimpleFieldOnCells(FieldOnCells):
    """A field on cells to read and change point by point (one sub-point)."""

    deck_methods: ClassVar[frozenset[str]] = frozenset(
        {
            "getValues",
            "getComponents",
            "size",
            "getNumberOfPointsOfCell",
            "getNumberOfSubPointsOfCell",
            "getNumberOfComponents",
            "getValue",
            "setValue",
            "toFieldOnCells",
        }
    )

    def _row(self, cell) -> int | None:
        rows = np.flatnonzero(np.asarray(self.cells) == int(cell))
        return int(rows[0]) if rows.size else None

    def getNumberOfPointsOfCell(self, cell) -> int:  # noqa: N802
        row = self._row(cell)
        return 0 if row is None else int(self._present()[row].sum())

    def getNumberOfSubPointsOfCell(self, cell) -> int:  # noqa: N802
        return 0 if self._row(cell) is None else 1

    def getNumberOfComponents(self) -> int:  # noqa: N802
        return len(self.components)

    def _where(self, cell, component, point, sub_point) -> tuple[int, int, int]:
        row = self._row(cell)
        if row is None or not 0 <= int(point) < self.getNumberOfPointsOfCell(cell):
            raise CommandError(f"{self.name}: cell {cell} has no point {point}")
        if int(sub_point) != 0 or not 0 <= int(component) < len(self.components):
            raise CommandError(
                f"{self.name}: no component {component} or sub-point {sub_point} at cell {cell}"
            )
        return row, int(point), int(component)

    def getValue(self, cell, component, point, sub_point) -> float:  # noqa: N802
        row, point, component = self._where(cell, component, point, sub_point)
        value = float(self.values[row, point, component])
        if np.isnan(value):
            raise CommandError(f"{self.name}: no value at cell {cell}, point {point}")
        return value

    def setValue(self, cell, component, point, sub_point, value) -> None:  # noqa: N802
        row, point, component = self._where(cell, component, point, sub_point)
        self.values[row, point, component] = float(value)

    def toFieldOnCells(self, descriptor=None, option=None, parameter=None) -> FieldOnCells:  # noqa: N802
        # the descriptor and parameter name code_aster's storage only
        return FieldOnCells(option or self.name, self.cells, self.components, self.values.copy())


def result_cell_field(result, name: str, position: int) -> FieldOnCells:
    """The element field ``name`` of a result at one stored order (its row)."""
    field = (getattr(result, "element_fields", None) or {}).get(name)
    if field is None:
        raise CommandError(f"result {result.name or ''} has no element field {name}")
    if field.sub_points > 1:
        raise CommandError(f"{name} is on sub-points (multifibre beams): not available as a field")
    values = np.asarray(field.values)[position]
    if np.iscomplexobj(values):
        raise CommandError(f"{name} is complex: a FieldOnCellsReal holds real values")
    return FieldOnCells(name, np.asarray(field.cells), tuple(field.components), values.copy())


def max_resultant_for_pipe(result, name: str) -> FieldOnCells:
    """code_aster's computeMaxResultantForPipe (see the module docstring)."""
    name = str(name).strip()
    if name not in PIPE_FIELDS:
        raise CommandError(f"computeMaxResultantForPipe: {name!r} is not EFGE_ELNO or EGRU_ELNO")
    field = (getattr(result, "element_fields", None) or {}).get(name)
    if field is None:
        raise CommandError(f"computeMaxResultantForPipe: the result has no field {name}")
    values = np.asarray(field.values, dtype=float)  # (n_orders, n_cells, n_points, 6)
    stored = ~np.all(np.isnan(values), axis=(1, 2, 3))
    if not stored.any():
        raise CommandError(f"computeMaxResultantForPipe: {name} is stored at no order")
    values = values[stored]
    out = values[0].copy()
    forces = np.abs(values[..., :3])
    with np.errstate(invalid="ignore"):
        largest = np.where(np.isnan(forces), -1.0, forces).max(axis=0)
    found = largest >= 0.0
    # a point with any force found takes the three maxima (NaN for a missing one)
    maxima = np.where(found, largest, np.nan)
    out[..., :3] = np.where(found.any(axis=-1)[..., None], maxima, out[..., :3])
    moments = values[..., 3:6]
    norms = np.where(np.isnan(moments).any(axis=-1), -1.0, np.linalg.norm(moments, axis=-1))
    # the first order reaching the largest norm, as a strict > scan keeps it
    at = np.argmax(norms, axis=0)
    best = np.take_along_axis(norms, at[None], axis=0)[0]
    chosen = np.abs(np.take_along_axis(moments, at[None, ..., None], axis=0)[0])
    out[..., 3:6] = np.where((best >= 0.0)[..., None], chosen, out[..., 3:6])
    return FieldOnCells(name, np.asarray(field.cells), tuple(field.components), out)
