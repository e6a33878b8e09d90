"""Reader for MED meshes (SALOME's HDF5 format, ``LIRE_MAILLAGE(FORMAT='MED')``).

Built on ``medcoupling`` (``MEDFileUMesh``). The result is a
:class:`~asterlite.concepts.mesh.Mesh` laid out as code_aster reads it:

- coordinates padded to 3D (``dim`` keeps the MED space dimension);
- cells of every dimension (points, segments, faces, volumes), numbered by
  increasing MED geometric type (POI1, SEG2, SEG3, SEG4, TRIA3, QUAD4, ...,
  HEXA27), in file order within a type, with code_aster type names and
  code_aster node ordering (MED and code_aster differ for volumes);
- node and cell names from the file when it has them (meshes written by
  code_aster do), else ``N1, N2, ...`` and ``M1, M2, ...``;
- node groups and cell groups rebuilt from the families; a name used at
  both levels gives a node group and a cell group, as in code_aster.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from asterlite.concepts.mesh import Mesh


class MedMeshError(ValueError):
    """A MED file asterlite cannot read as a mesh."""


# MED geometric type number (code_aster numbers cells in increasing order of
# it), code_aster name, and the MED positions of code_aster's nodes (0-based)
# when the two numberings differ. Keyed by medcoupling's type names.
_TYPES = {
    "NORM_POINT1": (1, "POI1", None),
    "NORM_SEG2": (102, "SEG2", None),
    "NORM_SEG3": (103, "SEG3", None),
    "NORM_SEG4": (104, "SEG4", None),
    "NORM_TRI3": (203, "TRIA3", None),
    "NORM_QUAD4": (204, "QUAD4", None),
    "NORM_TRI6": (206, "TRIA6", None),
    "NORM_TRI7": (207, "TRIA7", None),
    "NORM_QUAD8": (208, "QUAD8", None),
    "NORM_QUAD9": (209, "QUAD9", None),
    "NORM_TETRA4": (304, "TETRA4", (0, 2, 1, 3)),
    "NORM_PYRA5": (305, "PYRAM5", (0, 3, 2, 1, 4)),
    "NORM_PENTA6": (306, "PENTA6", (0, 2, 1, 3, 5, 4)),
    "NORM_HEXA8": (308, "HEXA8", (0, 3, 2, 1, 4, 7, 6, 5)),
    "NORM_TETRA10": (310, "TETRA10", (0, 2, 1, 3, 6, 5, 4, 7, 9, 8)),
    "NORM_PYRA13": (313, "PYRAM13", (0, 3, 2, 1, 4, 8, 7, 6, 5, 9, 12, 11, 10)),
    "NORM_PENTA15": (315, "PENTA15", (0, 2, 1, 3, 5, 4, 8, 7, 6, 12, 14, 13, 11, 10, 9)),
    "NORM_PENTA18": (
        318,
        "PENTA18",
        (0, 2, 1, 3, 5, 4, 8, 7, 6, 12, 14, 13, 11, 10, 9, 17, 16, 15),
    ),
    "NORM_HEXA20": (
        320,
        "HEXA20",
        (0, 3, 2, 1, 4, 7, 6, 5, 11, 10, 9, 8, 16, 19, 18, 17, 15, 14, 13, 12),
    ),
    "NORM_HEXA27": (
        327,
        "HEXA27",
        (0, 3, 2, 1, 4, 7, 6, 5, 11, 10, 9, 8, 16, 19, 18, 17, 15, 14, 13, 12)
        + (20, 24, 23, 22, 21, 25, 26),
    ),
}


def _medcoupling():
    try:
        import medcoupling
    except ImportError as exc:  # pragma: no cover - declared dependency
        raise MedMeshError("reading MED files needs the 'medcoupling' package") from exc
    return medcoupling


def med_mesh_names(path: Path) -> list[str]:
    """Names of the meshes stored in a MED file."""
    mc = _medcoupling()
    try:
        return list(mc.GetMeshNames(str(path)))
    except Exception as exc:  # medcoupling raises InterpKernelException
        raise MedMeshError(f"{path}: not a readable MED file ({_first_line(exc)})") from exc


def _first_line(exc: Exception) -> str:
    text = str(exc).strip().splitlines()
    return text[0] if text else type(exc).__name__


def _names(field, count: int, prefix: str) -> list[str]:
    """Names from a MED name field, or generated ones when absent, blank or
    not unique (names must identify entities)."""
    if field is not None:
        names = [s.strip() for s in field.toStrList()[:count]]
        if len(names) == count and all(names) and len(set(names)) == count:
            return names
    return [f"{prefix}{i + 1}" for i in range(count)]


def read_med_mesh(path: Path, name: str | None = None) -> Mesh:
    """Read mesh ``name`` (default: the first) of a MED file: validated, then
    read in a child process whose crash on a damaged file becomes a
    MedMeshError (:mod:`asterlite.io.med_check`)."""
    from asterlite.io.input_files import InputFileError, check_regular_file
    from asterlite.io.med_check import read_isolated

    path = Path(path)
    try:  # a FIFO or a device is refused here and again in the child, on its descriptor
        check_regular_file(path, "MED file")
    except FileNotFoundError:
        raise MedMeshError(f"{path}: no such MED file") from None
    except InputFileError as error:
        raise MedMeshError(str(error)) from None
    return read_isolated(path, name, _read_here)


def _read_here(path: Path, name: str | None) -> Mesh:
    """The reading itself, in this process (the file is validated already)."""
    mc = _medcoupling()
    available = med_mesh_names(path)
    if not available:
        raise MedMeshError(f"{path}: the MED file holds no mesh")
    if name is None:
        name = available[0]
    elif name not in available:
        raise MedMeshError(f"{path}: no mesh named '{name}' (the file has {', '.join(available)})")
    try:
        med = mc.MEDFileMesh.New(str(path), name)
    except Exception as exc:
        raise MedMeshError(f"{path}: cannot read mesh '{name}' ({_first_line(exc)})") from exc
    if not isinstance(med, mc.MEDFileUMesh):
        raise MedMeshError(f"{path}: mesh '{name}' is not unstructured ({type(med).__name__})")

    coords = med.getCoords().toNumPyArray().reshape(med.getNumberOfNodes(), -1)
    dim = coords.shape[1]
    if dim > 3:
        raise MedMeshError(f"{path}: space dimension {dim} is not supported")
    coords3 = np.zeros((len(coords), 3))
    coords3[:, :dim] = coords
    n_nodes = len(coords3)
    node_names = _names(med.getNameFieldAtLevel(1), n_nodes, "N")
    _check_finite(path, name, coords3, node_names)

    # cells of each level, tagged with their MED type number for ordering
    parts = []  # (med type number, level, indices in level, aster type, connectivity)
    level_sizes = {}
    for level in med.getNonEmptyLevels():
        umesh = med.getMeshAtLevel(level)
        level_sizes[level] = umesh.getNumberOfCells()
        conn = umesh.getNodalConnectivity().toNumPyArray()
        index = umesh.getNodalConnectivityIndex().toNumPyArray()
        types = conn[index[:-1]]
        for code in np.unique(types):
            type_name = mc.MEDCouplingUMesh.GetReprOfGeometricType(int(code))
            if type_name not in _TYPES:
                raise MedMeshError(f"{path}: cells of type {type_name} are not supported")
            number, aster_type, order = _TYPES[type_name]
            cells = np.flatnonzero(types == code)
            width = int(index[cells[0] + 1] - index[cells[0]] - 1)
            nodes = conn[index[cells][:, None] + 1 + np.arange(width)]
            if order is not None:
                nodes = nodes[:, order]
            parts.append((number, level, cells, aster_type, nodes))
    parts.sort(key=lambda p: (p[0], -p[1]))  # stable in file order within a type

    # global numbering: position of (level, index in level) in the cell list
    global_index = {lev: np.full(size, -1, dtype=int) for lev, size in level_sizes.items()}
    cell_types: list[str] = []
    cell_nodes: list[tuple[int, ...]] = []
    level_names = {lev: _level_names(med, lev, size) for lev, size in level_sizes.items()}
    raw_names: list[str | None] = []
    for _, level, cells, aster_type, nodes in parts:
        global_index[level][cells] = np.arange(len(cell_types), len(cell_types) + len(cells))
        cell_types.extend([aster_type] * len(cells))
        cell_nodes.extend(tuple(int(n) for n in row) for row in nodes)
        names = level_names[level]
        raw_names.extend(names[c] if names is not None else None for c in cells)
    n_cells = len(cell_types)
    if raw_names and all(raw_names) and len(set(raw_names)) == n_cells:
        cell_names = list(raw_names)
    else:
        cell_names = [f"M{i + 1}" for i in range(n_cells)]

    node_groups: dict[str, np.ndarray] = {}
    cell_groups: dict[str, np.ndarray] = {}
    for group in med.getGroupsNames():
        levels = med.getGrpNonEmptyLevelsExt(group)
        if 1 in levels:
            node_groups[group] = np.sort(med.getNodeGroupArr(group).toNumPyArray()).astype(int)
        members = [
            global_index[lev][med.getGroupArr(lev, group).toNumPyArray()]
            for lev in levels
            if lev != 1 and lev in global_index
        ]
        if members:
            cell_groups[group] = np.sort(np.concatenate(members)).astype(int)

    return Mesh(
        coords=coords3,
        node_names=node_names,
        cell_names=cell_names,
        cell_types=cell_types,
        cell_nodes=cell_nodes,
        node_groups=node_groups,
        cell_groups=cell_groups,
        dim=dim,
        title=(med.getDescription() or "").strip(),
    )


def _check_finite(path: Path, mesh: str, coords: np.ndarray, node_names: list[str]) -> None:
    """A NaN or infinite coordinate has no place in a mesh: name the first such node."""
    bad = np.flatnonzero(~np.isfinite(coords).all(axis=1))
    if bad.size:
        node = int(bad[0])
        coordinates = ", ".join(repr(float(v)) for v in coords[node])
        more = f" (and {bad.size - 1} more nodes)" if bad.size > 1 else ""
        raise MedMeshError(
            f"{path}: mesh '{mesh}': node {node_names[node]} (number {node + 1}) has a "
            f"non-finite coordinate ({coordinates}){more}"
        )


def _level_names(med, level: int, size: int) -> list[str] | None:
    field = med.getNameFieldAtLevel(level)
    if field is None:
        return None
    names = [s.strip() for s in field.toStrList()[:size]]
    return names if len(names) == size else None
