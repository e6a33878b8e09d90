"""Seismic loads (CALC_CHAR_SEISME).

Mono-support: the structure's relative motion under a support acceleration
γ(t)·d is driven by -M Δ_d γ(t), with Δ_d the rigid-body field that is d_i on
every DOF of component i (DX, DY, DZ, DRX, DRY, DRZ for a 6-component
direction). code_aster keeps the value on blocked DOFs too.

Multi-support: the load of the absolute formulation for the supports S moving
along d is -M Σ_{s in S} Σ_i d_i ψ_(s, i), with ψ_(s, i) the static mode of a
unit displacement of component i at node s (MODE_STATIQUE/MODE_STAT); code_aster
then zeroes it on the blocked DOFs.

In both cases the direction is normalised to unit length first.
"""

from __future__ import annotations

import numpy as np

COMPONENTS = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")


class SeismicError(ValueError):
    pass


def unit_direction(direction) -> np.ndarray:
    d = np.asarray(direction, dtype=float).ravel()
    if d.size not in (3, 6):
        raise SeismicError("DIRECTION must have 3 or 6 components")
    norm = float(np.linalg.norm(d))
    if norm == 0.0:
        raise SeismicError("DIRECTION is the zero vector")
    return d / norm


def rigid_field(components, direction) -> np.ndarray:
    """Δ_d: d_i on every DOF of component COMPONENTS[i], zero elsewhere."""
    d = unit_direction(direction)
    comps = np.asarray(components, dtype=object)
    field = np.zeros(len(comps))
    for name, value in zip(COMPONENTS, d, strict=False):
        field[comps == name] = value
    return field


def mono_support_load(mass, components, direction) -> np.ndarray:
    """-M Δ_d."""
    return -(mass @ rigid_field(components, direction))


def multi_support_load(mass, static_shapes: np.ndarray, weights, blocked_rows) -> np.ndarray:
    """-M Σ_k w_k ψ_k, zeroed on ``blocked_rows``.

    ``static_shapes`` (n_dofs, k) are the static modes of the moving support
    DOFs and ``weights`` the matching direction components."""
    combined = np.asarray(static_shapes, dtype=float) @ np.asarray(weights, dtype=float)
    load = -(mass @ combined)
    load = np.asarray(load, dtype=float).ravel()
    load[np.asarray(list(blocked_rows), dtype=int)] = 0.0
    return load


def static_mode_columns(labels, node_names, components, direction):
    """(columns, weights, missing) of the static modes ``"NODE CMP"`` needed by
    a multi-support load: one per node and non-zero direction component."""
    d = unit_direction(direction)
    where = {label: j for j, label in enumerate(labels)}
    columns, weights, missing = [], [], []
    for i, value in enumerate(d):
        if abs(value) <= np.finfo(float).eps:
            continue
        for name in node_names:
            label = f"{name} {components[i]}"
            if label in where:
                columns.append(where[label])
                weights.append(value)
            else:
                missing.append(label)
    return columns, weights, missing


def combined_static_shape(modes, node_names, direction) -> np.ndarray:
    """Σ_s Σ_i d_i ψ_(s, i) on ``modes.numbering``: the displacement field
    produced by a unit motion of the supports ``node_names`` along the
    (normalised) ``direction`` -- what DYNA_VIBRA MULT_APPUI adds to Φ q
    (times the support displacement, velocity or acceleration) to restore
    absolute fields. Raises SeismicError naming a missing static mode."""
    columns, weights, missing = static_mode_columns(
        modes.mode_labels, list(node_names), COMPONENTS, direction
    )
    if missing:
        raise SeismicError(f"no static mode for {', '.join(missing[:4])}")
    return np.asarray(modes.shapes, dtype=float)[:, columns] @ np.asarray(weights, dtype=float)
