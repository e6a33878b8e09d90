"""Generalised forces (``EFGE_ELNO``, ``EFGE_ELGA``) and stresses
(``SIEF_ELGA``, ``SIGM_ELNO``) of DKT plates, as code_aster's dktedg /
dkqedg, dktsie / dkqsie and te0451 compute them for an isotropic
linear-elastic plate without offset.

At each node of a cell (the NOEU family: the corners' reference
coordinates), from the local displacements:

- membrane forces ``N = D_m eps`` (NXX NYY NXY), ``eps`` constant on a
  triangle, at the node on a quadrangle;
- moments ``M = D_f kappa`` (MXX MYY MXY), ``kappa`` the curvatures of the
  discrete Kirchhoff rotations at the node;
- shear forces from the equilibrium of moments, ``QX = MXX,x + MXY,y`` and
  ``QY = MXY,x + MYY,y``: the second derivatives of the rotations taken with
  the Jacobian at the node (exact on triangles and parallelograms, the same
  approximation as code_aster's dkqtxy on other quadrangles).

Stresses: at the RIGI Gauss points, on 3 sub-points (bottom, middle, top)
of each of the COQUE_NCOU equal layers, sub-point index 3 (layer - 1) +
level; SIGM_ELNO takes each sub-point's Gauss values to the nodes; EFGE_ELGA
integrates SIEF_ELGA through the thickness (Simpson's rule on each layer).

Forces and stresses are given in the cells' output frame (code_aster's coqrep): x along
the projection on the cell's plane of the direction ``ANGL_REP`` (alpha,
beta) of AFFE_CARA_ELEM/COQUE, (0, 0) being the global X. Values are linear
in the displacements, so complex states (a dyna_harmo) give complex fields.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import ElementField
from asterlite.fem.element_errors import ElementError
from asterlite.fem.plate_elements import (
    _CELLS,
    _geometry,
    _material,
    _membrane_operator,
    _plane_stress,
    local_frames,
    rotation_functions,
    shell_values,
)
from asterlite.fem.solid_fields import gauss_to_nodes
from asterlite.fem.solid_reference import REFERENCE_ELEMENTS, gauss_family

PLATE_EFGE_COMPONENTS = ("NXX", "NYY", "NXY", "MXX", "MYY", "MXY", "QX", "QY")
SIGMA_COMPONENTS = ("SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ")
PLATE_FIELD_OPTIONS = ("EFGE_ELNO", "EFGE_ELGA", "SIEF_ELGA", "SIGM_ELNO")

#: step of the central differences of the rotations' reference gradients:
#: those gradients are polynomials of degree <= 2, so the difference is exact
_STEP = 0.25


def output_axes(frames: np.ndarray, angles: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(cos, sin) of the output x axis in each cell's local frame: the
    projection on the cell's plane of the direction of ANGL_REP (degrees)."""
    alpha, beta = np.radians(angles[:, 0]), np.radians(angles[:, 1])
    direction = np.stack(
        [np.cos(beta) * np.cos(alpha), np.cos(beta) * np.sin(alpha), -np.sin(beta)], axis=1
    )
    normal = frames[:, 2]
    projected = direction - np.sum(direction * normal, axis=1)[:, None] * normal
    length = np.linalg.norm(projected, axis=1)
    if np.any(length <= 1e-12):
        raise ElementError("ANGL_REP is normal to a plate cell: its output frame is undefined")
    c = np.einsum("ei,ei->e", projected, frames[:, 0])
    s = np.einsum("ei,ei->e", projected, frames[:, 1])
    norm = np.hypot(c, s)
    return c / norm, s / norm


def _rotation_hessians(xy, rotation_ref, points) -> np.ndarray:
    """(e, q, 2, 3n, 2, 2) second reference derivatives of the rotations."""
    columns = []
    for r in range(2):
        shift = np.zeros(2)
        shift[r] = _STEP
        _, ahead = rotation_functions(xy, rotation_ref, points + shift)
        _, behind = rotation_functions(xy, rotation_ref, points - shift)
        columns.append((ahead - behind) / (2.0 * _STEP))
    return np.stack(columns, axis=-1)


def _local_forces(xy, kind, young, poisson, thickness, u_membrane, u_bending, points):
    """(o, e, q, 8) forces in the cells' local frames at reference ``points``
    for local membrane DOFs (o, e, 2n) and bending DOFs (o, e, 3n)."""
    corner_ref, rotation_ref, _ = _CELLS[kind]
    inverse, _ = _geometry(xy, corner_ref, points)
    if kind == "TRIA3":  # constant membrane strain
        centre = np.array([[1.0 / 3.0, 1.0 / 3.0]])
        inverse_m, _ = _geometry(xy, corner_ref, centre)
        bm = np.broadcast_to(
            _membrane_operator(inverse_m, corner_ref, centre),
            (len(xy), len(points), 3, 2 * len(points)),
        )
    else:
        bm = _membrane_operator(inverse, corner_ref, points)
    dm = _plane_stress(young, poisson, thickness)
    df = _plane_stress(young, poisson, thickness**3 / 12.0)
    _, derivatives = rotation_functions(xy, rotation_ref, points)
    grad = np.einsum("eqcdr,eqra->eqcda", derivatives, inverse)
    bf = np.stack(
        [grad[:, :, 0, :, 0], grad[:, :, 1, :, 1], grad[:, :, 0, :, 1] + grad[:, :, 1, :, 0]],
        axis=2,
    )
    hess = np.einsum(
        "eqcdrs,eqra,eqsb->eqcdab", _rotation_hessians(xy, rotation_ref, points), inverse, inverse
    )
    # d kappa / d x_a (e, q, 3, 3n, 2)
    dkappa = np.stack(
        [
            hess[:, :, 0, :, 0, :],
            hess[:, :, 1, :, 1, :],
            hess[:, :, 0, :, 1, :] + hess[:, :, 1, :, 0, :],
        ],
        axis=2,
    )
    membrane = np.einsum("eij,eqjk,oek->oeqi", dm, bm, u_membrane)
    moments = np.einsum("eij,eqjk,oek->oeqi", df, bf, u_bending)
    dmoments = np.einsum("eij,eqjka,oek->oeqia", df, dkappa, u_bending)
    qx = dmoments[..., 0, 0] + dmoments[..., 2, 1]
    qy = dmoments[..., 2, 0] + dmoments[..., 1, 1]
    return np.concatenate([membrane, moments, qx[..., None], qy[..., None]], axis=-1)


def _to_output_frame(forces: np.ndarray, c: np.ndarray, s: np.ndarray) -> np.ndarray:
    """Rotate (o, e, n, 8) local forces into the output frame (x' = c x + s y)."""
    c, s = c[None, :, None], s[None, :, None]
    out = np.empty_like(forces)
    for base in (0, 3):  # the membrane and the moment tensors
        xx, yy, xy = forces[..., base], forces[..., base + 1], forces[..., base + 2]
        out[..., base] = c * c * xx + s * s * yy + 2.0 * c * s * xy
        out[..., base + 1] = s * s * xx + c * c * yy - 2.0 * c * s * xy
        out[..., base + 2] = -c * s * xx + c * s * yy + (c * c - s * s) * xy
    out[..., 6] = c * forces[..., 6] + s * forces[..., 7]
    out[..., 7] = -s * forces[..., 6] + c * forces[..., 7]
    return out


def plate_element_fields(
    model, characteristics, materials, numbering, cells, values: np.ndarray, options
) -> dict[str, ElementField]:
    """EFGE_ELNO of DKT cells for nodal values (n_orders, n_dofs), real or
    complex: (n_orders, n_cells, max nodes, 8), NaN beyond a cell's nodes."""
    other = [name for name in options if name not in PLATE_FIELD_OPTIONS]
    if other:
        raise ValueError(
            f"{other[0]} is not computed for DKT plates ({', '.join(PLATE_FIELD_OPTIONS)})"
        )
    mesh = model.mesh
    cells = np.asarray(cells, dtype=int)
    values = np.asarray(values)
    max_nodes = max(len(mesh.cell_nodes[int(c)]) for c in cells)
    dtype = np.result_type(values, float)
    out = np.full((values.shape[0], len(cells), max_nodes, 8), np.nan, dtype=dtype)
    shells_of = characteristics.shells if characteristics is not None else {}
    layers = max(int(shells_of.get(int(c), {}).get("COQUE_NCOU", 1)) for c in cells)
    levels = 3 * layers
    gauss = np.full((values.shape[0], len(cells), max_nodes * levels, 6), np.nan, dtype=dtype)
    nodal = np.full_like(gauss, np.nan)
    efge_gauss = np.full((values.shape[0], len(cells), max_nodes, 8), np.nan, dtype=dtype)
    for kind in _CELLS:
        rows = np.array([k for k, c in enumerate(cells) if mesh.cell_types[c] == kind], dtype=int)
        if not rows.size:
            continue
        members = cells[rows]
        shell = shell_values(characteristics, members, mesh)
        if np.any(shell["EXCENTREMENT"]):
            raise ElementError(
                "forces and stresses of DKT cells with EXCENTREMENT are not computed"
            )
        if any(shells_of[int(c)].get("VECTEUR") is not None for c in members):
            raise ElementError(
                "forces and stresses of DKT cells whose output frame is given by VECTEUR"
            )
        angles = np.array([shells_of[int(c)].get("ANGL_REP", (0.0, 0.0)) for c in members], float)
        props = _material(materials, members, mesh, False)
        conn = np.array([mesh.cell_nodes[c] for c in members], dtype=int)
        n = conn.shape[1]
        coords = mesh.coords[conn]
        frames = local_frames(coords)
        xy = np.einsum("eij,enj->eni", frames, coords)[..., :2]
        comps = ["DX", "DY", "DZ", "DRX", "DRY", "DRZ"]
        dofs = numbering.dof_indices(np.repeat(conn.ravel(), 6), comps * conn.size)
        gathered = np.zeros((values.shape[0], dofs.size), dtype=values.dtype)
        gathered[:, dofs >= 0] = values[:, dofs[dofs >= 0]]
        gathered = gathered.reshape(values.shape[0], len(members), n, 2, 3)
        # translations and rotations of each node in the cell's local frame
        local = np.einsum("eij,oenkj->oenki", frames, gathered)
        u_membrane = local[:, :, :, 0, :2].reshape(values.shape[0], len(members), 2 * n)
        bending = np.stack(
            [local[:, :, :, 0, 2], local[:, :, :, 1, 1], -local[:, :, :, 1, 0]], axis=-1
        )
        u_bending = bending.reshape(values.shape[0], len(members), 3 * n)
        corner_ref, _, family = _CELLS[kind]
        c, s = output_axes(frames, angles)
        args = (xy, kind, props["E"], props["NU"], shell["EPAIS"], u_membrane, u_bending)
        try:
            at_nodes = _local_forces(*args, REFERENCE_ELEMENTS[corner_ref].nodes)
            points = gauss_family(corner_ref, family)[0]
            at_points = _local_forces(*args, points) if set(options) - {"EFGE_ELNO"} else None
        except ElementError as exc:
            raise ElementError(f"DKT {kind} cells: {exc}") from None
        out[:, rows, :n, :] = _to_output_frame(at_nodes, c, s)
        if at_points is None:
            continue
        ncou = np.array([int(shells_of[int(m)].get("COQUE_NCOU", 1)) for m in members])
        if np.any(ncou != layers):
            raise ElementError("SIEF_ELGA of DKT cells with different COQUE_NCOU in one call")
        sigma = _layer_stresses(_to_output_frame(at_points, c, s), shell["EPAIS"], layers)
        q = len(points)
        gauss[:, rows, : q * levels, :] = sigma.reshape(values.shape[0], len(members), -1, 6)
        efge_gauss[:, rows, :q, :] = through_thickness_forces(sigma, shell["EPAIS"])
        # SIGM_ELNO: each sub-point's Gauss values taken to the nodes
        to_nodes = gauss_to_nodes(corner_ref, family)
        at_corner = np.einsum("nq,oeqlc->oenlc", to_nodes, sigma)
        nodal[:, rows, : n * levels, :] = at_corner.reshape(values.shape[0], len(members), -1, 6)
    fields = {}
    for name in options:
        if name == "EFGE_ELNO":
            fields[name] = ElementField(name, cells, PLATE_EFGE_COMPONENTS, out.copy())
        elif name == "EFGE_ELGA":
            fields[name] = ElementField(name, cells, PLATE_EFGE_COMPONENTS, efge_gauss.copy())
        elif name == "SIEF_ELGA":
            fields[name] = ElementField(name, cells, SIGMA_COMPONENTS, gauss.copy(), levels)
        else:
            fields[name] = ElementField(name, cells, SIGMA_COMPONENTS, nodal.copy(), levels)
    return fields


def through_thickness_forces(sigma: np.ndarray, thickness: np.ndarray) -> np.ndarray:
    """(o, e, q, 8) generalised forces from the layer stresses (o, e, q,
    3 layers, 6) at the bottom, middle and top of equal layers: Simpson's
    rule on each layer, N = sum of sigma dz, M = sum of z sigma dz, Q = sum of
    tau dz (code_aster's te0451 for EFGE_ELGA; exact for the linear and
    parabolic profiles of an isotropic plate)."""
    layers = sigma.shape[-2] // 3
    h = np.asarray(thickness, dtype=float)[None, :, None]
    step = h / layers
    weights = np.array([1.0, 4.0, 1.0]) / 6.0
    forces = np.zeros(sigma.shape[:3] + (8,), dtype=sigma.dtype)
    for k in range(layers):
        bottom = -h / 2.0 + k * step
        for level in range(3):
            stress = sigma[..., 3 * k + level, :]
            w = weights[level] * step
            z = bottom + 0.5 * level * step
            forces[..., 0:3] += w[..., None] * stress[..., [0, 1, 3]]
            forces[..., 3:6] += (w * z)[..., None] * stress[..., [0, 1, 3]]
            forces[..., 6:8] += w[..., None] * stress[..., [4, 5]]
    return forces


def _layer_stresses(forces: np.ndarray, thickness: np.ndarray, layers: int) -> np.ndarray:
    """(o, e, q, 3 layers, 6) stresses at the bottom, middle and top of each
    of ``layers`` equal layers from the generalised forces (o, e, q, 8) of
    an isotropic plate: sigma = N / h + 12 z M / h^3 in the plane, the
    parabolic 3 Q / (2 h) (1 - 4 z^2 / h^2) across it, SIZZ = 0 (code_aster's
    dktsie / dkqsie)."""
    h = thickness[None, :, None, None]
    z = (
        np.array([-0.5 + (k + 0.5 * level) / layers for k in range(layers) for level in range(3)])[
            None, None, None, :
        ]
        * h
    )
    membrane, moments = forces[..., None, 0:3], forces[..., None, 3:6]
    in_plane = membrane / h[..., None] + 12.0 * z[..., None] * moments / h[..., None] ** 3
    shear_profile = 1.5 / h * (1.0 - 4.0 * z * z / (h * h))
    shear = forces[..., None, 6:8] * shear_profile[..., None]
    zero = np.zeros_like(in_plane[..., :1])
    return np.concatenate([in_plane[..., :2], zero, in_plane[..., 2:3], shear], axis=-1)
