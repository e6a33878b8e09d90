"""Element matrices of plane and axisymmetric solids (``D_PLAN``, ``C_PLAN``,
``AXIS``), vectorised over the cells of one type.

The mesh is the (x, y) plane (``AXIS``: x the radius r, y the axis); a
``D_PLAN`` or ``C_PLAN`` element has unit thickness, an ``AXIS`` element is
one radian of the solid of revolution (code_aster's conventions: its
integrals carry the weight r, not 2 pi r). Strains are
``(EPXX, EPYY, EPZZ, 2 EPXY)``, ``EPZZ`` being 0 in plane strain, free in
plane stress and the hoop strain ``u_r / r`` in axisymmetry.

- stiffness ``K = sum_g w_g |J| (r) B^T D B`` on the ``RIGI`` family of
  code_aster's element (``MEDPTR3`` ... ``MEAXQU9``: one point on TRIA3,
  three on TRIA6 (six in ``AXIS``), 2x2 on QUAD4, 3x3 on QUAD8/QUAD9);
- mass ``M = sum_g w_g |J| (r) rho N N^T`` on the ``MASS`` family, consistent
  only: code_aster's plane elements have no ``MASS_MECA_DIAG``, so a lumped
  mass is refused;
- damping ``C = AMOR_ALPHA K + AMOR_BETA M`` (Rayleigh, per element).

D is isotropic (E, NU) or orthotropic (ELAS_ORTH: L and T in the plane turned
by MASSIF's first angle, N out of it; :mod:`asterlite.fem.orthotropic`).
A viscoelastic material (ELAS_VISCO) gives a complex D: RIGI_MECA takes
the real part of K, RIGI_MECA_HYST (``complex_stiffness``) the whole of it
(code_aster's te0230).

Edge cells (SEG2, SEG3) carried by these modelisations take loads only.
"""

from __future__ import annotations

from collections import defaultdict

import numpy as np

from asterlite.concepts.assembly import ElementBlock
from asterlite.fem.element_errors import ElementError
from asterlite.fem.element_materials import elastic_values
from asterlite.fem.orthotropic import global_hooke, plane_hooke
from asterlite.fem.solid_elements import jacobian_determinants, jacobians
from asterlite.fem.solid_reference import CellKind, tabulated

COMPONENTS = ("DX", "DY")
PLANE_MODELISATIONS = ("D_PLAN", "C_PLAN", "AXIS")
#: Stress and strain components of the plane elements (code_aster's order).
STRESS_COMPONENTS = ("SIXX", "SIYY", "SIZZ", "SIXY")
STRAIN_COMPONENTS = ("EPXX", "EPYY", "EPZZ", "EPXY")

#: surface cells of the plane modelisations (code_aster's MEDPTR3 ... MEDPQU9)
_PLANE_CELLS = {
    "TRIA3": CellKind("TR3", "FPG1", "FPG3"),
    "TRIA6": CellKind("TR6", "FPG3", "FPG6"),
    "QUAD4": CellKind("QU4", "FPG4", "FPG4"),
    "QUAD8": CellKind("QU8", "FPG9", "FPG9"),
    "QUAD9": CellKind("QU9", "FPG9", "FPG9"),
}
#: code_aster's axisymmetric six-node triangle integrates its stiffness on six points
_AXIS_CELLS = {**_PLANE_CELLS, "TRIA6": CellKind("TR6", "FPG6", "FPG6")}
EDGE_CELLS = ("SEG2", "SEG3")


def surface_cells(modelisation: str) -> dict[str, CellKind]:
    """Cell type -> reference element and Gauss families of a plane modelisation."""
    return _AXIS_CELLS if modelisation == "AXIS" else _PLANE_CELLS


def cells_by_type(mesh, cells, modelisation: str) -> dict[str, np.ndarray]:
    """Surface cells grouped by type (edges left out)."""
    kinds = surface_cells(modelisation)
    grouped: dict[str, list[int]] = defaultdict(list)
    for cell in np.asarray(cells, dtype=int):
        kind = mesh.cell_types[cell]
        if kind in kinds:
            grouped[kind].append(int(cell))
    return {k: np.array(v, dtype=int) for k, v in grouped.items()}


def plane_coordinates(mesh, conn: np.ndarray) -> np.ndarray:
    """(e, n, 2) in-plane coordinates of cells; the cells must lie in z = const."""
    coords = mesh.coords[conn]
    z = coords[..., 2]
    off = np.abs(z - z[:, :1]) > 1e-9 * (1.0 + np.abs(coords[..., :2]).max())
    if np.any(off):
        nodes = conn[np.nonzero(np.any(off, axis=1))[0][0]]
        names = ", ".join(mesh.node_names[n] for n in nodes)
        raise ElementError(f"plane elements must lie in a plane z = const (nodes {names})")
    return coords[..., :2]


def elasticity(modelisation: str, young, poisson) -> np.ndarray:
    """(e, 4, 4) elasticity on (xx, yy, zz, engineering xy), complex for
    complex moduli."""
    young = np.asarray(young)
    poisson = np.asarray(poisson)
    d = np.zeros((len(young), 4, 4), dtype=np.result_type(young, poisson, float))
    if modelisation == "C_PLAN":
        c = young / (1.0 - poisson**2)
        d[:, 0, 0] = d[:, 1, 1] = c
        d[:, 0, 1] = d[:, 1, 0] = c * poisson
        d[:, 3, 3] = c * (1.0 - poisson) / 2.0
        return d
    lam = young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson))
    mu = young / (2.0 * (1.0 + poisson))
    d[:, :3, :3] = lam[:, None, None]
    for i in range(3):
        d[:, i, i] += 2.0 * mu
    d[:, 3, 3] = mu
    return d


def strain_operator(modelisation: str, coords, kind: CellKind, family: str):
    """B (e, q, 4, 2n) and the integration weights w |J| (r) (e, q)."""
    values, grads, weights = tabulated(kind.reference, family)
    g, det = jacobians(coords, grads)
    e, q, n, _ = g.shape
    b = np.zeros((e, q, 4, 2 * n))
    b[:, :, 0, 0::2] = g[..., 0]
    b[:, :, 1, 1::2] = g[..., 1]
    b[:, :, 3, 0::2] = g[..., 1]
    b[:, :, 3, 1::2] = g[..., 0]
    scale = det * weights[None, :]
    if modelisation == "AXIS":
        radius = np.einsum("qa,ea->eq", values, coords[..., 0])
        if np.any(radius <= 0.0):
            raise ElementError("axisymmetric elements need x = r > 0 at their Gauss points")
        b[:, :, 2, 0::2] = values[None, :, :] / radius[:, :, None]
        scale = scale * radius
    return b, scale


def stiffness(modelisation: str, coords, kind: CellKind, young, poisson, hooke=None) -> np.ndarray:
    """(e, 2n, 2n) stiffness; ``hooke``: (e, 4, 4) Hooke matrices to use
    instead of the isotropic ones of ``young`` and ``poisson``."""
    b, scale = strain_operator(modelisation, coords, kind, kind.rigi)
    d = elasticity(modelisation, young, poisson) if hooke is None else hooke
    db = np.einsum("eij,eqjk->eqik", d, b)
    return np.einsum("eq,eqji,eqjk->eik", scale, b, db)


def mass(modelisation: str, coords, kind: CellKind, density) -> np.ndarray:
    values, grads, weights = tabulated(kind.reference, kind.mass)
    det = jacobian_determinants(coords, grads)
    scale = det * weights[None, :] * np.asarray(density, dtype=float)[:, None]
    if modelisation == "AXIS":
        scale = scale * np.einsum("qa,ea->eq", values, coords[..., 0])
    scalar = np.einsum("eq,qa,qb->eab", scale, values, values)
    e, n, _ = scalar.shape
    return (scalar[:, :, None, :, None] * np.eye(2)[None, None, :, None, :]).reshape(
        e, 2 * n, 2 * n
    )


def material_values(materials, cells, mesh, modelisation: str, need_density: bool):
    return elastic_values(
        materials, cells, mesh, modelisation, need_density, viscoelastic=True, orthotropic=True
    )


def plane_blocks(
    model,
    characteristics,
    matrix,
    cells,
    materials=None,
    lumped=False,
    complex_stiffness=False,
    **_options,
) -> list[ElementBlock]:
    """Global-frame K, M or A matrices of the plane cells among ``cells``
    (one modelisation: element_blocks groups cells by modelisation);
    ``complex_stiffness``: K with the imaginary part of viscoelastic materials."""
    if matrix not in ("K", "M", "A"):
        raise ElementError(f"unknown element matrix {matrix!r}")
    mesh = model.mesh
    cells = np.asarray(cells, dtype=int)
    if not len(cells):
        return []
    modelisation = model.cell_modelisation[int(cells[0])]
    if lumped and matrix != "K":
        raise ElementError(
            f"{modelisation} elements have no diagonal mass (MASS_MECA_DIAG) in code_aster"
        )
    blocks = []
    for kind_name, members in cells_by_type(mesh, cells, modelisation).items():
        kind = surface_cells(modelisation)[kind_name]
        conn = np.array([mesh.cell_nodes[c] for c in members], dtype=int)
        coords = plane_coordinates(mesh, conn)
        props = material_values(materials, members, mesh, modelisation, matrix != "K")
        hooke = None
        if np.any(props["ORTHO"]):
            d3 = global_hooke(
                materials, characteristics, members, mesh, modelisation, props["E"], props["NU"]
            )
            hooke = plane_hooke(d3, modelisation)
        try:
            if matrix == "K":
                mats = stiffness(modelisation, coords, kind, props["E"], props["NU"], hooke)
                if np.iscomplexobj(mats) and not complex_stiffness:
                    mats = mats.real
            elif matrix == "M":
                mats = mass(modelisation, coords, kind, props["RHO"])
            else:
                alpha, beta = props["AMOR_ALPHA"], props["AMOR_BETA"]
                mats = np.zeros((len(members), 2 * conn.shape[1], 2 * conn.shape[1]))
                if np.any(alpha):
                    k = stiffness(modelisation, coords, kind, props["E"], props["NU"], hooke)
                    mats += alpha[:, None, None] * k.real
                if np.any(beta):
                    mats += beta[:, None, None] * mass(
                        modelisation, coords, kind, np.nan_to_num(props["RHO"])
                    )
        except ElementError as exc:
            raise ElementError(f"{modelisation} {kind_name} cells: {exc}") from None
        blocks.append(ElementBlock(nodes=conn, components=COMPONENTS, matrices=mats))
    return blocks
