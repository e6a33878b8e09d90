"""Local frame of a shock connection (R5.06.03 §6.2), set up once in numpy.

The local x axis is the obstacle's normal; two nautical angles (alpha about Z, beta
about the new Y) bring the global X onto it, and a third angle gamma (about
the local x) fixes y_loc and z_loc. code_aster's choice of gamma:

- a twist angle given: gamma = that angle (degrees);
- otherwise, BI_PLAN_Y: y_loc follows the projection of node1 -> node2;
  BI_PLAN_Z: z_loc follows node1 -> node2 (y_loc = z_dir x normal);
  every other type: gamma = 0.
"""

from __future__ import annotations

import math

import numpy as np

TINY = np.finfo(np.float64).tiny


def nautical_angles(x_axis) -> tuple[float, float]:
    """(alpha, beta) in radians bringing the global X onto ``x_axis``."""
    gx, gy, gz = (float(c) for c in x_axis)
    alpha = 0.0 if abs(gx) <= TINY and abs(gy) <= TINY else math.atan2(gy, gx)
    p = math.hypot(gx, gy)
    beta = 0.0 if abs(gz) <= TINY and p <= TINY else -math.atan2(gz, p)
    return alpha, beta


def rotation_matrix(alpha: float, beta: float, gamma: float) -> np.ndarray:
    """Global -> local rotation R = R_x(gamma) R_y(beta) R_z(alpha).

    Entries below 1e-6 in each elementary rotation are zeroed as code_aster
    does, so that right angles give exact zeros (cos(pi/2) = 6e-17).
    """
    ca, sa = math.cos(alpha), math.sin(alpha)
    cb, sb = math.cos(beta), math.sin(beta)
    cg, sg = math.cos(gamma), math.sin(gamma)
    about_z = np.array([[ca, sa, 0.0], [-sa, ca, 0.0], [0.0, 0.0, 1.0]])
    about_y = np.array([[cb, 0.0, -sb], [0.0, 1.0, 0.0], [sb, 0.0, cb]])
    about_x = np.array([[1.0, 0.0, 0.0], [0.0, cg, sg], [0.0, -sg, cg]])
    for r in (about_z, about_y, about_x):
        r[np.abs(r) < 1.0e-6] = 0.0
    return about_x @ about_y @ about_z


def vrille_towards(x_axis, direction) -> float:
    """Angle gamma making y_loc the projection of ``direction`` on the plane normal to x."""
    alpha, beta = nautical_angles(x_axis)
    g = rotation_matrix(alpha, beta, 0.0) @ np.asarray(direction, dtype=float)
    if abs(g[2]) <= TINY and abs(g[1]) <= TINY:
        return 0.0
    return math.atan2(g[2], g[1])


def local_frame(obstacle_type: str, norm_obst, angl_vril_deg, coord1, coord2=None) -> np.ndarray:
    """Global -> local rotation of one shock, following code_aster's rules."""
    x_axis = np.asarray(norm_obst, dtype=float)
    alpha, beta = nautical_angles(x_axis)
    if angl_vril_deg is not None:
        gamma = math.radians(float(angl_vril_deg))
    elif obstacle_type == "BI_PLAN_Y":
        gamma = vrille_towards(x_axis, np.asarray(coord2) - np.asarray(coord1))
    elif obstacle_type == "BI_PLAN_Z":
        z_dir = np.asarray(coord2, dtype=float) - np.asarray(coord1, dtype=float)
        gamma = vrille_towards(x_axis, np.cross(z_dir, x_axis))
    else:
        gamma = 0.0
    return rotation_matrix(alpha, beta, gamma)


def default_origin(coord1, coord2=None) -> np.ndarray:
    """The obstacle's origin when the deck gives none: mid-point of the two
    nodes (BI_*); for a single node code_aster takes half of the node's coordinates (its own rule,
    reproduced as is so decks relying on it behave the same)."""
    c1 = np.asarray(coord1, dtype=float)
    if coord2 is None:
        return 0.5 * c1
    return 0.5 * (c1 + np.asarray(coord2, dtype=float))


def rest_side_signs(rot, origin, coord1, coord2=None) -> tuple[float, float]:
    """-sign of (node1 - node2) local y and z at rest: the side node 2 lies on
    for BI_PLAN_Y/BI_PLAN_Z (node 1 alone for single-node obstacles)."""
    d = rot @ (np.asarray(coord1, dtype=float) - origin)
    if coord2 is not None:
        d = d - rot @ (np.asarray(coord2, dtype=float) - origin)
    return (-1.0 if d[1] >= 0.0 else 1.0), (-1.0 if d[2] >= 0.0 else 1.0)
