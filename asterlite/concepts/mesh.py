"""Mesh concept: nodes, cells and their named groups."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from asterlite.concepts.base import Concept

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
    if len(name) > 1 and name[0] == prefix and name[1:].isdigit() and name[1] != "0":
        index = int(name[1:]) - 1
        if index < count:
            return index
    return None


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
        """Index of a node by name; code_aster 17 also names nodes ``N<i>`` by
        their 1-based position (mesh names are not kept), so that is the fallback."""
        index = self.node_index.get(name)
        if index is None:
            index = _positional(name, "N", self.n_nodes)
        return index

    def find_cell(self, name: str) -> int | None:
        """Index of a cell by name, falling back on code_aster 17's ``M<i>``."""
        index = self.cell_index.get(name)
        if index is None:
            index = _positional(name, "M", self.n_cells)
        return index

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

    def hasGroupOfNodes(self, name, local=False) -> bool:  # noqa: N802
        return name in self.node_groups

    def hasGroupOfCells(self, name, local=False) -> bool:  # noqa: N802
        return name in self.cell_groups

    def getGroupsOfNodes(self, local=False) -> list[str]:  # noqa: N802
        return list(self.node_groups)

    def getGroupsOfCells(self, local=False) -> list[str]:  # noqa: N802
        return list(self.cell_groups)
