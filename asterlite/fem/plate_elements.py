"""Discrete Kirchhoff plates (``MODELISATION='DKT'``): DKT triangles (TRIA3)
and DKQ quadrangles (QUAD4), with code_aster's formulation so that matrices
agree with its MEDKTR3 / MEDKQU4 elements.

Each cell has a local frame (code_aster's): x along node 1 -> 2 and z normal
to the triangle; for a quadrangle x joins the middles of sides 4-1 and 2-3
and z is normal to x and to the line joining the middles of sides 1-2 and
3-4. Local DOFs per node are DX DY DZ DRX DRY DRZ.

- Membrane (DX, DY): the linear triangle (one point), the bilinear
  quadrangle (2x2 points), ``D_m = E h / (1 - nu^2) [...]``.
- Bending (DZ and the rotations ``beta_x = DRY``, ``beta_y = -DRX``, with
  ``beta = -grad w`` on a thin plate): rotations interpolated quadratically
  (six-node triangle, eight-node serendipity quadrangle) whose mid-side values
  follow from the discrete Kirchhoff conditions (the tangential rotation
  equals the slope of the cubic deflection of the side at its middle, the
  normal rotation varies linearly), curvatures ``(beta_x,x, beta_y,y,
  beta_x,y + beta_y,x)`` on the RIGI family (3 points, 2x2 points),
  ``D_f = E h^3 / (12 (1 - nu^2)) [...]``.
- DRZ, which the plate does not resist, gets ``COEF_RIGI_DRZ`` times the
  smallest rotational diagonal term of the bending matrix, on every node.
- Mass (``rho h``): membrane ``A/6, A/12`` (triangle) or ``A/9 [1, 1/2,
  1/4]`` (quadrangle) per direction; deflection interpolated by code_aster's
  incomplete cubic (nodal w and slopes) on the RIGI family; rotary inertia
  ``rho h^3/12`` of the rotations only with ``INER_ROTA='OUI'`` (code_aster
  leaves it out otherwise); the DRZ term as for the stiffness.
- Diagonal mass (``MASS_MECA_DIAG``): code_aster's lumping of the global
  consistent matrix's diagonal (translations scaled to the element mass).
- Damping: ``AMOR_ALPHA K + AMOR_BETA M`` per element.
- Gravity: the weight ``rho h g`` spread on the corners without moments.

Characteristics come from ``AFFE_CARA_ELEM/COQUE`` (``EPAIS``,
``COEF_RIGI_DRZ``, ``INER_ROTA``, ``EXCENTREMENT``: a mid-surface offset e
along the local z, which couples membrane and bending through ``e D_m`` and
adds ``e^2 D_m`` to the bending, ``rho h e`` and ``rho h e^2`` to the mass).
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import ElementBlock
from asterlite.fem.element_errors import ElementError
from asterlite.fem.element_materials import elastic_values
from asterlite.fem.solid_reference import REFERENCE_ELEMENTS, gauss_family

COMPONENTS = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")
PLATE_MODELISATIONS = ("DKT",)

#: cell type -> (corner reference, rotation reference, RIGI family)
_CELLS = {"TRIA3": ("TR3", "TR6", "FPG3"), "QUAD4": ("QU4", "QU8", "FPG4")}


# -- local frames --------------------------------------------------------------------


def local_frames(coords: np.ndarray) -> np.ndarray:
    """(e, 3, 3) rows e_x, e_y, e_z of the local frames of cells (e, n, 3)."""
    if coords.shape[1] == 3:
        x_axis = coords[:, 1] - coords[:, 0]
        normal = np.cross(x_axis, coords[:, 2] - coords[:, 0])
    else:
        x_axis = (coords[:, 2] + coords[:, 1] - coords[:, 0] - coords[:, 3]) / 2.0
        across = (coords[:, 3] + coords[:, 2] - coords[:, 1] - coords[:, 0]) / 2.0
        normal = np.cross(x_axis, across)
    x_axis = x_axis / np.linalg.norm(x_axis, axis=1)[:, None]
    normal = normal / np.linalg.norm(normal, axis=1)[:, None]
    y_axis = np.cross(normal, x_axis)
    y_axis = y_axis / np.linalg.norm(y_axis, axis=1)[:, None]
    return np.stack([x_axis, y_axis, normal], axis=1)


# -- interpolations ------------------------------------------------------------------


def _sides(n: int):
    return [(k, (k + 1) % n) for k in range(n)]


def rotation_functions(xy: np.ndarray, rotation_ref: str, points: np.ndarray):
    """Values (e, q, 2, 3n) and reference derivatives (e, q, 2, 3n, 2) of
    (beta_x, beta_y) in terms of the bending DOFs (w, beta_x, beta_y) of the
    n corners, for cells with local corner coordinates xy (e, n, 2)."""
    e, n, _ = xy.shape
    quadratic = REFERENCE_ELEMENTS[rotation_ref]
    values = quadratic.values(points).real  # (q, 2n): corners then mid-sides
    grads = quadratic.gradients(points)  # (q, 2n, 2)
    # nodal rotations (2n nodes, 2 components) as a linear map of the 3n DOFs
    nodal = np.zeros((e, 2 * n, 2, 3 * n))
    for a in range(n):
        nodal[:, a, 0, 3 * a + 1] = 1.0
        nodal[:, a, 1, 3 * a + 2] = 1.0
    for k, (i, j) in enumerate(_sides(n)):
        d = xy[:, j] - xy[:, i]
        length = np.linalg.norm(d, axis=1)
        c, s = d[:, 0] / length, d[:, 1] / length
        # tangential / normal rotations of the side's ends
        tangential = np.zeros((e, 3 * n))
        normal = np.zeros((e, 3 * n))
        tangential[:, 3 * i] = 1.5 / length
        tangential[:, 3 * j] = -1.5 / length
        for end in (i, j):
            tangential[:, 3 * end + 1] -= 0.25 * c
            tangential[:, 3 * end + 2] -= 0.25 * s
            normal[:, 3 * end + 1] -= 0.5 * s
            normal[:, 3 * end + 2] += 0.5 * c
        nodal[:, n + k, 0] = c[:, None] * tangential - s[:, None] * normal
        nodal[:, n + k, 1] = s[:, None] * tangential + c[:, None] * normal
    at_points = np.einsum("qm,emcd->eqcd", values, nodal)
    derivatives = np.einsum("qmr,emcd->eqcdr", grads, nodal)
    return at_points, derivatives


def _geometry(xy: np.ndarray, corner_ref: str, points: np.ndarray):
    """Inverse Jacobians (e, q, 2, 2) and |J| (e, q) of the corner map."""
    grads = REFERENCE_ELEMENTS[corner_ref].gradients(points)  # (q, n, 2)
    jac = np.einsum("ena,qnb->eqab", xy, grads)  # dx_a / dxi_b
    det = np.linalg.det(jac)
    if np.any(det <= 0.0):
        raise ElementError("a plate cell is degenerate or folded (Jacobian <= 0)")
    return np.linalg.inv(jac), det


def deflection_functions(xy: np.ndarray, points: np.ndarray) -> np.ndarray:
    """(e, q, 3n) code_aster's deflection interpolation for the plate mass:
    an incomplete cubic of the nodal w and slopes (beta = -grad w)."""
    e, n, _ = xy.shape
    xi, eta = points[:, 0], points[:, 1]
    if n == 3:
        lam = 1.0 - xi - eta
        bubble = xi * eta * lam
        base = np.stack(
            [
                lam * lam * (3.0 - 2.0 * lam) + 2.0 * bubble,
                lam * lam * xi + bubble / 2.0,
                lam * lam * eta + bubble / 2.0,
                xi * xi * (3.0 - 2.0 * xi) + 2.0 * bubble,
                xi * xi * (xi - 1.0) - bubble,
                xi * xi * eta + bubble / 2.0,
                eta * eta * (3.0 - 2.0 * eta) + 2.0 * bubble,
                eta * eta * xi + bubble / 2.0,
                eta * eta * (eta - 1.0) - bubble,
            ],
            axis=1,
        )
        # the map is affine: every corner's slopes go with dx/dxi = x2 - x1
        # and dx/deta = x3 - x1 (sides 1-2 and 3-1)
        d = xy[:, [1, 2, 0]] - xy[:, [0, 1, 2]]  # sides 1-2, 2-3, 3-1
        # slope terms of each corner: (function index, side, sign) pairs
        terms = {a: ((3 * a + 1, 0, -1.0), (3 * a + 2, 2, 1.0)) for a in range(3)}
        scale = 1.0
    else:
        pq, mq, pe, me = 1.0 + xi, 1.0 - xi, 1.0 + eta, 1.0 - eta
        cq, ce = 1.0 - xi * xi, 1.0 - eta * eta
        base = (
            np.stack(
                [
                    mq * me * (cq + ce - xi - eta),
                    mq * me * cq,
                    mq * me * ce,
                    pq * me * (cq + ce + xi - eta),
                    -pq * me * cq,
                    pq * me * ce,
                    pq * pe * (cq + ce + xi + eta),
                    -pq * pe * cq,
                    -pq * pe * ce,
                    mq * pe * (cq + ce - xi + eta),
                    mq * pe * cq,
                    -mq * pe * ce,
                ],
                axis=1,
            )
            / 8.0
        )
        d = xy[:, [1, 2, 3, 0]] - xy[:, [0, 1, 2, 3]]  # sides 1-2, 2-3, 3-4, 4-1
        terms = {0: ((1, 0, -1.0), (2, 3, 1.0)), 1: ((4, 0, -1.0), (5, 1, -1.0)),
                 2: ((7, 2, 1.0), (8, 1, -1.0)), 3: ((10, 2, 1.0), (11, 3, 1.0))}  # fmt: skip
        scale = 0.5
    out = np.zeros((e, len(points), 3 * n))
    for a in range(n):
        out[:, :, 3 * a] = base[None, :, 3 * a]
        for function, side, sign in terms[a]:
            for comp in (0, 1):  # the x and y slopes: DOFs beta_x, beta_y
                out[:, :, 3 * a + 1 + comp] += (
                    scale * sign * d[:, side, comp][:, None] * base[None, :, function]
                )
    return out


# -- matrices ------------------------------------------------------------------------


def _membrane_operator(inverse: np.ndarray, corner_ref: str, points) -> np.ndarray:
    """(e, q, 3, 2n) membrane strains (xx, yy, 2xy) of the corner DOFs (u, v)."""
    grads = REFERENCE_ELEMENTS[corner_ref].gradients(points)
    g = np.einsum("qnb,eqba->eqna", grads, inverse)  # dN/dx_a
    e, q, n, _ = g.shape
    b = np.zeros((e, q, 3, 2 * n))
    b[:, :, 0, 0::2] = g[..., 0]
    b[:, :, 1, 1::2] = g[..., 1]
    b[:, :, 2, 0::2] = g[..., 1]
    b[:, :, 2, 1::2] = g[..., 0]
    return b


def _plane_stress(young, poisson, factor) -> np.ndarray:
    c = young * factor / (1.0 - poisson**2)
    d = np.zeros((len(c), 3, 3))
    d[:, 0, 0] = d[:, 1, 1] = c
    d[:, 0, 1] = d[:, 1, 0] = c * poisson
    d[:, 2, 2] = c * (1.0 - poisson) / 2.0
    return d


def local_parts(xy, kind, young, poisson, thickness, offset=None):
    """Membrane (e, 2n, 2n), bending (e, 3n, 3n) and membrane-bending
    coupling (e, 2n, 3n) local stiffnesses. With an ``offset`` e of the
    mid-surface from the mesh surface, the mid-surface strain is
    ``eps + e kappa``: coupling ``e D_m`` and bending ``D_f + e^2 D_m``."""
    corner_ref, rotation_ref, family = _CELLS[kind]
    points, weights = gauss_family(corner_ref, family)
    inverse, det = _geometry(xy, corner_ref, points)
    scale = det * weights[None, :]
    if kind == "TRIA3":  # constant strain: code_aster integrates it once
        centre = np.array([[1.0 / 3.0, 1.0 / 3.0]])
        inverse_m, det_m = _geometry(xy, corner_ref, centre)
        bm = _membrane_operator(inverse_m, corner_ref, centre)
        scale_m = det_m * 0.5
    else:
        bm = _membrane_operator(inverse, corner_ref, points)
        scale_m = scale
    dm = _plane_stress(young, poisson, thickness)
    membrane = np.einsum("eq,eqji,ejk,eqkl->eil", scale_m, bm, dm, bm)
    _, derivatives = rotation_functions(xy, rotation_ref, points)
    # d beta_c / dx_a = sum_r d beta_c / d xi_r  (dxi_r / dx_a)
    grad = np.einsum("eqcdr,eqra->eqcda", derivatives, inverse)
    twist = grad[:, :, 0, :, 1] + grad[:, :, 1, :, 0]
    bf = np.stack([grad[:, :, 0, :, 0], grad[:, :, 1, :, 1], twist], axis=2)
    df = _plane_stress(young, poisson, thickness**3 / 12.0)
    offset = np.zeros(len(xy)) if offset is None else np.asarray(offset, dtype=float)
    df = df + (offset**2)[:, None, None] * dm
    bending = np.einsum("eq,eqji,ejk,eqkl->eil", scale, bf, df, bf)
    coupling = np.zeros((len(xy), bm.shape[-1], bf.shape[-1]))
    if np.any(offset):
        dmf = offset[:, None, None] * dm
        if kind == "TRIA3":  # the constant membrane strains on the bending points
            bm = np.broadcast_to(bm, (len(xy), len(weights)) + bm.shape[2:])
        coupling = np.einsum("eq,eqji,ejk,eqkl->eil", scale, bm, dmf, bf)
    return membrane, bending, coupling


def local_masses(xy, kind, density, thickness, rotary: np.ndarray, offset=None):
    """Membrane (e, 2n, 2n), bending (e, 3n, 3n) and coupling (e, 2n, 3n)
    local masses; an offset e adds ``rho h e^2`` to the rotary inertia and
    couples the membrane displacements (linear functions) to the rotations
    through ``rho h e``."""
    corner_ref, rotation_ref, family = _CELLS[kind]
    n = xy.shape[1]
    surface = density * thickness
    points, weights = gauss_family(corner_ref, family)
    _, det = _geometry(xy, corner_ref, points)
    if n == 3:
        area = det[:, 0] / 2.0
        pattern = (np.ones((3, 3)) + np.eye(3)) / 12.0
    else:
        d = xy[:, 2] - xy[:, 0]
        f = xy[:, 3] - xy[:, 1]
        area = (d[:, 0] * f[:, 1] - d[:, 1] * f[:, 0]) / 2.0
        distance = np.array([[0, 1, 2, 1], [1, 0, 1, 2], [2, 1, 0, 1], [1, 2, 1, 0]])
        pattern = np.array([1.0, 0.5, 0.25])[distance] / 9.0
    scalar = (surface * area)[:, None, None] * pattern[None]
    membrane = np.einsum("eab,cd->eacbd", scalar, np.eye(2)).reshape(len(xy), 2 * n, 2 * n)
    scale = det * weights[None, :]
    w = deflection_functions(xy, points)
    bending = np.einsum("eq,eqi,eqj->eij", scale * surface[:, None], w, w)
    offset = np.zeros(len(xy)) if offset is None else np.asarray(offset, dtype=float)
    coupling = np.zeros((len(xy), 2 * n, 3 * n))
    if np.any(rotary) or np.any(offset):
        beta, _ = rotation_functions(xy, rotation_ref, points)
        inertia = density * thickness**3 / 12.0 * rotary + surface * offset**2
        bending += np.einsum("eq,eqci,eqcj->eij", scale * inertia[:, None], beta, beta)
        if np.any(offset):
            linear = REFERENCE_ELEMENTS[corner_ref].values(points).real  # (q, n)
            shape = np.einsum("qa,cd->qacd", linear, np.eye(2)).reshape(len(points), 2 * n, 2)
            weight = scale * (surface * offset)[:, None]
            coupling = np.einsum("eq,qic,eqcj->eij", weight, shape, beta)
    return membrane, bending, coupling


def assemble_local(membrane, bending, drz_factor, coupling=None) -> np.ndarray:
    """(e, 6n, 6n) local matrix: membrane on DX DY, bending DOFs (w, beta_x,
    beta_y) = (DZ, DRY, -DRX), DRZ = factor x the smallest rotational term."""
    e, nb, _ = bending.shape
    n = nb // 3
    p_m = np.zeros((2 * n, 6 * n))
    p_b = np.zeros((3 * n, 6 * n))
    for a in range(n):
        p_m[2 * a, 6 * a] = p_m[2 * a + 1, 6 * a + 1] = 1.0
        p_b[3 * a, 6 * a + 2] = 1.0
        p_b[3 * a + 1, 6 * a + 4] = 1.0
        p_b[3 * a + 2, 6 * a + 3] = -1.0
    out = np.einsum("ia,eij,jb->eab", p_m, membrane, p_m)
    out += np.einsum("ia,eij,jb->eab", p_b, bending, p_b)
    if coupling is not None and np.any(coupling):
        mixed = np.einsum("ia,eij,jb->eab", p_m, coupling, p_b)
        out += mixed + mixed.transpose(0, 2, 1)
    rotations = [3 * a + r for a in range(n) for r in (1, 2)]
    smallest = np.min(bending[:, rotations, rotations], axis=1)
    for a in range(n):
        out[:, 6 * a + 5, 6 * a + 5] = drz_factor * smallest
    return out


def to_global(local: np.ndarray, frames: np.ndarray) -> np.ndarray:
    """R^T A R with R the per-node rotation of translations and rotations."""
    e, size, _ = local.shape
    rot = np.zeros((e, size, size))
    for k in range(size // 3):
        rot[:, 3 * k : 3 * k + 3, 3 * k : 3 * k + 3] = frames
    return np.einsum("eji,ejk,ekl->eil", rot, local, rot)


# -- characteristics and blocks -------------------------------------------------------


def shell_values(characteristics, cells, mesh) -> dict[str, np.ndarray]:
    """EPAIS, COEF_RIGI_DRZ, INER_ROTA (1/0) and EXCENTREMENT of plate cells."""
    shells = characteristics.shells if characteristics is not None else {}
    missing = [int(c) for c in cells if int(c) not in shells]
    if missing:
        names = ", ".join(mesh.cell_names[c] for c in missing[:5])
        raise ElementError(f"DKT cells {names} have no thickness (AFFE_CARA_ELEM/COQUE)")
    return {
        key: np.array([float(shells[int(c)][key]) for c in cells])
        for key in ("EPAIS", "COEF_RIGI_DRZ", "INER_ROTA", "EXCENTREMENT")
    }


def _material(materials, cells, mesh, need_density):
    return elastic_values(materials, cells, mesh, "DKT", need_density)


def plate_matrices(matrix, coords, kind, props, shell) -> np.ndarray:
    """(e, 6n, 6n) global-frame K or M of plate cells with global corner
    coordinates (e, n, 3)."""
    frames = local_frames(coords)
    xy = np.einsum("eij,enj->eni", frames, coords)[..., :2]
    offset = shell["EXCENTREMENT"]
    if matrix == "K":
        parts = local_parts(xy, kind, props["E"], props["NU"], shell["EPAIS"], offset)
    else:
        density = np.nan_to_num(props["RHO"])
        parts = local_masses(xy, kind, density, shell["EPAIS"], shell["INER_ROTA"], offset)
    membrane, bending, coupling = parts
    local = assemble_local(membrane, bending, shell["COEF_RIGI_DRZ"], coupling)
    return to_global(local, frames)


def plate_blocks(
    model, characteristics, matrix, cells, materials=None, lumped=False, **_options
) -> list[ElementBlock]:
    """Global-frame K, M or A matrices of the DKT cells among ``cells``."""
    if matrix not in ("K", "M", "A"):
        raise ElementError(f"unknown element matrix {matrix!r}")
    mesh = model.mesh
    blocks = []
    for kind in _CELLS:
        members = np.array([int(c) for c in cells if mesh.cell_types[c] == kind], dtype=int)
        if not members.size:
            continue
        conn = np.array([mesh.cell_nodes[c] for c in members], dtype=int)
        coords = mesh.coords[conn]
        props = _material(materials, members, mesh, matrix != "K")
        shell = shell_values(characteristics, members, mesh)
        try:
            if matrix == "A":
                alpha, beta = props["AMOR_ALPHA"], props["AMOR_BETA"]
                mats = np.zeros((len(members), 6 * conn.shape[1], 6 * conn.shape[1]))
                if np.any(alpha):
                    mats += alpha[:, None, None] * plate_matrices("K", coords, kind, props, shell)
                if np.any(beta):
                    mats += beta[:, None, None] * plate_matrices("M", coords, kind, props, shell)
            elif matrix == "M" and lumped:
                consistent = plate_matrices("M", coords, kind, props, shell)
                mass = np.nan_to_num(props["RHO"]) * shell["EPAIS"] * plate_areas(coords)
                mats = lump_plate_mass(consistent, mass)
            else:
                mats = plate_matrices(matrix, coords, kind, props, shell)
        except ElementError as exc:
            raise ElementError(f"DKT {kind} cells: {exc}") from None
        blocks.append(ElementBlock(nodes=conn, components=COMPONENTS, matrices=mats))
    return blocks


def plate_areas(coords: np.ndarray) -> np.ndarray:
    """(e,) areas of plate cells in their local planes (projected)."""
    return nodal_area_weights(coords).sum(axis=1)


def lump_plate_mass(consistent: np.ndarray, mass: np.ndarray) -> np.ndarray:
    """code_aster's MASS_MECA_DIAG of plates (dialum): the diagonal of the
    global consistent matrix, the DX terms (and DRX's) scaled so that they
    sum to the element mass, likewise DY (DRY) and DZ (DRZ); a zero diagonal
    term becomes 1e-5 x the DX scale x the smallest non-zero term."""
    e, size, _ = consistent.shape
    diag = np.einsum("eii->ei", consistent).reshape(e, size // 6, 6)
    sums = diag[:, :, :3].sum(axis=1)  # (e, 3): DX, DY, DZ
    scale = mass[:, None] / sums
    lumped = diag * np.concatenate([scale, scale], axis=1)[:, None, :]
    flat_diag = diag.reshape(e, size)
    zero = flat_diag == 0.0
    smallest = np.where(zero, np.inf, flat_diag).min(axis=1)
    filler = 1e-5 * scale[:, 0] * np.minimum(smallest, flat_diag[:, 0])
    lumped = lumped.reshape(e, size)
    lumped[zero] = np.broadcast_to(filler[:, None], (e, size))[zero]
    out = np.zeros_like(consistent)
    idx = np.arange(size)
    out[:, idx, idx] = lumped
    return out


# -- loads ---------------------------------------------------------------------------


def nodal_area_weights(coords: np.ndarray) -> np.ndarray:
    """(e, n) share of a uniform surface load taken by each corner, as
    code_aster's dxtfor/dxqfor: A/3 on a triangle; on a quadrangle, half the
    sum over the four corner triangles (i-1, i, i+1) of a third of their
    (local, projected) area."""
    frames = local_frames(coords)
    xy = np.einsum("eij,enj->eni", frames, coords)[..., :2]
    n = xy.shape[1]
    if n == 3:
        d1, d2 = xy[:, 1] - xy[:, 0], xy[:, 2] - xy[:, 0]
        area = (d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / 2.0
        return np.repeat(area[:, None] / 3.0, 3, axis=1)
    corner = np.zeros((len(xy), 4))
    for k in range(4):
        after, before = xy[:, (k + 1) % 4] - xy[:, k], xy[:, k] - xy[:, (k - 1) % 4]
        corner[:, k] = (before[:, 0] * after[:, 1] - before[:, 1] * after[:, 0]) / 2.0
    weights = np.zeros_like(corner)
    for k in range(4):
        for t in (k - 1, k, k + 1):  # the corner triangles holding node k
            weights[:, k] += corner[:, t % 4] / 6.0
    return weights


def plate_gravity_terms(model, characteristics, materials, cells, acceleration) -> list:
    """Nodal forces of gravity ``acceleration`` (3,) on DKT cells: the weight
    rho h g spread on the corners (no moments), as code_aster's te0032."""
    mesh = model.mesh
    acceleration = np.asarray(acceleration, dtype=float)
    terms = []
    for kind in _CELLS:
        members = np.array(
            [
                int(c)
                for c in cells
                if mesh.cell_types[c] == kind and model.cell_modelisation.get(int(c)) == "DKT"
            ],
            dtype=int,
        )
        if not members.size:
            continue
        conn = np.array([mesh.cell_nodes[c] for c in members], dtype=int)
        props = _material(materials, members, mesh, need_density=True)
        shell = shell_values(characteristics, members, mesh)
        surface = props["RHO"] * shell["EPAIS"]
        weights = nodal_area_weights(mesh.coords[conn]) * surface[:, None]
        forces = weights[:, :, None] * acceleration[None, None, :]
        nodes = np.repeat(conn.ravel(), 3)
        comps = ["DX", "DY", "DZ"] * conn.size
        terms.extend(zip(nodes.tolist(), comps, forces.ravel().tolist(), strict=True))
    return terms
