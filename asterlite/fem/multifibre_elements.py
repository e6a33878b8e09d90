"""Element computers of the multifibre beams ``POU_D_EM`` (Euler-Bernoulli)
and ``POU_D_TGM`` (Timoshenko with warping) for
:func:`asterlite.fem.elements.element_blocks` (POU_D_EM's matrices in
:mod:`asterlite.fem.fibres`).

Each cell needs its fibre groups (AFFE_CARA_ELEM/MULTIFIBRE), a POUTRE
section (JX for torsion; POU_D_TGM also takes AY, AZ, EY, EZ, JG there),
and a multifibre behaviour (AFFE_MATERIAU/AFFE_COMPOR) giving each group's
material and the section material (MATER_SECT: G = E / 2(1 + NU) for
torsion and shear, AMOR_ALPHA and AMOR_BETA of the Rayleigh damping
C = α K + β M, as code_aster's te0121).

POU_D_TGM, as code_aster's pmfk21 / pmfm21: POU_D_TG's matrices with the
axial and bending stiffnesses Σ E A, Σ E A z², Σ E A y² of the fibres (first
moments have no effect on this element), E JG with E = Σ E A / Σ A, the mass
from Σ ρ A and the fibres' geometric inertias. Its lumped mass is not
available (nor is POU_D_TG's).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.concepts.assembly import ElementBlock
from asterlite.fem import beam
from asterlite.fem.beam import cell_angles
from asterlite.fem.element_errors import ElementError
from asterlite.fem.fibres import FibreError, mass_local, section_integrals, stiffness_local

MULTIFIBRE_MODELISATIONS = ("POU_D_EM", "POU_D_TGM")
COMPONENTS = {"POU_D_EM": beam.BEAM_COMPONENTS, "POU_D_TGM": beam.BEAM_COMPONENTS + ("GRX",)}


@dataclass
class _Section:
    young: np.ndarray  # E-weighted fibre integrals
    density: np.ndarray  # ρ-weighted
    geometric: np.ndarray  # area-only
    shear: float  # G of the section material
    alpha: float
    beta: float
    poutre: dict  # the POUTRE section of the cell


def _parameter(material, name: str, where: str, required: bool = True) -> float:
    value = material.get(name)
    if value is None:
        if required:
            raise ElementError(f"{where}: material {material.name or '?'} has no {name} (ELAS)")
        return 0.0
    return float(value)


def cell_section(model, characteristics, materials, cell: int) -> _Section:
    kind = model.cell_modelisation[cell]
    where = f"{kind} cell {model.mesh.cell_names[cell]}"
    groups = characteristics.fibre_groups.get(cell) if characteristics is not None else None
    if groups is None:
        raise ElementError(f"{where} has no fibres (AFFE_CARA_ELEM/MULTIFIBRE)")
    section = characteristics.sections.get(cell)
    if section is None or "JX" not in section:
        raise ElementError(f"{where} has no POUTRE section giving JX (torsion)")
    behaviour = materials.cell_behaviour.get(cell) if materials is not None else None
    if behaviour is None:
        raise ElementError(f"{where} has no multifibre behaviour (AFFE_MATERIAU/AFFE_COMPOR)")
    given = materials.cell_materials.get(cell, ())
    geometry = characteristics.geom_fibre
    young_sum, rho_sum, area_sum = np.zeros(6), np.zeros(6), np.zeros(6)
    for group in groups:
        material = behaviour.group_material.get(group)
        if material is None:
            raise ElementError(
                f"{where}: the multifibre behaviour gives no material to fibre group {group!r}"
            )
        if not any(material is m for m in given):
            raise ElementError(
                f"{where}: the material of fibre group {group!r} is not among the materials "
                "AFFE_MATERIAU/AFFE gives the cell"
            )
        fibres = geometry.groups[group]
        integrals = section_integrals(fibres.y, fibres.z, fibres.area)
        young_sum += _parameter(material, "E", where) * integrals
        rho_sum += _parameter(material, "RHO", where, required=False) * integrals
        area_sum += integrals
    sect = behaviour.section_material
    shear = beam.shear_modulus(_parameter(sect, "E", where), _parameter(sect, "NU", where, False))
    return _Section(
        young=young_sum,
        density=rho_sum,
        geometric=area_sum,
        shear=float(shear),
        alpha=_parameter(sect, "AMOR_ALPHA", where, False),
        beta=_parameter(sect, "AMOR_BETA", where, False),
        poutre=section,
    )


def _euler_local(s: _Section, length: float, matrix: str, lumped: bool, where: str):
    gj = s.shear * float(s.poutre["JX"])
    stiffness = stiffness_local(length, s.young, gj) if matrix != "M" else None
    if matrix == "K":
        return stiffness
    if not np.any(s.density):
        raise ElementError(f"the mass of {where} needs RHO in its fibre materials (ELAS)")
    centre_z, centre_y = s.young[2] / s.young[0], -s.young[1] / s.young[0]
    mass = mass_local(length, s.density, centre_z, centre_y, lumped=lumped)
    return mass if matrix == "M" else s.alpha * stiffness + s.beta * mass


def _warping_local(s: _Section, length: float, matrix: str, lumped: bool, where: str):
    area = s.geometric[0]
    ay, az = float(s.poutre.get("AY", 0.0)), float(s.poutre.get("AZ", 0.0))
    if not (ay > 0.0 and az > 0.0):
        raise ElementError(f"{where} needs the shear coefficients AY and AZ (POUTRE)")
    if not s.young[0] > 0.0:
        raise ElementError(f"the fibres of {where} give no axial stiffness (Σ E A = 0)")
    young = s.young[0] / area
    offsets = dict(
        ay=ay, az=az, ey=-float(s.poutre.get("EY", 0.0)), ez=-float(s.poutre.get("EZ", 0.0))
    )
    stiffness = None
    if matrix != "M":
        stiffness = beam.warping_beam_stiffness_local(
            length, young, s.shear, area, s.young[4] / young, s.young[3] / young,
            float(s.poutre["JX"]), float(s.poutre.get("JG", 0.0)), **offsets,
        )[0]  # fmt: skip
    if matrix == "K":
        return stiffness
    if lumped:
        raise ElementError(f"MASS_MECA_DIAG of {where} is not available")
    if not np.any(s.density):
        raise ElementError(f"the mass of {where} needs RHO in its fibre materials (ELAS)")
    iy, iz = s.geometric[4], s.geometric[3]
    # the shear parameter takes the E-weighted inertias, the rotary inertia the geometric
    # ones: one modulus serves both only when E-weighting leaves their ratio unchanged
    modulus_y, modulus_z = s.young[4] / iy, s.young[3] / iz
    if not np.isclose(modulus_y, modulus_z, rtol=1e-12):
        raise ElementError(
            f"the mass of {where} with fibre groups of different E in the two bending planes"
        )
    mass = beam.warping_beam_mass_local(
        length, s.density[0] / area, modulus_y, s.shear, area, iy, iz, **offsets
    )[0]
    return mass if matrix == "M" else s.alpha * stiffness + s.beta * mass


def local_matrix(
    model, characteristics, materials, cell: int, length: float, matrix: str, lumped=False
):
    """Local matrix K, M (MASS_MECA_DIAG with ``lumped``) or A of one
    multifibre cell of length ``length``."""
    kind = model.cell_modelisation[cell]
    where = f"{kind} cell {model.mesh.cell_names[cell]}"
    section = cell_section(model, characteristics, materials, cell)
    compute = _euler_local if kind == "POU_D_EM" else _warping_local
    try:
        return compute(section, length, matrix, lumped, where)
    except (FibreError, beam.BeamError) as exc:
        raise ElementError(f"{where}: {exc}") from None


def multifibre_blocks(
    model, characteristics, matrix, cells, materials=None, lumped=False, **_options
) -> list[ElementBlock]:
    """Global-frame matrices (K, M or A) of POU_D_EM or POU_D_TGM cells (one modelisation)."""
    if matrix not in ("K", "M", "A"):
        raise ElementError(f"unknown element matrix {matrix!r}")
    mesh = model.mesh
    cells = np.asarray(cells, dtype=int)
    if not len(cells):
        return []
    components = COMPONENTS[model.cell_modelisation[int(cells[0])]]
    size = 2 * len(components)
    conn, lengths = beam.segment_cells(mesh, cells)
    local = np.zeros((len(cells), size, size))
    for k, cell in enumerate(cells):
        local[k] = local_matrix(
            model, characteristics, materials, int(cell), lengths[k], matrix, lumped
        )
    angles = cell_angles(model, characteristics, cells)
    out = beam.to_global(local, beam.rotation_from_angles(angles), len(components))
    return [ElementBlock(nodes=conn, components=components, matrices=out)]
