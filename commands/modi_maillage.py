"""MODI_MAILLAGE: change node coordinates in place (ECHELLE, TRANSLATION,
ROTATION, SYMETRIE, DEFORME) or the orientation of skin faces (ORIE_PEAU);
the mesh is returned (reuse)."""

from __future__ import annotations

import numpy as np

from asterlite.fem.selection import as_tuple, cell_group_members
from asterlite.fem.skin import SkinError, is_plane, orient_edges, orient_skin

_SUPPORTED = ("ECHELLE", "TRANSLATION", "ROTATION", "SYMETRIE", "DEFORME", "ORIE_PEAU")
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
            try:
                if plane:  # code_aster: a mesh with constant Z has edges as skin
                    count = orient_edges(mesh, faces, volumes)
                else:
                    count = orient_skin(mesh, faces, volumes)
            except SkinError as exc:
                ctx.error(str(exc), faces_key, occ)
            what = "edges" if plane else "faces"
            ctx.log(f"{factor}: {count} of {len(faces)} {what} reversed")


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


def _deforme(ctx, mesh, occ) -> None:
    if occ.get("ALEA") is not None:
        # a small reproducible perturbation of every coordinate in [-ALEA, ALEA]
        amplitude = float(occ["ALEA"])
        rng = np.random.default_rng(0)
        shift = rng.uniform(-amplitude, amplitude, size=mesh.coords.shape)
        shift[:, mesh.dim :] = 0.0
        mesh.coords[:] = mesh.coords + shift
        return
    field = occ["DEPL"]
    numbering = field.numbering
    if numbering.mesh is not mesh:
        ctx.error("DEPL is a field on another mesh", "DEPL", occ)
    for axis, comp in enumerate(("DX", "DY", "DZ")):
        rows = numbering.dof_indices(np.arange(mesh.n_nodes), comp)
        present = rows >= 0
        mesh.coords[present, axis] += field.values[rows[present]]


def run(ctx, kw):
    mesh = kw["MAILLAGE"]
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
    done = [k for k in _SUPPORTED if kw.get(k)]
    ctx.log(f"mesh modified: {', '.join(done)}")
    return mesh
