"""Seismic plane waves on paraxial boundaries (``AFFE_CHAR_MECA_F/ONDE_PLANE``
on ``3D_ABSO`` faces and ``D_PLAN_ABSO`` edges), as code_aster's te0498 (3D)
and te0499 (2D) compute them.

The free field is a sum of plane waves ``u = a g(t - (n.x - r)/c) p``: the
incident wave (``TYPE_ONDE`` P, SV, SH in 3D, P or S in 2D; direction of
propagation n, ``COOR_SOURCE`` giving its front's reference r = n.x0) and,
with ``COOR_REFLECHI`` (a free surface z = z1, the vertical being z in 3D
and y in 2D), the wave reflected by the surface and the converted one, with
the free-surface reflection coefficients of an elastic half-space (P-P and
P-SV, SV-SV and SV-P; SH reflects whole). A wave coming horizontally is
reflected back along -n by the plane n.x = n.x1. ``FONC_SIGNAL`` is the
incident velocity ``v``; the displacement ``DEPL_IMPO`` is used only with
``LONG_CARA`` springs.

On a boundary cell of unit normal n_b (the cell's orientation, outward once
ORIE_PEAU has turned the skin), the structure takes the nodal forces
``int N t dS`` with

    t = COEF_AMOR (rho c_p v_n + rho c_s v_t) + ((lambda + 2 mu) u_n + mu u_t) / L
        + sigma n_b

(``v_n``, ``v_t`` the normal and tangential parts of the free-field velocity,
the springs only with ``LONG_CARA`` = L, ``sigma`` the free-field stress
``-(v / c) p (x) n`` symmetrised through Hooke's law): the dashpots' force
on the free-field motion plus its stress vector, which code_aster's te0498
computes with the opposite sign and DYNA_VIBRA subtracts (dlnew0). A vertical
wave reaching a horizontal base thus pushes with 2 rho c_p v.

``plane_wave_history`` gives these forces at every instant of a list at
once (they are not a fixed vector times a function of time: each point of
the boundary sees the signal with its own delay).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from asterlite.fem.absorbing_elements import _edge_geometry, _face_geometry, _material
from asterlite.fem.element_errors import ElementError
from asterlite.fem.plane_elements import plane_coordinates

_EPS = np.finfo(float).eps


@dataclass
class PlaneWave:
    """One ONDE_PLANE occurrence: ``signal`` and ``displacement`` are
    callables of time (the latter may be None)."""

    kind: str
    direction: np.ndarray
    signal: object
    source: np.ndarray
    reflection: np.ndarray | None = None
    displacement: object | None = None
    waves: list = field(default_factory=list, repr=False)


@dataclass
class _Wave:
    amplitude: float
    polarisation: np.ndarray
    propagation: np.ndarray
    speed: float
    reference: float


def _evaluate(function, times: np.ndarray) -> np.ndarray:
    """A function of time on an array (0 before its start, as code_aster)."""
    out = np.zeros(times.shape)
    started = times >= 0.0
    flat = times[started]
    try:
        values = np.asarray(function(flat), dtype=float)
        if values.shape != flat.shape:
            raise ValueError
    except Exception:  # noqa: BLE001 - deck functions may only take scalars
        values = np.array([float(function(float(t))) for t in flat])
    out[started] = values
    return out


def _frame(wave: PlaneWave, dim: int):
    """code_aster's wave frame: (d, tangent, normal, cosa, sina, cosg, sing,
    sign of the tangent, dse flag) with d the unit direction."""
    given = np.asarray(wave.direction, dtype=float)
    if dim == 2:
        d = given[:2] / np.linalg.norm(given[:2])
        # the vertical is y; S waves move along d turned by +90 degrees
        return d, None, np.array([-d[1], d[0]]), d[1], d[0], 1.0, 0.0, 1.0, 1.0
    d = given / np.linalg.norm(given)
    cosa = d[2]
    if abs(d[2] - 1.0) <= _EPS:
        sina, cosg, sing = 0.0, 1.0, 0.0
    elif abs(d[1]) <= _EPS:
        sina, cosg, sing = d[0], 1.0, 0.0
    elif abs(d[0]) <= _EPS:
        sina, cosg, sing = d[1], 0.0, 1.0
    else:
        sina = np.sin(np.arccos(cosa)) * (1.0 if d[0] > 0.0 else -1.0)
        cosg, sing = d[0] / sina, d[1] / sina
    tangent = np.array([sing, -cosg, 0.0])
    sign = tangent[1] / abs(tangent[1]) if cosg > 0.0 else -tangent[0] / abs(tangent[0])
    tangent = tangent / np.linalg.norm(tangent)
    normal = np.array(
        [-tangent[1] * d[2], tangent[0] * d[2], -tangent[0] * d[1] + tangent[1] * d[0]]
    )
    dse = 1.0 if d[2] > 0.0 else 0.0
    return d, tangent, normal, cosa, sina, cosg, sing, sign, dse


def wave_set(wave: PlaneWave, dim: int, poisson: float, cp: float, cs: float) -> list[_Wave]:
    """The incident, reflected and converted plane waves of the free field."""
    kind = wave.kind
    d, tangent, normal, cosa, sina, cosg, sing, sign, dse = _frame(wave, dim)
    polar = {"P": d, "SV": normal, "S": normal, "SH": tangent}[kind]
    speed, other = (cp, cs) if kind == "P" else (cs, cp)
    x0 = np.asarray(wave.source, dtype=float)[:dim]
    h = float(d @ x0)
    waves = [_Wave(1.0, polar, d, speed, h)]
    if wave.reflection is None:
        return waves
    x1 = np.asarray(wave.reflection, dtype=float)[:dim]
    if not abs(cosa) > 0.0:  # horizontal incidence: reflected back along -d
        waves.append(_Wave(1.0, polar, -d, speed, h - 2.0 * float(d @ x1)))
        return waves
    ratio = np.sqrt(2.0 + 2.0 * poisson / (1.0 - 2.0 * poisson))  # c_p / c_s
    a2 = np.arcsin(sina)
    kr = 1.0 / ratio
    if kind == "P":
        b2 = np.arcsin(sina / ratio)
        nr = kr**2 * np.sin(2 * b2) * np.sin(2 * a2) + np.cos(2 * b2) ** 2
        reflected = (kr**2 * np.sin(2 * a2) * np.sin(2 * b2) - np.cos(2 * b2) ** 2) / nr
        converted = 2.0 * kr * np.sin(2 * a2) * np.cos(2 * b2) / nr
    elif kind in ("SV", "S"):
        if abs(sina * ratio) - 1.0 > _EPS:
            raise ElementError(
                "ONDE_PLANE: the S wave's incidence is beyond the critical angle "
                "(no reflected P wave)"
            )
        b2 = np.arcsin(sina * ratio * (dse if dim == 3 else 1.0))
        nr = kr**2 * np.sin(2 * b2) * np.sin(2 * a2) + np.cos(2 * a2) ** 2
        reflected = (kr**2 * np.sin(2 * a2) * np.sin(2 * b2) - np.cos(2 * a2) ** 2) / nr
        converted = -2.0 * kr * np.sin(2 * a2) * np.cos(2 * a2) / nr
    else:  # SH
        b2, reflected, converted = a2, 1.0, 0.0
    cb, sb = np.cos(b2), np.sin(b2)
    # directions mirrored by the surface; the converted wave leaves at b2
    mirror = d.copy()
    mirror[-1] = -mirror[-1]
    if dim == 3:
        outgoing = np.array([sb * cosg, sb * sing, -cb])
        converted_polar = np.array([cb * cosg, cb * sing, sb])
        vertical = 2
        source_in_plane = x0[0] * sina * cosg + x0[1] * sina * sing
    else:
        outgoing = np.array([sb, -cb])
        converted_polar = np.array([cb, sb])
        vertical = 1
        source_in_plane = x0[0] * sina
    depth = x1[vertical] - x0[vertical]
    dist1 = source_in_plane + (2.0 * x1[vertical] - x0[vertical]) * (-cosa)
    # the point of the surface the converted wave leaves from, shifted
    factor = 1.0 / ratio if kind == "P" else ratio
    shift = (sina / cosa) * depth - sb * depth * factor / cosa
    image = x0.copy()
    image[vertical] = x1[vertical] + cb * depth * factor / cosa
    if dim == 3:
        image[0] = x0[0] + shift * cosg
        image[1] = x0[1] + shift * sing
    else:
        image[0] = x0[0] + shift
    dist2 = float(outgoing @ image)
    if kind == "P":
        reflected_polar = mirror
        converted_polar = converted_polar
    elif kind in ("SV", "S"):
        reflected_polar = -polar.copy()
        reflected_polar[-1] = polar[-1]
        converted_polar = sign * outgoing
    else:
        reflected_polar = polar
    waves.append(_Wave(reflected, reflected_polar, mirror, speed, dist1))
    if converted:
        waves.append(_Wave(converted, converted_polar, outgoing, other, dist2))
    return waves


def free_field(waves, points: np.ndarray, times: np.ndarray, signal, displacement=None):
    """Velocity (T, Q, dim), displacement (T, Q, dim) or None, and the
    displacement gradient (T, Q, dim, dim) of the free field at points (Q, dim)."""
    dim = points.shape[1]
    velocity = np.zeros((len(times), len(points), dim))
    gradient = np.zeros((len(times), len(points), dim, dim))
    moved = None if displacement is None else np.zeros_like(velocity)
    for w in waves:
        delay = times[:, None] - (points @ w.propagation - w.reference)[None, :] / w.speed
        f = w.amplitude * _evaluate(signal, delay)
        velocity += f[..., None] * w.polarisation
        gradient -= (f / w.speed)[..., None, None] * np.einsum(
            "i,j->ij", w.polarisation, w.propagation
        )
        if moved is not None:
            g = w.amplitude * _evaluate(displacement, delay)
            moved += g[..., None] * w.polarisation
    return velocity, moved, gradient


def plane_wave_history(model, materials, cells, wave: PlaneWave, times):
    """Nodal forces the plane wave applies to the structure through absorbing
    cells at every instant: (nodes (m,), components (m,), values (n_times, m))."""
    mesh = model.mesh
    times = np.atleast_1d(np.asarray(times, dtype=float))
    cells = np.asarray(cells, dtype=int)
    if wave.source is None:
        raise ElementError("ONDE_PLANE without COOR_SOURCE (a signal of X and INST)")
    kinds: dict[tuple, list[int]] = {}
    for cell in cells:
        modelisation = model.cell_modelisation.get(int(cell))
        if modelisation not in ("3D_ABSO", "D_PLAN_ABSO"):
            raise ElementError(
                f"ONDE_PLANE on cell {mesh.cell_names[cell]}, which is not an absorbing "
                "boundary (3D_ABSO, D_PLAN_ABSO)"
            )
        kinds.setdefault((modelisation, mesh.cell_types[cell]), []).append(int(cell))
    nodes_out, comps_out, values_out = [], [], []
    for (modelisation, kind), members in kinds.items():
        members = np.array(members, dtype=int)
        plane = modelisation == "D_PLAN_ABSO"
        dim = 2 if plane else 3
        if plane and wave.kind not in ("P", "S"):
            raise ElementError(f"ONDE_PLANE TYPE_ONDE={wave.kind!r} on a plane model (P or S)")
        if not plane and wave.kind not in ("P", "SV", "SH"):
            raise ElementError(f"ONDE_PLANE TYPE_ONDE={wave.kind!r} on a 3D model (P, SV, SH)")
        conn = np.array([mesh.cell_nodes[c] for c in members], dtype=int)
        coords = plane_coordinates(mesh, conn) if plane else mesh.coords[conn]
        values, scale, normal = (_edge_geometry if plane else _face_geometry)(coords, kind)
        points = np.einsum("qa,eai->eqi", values, coords)  # (e, q, dim)
        props = _material(materials, members, mesh, modelisation)
        forces = np.zeros((len(times), len(members), conn.shape[1], dim))
        groups: dict[tuple, list[int]] = {}
        for k in range(len(members)):
            # NaN (no LONG_CARA) as None: NaNs never compare equal, so every
            # cell would make a group of its own
            key = tuple(
                None if np.isnan(value) else value
                for value in (
                    float(props[n][k]) for n in ("E", "NU", "RHO", "COEF_AMOR", "LONG_CARA")
                )
            )
            groups.setdefault(key, []).append(k)
        for (young, nu, rho, coef, length), rows in groups.items():
            rows = np.array(rows, dtype=int)
            lam = young * nu / ((1 + nu) * (1 - 2 * nu))
            mu = young / (2 * (1 + nu))
            cp, cs = np.sqrt((lam + 2 * mu) / rho), np.sqrt(mu / rho)
            waves = wave_set(wave, dim, nu, cp, cs)
            pts = points[rows].reshape(-1, dim)
            springs = wave.displacement is not None and length is not None
            velocity, moved, grad = free_field(
                waves, pts, times, wave.signal, wave.displacement if springs else None
            )
            shape = (len(times), len(rows), points.shape[1], dim)
            velocity, grad = velocity.reshape(shape), grad.reshape(shape + (dim,))
            n = normal[rows]
            strain = 0.5 * (grad + np.swapaxes(grad, -1, -2))
            trace = np.trace(strain, axis1=-2, axis2=-1)
            stress = 2 * mu * strain + lam * trace[..., None, None] * np.eye(dim)
            along = np.einsum("teqi,eqi->teq", velocity, n)[..., None] * n
            traction = -rho * coef * (cp * along + cs * (velocity - along))
            if springs:
                moved = moved.reshape(shape)
                along_u = np.einsum("teqi,eqi->teq", moved, n)[..., None] * n
                traction -= ((lam + 2 * mu) * along_u + mu * (moved - along_u)) / length
            traction -= np.einsum("teqij,eqj->teqi", stress, n)
            # te0498's vector, which DYNA_VIBRA subtracts: the applied force is its opposite
            forces[:, rows] = -np.einsum("eq,qa,teqi->teai", scale[rows], values, traction)
        comps = ("DX", "DY", "DZ")[:dim]
        nodes_out.append(np.repeat(conn.ravel(), dim))
        comps_out.extend(list(comps) * conn.size)
        values_out.append(forces.reshape(len(times), -1))
    return np.concatenate(nodes_out), comps_out, np.concatenate(values_out, axis=1)
