"""Element computer of the multifibre Euler-Bernoulli beam ``POU_D_EM``
for :func:`asterlite.fem.elements.element_blocks` (matrices in
:mod:`asterlite.fem.fibres`).

Each cell needs its fibre groups (AFFE_CARA_ELEM/MULTIFIBRE), a POUTRE
section for the torsion constant JX, and a multifibre behaviour
(AFFE_MATERIAU/AFFE_COMPOR) giving each group's material and the section
material (MATER_SECT: G = E / 2(1 + NU) for torsion, AMOR_ALPHA and
AMOR_BETA of the Rayleigh damping C = α K + β M, as code_aster's te0121).
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import ElementBlock
from asterlite.fem import beam
from asterlite.fem.beam_elements import cell_angles
from asterlite.fem.element_errors import ElementError
from asterlite.fem.fibres import FibreError, mass_local, section_integrals, stiffness_local

MULTIFIBRE_MODELISATIONS = ("POU_D_EM",)


def _parameter(material, name: str, cell_name: str, required: bool = True) -> float:
    value = material.get(name)
    if value is None:
        if required:
            raise ElementError(
                f"POU_D_EM cell {cell_name}: material {material.name or '?'} has no {name} (ELAS)"
            )
        return 0.0
    return float(value)


def _cell_section(model, characteristics, materials, cell: int):
    """(E-weighted integrals, ρ-weighted integrals, G JX, α, β, materials)."""
    name = model.mesh.cell_names[cell]
    groups = characteristics.fibre_groups.get(cell) if characteristics is not None else None
    if groups is None:
        raise ElementError(f"POU_D_EM cell {name} has no fibres (AFFE_CARA_ELEM/MULTIFIBRE)")
    section = characteristics.sections.get(cell)
    if section is None or "JX" not in section:
        raise ElementError(f"POU_D_EM cell {name} has no POUTRE section giving JX (torsion)")
    behaviour = materials.cell_behaviour.get(cell) if materials is not None else None
    if behaviour is None:
        raise ElementError(
            f"POU_D_EM cell {name} has no multifibre behaviour (AFFE_MATERIAU/AFFE_COMPOR)"
        )
    given = materials.cell_materials.get(cell, ())
    geometry = characteristics.geom_fibre
    young_sum = np.zeros(6)
    rho_sum = np.zeros(6)
    for group in groups:
        material = behaviour.group_material.get(group)
        if material is None:
            raise ElementError(
                f"POU_D_EM cell {name}: the multifibre behaviour gives no material to "
                f"fibre group {group!r}"
            )
        if not any(material is m for m in given):
            raise ElementError(
                f"POU_D_EM cell {name}: the material of fibre group {group!r} is not among "
                "the materials AFFE_MATERIAU/AFFE gives the cell"
            )
        fibres = geometry.groups[group]
        integrals = section_integrals(fibres.y, fibres.z, fibres.area)
        young_sum += _parameter(material, "E", name) * integrals
        rho_sum += _parameter(material, "RHO", name, required=False) * integrals
    sect = behaviour.section_material
    shear = beam.shear_modulus(_parameter(sect, "E", name), _parameter(sect, "NU", name, False))
    alpha = _parameter(sect, "AMOR_ALPHA", name, False)
    beta = _parameter(sect, "AMOR_BETA", name, False)
    return young_sum, rho_sum, float(shear) * float(section["JX"]), alpha, beta


def local_matrix(
    model, characteristics, materials, cell: int, length: float, matrix: str, lumped=False
):
    """12x12 local matrix K, M (MASS_MECA_DIAG with ``lumped``) or A of one
    POU_D_EM cell of length ``length``."""
    name = model.mesh.cell_names[cell]
    young_sum, rho_sum, gj, alpha, beta = _cell_section(model, characteristics, materials, cell)
    try:
        stiffness = stiffness_local(length, young_sum, gj) if matrix != "M" else None
        if matrix != "K":
            if not np.any(rho_sum) and matrix == "M":
                raise ElementError(
                    f"the mass of POU_D_EM cell {name} needs RHO in its fibre materials (ELAS)"
                )
            centre_z = young_sum[2] / young_sum[0]
            centre_y = -young_sum[1] / young_sum[0]
            mass = mass_local(length, rho_sum, centre_z, centre_y, lumped=lumped)
    except FibreError as exc:
        raise ElementError(f"POU_D_EM cell {name}: {exc}") from None
    if matrix == "K":
        return stiffness
    if matrix == "M":
        return mass
    return alpha * stiffness + beta * mass


def multifibre_blocks(
    model, characteristics, matrix, cells, materials=None, lumped=False, **_options
) -> list[ElementBlock]:
    """Global-frame matrices (K, M or A) of POU_D_EM cells."""
    if matrix not in ("K", "M", "A"):
        raise ElementError(f"unknown element matrix {matrix!r}")
    mesh = model.mesh
    cells = np.asarray(cells, dtype=int)
    if not len(cells):
        return []
    conn = np.array([mesh.cell_nodes[c] for c in cells], dtype=int).reshape(-1, 2)
    lengths = beam.segment_lengths(mesh.coords[conn[:, 0]], mesh.coords[conn[:, 1]])
    local = np.zeros((len(cells), 12, 12))
    for k, cell in enumerate(cells):
        local[k] = local_matrix(
            model, characteristics, materials, int(cell), lengths[k], matrix, lumped
        )
    angles = cell_angles(model, characteristics, cells)
    out = beam.to_global(local, beam.rotation_from_angles(angles), 6)
    return [ElementBlock(nodes=conn, components=beam.BEAM_COMPONENTS, matrices=out)]
