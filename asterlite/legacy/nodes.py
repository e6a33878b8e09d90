"""Mesh node names of legacy decks as the node groups code_aster 17 asks for.

Before code_aster 15 a nonlinearity or a support named its nodes
(``NOEUD_1='N6'``, ``EXCIT=_F(MULT_APPUI='OUI', NOEUD='NO1')``). Today's
syntax names node groups (``GROUP_NO_1``, ``GROUP_NO``); code_aster 17
still accepts the node names of the nonlinearities as hidden keywords, but
not those of ``EXCIT``. A node name becomes a group name only when the
meshes of the run hold a group with exactly that node (most meshes define
one group per node, named like it), so the ported deck computes with the
same nodes.

The meshes are those of the run's input units (the ``.export``), read the
same way by ``asterlite run`` and ``asterlite port``, so both make the same
choice.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from functools import lru_cache
from pathlib import Path

from asterlite.io.input_files import read_head

HDF5_SIGNATURE = b"\x89HDF\r\n\x1a\n"


@lru_cache(maxsize=16)
def _read_mesh(path: str, stamp: float):
    """The mesh file at ``path``, or None when it is not a mesh asterlite reads."""
    try:
        head = read_head(Path(path), 8, "mesh")  # a FIFO is refused, never waited on
        if head == HDF5_SIGNATURE:
            from asterlite.io.med_mesh import read_med_mesh

            mesh = read_med_mesh(Path(path))
        else:
            from asterlite.io.aster_mesh import read_aster_mesh

            mesh = read_aster_mesh(path)
    except Exception:  # not a mesh (a function table, a results file...)
        return None
    return mesh


def _entity_groups(mesh, cells: bool) -> tuple[frozenset, dict]:
    """(entity names, {group: frozenset of entity names}) of a mesh's nodes or cells."""
    names = mesh.cell_names if cells else mesh.node_names
    members = mesh.cell_groups if cells else mesh.node_groups
    groups = {group: frozenset(names[int(i)] for i in found) for group, found in members.items()}
    return frozenset(names), groups


def _mesh_groups(path: str, stamp: float, cells: bool = False) -> tuple[frozenset, dict] | None:
    """(node or cell names, {group: frozenset of names}) of the mesh file at ``path``,
    or None when the file is not a mesh asterlite reads."""
    mesh = _read_mesh(path, stamp)
    return None if mesh is None else _entity_groups(mesh, cells)


def _meshes(paths: Iterable[Path], cells: bool = False) -> list[tuple[frozenset, dict]]:
    found = []
    for path in paths:
        try:
            stamp = Path(path).stat().st_mtime
        except OSError:
            continue
        groups = _mesh_groups(str(path), stamp, cells)
        if groups is not None:
            found.append(groups)
    return found


def group_resolver(paths: Iterable[Path]) -> Callable[[str], str | None]:
    """``node name -> group name`` over the meshes at ``paths`` (read on first use).

    The group must hold exactly that node in every mesh that has the node;
    a group named like the node is preferred, then the first by name.
    """
    paths = list(paths)
    meshes: list | None = None

    def resolve(node: str) -> str | None:
        nonlocal meshes
        if meshes is None:
            meshes = _meshes(paths)
        return _own_group(meshes, node)

    return resolve


def node_number_resolver(paths: Iterable[Path]) -> Callable[[str], int | None]:
    """``node name -> its 1-based number`` over the meshes at ``paths`` (read on
    first use): the number code_aster 17 writes in tables. None when no mesh has
    the node, or when meshes number it differently (a table cannot tell which)."""
    paths = list(paths)
    meshes: list | None = None

    def resolve(node: str) -> int | None:
        nonlocal meshes
        if meshes is None:
            meshes = [m for m in (_read_mesh(str(p), _stamp(p)) for p in paths) if m is not None]
        numbers = {m.node_index[node] + 1 for m in meshes if node in m.node_index}
        return numbers.pop() if len(numbers) == 1 else None

    return resolve


def _stamp(path) -> float:
    try:
        return Path(path).stat().st_mtime
    except OSError:
        return 0.0


def _own_group(meshes: list[tuple[frozenset, dict]], name: str) -> str | None:
    """The group holding exactly the entity ``name`` in every mesh that has it
    (the one named like it preferred, then the first by name), or None."""
    candidates = None
    for names, groups in meshes:
        if name not in names:
            continue
        own = {group for group, members in groups.items() if members == {name}}
        candidates = own if candidates is None else candidates & own
    if not candidates:
        return None
    return name if name in candidates else sorted(candidates)[0]


# -------------------------------------------------------- groups made for a deck

GROUP_PREFIX = "LEGACY_"  # then LEGACY2_, LEGACY3_... until nothing can clash
GROUP_NAME_LIMIT = 24  # characters of a group name in code_aster


class LegacyGroups:
    """Node and cell groups standing for the mesh nodes and cells a legacy deck names.

    A name becomes the mesh's own group holding just that entity when there
    is one; otherwise a group made for the deck, named with a prefix that
    neither the deck's text nor any group of its meshes contains (so no group
    the deck reads or creates can be confused with it), and created when the
    mesh is read (:meth:`creations`). ``named`` are the (kind, name) pairs
    the deck gives where today's syntax takes groups (``"node"``/``"cell"``).
    """

    def __init__(self, mesh_paths: Iterable[Path], texts: Iterable[str], named: set):
        self.paths = list(mesh_paths)
        self.texts = list(texts)
        self.named = set(named)
        self._meshes: dict[bool, list] = {}
        self._prefix: str | None = None

    def meshes(self, cells: bool) -> list[tuple[frozenset, dict]]:
        if cells not in self._meshes:
            self._meshes[cells] = _meshes(self.paths, cells)
        return self._meshes[cells]

    @property
    def prefix(self) -> str:
        if self._prefix is None:
            taken = [
                g for cells in (False, True) for _, groups in self.meshes(cells) for g in groups
            ]
            number = 1
            while True:
                prefix = GROUP_PREFIX if number == 1 else f"LEGACY{number}_"
                clash = any(prefix in text for text in self.texts)
                if not clash and not any(g.startswith(prefix) for g in taken):
                    break
                number += 1
            self._prefix = prefix
        return self._prefix

    def group_of(self, name, cells: bool = False) -> str | None:
        """The group standing for the node (or cell) ``name``, or None."""
        if not isinstance(name, str):
            return None
        meshes = self.meshes(cells)
        own = _own_group(meshes, name)
        if own is not None:
            return own
        kind = "cell" if cells else "node"
        made = self.prefix + name
        if (kind, name) in self.named and len(made) <= GROUP_NAME_LIMIT:
            if any(name in names for names, _ in meshes):
                return made
        return None

    def creations(self, path) -> tuple[dict, dict]:
        """({group: node}, {group: cell}) to create in the mesh read from ``path``."""
        if not self.named:  # the decks name no node or cell: nothing to read the mesh for
            return {}, {}
        try:
            stamp = Path(path).stat().st_mtime
        except OSError:
            return {}, {}
        made: tuple[dict, dict] = ({}, {})
        for index, cells in enumerate((False, True)):
            found = _mesh_groups(str(path), stamp, cells)
            if found is None:
                return {}, {}
            kind = "cell" if cells else "node"
            for entity_kind, name in sorted(self.named):
                if entity_kind != kind or name not in found[0]:
                    continue
                group = self.group_of(name, cells)
                if group is not None and group.startswith(self.prefix):
                    made[index][group] = name
        return made
