"""gmsh meshes (LIRE_MAILLAGE FORMAT='GMSH'), read as code_aster's PRE_GMSH
converts them (its pregms / gmlelt): ASCII formats 1 ($NOD ... $ELM) and 2
($MeshFormat 2.x).

- nodes are named ``N<gmsh number>``, cells ``M<gmsh number>``; nodes no
  cell uses are dropped; coordinates are 3D;
- format 1: each cell joins the group ``GM<physical number>``;
- format 2: with $PhysicalNames, a cell joins each named group whose tag is
  among its tags and whose dimension is the cell's (names cut to 8
  characters); without $PhysicalNames there are no groups;
- a group of a single POI1 cell is also a node group of that node.

Cell types: gmsh's 1-11, 15, 16, 17 (SEG2 ... TETRA10, POI1, QUAD8, HEXA20);
gmsh's 9-node quadrangle becomes a QUAD8 on its first 8 nodes and the
10-node tetrahedron has its last two nodes swapped, as in code_aster. The
other types are refused by name.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from asterlite.concepts.mesh import Mesh

#: gmsh type -> (code_aster type, gmsh node count, dimension)
_TYPES = {
    1: ("SEG2", 2, 1),
    2: ("TRIA3", 3, 2),
    3: ("QUAD4", 4, 2),
    4: ("TETRA4", 4, 3),
    5: ("HEXA8", 8, 3),
    6: ("PENTA6", 6, 3),
    7: ("PYRAM5", 5, 3),
    8: ("SEG3", 3, 1),
    9: ("TRIA6", 6, 2),
    10: ("QUAD8", 9, 2),
    11: ("TETRA10", 10, 3),
    15: ("POI1", 1, 0),
    16: ("QUAD8", 8, 2),
}
#: code_aster node position -> gmsh node position, where they differ
_REORDER = {11: [0, 1, 2, 3, 4, 5, 6, 7, 9, 8]}
_ASTER_NODES = {"QUAD8": 8}


class GmshMeshError(ValueError):
    """A gmsh file asterlite cannot read (message names the line)."""


def _cell_nodes(gmsh_type: int, nodes: list[int]) -> list[int]:
    order = _REORDER.get(gmsh_type)
    picked = [nodes[k] for k in order] if order else nodes
    kind = _TYPES[gmsh_type][0]
    return picked[: _ASTER_NODES.get(kind, len(picked))]


def read_gmsh_mesh(path) -> Mesh:
    path = Path(path)
    lines = path.read_text(errors="replace").splitlines()
    tokens = [line.split() for line in lines]
    first = next((k for k, t in enumerate(tokens) if t), None)
    if first is None:
        raise GmshMeshError(f"{path.name}: empty file")
    head = tokens[first][0]
    if head == "$NOD":
        return _read(path, tokens, first, version=1, names={})
    if head == "$MeshFormat":
        fmt = tokens[first + 1]
        if not fmt or not fmt[0].startswith("2"):
            raise GmshMeshError(
                f"{path.name}:{first + 2}: gmsh format {fmt[0] if fmt else '?'}: code_aster "
                "reads formats 1 and 2 (save the mesh as 'Version 2 ASCII')"
            )
        if len(fmt) > 1 and fmt[1] != "0":
            raise GmshMeshError(f"{path.name}:{first + 2}: binary gmsh files are not read")
        names = _physical_names(path, tokens)
        return _read(path, tokens, first, version=2, names=names)
    raise GmshMeshError(f"{path.name}:{first + 1}: not a gmsh file (expected $NOD or $MeshFormat)")


def _section(path, tokens, start_words, after=0) -> int:
    for k in range(after, len(tokens)):
        if tokens[k] and tokens[k][0] in start_words:
            return k
    raise GmshMeshError(f"{path.name}: no {'/'.join(start_words)} section")


def _physical_names(path, tokens) -> dict[tuple[int, int], str]:
    """(dimension, tag) -> group name of a format-2 $PhysicalNames section."""
    start = next((k for k, t in enumerate(tokens) if t and t[0] == "$PhysicalNames"), None)
    if start is None:
        return {}
    count = int(tokens[start + 1][0])
    out = {}
    for k in range(start + 2, start + 2 + count):
        words = tokens[k]
        name = " ".join(words[2:]).strip('"')[:8].rstrip()
        out[int(words[0]), int(words[1])] = name
    return out


def _read(path, tokens, first, version: int, names) -> Mesh:
    nodes_at = _section(path, tokens, ("$NOD", "$Nodes"), first)
    n_nodes = int(tokens[nodes_at + 1][0])
    numbers, coords = [], []
    for k in range(nodes_at + 2, nodes_at + 2 + n_nodes):
        words = tokens[k]
        try:
            numbers.append(int(words[0]))
            coords.append([float(w) for w in words[1:4]])
        except (ValueError, IndexError):
            raise GmshMeshError(
                f"{path.name}:{k + 1}: expected a node number and 3 coordinates"
            ) from None
    cells_at = _section(path, tokens, ("$ELM", "$Elements"), nodes_at + 2 + n_nodes)
    n_cells = int(tokens[cells_at + 1][0])
    position = {n: i for i, n in enumerate(numbers)}
    cell_names, cell_types, cell_nodes, cell_tags, cell_dims = [], [], [], [], []
    for k in range(cells_at + 2, cells_at + 2 + n_cells):
        words = [int(w) for w in tokens[k]]
        number, gmsh_type = words[0], words[1]
        if gmsh_type not in _TYPES:
            raise GmshMeshError(
                f"{path.name}:{k + 1}: gmsh element type {gmsh_type} is not read "
                f"(types {', '.join(str(t) for t in sorted(_TYPES))})"
            )
        kind, count, dim = _TYPES[gmsh_type]
        if version == 1:
            tags, given = [words[2]], words[5 : 5 + words[4]]
            if words[4] != count:
                raise GmshMeshError(f"{path.name}:{k + 1}: {words[4]} nodes for a {kind}")
        else:
            n_tags = words[2]
            tags, given = words[3 : 3 + n_tags], words[3 + n_tags : 3 + n_tags + count]
        if len(given) != count:
            raise GmshMeshError(f"{path.name}:{k + 1}: a {kind} needs {count} nodes")
        try:
            local = [position[n] for n in _cell_nodes(gmsh_type, given)]
        except KeyError as exc:
            raise GmshMeshError(f"{path.name}:{k + 1}: unknown node {exc.args[0]}") from None
        cell_names.append(f"M{number}")
        cell_types.append(kind)
        cell_nodes.append(tuple(local))
        cell_tags.append(tags)
        cell_dims.append(dim)
    groups: dict[str, list[int]] = {}
    if version == 1:
        for c, tags in enumerate(cell_tags):
            groups.setdefault(f"GM{tags[0]}", []).append(c)
    else:
        for (dim, tag), name in names.items():
            members = [c for c, tags in enumerate(cell_tags) if tag in tags and cell_dims[c] == dim]
            groups.setdefault(name, []).extend(members)
    used = sorted({n for nodes in cell_nodes for n in nodes})
    renumber = {old: new for new, old in enumerate(used)}
    # a group of one POI1 cell also names its node (gmeelt)
    node_groups = {
        name: np.array([renumber[cell_nodes[m[0]][0]]], dtype=int)
        for name, m in groups.items()
        if len(m) == 1 and cell_types[m[0]] == "POI1"
    }
    return Mesh(
        coords=np.array([coords[i] for i in used], dtype=float).reshape(-1, 3),
        node_names=[f"N{numbers[i]}" for i in used],
        cell_names=cell_names,
        cell_types=cell_types,
        cell_nodes=[tuple(renumber[n] for n in nodes) for nodes in cell_nodes],
        cell_groups={name: np.array(m, dtype=int) for name, m in groups.items()},
        node_groups=node_groups,
        dim=3,
        title="INTERFACE_GMSH",
    )
