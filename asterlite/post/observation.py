"""What OBSERVATION computes on a field, independently of keywords.

An :class:`ObservedField` is a nodal field at several states (orders): values
(n_states, n_nodes, n_components) on ``nodes`` with ``defined`` telling which
(node, component) pairs exist, as code_aster's simple nodal fields
(``cham_no_s``) do. A displacement-like field on a DOF numbering and a
``*_NOEU`` field both become one, go through the gauge average, the sensor
frames, the projection and the filter, and become a numbering or a
``*_NOEU`` field again.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.arrays import sorted_unique
from asterlite.concepts.assembly import DofNumbering, NodalComponentField
from asterlite.fem.dofs import sort_components
from asterlite.fem.frames import rotation_from_angles

_TENSOR_PAIRS = ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))


@dataclass
class ObservedField:
    nodes: np.ndarray  # (n_nodes,) mesh node indices, increasing
    components: tuple[str, ...]
    values: np.ndarray  # (n_states, n_nodes, n_components)
    defined: np.ndarray  # (n_nodes, n_components) bool

    @classmethod
    def from_dofs(cls, numbering: DofNumbering, values: np.ndarray) -> ObservedField:
        """A field on ``numbering``'s DOFs, values (n_states, n_dofs)."""
        nodes = sorted_unique(np.asarray([n for n, _ in numbering.dofs], dtype=int))
        components = tuple(sort_components({c for _, c in numbering.dofs}))
        row = {int(n): i for i, n in enumerate(nodes)}
        column = {c: j for j, c in enumerate(components)}
        rows = np.array([row[n] for n, _ in numbering.dofs], dtype=int)
        columns = np.array([column[c] for _, c in numbering.dofs], dtype=int)
        values = np.asarray(values)
        out = np.zeros((values.shape[0], nodes.size, len(components)), dtype=values.dtype)
        out[:, rows, columns] = values
        defined = np.zeros((nodes.size, len(components)), dtype=bool)
        defined[rows, columns] = True
        return cls(nodes, components, out, defined)

    @classmethod
    def from_node_field(cls, field: NodalComponentField, states) -> ObservedField:
        defined = getattr(field, "defined", None)
        if defined is None:
            defined = np.ones((len(field.nodes), len(field.components)), dtype=bool)
        return cls(
            np.asarray(field.nodes, dtype=int),
            tuple(field.components),
            np.asarray(field.values)[states].copy(),
            np.asarray(defined, dtype=bool).copy(),
        )

    def dofs(self) -> list[tuple[int, str]]:
        """The defined (node, component) pairs, node by node."""
        rows, columns = np.nonzero(self.defined)
        return [
            (int(self.nodes[r]), self.components[c]) for r, c in zip(rows, columns, strict=True)
        ]

    def dof_values(self) -> np.ndarray:
        """(n_states, n_dofs) values in the order of :meth:`dofs`."""
        rows, columns = np.nonzero(self.defined)
        return self.values[:, rows, columns]

    def node_field(self, name: str) -> NodalComponentField:
        defined = None if self.defined.all() else self.defined.copy()
        return NodalComponentField(
            name, self.nodes.copy(), self.components, self.values.copy(), defined
        )

    def rows_of(self, nodes) -> np.ndarray:
        """Rows of the given mesh nodes that the field holds."""
        return np.nonzero(np.isin(self.nodes, np.asarray(nodes, dtype=int)))[0]


# ---------------------------------------------------------------- gauges


@dataclass(frozen=True)
class GaugeVariation:
    """A component varying over a gauge more than SEUIL_VARI allows."""

    state: int
    component: str


def gauge_average(
    field: ObservedField, gauges: list[tuple[np.ndarray, float, tuple[str, ...]]]
) -> tuple[ObservedField, list[tuple[int, GaugeVariation]]]:
    """Each gauge's (nodes, threshold, masked components) mean strain set at
    every node of the gauge: the field the gauges see. Returns that field,
    defined on the gauges' nodes only (a later gauge wins on a shared node),
    and the (gauge index, variation) of each component whose values over a
    gauge stray from their mean by more than threshold x |mean| (real and
    imaginary parts apart), unless masked."""
    row_of = {int(n): i for i, n in enumerate(field.nodes)}
    states, _, n_cmp = field.values.shape
    kept_nodes = sorted({int(n) for nodes, _, _ in gauges for n in nodes})
    out_row = {n: i for i, n in enumerate(kept_nodes)}
    values = np.zeros((states, len(kept_nodes), n_cmp), dtype=field.values.dtype)
    variations = []
    for index, (nodes, threshold, masked) in enumerate(gauges):
        missing = [int(n) for n in nodes if int(n) not in row_of]
        if missing:
            raise ValueError(f"node index {missing[0]} of gauge {index + 1} carries no strain")
        rows = [row_of[int(n)] for n in nodes]
        if not field.defined[rows].all():
            raise ValueError(f"a node of gauge {index + 1} lacks a strain component")
        sample = field.values[:, rows, :]  # (states, n, cmp)
        mean = sample.mean(axis=1)
        for part in (np.real, np.imag):
            spread = np.abs(part(sample) - part(mean)[:, None, :]).max(axis=1)
            over = spread > threshold * np.abs(part(mean))
            for state, column in zip(*np.nonzero(over), strict=True):
                name = field.components[column]
                if name not in masked:
                    variations.append((index, GaugeVariation(int(state), name)))
        values[:, [out_row[int(n)] for n in nodes], :] = mean[:, None, :]
    defined = np.ones((len(kept_nodes), n_cmp), dtype=bool)
    result = ObservedField(np.asarray(kept_nodes, dtype=int), field.components, values, defined)
    return result, sorted(set(variations), key=lambda v: (v[0], v[1].state, v[1].component))


# ---------------------------------------------------------------- frames


def gauge_axes(vect_x, vect_y) -> np.ndarray:
    """The global-to-local rotation of a gauge frame (code_aster's DIR_JAUGE):
    x along VECT_X and y in the plane (VECT_X, VECT_Y); with VECT_X alone, y
    is e_k x VECT_X for the global axis e_k giving the longest product (the
    first on ties); with VECT_Y alone, y is VECT_Y and x is e_k x VECT_Y
    chosen the same way; neither: the global frame."""
    if vect_x is None and vect_y is None:
        return np.eye(3)
    given = np.asarray(vect_x if vect_x is not None else vect_y, dtype=float)
    if vect_x is not None and vect_y is not None:
        x, y = given, np.asarray(vect_y, dtype=float)
    else:
        products = [np.cross(axis, given) for axis in np.eye(3)]
        other = products[int(np.argmax([np.linalg.norm(p) for p in products]))]
        x, y = (given, other) if vect_x is not None else (other, given)
    z = np.cross(x, y)
    if np.linalg.norm(z) == 0.0:
        raise ValueError("VECT_X and VECT_Y do not span a plane")
    # code_aster keeps the given vector's length: VECT_X as x, (x ^ y) ^ x as
    # y; or VECT_Y as y and y ^ (x ^ y) as x
    if vect_x is not None:
        return nautical_rotation(x, np.cross(z, x))
    return nautical_rotation(np.cross(y, z), y)


def normal_axes(normal, vect_x=None, vect_y=None) -> np.ndarray:
    """The rotation of a frame built on a surface normal (code_aster's
    REPERE='NORMALE'): x = VECT_X and y = normal ^ VECT_X, or y = VECT_Y and
    x = VECT_Y ^ normal."""
    n = np.asarray(normal, dtype=float)
    if vect_x is not None:
        x = np.asarray(vect_x, dtype=float)
        return nautical_rotation(x, np.cross(n, x))
    y = np.asarray(vect_y, dtype=float)
    return nautical_rotation(np.cross(y, n), y)


def nautical_rotation(x_axis, y_axis) -> np.ndarray:
    """The rotation of code_aster's nautical angles of a frame given by its x
    and y vectors, as its observation macro computes them: alpha and beta
    from x, the twist gamma from y against the horizontal normal of x. The
    vectors need not be unit nor orthogonal; as in code_aster the twist's
    sine carries the length of x."""
    x = np.asarray(x_axis, dtype=float)
    y = np.asarray(y_axis, dtype=float)
    horizontal = float(np.hypot(x[0], x[1]))
    alpha = float(np.arctan2(x[1], x[0])) if horizontal > 0.0 else 0.0
    beta = float(np.arctan2(-x[2], horizontal))
    across = np.array([-np.sin(alpha), np.cos(alpha), 0.0])
    gamma = float(np.arctan2(x @ np.cross(across, y), across @ y))
    return rotation_from_angles(np.array([alpha, beta, gamma]))


def rotate_vectors(field: ObservedField, rows: np.ndarray, names, axes: np.ndarray) -> None:
    """v' = P v at ``rows`` for the components ``names`` (2 or 3 of them);
    ``axes`` (len(rows), 3, 3). Two components use the frame's plane block."""
    columns = _columns(field, rows, names)
    size = len(columns)
    block = field.values[:, rows][:, :, columns]
    rotated = np.einsum("pij,spj->spi", axes[:, :size, :size], block)
    _store(field, rows, columns, rotated)


def rotate_tensors(field: ObservedField, rows: np.ndarray, names, axes: np.ndarray) -> None:
    """S' = P S P^T at ``rows``; ``names`` are xx yy zz xy xz yz (six) or
    xx yy zz xy (four: the plane block, zz unchanged)."""
    columns = _columns(field, rows, names)
    block = field.values[:, rows][:, :, columns]
    full = np.zeros(block.shape[:2] + (3, 3), dtype=block.dtype)
    pairs = _TENSOR_PAIRS[: len(columns)]
    for k, (i, j) in enumerate(pairs):
        full[..., i, j] = full[..., j, i] = block[..., k]
    turned = np.einsum("pai,spij,pbj->spab", axes, full, axes)
    rotated = np.stack([turned[..., i, j] for i, j in pairs], axis=-1)
    _store(field, rows, columns, rotated)


def plane_rotation(axes: np.ndarray) -> bool:
    """Whether every frame turns about Z only (a 2D field can follow it)."""
    return bool(np.allclose(np.abs(axes[:, 2, 2]), 1.0, rtol=0.0, atol=1e-12))


def _columns(field, rows, names) -> list[int]:
    missing = [n for n in names if n not in field.components]
    if missing:
        raise ValueError(f"the field has no component {missing[0]}")
    columns = [field.components.index(n) for n in names]
    if not field.defined[np.ix_(rows, columns)].all():
        raise ValueError(f"a node to turn lacks one of the components {', '.join(names)}")
    return columns


def _store(field, rows, columns, rotated) -> None:
    for k, column in enumerate(columns):
        field.values[:, rows, column] = rotated[..., k]


# ---------------------------------------------------------------- projection


def project(field: ObservedField, placement, targets: np.ndarray) -> ObservedField:
    """The field at the ``targets`` nodes placed in cells of its mesh
    (``placement.nodes[target] = (cell nodes, weights)``), as code_aster's
    cnsprj interpolates a field that may lack values: with every cell node
    holding the component, the interpolation; with some, the weights > 0 of
    those renormalised; with only zero or negative weights among them, their
    mean. A target whose cell holds no value of a component lacks it."""
    row_of = {int(n): i for i, n in enumerate(field.nodes)}
    targets = np.asarray(targets, dtype=int)
    states = field.values.shape[0]
    n_cmp = len(field.components)
    values = np.zeros((states, targets.size, n_cmp), dtype=field.values.dtype)
    defined = np.zeros((targets.size, n_cmp), dtype=bool)
    for t, node in enumerate(targets):
        where = placement.nodes.get(int(node))
        if where is None:
            continue
        conn, weights = where
        rows = np.array([row_of.get(int(n), -1) for n in conn])
        weights = np.asarray(weights, dtype=float)
        for c in range(n_cmp):
            holds = rows >= 0
            holds[holds] = field.defined[rows[holds], c]
            if not holds.any():
                continue
            defined[t, c] = True
            if holds.all():
                values[:, t, c] = field.values[:, rows, c] @ weights
                continue
            positive = holds & (weights > 0.0)
            if positive.any():
                w = weights[positive]
                values[:, t, c] = field.values[:, rows[positive], c] @ w / w.sum()
            else:
                values[:, t, c] = field.values[:, rows[holds], c].mean(axis=1)
    return ObservedField(targets.copy(), field.components, values, defined)


# ---------------------------------------------------------------- filter


def keep(field: ObservedField, chosen: list[tuple[np.ndarray, tuple[str, ...]]]) -> ObservedField:
    """The field reduced to the union of (nodes, components) choices: the
    nodes and components chosen that the field holds (CREA_CHAMP ASSE)."""
    mask = np.zeros_like(field.defined)
    for nodes, names in chosen:
        rows = field.rows_of(nodes)
        columns = [field.components.index(n) for n in names if n in field.components]
        mask[np.ix_(rows, columns)] = True
    mask &= field.defined
    rows = np.nonzero(mask.any(axis=1))[0]
    columns = np.nonzero(mask.any(axis=0))[0]
    return ObservedField(
        field.nodes[rows],
        tuple(field.components[c] for c in columns),
        field.values[:, rows][:, :, columns],
        mask[np.ix_(rows, columns)],
    )
