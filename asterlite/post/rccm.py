"""RCC-M piping rule B3600: the equivalent moment of beam cells.

``POST_RCCM`` with ``OPTION='MOMENT_EQUIVALENT'`` reads the generalised
forces by element node (``EFGE_ELNO``: N VY VZ MT MFY MFZ) and works with
the moments only: MT, MFY, MFZ and the equivalent moment
``MEQ = sqrt(MT² + MFY² + MFZ²)``. Over several instants each of the four
components keeps its own largest magnitude (so MT, MFY and MFZ of a row
may come from different instants), as code_aster's ``MAXI_ABS`` selection
with absolute values does.

The table has one row per (cell, node of the cell), cells in mesh order,
cells and nodes named by their 1-based numbers (code_aster 17).
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.table import Table

MOMENT_COMPONENTS = ("MT", "MFY", "MFZ")
MOMEQ_COMPONENTS = MOMENT_COMPONENTS + ("MEQ",)


def moment_components(values: np.ndarray, components) -> np.ndarray:
    """MT, MFY, MFZ (last axis) picked from an EFGE field's values."""
    missing = [c for c in MOMENT_COMPONENTS if c not in components]
    if missing:
        raise ValueError(
            f"the field has no component {missing[0]} (it has {', '.join(components)})"
        )
    index = [list(components).index(c) for c in MOMENT_COMPONENTS]
    return np.asarray(values, dtype=float)[..., index]


def equivalent_moment(moments: np.ndarray) -> np.ndarray:
    """MT, MFY, MFZ followed by MEQ = sqrt(MT² + MFY² + MFZ²) on the last axis."""
    meq = np.sqrt(np.sum(moments * moments, axis=-1, keepdims=True))
    return np.concatenate([moments, meq], axis=-1)


def max_magnitude(values: np.ndarray, axis: int = 0) -> np.ndarray:
    """The largest absolute value along ``axis`` (the instants), component by component."""
    return np.max(np.abs(values), axis=axis)


def moment_equivalent_values(values: np.ndarray, components, orders) -> np.ndarray:
    """(n_cells, n_points, 4) MT MFY MFZ MEQ: the maxima of their magnitudes
    over the selected orders (row indices of ``values``, (n_orders, n_cells,
    n_points, n_cmp))."""
    picked = np.asarray(values, dtype=float)[np.asarray(orders, dtype=int)]
    return max_magnitude(equivalent_moment(moment_components(picked, components)))


def moment_equivalent_table(
    values: np.ndarray, cells, cell_nodes, result_name: str, field_name: str
) -> Table:
    """POST_RCCM's table: RESULTAT, NOM_CHAM, MAILLE, NOEUD, MT, MFY, MFZ, MEQ
    for (n_cells, n_points, 4) ``values`` on ``cells`` whose nodes are
    ``cell_nodes`` (connectivity, one tuple per cell)."""
    table = Table()
    for name, code in (("RESULTAT", "K8"), ("NOM_CHAM", "K16"), ("MAILLE", "K8"), ("NOEUD", "K8")):
        table.add_column(name, code)
    for name in MOMEQ_COMPONENTS:
        table.add_column(name, "R")
    for row, cell in enumerate(cells):
        for point, node in enumerate(cell_nodes[row][: values.shape[1]]):
            line = {
                "RESULTAT": result_name,
                "NOM_CHAM": field_name,
                "MAILLE": str(int(cell) + 1),
                "NOEUD": str(int(node) + 1),
            }
            line.update(zip(MOMEQ_COMPONENTS, map(float, values[row, point]), strict=True))
            table.add_row(line)
    return table
