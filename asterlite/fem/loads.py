"""Nodal load terms of mechanical loads: nodal forces, gravity (PESANTEUR)
and distributed beam forces (FORCE_POUTRE).

Terms are ``(node, component, value)`` triples summed by
:func:`asterlite.fem.assemble.assemble_terms`.

- Gravity: ``M a`` with the consistent element masses of the cells (all of
  them, or the GROUP_MA of PESANTEUR) for a uniform acceleration ``g d``
  (translations only). For beams this is the consistent load of the weight
  ``rho A g`` per unit length (end forces and moments).
- FORCE_POUTRE: forces / moments per unit length, uniform or varying linearly
  along each cell (AFFE_CHAR_MECA_F: values at its two nodes), in the global
  frame (FX FY FZ MX MY MZ) or the local one (N VY VZ MT MFY MFZ), turned into
  the consistent nodal loads of the cubic beam (uniform: ``q L / 2`` forces,
  ``q L^2 / 12`` end moments, distributed bending moments ``m`` giving ``-/+ m``
  forces).
- FORCE_ELEC: Laplace forces on beam conductors
  (:mod:`asterlite.fem.laplace_force`), in the global frame.
"""

from __future__ import annotations

import numpy as np

from asterlite.errors import CommandError
from asterlite.fem import beam
from asterlite.fem.beam import cell_angles
from asterlite.fem.elements import ElementError, element_blocks
from asterlite.fem.laplace_force import laplace_vectors
from asterlite.fem.pipe_elements import (
    PIPE_MODELISATIONS,
    pipe_gravity_terms,
    pipe_pressure_terms,
)
from asterlite.fem.plane_loads import plane_cells, plane_load_terms, surface_force_terms
from asterlite.fem.plate_elements import plate_gravity_terms
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
    # plates: the weight spread on the corners (code_aster's te0032)
    pool = model.cell_modelisation if cells is None else np.asarray(cells, dtype=int).ravel()
    plates = np.array([int(c) for c in pool if model.cell_modelisation.get(int(c)) == "DKT"], int)
    terms.extend(plate_gravity_terms(model, characteristics, materials, plates, d))
    # pipes: the weight on the translations only (code_aster's te0583)
    pipes = np.array(
        [int(c) for c in pool if model.cell_modelisation.get(int(c)) in PIPE_MODELISATIONS], int
    )
    terms.extend(pipe_gravity_terms(model, characteristics, materials, pipes, d))
    if len(solid) or len(plane) or len(plates) or len(pipes):
        handled = set(solid.tolist()) | set(plane.tolist()) | set(plates.tolist())
        handled |= set(pipes.tolist())
        cells = sorted({int(c) for c in pool} - handled)
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


def _local_beam_vector(q1: np.ndarray, q2: np.ndarray, length: np.ndarray) -> np.ndarray:
    """(n, 12) consistent local nodal loads of loads varying linearly from q1
    at the first node to q2 at the second, (n, 6) local (fx, fy, fz, mx, my,
    mz) per unit length, on beams of the given lengths (code_aster's ptfop1
    for constant sections: the cubic beam's work of the trapezoidal loads)."""
    L = length
    f = np.zeros((len(L), 12))
    a, b = q1.T, q2.T  # a[k], b[k]: component k at the first and second node
    for k in (0, 3):  # axial force, torque: linear shape functions
        f[:, k] = (a[k] / 3 + b[k] / 6) * L
        f[:, 6 + k] = (a[k] / 6 + b[k] / 3) * L
    f[:, 1] = (7 * a[1] + 3 * b[1]) * L / 20 - (a[5] + b[5]) / 2
    f[:, 7] = (3 * a[1] + 7 * b[1]) * L / 20 + (a[5] + b[5]) / 2
    f[:, 2] = (7 * a[2] + 3 * b[2]) * L / 20 + (a[4] + b[4]) / 2
    f[:, 8] = (3 * a[2] + 7 * b[2]) * L / 20 - (a[4] + b[4]) / 2
    L2 = L * L
    f[:, 4] = -(a[2] / 20 + b[2] / 30) * L2 - (b[4] - a[4]) * L / 12
    f[:, 10] = (a[2] / 30 + b[2] / 20) * L2 + (b[4] - a[4]) * L / 12
    f[:, 5] = (a[1] / 20 + b[1] / 30) * L2 - (b[5] - a[5]) * L / 12
    f[:, 11] = -(a[1] / 30 + b[1] / 20) * L2 + (b[5] - a[5]) * L / 12
    return f


def _end_values(cells, values, local: bool, values_2=None):
    """Components (n_cells, 6) at the first and the second node of each cell."""
    keys = LOCAL_KEYS if local else GLOBAL_KEYS
    if values_2 is None:
        q = np.array([float(values.get(k) or 0.0) for k in keys])
        return np.broadcast_to(q, (len(cells), 6)), np.broadcast_to(q, (len(cells), 6))
    return np.asarray(values, float), np.asarray(values_2, float)


def _beam_local_vectors(rot, length, q1, q2, local: bool) -> np.ndarray:
    """(n, 12) local-frame consistent loads of 6-DOF beams (q in the global
    frame unless ``local``)."""
    if not local:
        q1, q2 = (
            np.concatenate(
                [np.einsum("eij,ej->ei", rot, q[:, :3]), np.einsum("eij,ej->ei", rot, q[:, 3:])],
                axis=1,
            )
            for q in (q1, q2)
        )
    return _local_beam_vector(q1, q2, length)


def _geometry(model, characteristics, members):
    mesh = model.mesh
    conn = np.array([mesh.cell_nodes[c] for c in members], dtype=int).reshape(-1, 2)
    x1, x2 = mesh.coords[conn[:, 0]], mesh.coords[conn[:, 1]]
    length = beam.segment_lengths(x1, x2)
    rot = beam.rotation_from_angles(cell_angles(model, characteristics, members))
    return conn, x1, x2, length, rot


#: components of the beams and bars FORCE_POUTRE loads (the multifibre beams'
#: consistent line loads are POU_D_E's and POU_D_TG's: code_aster's te0150 serves them all)
_LOADED_COMPONENTS = {
    **beam.COMPONENTS,
    "POU_D_EM": beam.BEAM_COMPONENTS,
    "POU_D_TGM": beam.COMPONENTS["POU_D_TG"],
}


def beam_force_terms(model, characteristics, cells, values, local: bool, values_2=None) -> list:
    """Consistent nodal terms of FORCE_POUTRE on beam (or bar) cells: ``values``
    a dict of uniform components, or (with ``values_2``) arrays (n_cells, 6) of
    the components at the first and the second node of each cell."""
    mesh = model.mesh
    cells = np.asarray(cells, dtype=int)
    at_first, at_second = _end_values(cells, values, local, values_2)
    terms = []
    kinds = np.array([str(model.cell_modelisation.get(int(c))) for c in cells])
    for modelisation in sorted(set(kinds.tolist())):
        chosen = kinds == modelisation
        members = cells[chosen]
        q1, q2 = at_first[chosen], at_second[chosen]
        if modelisation not in _LOADED_COMPONENTS:
            names = ", ".join(mesh.cell_names[c] for c in members[:3])
            raise ElementError(f"FORCE_POUTRE applies to beams, not to {modelisation} ({names})")
        conn, x1, x2, length, rot = _geometry(model, characteristics, members)
        comps = _LOADED_COMPONENTS[modelisation]
        if len(comps) >= 6:
            f_local = _beam_local_vectors(rot, length, q1, q2, local)
            r = beam.element_rotation(rot, 6)
            f = np.einsum("eji,ej->ei", r, f_local)
            if len(comps) == 7:  # POU_D_TG: the line load does no work on GRX
                f = np.insert(f.reshape(-1, 2, 6), 6, 0.0, axis=2).reshape(-1, 14)
        else:
            dim = len(comps)
            if local:
                axis = (x2 - x1) / length[:, None]
                force1, force2 = q1[:, :1] * axis, q2[:, :1] * axis
            else:
                force1, force2 = q1[:, :3], q2[:, :3]
            first = (force1 / 3 + force2 / 6)[:, :dim] * length[:, None]
            second = (force1 / 6 + force2 / 3)[:, :dim] * length[:, None]
            f = np.concatenate([first, second], axis=1)
        nodes = np.repeat(conn, len(comps), axis=1).ravel()
        names = list(comps) * (2 * len(members))
        terms.extend(zip(nodes.tolist(), names, f.ravel().tolist(), strict=True))
    return terms


def beam_element_loads(model, characteristics, cells, load) -> np.ndarray:
    """(n_cells, 12) local-frame consistent loads of a load's FORCE_POUTRE on
    6-DOF beam cells (what code_aster's beam elements take off their internal
    forces when CALC_CHAMP gives the load in EXCIT); nodal forces act on no
    element. Gravity is refused here (not taken off yet)."""
    cells = np.asarray(cells, dtype=int)
    out = np.zeros((len(cells), 12))
    if load.extra.get("PESANTEUR") is not None:
        raise ElementError("CALC_CHAMP EXCIT with a PESANTEUR load on beams")
    position = {int(c): k for k, c in enumerate(cells)}
    for item in load.extra.get("FORCE_POUTRE", []):
        item_cells = np.asarray(item["CELLS"], dtype=int)
        q1, q2 = _end_values(item_cells, item["VALUES"], item["LOCAL"], item.get("VALUES_2"))
        here = np.array([int(c) in position for c in item_cells], dtype=bool)
        members = item_cells[here]
        if not members.size:
            continue
        _, _, _, length, rot = _geometry(model, characteristics, members)
        f_local = _beam_local_vectors(rot, length, q1[here], q2[here], item["LOCAL"])
        rows = [position[int(c)] for c in members]
        np.add.at(out, rows, f_local)
    return out


def load_terms(
    load, characteristics=None, materials=None, complex_values=False, history_apart=False
) -> list:
    """Every nodal term of one AFFE_CHAR_MECA load (constant values). A load
    with complex values (AFFE_CHAR_MECA_C) gives complex terms, for callers
    that compute on complex values only (``complex_values``). A caller that
    takes the load's history of time and space apart (``history_apart``:
    :func:`load_history`) gets the constant terms only; any other caller
    is refused such a load by name."""
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
    return _real_load_terms(load, characteristics, materials, history_apart)


#: instants of a load history computed at once (bounds its work arrays)
HISTORY_CHUNK = 8


def load_history(load, materials):
    """The part of a load that is a history of time and space, as a function
    ``times -> (nodes, components, values (n_times, m))``; None when the load
    has none. Such parts are an ``AFFE_CHAR_MECA_F/ONDE_PLANE`` wave (each
    boundary point sees the wave with its own delay, so it is no vector times
    f(t)), an ``EVOL_CHAR`` (nodal forces given at instants) and the
    ``AFFE_CHAR_MECA_F/FORCE_NODALE`` values that are functions of INST (and
    of the node's X, Y, Z)."""
    parts = []
    waves = load.extra.get("ONDE_PLANE")
    if waves:
        parts.append(_plane_wave_history(load, materials, waves))
    evolution = load.extra.get("EVOL_CHAR")
    if evolution is not None:
        parts.append(evol_char_history(evolution, load.name or ""))
    timed = load.extra.get("FORCE_NODALE_INST")
    if timed:
        parts.append(nodal_force_history(timed))
    if len(parts) < 2:
        return parts[0] if parts else None

    def history(times):
        found = [part(times) for part in parts]
        nodes = np.concatenate([p[0] for p in found])
        components = [c for p in found for c in p[1]]
        return nodes, components, np.concatenate([p[2] for p in found], axis=1)

    return history


def _plane_wave_history(load, materials, waves):
    from asterlite.fem.plane_wave import plane_wave_history  # ONDE_PLANE decks only

    def at(times):
        # each ONDE_PLANE occurrence adds its own terms
        parts = [
            plane_wave_history(load.model, materials, wave["CELLS"], wave["WAVE"], times)
            for wave in waves
        ]
        nodes = np.concatenate([p[0] for p in parts])
        components = [c for p in parts for c in p[1]]
        return nodes, components, np.concatenate([p[2] for p in parts], axis=1)

    def history(times):
        # by a few instants at a time: the free field's gradients and stresses
        # at every boundary point would otherwise be held for every instant at once
        times = np.atleast_1d(np.asarray(times, dtype=float))
        nodes, components, first = at(times[:HISTORY_CHUNK])
        starts = range(HISTORY_CHUNK, times.size, HISTORY_CHUNK)
        values = [first] + [at(times[k : k + HISTORY_CHUNK])[2] for k in starts]
        return nodes, components, np.concatenate(values, axis=0)

    return history


def nodal_force_history(timed):
    """Nodal forces given as functions of INST at their nodes
    (``[(node, component, ValueInTime)]``), at any instants."""
    nodes = np.array([node for node, _, _ in timed], dtype=int)
    components = [component for _, component, _ in timed]

    def history(times):
        times = np.atleast_1d(np.asarray(times, dtype=float))
        values = np.empty((times.size, len(timed)))
        for k, (_, _, value) in enumerate(timed):
            values[:, k] = value.evaluate(times)
        return nodes, components, values

    return history


def evol_char_history(evolution, name: str = ""):
    """The FORC_NODA of an evol_char at any instants, linear between its
    stored instants; an instant outside them is an error, as in code_aster
    (its rsinch without extrapolation: CHARGES8_2). Only the DOFs that carry
    a force at some instant are listed."""
    stored = np.asarray(evolution.times, dtype=float)
    forces = np.asarray(evolution.fields["FORC_NODA"], dtype=float)
    loaded = np.flatnonzero(np.any(forces != 0.0, axis=0))
    forces = forces[:, loaded]
    nodes = np.array([evolution.numbering.dofs[i][0] for i in loaded], dtype=int)
    components = [evolution.numbering.dofs[i][1] for i in loaded]
    span = max(abs(stored[0]), abs(stored[-1]), 1.0)
    tolerance = 1.0e-10 * span

    def history(times):
        times = np.atleast_1d(np.asarray(times, dtype=float))
        outside = (times < stored[0] - tolerance) | (times > stored[-1] + tolerance)
        if np.any(outside):
            t = float(times[np.flatnonzero(outside)[0]])
            raise CommandError(
                f"the EVOL_CHAR of the load {name} has no forces at INST={t:g}: it holds "
                f"[{stored[0]:g}, {stored[-1]:g}] (code_aster does not extrapolate it either)",
                path="EXCIT",
            )
        right = np.clip(np.searchsorted(stored, times, side="right"), 1, stored.size - 1)
        left = right - 1
        width = stored[right] - stored[left]
        weight = np.clip((times - stored[left]) / np.where(width > 0, width, 1.0), 0.0, 1.0)
        values = (1.0 - weight)[:, None] * forces[left] + weight[:, None] * forces[right]
        return nodes, components, values

    return history


def _real_load_terms(load, characteristics=None, materials=None, history_apart=False) -> list:
    if load.extra.get("EVOL_CHAR") is not None and not history_apart:
        from asterlite.errors import UnsupportedError

        raise UnsupportedError(
            f"the EVOL_CHAR load {load.name or ''} where a fixed load vector is taken: "
            "its forces are a history of instants (asterlite.fem.loads.load_history), "
            "which this command does not take yet"
        )
    if load.extra.get("FORCE_NODALE_INST") and not history_apart:
        from asterlite.errors import UnsupportedError

        raise UnsupportedError(
            f"the load {load.name or ''} whose FORCE_NODALE are functions of INST "
            "(AFFE_CHAR_MECA_F) where a fixed load vector is taken: its forces are a "
            "history (asterlite.fem.loads.load_history), which this command does not take yet"
        )
    if load.extra.get("ONDE_PLANE") is not None and not history_apart:
        from asterlite.errors import UnsupportedError

        # each boundary point sees the wave with its own delay: no vector times f(t)
        raise UnsupportedError(
            f"the ONDE_PLANE load {load.name or ''} (AFFE_CHAR_MECA_F) where a fixed "
            "load vector is taken: its forces are a history of time and space "
            "(asterlite.fem.plane_wave.plane_wave_history), which this command does not "
            "take yet"
        )
    model = load.model
    terms = list(load.nodal_forces)
    terms.extend(load.extra.get("VECT_ASSE", ()))
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
            beam_force_terms(
                model,
                characteristics,
                item["CELLS"],
                item["VALUES"],
                item["LOCAL"],
                item.get("VALUES_2"),
            )
        )
    terms.extend(laplace_force_terms(model, load.extra.get("FORCE_ELEC")))
    for item in load.extra.get("FORCE_TUYAU", []):
        if characteristics is None:
            raise ElementError("FORCE_TUYAU needs the pipes' CARA_ELEM")
        terms.extend(pipe_pressure_terms(model, characteristics, item["CELLS"], item["PRES"]))
    terms.extend(solid_load_terms(model.mesh, load.extra))
    terms.extend(plane_load_terms(model, load.extra))
    return terms


_BEAM_FORCES_MOMENTS = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")


def laplace_force_terms(model, on_cells) -> list:
    """Nodal terms of FORCE_ELEC: ``on_cells`` maps each beam cell to its
    second conductor (a warping DOF, POU_D_TG's GRX, gets nothing)."""
    if not on_cells:
        return []
    mesh = model.mesh
    by_conductor: dict = {}
    for cell, conductor in on_cells.items():
        by_conductor.setdefault(conductor, []).append(int(cell))
    coords = np.asarray(mesh.coords, dtype=float)
    if coords.shape[1] < 3:
        coords = np.pad(coords, ((0, 0), (0, 3 - coords.shape[1])))
    terms = []
    for conductor, cells in by_conductor.items():
        conn = np.array([mesh.cell_nodes[c][:2] for c in cells], dtype=int)
        names = [mesh.cell_names[c] for c in cells]
        vectors = laplace_vectors(coords[conn[:, 0]], coords[conn[:, 1]], conductor, names)
        nodes = np.repeat(conn, 6, axis=1).ravel()
        comps = list(_BEAM_FORCES_MOMENTS) * (2 * len(cells))
        terms.extend(zip(nodes.tolist(), comps, vectors.ravel().tolist(), strict=True))
    return terms
