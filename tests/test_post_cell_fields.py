"""code_aster 17's object API on element fields (asterlite.post.cell_fields):
a FieldOnCells of one order, its SimpleFieldOnCells, and
computeMaxResultantForPipe against the rule of code_aster's
PostProcessing.cxx written out point by point."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from asterlite.concepts.assembly import ElementField
from asterlite.errors import CommandError
from asterlite.post.cell_fields import max_resultant_for_pipe, result_cell_field

COMPONENTS = ("N", "VY", "VZ", "MT", "MFY", "MFZ")


def result_with_field():
    rng = np.random.default_rng(7)
    values = rng.normal(size=(4, 2, 2, 6))
    values[:, 1, 1, :] = np.nan  # cell 5 is a point cell: one ELNO point
    values[2] = np.nan  # an order where the field is not stored
    field = ElementField("EFGE_ELNO", np.array([3, 5]), COMPONENTS, values)
    return SimpleNamespace(name="R", element_fields={"EFGE_ELNO": field}), values


def test_simple_field_on_cells_reads_and_writes_the_cells_points():
    result, values = result_with_field()
    field = result_cell_field(result, "EFGE_ELNO", 1).toSimpleFieldOnCells()
    assert [field.getNumberOfPointsOfCell(c) for c in (3, 5, 4)] == [2, 1, 0]
    assert field.getNumberOfSubPointsOfCell(4) == 0
    assert field.getValue(5, 2, 0, 0) == values[1, 1, 0, 2]
    with pytest.raises(CommandError):
        field.getValue(5, 2, 1, 0)  # no second point on the point cell
    field.setValue(3, 4, 1, 0, 9.5)
    assert field.getValue(3, 4, 1, 0) == 9.5
    assert len(field.toFieldOnCells(None, "EFGE_ELNO", "PEFFORR").getValues()) == 3 * 6


def test_max_resultant_for_pipe_is_code_aster_rule():
    result, values = result_with_field()
    out = max_resultant_for_pipe(result, "EFGE_ELNO").toSimpleFieldOnCells()
    stored = [0, 1, 3]
    for row, cell in enumerate((3, 5)):
        for point in range(2 if cell == 3 else 1):
            history = values[stored, row, point]
            for k in range(3):
                assert out.getValue(cell, k, point, 0) == np.abs(history[:, k]).max()
            best = int(np.argmax(np.linalg.norm(history[:, 3:], axis=1)))
            for k in range(3, 6):
                assert out.getValue(cell, k, point, 0) == abs(history[best, k])
    with pytest.raises(CommandError):
        max_resultant_for_pipe(result, "SIEF_ELNO")


def test_indexes_for_field_name_are_the_orders_storing_it():
    """``getIndexesForFieldName``: every order for a nodal field, the orders
    CALC_CHAMP computed for an element field, none for an absent field."""
    from asterlite.post.deck_api import field_indexes

    result, _ = result_with_field()
    result.getIndexes = lambda: [10, 20, 30, 40]
    result.fields = {"DEPL": np.zeros((4, 3)), "VITE": np.zeros((4, 3))}
    assert field_indexes(result, "EFGE_ELNO") == [10, 20, 40]
    assert field_indexes(result, " vite ") == [10, 20, 30, 40]
    assert field_indexes(result, "SIEF_ELNO") == []
    # a modal basis: its shapes are the DEPL of every mode
    modes = SimpleNamespace(getIndexes=lambda: [1, 2], element_fields={})
    assert field_indexes(modes, "DEPL") == [1, 2]
    assert field_indexes(modes, "VITE") == []
