"""Loads of plane and axisymmetric solids (``D_PLAN``, ``C_PLAN``, ``AXIS``).

- Surface forces (gravity ``PESANTEUR``, ``FORCE_INTERNE``): ``f_a = int N_a b dA``
  on the ``RIGI`` family of each surface cell, ``b = rho g`` for gravity with
  the in-plane components of the direction (code_aster's te0085 / te0093).
- Edge loads on SEG2 / SEG3 cells (code_aster's MEPLSE2/3, MEAXSE2/3, on
  two and four Gauss points): ``PRES_REP`` gives ``-p n + c t`` per unit
  length, ``c`` the ``CISA_2D`` shear, ``t = dx/ds`` the edge's tangent from
  its first node to its second and ``n = (t_y, -t_x)`` (the outward normal
  when the boundary runs counter-clockwise); ``FORCE_CONTOUR`` a force per
  unit length in the global frame.

``AXIS`` integrals carry the weight r (one radian), as the element matrices.
Terms are ``(node, component, value)`` triples.
"""

from __future__ import annotations

import numpy as np

from asterlite.fem.element_errors import ElementError
from asterlite.fem.plane_elements import (
    PLANE_MODELISATIONS,
    cells_by_type,
    plane_coordinates,
    surface_cells,
)
from asterlite.fem.solid_elements import jacobian_determinants
from asterlite.fem.solid_reference import tabulated

COMPONENTS = ("DX", "DY")

#: Lagrange points of code_aster's segments (SE3: the middle node last) and
#: the number of Gauss points of their RIGI family.
_SEGMENTS = {"SEG2": (np.array([-1.0, 1.0]), 2), "SEG3": (np.array([-1.0, 1.0, 0.0]), 4)}


def segment_basis(kind: str):
    """Values (q, n), derivatives (q, n) and weights (q,) on the RIGI family."""
    nodes, n_points = _SEGMENTS[kind]
    points, weights = np.polynomial.legendre.leggauss(n_points)
    coefficients = np.linalg.inv(np.vander(nodes, len(nodes), increasing=True))
    powers = np.vander(points, len(nodes), increasing=True)
    derivative = np.zeros_like(powers)
    for k in range(1, len(nodes)):
        derivative[:, k] = k * points ** (k - 1)
    return powers @ coefficients, derivative @ coefficients, weights


def _terms(conn: np.ndarray, forces: np.ndarray) -> list:
    nodes = np.repeat(conn.ravel(), 2)
    comps = list(COMPONENTS) * conn.size
    return list(zip(nodes.tolist(), comps, forces.ravel().tolist(), strict=True))


def plane_cells(model, cells=None) -> np.ndarray:
    """The cells (of ``cells``, default all) carrying a plane modelisation."""
    pool = model.cell_modelisation if cells is None else np.asarray(cells, dtype=int).ravel()
    return np.array(
        [int(c) for c in pool if model.cell_modelisation.get(int(c)) in PLANE_MODELISATIONS], int
    )


def surface_force_terms(model, cells, force, materials=None, per_mass=False) -> list:
    """Nodal forces of a uniform force (2,) per unit area (per unit mass,
    times the cell's RHO, with ``per_mass``) on plane surface cells."""
    mesh = model.mesh
    force = np.asarray(force, dtype=float)[:2]
    cells = np.asarray(cells, dtype=int)
    terms = []
    kinds = np.array([model.cell_modelisation[int(c)] for c in cells])
    for modelisation in sorted(set(kinds.tolist())):
        for kind_name, members in cells_by_type(
            mesh, cells[kinds == modelisation], modelisation
        ).items():
            kind = surface_cells(modelisation)[kind_name]
            values, grads, weights = tabulated(kind.reference, kind.rigi)
            conn = np.array([mesh.cell_nodes[c] for c in members], dtype=int)
            coords = plane_coordinates(mesh, conn)
            det = jacobian_determinants(coords, grads, mesh, members)
            scale = weights[None, :] * det
            if modelisation == "AXIS":
                scale = scale * np.einsum("qa,ea->eq", values, coords[..., 0])
            if per_mass:
                scale = scale * _densities(materials, members, mesh)[:, None]
            nodal = np.einsum("eq,qa->ea", scale, values)
            terms.extend(_terms(conn, nodal[:, :, None] * force[None, None, :]))
    return terms


def _densities(materials, cells, mesh) -> np.ndarray:
    if materials is None:
        raise ElementError("gravity on plane elements needs a material field (CHAM_MATER)")
    rho = materials.values(cells, "RHO", np.nan)
    if np.any(np.isnan(rho)):
        names = ", ".join(mesh.cell_names[c] for c in cells[np.isnan(rho)][:3])
        raise ElementError(f"gravity needs RHO in the material (ELAS) of cells {names}")
    return rho


def _edge_geometry(mesh, members, kind: str, axisymmetric: bool):
    """Connectivity, shape values (q, n), weights x length jacobian (x r) (e, q)
    and unit tangents (e, q, 2) of edge cells."""
    values, derivatives, weights = segment_basis(kind)
    conn = np.array([mesh.cell_nodes[c] for c in members], dtype=int)
    coords = plane_coordinates(mesh, conn)
    tangent = np.einsum("qa,eai->eqi", derivatives, coords)
    length = np.linalg.norm(tangent, axis=2)
    if np.any(length <= 0.0):
        bad = members[np.nonzero(np.any(length <= 0.0, axis=1))[0][0]]
        raise ElementError(f"edge cell {mesh.cell_names[bad]} is degenerate")
    scale = weights[None, :] * length
    if axisymmetric:
        scale = scale * np.einsum("qa,ea->eq", values, coords[..., 0])
    return conn, values, scale, tangent / length[:, :, None]


def _edges(model, cells):
    """(kind, axisymmetric) -> edge cells, checked to be edges of a plane model."""
    mesh = model.mesh
    out: dict[tuple[str, bool], list[int]] = {}
    for cell in np.asarray(cells, dtype=int):
        kind = mesh.cell_types[cell]
        modelisation = model.cell_modelisation.get(int(cell))
        if kind not in _SEGMENTS or modelisation not in PLANE_MODELISATIONS:
            raise ElementError(
                f"cell {mesh.cell_names[cell]} ({kind}) is not an edge of a plane model"
            )
        out.setdefault((kind, modelisation == "AXIS"), []).append(int(cell))
    return {k: np.array(v, dtype=int) for k, v in out.items()}


def edge_pressure_terms(model, cells, pressure: float, shear: float = 0.0) -> list:
    """Nodal forces of a uniform pressure (and CISA_2D shear) on edges."""
    terms = []
    for (kind, axisymmetric), members in _edges(model, cells).items():
        conn, values, scale, tangent = _edge_geometry(model.mesh, members, kind, axisymmetric)
        normal = np.stack([tangent[..., 1], -tangent[..., 0]], axis=2)
        traction = -float(pressure) * normal + float(shear) * tangent
        terms.extend(_terms(conn, np.einsum("eq,qa,eqi->eai", scale, values, traction)))
    return terms


def edge_force_terms(model, cells, force) -> list:
    """Nodal forces of a uniform force (2,) per unit length on edges."""
    force = np.asarray(force, dtype=float)[:2]
    terms = []
    for (kind, axisymmetric), members in _edges(model, cells).items():
        conn, values, scale, _ = _edge_geometry(model.mesh, members, kind, axisymmetric)
        nodal = np.einsum("eq,qa->ea", scale, values)
        terms.extend(_terms(conn, nodal[:, :, None] * force[None, None, :]))
    return terms


def plane_load_terms(model, extra: dict) -> list:
    """Terms of the plane items of a load (edge pressure and forces, surface forces)."""
    terms = []
    for item in extra.get("PRES_REP_2D", []):
        terms.extend(edge_pressure_terms(model, item["CELLS"], item["PRES"], item["CISA_2D"]))
    for item in extra.get("FORCE_CONTOUR", []):
        terms.extend(edge_force_terms(model, item["CELLS"], item["FORCE"]))
    for item in extra.get("FORCE_INTERNE_2D", []):
        terms.extend(surface_force_terms(model, item["CELLS"], item["FORCE"]))
    return terms
