"""Paraxial absorbing boundaries (``3D_ABSO`` on faces, ``D_PLAN_ABSO`` on
edges of plane-strain models), as code_aster's MEAB_FACE* / MEPASE* elements.

On a boundary of unit normal n, the outgoing waves of an elastic medium are
absorbed by the tractions ``t = -(rho c_p n n^T + rho c_s (I - n n^T)) v``
(the first-order paraxial condition, ``c_p`` and ``c_s`` the pressure and
shear wave speeds). Their element matrix is a damping (``AMOR_MECA``)

    C_e = int N^T (COEF_AMOR sqrt((lambda + 2 mu) rho) n n^T
                   + COEF_AMOR sqrt(mu rho) (I - n n^T)) N dS

with the material's ``COEF_AMOR`` (1 by default). When the material gives
``LONG_CARA`` (a length L), a stiffness of the same form with
``(lambda + 2 mu) / L`` and ``mu / L`` is added to ``RIGI_MECA`` (springs
that keep the boundary from drifting); without it the element has no
stiffness. The elements have no mass. Integration: code_aster's families
(edges: 2 and 4 points; faces: TRIA3 on its edge midpoints, QUAD4 2x2,
TRIA6 six points, QUAD8/9 3x3).
"""

from __future__ import annotations

from collections import defaultdict

import numpy as np

from asterlite.concepts.assembly import ElementBlock
from asterlite.fem.element_errors import ElementError
from asterlite.fem.element_materials import material_parameters
from asterlite.fem.plane_elements import plane_coordinates
from asterlite.fem.plane_loads import segment_basis
from asterlite.fem.solid_reference import tabulated

ABSORBING_MODELISATIONS = ("3D_ABSO", "D_PLAN_ABSO")
#: face cells of 3D_ABSO: reference element and RIGI family (MEAB_FACE3 ... 9)
FACE_FAMILIES = {
    "TRIA3": ("TR3", "COT3"),
    "TRIA6": ("TR6", "FPG6"),
    "QUAD4": ("QU4", "FPG4"),
    "QUAD8": ("QU8", "FPG9"),
    "QUAD9": ("QU9", "FPG9"),
}
EDGE_KINDS = ("SEG2", "SEG3")


def _face_geometry(coords, kind):
    """Shape values (q, n), weights x area (e, q), unit normals (e, q, 3)."""
    reference, family = FACE_FAMILIES[kind]
    values, grads, weights = tabulated(reference, family)
    tangents = np.einsum("qnj,eni->eqji", grads, coords)
    normal = np.cross(tangents[:, :, 0, :], tangents[:, :, 1, :])
    area = np.linalg.norm(normal, axis=2)
    if np.any(area <= 0.0):
        raise ElementError("a degenerate absorbing face (zero area)")
    return values, weights[None, :] * area, normal / area[:, :, None]


def _edge_geometry(coords, kind):
    """Shape values (q, n), weights x length (e, q), unit normals (e, q, 2)."""
    values, derivatives, weights = segment_basis(kind)
    tangent = np.einsum("qa,eai->eqi", derivatives, coords)
    length = np.linalg.norm(tangent, axis=2)
    if np.any(length <= 0.0):
        raise ElementError("a degenerate absorbing edge (zero length)")
    unit = tangent / length[:, :, None]
    normal = np.stack([unit[..., 1], -unit[..., 0]], axis=2)
    return values, weights[None, :] * length, normal


def boundary_matrices(values, scale, normal, normal_coef, tangential_coef) -> np.ndarray:
    """(e, d n, d n) int N_i N_l (a n n^T + b (I - n n^T)) dS, DOFs node by node."""
    dim = normal.shape[-1]
    nn = np.einsum("eqa,eqb->eqab", normal, normal)
    tensor = normal_coef[:, None, None, None] * nn + tangential_coef[:, None, None, None] * (
        np.eye(dim) - nn
    )
    out = np.einsum("eq,qi,ql,eqab->eialb", scale, values, values, tensor)
    e, n = out.shape[:2]
    return out.reshape(e, n * dim, n * dim)


#: parameters of a paraxial boundary's material (COEF_AMOR scales its damping;
#: LONG_CARA gives the optional springs)
ABSORBING = (
    ("E", np.nan),
    ("NU", np.nan),
    ("RHO", np.nan),
    ("COEF_AMOR", 1.0),
    ("LONG_CARA", np.nan),
)


def _material(materials, cells, mesh, modelisation):
    props = material_parameters(materials, cells, mesh, modelisation, ABSORBING)
    if any(np.any(np.isnan(props[k])) for k in ("E", "NU", "RHO")):
        raise ElementError(f"the material of {modelisation} elements needs E, NU and RHO (ELAS)")
    return props


def absorbing_blocks(
    model, characteristics, matrix, cells, materials=None, lumped=False, **_options
) -> list[ElementBlock]:
    """AMOR_MECA ('A') and, with LONG_CARA, RIGI_MECA ('K') of absorbing cells;
    they have no mass."""
    if matrix not in ("K", "M", "A"):
        raise ElementError(f"unknown element matrix {matrix!r}")
    if matrix == "M":
        return []
    mesh = model.mesh
    cells = np.asarray(cells, dtype=int)
    if not len(cells):
        return []
    modelisation = model.cell_modelisation[int(cells[0])]
    plane = modelisation == "D_PLAN_ABSO"
    accepted = EDGE_KINDS if plane else tuple(FACE_FAMILIES)
    grouped: dict[str, list[int]] = defaultdict(list)
    for cell in cells:
        if mesh.cell_types[cell] in accepted:
            grouped[mesh.cell_types[cell]].append(int(cell))
    blocks = []
    for kind, members in grouped.items():
        members = np.array(members, dtype=int)
        props = _material(materials, members, mesh, modelisation)
        young, poisson, density = props["E"], props["NU"], props["RHO"]
        lam = young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson))
        mu = young / (2.0 * (1.0 + poisson))
        if matrix == "A":
            normal_coef = props["COEF_AMOR"] * np.sqrt((lam + 2.0 * mu) * density)
            tangential_coef = props["COEF_AMOR"] * np.sqrt(mu * density)
        else:
            length = props["LONG_CARA"]
            given = ~np.isnan(length)
            if not given.any():
                continue
            inverse = np.where(given, 1.0 / np.where(given, length, 1.0), 0.0)
            normal_coef = (lam + 2.0 * mu) * inverse
            tangential_coef = mu * inverse
        conn = np.array([mesh.cell_nodes[c] for c in members], dtype=int)
        try:
            if plane:
                geometry = _edge_geometry(plane_coordinates(mesh, conn), kind)
                components = ("DX", "DY")
            else:
                geometry = _face_geometry(mesh.coords[conn], kind)
                components = ("DX", "DY", "DZ")
        except ElementError as exc:
            names = ", ".join(mesh.cell_names[c] for c in members[:3])
            raise ElementError(f"{modelisation} cells {names}: {exc}") from None
        mats = boundary_matrices(*geometry, normal_coef, tangential_coef)
        blocks.append(ElementBlock(nodes=conn, components=components, matrices=mats))
    return blocks
