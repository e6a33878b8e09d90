"""Mesh concept: nodes, cells and their named groups."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from asterlite.concepts.base import Concept
from asterlite.errors import DeckRuntimeError

#: Number of nodes of each code_aster cell type asterlite knows.
CELL_NODE_COUNTS = {
    "POI1": 1,
    "SEG2": 2,
    "SEG3": 3,
    "SEG4": 4,
    "TRIA3": 3,
    "TRIA6": 6,
    "TRIA7": 7,
    "QUAD4": 4,
    "QUAD8": 8,
    "QUAD9": 9,
    "TETRA4": 4,
    "TETRA10": 10,
    "PYRAM5": 5,
    "PYRAM13": 13,
    "PENTA6": 6,
    "PENTA15": 15,
    "PENTA18": 18,
    "HEXA8": 8,
    "HEXA20": 20,
    "HEXA27": 27,
}


def _positional(name: str, prefix: str, count: int) -> int | None:
    """The 0-based index code_aster 17 reads in ``N<i>``/``M<i>`` or ``<i>``."""
    number = name[1:] if name[:1] == prefix else name
    if number.isdigit() and number[0] != "0":
        index = int(number) - 1
        if index < count:
            return index
    return None


def _lookup(name: str, prefix: str, by_name: dict, count: int, names_kept: bool) -> int | None:
    if not names_kept:
        index = _positional(name, prefix, count)
        if index is not None:
            return index
    index = by_name.get(name)
    if index is None and names_kept:
        index = _positional(name, prefix, count)
    return index


@dataclass(eq=False)
class Mesh(Concept):
    """An unstructured mesh as code_aster sees it.

    ``coords`` is (n_nodes, 3) even for 2D meshes (z = 0), ``dim`` says
    which. Cells are kept as parallel lists: name, type (code_aster names:
    ``POI1``, ``SEG2``, ``TRIA3``, ``QUAD4``...), node indices. Groups map a
    name to an int array of node or cell indices, in the order given.
    """

    aster_types = ("maillage_sdaster",)
    # code_aster 16-17's getters of a mesh (its object API)
    deck_methods = frozenset(
        {
            "getName",
            "getNumberOfNodes",
            "getNumberOfCells",
            "getCells",
            "getDimension",
            "hasGroupOfNodes",
            "hasGroupOfCells",
            "getGroupsOfNodes",
            "getGroupsOfCells",
            "addNodeLabels",
            "addCellLabels",
            "getCoordinates",
            "getNodes",
            "getNodesFromCells",
        }
    )

    coords: np.ndarray
    node_names: list[str]
    cell_names: list[str]
    cell_types: list[str]
    cell_nodes: list[tuple[int, ...]]
    node_groups: dict[str, np.ndarray] = field(default_factory=dict)
    cell_groups: dict[str, np.ndarray] = field(default_factory=dict)
    dim: int = 3
    title: str = ""
    # MODI_MAILLAGE ABSC_CURV's carte: cell -> abscissa of its nodes (ABSC1...)
    curvilinear_abscissa: dict[int, tuple[float, ...]] | None = None
    # False where code_aster keeps no names for the mesh (a file read by
    # code_aster 16 and later): there ``N<i>``/``M<i>`` are positions first
    names_kept: bool = True
    # MACR_ADAP_MAIL's history: how many uniform refinements every cell has
    # had, and whether a zone adaptation left cells of several levels
    uniform_level: int = 0
    zone_adapted: bool = False

    def __post_init__(self) -> None:
        self.node_index = {n: i for i, n in enumerate(self.node_names)}
        self.cell_index = {n: i for i, n in enumerate(self.cell_names)}

    @property
    def n_nodes(self) -> int:
        return len(self.node_names)

    @property
    def n_cells(self) -> int:
        return len(self.cell_names)

    def refresh_indices(self) -> None:
        """Rebuild name lookups after nodes or cells were added."""
        self.__post_init__()

    # -- lookups used by commands (KeyError names the missing entity) --------

    def find_node(self, name: str) -> int | None:
        """Index of a node by name. code_aster 17 names a node ``N<i>`` by its
        1-based position where the mesh keeps no names (char8_to_int): there
        the position wins, elsewhere it is the fallback of a missing name."""
        return _lookup(name, "N", self.node_index, self.n_nodes, self.names_kept)

    def node_label(self, index: int) -> str:
        """The name code_aster gives node ``index``: its own where the mesh
        keeps names, else ``N<i>`` of its 1-based position (int_to_char8)."""
        return self.node_names[index] if self.names_kept else f"N{index + 1}"

    def find_cell(self, name: str) -> int | None:
        """Index of a cell by name, with code_aster 17's ``M<i>`` as for nodes."""
        return _lookup(name, "M", self.cell_index, self.n_cells, self.names_kept)

    def node_group(self, name: str) -> np.ndarray:
        return self.node_groups[name]

    def cell_group(self, name: str) -> np.ndarray:
        return self.cell_groups[name]

    def nodes_of_cells(self, cells) -> np.ndarray:
        """Distinct node indices of the given cells, in first-seen order."""
        seen: dict[int, None] = {}
        for c in np.asarray(cells, dtype=int).ravel():
            for n in self.cell_nodes[c]:
                seen.setdefault(n, None)
        return np.fromiter(seen, dtype=int, count=len(seen))

    def cells_of_type(self, cell_type: str) -> np.ndarray:
        return np.array([i for i, t in enumerate(self.cell_types) if t == cell_type], dtype=int)

    def add_cells(self, names, cell_type: str, nodes) -> np.ndarray:
        """Append cells of one type; returns their indices."""
        start = self.n_cells
        for name, conn in zip(names, nodes, strict=True):
            if name in self.cell_index:
                raise ValueError(f"cell {name} already exists")
            self.cell_index[name] = len(self.cell_names)
            self.cell_names.append(name)
            self.cell_types.append(cell_type)
            self.cell_nodes.append(tuple(int(n) for n in conn))
        return np.arange(start, self.n_cells)

    def copy(self) -> Mesh:
        return Mesh(
            coords=self.coords.copy(),
            node_names=list(self.node_names),
            cell_names=list(self.cell_names),
            cell_types=list(self.cell_types),
            cell_nodes=list(self.cell_nodes),
            node_groups={k: v.copy() for k, v in self.node_groups.items()},
            cell_groups={k: v.copy() for k, v in self.cell_groups.items()},
            dim=self.dim,
            title=self.title,
            curvilinear_abscissa=(
                None if self.curvilinear_abscissa is None else dict(self.curvilinear_abscissa)
            ),
            names_kept=self.names_kept,
            uniform_level=self.uniform_level,
            zone_adapted=self.zone_adapted,
        )

    # -- code_aster's object API ----------------------------------------------

    def getNumberOfNodes(self) -> int:  # noqa: N802 - code_aster's names
        return self.n_nodes

    def getNumberOfCells(self) -> int:  # noqa: N802
        return self.n_cells

    def getCells(self) -> list[int]:  # noqa: N802
        """The cells' indices (code_aster 17 numbers them from 0)."""
        return list(range(self.n_cells))

    def getDimension(self) -> int:  # noqa: N802
        return self.dim

    def getNodes(self, group_name=(), localNumbering=True, same_rank=None) -> list[int]:  # noqa: N802, N803
        """Nodes (from 0) of groups of nodes: every node without a name, one
        group's in its order, several groups' merged and sorted; a name the
        mesh does not have adds none (code_aster's Mesh::getNodes)."""
        names = [group_name] if isinstance(group_name, str) else list(group_name)
        names = [name for name in names if name]
        if not names:
            return list(range(self.n_nodes))
        found = [self.node_groups[name] for name in names if name in self.node_groups]
        if len(found) == 1:
            return [int(i) for i in found[0]]
        return np.unique(np.concatenate(found)).tolist() if found else []

    def getNodesFromCells(self, group_name, localNumbering=True, same_rank=None) -> list[int]:  # noqa: N802, N803
        """The sorted nodes (from 0) of the cells of groups of cells."""
        names = [group_name] if isinstance(group_name, str) else list(group_name)
        cells = [self.cell_groups[name] for name in names if name in self.cell_groups]
        if not cells:
            return []
        return sorted(self.nodes_of_cells(np.concatenate(cells)).tolist())

    def getCoordinates(self) -> MeshCoordinates:  # noqa: N802
        """The nodes' coordinates, three per node as code_aster keeps them."""
        xyz = np.zeros((self.n_nodes, 3))
        xyz[:, : self.coords.shape[1]] = self.coords
        return MeshCoordinates(xyz)

    def hasGroupOfNodes(self, name, local=False) -> bool:  # noqa: N802
        return name in self.node_groups

    def hasGroupOfCells(self, name, local=False) -> bool:  # noqa: N802
        return name in self.cell_groups

    def getGroupsOfNodes(self, local=False) -> list[str]:  # noqa: N802
        return list(self.node_groups)

    def getGroupsOfCells(self, local=False) -> list[str]:  # noqa: N802
        return list(self.cell_groups)

    def addNodeLabels(self, labels) -> None:  # noqa: N802
        """Rename every node, in order (code_aster's Mesh.addNodeLabels: one
        label per node, the names it had replaced)."""
        self.node_names = self._labels(labels, self.n_nodes, "node")
        self.node_index = {n: i for i, n in enumerate(self.node_names)}
        self.names_kept = True  # code_aster looks labelled nodes up by name

    def addCellLabels(self, labels) -> None:  # noqa: N802
        """Rename every cell, in order (code_aster's Mesh.addCellLabels)."""
        self.cell_names = self._labels(labels, self.n_cells, "cell")
        self.cell_index = {n: i for i, n in enumerate(self.cell_names)}

    @staticmethod
    def _labels(labels, count: int, what: str) -> list[str]:
        if isinstance(labels, str) or not all(isinstance(x, str) for x in labels):
            raise DeckRuntimeError(f"add{what.title()}Labels takes a list of names")
        names = [str(x).strip() for x in labels]
        if len(names) != count:
            raise DeckRuntimeError(f"Bad label size: {len(names)} labels for {count} {what}s")
        if len(set(names)) != count:
            raise DeckRuntimeError(f"add{what.title()}Labels: the {what} labels repeat a name")
        return names


@dataclass(eq=False)
class CellConstantField(Concept):
    """A field constant by cell (code_aster's ``carte``), as CREA_CHAMP EXTR
    takes it from a mesh (``CART_ABSC_R``: MODI_MAILLAGE ABSC_CURV's abscissa).

    ``values`` maps a mesh cell to its components' values, the first
    ``len(values[cell])`` of ``components`` (a SEG2 carries ABSC1, ABSC2)."""

    aster_types = ("carte_sdaster", "cham_gd_sdaster")

    mesh: Mesh
    field_type: str
    components: tuple[str, ...]
    values: dict[int, tuple[float, ...]]


class MeshCoordinates:
    """code_aster's MeshCoordinatesField as a deck reads it: (x, y, z) per node,
    a copy (changing the mesh's geometry goes through MODI_MAILLAGE)."""

    deck_methods = frozenset({"getValues", "toNumpy", "size"})

    def __init__(self, xyz: np.ndarray):
        self._xyz = xyz

    def getValues(self) -> list[float]:  # noqa: N802 - code_aster's name
        """x1, y1, z1, x2, ... as a list."""
        return self._xyz.ravel().tolist()

    def toNumpy(self) -> np.ndarray:  # noqa: N802
        """The (number of nodes, 3) array."""
        return self._xyz.copy()

    def size(self) -> int:
        return self._xyz.size
