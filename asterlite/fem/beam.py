"""Straight two-node beams and bars: element matrices and local frames.

Elements (code_aster names):

- ``POU_D_E``: Euler-Bernoulli beam, 6 DOF per node;
- ``POU_D_T``: Timoshenko beam, same DOFs, shear flexibility through the
  parameter ``phi = 12 E I AY / (G A L^2)`` (``AY``/``AZ`` are code_aster's
  shear coefficients, >= 1, see :mod:`asterlite.fem.sections`);
- ``POU_D_TG``: POU_D_T plus the warping DOF ``GRX`` (rate of twist) on
  each node: torsion with Saint-Venant ``G JX`` and warping ``E JG``
  stiffness from a cubic twist angle (code_aster's ptka21), no GRX mass;
- ``BARRE`` / ``2D_BARRE``: axial bars with translations only.

DOF order inside an element is node 1 then node 2, each
``DX DY DZ DRX DRY DRZ`` (``DX DY DZ`` for BARRE, ``DX DY`` for 2D_BARRE).
Local axes: x from node 1 to node 2, y and z the principal axes of the
section (IY is the second moment about y, bending in the xOz plane).

What code_aster does and this module follows:

- stiffness: the classical closed-form Timoshenko matrix (phi = 0 for
  POU_D_E), with the shear-centre offset EY/EZ applied as a change of
  reference point for the transverse displacements;
- consistent mass (MASS_MECA): the shear-dependent consistent mass with
  rotary inertia for POU_D_T; for POU_D_E (or a zero AY/AZ) the cubic
  consistent mass *without* rotary inertia. Torsional inertia uses the
  polar moment IY + IZ (not JX) in both cases;
- lumped mass (MASS_MECA_DIAG): half the mass at each node, torsion
  rho L (IY + IZ) / 2 and bending rotations rho A L^3 / 105 + 2 rho I L / 15;
- frame: nautical angles (alpha, beta) from the segment, gamma = 0 unless
  ORIENTATION gives ANGL_VRIL, VECT_Y or VECT_Z (see :func:`seg2_angles`);
  global matrices are ``R^T K R`` with ``R`` the block-diagonal rotation.

Every function is vectorised over elements: lengths and section values may
be arrays of shape (n,) or scalars.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from asterlite.fem.frames import rotation_from_angles

BEAM_COMPONENTS = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")
BAR_COMPONENTS = ("DX", "DY", "DZ")
BAR_2D_COMPONENTS = ("DX", "DY")

#: Components per node of each modelisation this module computes.
COMPONENTS = {
    "POU_D_E": BEAM_COMPONENTS,
    "POU_D_T": BEAM_COMPONENTS,
    "POU_D_TG": BEAM_COMPONENTS + ("GRX",),
    "BARRE": BAR_COMPONENTS,
    "2D_BARRE": BAR_2D_COMPONENTS,
}

# Local DOF indices (0-based) of the 12-DOF beam.
_U1, _V1, _W1, _RX1, _RY1, _RZ1, _U2, _V2, _W2, _RX2, _RY2, _RZ2 = range(12)

#: code_aster tests lengths and vector components against the smallest normal float.
_TINY = np.finfo(float).tiny


class BeamError(ValueError):
    """Element data a beam or bar cannot be computed with."""


def shear_modulus(young, poisson):
    """G = E / (2 (1 + nu)), as the beam elements compute it from ELAS."""
    return np.asarray(young, dtype=float) / (2.0 * (1.0 + np.asarray(poisson, dtype=float)))


# -- frames ---------------------------------------------------------------------


def segment_lengths(x1, x2) -> np.ndarray:
    """(n,) distances between node 1 and node 2 of each segment."""
    return np.linalg.norm(np.asarray(x2, float) - np.asarray(x1, float), axis=-1)


def segment_cells(mesh, cells) -> tuple[np.ndarray, np.ndarray]:
    """(n, 2) nodes and (n,) lengths of the two-node cells ``cells``."""
    conn = np.array([mesh.cell_nodes[c] for c in cells], dtype=int).reshape(-1, 2)
    return conn, segment_lengths(mesh.coords[conn[:, 0]], mesh.coords[conn[:, 1]])


def axis_angles(direction) -> np.ndarray:
    """(n, 2) nautical angles (alpha, beta) turning global X onto ``direction``.

    Like code_aster's ``angvx``: alpha = 0 for a vertical direction, beta
    positive when x points down; only exact zeros count as zero.
    """
    d = np.atleast_2d(np.asarray(direction, dtype=float))
    horizontal = np.hypot(d[:, 0], d[:, 1])
    flat = (np.abs(d[:, 0]) <= _TINY) & (np.abs(d[:, 1]) <= _TINY)
    alpha = np.where(flat, 0.0, np.arctan2(d[:, 1], d[:, 0]))
    null = flat & (np.abs(d[:, 2]) <= _TINY)
    beta = np.where(null, 0.0, -np.arctan2(d[:, 2], horizontal))
    return np.stack([alpha, beta], axis=-1)


def _gamma_towards(x_axis, hint, axis: str) -> np.ndarray:
    """Twist angle making local y (axis='Y') or z (axis='Z') lie in the plane
    (x_axis, hint), on the side of ``hint`` (code_aster's angvxy / angvxz)."""
    ab = axis_angles(x_axis)
    p0 = rotation_from_angles(np.column_stack([ab, np.zeros(len(ab))]))
    h = np.broadcast_to(np.asarray(hint, dtype=float), (len(ab), 3))
    local = np.einsum("eij,ej->ei", p0, h)
    parallel = (np.abs(local[:, 1]) <= _TINY) & (np.abs(local[:, 2]) <= _TINY)
    if axis == "Y":
        return np.where(parallel, 0.0, np.arctan2(local[:, 2], local[:, 1]))
    return np.where(parallel, np.pi / 2.0, np.arctan2(-local[:, 1], local[:, 2]))


def seg2_angles(x1, x2, cara: str | None = None, vale=None) -> np.ndarray:
    """(n, 3) nautical angles (radians) of beam segments from node 1 to node 2.

    ``cara``/``vale`` are an ``AFFE_CARA_ELEM/ORIENTATION`` occurrence:
    ``ANGL_VRIL`` (twist gamma in degrees), ``VECT_Y`` or ``VECT_Z`` (a vector
    whose projection normal to the beam gives local y, resp. z). Without
    one, gamma = 0: for a horizontal beam local z is then global Z; for a
    vertical one local y is global Y. ``ANGL_NAUT`` / ``VECT_X_Y`` only apply
    to zero-length segments, as in code_aster.
    """
    x1 = np.atleast_2d(np.asarray(x1, dtype=float))
    x2 = np.atleast_2d(np.asarray(x2, dtype=float))
    d = x2 - x1
    lengths = np.linalg.norm(d, axis=-1)
    angles = np.zeros((len(d), 3))
    angles[:, :2] = axis_angles(d)
    if cara is None:
        return angles
    cara = cara.upper()
    if cara in ("ANGL_VRIL", "VECT_Y", "VECT_Z") and np.any(lengths <= 0.0):
        raise BeamError(f"ORIENTATION {cara} needs segments of non-zero length")
    if cara == "ANGL_VRIL":
        angles[:, 2] = np.deg2rad(float(np.ravel(vale)[0]))
    elif cara in ("VECT_Y", "VECT_Z"):
        hint = np.asarray(vale, dtype=float).ravel()[:3]
        if not np.dot(hint, hint) > 0.0:
            raise BeamError(f"ORIENTATION {cara} needs a non-zero vector")
        angles[:, 2] = _gamma_towards(d, hint, cara[-1])
    elif cara in ("ANGL_NAUT", "VECT_X_Y"):
        raise BeamError(
            f"ORIENTATION {cara} cannot orient a beam segment of non-zero length "
            "(use ANGL_VRIL, VECT_Y or VECT_Z)"
        )
    else:
        raise BeamError(f"unknown ORIENTATION CARA '{cara}'")
    return angles


def element_rotation(rotations: np.ndarray, per_node: int, n_nodes: int = 2) -> np.ndarray:
    """(n, 3, 3) global-to-local rotations -> (n, d, d) block-diagonal operator.

    Each vector triple of each node (translations, then rotations when
    ``per_node`` is 6 or 7) turns with the same 3x3 block; ``per_node`` 2 is
    the plane case (DX, DY) using the in-plane 2x2 block. The seventh DOF of
    POU_D_TG's nodes (GRX, the rate of twist about the beam's own axis) is a
    scalar of the element's frame: it keeps its value.
    """
    p = np.asarray(rotations, dtype=float)
    if per_node == 2:
        p = p[:, :2, :2]
    size = p.shape[-1]
    vectors, scalars = divmod(per_node, size)
    node = np.zeros((len(p), per_node, per_node))
    for k in range(vectors):
        node[:, k * size : (k + 1) * size, k * size : (k + 1) * size] = p
    for k in range(vectors * size, per_node):
        node[:, k, k] = 1.0
    # kron(I, node block) for each element
    eye = np.eye(n_nodes)
    return np.einsum("ab,eij->eaibj", eye, node).reshape(len(p), per_node * n_nodes, -1)


def to_global(local: np.ndarray, rotations: np.ndarray, per_node: int) -> np.ndarray:
    """Element matrices from the local to the global frame: R^T A R."""
    r = element_rotation(rotations, per_node)
    return np.einsum("eji,ejk,ekl->eil", r, local, r)


# -- beam matrices in the local frame ----------------------------------------------


def _broadcast(length, *values):
    length = np.atleast_1d(np.asarray(length, dtype=float))
    if np.any(length <= 0.0):
        raise BeamError("beam element of zero length")
    out = np.broadcast_arrays(length, *(np.asarray(v, dtype=float) for v in values))
    return [np.array(v, dtype=float) for v in out]


def _symmetrise(upper: np.ndarray) -> np.ndarray:
    """Fill the lower triangle of matrices given by their upper triangle."""
    full = upper + np.swapaxes(upper, -1, -2)
    idx = np.arange(upper.shape[-1])
    full[..., idx, idx] -= upper[..., idx, idx]
    return full


def _offset_transform(ey, ez) -> np.ndarray:
    """(n, 12, 12) map from centroid DOFs to shear-centre transverse DOFs:
    v_c = v - EZ rx, w_c = w + EY rx (EY, EZ: shear centre minus centroid)."""
    n = len(ey)
    t = np.broadcast_to(np.eye(12), (n, 12, 12)).copy()
    for v, w, rx in ((_V1, _W1, _RX1), (_V2, _W2, _RX2)):
        t[:, v, rx] = -ez
        t[:, w, rx] = ey
    return t


def _apply_offset(mats: np.ndarray, ey, ez) -> np.ndarray:
    if not (np.any(ey) or np.any(ez)):
        return mats
    t = _offset_transform(ey, ez)
    return np.einsum("eji,ejk,ekl->eil", t, mats, t)


def beam_stiffness_local(
    length, young, shear, area, iy, iz, jx, ay=0.0, az=0.0, ey=0.0, ez=0.0
) -> np.ndarray:
    """(n, 12, 12) local stiffness of straight beams of constant section.

    ``ay`` / ``az`` are the shear coefficients (0: no shear deformation, the
    Euler-Bernoulli matrix). ``ay`` goes with bending in the xOy plane
    (IZ), ``az`` with the xOz plane (IY).
    """
    L, E, G, A, Iy, Iz, J, ay, az, ey, ez = _broadcast(
        length, young, shear, area, iy, iz, jx, ay, az, ey, ez
    )
    if np.any(G <= 0.0):
        raise BeamError("beam stiffness needs a positive shear modulus (check E and NU)")
    k = np.zeros((len(L), 12, 12))
    axial = E * A / L
    k[:, _U1, _U1] = k[:, _U2, _U2] = axial
    k[:, _U1, _U2] = -axial
    torsion = G * J / L
    k[:, _RX1, _RX1] = k[:, _RX2, _RX2] = torsion
    k[:, _RX1, _RX2] = -torsion
    # bending in xOy: (v, rz); in xOz: (w, ry), where ry = -dw/dx flips signs
    for (t1, r1, t2, r2), inertia, coef, sign in (
        ((_V1, _RZ1, _V2, _RZ2), Iz, ay, 1.0),
        ((_W1, _RY1, _W2, _RY2), Iy, az, -1.0),
    ):
        ei = E * inertia
        phi = 12.0 * ei * coef / (G * A * L * L)
        den = 1.0 + phi
        k[:, t1, t1] = k[:, t2, t2] = 12.0 * ei / (den * L**3)
        k[:, t1, t2] = -12.0 * ei / (den * L**3)
        k[:, t1, r1] = k[:, t1, r2] = sign * 6.0 * ei / (den * L**2)
        k[:, r1, t2] = k[:, t2, r2] = -sign * 6.0 * ei / (den * L**2)
        k[:, r1, r1] = k[:, r2, r2] = (4.0 + phi) * ei / (den * L)
        k[:, r1, r2] = (2.0 - phi) * ei / (den * L)
    return _apply_offset(_symmetrise(k), ey, ez)


def _bending_mass(L, mass, phi, r):
    """Consistent-mass coefficients of one bending plane (Przemieniecki's
    Timoshenko beam with rotary inertia ratio r = I / (A L^2))."""
    c = mass / (1.0 + phi) ** 2
    p2 = phi * phi
    return {
        "tt": c * (13.0 / 35 + 7.0 * phi / 10 + p2 / 3 + 6.0 * r / 5),
        "tr": c * L * (11.0 / 210 + 11.0 * phi / 120 + p2 / 24 + r / 10 - phi * r / 2),
        "tt2": c * (9.0 / 70 + 3.0 * phi / 10 + p2 / 6 - 6.0 * r / 5),
        "tr2": c * L * (-13.0 / 420 - 3.0 * phi / 40 - p2 / 24 + r / 10 - phi * r / 2),
        "rr": c * L * L * (1.0 / 105 + phi / 60 + p2 / 120 + r * (2.0 / 15 + phi / 6 + p2 / 3)),
        "rr2": c * L * L * (-1.0 / 140 - phi / 60 - p2 / 120 - r * (1.0 / 30 + phi / 6 - p2 / 6)),
    }


def _offset_mass(L, mass, ey, ez) -> np.ndarray:
    """(n, 12, 12) inertia coupling of a centroid offset from the shear centre,
    as code_aster adds it before moving to the centroid: the kinetic energy
    of v - EZ rx and w - EY rx with cubic (v, w) and linear (rx) shapes."""
    gauss, weights = np.polynomial.legendre.leggauss(4)
    xi, wts = (gauss + 1.0) / 2.0, weights / 2.0
    n = len(L)
    out = np.zeros((n, 12, 12))
    for s, w in zip(xi, wts, strict=True):
        h1, h2 = 1 - 3 * s**2 + 2 * s**3, s - 2 * s**2 + s**3
        h3, h4 = 3 * s**2 - 2 * s**3, -(s**2) + s**3
        nv = np.zeros((n, 12))
        nw = np.zeros((n, 12))
        nr = np.zeros((n, 12))
        nv[:, [_V1, _RZ1, _V2, _RZ2]] = np.column_stack([h1 + 0 * L, L * h2, h3 + 0 * L, L * h4])
        nw[:, [_W1, _RY1, _W2, _RY2]] = np.column_stack([h1 + 0 * L, -L * h2, h3 + 0 * L, -L * h4])
        nr[:, _RX1], nr[:, _RX2] = 1.0 - s, s
        centroid = -ez[:, None] * nv - ey[:, None] * nw
        term = np.einsum("ei,ej->eij", centroid, nr)
        term = term + np.swapaxes(term, 1, 2)
        term += (ey**2 + ez**2)[:, None, None] * np.einsum("ei,ej->eij", nr, nr)
        out += w * term
    return mass[:, None, None] * out


def beam_mass_local(
    length, density, young, shear, area, iy, iz, ay=0.0, az=0.0, ey=0.0, ez=0.0, lumped=False
) -> np.ndarray:
    """(n, 12, 12) local mass of straight beams of constant section.

    Consistent (``lumped=False``): with shear (both ``ay`` and ``az``
    non-zero) the Timoshenko consistent mass including rotary inertia,
    otherwise the Euler-Bernoulli one without rotary inertia, as code_aster.
    Lumped: code_aster's diagonal MASS_MECA_DIAG matrix.
    """
    L, rho, E, G, A, Iy, Iz, ay, az, ey, ez = _broadcast(
        length, density, young, shear, area, iy, iz, ay, az, ey, ez
    )
    n = len(L)
    mass = rho * A * L
    m = np.zeros((n, 12, 12))
    polar = rho * L * (Iy + Iz)
    if lumped:
        rotary = rho * A * L**3 / 105.0
        diag = np.column_stack(
            [mass / 2] * 3
            + [polar / 2, rotary + 2 * rho * Iy * L / 15, rotary + 2 * rho * Iz * L / 15]
        )
        m[:, np.arange(12), np.arange(12)] = np.tile(diag, 2)
        return m
    m[:, _U1, _U1] = m[:, _U2, _U2] = mass / 3
    m[:, _U1, _U2] = mass / 6
    m[:, _RX1, _RX1] = m[:, _RX2, _RX2] = polar / 3
    m[:, _RX1, _RX2] = polar / 6
    timoshenko = (ay != 0.0) & (az != 0.0)
    if np.any(timoshenko) and np.any(G <= 0.0):
        raise BeamError("Timoshenko beam mass needs a positive shear modulus")
    safe_g = np.where(G > 0.0, G, 1.0)
    for (t1, r1, t2, r2), inertia, coef, sign in (
        ((_V1, _RZ1, _V2, _RZ2), Iz, ay, 1.0),
        ((_W1, _RY1, _W2, _RY2), Iy, az, -1.0),
    ):
        phi = np.where(timoshenko, 12.0 * E * inertia * coef / (safe_g * A * L * L), 0.0)
        r = np.where(timoshenko, inertia / (A * L * L), 0.0)
        c = _bending_mass(L, mass, phi, r)
        m[:, t1, t1] = m[:, t2, t2] = c["tt"]
        m[:, t1, t2] = c["tt2"]
        m[:, t1, r1] = sign * c["tr"]
        m[:, t2, r2] = -sign * c["tr"]
        m[:, t1, r2] = sign * c["tr2"]
        m[:, r1, t2] = -sign * c["tr2"]
        m[:, r1, r1] = m[:, r2, r2] = c["rr"]
        m[:, r1, r2] = c["rr2"]
    m = _symmetrise(m)
    if np.any(ey) or np.any(ez):
        m = _apply_offset(m + _offset_mass(L, mass, ey, ez), ey, ez)
    return m


# -- Timoshenko beams with warping (POU_D_TG) ----------------------------------------

#: the 12 DOFs of POU_D_T inside the 14 of POU_D_TG (GRX after DRZ on each node)
_TG_INDEX = np.array([0, 1, 2, 3, 4, 5, 7, 8, 9, 10, 11, 12])
_RX1_TG, _GRX1, _RX2_TG, _GRX2 = 3, 6, 10, 13


def warping_beam_stiffness_local(
    length, young, shear, area, iy, iz, jx, jg, ay, az, ey=0.0, ez=0.0
) -> np.ndarray:
    """(n, 14, 14) local stiffness of POU_D_TG: POU_D_T's axial and bending
    terms, and torsion with warping (DRX, GRX = the rate of twist) from the
    cubic twist angle, ``G J`` (Saint-Venant) and ``E JG`` (warping); the
    shear-centre offset EY/EZ moves the transverse DOFs as for POU_D_T."""
    L, E, G, A, Iy, Iz, J, Jg, ay, az, ey, ez = _broadcast(
        length, young, shear, area, iy, iz, jx, jg, ay, az, ey, ez
    )
    k12 = beam_stiffness_local(L, E, G, A, Iy, Iz, J, ay, az)
    k = np.zeros((len(L), 14, 14))
    k[:, _TG_INDEX[:, None], _TG_INDEX[None, :]] = k12
    gj, ej = G * J, E * Jg
    a = 6.0 * gj / (5.0 * L) + 12.0 * ej / L**3
    b = gj / 10.0 + 6.0 * ej / L**2
    c = 2.0 * gj * L / 15.0 + 4.0 * ej / L
    d = -gj * L / 30.0 + 2.0 * ej / L
    block = np.zeros((len(L), 4, 4))  # DRX1, GRX1, DRX2, GRX2
    block[:, 0] = np.stack([a, b, -a, b], axis=1)
    block[:, 1] = np.stack([b, c, -b, d], axis=1)
    block[:, 2] = np.stack([-a, -b, a, -b], axis=1)
    block[:, 3] = np.stack([b, d, -b, c], axis=1)
    torsion = np.array([_RX1_TG, _GRX1, _RX2_TG, _GRX2])
    k[:, torsion[:, None], torsion[None, :]] = block
    if np.any(ey) or np.any(ez):
        t = np.broadcast_to(np.eye(14), k.shape).copy()
        t[:, _TG_INDEX[:, None], _TG_INDEX[None, :]] = _offset_transform(ey, ez)
        k = np.einsum("eji,ejk,ekl->eil", t, k, t)
    return k


def warping_beam_mass_local(length, density, young, shear, area, iy, iz, ay, az, ey, ez):
    """(n, 14, 14) POU_D_TG mass: POU_D_T's consistent mass, none on GRX
    (code_aster's)."""
    m12 = beam_mass_local(length, density, young, shear, area, iy, iz, ay, az, ey, ez)
    m = np.zeros((len(m12), 14, 14))
    m[:, _TG_INDEX[:, None], _TG_INDEX[None, :]] = m12
    return m


# -- bars -------------------------------------------------------------------------


def bar_stiffness_local(length, young, area, dim: int = 3) -> np.ndarray:
    """(n, 2 dim, 2 dim) local stiffness of bars: axial EA/L only."""
    L, E, A = _broadcast(length, young, area)
    k = np.zeros((len(L), 2 * dim, 2 * dim))
    axial = E * A / L
    k[:, 0, 0] = k[:, dim, dim] = axial
    k[:, 0, dim] = k[:, dim, 0] = -axial
    return k


def bar_mass_local(length, density, area, dim: int = 3, lumped=False) -> np.ndarray:
    """(n, 2 dim, 2 dim) bar mass, the same in every direction:
    rho A L / 6 [[2, 1], [1, 2]] per component, or rho A L / 2 lumped."""
    L, rho, A = _broadcast(length, density, area)
    mass = rho * A * L
    pattern = np.eye(2) / 2 if lumped else np.array([[2.0, 1.0], [1.0, 2.0]]) / 6
    return mass[:, None, None] * np.kron(pattern, np.eye(dim))[None]


# -- from AFFE_CARA_ELEM data -----------------------------------------------------


def _shear_coefficients(modelisation: str, section: Mapping) -> tuple:
    if modelisation == "POU_D_E":
        return 0.0, 0.0
    missing = [name for name in ("AY", "AZ") if name not in section]
    if missing:
        raise BeamError(
            f"POU_D_T needs the shear coefficients {' and '.join(missing)} "
            "(give them in SECTION='GENERALE', or use POU_D_E)"
        )
    return section["AY"], section["AZ"]


def local_matrices(
    modelisation: str,
    matrix: str,
    length,
    section: Mapping,
    young,
    poisson=0.0,
    density=0.0,
    lumped: bool = False,
) -> np.ndarray:
    """Local element matrices for ``matrix`` 'K' (RIGI_MECA) or 'M'
    (MASS_MECA, MASS_MECA_DIAG with ``lumped``) from section properties
    (:func:`asterlite.fem.sections.section_properties`) and ELAS values."""
    modelisation = modelisation.upper()
    if modelisation not in COMPONENTS:
        raise BeamError(f"modelisation {modelisation} is not a straight beam or bar")
    if matrix not in ("K", "M"):
        raise BeamError(f"beam matrix '{matrix}' unknown (K or M)")
    if modelisation in ("BARRE", "2D_BARRE"):
        dim = len(COMPONENTS[modelisation])
        if matrix == "K":
            return bar_stiffness_local(length, young, section["A"], dim)
        return bar_mass_local(length, density, section["A"], dim, lumped)
    ay, az = _shear_coefficients(modelisation, section)
    common = dict(
        area=section["A"],
        iy=section["IY"],
        iz=section["IZ"],
        ay=ay,
        az=az,
        # code_aster's EY, EZ place the centroid relative to the shear centre
        # (sdll400a's deck supports its channel at the shear centre with
        # DY - 0.2215 DRX = 0 for EZ = -0.2215); ey, ez here are the shear
        # centre relative to the centroid
        ey=-section.get("EY", 0.0),
        ez=-section.get("EZ", 0.0),
    )
    shear = shear_modulus(young, poisson)
    if modelisation == "POU_D_TG":
        if matrix == "K":
            jg = section.get("JG", 0.0)
            return warping_beam_stiffness_local(
                length, young, shear, jx=section["JX"], jg=jg, **common
            )
        if lumped:
            raise BeamError("MASS_MECA_DIAG of POU_D_TG elements is not available")
        return warping_beam_mass_local(length, density, young, shear, **common)
    if matrix == "K":
        return beam_stiffness_local(length, young, shear, jx=section["JX"], **common)
    return beam_mass_local(length, density, young, shear, lumped=lumped, **common)


def global_matrices(
    modelisation: str,
    matrix: str,
    x1,
    x2,
    section: Mapping,
    young,
    poisson=0.0,
    density=0.0,
    angles=None,
    lumped: bool = False,
) -> np.ndarray:
    """(n, d, d) element matrices in the global frame for segments x1 -> x2.

    ``angles`` (n, 3) are the nautical angles of each element in radians
    (default: :func:`seg2_angles` without ORIENTATION).
    """
    x1 = np.atleast_2d(np.asarray(x1, dtype=float))
    x2 = np.atleast_2d(np.asarray(x2, dtype=float))
    if x1.shape[-1] == 2:  # plane meshes: z = 0
        x1, x2 = (np.column_stack([x, np.zeros(len(x))]) for x in (x1, x2))
    if angles is None:
        angles = seg2_angles(x1, x2)
    local = local_matrices(
        modelisation, matrix, segment_lengths(x1, x2), section, young, poisson, density, lumped
    )
    local = np.broadcast_to(local, (len(x1),) + local.shape[1:])
    per_node = len(COMPONENTS[modelisation.upper()])
    return to_global(local, rotation_from_angles(np.asarray(angles, dtype=float)), per_node)


def cell_angles(model, characteristics, cells) -> np.ndarray:
    """(n, 3) nautical angles of SEG2 cells: ORIENTATION when given, else the
    segment direction with no twist (code_aster's default)."""
    mesh = model.mesh
    conn = np.array([mesh.cell_nodes[c] for c in cells], dtype=int).reshape(-1, 2)
    angles = seg2_angles(mesh.coords[conn[:, 0]], mesh.coords[conn[:, 1]])
    if characteristics is not None:
        for k, cell in enumerate(cells):
            given = characteristics.orientation.get(int(cell))
            if given is not None:
                angles[k] = given
    return angles
