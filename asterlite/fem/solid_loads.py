"""Loads and mass properties of 3D solid elements.

- Volume forces (gravity ``PESANTEUR``, ``FORCE_INTERNE``): ``f_a = int N_a b dV``
  on the ``RIGI`` family of each volume cell, ``b = rho g`` for gravity
  (code_aster integrates the weight on the stiffness points, not with the mass
  matrix).
- Face forces (``FORCE_FACE``, forces per unit area in the global frame) and
  pressure (``PRES_REP``: ``f = -p n``, ``n`` the unit normal
  ``dx/dxi x dx/deta`` given by the order of the face's nodes, so that a
  positive pressure pushes against the normal) on face cells, ``RIGI``
  family of code_aster's face elements.
- Mass properties (``POST_ELEM MASS_INER``): volume, first and second moments
  ``int rho x dV``, ``int rho x x^T dV`` on the ``RIGI`` family, as
  code_aster computes them for volume elements.

Terms are ``(node, component, value)`` triples.
"""

from __future__ import annotations

import numpy as np

from asterlite.fem.element_errors import ElementError
from asterlite.fem.solid_elements import cells_by_type, connectivity, jacobian_determinants
from asterlite.fem.solid_reference import FACE_CELLS, VOLUME_CELLS, tabulated

COMPONENTS = ("DX", "DY", "DZ")


def _terms(conn: np.ndarray, forces: np.ndarray) -> list:
    """Triples of nodal forces (e, n, 3) on the nodes conn (e, n)."""
    nodes = np.repeat(conn.ravel(), 3)
    comps = list(COMPONENTS) * conn.size
    return list(zip(nodes.tolist(), comps, forces.ravel().tolist(), strict=True))


def _densities(materials, cells, mesh) -> np.ndarray:
    if materials is None:
        raise ElementError("gravity on 3D elements needs a material field (CHAM_MATER)")
    rho = materials.values(cells, "RHO", np.nan)
    if np.any(np.isnan(rho)):
        bad = cells[np.isnan(rho)][:3]
        names = ", ".join(mesh.cell_names[c] for c in bad)
        raise ElementError(f"gravity needs RHO in the material (ELAS) of cells {names}")
    return rho


def volume_force_terms(mesh, cells, force, materials=None, per_mass=False) -> list:
    """Consistent nodal forces of a uniform body force ``force`` (3,) per unit
    volume, or per unit mass (times the cell's RHO) with ``per_mass``."""
    force = np.asarray(force, dtype=float)
    terms = []
    for kind, members in cells_by_type(mesh, cells).items():
        spec = VOLUME_CELLS[kind]
        values, grads, weights = tabulated(spec.reference, spec.rigi)
        conn = connectivity(mesh, members)
        det = jacobian_determinants(mesh.coords[conn], grads, mesh, members)
        scale = weights[None, :] * det
        if per_mass:
            scale = scale * _densities(materials, members, mesh)[:, None]
        nodal = np.einsum("eq,qa->ea", scale, values)
        terms.extend(_terms(conn, nodal[:, :, None] * force[None, None, :]))
    return terms


def solid_cells(model, cells=None) -> np.ndarray:
    """The cells (of ``cells``, default all) that carry the 3D modelisation."""
    pool = model.cell_modelisation if cells is None else np.asarray(cells, dtype=int).ravel()
    return np.array([int(c) for c in pool if model.cell_modelisation.get(int(c)) == "3D"], int)


def _face_geometry(mesh, members, spec):
    """Shape values (q, n), weights x area jacobian (e, q) and unit normals
    (e, q, 3) of face cells."""
    values, grads, weights = tabulated(spec.reference, spec.rigi)
    conn = connectivity(mesh, members)
    coords = mesh.coords[conn]
    tangents = np.einsum("qnj,eni->eqji", grads, coords)  # (e, q, 2, 3)
    normal = np.cross(tangents[:, :, 0, :], tangents[:, :, 1, :])
    area = np.linalg.norm(normal, axis=2)
    if np.any(area <= 0.0):
        bad = members[np.nonzero(np.any(area <= 0.0, axis=1))[0][0]]
        raise ElementError(f"face cell {mesh.cell_names[bad]} is degenerate")
    return conn, values, weights[None, :] * area, normal / area[:, :, None]


def _faces_by_type(mesh, cells) -> dict[str, np.ndarray]:
    out: dict[str, list[int]] = {}
    for cell in np.asarray(cells, dtype=int):
        kind = mesh.cell_types[cell]
        if kind not in FACE_CELLS:
            raise ElementError(f"cell {mesh.cell_names[cell]} ({kind}) is not a face of a 3D model")
        out.setdefault(kind, []).append(int(cell))
    return {k: np.array(v, dtype=int) for k, v in out.items()}


def face_force_terms(mesh, cells, force) -> list:
    """Nodal forces of a uniform surface force (3,) per unit area on faces."""
    force = np.asarray(force, dtype=float)
    terms = []
    for kind, members in _faces_by_type(mesh, cells).items():
        conn, values, wa, _ = _face_geometry(mesh, members, FACE_CELLS[kind])
        nodal = np.einsum("eq,qa->ea", wa, values)
        terms.extend(_terms(conn, nodal[:, :, None] * force[None, None, :]))
    return terms


def pressure_terms(mesh, cells, pressure: float) -> list:
    """Nodal forces of a uniform pressure on faces: ``-p n dA``."""
    terms = []
    for kind, members in _faces_by_type(mesh, cells).items():
        conn, values, wa, normals = _face_geometry(mesh, members, FACE_CELLS[kind])
        nodal = -float(pressure) * np.einsum("eq,qa,eqi->eai", wa, values, normals)
        terms.extend(_terms(conn, nodal))
    return terms


def solid_load_terms(mesh, extra: dict) -> list:
    """Terms of the FORCE_FACE, PRES_REP and FORCE_INTERNE items of a load."""
    terms = []
    for item in extra.get("FORCE_FACE", []):
        terms.extend(face_force_terms(mesh, item["CELLS"], item["FORCE"]))
    for item in extra.get("PRES_REP", []):
        terms.extend(pressure_terms(mesh, item["CELLS"], item["PRES"]))
    for item in extra.get("FORCE_INTERNE", []):
        terms.extend(volume_force_terms(mesh, item["CELLS"], item["FORCE"]))
    return terms


def solid_inertia(model, materials, cells=None) -> np.ndarray:
    """6x6 ``R^T M R`` of the 3D cells for the rigid-body modes about the
    origin (translations, then rotations ``e_k x x``), from the volume
    integrals of rho, rho x and rho x x^T on the RIGI family."""
    mesh = model.mesh
    members_all = solid_cells(model, cells)
    mass, first, second = 0.0, np.zeros(3), np.zeros((3, 3))
    for kind, members in cells_by_type(mesh, members_all).items():
        spec = VOLUME_CELLS[kind]
        values, grads, weights = tabulated(spec.reference, spec.rigi)
        conn = connectivity(mesh, members)
        coords = mesh.coords[conn]
        det = jacobian_determinants(coords, grads, mesh, members)
        rho = _densities(materials, members, mesh)
        dm = rho[:, None] * det * weights[None, :]  # (e, q)
        points = np.einsum("qa,eai->eqi", values, coords)
        mass += float(dm.sum())
        first += np.einsum("eq,eqi->i", dm, points)
        second += np.einsum("eq,eqi,eqj->ij", dm, points, points)
    return rigid_matrix(mass, first, second)


def rigid_matrix(mass: float, first: np.ndarray, second: np.ndarray) -> np.ndarray:
    """The 6x6 rigid-body mass matrix of a body with mass m, first moment
    s = int x dm and second moment S = int x x^T dm about the origin."""
    out = np.zeros((6, 6))
    out[:3, :3] = mass * np.eye(3)
    skew = np.array(
        [[0.0, -first[2], first[1]], [first[2], 0.0, -first[0]], [-first[1], first[0], 0.0]]
    )
    # rotation k moves a point by e_k x x: translation coupling int (e_k x x)_i dm
    out[3:, :3] = skew
    out[:3, 3:] = skew.T
    out[3:, 3:] = np.trace(second) * np.eye(3) - second
    return out
