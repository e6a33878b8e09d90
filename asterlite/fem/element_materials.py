"""The material parameters of a family's cells, read from the material field
(``CHAM_MATER``), with the refusals every continuum family shares: no field,
cells without a material, a parameter the element needs left undefined."""

from __future__ import annotations

import numpy as np

from asterlite.fem.element_errors import ElementError

#: ELAS parameters of the continuum families and their values when absent
#: (NaN: the element cannot do without it)
ELASTIC = (
    ("E", np.nan),
    ("NU", np.nan),
    ("RHO", np.nan),
    ("AMOR_ALPHA", 0.0),
    ("AMOR_BETA", 0.0),
)


def material_parameters(
    materials, cells, mesh, family: str, defaults, groups=None
) -> dict[str, np.ndarray]:
    """``{name: values on cells}`` for each ``(name, default)`` of ``defaults``
    (``groups``: the field's ``material_groups(cells)``, when known)."""
    if materials is None:
        raise ElementError(f"{family} elements need a material field (CHAM_MATER)")
    if groups is None:
        groups = materials.material_groups(cells)
    missing = [rows for material, rows in groups if material is None]
    if missing:
        names = ", ".join(mesh.cell_names[cells[k]] for k in missing[0][:5])
        raise ElementError(f"no material is assigned to the {family} cells {names}")
    return {
        name: materials.values(cells, name, default, groups=groups) for name, default in defaults
    }


def elastic_values(
    materials, cells, mesh, family: str, need_density: bool, viscoelastic=False, orthotropic=False
):
    """E, NU, RHO and the Rayleigh coefficients of isotropic elastic cells;
    RHO is required when a mass is computed (``need_density``).

    ``orthotropic``: the family takes ELAS_ORTH materials (3D and plane
    solids); their cells have NaN E and NU and are marked in ``out["ORTHO"]``
    (their Hooke matrix is :func:`asterlite.fem.orthotropic.global_hooke`'s).
    Other families refuse such a material by name.

    ``viscoelastic``: the family takes ELAS_VISCO materials (3D and plane
    solids, as code_aster's te0050/te0230); their cells get the complex
    E = 2 G (1 + NU) and NU, whose Hooke matrix has the complex Lamé
    coefficients 2 G NU / (1 - 2 NU) and G (E and NU become complex arrays).
    Other families refuse such a material by name."""
    # the cells grouped by material once: every test below is per material, not per cell
    groups = materials.material_groups(cells) if materials is not None else None
    out = material_parameters(materials, cells, mesh, family, ELASTIC, groups=groups)
    visco = [
        (rows, material.viscoelastic)
        for material, rows in groups
        if material.viscoelastic is not None
    ]
    if visco and not viscoelastic:
        first = np.sort(np.concatenate([rows for rows, _ in visco]))[:5]
        names = ", ".join(mesh.cell_names[cells[k]] for k in first)
        raise ElementError(
            f"{family} elements take no viscoelastic material (DEFI_MATERIAU ELAS_VISCO, "
            f"cells {names}): only 3D and plane solids (3D, D_PLAN, C_PLAN, AXIS) do"
        )
    if visco:
        out["E"] = out["E"].astype(complex)
        out["NU"] = out["NU"].astype(complex)
        for rows, values in visco:
            shear = np.full(len(rows), values["G"], dtype=complex)
            poisson = np.full(len(rows), values["NU"], dtype=complex)
            out["E"][rows] = 2.0 * shear * (1.0 + poisson)
            out["NU"][rows] = poisson
    ortho = np.zeros(len(cells), dtype=bool)
    for material, rows in groups:
        ortho[rows] = material.orthotropic is not None
    if np.any(ortho) and not orthotropic:
        names = ", ".join(mesh.cell_names[c] for c in np.asarray(cells)[ortho][:5])
        raise ElementError(
            f"{family} elements take no orthotropic material (DEFI_MATERIAU ELAS_ORTH, "
            f"cells {names}): only 3D and plane solids (3D, D_PLAN, C_PLAN, AXIS) do"
        )
    out["ORTHO"] = ortho
    isotropic = ~ortho
    if np.any(np.isnan(out["E"][isotropic])) or np.any(np.isnan(out["NU"][isotropic])):
        raise ElementError(f"the material of {family} elements needs E and NU (ELAS)")
    if need_density and np.any(np.isnan(out["RHO"])):
        raise ElementError(f"the mass of {family} elements needs RHO in the material (ELAS)")
    return out
