"""Element matrices of discrete elements (``DIS_T``, ``DIS_TR``, ``2D_DIS_T``,
``2D_DIS_TR``) from ``AFFE_CARA_ELEM/DISCRET`` characteristics.

A characteristic name reads ``<K|M|A>_<T|TR>[_D]_<N|L>``: stiffness, mass or
damping; translations only or translations and rotations; diagonal or full
(symmetric, upper triangle given column by column); on a node (``POI1``)
or a link (``SEG2``). DOFs are ordered node by node, components in
code_aster's order (DX DY DZ DRX DRY DRZ, or DX DY DRZ in 2D).

Conventions follow code_aster: ``M_T_D_N`` and ``M_T_D_L`` give the mass m
to every translation of every node; ``M_TR_D_N`` = (m, Ixx, Iyy, Izz, Ixy,
Iyz, Ixz, ex, ey, ez) includes the eccentricity e of the centre of mass
(2D: m, Izz, ex, ey); ``M_TR_D_L`` = (m, Ixx, Iyy, Izz) (2D: m, Izz) on
both nodes; diagonal link stiffnesses k give the spring [[k, -k], [-k, k]].
"""

from __future__ import annotations

import re

import numpy as np

_CARA = re.compile(r"^([KMA])_(T|TR)(_D)?_([NL])$")


class DiscreteError(ValueError):
    """Inconsistent characteristic (wrong count, wrong cell, wrong modelisation)."""


def parse_cara(cara: str) -> tuple[str, str, bool, str]:
    """'K_TR_D_L' -> ('K', 'TR', True, 'L')."""
    m = _CARA.match(cara)
    if not m:
        raise DiscreteError(f"unknown discrete characteristic {cara}")
    return m.group(1), m.group(2), bool(m.group(3)), m.group(4)


def dofs_per_node(kind: str, dim: int) -> int:
    return {("T", 3): 3, ("TR", 3): 6, ("T", 2): 2, ("TR", 2): 3}[(kind, dim)]


def expected_count(cara: str, dim: int, symmetric: bool = True) -> int:
    """Number of VALE values code_aster expects for ``cara``."""
    matrix, kind, diagonal, support = parse_cara(cara)
    per_node = dofs_per_node(kind, dim)
    if diagonal:
        if matrix != "M":
            return per_node
        if kind == "T":
            return 1
        if support == "N":
            return 10 if dim == 3 else 4
        return 4 if dim == 3 else 2
    size = per_node * (1 if support == "N" else 2)
    return size * (size + 1) // 2 if symmetric else size * size


def unpack_upper(values, size: int) -> np.ndarray:
    """Symmetric matrix from its upper triangle given column by column."""
    v = np.asarray(values, dtype=float)
    rows, cols = [], []
    for j in range(size):
        for i in range(j + 1):
            rows.append(i)
            cols.append(j)
    a = np.zeros((size, size))
    a[rows, cols] = v
    a[cols, rows] = v
    return a


def unpack_full(values, size: int) -> np.ndarray:
    """Non-symmetric matrix given column by column."""
    return np.asarray(values, dtype=float).reshape(size, size).T.copy()


def _link(diagonal_values: np.ndarray) -> np.ndarray:
    """Two-node spring from per-component stiffnesses: [[D, -D], [-D, D]]."""
    d = np.diag(diagonal_values)
    return np.block([[d, -d], [-d, d]])


def _eccentric_mass_3d(v: np.ndarray) -> np.ndarray:
    m, ixx, iyy, izz, ixy, iyz, ixz, ex, ey, ez = v
    a = np.zeros((6, 6))
    a[0, 0] = a[1, 1] = a[2, 2] = m
    # coupling translation / rotation from the offset centre of mass
    a[1, 3] = -m * ez
    a[2, 3] = m * ey
    a[0, 4] = m * ez
    a[2, 4] = -m * ex
    a[0, 5] = -m * ey
    a[1, 5] = m * ex
    a[3, 3] = ixx + m * (ey * ey + ez * ez)
    a[4, 4] = iyy + m * (ex * ex + ez * ez)
    a[5, 5] = izz + m * (ex * ex + ey * ey)
    a[3, 4] = ixy - m * ex * ey
    a[4, 5] = iyz - m * ey * ez
    a[3, 5] = ixz - m * ex * ez
    return np.triu(a) + np.triu(a, 1).T


def _eccentric_mass_2d(v: np.ndarray) -> np.ndarray:
    m, izz, ex, ey = v
    a = np.zeros((3, 3))
    a[0, 0] = a[1, 1] = m
    a[0, 2] = a[2, 0] = m * ey
    a[1, 2] = a[2, 1] = -m * ex
    a[2, 2] = izz + m * (ex * ex + ey * ey)
    return a


def local_matrix(cara: str, values, dim: int, symmetric: bool = True) -> np.ndarray:
    """The element matrix (in the frame the values are given in) of one
    characteristic: (d, d) with d = DOFs per node x (1 for _N, 2 for _L)."""
    matrix, kind, diagonal, support = parse_cara(cara)
    v = np.atleast_1d(np.asarray(values, dtype=float))
    count = expected_count(cara, dim, symmetric)
    if v.size != count:
        raise DiscreteError(f"{cara} expects {count} values, got {v.size}")
    per_node = dofs_per_node(kind, dim)
    size = per_node * (1 if support == "N" else 2)
    if not diagonal:
        return unpack_upper(v, size) if symmetric else unpack_full(v, size)
    if matrix in "KA":
        return np.diag(v) if support == "N" else _link(v)
    # diagonal masses
    if kind == "T":
        return np.eye(size) * v[0]
    if support == "N":
        return _eccentric_mass_3d(v) if dim == 3 else _eccentric_mass_2d(v)
    m = v[0]
    inertia = v[1:]
    per = np.concatenate([[m] * (per_node - inertia.size), inertia])
    return np.diag(np.concatenate([per, per]))
