"""Laplace forces on beam conductors: AFFE_CHAR_MECA/FORCE_ELEC, computed as
code_aster's element routine for CHAR_MECA_FRELEC (te0145) does.

The load gives a force per unit length *without* the currents: its value in
time, ``mu0 i1(t) i2(t) / (2 pi)``, is the FONC_MULT the load is multiplied
by (DEFI_FONC_ELEC builds it). The second conductor is given as

- ``DIRECT`` (no POSITION): the force per unit length (FX, FY, FZ) itself;
- ``TRANS`` (POSITION='PARA', TRANS): a parallel conductor, the cell moved by
  TRANS; force ``1/d`` with d the distance between the two;
- ``DIST`` (POSITION='PARA', DIST, POINT2): a parallel conductor at the
  distance DIST, through POINT2; force ``1/DIST`` towards it;
- ``INFINITE`` (POSITION='INFI', POINT1, POINT2): an infinite straight
  conductor through the two points, field ``1/d``;
- ``FINITE`` (POSITION='FINI'): the segment POINT1-POINT2, field
  ``(cos a1 - cos a2) / (2 d)`` (Biot and Savart for a finite segment).

The element axis, from the cell's first node to its second, is the current's
direction in the conductor; POINT1 to POINT2 that of the second conductor:
currents of the same sign attract. Uniform loads (DIRECT, TRANS, DIST) give
the cubic beam's consistent nodal forces and end moments (``q L / 2``,
``+/- q L^2 / 12``); the field of a second conductor at any position is
integrated at 100 midpoints along the cell with the cubic beam's shape
functions. code_aster's te0145 walks those points from the second node to
the first while weighting them with the shape functions of the first node,
which mirrors a varying load end for end; asterlite computes the same
vector, so that its results match code_aster's (a uniform load is left
unchanged by the mirroring).

Vectors are in the global frame: (force, moment) at the first node then the
second, 12 values per cell.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.fem.elements import ElementError

#: the second conductor's forms (see the module docstring)
DIRECT, TRANS, DIST, INFINITE, FINITE = "DIRECT", "TRANS", "DIST", "INFINITE", "FINITE"

#: integration points along a cell for INFINITE and FINITE (code_aster's count)
_SAMPLES = 100
#: below this |e x F| the DIRECT force is taken as axial (code_aster's absolute bound)
_AXIAL_BOUND = 1.0e-3
#: a point closer to the second conductor's line than this fraction of its
#: distance to POINT1 is on the line and adds nothing
_ON_LINE = 1.0e-8


@dataclass(frozen=True)
class SecondConductor:
    """One FORCE_ELEC occurrence: ``kind`` and its two vectors (FX FY FZ or
    TRANS or (DIST, 0, 0) in ``first``; POINT2 in ``second`` for DIST;
    POINT1 and POINT2 for INFINITE and FINITE)."""

    kind: str
    first: tuple[float, float, float]
    second: tuple[float, float, float] = (0.0, 0.0, 0.0)


def laplace_vectors(x1, x2, conductor: SecondConductor, names=None) -> np.ndarray:
    """(n, 12) global nodal forces and moments of the cells from x1 to x2
    ((n, 3) coordinates of their first and second nodes); ``names`` (the
    cells' names) for messages."""
    x1 = np.asarray(x1, dtype=float)
    x2 = np.asarray(x2, dtype=float)
    axis = x2 - x1
    length = np.linalg.norm(axis, axis=1)
    if np.any(length == 0.0):
        raise ElementError(
            f"FORCE_ELEC on a cell of zero length ({_first_name(names, length == 0)})"
        )
    e = axis / length[:, None]
    first = np.asarray(conductor.first, dtype=float)
    second = np.asarray(conductor.second, dtype=float)
    if conductor.kind == DIRECT:
        return _direct(e, length, first)
    if conductor.kind == TRANS:
        return _parallel(e, length, -np.broadcast_to(first, e.shape), None, names)
    if conductor.kind == DIST:
        middle = 0.5 * x2 + 0.5 * x1
        return _parallel(e, length, middle - second, float(first[0]), names)
    if conductor.kind in (INFINITE, FINITE):
        return _line(x1, x2, e, length, first, second, conductor.kind == FINITE, names)
    raise ValueError(f"unknown second conductor {conductor.kind!r}")


def _first_name(names, mask) -> str:
    if names is None:
        return "cell"
    return str(np.asarray(names, dtype=object)[np.asarray(mask)][0])


def _uniform(length, force, moment_axis, moment_scale) -> np.ndarray:
    """Consistent loads of a uniform force per unit length ``force`` (n, 3):
    half of it on each node, end moments ``+/- scale L^2 / 12`` about
    ``moment_axis``."""
    out = np.zeros((len(length), 12))
    half = 0.5 * length[:, None] * force
    moment = (moment_scale * length**2 / 12.0)[:, None] * moment_axis
    out[:, 0:3] = half
    out[:, 3:6] = moment
    out[:, 6:9] = half
    out[:, 9:12] = -moment
    return out


def _direct(e, length, force) -> np.ndarray:
    """FX, FY, FZ: axial part and transverse part of the given force."""
    force = np.broadcast_to(force, e.shape)
    w = np.cross(e, force)
    wm = np.linalg.norm(w, axis=1)
    out = np.zeros((len(length), 12))
    axial = wm < _AXIAL_BOUND
    out[axial, 0:3] = 0.5 * length[axial, None] * force[axial]
    out[axial, 6:9] = out[axial, 0:3]
    bent = ~axial
    if bent.any():
        w_hat = w[bent] / wm[bent, None]
        v = np.cross(w_hat, e[bent])
        along = np.einsum("ij,ij->i", force[bent], e[bent])
        across = np.einsum("ij,ij->i", force[bent], v)
        transverse = along[:, None] * e[bent] + across[:, None] * v
        out[bent] = _uniform(length[bent], transverse, w_hat, across)
    return out


def _parallel(e, length, r, distance, names) -> np.ndarray:
    """TRANS (``r`` = -TRANS, d its distance across the axis) and DIST (``r``
    from POINT2 to the cell's middle, d = DIST): 1/d towards the conductor."""
    b = np.cross(e, r)
    across = np.linalg.norm(b, axis=1)
    d = across if distance is None else np.full(len(e), distance)
    u = np.cross(e, b)
    norm = np.linalg.norm(u, axis=1)
    if np.any(norm == 0.0) or np.any(d == 0.0):
        bad = (norm == 0.0) | (d == 0.0)
        what = "TRANS is along" if distance is None else "POINT2 is on the axis of"
        raise ElementError(
            f"FORCE_ELEC POSITION='PARA': {what} the cell {_first_name(names, bad)} (or DIST "
            "is zero): no direction or distance between the conductors"
        )
    u = u / norm[:, None]
    w = np.cross(e, u)
    return _uniform(length, u / d[:, None], w, 1.0 / d)


def _line(x1, x2, e, length, p1, p2, finite, names) -> np.ndarray:
    """INFINITE and FINITE: the field of the line P1 P2 integrated at the
    cell's midpoints (see the module docstring for the walk's direction)."""
    span = p2 - p1
    if not np.linalg.norm(span) > 0.0:
        raise ElementError("FORCE_ELEC: POINT1 and POINT2 are the same point")
    f = span / np.linalg.norm(span)
    alpha = (np.arange(1, _SAMPLES + 1) - 0.5) / _SAMPLES  # (m,)
    points = x2[:, None, :] * (1.0 - alpha)[None, :, None] + x1[:, None, :] * alpha[None, :, None]
    q = points - p1  # (n, m, 3)
    r = points - p2
    b = np.cross(f, q)
    d = np.linalg.norm(b, axis=2)
    q_norm = np.linalg.norm(q, axis=2)
    with np.errstate(invalid="ignore", divide="ignore"):
        on_line = ~(d / np.where(q_norm > 0.0, q_norm, 1.0) >= _ON_LINE) | (q_norm == 0.0)
    d_safe = np.where(on_line, 1.0, d)
    b_hat = b / d_safe[..., None]
    u = np.cross(e[:, None, :], b_hat)
    um = np.linalg.norm(u, axis=2)
    if np.any((um == 0.0) & ~on_line):
        cell = np.any((um == 0.0) & ~on_line, axis=1)
        raise ElementError(
            f"FORCE_ELEC: the cell {_first_name(names, cell)} lies along the field of the "
            "second conductor at some point: code_aster's direction of the moment is undefined "
            "there (a division by zero)"
        )
    v = u / np.where(um > 0.0, um, 1.0)[..., None]
    w = np.cross(e[:, None, :], v)
    if finite:
        q_hat = q / np.where(q_norm > 0.0, q_norm, 1.0)[..., None]
        r_norm = np.linalg.norm(r, axis=2)
        r_hat = r / np.where(r_norm > 0.0, r_norm, 1.0)[..., None]
        cosines = np.einsum("k,nmk->nm", f, q_hat - r_hat)
        s = cosines * 5.0e-3 * length[:, None] / d_safe
    else:
        s = 0.01 * length[:, None] / d_safe
    s = np.where(on_line, 0.0, s)
    a2, a3 = alpha**2, alpha**3
    shapes = (
        1.0 - 3.0 * a2 + 2.0 * a3,  # force, first node
        alpha - 2.0 * a2 + a3,  # moment, first node (times L)
        3.0 * a2 - 2.0 * a3,  # force, second node
        -a2 + a3,  # moment, second node (times L)
    )
    out = np.zeros((len(length), 12))
    for k, (shape, vectors, scale) in enumerate(
        zip(shapes, (u, w, u, w), (1.0, length, 1.0, length), strict=True)
    ):
        weights = s * shape[None, :]
        out[:, 3 * k : 3 * k + 3] = np.einsum("nm,nmk->nk", weights, vectors) * np.reshape(
            scale, (-1, 1)
        )
    return out
