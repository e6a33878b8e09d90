"""Elbow (curved) pipe elements on SEG3 cells: geometry, frames and the
strain and shape operators, as code_aster's angcou, beamBMatrCurved,
shellBMatrCurved and beamNMatrCurved (R3.08.06).

An elbow is the arc of a torus through the cell's three nodes: bend radius
``Rc`` and angle ``theta`` from the chords. Each node has its own frame (x
tangent to the arc, y towards the bend centre, z = -n with n the bend
plane's normal t2 ^ t1); the middle node's frame is the chord's. The
abscissa along the element is the angle s = (1 + xi) theta / 2, a fibre at
phi lies at the distance Rc + r sin(phi) from the bend centre, and the
Fourier terms of the ovalisation are measured from the generating line, at
the angle ``omega`` from the bend plane's normal.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


class PipeError(ValueError):
    """A pipe element that cannot be computed (bad section, geometry)."""


@dataclass(frozen=True)
class Elbow:
    """Bend radius, bend angle and generating-line angle of an elbow cell."""

    radius: float  # RCOURB
    angle: float  # ANGCOU (theta)
    omega: float  # ANGZZK

    def node_angles(self, n_nodes: int) -> np.ndarray:
        """Angular abscissae of the cell's nodes (ends first)."""
        if n_nodes == 3:
            return np.array([0.0, self.angle, self.angle / 2.0])
        return np.array([0.0, self.angle, self.angle / 3.0, 2.0 * self.angle / 3.0])


def _frame(x, y) -> np.ndarray:
    x = x / np.linalg.norm(x)
    y = y - np.dot(y, x) * x
    y = y / np.linalg.norm(y)
    return np.array([x, y, np.cross(x, y)])


def _rotate(vector, axis, cosine, sine) -> np.ndarray:
    """Rodrigues' rotation of ``vector`` about the unit ``axis``."""
    first = np.cross(axis, vector)
    return vector + sine * first + (1.0 - cosine) * np.cross(axis, first)


def elbow_frames(coords, generator, backwards: bool, given: bool, relative: bool = True):
    """(Elbow, [P1, P2, P3] node frames, carried generating line, the line
    halfway) of a three-node arc (code_aster's angcou, curved branch). ``generator`` is the
    generating line arriving at the cell (at node 1, or at node 2 when the
    line is walked ``backwards``); ``given``: it comes from a GENE_TUYAU."""
    c1, c2, c3 = (np.asarray(c, dtype=float) for c in coords[:3])
    t1, t2 = c3 - c1, c2 - c3
    t1, t2 = t1 / np.linalg.norm(t1), t2 / np.linalg.norm(t2)
    normal = np.cross(t2, t1)
    sine = np.linalg.norm(normal)
    normal /= sine
    theta = 2.0 * np.arctan2(sine, np.dot(t1, t2))
    chord = c2 - c1
    radius = np.linalg.norm(chord) / 2.0 / sine
    y3 = np.cross(chord, normal)
    ct2, st2 = np.cos(theta / 2.0), np.sin(theta / 2.0)
    x1, x2 = chord * ct2 - y3 * st2, chord * ct2 + y3 * st2
    frames = [_frame(x, np.cross(x, normal)) for x in (x1, x2, chord)]
    x1, x2 = x1 / np.linalg.norm(x1), x2 / np.linalg.norm(x2)
    # the generating line on the arriving end's tangent, then turned along the arc
    sign = -1 if backwards else 1
    axis = normal if sign < 0 else -normal
    start = x1 if (sign > 0 and given) else x2
    if np.linalg.norm(np.cross(start, generator)) <= 1e-4 * np.linalg.norm(generator):
        raise PipeError("the generating line (GENE_TUYAU) is tangent to the elbow")
    zk1 = np.cross(np.cross(start, generator), start)
    zk1 /= np.linalg.norm(zk1)
    zk2 = _rotate(zk1, axis, np.cos(theta), np.sin(theta))
    zk2 /= np.linalg.norm(zk2)
    zk3 = _rotate(zk1, axis, ct2, st2)
    zk3 /= np.linalg.norm(zk3)

    def angle(zk, tangent):
        return np.arctan2(np.dot(tangent, np.cross(zk, normal)), np.dot(normal, zk))

    omega_in = angle(zk1, x2 if sign < 0 else x1)
    omega = angle(zk2, x2 if (sign > 0 and given) else x1)
    if not relative:
        tolerance = 1e-4
    elif abs(omega) < np.finfo(float).eps:
        tolerance = np.finfo(float).eps
    else:
        tolerance = 1e-4 * abs(omega)
    if abs(omega_in - omega) > tolerance:
        raise PipeError(
            f"the generating line turns along the elbow (angles {omega:g} and {omega_in:g})"
        )
    return Elbow(radius, theta, omega), frames, zk2, zk3


def elbow_frames_seg4(coords, generator, backwards: bool, given: bool, relative: bool = True):
    """(Elbow, [P1..P4], carried generating line) of a SEG4 elbow: two
    three-node arcs, nodes (1, 4, 3) then (3, 2, 4), which must agree on the
    radius, the angle and omega (code_aster's angco4)."""
    c = [np.asarray(x, dtype=float) for x in coords[:4]]
    first, f1, _, half = elbow_frames([c[0], c[3], c[2]], generator, backwards, given, relative)
    second, f2, zk2, _ = elbow_frames([c[2], c[1], c[3]], half, backwards, given, relative)
    for name, a, b in (
        ("radius", first.radius, second.radius),
        ("angle", first.angle, second.angle),
        ("omega", first.omega, second.omega),
    ):
        limit = 1e-4 if not relative else max(1e-4 * abs(a), np.finfo(float).eps)
        if abs(a - b) > limit:
            raise PipeError(f"its two halves differ in {name} ({a:g}, {b:g}): not an arc")
    elbow = Elbow(second.radius, 1.5 * first.angle, first.omega)
    return elbow, [f1[0], f2[1], f2[0], f2[2]], zk2


def elbow_strain_operator(h, dh, d2h, xi, elbow: Elbow, section, modes: int, shape):
    """B (npg, layers, sectors, 4, n_dofs) of an elbow; ``h``, ``dh``, ``d2h``
    are (npg, nno) in the reference coordinate, ``shape`` the broadcast
    (npg, layers, sectors)."""
    n_points, n_nodes = h.shape
    zeta, phi, _, r = section.points()
    big_r = section.mean_radius
    rc, theta, omega = elbow.radius, elbow.angle, elbow.omega
    tk = elbow.node_angles(n_nodes)
    scale = 2.0 / theta
    dh, d2h = dh * scale, d2h * scale**2
    per = 9 + 6 * (modes - 1)
    b = np.zeros(shape + (4, n_nodes * per))
    cos, sin = np.cos(phi), np.sin(phi)
    cos_t, sin_t = np.cos(phi - omega), np.sin(phi - omega)
    denr = rc + r * sin
    dena = rc + big_r * sin
    dent = 1.0 / denr + big_r / (r * dena)
    s = (1.0 + xi) * theta / 2.0
    for a in range(n_nodes):
        hk, dk, d2k = (v[:, a][:, None, None] for v in (h, dh, d2h))
        ck, sk = np.cos(s - tk[a])[:, None, None], np.sin(s - tk[a])[:, None, None]
        base = a * per

        def put(row, col, value, base=base):
            b[..., row, base + col] = np.broadcast_to(value, shape)

        put(0, 0, dk * ck / denr)
        put(0, 1, dk * sk / denr)
        put(0, 3, r * cos * dk * sk / denr)
        put(0, 4, -r * cos * dk * ck / denr)
        put(0, 5, r * sin * dk / denr)
        put(2, 0, cos * dk * sk / denr)
        put(2, 1, -cos * dk * ck / denr)
        put(2, 2, sin * dk / denr)
        put(2, 3, -(hk * sk * rc * sin + r * dk * ck) / denr)
        put(2, 4, (hk * ck * rc * sin - r * dk * sk) / denr)
        put(2, 5, rc * cos * hk / denr)
        put(3, 0, sin * dk * sk / denr)
        put(3, 1, -sin * dk * ck / denr)
        put(3, 2, -cos * dk / denr)
        put(3, 3, rc * cos * hk * sk / denr)
        put(3, 4, -rc * cos * hk * ck / denr)
        put(3, 5, rc * sin * hk / denr)
        for m in range(2, modes + 1):
            cm, sm = np.cos(m * (phi - omega)), np.sin(m * (phi - omega))
            for sign, col, c_, s_ in (
                (1.0, 6 + 3 * (m - 2), cm, sm),
                (-1.0, 6 + 3 * (modes - 1) + 3 * (m - 2), sm, cm),
            ):
                # out of phase: cos -> sin and sin -> -cos in the derivatives
                put(0, col, dk * c_ / dena)
                put(0, col + 1, hk * s_ * cos * (1.0 + zeta / big_r) / denr)
                put(
                    0,
                    col + 2,
                    -zeta * d2k * c_ / (denr * dena)
                    + hk * c_ * sin / denr
                    + sign * zeta * m * hk * s_ * cos / (big_r * denr),
                )
                put(1, col + 1, sign * (m / r) * hk * c_ * (1.0 + zeta / big_r))
                put(1, col + 2, hk * c_ * (1.0 + zeta * m * m / big_r) / r)
                put(
                    2,
                    col,
                    -sign * (m / r) * hk * s_
                    - hk * c_ * cos / denr
                    - zeta * hk * cos * sin * c_ / dena * dent
                    + zeta * hk * (c_ * cos - sign * m * s_ * sin) / (r * dena),
                )
                put(2, col + 1, dk * s_ * (1.0 + zeta / big_r) / denr)
                put(
                    2,
                    col + 2,
                    sign * zeta * m * dk * s_ * (1.0 / (big_r * denr) + 1.0 / (r * dena))
                    + zeta * dk * cos * c_ / dena * dent,
                )
        col = 6 + 6 * (modes - 1)
        put(0, col, hk * sin / denr - zeta * d2k / (dena * denr))
        put(1, col, hk / r)
        put(2, col, zeta * dk * cos / dena * dent)
        twist = (1.0 + 2.0 * zeta / big_r) / denr + zeta / (r * dena)
        put(
            0,
            col + 1,
            -zeta * d2k * cos_t / (denr * dena)
            + 2.0 * hk * cos * sin_t / denr * zeta / big_r
            + hk * (cos_t * sin + cos * sin_t) / denr,
        )
        put(1, col + 1, 2.0 * hk * cos_t * (1.0 + zeta / big_r) / r)
        put(2, col + 1, dk * sin_t * twist + zeta * dk * cos_t * cos / dena * dent)
        put(
            0,
            col + 2,
            -zeta * d2k * sin_t / (dena * denr)
            + hk * (sin * sin_t - cos * cos_t) / denr
            - 2.0 * zeta * hk * cos * cos_t / (big_r * denr),
        )
        put(1, col + 2, 2.0 * hk * sin_t * (1.0 + zeta / big_r) / r)
        put(2, col + 2, -dk * cos_t * twist + zeta * dk * sin_t * cos / dena * dent)
    return b


def elbow_beam_shape(hk, ck, sk, r, cos, sin) -> list[tuple[int, int, np.ndarray]]:
    """(row, column, value) of the beam rows of the elbow's shape operator
    at one node: the section moves rigidly, its node's frame turned to the
    Gauss point's."""
    return [
        (0, 0, hk * ck),
        (0, 1, hk * sk),
        (0, 3, hk * r * cos * sk),
        (0, 4, -hk * r * cos * ck),
        (0, 5, hk * r * sin),
        (1, 0, -hk * sk),
        (1, 1, hk * ck),
        (1, 3, hk * r * cos * ck),
        (1, 4, hk * r * cos * sk),
        (2, 2, hk),
        (2, 3, -hk * r * sin * ck),
        (2, 4, -hk * r * sin * sk),
    ]


def fibre_length_factor(elbow: Elbow, r, phi) -> np.ndarray:
    """d(arc length)/d(xi) of the fibre at (r, phi): theta (Rc + r sin phi) / 2."""
    return elbow.angle * (elbow.radius + r * np.sin(phi)) / 2.0
