"""MODI_MAILLAGE: change node coordinates in place (ECHELLE, TRANSLATION,
ROTATION, SYMETRIE, DEFORME), the orientation of skin faces (ORIE_PEAU) and
of shells (ORIE_NORM_COQUE), or store the curvilinear abscissa of a line of
segments (ABSC_CURV); the mesh is returned (reuse)."""

from __future__ import annotations

import numpy as np

from asterlite.fem.abscissa import AbscissaError, curvilinear_abscissa
from asterlite.fem.mesh_degree import QuarterPointError, quarter_points
from asterlite.fem.selection import (
    as_tuple,
    cell_group_members,
    named_nodes,
    node_group_members,
    select_cells,
)
from asterlite.fem.shell_orientation import ShellOrientationError, orient_shells
from asterlite.fem.skin import SkinError, is_plane, orient_edges, orient_skin

_SUPPORTED = (
    *("ECHELLE", "TRANSLATION", "ROTATION", "SYMETRIE", "DEFORME", "ORIE_PEAU"),
    *("ORIE_NORM_COQUE", "ABSC_CURV", "MODI_MAILLE"),
)
# code_aster 15's name of ORIE_PEAU for 3D skins, and its keywords
_SKIN_KEYWORDS = {
    "ORIE_PEAU": ("GROUP_MA_PEAU", "GROUP_MA_INTERNE"),
    "ORIE_PEAU_3D": ("GROUP_MA", "GROUP_MA_VOLU"),
}


def _orient_skin(ctx, mesh, kw) -> None:
    """ORIE_PEAU: skin faces turned to point out of their volume cells."""

    plane = is_plane(mesh)
    for factor, (faces_key, volumes_key) in _SKIN_KEYWORDS.items():
        for occ in kw.factor(factor):
            if plane and factor == "ORIE_PEAU_3D":
                ctx.error("ORIE_PEAU_3D on a plane mesh", factor, occ)
            faces = cell_group_members(ctx, occ, mesh, faces_key)
            volumes = (
                cell_group_members(ctx, occ, mesh, volumes_key) if occ.get(volumes_key) else None
            )
            alone: list[int] = []
            try:
                if plane:  # code_aster: a mesh with constant Z has edges as skin
                    count = orient_edges(mesh, faces, volumes, alone)
                else:
                    count = orient_skin(mesh, faces, volumes, alone)
            except SkinError as exc:
                ctx.error(str(exc), faces_key, occ)
            what = "edges" if plane else "faces"
            ctx.log(f"{factor}: {count} of {len(faces)} {what} reversed")
            if alone:
                inside = "surface" if plane else "volume"
                ctx.log(
                    f"warning: {factor}: {len(alone)} {what} bound no {inside} cell and are "
                    f"left as they are (the first: {mesh.cell_names[alone[0]]})"
                )


def _orient_shells(ctx, mesh, kw) -> None:
    """ORIE_NORM_COQUE: each GROUP_MA's shell cells turned to one normal,
    along VECT_NORM at the node given (the first of GROUP_NO; without it the
    first node of the first cell), else as the group's first cell."""
    for occ in kw.factor("ORIE_NORM_COQUE"):
        groups = as_tuple(occ["GROUP_MA"])
        vector = occ.get("VECT_NORM")
        node = None
        if vector is not None:
            vector = _vector(vector)
            if occ.get("GROUP_NO") is not None:
                node = node_group_members(ctx, occ, mesh)[0]
            elif occ.get("NOEUD") is not None:
                node = mesh.find_node(as_tuple(occ["NOEUD"])[0])
                if node is None:
                    ctx.error(f"the mesh has no node {occ['NOEUD']!r}", "NOEUD", occ)
        for group in groups:
            cells = cell_group_members(ctx, {"GROUP_MA": group}, mesh)
            start = node if node is not None or not cells else mesh.cell_nodes[cells[0]][0]
            try:
                count = orient_shells(mesh, cells, vector, start)
            except ShellOrientationError as exc:
                ctx.error(f"group {group}: {exc}", "GROUP_MA", occ)
            ctx.log(f"ORIE_NORM_COQUE: {count} of {len(cells)} cells of {group} reversed")


def _vector(values, dim: int = 3) -> np.ndarray:
    v = np.zeros(3)
    values = np.atleast_1d(np.asarray(as_tuple(values), dtype=float))
    v[: min(values.size, dim)] = values[:dim]
    return v


def rotation_matrix(axis, angle_degrees: float) -> np.ndarray:
    """Rotation by ``angle_degrees`` about the unit vector ``axis`` (Rodrigues)."""
    k = np.asarray(axis, dtype=float)
    k = k / np.linalg.norm(k)
    a = np.radians(angle_degrees)
    cross = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    return np.eye(3) + np.sin(a) * cross + (1.0 - np.cos(a)) * cross @ cross


def _rotate(ctx, mesh, occ) -> None:
    p1 = _vector(occ["POIN_1"])
    if occ.get("POIN_2") is not None:
        axis = _vector(occ["POIN_2"]) - p1
    elif occ.get("DIR") is not None:
        axis = _vector(occ["DIR"])
    elif mesh.dim == 2:
        axis = np.array([0.0, 0.0, 1.0])
    else:
        ctx.error("ROTATION of a 3D mesh needs DIR or POIN_2", "DIR", occ)
    if not np.linalg.norm(axis) > 0.0:
        ctx.error("the rotation axis is a zero vector", "DIR", occ)
    r = rotation_matrix(axis, float(occ.get("ANGLE", 0.0)))
    mesh.coords[:] = (mesh.coords - p1) @ r.T + p1


def _mirror(ctx, mesh, occ) -> None:
    point = _vector(occ["POINT"])
    if mesh.dim == 2:
        along = _vector(occ["AXE_1"])
        normal = np.array([-along[1], along[0], 0.0])
    else:
        if occ.get("AXE_2") is None:
            ctx.error("SYMETRIE of a 3D mesh needs AXE_2", "AXE_2", occ)
        normal = np.cross(_vector(occ["AXE_1"]), _vector(occ["AXE_2"]))
    norm = np.linalg.norm(normal)
    if not norm > 0.0:
        ctx.error("the symmetry axes do not define a plane", "AXE_1", occ)
    n = normal / norm
    distance = (mesh.coords - point) @ n
    mesh.coords[:] = mesh.coords - 2.0 * distance[:, None] * n


def lehmer_uniform(count: int, seed: int = 24331) -> np.ndarray:
    """``count`` numbers in (0, 1) of the minimal-standard Lehmer generator
    (multiplier 16807, modulus 2**31 - 1) that code_aster's ggubs draws,
    starting from its seed; each is the new state over 2**31."""
    out = np.empty(count)
    state = seed
    for i in range(count):
        state = state * 16807 % 2147483647
        out[i] = state / 2147483648.0
    return out


def _random_shift(mesh, alea: float) -> None:
    """DEFORME ALEA as code_aster's modi_alea: node by node, x, y and z move by
    (2 r - 1) * ALEA * (the mesh's extent along that axis), r drawn in turn
    from one generator seeded 24331 (three draws per node whatever the
    dimension, so a 2D mesh moves as code_aster moves it)."""
    coords = mesh.coords
    extent = np.zeros(3)
    extent[: coords.shape[1]] = coords.max(axis=0) - coords.min(axis=0)
    draws = lehmer_uniform(3 * mesh.n_nodes).reshape(mesh.n_nodes, 3)
    shift = 2.0 * (draws - 0.5) * (alea * extent)
    coords[:] = coords + shift[:, : coords.shape[1]]


def _deforme(ctx, mesh, occ) -> None:
    if occ.get("ALEA") is not None:
        _random_shift(mesh, float(occ["ALEA"]))
        return
    field = occ["DEPL"]
    numbering = field.numbering
    if numbering.mesh is not mesh:
        ctx.error("DEPL is a field on another mesh", "DEPL", occ)
    for axis, comp in enumerate(("DX", "DY", "DZ")):
        rows = numbering.dof_indices(np.arange(mesh.n_nodes), comp)
        present = rows >= 0
        mesh.coords[present, axis] += field.values[rows[present]]


def _abscissa(ctx, mesh, occ) -> None:
    """ABSC_CURV: the abscissa carte of the chosen cells from the origin node."""
    origin_key = "GROUP_NO_ORIG" if occ.get("GROUP_NO_ORIG") is not None else "NOEUD_ORIG"
    if origin_key == "GROUP_NO_ORIG":
        origin = node_group_members(ctx, occ, mesh, origin_key)
    else:
        origin = named_nodes(ctx, occ, mesh, origin_key)
    if len(origin) != 1:
        ctx.error(f"{origin_key} must name exactly one node ({len(origin)} given)", origin_key, occ)
    cells = select_cells(ctx, occ, mesh)
    try:
        carte = curvilinear_abscissa(mesh, cells, origin[0])
    except AbscissaError as exc:
        ctx.error(str(exc), "GROUP_MA" if occ.get("GROUP_MA") else "TOUT", occ)
    if mesh.curvilinear_abscissa is not None:
        ctx.log("ABSC_CURV: the mesh's former curvilinear abscissa is replaced")
    mesh.curvilinear_abscissa = carte
    length = max((max(v) for v in carte.values()), default=0.0)
    ctx.log(f"ABSC_CURV: {len(carte)} cells, line length {length:.6g}")


def _noeud_quart(ctx, mesh, occ) -> None:
    """MODI_MAILLE OPTION='NOEUD_QUART' with a front of nodes (GROUP_NO_FOND,
    NOEUD_FOND): quarter-point cells around it; a front of cells
    (GROUP_MA_FOND, MAILLE_FOND) is refused by name."""
    for keyword in ("GROUP_MA_FOND", "MAILLE_FOND"):
        if occ.get(keyword) is not None:
            ctx.unsupported(f"MODI_MAILLE NOEUD_QUART with {keyword}", keyword, occ)
    front = node_group_members(ctx, occ, mesh, "GROUP_NO_FOND")
    front += named_nodes(ctx, occ, mesh, "NOEUD_FOND")
    try:
        count = quarter_points(mesh, list(dict.fromkeys(front)))
    except QuarterPointError as exc:
        ctx.error(str(exc), "GROUP_NO_FOND", occ)
    ctx.log(f"NOEUD_QUART: middle nodes of {count} cells moved to the quarter points")


def run(ctx, kw):
    mesh = kw["MAILLAGE"]
    for occ in kw.factor("MODI_MAILLE"):
        _noeud_quart(ctx, mesh, occ)
    # code_aster order: deformation, translation, rotation, symmetry, scale
    for occ in kw.factor("DEFORME"):
        _deforme(ctx, mesh, occ)
    if kw.get("TRANSLATION") is not None:
        mesh.coords[:] = mesh.coords + _vector(kw["TRANSLATION"], mesh.dim)
    for occ in kw.factor("ROTATION"):
        _rotate(ctx, mesh, occ)
    for occ in kw.factor("SYMETRIE"):
        _mirror(ctx, mesh, occ)
    if kw.get("ECHELLE") is not None:
        mesh.coords[:] = mesh.coords * float(kw["ECHELLE"])
    _orient_skin(ctx, mesh, kw)
    _orient_shells(ctx, mesh, kw)
    for occ in kw.factor("ABSC_CURV"):
        _abscissa(ctx, mesh, occ)
    done = [k for k in _SUPPORTED if kw.get(k)]
    ctx.log(f"mesh modified: {', '.join(done)}")
    return mesh
