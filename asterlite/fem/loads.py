"""Nodal load terms of mechanical loads: nodal forces, gravity (PESANTEUR)
and distributed beam forces (FORCE_POUTRE).

Terms are ``(node, component, value)`` triples summed by
:func:`asterlite.fem.assemble.assemble_terms`.

- Gravity: ``M a`` with the consistent element masses of the cells (all of
  them, or the GROUP_MA of PESANTEUR) for a uniform acceleration ``g d``
  (translations only). For beams this is the consistent load of the weight
  ``rho A g`` per unit length (end forces and moments).
- FORCE_POUTRE: uniform forces / moments per unit length, in the global frame
  (FX FY FZ MX MY MZ) or the local one (N VY VZ MT MFY MFZ), turned into the
  consistent nodal loads of the cubic beam: ``q L / 2`` forces, ``q L^2 / 12``
  end moments, distributed bending moments ``m`` giving ``-/+ m`` forces.
"""

from __future__ import annotations

import numpy as np

from asterlite.fem import beam
from asterlite.fem.beam_elements import cell_angles
from asterlite.fem.elements import ElementError, element_blocks
from asterlite.fem.plane_loads import plane_cells, plane_load_terms, surface_force_terms
from asterlite.fem.solid_loads import solid_cells, solid_load_terms, volume_force_terms

_TRANSLATIONS = ("DX", "DY", "DZ")
GLOBAL_KEYS = ("FX", "FY", "FZ", "MX", "MY", "MZ")
LOCAL_KEYS = ("N", "VY", "VZ", "MT", "MFY", "MFZ")


def gravity_terms(model, characteristics, gravity: float, direction, materials=None, cells=None):
    """Nodal forces M a of a uniform acceleration ``gravity * direction/|direction|``."""
    d = np.asarray(direction, dtype=float)
    norm = np.linalg.norm(d)
    if norm == 0.0:
        raise ElementError("PESANTEUR DIRECTION is a zero vector")
    d = gravity * d / norm
    # 3D and plane solids: the weight integrated on the RIGI points, as code_aster does
    solid = solid_cells(model, cells)
    terms = volume_force_terms(model.mesh, solid, d, materials, per_mass=True)
    plane = plane_cells(model, cells)
    terms.extend(surface_force_terms(model, plane, d, materials, per_mass=True))
    if len(solid) or len(plane):
        pool = model.cell_modelisation if cells is None else np.asarray(cells, dtype=int).ravel()
        cells = sorted({int(c) for c in pool} - set(solid.tolist()) - set(plane.tolist()))
        if not cells:
            return terms
    for block in element_blocks(model, characteristics, "M", materials=materials, cells=cells):
        accel = np.array(
            [d[_TRANSLATIONS.index(c)] if c in _TRANSLATIONS else 0.0 for c in block.components]
        )
        n_el, per_el = block.nodes.shape
        forces = block.matrices @ np.tile(accel, per_el)  # (n_el, d)
        nodes = np.repeat(block.nodes, len(block.components), axis=1).ravel()
        comps = list(block.components) * (per_el * n_el)
        terms.extend(zip(nodes.tolist(), comps, forces.ravel().tolist(), strict=True))
    return terms


def _local_beam_vector(q: np.ndarray, length: np.ndarray) -> np.ndarray:
    """(n, 12) consistent local nodal loads of uniform loads q (n, 6) = local
    (fx, fy, fz, mx, my, mz) per unit length on beams of the given lengths."""
    L = length
    f = np.zeros((len(L), 12))
    fx, fy, fz, mx, my, mz = q.T
    f[:, 0] = f[:, 6] = fx * L / 2
    f[:, 1] = f[:, 7] = fy * L / 2
    f[:, 2] = f[:, 8] = fz * L / 2
    f[:, 3] = f[:, 9] = mx * L / 2
    f[:, 5] = fy * L * L / 12
    f[:, 11] = -fy * L * L / 12
    f[:, 4] = -fz * L * L / 12
    f[:, 10] = fz * L * L / 12
    # distributed bending moments: work m_z v' and -m_y w'
    f[:, 1] -= mz
    f[:, 7] += mz
    f[:, 2] += my
    f[:, 8] -= my
    return f


def beam_force_terms(model, characteristics, cells, values: dict, local: bool) -> list:
    """Consistent nodal terms of FORCE_POUTRE on beam (or bar) cells."""
    mesh = model.mesh
    cells = np.asarray(cells, dtype=int)
    keys = LOCAL_KEYS if local else GLOBAL_KEYS
    q = np.array([float(values.get(k) or 0.0) for k in keys])
    terms = []
    kinds = np.array([str(model.cell_modelisation.get(int(c))) for c in cells])
    for modelisation in sorted(set(kinds.tolist())):
        members = cells[kinds == modelisation]
        if modelisation not in beam.COMPONENTS:
            names = ", ".join(mesh.cell_names[c] for c in members[:3])
            raise ElementError(f"FORCE_POUTRE applies to beams, not to {modelisation} ({names})")
        conn = np.array([mesh.cell_nodes[c] for c in members], dtype=int).reshape(-1, 2)
        x1, x2 = mesh.coords[conn[:, 0]], mesh.coords[conn[:, 1]]
        length = beam.segment_lengths(x1, x2)
        rot = beam.rotation_from_angles(cell_angles(model, characteristics, members))
        comps = beam.COMPONENTS[modelisation]
        if len(comps) == 6:
            if local:
                q_local = np.broadcast_to(q, (len(members), 6))
            else:
                q_local = np.concatenate(
                    [np.einsum("eij,j->ei", rot, q[:3]), np.einsum("eij,j->ei", rot, q[3:])], axis=1
                )
            f_local = _local_beam_vector(q_local, length)
            r = beam.element_rotation(rot, 6)
            f = np.einsum("eji,ej->ei", r, f_local)
        else:
            dim = len(comps)
            if local:
                axis = (x2 - x1) / length[:, None]
                force = q[0] * axis
            else:
                force = np.broadcast_to(q[:3], (len(members), 3))
            half = force[:, :dim] * length[:, None] / 2
            f = np.concatenate([half, half], axis=1)
        nodes = np.repeat(conn, len(comps), axis=1).ravel()
        names = list(comps) * (2 * len(members))
        terms.extend(zip(nodes.tolist(), names, f.ravel().tolist(), strict=True))
    return terms


def load_terms(load, characteristics=None, materials=None, complex_values=False) -> list:
    """Every nodal term of one AFFE_CHAR_MECA load (constant values). A load
    with complex values (AFFE_CHAR_MECA_C) gives complex terms, for callers
    that compute on complex values only (``complex_values``)."""
    imaginary = getattr(load, "imaginary", None)
    if imaginary is not None:
        if not complex_values:
            from asterlite.errors import UnsupportedError

            raise UnsupportedError(
                f"the complex load {load.name or ''} (AFFE_CHAR_MECA_C) in a computation "
                "on real values (code_aster uses it in harmonic responses)"
            )
        real_terms = _real_load_terms(load, characteristics, materials)
        imag_terms = _real_load_terms(imaginary, characteristics, materials)
        return real_terms + [(n, c, 1j * v) for n, c, v in imag_terms]
    return _real_load_terms(load, characteristics, materials)


def _real_load_terms(load, characteristics=None, materials=None) -> list:
    model = load.model
    terms = list(load.nodal_forces)
    gravity = load.extra.get("PESANTEUR")
    if gravity is not None:
        terms.extend(
            gravity_terms(
                model,
                characteristics,
                gravity["GRAVITE"],
                gravity["DIRECTION"],
                materials=materials,
                cells=gravity.get("CELLS"),
            )
        )
    for item in load.extra.get("FORCE_POUTRE", []):
        terms.extend(
            beam_force_terms(model, characteristics, item["CELLS"], item["VALUES"], item["LOCAL"])
        )
    terms.extend(solid_load_terms(model.mesh, load.extra))
    terms.extend(plane_load_terms(model, load.extra))
    return terms
