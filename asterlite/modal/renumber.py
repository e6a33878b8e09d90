"""Moving fields and bases between DOF numberings of the same mesh.

code_aster's DEFI_BASE_MODALE (NUME_REF) and projections copy vectors from
one numbering to another by (node, component): DOFs the target lacks are
dropped, DOFs the source lacks are zero.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import DofNumbering


def same_dofs(a: DofNumbering, b: DofNumbering) -> bool:
    return a is b or a.dofs == b.dofs


def row_map(source: DofNumbering, target: DofNumbering) -> np.ndarray:
    """For each target DOF, its row in ``source`` (-1 when absent)."""
    return source.dof_indices(target.dof_nodes, target.dof_components)


def transfer(values: np.ndarray, source: DofNumbering, target: DofNumbering) -> np.ndarray:
    """``values`` (n_source, ...) expressed on ``target`` (n_target, ...);
    complex values stay complex."""
    values = np.asarray(values)
    values = values.astype(complex if np.iscomplexobj(values) else float, copy=False)
    if same_dofs(source, target):
        return values
    rows = row_map(source, target)
    out = np.zeros((target.n_dofs, *values.shape[1:]), dtype=values.dtype)
    present = rows >= 0
    out[present] = values[rows[present]]
    return out


def lost_rows(values: np.ndarray, source: DofNumbering, target: DofNumbering) -> np.ndarray:
    """Source rows that hold a non-zero value but have no DOF in ``target``."""
    values = np.asarray(values, dtype=float).reshape(source.n_dofs, -1)
    rows = target.dof_indices(source.dof_nodes, source.dof_components)
    return np.flatnonzero((rows < 0) & np.any(values != 0.0, axis=1))
