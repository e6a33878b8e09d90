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

HDF5_SIGNATURE = b"\x89HDF\r\n\x1a\n"


@lru_cache(maxsize=16)
def _mesh_groups(path: str, stamp: float) -> tuple[frozenset, dict] | None:
    """(node names, {group: frozenset of node names}) of the mesh file at ``path``,
    or None when the file is not a mesh asterlite reads."""
    try:
        with open(path, "rb") as stream:
            head = stream.read(8)
        if head == HDF5_SIGNATURE:
            from asterlite.io.med_mesh import read_med_mesh

            mesh = read_med_mesh(Path(path))
        else:
            from asterlite.io.aster_mesh import read_aster_mesh

            mesh = read_aster_mesh(path)
    except Exception:  # not a mesh (a function table, a results file...)
        return None
    names = mesh.node_names
    groups = {
        group: frozenset(names[int(i)] for i in members)
        for group, members in mesh.node_groups.items()
    }
    return frozenset(names), groups


def _meshes(paths: Iterable[Path]) -> list[tuple[frozenset, dict]]:
    found = []
    for path in paths:
        try:
            stamp = Path(path).stat().st_mtime
        except OSError:
            continue
        groups = _mesh_groups(str(path), stamp)
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
        candidates = None
        for names, groups in meshes:
            if node not in names:
                continue
            own = {group for group, members in groups.items() if members == {node}}
            candidates = own if candidates is None else candidates & own
        if not candidates:
            return None
        return node if node in candidates else sorted(candidates)[0]

    return resolve
