"""Plate fields between the frames of a DKT cell, as code_aster's
MODI_REPERE changes them for REPERE='COQUE', 'COQUE_INTR_UTIL' and
'COQUE_UTIL_INTR' (its chrpel, chrpan and the plates' te0442).

Each cell has three in-plane frames sharing its normal:

- the intrinsic frame (code_aster's dxtpgl / dxqpgl, here
  :func:`asterlite.fem.plate_elements.local_frames`);
- the user frame of AFFE_CARA_ELEM/COQUE, whose x axis is the projection on
  the cell's plane of the direction ANGL_REP (alpha, beta) or VECTEUR
  (coqrep), the frame fields are computed in;
- for REPERE='COQUE', the frame MODI_REPERE's AFFE gives the same way
  (ANGL_REP or VECTEUR; (0, 0) on the cells AFFE does not name).

A field of generalised quantities (NXX NYY NXY MXX MYY MXY QX QY, or the
strains EXX ... GAY) turns its two in-plane tensors and its shear vector;
a stress or strain tensor (SIXX SIYY SIZZ SIXY SIXZ SIYZ) its in-plane
tensor and its transverse shear vector, SIZZ unchanged (dxefro, dxsiro).
Values are linear in the fields, so complex fields turn the same way.
"""

from __future__ import annotations

import numpy as np

from asterlite.fem.plate_elements import local_frames
from asterlite.fem.plate_fields import output_axes

# the in-plane tensors (xx, yy, xy) and vectors (x, y) of each layout
GENERALISED = (((0, 1, 2), (3, 4, 5)), ((6, 7),))
TENSOR = (((0, 1, 3),), ((4, 5),))


def angles_from_vector(vector) -> tuple[float, float]:
    """(alpha, beta) in degrees of a direction (code_aster's angvx)."""
    x, y, z = (float(v) for v in vector)
    tiny = np.finfo(float).tiny
    alpha = 0.0 if abs(x) <= tiny and abs(y) <= tiny else np.arctan2(y, x)
    p = np.hypot(x, y)
    beta = 0.0 if abs(z) <= tiny and p <= tiny else -np.arctan2(z, p)
    return float(np.degrees(alpha)), float(np.degrees(beta))


def frame_axes(mesh, cells, angles) -> tuple[np.ndarray, np.ndarray]:
    """(cos, sin) of the x axis given by ``angles`` (n_cells, 2; degrees) in
    each cell's intrinsic frame."""
    angles = np.asarray(angles, dtype=float).reshape(-1, 2)
    counts = np.array([len(mesh.cell_nodes[int(c)]) for c in cells])
    c, s = np.zeros(len(cells)), np.zeros(len(cells))
    for count in np.unique(counts):  # triangles and quadrangles apart
        rows = np.flatnonzero(counts == count)
        coords = np.stack([mesh.coords[list(mesh.cell_nodes[int(cells[r])])] for r in rows])
        c[rows], s[rows] = output_axes(local_frames(coords), angles[rows])
    return c, s


def rotate_in_plane(values: np.ndarray, layout, c: np.ndarray, s: np.ndarray) -> np.ndarray:
    """``values`` (o, e, p, n_comp) expressed in the frame whose x axis is
    (c, s) (per cell, e) in the current one: x' = c x + s y, y' = -s x + c y."""
    c = np.asarray(c)[None, :, None]
    s = np.asarray(s)[None, :, None]
    out = np.array(values, copy=True)
    tensors, vectors = layout
    for xx_, yy_, xy_ in tensors:
        xx, yy, xy = values[..., xx_], values[..., yy_], values[..., xy_]
        out[..., xx_] = c * c * xx + s * s * yy + 2.0 * c * s * xy
        out[..., yy_] = s * s * xx + c * c * yy - 2.0 * c * s * xy
        out[..., xy_] = -c * s * xx + c * s * yy + (c * c - s * s) * xy
    for x_, y_ in vectors:
        x, y = values[..., x_], values[..., y_]
        out[..., x_] = c * x + s * y
        out[..., y_] = -s * x + c * y
    return out


def change_shell_frame(values, layout, repere: str, user, target=None) -> np.ndarray:
    """``values`` (o, e, p, n_comp) of fields in the cells' user frames
    (``user``: (c, s) per cell) expressed as ``repere`` asks: 'COQUE' in the
    ``target`` frames ((c, s) per cell), 'COQUE_INTR_UTIL' from the
    intrinsic frames to the user ones, 'COQUE_UTIL_INTR' back."""
    c1, s1 = user
    if repere == "COQUE_INTR_UTIL":
        return rotate_in_plane(values, layout, c1, s1)
    intrinsic = rotate_in_plane(values, layout, c1, -s1)
    if repere == "COQUE_UTIL_INTR":
        return intrinsic
    if repere != "COQUE":
        raise ValueError(repere)
    c2, s2 = target
    return rotate_in_plane(intrinsic, layout, c2, s2)
