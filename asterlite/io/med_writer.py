"""Writer for MED files (SALOME's HDF5 format, ``IMPR_RESU(FORMAT='MED')``).

Built on ``medcoupling``. What is written, as code_aster lays it out:

- the mesh: coordinates in the mesh's space dimension, cells split by
  dimension into MED levels and sorted by MED geometric type (code_aster's
  numbering order, so :func:`asterlite.io.med_mesh.read_med_mesh` gives the
  cells back in the same order when they were already sorted), node and cell
  names (MED keeps 16 characters), node groups and cell groups (stored as MED
  families, built here as code_aster does: one family per distinct set of
  groups, positive numbers for nodes, negative for cells, and family 0 for
  the entities in no group, so that readers which expect every family but
  FAMILLE_ZERO to carry groups, such as meshio, read the file);
- time series of nodal fields (:class:`NodalSeries`): one MED time step per
  stored instant or mode, numbered by NUME_ORDRE (``numdt``; ``numit`` is
  -1) with the instant (or the frequency, for modes) as time value, one value
  per node and component; a field restricted to some nodes gets a MED profile;
- time series of element fields (:class:`ElementSeries`): ``*_ELNO`` values
  by element node (MED ``MED_NOEUD_MAILLE``, medcoupling's ``ON_GAUSS_NE``,
  as code_aster writes ELNO fields), ``*_ELGA`` values at Gauss points
  (``ON_GAUSS_PT`` with a Gauss localization per cell type: Gauss–Legendre
  points on the reference segment for beams); a field on some cells only
  gets a cell profile per mesh level.

The file version follows code_aster's ``VERSION_MED``: ``"3.3.1"``,
``"4.0.0"`` (the default here) or ``"4.1.0"``; libmed 4.1's ``mdump`` reads
all three. medcoupling's plain ``write`` would give MED 5, which libmed 4.1
tools reject, so it is never used.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from asterlite.arrays import sorted_unique
from asterlite.concepts.mesh import Mesh
from asterlite.fem.dofs import sort_components
from asterlite.io.med_mesh import _TYPES as _MED_TYPES

#: MED short names (entity names) and field/mesh names have fixed sizes.
MED_SNAME_SIZE = 16
MED_NAME_SIZE = 64

#: ``VERSION_MED`` -> medcoupling writer method.
WRITERS = {"3.3.1": "write33", "4.0.0": "write40", "4.1.0": "write41"}

# code_aster cell type -> (MED type number, medcoupling type name, MED order of
# code_aster nodes or None)
_ASTER_TO_MED = {aster: (number, med, order) for med, (number, aster, order) in _MED_TYPES.items()}

_CELL_DIMENSION = {"POI": 0, "SEG": 1, "TRI": 2, "QUA": 2}


class MedWriteError(ValueError):
    """Something asterlite cannot write to a MED file."""


def _medcoupling():
    try:
        import medcoupling
    except ImportError as exc:  # pragma: no cover - declared dependency
        raise MedWriteError("writing MED files needs the 'medcoupling' package") from exc
    return medcoupling


def complex_part(values, part: str) -> np.ndarray:
    """IMPR_RESU's PARTIE of a field's values, as code_aster writes them (its
    ircmva): REEL, IMAG, MODULE or PHASE (degrees, atan2); a real field has a
    zero imaginary part and a phase of 0 or 180."""
    values = np.asarray(values)
    if part == "REEL":
        return np.array(values.real, dtype=float)
    if part == "IMAG":
        return np.array(values.imag, dtype=float)
    if part == "MODULE":
        return np.abs(values).astype(float)
    if part == "PHASE":
        return np.degrees(np.arctan2(values.imag, values.real)).astype(float)
    raise ValueError(part)


@dataclass
class NodalSeries:
    """A nodal field at a sequence of steps, ready for MED.

    ``values`` is (n_steps, n_nodes, n_components) on the mesh nodes
    ``nodes`` (0-based indices; None means every node, in mesh order);
    ``times`` (instants or frequencies) and ``orders`` (NUME_ORDRE) have
    length n_steps.
    """

    name: str
    components: tuple[str, ...]
    values: np.ndarray
    times: np.ndarray
    orders: np.ndarray
    nodes: np.ndarray | None = None


@dataclass
class ElementSeries:
    """An element field at a sequence of steps, ready for MED.

    ``values`` is (n_steps, n_cells, n_points, n_components) on the mesh
    cells ``cells`` (0-based); ``location`` is ``"ELNO"`` (points are the
    cell's nodes in connectivity order) or ``"ELGA"`` (Gauss points).
    """

    name: str
    location: str
    cells: np.ndarray
    components: tuple[str, ...]
    values: np.ndarray
    times: np.ndarray
    orders: np.ndarray


def med_field_name(result_name: str, field_name: str) -> str:
    """code_aster's MED field name: the result name left-justified on 8
    characters, padded with ``_``, followed by the field name (``MODES___DEPL``)."""
    prefix = (result_name or "").strip()[:8].ljust(8, "_")
    return (prefix + field_name.strip())[:MED_NAME_SIZE]


def dofs_to_nodal(numbering, values, nodes=None, components=()) -> tuple:
    """Spread DOF vectors onto nodes and components.

    ``values`` is (n_steps, n_dofs) on ``numbering``'s DOFs. Returns
    ``(nodes, components, array)`` where ``array`` is (n_steps, n_nodes,
    n_components): the nodes carrying DOFs (restricted to ``nodes`` when
    given, in that order), the components present (restricted to
    ``components`` when given, in the given order; else code_aster's
    order), and zero where a node lacks a component. Complex values (a
    harmonic result's) stay complex.
    """

    values = np.atleast_2d(np.asarray(values))
    values = values.astype(complex if np.iscomplexobj(values) else float, copy=False)
    dof_nodes = np.array([n for n, _ in numbering.dofs], dtype=int)
    dof_comps = [c for _, c in numbering.dofs]
    if components:
        comps = tuple(components)
    else:
        comps = sort_components(set(dof_comps))
    if nodes is None:
        chosen = sorted_unique(dof_nodes)
    else:
        carried = set(dof_nodes.tolist())
        chosen = np.array([int(n) for n in nodes if int(n) in carried], dtype=int)
    node_pos = {int(n): k for k, n in enumerate(chosen)}
    comp_pos = {c: k for k, c in enumerate(comps)}
    out = np.zeros((values.shape[0], len(chosen), len(comps)), dtype=values.dtype)
    for dof, (node, comp) in enumerate(numbering.dofs):
        k, j = node_pos.get(node), comp_pos.get(comp)
        if k is not None and j is not None:
            out[:, k, j] = values[:, dof]
    return chosen, comps, out


# -- mesh ---------------------------------------------------------------------


def _cell_dimension(cell_type: str) -> int:
    return _CELL_DIMENSION.get(cell_type[:3], 3)


def _padded(names, size: int = MED_SNAME_SIZE) -> list[str]:
    return [str(n)[:size].ljust(size) for n in names]


def _level_layout(mesh: Mesh) -> tuple[int, dict[int, np.ndarray]]:
    """(mesh dimension, {level: global cell indices in MED order}); level 0
    holds the cells of highest dimension, -1 the next, ..."""
    for t in set(mesh.cell_types):
        if t not in _ASTER_TO_MED:
            raise MedWriteError(f"cells of type {t} cannot be written to MED")
    dims = np.array([_cell_dimension(t) for t in mesh.cell_types], dtype=int)
    mesh_dim = int(dims.max()) if dims.size else 0
    numbers = np.array([_ASTER_TO_MED[t][0] for t in mesh.cell_types], dtype=int)
    levels = {}
    for dim in sorted(set(dims.tolist()), reverse=True):
        cells = np.flatnonzero(dims == dim)
        cells = cells[np.argsort(numbers[cells], kind="stable")]
        levels[dim - mesh_dim] = cells
    return mesh_dim, levels


def _coords_array(mc, mesh: Mesh):
    dim = max(1, min(int(mesh.dim), 3))
    coords = mc.DataArrayDouble(np.ascontiguousarray(mesh.coords[:, :dim], dtype=float))
    coords.setInfoOnComponents(["X", "Y", "Z"][:dim])
    return coords


def _level_mesh(mc, name: str, coords, mesh: Mesh, cells: np.ndarray, dim: int):
    """The cells of one level as a MEDCouplingUMesh, connectivity given at once:
    per cell its medcoupling type code then its nodes in MED order (what
    inserting the cells one by one builds, without a Python call per cell)."""
    umesh = mc.MEDCouplingUMesh(name, dim)
    umesh.setCoords(coords)
    rows, index = [], [np.zeros(1, dtype=np.int64)]
    offset = 0
    for run in _runs_of_one_type(mesh, cells):
        _, med_type, order = _ASTER_TO_MED[mesh.cell_types[run[0]]]
        nodes = np.array([mesh.cell_nodes[c] for c in run], dtype=np.int64).reshape(len(run), -1)
        if order is not None:
            reordered = np.empty_like(nodes)
            reordered[:, list(order)] = nodes
            nodes = reordered
        width = nodes.shape[1] + 1
        block = np.empty((len(run), width), dtype=np.int64)
        block[:, 0] = getattr(mc, med_type)
        block[:, 1:] = nodes
        rows.append(block.ravel())
        index.append(offset + width * np.arange(1, len(run) + 1, dtype=np.int64))
        offset += width * len(run)
    connectivity = np.concatenate(rows) if rows else np.zeros(0, dtype=np.int64)
    umesh.setConnectivity(
        mc.DataArrayInt64(connectivity), mc.DataArrayInt64(np.concatenate(index)), True
    )
    return umesh


def _runs_of_one_type(mesh: Mesh, cells: np.ndarray) -> list[list[int]]:
    """``cells`` cut into consecutive runs of one cell type (and node count)."""
    runs: list[list[int]] = []
    previous = None
    for cell in cells.tolist():
        kind = (mesh.cell_types[cell], len(mesh.cell_nodes[cell]))
        if kind != previous:
            runs.append([])
            previous = kind
        runs[-1].append(cell)
    return runs


def med_mesh(mesh: Mesh, name: str):
    """The mesh as a ``medcoupling.MEDFileUMesh`` named ``name``."""
    mc = _medcoupling()
    name = (name or "MAILLAGE")[:MED_NAME_SIZE]
    coords = _coords_array(mc, mesh)
    med = mc.MEDFileUMesh()
    med.setName(name)
    med.setDescription((mesh.title or "")[:200])
    mesh_dim, levels = _level_layout(mesh)
    if not levels:
        med.setCoords(coords)
    position = {}  # global cell -> (level, index in level)
    for level, cells in levels.items():
        umesh = _level_mesh(mc, name, coords, mesh, cells, mesh_dim + level)
        med.setMeshAtLevel(level, umesh)
        names = [mesh.cell_names[c] for c in cells]
        med.setNameFieldAtLevel(level, mc.DataArrayAsciiChar(_padded(names)))
        for k, cell in enumerate(cells):
            position[int(cell)] = (level, k)
    med.setNameFieldAtLevel(1, mc.DataArrayAsciiChar(_padded(mesh.node_names)))
    _set_families(mc, med, mesh, levels)
    return med


# MED's family of the entities that belong to no group
FAMILY_ZERO = "FAMILLE_ZERO"


def _memberships(count: int, groups: dict) -> list[tuple[str, ...]]:
    """The sorted group names of each of ``count`` entities."""
    held: list[list[str]] = [[] for _ in range(count)]
    for group in sorted(groups):
        for member in np.unique(np.asarray(groups[group], dtype=int)):
            held[int(member)].append(group)
    return [tuple(names) for names in held]


def _family_name(number: int, groups: tuple[str, ...]) -> str:
    """A unique family name: its number, then its groups (MED keeps 64 characters)."""
    return f"FAM_{number}_{'_'.join(groups)}"[:MED_NAME_SIZE]


def _family_numbers(memberships, families: dict, sign: int) -> list[int]:
    """Each entity's family number, adding to ``families`` ({groups: number})
    the sets of groups not seen yet; entities in no group get 0."""
    numbers = []
    for groups in memberships:
        if not groups:
            numbers.append(0)
            continue
        if groups not in families:
            families[groups] = sign * (len(families) + 1)
        numbers.append(families[groups])
    return numbers


def _set_families(mc, med, mesh: Mesh, levels) -> None:
    """Node and cell families as code_aster writes them: one per distinct set
    of groups (nodes 1, 2, ...; cells -1, -2, ... shared by every level), and
    family 0 for the entities in no group. medcoupling's own ``setGroupsAtLevel``
    gives those a family without groups, which meshio cannot read."""
    node_groups = {g: m for g, m in mesh.node_groups.items() if len(m)}
    node_families: dict[tuple[str, ...], int] = {}
    numbers = _family_numbers(_memberships(len(mesh.node_names), node_groups), node_families, 1)
    med.setFamilyFieldArr(1, mc.DataArrayInt(numbers))
    cell_groups = {g: m for g, m in mesh.cell_groups.items() if len(m)}
    cell_memberships = _memberships(len(mesh.cell_names), cell_groups)
    cell_families: dict[tuple[str, ...], int] = {}
    for level, cells in levels.items():
        at_level = [cell_memberships[int(c)] for c in cells]
        numbers = _family_numbers(at_level, cell_families, -1)
        med.setFamilyFieldArr(level, mc.DataArrayInt(numbers))
    med.addFamily(FAMILY_ZERO, 0)
    group_families: dict[str, list[str]] = {}
    for groups, number in [*node_families.items(), *cell_families.items()]:
        name = _family_name(number, groups)
        med.addFamily(name, number)
        for group in groups:
            group_families.setdefault(group, []).append(name)
    for group, names in group_families.items():
        med.setFamiliesOnGroup(group, names)


# -- fields -------------------------------------------------------------------


def _support_mesh(mc, med):
    """A mesh the nodal fields can be defined on (every node)."""
    levels = med.getNonEmptyLevels()
    if levels:
        return med.getMeshAtLevel(levels[0])
    umesh = mc.MEDCouplingUMesh(med.getName(), 0)
    umesh.setCoords(med.getCoords())
    umesh.allocateCells(0)
    umesh.finishInsertingCells()
    return umesh


def med_field(series: NodalSeries, med):
    """The series as a ``medcoupling.MEDFileFieldMultiTS`` on mesh ``med``."""
    mc = _medcoupling()
    support = _support_mesh(mc, med)
    values = np.asarray(series.values, dtype=float)
    n_steps, n_nodes, n_comp = values.shape
    whole = series.nodes is None or (
        n_nodes == med.getNumberOfNodes() and np.array_equal(series.nodes, np.arange(n_nodes))
    )
    nodes = None
    if not whole:
        if n_nodes == 0:
            raise MedWriteError(f"field {series.name}: no node to write")
        order = np.argsort(np.asarray(series.nodes, dtype=int), kind="stable")
        nodes = np.asarray(series.nodes, dtype=int)[order]
        values = values[:, order, :]  # MED profiles list entities in increasing order
    multi = mc.MEDFileFieldMultiTS()
    for step in range(n_steps):
        field = mc.MEDCouplingFieldDouble(mc.ON_NODES, mc.ONE_TIME)
        field.setName(series.name[:MED_NAME_SIZE])
        field.setMesh(support)
        array = mc.DataArrayDouble(np.ascontiguousarray(values[step].reshape(n_nodes, n_comp)))
        array.setInfoOnComponents(list(series.components))
        field.setArray(array)
        field.setTime(float(series.times[step]), int(series.orders[step]), -1)
        if whole:
            multi.appendFieldNoProfileSBT(field)
            continue
        profile = mc.DataArrayInt([int(n) for n in nodes])
        profile.setName(f"PFL_{series.name}"[:MED_NAME_SIZE])
        one = mc.MEDFileField1TS()
        one.setFieldProfile(field, med, 1, profile)
        multi.pushBackTimeStep(one)
    return multi


def gauss_localization(cell_type: str, n_points: int) -> tuple[list, list, list]:
    """(reference node coordinates, Gauss point coordinates, weights) of a
    cell type with ``n_points`` Gauss points: Gauss–Legendre on [-1, 1] for
    segments (beam elements); other types are not written."""
    if not cell_type.startswith("SEG"):
        raise MedWriteError(f"Gauss points of {cell_type} cells cannot be written to MED")
    n_nodes = int(cell_type[3:])
    reference = [-1.0, 1.0] + [0.0] * (n_nodes == 3) + ([-1 / 3, 1 / 3] if n_nodes == 4 else [])
    points, weights = np.polynomial.legendre.leggauss(n_points)
    return reference, points.tolist(), weights.tolist()


def _element_layout(series: ElementSeries, med, mesh: Mesh) -> dict:
    """{level: (positions of the cells in the level, rows of the series)},
    rows sorted by position (MED profiles are increasing)."""
    _, levels = _level_layout(mesh)
    position = {}
    for level, cells in levels.items():
        for k, cell in enumerate(cells):
            position[int(cell)] = (level, k)
    layout: dict[int, list] = {}
    for row, cell in enumerate(np.asarray(series.cells, dtype=int)):
        level, k = position[int(cell)]
        layout.setdefault(level, []).append((k, row))
    return {
        level: (np.array([k for k, _ in sorted(pairs)]), np.array([r for _, r in sorted(pairs)]))
        for level, pairs in layout.items()
    }


def _point_order(mesh: Mesh, cells, location: str) -> list[np.ndarray]:
    """For each cell, where each asterlite point goes among the MED points
    (ELNO: MED node order of the cell type; ELGA: unchanged)."""
    out = []
    for cell in cells:
        order = _ASTER_TO_MED[mesh.cell_types[int(cell)]][2]
        n = len(mesh.cell_nodes[int(cell)])
        out.append(
            np.asarray(order) if (location == "ELNO" and order is not None) else np.arange(n)
        )
    return out


def med_element_field(series: ElementSeries, med, mesh: Mesh):
    """The element series as a ``medcoupling.MEDFileFieldMultiTS``."""
    mc = _medcoupling()
    if series.location not in ("ELNO", "ELGA"):
        raise MedWriteError(f"field {series.name}: unknown location {series.location!r}")
    values = np.asarray(series.values, dtype=float)
    n_steps, n_cells, n_points, n_comp = values.shape
    if n_cells == 0:
        raise MedWriteError(f"field {series.name}: no cell to write")
    if series.location == "ELNO":
        for cell in series.cells:
            if len(mesh.cell_nodes[int(cell)]) != n_points:
                raise MedWriteError(
                    f"field {series.name}: {n_points} values per cell, cell "
                    f"{mesh.cell_names[int(cell)]} has {len(mesh.cell_nodes[int(cell)])} nodes"
                )
        orders = _point_order(mesh, series.cells, "ELNO")
        reordered = np.empty_like(values)
        for row, order in enumerate(orders):
            reordered[:, row, order, :] = values[:, row, :, :]
        values = reordered
    layout = _element_layout(series, med, mesh)
    kind = mc.ON_GAUSS_NE if series.location == "ELNO" else mc.ON_GAUSS_PT
    multi = mc.MEDFileFieldMultiTS()
    for step in range(n_steps):
        one = mc.MEDFileField1TS()
        for level, (positions, rows) in layout.items():
            level_mesh = med.getMeshAtLevel(level)
            whole = positions.size == level_mesh.getNumberOfCells()
            sub = level_mesh if whole else level_mesh.buildPartOfMySelf(positions.tolist(), True)
            field = mc.MEDCouplingFieldDouble(kind, mc.ONE_TIME)
            field.setName(series.name[:MED_NAME_SIZE])
            field.setMesh(sub)
            if kind == mc.ON_GAUSS_PT:
                for cell_type in sorted({mesh.cell_types[int(series.cells[r])] for r in rows}):
                    geometry = getattr(mc, _ASTER_TO_MED[cell_type][1])
                    field.setGaussLocalizationOnType(
                        geometry, *gauss_localization(cell_type, n_points)
                    )
            block = values[step][rows].reshape(rows.size * n_points, n_comp)
            array = mc.DataArrayDouble(np.ascontiguousarray(block))
            array.setInfoOnComponents(list(series.components))
            field.setArray(array)
            field.setTime(float(series.times[step]), int(series.orders[step]), -1)
            field.checkConsistencyLight()
            if whole:
                one.setFieldNoProfileSBT(field)
            else:
                profile = mc.DataArrayInt(positions.tolist())
                profile.setName(f"PFL_{series.name}_{-level}"[:MED_NAME_SIZE])
                one.setFieldProfile(field, med, level, profile)
        multi.pushBackTimeStep(one)
    return multi


def write_med(
    path: str | Path,
    mesh: Mesh,
    mesh_name: str,
    fields: list[NodalSeries | ElementSeries] = (),
    *,
    version: str = "4.0.0",
    append: bool = False,
) -> Path:
    """Write ``mesh`` (unless ``append`` and the file already holds a mesh of
    that name) and the nodal and element ``fields`` to the MED file ``path``.

    ``append=False`` starts a new file; ``append=True`` adds to an existing
    one (fields of the same name are replaced).
    """
    mc = _medcoupling()
    path = Path(path)
    writer = WRITERS.get(version)
    if writer is None:
        raise MedWriteError(f"MED version {version!r} is not supported ({', '.join(WRITERS)})")
    mesh_name = (mesh_name or "MAILLAGE")[:MED_NAME_SIZE]
    med = med_mesh(mesh, mesh_name)
    present = append and path.is_file()
    if present and mesh_name in list(mc.GetMeshNames(str(path))):
        med = mc.MEDFileMesh.New(str(path), mesh_name)
    else:
        getattr(med, writer)(str(path), 0 if present else 2)
    for series in fields:
        if isinstance(series, ElementSeries):
            getattr(med_element_field(series, med, mesh), writer)(str(path), 0)
        else:
            getattr(med_field(series, med), writer)(str(path), 0)
    return path


def med_field_names(path: str | Path) -> list[str]:
    """Names of the fields stored in a MED file."""
    mc = _medcoupling()
    return list(mc.GetAllFieldNames(str(path)))


__all__ = [
    "ElementSeries",
    "MedWriteError",
    "NodalSeries",
    "dofs_to_nodal",
    "gauss_localization",
    "med_element_field",
    "med_field",
    "med_field_name",
    "med_field_names",
    "med_mesh",
    "write_med",
]
