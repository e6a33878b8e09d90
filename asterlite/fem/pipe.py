"""Straight pipe elements TUYAU_3M and TUYAU_6M: local stiffness, mass and
internal forces, as code_aster integrates them (R3.08.06).

The pipe's displacement is a Timoshenko beam's (DX..DRZ, the section stays
a rigid disc) plus a thin shell's ovalisation, a Fourier series around the
section: for each mode m = 2..M the in-phase terms (UIm, VIm, WIm: axial u
cos(m phi), tangential v sin(m phi), radial w cos(m phi)) and the
out-of-phase ones (UOm, VOm, WOm: sin, cos, sin), plus the swelling WO and
the mode-1 terms WI1, WO1. M = 3 (TUYAU_3M) or 6 (TUYAU_6M); per node
6 + 6 (M - 1) + 3 DOFs in code_aster's order (:func:`node_components`).

Integration, as code_aster: Gauss points along the axis (``RIGI``: 2 on a
SEG3, 3 on a SEG4; ``MASS``: 3), Simpson's rule through the thickness
(2 TUYAU_NCOU + 1 points) and around the section (2 TUYAU_NSEC + 1 points,
phi from 0 to 2 pi). Strains: axial, hoop, in-plane shear, transverse shear;
plane-stress Hooke law, shear modulus on both shears. The layers' radius is
the mean radius unless MODI_METRIQUE='OUI' (then the layer's own).
The local frame: x from node 1 to node 2, z opposite the generating line
(ORIENTATION GENE_TUYAU carried along the pipe), phi measured from it.
The beam DOFs turn with the frame, the shell DOFs do not.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import numpy as np

from asterlite.fem.pipe_elbow import (
    Elbow,
    PipeError,
    elbow_beam_shape,
    elbow_strain_operator,
    fibre_length_factor,
)

__all__ = ["Elbow", "PipeError"]

#: Gauss rules on [-1, 1] (code_aster's FPG2 and FPG3, in its point order).
_GAUSS = {
    2: (np.array([1.0, -1.0]) / np.sqrt(3.0), np.array([1.0, 1.0])),
    3: (np.array([-np.sqrt(0.6), 0.0, np.sqrt(0.6)]), np.array([5.0, 8.0, 5.0]) / 9.0),
}
#: Reference abscissae of the nodes of SEG3 and SEG4 (ends first).
_NODES = {3: np.array([-1.0, 1.0, 0.0]), 4: np.array([-1.0, 1.0, -1.0 / 3.0, 1.0 / 3.0])}
#: Gauss points of the RIGI family by node count (the MASS family has 3).
RIGI_POINTS = {3: 2, 4: 3}
MASS_POINTS = 3


def node_components(modes: int) -> tuple[str, ...]:
    """DOF names of a pipe node with Fourier modes up to ``modes``."""
    inphase = [f"{d}I{m}" for m in range(2, modes + 1) for d in "UVW"]
    outphase = [f"{d}O{m}" for m in range(2, modes + 1) for d in "UVW"]
    return ("DX", "DY", "DZ", "DRX", "DRY", "DRZ", *inphase, *outphase, "WO", "WI1", "WO1")


@cache
def lagrange(n_nodes: int, n_points: int):
    """(h, dh, d2h, xi, weights): shape functions and their first and second
    derivatives in the reference coordinate at the Gauss points, (npg, nno)."""
    xi, weights = _GAUSS[n_points]
    nodes = _NODES[n_nodes]
    h = np.ones((n_points, n_nodes))
    dh = np.zeros((n_points, n_nodes))
    d2h = np.zeros((n_points, n_nodes))
    for a in range(n_nodes):
        others = [nodes[b] for b in range(n_nodes) if b != a]
        poly = np.poly1d(others, r=True) / np.prod([nodes[a] - o for o in others])
        h[:, a] = poly(xi)
        dh[:, a] = poly.deriv(1)(xi)
        d2h[:, a] = poly.deriv(2)(xi) if n_nodes > 2 else 0.0
    return h, dh, d2h, xi, weights


@dataclass(frozen=True)
class PipeSection:
    """Geometry and integration of a pipe cross-section (POUTRE CERCLE R, EP)."""

    radius: float  # outer radius R
    thickness: float  # EP
    layers: int = 3  # TUYAU_NCOU
    sectors: int = 16  # TUYAU_NSEC
    metric: bool = False  # MODI_METRIQUE='OUI'

    @property
    def mean_radius(self) -> float:
        return self.radius - self.thickness / 2.0

    def points(self):
        """(zeta, phi, weight, layer radius) of the section's sub-points, each
        (n_layer_points, n_sector_points) broadcastable; the weight includes
        the area element t dphi r of code_aster's Simpson rule."""
        n, s = self.layers, self.sectors
        zeta = np.arange(2 * n + 1) * self.thickness / (2.0 * n) - self.thickness / 2.0
        phi = np.arange(2 * s + 1) * 2.0 * np.pi / (2.0 * s)
        radius = self.mean_radius + (zeta if self.metric else 0.0 * zeta)
        weight = (
            simpson(n)[:, None]
            * simpson(s)[None, :]
            * self.thickness
            * 2.0
            * np.pi
            / (4.0 * n * s)
            * radius[:, None]
        )
        return zeta[:, None], phi[None, :], weight, radius[:, None]


def simpson(n: int) -> np.ndarray:
    """Composite Simpson weights of 2n intervals (h = 1)."""
    w = np.empty(2 * n + 1)
    w[0::2], w[1::2] = 2.0 / 3.0, 4.0 / 3.0
    w[0] = w[-1] = 1.0 / 3.0
    return w


def elasticity(young: float, poisson: float) -> np.ndarray:
    """4x4 law of (axial, hoop, in-plane shear, transverse shear) strains."""
    c = np.zeros((4, 4))
    factor = young / (1.0 - poisson**2)
    c[0, 0] = c[1, 1] = factor
    c[0, 1] = c[1, 0] = poisson * factor
    c[2, 2] = c[3, 3] = young / (2.0 * (1.0 + poisson))
    return c


def strain_operator(
    modes: int, geometry: float | Elbow, section: PipeSection, n_nodes: int, n_points: int
) -> np.ndarray:
    """B (npg, n_layer_points, n_sector_points, 4, n_dofs) of a straight pipe
    of length ``geometry``, or of an elbow (local DOFs, code_aster's order)."""
    h, dh, d2h, xi, _ = lagrange(n_nodes, n_points)
    zeta, phi, _, r = section.points()
    shape = (n_points,) + np.broadcast(zeta, phi).shape
    if isinstance(geometry, Elbow):
        return elbow_strain_operator(h, dh, d2h, xi, geometry, section, modes, shape)
    scale = 2.0 / geometry
    dh, d2h = dh * scale, d2h * scale**2
    big_r = section.mean_radius
    per = 9 + 6 * (modes - 1)
    cos, sin = np.cos(phi), np.sin(phi)
    b = np.zeros(shape + (4, n_nodes * per))
    for a in range(n_nodes):
        # (npg, 1, 1) factors against (layers, sectors) ones
        hk, dk, d2k = (v[:, a][:, None, None] for v in (h, dh, d2h))
        base = a * per

        def put(row, col, value, base=base):
            b[..., row, base + col] = np.broadcast_to(value, shape)

        # beam: the section turns rigidly, at (y, z) = (-r sin phi, -r cos phi)
        put(0, 0, dk)
        put(0, 4, -r * cos * dk)
        put(0, 5, r * sin * dk)
        put(2, 1, -cos * dk)
        put(2, 2, sin * dk)
        put(2, 3, -r * dk)
        put(2, 4, sin * hk)
        put(2, 5, cos * hk)
        put(3, 1, -sin * dk)
        put(3, 2, -cos * dk)
        put(3, 4, -cos * hk)
        put(3, 5, sin * hk)
        # ovalisation modes m >= 2: in phase (u cos, v sin, w cos), out of phase
        for m in range(2, modes + 1):
            cm, sm = np.cos(m * phi), np.sin(m * phi)
            for sign, col, c_, s_ in (
                (1.0, 6 + 3 * (m - 2), cm, sm),
                (-1.0, 6 + 3 * (modes - 1) + 3 * (m - 2), sm, cm),
            ):
                # out of phase: cos -> sin and sin -> -cos in the derivatives
                put(0, col, dk * c_)
                put(0, col + 2, -zeta * d2k * c_)
                put(1, col + 1, sign * (m / r) * hk * c_ * (1.0 + zeta / big_r))
                put(1, col + 2, hk * c_ * (1.0 + zeta * m * m / big_r) / r)
                put(2, col, -sign * (m / r) * hk * s_)
                put(2, col + 1, dk * s_ * (1.0 + zeta / big_r))
                put(2, col + 2, sign * zeta * m * dk * s_ * (1.0 / big_r + 1.0 / r))
        col = 6 + 6 * (modes - 1)
        put(0, col, -zeta * d2k)
        put(1, col, hk / r)
        twist = 1.0 + 2.0 * zeta / big_r + zeta / r
        put(0, col + 1, -zeta * d2k * cos)
        put(1, col + 1, 2.0 * hk * cos * (1.0 + zeta / big_r) / r)
        put(2, col + 1, dk * sin * twist)
        put(0, col + 2, -zeta * d2k * sin)
        put(1, col + 2, 2.0 * hk * sin * (1.0 + zeta / big_r) / r)
        put(2, col + 2, -dk * cos * twist)
    return b


def quadrature_weights(geometry, section: PipeSection, n_points: int, n_nodes: int):
    """(npg, layers, sectors) weights of the volume integral (Gauss x Simpson x
    Jacobian: half the length, or the fibre's arc on an elbow)."""
    _, _, _, _, gauss = lagrange(n_nodes, n_points)
    _, phi, section_weight, r = section.points()
    if isinstance(geometry, Elbow):
        along = fibre_length_factor(geometry, r, phi)
    else:
        along = geometry / 2.0
    return gauss[:, None, None] * (section_weight * along)[None]


def stiffness(
    modes: int, geometry, section: PipeSection, young: float, poisson: float, n_nodes: int
) -> np.ndarray:
    """Local stiffness matrix of a pipe element (``geometry``: the length of
    a straight one, or an :class:`Elbow`)."""
    n_points = RIGI_POINTS[n_nodes]
    b = strain_operator(modes, geometry, section, n_nodes, n_points)
    weights = quadrature_weights(geometry, section, n_points, n_nodes)
    c = elasticity(young, poisson)
    cb = np.einsum("ij,...jk->...ik", c, b)
    return np.einsum("pls,plsik,plsij->kj", weights, b, cb)


def mass(modes: int, geometry, section: PipeSection, density: float, n_nodes: int):
    """Local consistent mass matrix of a pipe element.

    The shell terms follow code_aster's tumass column for column: it lays
    each mode's six terms out mode by mode (UI VI WI UO VO WO), the element
    vector mode-type by mode-type; with an exact Simpson rule (TUYAU_NSEC
    large enough for the products of modes) both give the same matrix."""
    h, _, _, xi, _ = lagrange(n_nodes, MASS_POINTS)
    _, phi, _, r = section.points()
    per = 9 + 6 * (modes - 1)
    shape = (MASS_POINTS,) + np.broadcast(r, phi).shape
    n = np.zeros(shape + (6, n_nodes * per))
    cos, sin = np.cos(phi), np.sin(phi)
    for a in range(n_nodes):
        hk = h[:, a][:, None, None]
        base = a * per

        def put(row, col, value, base=base):
            n[..., row, base + col] = np.broadcast_to(value, shape)

        if isinstance(geometry, Elbow):
            arc = (1.0 + xi) * geometry.angle / 2.0 - geometry.node_angles(n_nodes)[a]
            ck, sk = np.cos(arc)[:, None, None], np.sin(arc)[:, None, None]
            for row, col, value in elbow_beam_shape(hk, ck, sk, r, cos, sin):
                put(row, col, value)
        else:
            put(0, 0, hk)
            put(0, 4, -hk * r * cos)
            put(0, 5, hk * r * sin)
            put(1, 1, hk)
            put(1, 3, hk * r * cos)
            put(2, 2, hk)
            put(2, 3, -hk * r * sin)
        for m in range(2, modes + 1):
            col = 6 + 6 * (m - 2)
            cm, sm = np.cos(m * phi), np.sin(m * phi)
            put(3, col, hk * cm)
            put(3, col + 3, hk * sm)
            put(4, col + 1, hk * sm)
            put(4, col + 4, hk * cm)
            put(5, col + 2, hk * cm)
            put(5, col + 5, hk * sm)
        col = 6 + 6 * (modes - 1)
        put(5, col, hk)
        put(4, col + 1, hk * sin)
        put(5, col + 1, hk * cos)
        put(4, col + 2, -hk * cos)
        put(5, col + 2, hk * sin)
    weights = quadrature_weights(geometry, section, MASS_POINTS, n_nodes) * density
    return np.einsum("pls,plsik,plsij->kj", weights, n, n)


def section_forces_at_gauss(
    modes: int,
    geometry,
    section: PipeSection,
    young: float,
    poisson: float,
    n_nodes: int,
    u_local: np.ndarray,
) -> np.ndarray:
    """(..., npg, 6) N VY VZ MT MFY MFZ at the RIGI Gauss points from the
    stresses of local displacements ``u_local`` (..., n_dofs), integrated
    over the section as code_aster's EFGE (linear elasticity)."""
    n_points = RIGI_POINTS[n_nodes]
    b = strain_operator(modes, geometry, section, n_nodes, n_points)
    _, phi, weight, r = section.points()
    c = elasticity(young, poisson)
    stress = np.einsum("ij,plsjk,...k->...plsi", c, b, u_local)  # (..., npg, L, S, 4)
    cos, sin = np.cos(phi), np.sin(phi)
    s0, s2, s3 = stress[..., 0], stress[..., 2], stress[..., 3]
    parts = (
        s0,
        -(sin * s3 + cos * s2),
        sin * s2 - cos * s3,
        -s2 * r,
        -s0 * r * cos,
        s0 * r * sin,
    )
    return np.stack([np.sum(weight * p, axis=(-2, -1)) for p in parts], axis=-1)


@cache
def gauss_to_nodes(n_nodes: int) -> np.ndarray:
    """(nno, npg) code_aster's extrapolation of RIGI values to the nodes: a
    least-squares linear fit of the Gauss values at the end nodes, the
    inner nodes taking the linear values at their abscissae."""
    n_points = RIGI_POINTS[n_nodes]
    xi = _GAUSS[n_points][0]
    linear = np.stack([(1.0 - xi) / 2.0, (1.0 + xi) / 2.0], axis=1)  # (npg, 2)
    ends = np.linalg.pinv(linear)  # (2, npg)
    inner = _NODES[n_nodes][2:]
    inner_linear = np.stack([(1.0 - inner) / 2.0, (1.0 + inner) / 2.0], axis=1)
    return np.vstack([ends, inner_linear @ ends])


def local_frame(x_axis, generator) -> np.ndarray:
    """3x3 global-to-local rotation of a straight pipe (code_aster's angcou):
    x along the axis, y = x ^ g with g the generating line made orthogonal
    to x, so that z = -g and phi = 0 lies on the generating line."""
    x = np.asarray(x_axis, dtype=float)
    x = x / np.linalg.norm(x)
    g = np.asarray(generator, dtype=float)
    a = np.cross(x, g)
    if np.linalg.norm(a) <= 1e-4 * np.linalg.norm(g):
        raise PipeError("the generating line (GENE_TUYAU) is parallel to the pipe axis")
    g = np.cross(a, x)
    y = np.cross(x, g / np.linalg.norm(g))
    return np.array([x, y, np.cross(x, y)])
