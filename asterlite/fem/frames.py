"""Local frames: rotation matrices from nautical angles and segment directions.

A rotation matrix ``P`` maps global components to local ones
(``u_local = P @ u_global``); its rows are the local axes in global
coordinates. Nautical angles (alpha, beta, gamma) are code_aster's: a turn
alpha about Z, then beta about the new Y (positive beta tilts x *down*, so
beta = -asin(x_z)), then gamma (the "vrille") about the new x.
"""

from __future__ import annotations

import numpy as np


def rotation_from_angles(angles) -> np.ndarray:
    """(..., 3) nautical angles in radians -> (..., 3, 3) global-to-local rotations."""
    a = np.asarray(angles, dtype=float)
    ca, sa = np.cos(a[..., 0]), np.sin(a[..., 0])
    cb, sb = np.cos(a[..., 1]), np.sin(a[..., 1])
    cg, sg = np.cos(a[..., 2]), np.sin(a[..., 2])
    p = np.empty(a.shape[:-1] + (3, 3))
    p[..., 0, 0] = cb * ca
    p[..., 0, 1] = cb * sa
    p[..., 0, 2] = -sb
    p[..., 1, 0] = sg * sb * ca - cg * sa
    p[..., 1, 1] = sg * sb * sa + cg * ca
    p[..., 1, 2] = sg * cb
    p[..., 2, 0] = cg * sb * ca + sg * sa
    p[..., 2, 1] = cg * sb * sa - sg * ca
    p[..., 2, 2] = cg * cb
    return p


def angles_from_axis(x_axis, gamma=0.0) -> np.ndarray:
    """(..., 3) direction vectors -> (..., 3) nautical angles giving that local x.

    Zero vectors give zero angles (the global frame), as for a zero-length
    segment without ORIENTATION.
    """
    v = np.asarray(x_axis, dtype=float)
    norm = np.linalg.norm(v, axis=-1)
    safe = np.where(norm > 0, norm, 1.0)
    horizontal = np.hypot(v[..., 0], v[..., 1])
    alpha = np.where(horizontal > 1e-14 * safe, np.arctan2(v[..., 1], v[..., 0]), 0.0)
    beta = -np.arctan2(v[..., 2], horizontal)
    gamma = np.broadcast_to(np.asarray(gamma, dtype=float), alpha.shape)
    out = np.stack([alpha, beta, gamma], axis=-1)
    return np.where((norm > 0)[..., None], out, 0.0)


def angles_from_x_and_y(x_axis, y_hint) -> np.ndarray:
    """Nautical angles of a frame whose x is ``x_axis`` and whose y lies in the
    plane (x_axis, y_hint) (code_aster's VECT_Y / VECT_X_Y)."""
    angles = angles_from_axis(x_axis)
    p = rotation_from_angles(angles)
    y = np.asarray(y_hint, dtype=float)
    # components of y_hint in the gamma=0 local frame: gamma turns y towards it
    y_local = np.einsum("...ij,...j->...i", p, y)
    angles[..., 2] = np.arctan2(y_local[..., 2], y_local[..., 1])
    return angles


def block_rotation(p: np.ndarray, components: tuple[str, ...], n_nodes: int) -> np.ndarray:
    """(n, 3, 3) rotations -> (n, d, d) block-diagonal operator on an element's DOFs.

    Translations (DX DY DZ) and rotations (DRX DRY DRZ) rotate as vectors;
    in 2D (DX DY [DRZ]) the in-plane 2x2 block is used and DRZ is unchanged.
    """
    n = p.shape[0]
    per_node = len(components)
    r = np.zeros((n, per_node, per_node))
    idx = {c: k for k, c in enumerate(components)}
    for triple in (("DX", "DY", "DZ"), ("DRX", "DRY", "DRZ")):
        present = [c for c in triple if c in idx]
        if len(present) == 3:
            _place(r, [idx[c] for c in triple], p)
        elif present == ["DX", "DY"]:
            _place(r, [idx["DX"], idx["DY"]], p[:, :2, :2])
    for c in components:
        if c in ("DRZ",) and "DRX" not in idx:
            r[:, idx[c], idx[c]] = 1.0
        if c not in ("DX", "DY", "DZ", "DRX", "DRY", "DRZ"):
            r[:, idx[c], idx[c]] = 1.0
    d = per_node * n_nodes
    out = np.zeros((n, d, d))
    for a in range(n_nodes):
        s = slice(a * per_node, (a + 1) * per_node)
        out[:, s, s] = r
    return out


def _place(target: np.ndarray, rows: list[int], block: np.ndarray) -> None:
    for i, ri in enumerate(rows):
        for j, rj in enumerate(rows):
            target[:, ri, rj] = block[:, i, j]
