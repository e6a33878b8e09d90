"""Element matrices of 3D solid elements (``MODELISATION='3D'``), vectorised.

Cells of one type are computed together: reference shape-function
gradients at the Gauss points of the family code_aster uses
(:mod:`asterlite.fem.solid_reference`), Jacobians of every cell at every
point in one einsum, then

- stiffness ``K = sum_g w_g |J| B^T D B`` on the ``RIGI`` family, D the
  isotropic elasticity of the cell's material (E, NU) or its orthotropic one
  (ELAS_ORTH, in the frame of AFFE_CARA_ELEM MASSIF:
  :mod:`asterlite.fem.orthotropic`); a viscoelastic
  material (ELAS_VISCO) has a complex D: RIGI_MECA takes its real part,
  RIGI_MECA_HYST (``complex_stiffness``) the whole, as code_aster's te0050;
- mass ``M = sum_g w_g |J| rho N N^T`` (one block per direction) on the
  ``MASS`` family; ``MASS_MECA_DIAG`` scales its diagonal so that the element
  mass is kept (code_aster's diagonal lumping);
- damping ``C = AMOR_ALPHA K + AMOR_BETA M`` (Rayleigh, per element).

Face cells (TRIA3 ... QUAD9) and edges carried by the 3D modelisation only
take loads (:mod:`asterlite.fem.solid_loads`): they add no matrix.
"""

from __future__ import annotations

from collections import defaultdict

import numpy as np

from asterlite.concepts.assembly import ElementBlock
from asterlite.concepts.element_block import computed_block
from asterlite.fem.element_errors import ElementError
from asterlite.fem.element_materials import elastic_values
from asterlite.fem.orthotropic import global_hooke
from asterlite.fem.solid_reference import VOLUME_CELLS, tabulated

COMPONENTS = ("DX", "DY", "DZ")
SOLID_MODELISATIONS = ("3D",)


def cells_by_type(mesh, cells) -> dict[str, np.ndarray]:
    """Volume cells grouped by cell type (faces and edges left out)."""
    grouped: dict[str, list[int]] = defaultdict(list)
    for cell in np.asarray(cells, dtype=int):
        kind = mesh.cell_types[cell]
        if kind in VOLUME_CELLS:
            grouped[kind].append(int(cell))
    return {k: np.array(v, dtype=int) for k, v in grouped.items()}


def connectivity(mesh, cells) -> np.ndarray:
    return np.array([mesh.cell_nodes[c] for c in cells], dtype=int)


def _jacobian_matrices(coords: np.ndarray, gradients: np.ndarray, mesh=None, cells=None):
    """J (e, q, 3, 3) and det J (e, q); a degenerate cell is refused by name."""
    # J[e, q] = coords[e]^T grads[q]: dx_i / dxi_j, as batched matrix products
    jac = np.matmul(coords[:, None, :, :].transpose(0, 1, 3, 2), gradients[None, :, :, :])
    det = np.linalg.det(jac)
    if np.any(np.abs(det) <= 1e-300):
        bad = int(np.nonzero(np.any(np.abs(det) <= 1e-300, axis=1))[0][0])
        name = mesh.cell_names[cells[bad]] if mesh is not None else str(bad)
        raise ElementError(f"cell {name} is degenerate: zero Jacobian at a Gauss point")
    return jac, det


def jacobians(coords: np.ndarray, gradients: np.ndarray, mesh=None, cells=None):
    """Physical gradients (e, q, n, 3) and |J| (e, q) of cells with node
    coordinates ``coords`` (e, n, 3), reference gradients (q, n, 3)."""
    jac, det = _jacobian_matrices(coords, gradients, mesh, cells)
    inverse = np.linalg.inv(jac)  # dxi_j / dx_i
    physical = np.matmul(gradients[None, :, :, :], inverse)
    return physical, np.abs(det)


def jacobian_determinants(coords: np.ndarray, gradients: np.ndarray, mesh=None, cells=None):
    """|J| (e, q) alone, as :func:`jacobians` gives it, without inverting J
    (masses and loads need no physical gradients)."""
    return np.abs(_jacobian_matrices(coords, gradients, mesh, cells)[1])


def _check_material(materials, cells, mesh, need_density: bool) -> dict[str, np.ndarray]:
    return elastic_values(
        materials, cells, mesh, "3D", need_density, viscoelastic=True, orthotropic=True
    )


def strain_operators(g: np.ndarray) -> np.ndarray:
    """(e, q, 6, 3n) B of physical gradients ``g`` (e, q, n, 3): Voigt strains
    (xx, yy, zz, xy, xz, yz), engineering shears, DOFs node by node."""
    e, q, n, _ = g.shape
    b = np.zeros((e, q, 6, n, 3), dtype=g.dtype)
    for row, (i, j) in enumerate(((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))):
        b[:, :, row, :, i] = g[..., j]
        if i != j:
            b[:, :, row, :, j] = g[..., i]
    return b.reshape(e, q, 6, 3 * n)


def hooke_stiffness(coords, reference: str, family: str, hooke, mesh=None, cells=None):
    """(e, 3n, 3n) stiffness ``sum_g w |J| B^T D B`` for any Hooke matrices
    ``hooke`` (e, 6, 6) (anisotropic materials)."""
    _, grads, weights = tabulated(reference, family)
    g, det = jacobians(coords, grads, mesh, cells)
    b = strain_operators(g)
    db = np.einsum("eij,eqjk->eqik", hooke, b)
    return np.einsum("eq,eqji,eqjk->eik", det * weights[None, :], b, db)


def stiffness_matrices(
    coords, reference: str, family: str, young, poisson, mesh=None, cells=None
) -> np.ndarray:
    """(e, 3n, 3n) isotropic elastic stiffness, DOFs node by node (DX DY DZ);
    complex when ``young`` and ``poisson`` are (a viscoelastic material);
    ``mesh`` and ``cells`` name a degenerate cell in the error."""
    _, grads, weights = tabulated(reference, family)
    g, det = jacobians(coords, grads, mesh, cells)
    young = np.asarray(young)
    poisson = np.asarray(poisson)
    lam = young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson))
    mu = young / (2.0 * (1.0 + poisson))
    e, q, n, _ = g.shape
    # S[a i, b j] = sum_g w |J| dNa/dxi dNb/dxj: one batched matrix product
    flat = g.reshape(e, q, 3 * n)
    weighted = flat * (weights[None, :] * det)[:, :, None]
    s = np.matmul(weighted.transpose(0, 2, 1), flat).reshape(e, n, 3, n, 3)
    # sum_k S[a k, b k] = sum_g w |J| grad Na . grad Nb
    by_node = g.transpose(0, 2, 1, 3).reshape(e, n, 3 * q)
    scale = np.repeat(weights[None, :] * det, 3, axis=1)[:, None, :]
    dots = mu[:, None, None] * np.matmul(by_node * scale, by_node.transpose(0, 2, 1))
    # K[a i, b j] = lam S[a i, b j] + mu S[a j, b i] + mu delta_ij sum_k S[a k, b k],
    # direction pair by direction pair: (e, n, n) slices instead of a strided
    # transpose of the whole (e, n, 3, n, 3) array (half the time on 3D meshes),
    # with the same operations in the same order (the same bits)
    lam, mu = lam[:, None, None], mu[:, None, None]
    k = np.empty((e, n, 3, n, 3), dtype=np.result_type(s, lam, mu))
    for i in range(3):
        for j in range(3):
            block = lam * s[:, :, i, :, j]
            block += mu * s[:, :, j, :, i]
            if i == j:
                block += dots
            k[:, :, i, :, j] = block
    return k.reshape(e, 3 * n, 3 * n)


def scalar_mass(coords, reference: str, family: str, density, mesh=None, cells=None):
    """(e, n, n) ``int rho N_a N_b`` on the family."""
    values, grads, weights = tabulated(reference, family)
    det = jacobian_determinants(coords, grads, mesh, cells)
    wd = det * weights[None, :] * np.asarray(density, dtype=float)[:, None]
    n = values.shape[1]
    products = (values[:, :, None] * values[:, None, :]).reshape(len(weights), n * n)
    return (wd @ products).reshape(len(wd), n, n)


def expand_scalar(scalar: np.ndarray) -> np.ndarray:
    """(e, n, n) scalar matrices -> (e, 3n, 3n), the same on each direction."""
    e, n, _ = scalar.shape
    out = scalar[:, :, None, :, None] * np.eye(3)[None, None, :, None, :]
    return out.reshape(e, 3 * n, 3 * n)


def lump(scalar: np.ndarray) -> np.ndarray:
    """Diagonal scaled by total mass / trace (code_aster's MASS_MECA_DIAG)."""
    diag = np.einsum("eaa->ea", scalar)
    factor = scalar.sum(axis=(1, 2)) / diag.sum(axis=1)
    out = np.zeros_like(scalar)
    idx = np.arange(scalar.shape[1])
    out[:, idx, idx] = diag * factor[:, None]
    return out


def solid_blocks(
    model,
    characteristics,
    matrix,
    cells,
    materials=None,
    lumped=False,
    complex_stiffness=False,
    **_options,
) -> list[ElementBlock]:
    """Global-frame K, M or A matrices of the 3D volume cells among ``cells``;
    ``complex_stiffness``: K with the imaginary part of viscoelastic materials."""
    if matrix not in ("K", "M", "A"):
        raise ElementError(f"unknown element matrix {matrix!r}")
    mesh = model.mesh
    blocks = []
    for kind, members in cells_by_type(mesh, cells).items():
        spec = VOLUME_CELLS[kind]
        conn = connectivity(mesh, members)
        coords = mesh.coords[conn]
        props = _check_material(materials, members, mesh, need_density=matrix != "K")
        if np.any(props["ORTHO"]):
            props["HOOKE"] = global_hooke(
                materials, characteristics, members, mesh, "3D", props["E"], props["NU"]
            )

        def compute(start, stop, spec=spec, coords=coords, props=props, members=members):
            part = {name: values[start:stop] for name, values in props.items()}
            where = (mesh, members[start:stop])
            mats = _matrices(matrix, spec, coords[start:stop], part, lumped, where)
            if np.iscomplexobj(mats) and not complex_stiffness:
                mats = np.ascontiguousarray(mats.real)  # not a view holding the complex ones
            return mats

        try:
            # a few hundred cells at a time: the temporaries of B^T D B (complex
            # for viscoelastic materials) stay small, and symmetric matrices
            # are kept as upper triangles as they come
            blocks.append(computed_block(conn, COMPONENTS, compute))
        except ElementError as exc:
            raise ElementError(f"{kind} cells: {exc}") from None
    return blocks


def _matrices(matrix, spec, coords, props, lumped, where) -> np.ndarray:
    def stiffness():
        if "HOOKE" in props:
            return hooke_stiffness(coords, spec.reference, spec.rigi, props["HOOKE"], *where)
        young, poisson = props["E"], props["NU"]
        return stiffness_matrices(coords, spec.reference, spec.rigi, young, poisson, *where)

    def mass():
        density = np.nan_to_num(props["RHO"])
        scalar = scalar_mass(coords, spec.reference, spec.mass, density, *where)
        return expand_scalar(lump(scalar) if lumped else scalar)

    if matrix == "K":
        return stiffness()
    if matrix == "M":
        return mass()
    alpha, beta = props["AMOR_ALPHA"], props["AMOR_BETA"]
    n = coords.shape[1] * 3
    out = np.zeros((len(coords), n, n))
    if np.any(alpha):
        out += alpha[:, None, None] * stiffness().real
    if np.any(beta):
        out += beta[:, None, None] * mass()
    return out
