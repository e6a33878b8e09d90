"""Physical fields and histories from generalized and physical transient results.

Used by REST_GENE_PHYS, RECU_FONCTION, RECU_GENE and TEST_RESU: choosing the
instants (NUME_ORDRE / INST / LIST_INST, with or without interpolation),
choosing DOFs (GROUP_NO / NOEUD / GROUP_MA + NOM_CMP), and recombining modal
coordinates into physical values.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.concepts.assembly import ElementField
from asterlite.errors import CommandError, missing_name

FIELDS = ("DEPL", "VITE", "ACCE")


def as_tuple(value) -> tuple:
    """A keyword value as a tuple (scalar, tuple, list or None)."""
    if value is None:
        return ()
    if isinstance(value, tuple | list):
        return tuple(value)
    if isinstance(value, np.ndarray):
        return tuple(value.tolist())
    return (value,)


def values_of(value) -> np.ndarray:
    """Reals from a keyword value that may be a list concept (``.values``)."""
    if hasattr(value, "values") and isinstance(value.values, np.ndarray):
        return np.asarray(value.values, dtype=float)
    return np.asarray(as_tuple(value), dtype=float)


@dataclass
class InstantSelection:
    """Which states to produce: interpolation weights between archived states.

    Output state ``i`` is ``(1 - weight[i]) * state[lower[i]] + weight[i] *
    state[lower[i] + 1]`` (weight 0 picks an archived state exactly);
    ``times`` and ``order`` are those of the output.
    """

    lower: np.ndarray
    weight: np.ndarray
    times: np.ndarray
    order: np.ndarray
    # every archived state, in order: ``apply`` gives the states themselves
    whole: bool = False

    def apply(self, states: np.ndarray) -> np.ndarray:
        """Rows of ``states`` (n_archived, ...) at the selected instants: a
        new array, or for the whole archive a read-only view of ``states``
        (functions of a long transient share its archive, no copy)."""
        states = np.asarray(states)
        if self.whole and states.shape[0] == self.lower.size:
            return read_only(states)
        upper = np.minimum(self.lower + 1, states.shape[0] - 1)
        w = self.weight.reshape((-1,) + (1,) * (states.ndim - 1))
        picked = states[self.lower]  # indexing by an array copies
        if not np.any(self.weight):
            return picked
        return (1.0 - w) * picked + w * states[upper]


def read_only(values: np.ndarray) -> np.ndarray:
    """A view of ``values`` that cannot be written into (it is shared)."""
    view = values.view()
    view.flags.writeable = False
    return view


def nearest_archived(times, wanted, precision: float, criterion: str) -> np.ndarray:
    """Indices of the archived instants matching ``wanted`` within PRECISION
    (CRITERE RELATIF scales by |t|, absolute when t is zero); raises
    CommandError naming the first instant with no match."""
    times = np.asarray(times, dtype=float)
    wanted = np.atleast_1d(np.asarray(wanted, dtype=float))
    idx = np.clip(np.searchsorted(times, wanted), 0, times.size - 1)
    prev = np.maximum(idx - 1, 0)
    idx = np.where(np.abs(times[prev] - wanted) < np.abs(times[idx] - wanted), prev, idx)
    gap = np.abs(times[idx] - wanted)
    tolerance = np.where(
        (criterion == "RELATIF") & (wanted != 0), precision * np.abs(wanted), precision
    )
    missing = gap > tolerance
    if missing.any():
        t = wanted[missing][0]
        raise CommandError(
            f"no archived instant at {t:g} (PRECISION={precision:g}, CRITERE={criterion}); "
            f"archived instants run from {times[0]:g} to {times[-1]:g}"
        )
    return idx


def select_instants(
    times,
    order,
    *,
    nume_ordre=None,
    inst=None,
    interpolate: bool = False,
    precision: float = 1e-6,
    criterion: str = "RELATIF",
) -> InstantSelection:
    """States at the given NUME_ORDRE, or at the given instants (interpolated
    linearly when ``interpolate``), or every archived state."""
    times = np.asarray(times, dtype=float)
    order = np.asarray(order)
    if nume_ordre is not None and len(nume_ordre):
        wanted = np.asarray(nume_ordre, dtype=int)
        lookup = {int(o): i for i, o in enumerate(order)}
        absent = [int(n) for n in wanted if int(n) not in lookup]
        if absent:
            raise CommandError(
                f"NUME_ORDRE {absent[0]} is not archived (orders {order[0]}..{order[-1]})"
            )
        idx = np.array([lookup[int(n)] for n in wanted], dtype=int)
        return InstantSelection(idx, np.zeros(idx.size), times[idx], order[idx])
    if inst is not None:
        wanted = np.atleast_1d(np.asarray(inst, dtype=float))
        numbers = np.arange(1, wanted.size + 1)
        if not interpolate:
            idx = nearest_archived(times, wanted, precision, criterion)
            return InstantSelection(idx, np.zeros(idx.size), times[idx], numbers)
        return interpolation_weights(times, wanted, precision, numbers)
    idx = np.arange(times.size)
    return InstantSelection(idx, np.zeros(idx.size), read_only(times), read_only(order), True)


def interpolation_weights(times, wanted, precision, numbers) -> InstantSelection:
    """Linear interpolation between archived instants; instants outside the
    archive (beyond a relative PRECISION of the span) are an error."""
    span = max(times[-1] - times[0], abs(times[-1]), 1e-300)
    slack = max(precision, 1e-9) * span
    outside = (wanted < times[0] - slack) | (wanted > times[-1] + slack)
    if outside.any():
        raise CommandError(
            f"instant {wanted[outside][0]:g} is outside the archived range "
            f"[{times[0]:g}, {times[-1]:g}]"
        )
    clipped = np.clip(wanted, times[0], times[-1])
    if times.size == 1:
        return InstantSelection(np.zeros(wanted.size, int), np.zeros(wanted.size), wanted, numbers)
    lower = np.clip(np.searchsorted(times, clipped, side="right") - 1, 0, times.size - 2)
    weight = (clipped - times[lower]) / (times[lower + 1] - times[lower])
    # an instant on an archived one is taken exactly (no round-off mixing)
    weight = np.where(np.isclose(weight, 0.0, atol=1e-12), 0.0, weight)
    on_upper = np.isclose(weight, 1.0, rtol=0, atol=1e-12)
    lower = np.where(on_upper, lower + 1, lower)
    weight = np.where(on_upper, 0.0, weight)
    return InstantSelection(lower, weight, wanted.copy(), numbers)


def selection_from_keywords(ctx, kw, times, order, default_interpol: str = "NON"):
    """InstantSelection from the usual keywords (NUME_ORDRE, LIST_ORDRE,
    INST, LIST_INST, TOUT_ORDRE, TOUT_INST, INTERPOL, PRECISION, CRITERE)."""
    # TOUT_ORDRE / TOUT_INST ask for every archived state: what is selected when
    # no other selector is given (the catalogues' rules make them exclusive)
    kw.mark_used("TOUT_ORDRE", "TOUT_INST")
    interpol = kw.get("INTERPOL", default_interpol)
    precision = float(kw.get("PRECISION", 1e-6))
    criterion = kw.get("CRITERE", "RELATIF")
    nume = kw.get("NUME_ORDRE")
    if kw.get("LIST_ORDRE") is not None:
        nume = np.asarray(kw["LIST_ORDRE"].values, dtype=int)
    inst = None
    if kw.get("INST") is not None:
        inst = values_of(kw["INST"])
    elif kw.get("LIST_INST") is not None:
        inst = values_of(kw["LIST_INST"])
    try:
        return select_instants(
            times,
            order,
            nume_ordre=as_tuple(nume) if nume is not None else None,
            inst=inst,
            interpolate=interpol == "LIN",
            precision=precision,
            criterion=criterion,
        )
    except CommandError as exc:
        key = "NUME_ORDRE" if nume is not None else ("INST" if "INST" in kw else "LIST_INST")
        ctx.error(exc.message, key, kw)


# -- DOF selection --------------------------------------------------------


def node_indices(
    ctx, kw, mesh, *, allow_all: bool = True, with_cells: bool = True
) -> np.ndarray | None:
    """Mesh node indices named by GROUP_NO / NOEUD / GROUP_MA / MAILLE (the
    cells' nodes, unless ``with_cells`` is False), in order and without
    repeats; None when none is given (all nodes)."""
    chosen: list[int] = []
    for name in as_tuple(kw.get("GROUP_NO")):
        if name not in mesh.node_groups:
            ctx.error(missing_name("node group", name, mesh.node_groups), "GROUP_NO", kw)
        chosen.extend(int(i) for i in mesh.node_groups[name])
    for name in as_tuple(kw.get("NOEUD")):
        name = str(name)
        found = mesh.find_node(name)  # also code_aster 17's N<i>
        if found is not None:
            chosen.append(found)
        elif name.isdigit() and 1 <= int(name) <= mesh.n_nodes:
            chosen.append(int(name) - 1)  # code_aster 17 names nodes by number
        else:
            ctx.error(f"mesh has no node {name!r}", "NOEUD", kw)
    cells: list[int] = []
    for name in as_tuple(kw.get("GROUP_MA")) if with_cells else ():
        if name not in mesh.cell_groups:
            ctx.error(missing_name("cell group", name, mesh.cell_groups), "GROUP_MA", kw)
        cells.extend(int(i) for i in mesh.cell_groups[name])
    for name in as_tuple(kw.get("MAILLE")) if with_cells else ():
        found = mesh.find_cell(str(name))
        if found is None:
            ctx.error(f"mesh has no cell {name!r}", "MAILLE", kw)
        cells.append(found)
    for cell in cells:
        chosen.extend(mesh.cell_nodes[cell])
    if not chosen:
        return None if allow_all else np.zeros(0, dtype=int)
    return np.array(list(dict.fromkeys(chosen)), dtype=int)


def dof_rows(numbering, nodes: np.ndarray | None, components=()) -> np.ndarray:
    """Rows of ``numbering.dofs`` on the given nodes (all if None) and
    components (all if empty), in numbering order."""
    node_set = None if nodes is None else set(int(n) for n in nodes)
    comp_set = set(components)
    return np.array(
        [
            i
            for i, (node, comp) in enumerate(numbering.dofs)
            if (node_set is None or node in node_set) and (not comp_set or comp in comp_set)
        ],
        dtype=int,
    )


def node_label(mesh, node: int) -> str:
    return mesh.node_names[node] if node < len(mesh.node_names) else str(node + 1)


def single_node(ctx, kw, mesh, *, with_cells: bool = True) -> int:
    """The one node a RECU_FONCTION / TEST_RESU occurrence names."""
    nodes = node_indices(ctx, kw, mesh, allow_all=False, with_cells=with_cells)
    if nodes is None or nodes.size == 0:
        ctx.error("a node is required (GROUP_NO or NOEUD)", None, kw)
    if nodes.size > 1 and kw.get("GROUP_NO") is not None:
        group = as_tuple(kw["GROUP_NO"])[0]
        ctx.error(f"node group {group!r} holds {nodes.size} nodes: one expected", "GROUP_NO", kw)
    return int(nodes[0])


def recombine(shapes_rows: np.ndarray, generalized: np.ndarray) -> np.ndarray:
    """Physical values (n_instants, n_rows) = q (n_instants, n_modes) @ Φᵀ."""
    return np.asarray(generalized) @ np.asarray(shapes_rows).T


def support_motion(supports, rows, times, field: str) -> np.ndarray:
    """What the support motions add to a relative field for absolute motion:
    Σ_k ψ_k[rows] s_k(t), (n_times, n_rows). ``supports`` is the
    ``info["mult_appui"]`` list of a tran_gene (``"shape"``: the static mode
    ψ_k on the basis DOFs; ``"DEPL"``/``"VITE"``/``"ACCE"``: the support's
    motion functions of time); a missing motion adds nothing."""
    times = np.atleast_1d(np.asarray(times, dtype=float))
    rows = np.asarray(rows, dtype=int)
    extra = np.zeros((times.size, rows.size))
    for support in supports or ():
        motion = support.get(field[:4])
        if motion is None:
            continue
        shape = np.asarray(support["shape"], dtype=float)[rows]
        extra += np.outer(np.asarray(motion.evaluate(times), dtype=float), shape)
    return extra


def recombine_element_field(field, generalized):
    """An element field of the modes (values (n_modes, n_cells, n_points,
    n_components), as CALC_CHAMP stores it on a modal basis) recombined with
    generalized coordinates (n_instants, n_modes): Σ_j q_j(t) σ_j."""

    generalized = np.asarray(generalized, dtype=float)
    modal = np.asarray(field.values, dtype=float)
    if modal.shape[0] != generalized.shape[1]:
        raise CommandError(
            f"{field.name} holds {modal.shape[0]} modes, the coordinates {generalized.shape[1]}"
        )
    values = np.tensordot(generalized, modal, axes=(1, 0))
    return ElementField(field.name, np.asarray(field.cells).copy(), field.components, values)


def computed_fields(result) -> dict:
    """The element (``*_ELNO``, ``*_ELGA``) and smoothed nodal (``*_NOEU``)
    fields CALC_CHAMP or REST_GENE_PHYS stored on a result, by name."""
    return {
        **(getattr(result, "element_fields", None) or {}),
        **(getattr(result, "node_fields", None) or {}),
    }


def element_value_history(ctx, kw, result, name: str, mesh=None) -> np.ndarray:
    """Values along the orders of one component of an element field (``*_ELNO``
    at the node GROUP_NO / NOEUD of the cell, ``*_ELGA`` at POINT) or of a
    smoothed nodal field (``*_NOEU``) of a result, as RECU_FONCTION and
    TEST_RESU read it. ``mesh`` defaults to the result's numbering's."""
    mesh = mesh if mesh is not None else result.numbering.mesh
    component = as_tuple(kw.get("NOM_CMP"))[0] if kw.get("NOM_CMP") else None
    node_fields = getattr(result, "node_fields", None) or {}
    if name in node_fields:
        field = node_fields[name]
        node = single_node(ctx, kw, mesh)
        if node not in set(int(n) for n in field.nodes):
            ctx.error(f"{name} has no value at node {node_label(mesh, node)}", "GROUP_NO", kw)
        if component not in field.components:
            ctx.error(missing_name("component", component, field.components, name), "NOM_CMP", kw)
        if not field.holds(node, component):
            ctx.error(f"{name} has no {component} at node {node_label(mesh, node)}", "NOM_CMP", kw)
        return field.at(node, component)
    field = result.element_fields[name]
    cell = single_cell(ctx, kw, mesh)
    if cell not in set(int(c) for c in field.cells):
        ctx.error(f"{name} is not computed on cell {mesh.cell_names[cell]}", "GROUP_MA", kw)
    if component not in field.components:
        ctx.error(missing_name("component", component, field.components, name), "NOM_CMP", kw)
    if field.sub_points > 1:
        return _sub_point_values(ctx, kw, name, field, cell, component)
    if kw.get("POINT") is not None:
        point = int(kw["POINT"]) - 1
    else:
        node = single_node(ctx, kw, mesh, with_cells=False)
        connectivity = [int(n) for n in mesh.cell_nodes[cell]]
        if node not in connectivity:
            ctx.error(
                f"node {node_label(mesh, node)} is not a node of cell {mesh.cell_names[cell]}",
                "GROUP_NO",
                kw,
            )
        point = connectivity.index(node)
    n_points = field.values.shape[2]
    if not 0 <= point < n_points:
        ctx.error(f"{name} has {n_points} points per cell, not {point + 1}", "POINT", kw)
    return field.at(cell, point, component)


def _sub_point_values(ctx, kw, name, field, cell, component) -> np.ndarray:
    """Values of a field on sub-points (multifibre beams) at POINT, SOUS_POINT."""
    if kw.get("POINT") is None or kw.get("SOUS_POINT") is None:
        ctx.error(f"{name} is on sub-points (fibres): give POINT and SOUS_POINT", "POINT", kw)
    point, sub = int(kw["POINT"]) - 1, int(kw["SOUS_POINT"]) - 1
    n_points = field.values.shape[2] // field.sub_points
    if not 0 <= point < n_points:
        ctx.error(f"{name} has {n_points} points per cell, not {point + 1}", "POINT", kw)
    values = (
        field.at(cell, point * field.sub_points + sub, component)
        if 0 <= sub < field.sub_points
        else None
    )
    if values is None or np.all(np.isnan(values)):
        ctx.error(f"{name} has no sub-point {sub + 1} on this cell", "SOUS_POINT", kw)
    return values


def single_cell(ctx, kw, mesh) -> int:
    """The one cell a GROUP_MA / MAILLE keyword names."""
    cells: list[int] = []
    for name in as_tuple(kw.get("GROUP_MA")):
        if name not in mesh.cell_groups:
            ctx.error(missing_name("cell group", name, mesh.cell_groups), "GROUP_MA", kw)
        cells.extend(int(i) for i in mesh.cell_groups[name])
    for name in as_tuple(kw.get("MAILLE")):
        found = mesh.find_cell(str(name))
        if found is None:
            ctx.error(f"mesh has no cell {name!r}", "MAILLE", kw)
        cells.append(int(found))
    if not cells:
        ctx.error("a cell is required (GROUP_MA or MAILLE)", "GROUP_MA", kw)
    if len(set(cells)) > 1:
        ctx.error(f"{len(set(cells))} cells given: one expected", "GROUP_MA", kw)
    return cells[0]


# where DYNA_VIBRA keeps what each keyword adds to the relative fields
ADDED_MOTIONS = {
    "MULT_APPUI": ("mult_appui", "multi-support excitation (EXCIT MULT_APPUI)"),
    "CORR_STAT": ("corr_stat", "static correction (MODE_CORR, EXCIT CORR_STAT)"),
}


def added_motions(ctx, kw, result, keyword: str) -> list:
    """The ``info`` entries MULT_APPUI / CORR_STAT recombine (same layout:
    a shape on the basis DOFs and DEPL / VITE / ACCE functions of time)."""
    key, what = ADDED_MOTIONS[keyword]
    supports = result.info.get(key)
    if not supports:
        ctx.error(f"{keyword}='OUI' on a result computed without {what}", keyword, kw)
    return supports


def field_component_value(ctx, kw, field) -> float:
    """The value of NOM_CMP a RECU_FONCTION CHAM_GD occurrence names: at the
    node GROUP_NO / NOEUD of a nodal field, or at the cell GROUP_MA / MAILLE
    and its node (ELNO) or POINT (ELGA, ELNO) of a field by element. As in
    code_aster, a group naming several nodes or cells gives its first one
    (with a warning)."""
    component = str(kw.get("NOM_CMP"))
    numbering = getattr(field, "numbering", None)
    if numbering is not None:
        mesh = numbering.mesh
        node = first_of(ctx, kw, node_indices(ctx, kw, mesh, allow_all=False, with_cells=False))
        if node is None:
            ctx.error("a node is required (GROUP_NO or NOEUD)", "GROUP_NO", kw)
        row = numbering.index.get((node, component))
        if row is None:
            ctx.error(
                f"the field has no component {component} at node {node_label(mesh, node)}",
                "NOM_CMP",
                kw,
            )
        return float(np.asarray(field.values)[row])
    mesh = field.mesh
    cells: list[int] = []
    for name in as_tuple(kw.get("GROUP_MA")):
        if name not in mesh.cell_groups:
            ctx.error(missing_name("cell group", name, mesh.cell_groups), "GROUP_MA", kw)
        cells.extend(int(i) for i in mesh.cell_groups[name])
    for name in as_tuple(kw.get("MAILLE")):
        found = mesh.find_cell(str(name))
        if found is None:
            ctx.error(f"mesh has no cell {name!r}", "MAILLE", kw)
        cells.append(int(found))
    cell = first_of(ctx, kw, np.array(cells, dtype=int))
    if cell is None:
        ctx.error("a field by element needs GROUP_MA or MAILLE", "GROUP_MA", kw)
    n_points = np.asarray(field.values).shape[1]
    if kw.get("POINT") is not None:
        point = int(kw["POINT"]) - 1
        if not 0 <= point < n_points:
            ctx.error(f"the field has {n_points} points per cell, not {point + 1}", "POINT", kw)
    elif str(getattr(field, "field_type", "")).startswith("ELNO_"):
        nodes = node_indices(ctx, kw, mesh, allow_all=False, with_cells=False)
        node = first_of(ctx, kw, nodes)
        if node is None:
            ctx.error("an ELNO field needs GROUP_NO, NOEUD or POINT", "GROUP_NO", kw)
        connectivity = [int(n) for n in mesh.cell_nodes[cell]]
        if node not in connectivity:
            ctx.error(
                f"node {node_label(mesh, node)} is not a node of cell {mesh.cell_names[cell]}",
                "GROUP_NO",
                kw,
            )
        point = connectivity.index(node)
    elif n_points == 1:
        point = 0
    else:
        ctx.error("give POINT for a field at Gauss points", "POINT", kw)
    try:
        return float(field.value(cell, point, component))
    except KeyError as exc:
        ctx.error(str(exc.args[0]), "NOM_CMP", kw)


def first_of(ctx, kw, indices) -> int | None:
    """The first of several mesh indices (a warning when more were named)."""
    if indices is None or len(indices) == 0:
        return None
    if len(indices) > 1:
        ctx.log(f"warning: {len(indices)} entities named, the first one is used")
    return int(indices[0])
