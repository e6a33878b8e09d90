"""SIEF_ELGA of multifibre beams (POU_D_EM, linear elastic fibres): the
axial stress SIXX of every fibre at the element's two Gauss points, as
code_aster's te0537 computes it.

The fibre strain is ε = ε_axis - y κ_z + z κ_y with the cubic (Hermite)
bending curvatures and the axial strain of the linear mode plus the
incompatible quadratic mode, whose amplitude code_aster takes from its
STRX_ELGA field (a closed form, non-zero only when a first moment ∫E y or
∫E z of the section is positive: that is its rule and asterlite keeps it);
σ = E ε with E of the fibre's group.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import ElementField
from asterlite.fem import beam
from asterlite.fem.beam import cell_angles
from asterlite.fem.element_errors import ElementError
from asterlite.fem.fibres import section_integrals

#: positions (0..1 along the element) of code_aster's two Gauss points (FPG2)
GAUSS_POSITIONS = (0.5 - 0.5 / np.sqrt(3.0), 0.5 + 0.5 / np.sqrt(3.0))
_TINY_MOMENT = np.finfo(float).eps  # code_aster's r8prem


def _cell_fibres(characteristics, materials, cell: int, name: str):
    """(y, z, E) of a cell's fibres in element order, and its E-integrals."""
    behaviour = materials.cell_behaviour.get(cell) if materials is not None else None
    groups = characteristics.fibre_groups.get(cell) if characteristics is not None else None
    if behaviour is None or groups is None:
        raise ElementError(f"POU_D_EM cell {name} needs MULTIFIBRE fibres and AFFE_COMPOR")
    geometry = characteristics.geom_fibre
    y, z, young, integrals = [], [], [], np.zeros(6)
    for group in groups:
        fibres = geometry.groups[group]
        e = float(behaviour.group_material[group].get("E"))
        y.append(fibres.y)
        z.append(fibres.z)
        young.append(np.full(len(fibres.y), e))
        integrals += e * section_integrals(fibres.y, fibres.z, fibres.area)
    return np.concatenate(y), np.concatenate(z), np.concatenate(young), integrals


def _incompatible_amplitude(ul: np.ndarray, length: float, integrals) -> np.ndarray:
    """(n_orders,) amplitude of the incompatible axial mode (STRX_ELGA's)."""
    if not (integrals[1] >= _TINY_MOMENT or integrals[2] >= _TINY_MOMENT):
        return np.zeros(ul.shape[0], dtype=ul.dtype)
    coa, cob = 3.0 / (2.0 * length), 3.0 / 4.0
    ey, ez = integrals[1] / integrals[0], integrals[2] / integrals[0]
    return (
        coa * ey * ul[:, 1] - coa * ez * ul[:, 2] + cob * ez * ul[:, 4] + cob * ey * ul[:, 5]
        - coa * ey * ul[:, 7] + coa * ez * ul[:, 8] + cob * ez * ul[:, 10] + cob * ey * ul[:, 11]
    )  # fmt: skip


def multifibre_stresses(
    model, characteristics, materials, numbering, cells, values
) -> ElementField:
    """SIEF_ELGA (component SIXX) of POU_D_EM cells for nodal values
    (n_orders, n_dofs), real or complex (the stresses are linear in them)."""
    mesh = model.mesh
    cells = np.asarray(cells, dtype=int)
    values = np.asarray(values)
    conn = np.array([mesh.cell_nodes[c] for c in cells], dtype=int).reshape(-1, 2)
    rotations = beam.element_rotation(
        beam.rotation_from_angles(cell_angles(model, characteristics, cells)), 6
    )
    per_cell = [_cell_fibres(characteristics, materials, int(c), mesh.cell_names[c]) for c in cells]
    width = max(len(f[0]) for f in per_cell)
    out = np.full(
        (values.shape[0], len(cells), 2 * width, 1),
        np.nan,
        dtype=np.result_type(values, float),
    )
    for k, (y, z, young, integrals) in enumerate(per_cell):
        rows = np.concatenate(
            [numbering.dof_indices([node] * 6, beam.BEAM_COMPONENTS) for node in conn[k]]
        )
        element = np.zeros((values.shape[0], 12), dtype=out.dtype)
        present = rows >= 0
        element[:, present] = values[:, rows[present]]
        ul = element @ rotations[k].T
        length = float(np.linalg.norm(mesh.coords[conn[k, 1]] - mesh.coords[conn[k, 0]]))
        alpha = _incompatible_amplitude(ul, length, integrals)
        for point, xi in enumerate(GAUSS_POSITIONS):
            b1 = 1.0 / length
            b2 = (-6.0 + 12.0 * xi) / length**2
            b3 = (-4.0 + 6.0 * xi) / length
            b4 = (-2.0 + 6.0 * xi) / length
            g = (1.0 - 2.0 * xi) * 4.0 / length
            axial = (ul[:, 6] - ul[:, 0]) * b1 + g * alpha
            curv_y = b4 * ul[:, 10] + b3 * ul[:, 4] + b2 * (ul[:, 8] - ul[:, 2])
            curv_z = b4 * ul[:, 11] + b3 * ul[:, 5] + b2 * (ul[:, 1] - ul[:, 7])
            strain = axial[:, None] - np.outer(curv_z, y) + np.outer(curv_y, z)
            start = point * width
            out[:, k, start : start + len(y), 0] = strain * young[None, :]
    return ElementField("SIEF_ELGA", cells, ("SIXX",), out, sub_points=width)
