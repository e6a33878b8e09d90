"""DEFI_OBSTACLE: the shape of a shock connection (no dimensions)."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.transient import Obstacle
from asterlite.dynamics.model import OBSTACLE_CODES


def run(ctx, kw):
    kind = kw["TYPE"]
    if kind not in OBSTACLE_CODES:
        ctx.unsupported(
            f"obstacle TYPE={kind!r} (supported: {', '.join(OBSTACLE_CODES)})", "TYPE", kw
        )
    polar = None
    if kind == "DISCRET":
        polar = discrete_polygon(ctx, kw)
    return Obstacle(obstacle_type=kind, polar=polar)


def discrete_polygon(ctx, kw) -> np.ndarray:
    """VALE = (angle1, radius1, angle2, radius2, ...), angles in degrees in
    increasing order over [0, 360]: the concave polygon seen from its centre."""
    values = kw.get("VALE")
    if values is None:
        ctx.error("a DISCRET obstacle needs VALE=(angle, radius, ...)", "VALE", kw)
    values = np.asarray(values, dtype=float)
    if values.size < 4 or values.size % 2:
        ctx.error("VALE must hold (angle, radius) pairs, at least two", "VALE", kw)
    polar = values.reshape(-1, 2)
    if np.any(np.diff(polar[:, 0]) <= 0.0):
        ctx.error("DISCRET angles must increase", "VALE", kw)
    return polar
