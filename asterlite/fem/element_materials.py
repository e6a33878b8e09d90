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


def material_parameters(materials, cells, mesh, family: str, defaults) -> dict[str, np.ndarray]:
    """``{name: values on cells}`` for each ``(name, default)`` of ``defaults``."""
    if materials is None:
        raise ElementError(f"{family} elements need a material field (CHAM_MATER)")
    missing = [int(c) for c in cells if materials.material_of(c) is None]
    if missing:
        names = ", ".join(mesh.cell_names[c] for c in missing[:5])
        raise ElementError(f"no material is assigned to the {family} cells {names}")
    return {name: materials.values(cells, name, default) for name, default in defaults}


def elastic_values(materials, cells, mesh, family: str, need_density: bool, viscoelastic=False):
    """E, NU, RHO and the Rayleigh coefficients of isotropic elastic cells;
    RHO is required when a mass is computed (``need_density``).

    ``viscoelastic``: the family takes ELAS_VISCO materials (3D and plane
    solids, as code_aster's te0050/te0230); their cells get the complex
    E = 2 G (1 + NU) and NU, whose Hooke matrix has the complex Lamé
    coefficients 2 G NU / (1 - 2 NU) and G (E and NU become complex arrays).
    Other families refuse such a material by name."""
    out = material_parameters(materials, cells, mesh, family, ELASTIC)
    visco = [
        (k, material.viscoelastic)
        for k, cell in enumerate(np.asarray(cells, dtype=int))
        if (material := materials.material_of(int(cell))).viscoelastic is not None
    ]
    if visco and not viscoelastic:
        names = ", ".join(mesh.cell_names[cells[k]] for k, _ in visco[:5])
        raise ElementError(
            f"{family} elements take no viscoelastic material (DEFI_MATERIAU ELAS_VISCO, "
            f"cells {names}): only 3D and plane solids (3D, D_PLAN, C_PLAN, AXIS) do"
        )
    if visco:
        rows = np.array([k for k, _ in visco], dtype=int)
        shear = np.array([values["G"] for _, values in visco], dtype=complex)
        poisson = np.array([values["NU"] for _, values in visco], dtype=complex)
        out["E"] = out["E"].astype(complex)
        out["NU"] = out["NU"].astype(complex)
        out["E"][rows] = 2.0 * shear * (1.0 + poisson)
        out["NU"][rows] = poisson
    if np.any(np.isnan(out["E"])) or np.any(np.isnan(out["NU"])):
        raise ElementError(f"the material of {family} elements needs E and NU (ELAS)")
    if need_density and np.any(np.isnan(out["RHO"])):
        raise ElementError(f"the mass of {family} elements needs RHO in the material (ELAS)")
    return out
