"""RCC-M piping rule B3600: the equivalent moment of beam cells.

``POST_RCCM`` with ``OPTION='MOMENT_EQUIVALENT'`` reads the generalised
forces by element node (``EFGE_ELNO``: N VY VZ MT MFY MFZ) and works with
the moments only: MT, MFY, MFZ and the equivalent moment
``MEQ = sqrt(MT² + MFY² + MFZ²)``. Over several instants each of the four
components keeps its own value of largest magnitude, signed (so MT, MFY
and MFZ of a row may come from different instants), as code_aster's
``MAXI_ABS`` selection of values does.

The table has one row per (cell, node of the cell), cells in mesh order,
cells and nodes named by their 1-based numbers (code_aster 17), with the
node's curvilinear abscissa when the mesh has one (MODI_MAILLAGE ABSC_CURV).
A field given alone (CHAM_GD) is tabulated as it is, without maxima.
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
    """Along ``axis`` (the instants), component by component, the value of
    largest magnitude with its sign; the earliest wins a tie."""
    values = np.asarray(values, dtype=float)
    first = np.expand_dims(np.argmax(np.abs(values), axis=axis), axis)
    return np.take_along_axis(values, first, axis=axis).squeeze(axis)


def moment_equivalent_values(values: np.ndarray, components, orders) -> np.ndarray:
    """(n_cells, n_points, 4) MT MFY MFZ MEQ: the maxima of their magnitudes
    over the selected orders (row indices of ``values``, (n_orders, n_cells,
    n_points, n_cmp))."""
    picked = np.asarray(values, dtype=float)[np.asarray(orders, dtype=int)]
    return max_magnitude(equivalent_moment(moment_components(picked, components)))


def moment_equivalent_table(
    values: np.ndarray, cells, cell_nodes, head: dict, abscissa: dict | None
) -> Table:
    """POST_RCCM's table for (n_cells, n_points, 4) ``values`` on ``cells``
    whose nodes are ``cell_nodes`` (connectivity, one tuple per cell):
    ``head`` (RESULTAT and NOM_CHAM, or CHAM_GD), MAILLE, NOEUD, ABSC_CURV,
    MT, MFY, MFZ, MEQ. ABSC_CURV is the node's curvilinear abscissa from the
    mesh's carte ``abscissa`` (cell -> ABSC1...); without a carte there is
    no such column, and a cell the carte misses has it empty."""
    table = Table()
    for name in head:
        table.add_column(name, "K16" if name == "NOM_CHAM" else "K8")
    table.add_column("MAILLE", "K8")
    table.add_column("NOEUD", "K8")
    if abscissa is not None:
        table.add_column("ABSC_CURV", "R")
    for name in MOMEQ_COMPONENTS:
        table.add_column(name, "R")
    labels, nodes, along_cells, picked = [], [], [], []
    for row, cell in enumerate(cells):
        along = () if abscissa is None else abscissa.get(int(cell), ())
        label = str(int(cell) + 1)
        for point, node in enumerate(cell_nodes[row][: values.shape[1]]):
            labels.append(label)
            nodes.append(str(int(node) + 1))
            along_cells.append(float(along[point]) if point < len(along) else None)
            picked.append((row, point))
    data = {**head, "MAILLE": labels, "NOEUD": nodes}
    if abscissa is not None:
        data["ABSC_CURV"] = along_cells
    where = np.array(picked, dtype=np.intp).reshape(-1, 2)
    moments = np.asarray(values, dtype=float)[where[:, 0], where[:, 1]]
    for c, name in enumerate(MOMEQ_COMPONENTS):
        data[name] = moments[:, c]
    table.extend(len(labels), data)
    return table
