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


def elastic_values(materials, cells, mesh, family: str, need_density: bool):
    """E, NU, RHO and the Rayleigh coefficients of isotropic elastic cells;
    RHO is required when a mass is computed (``need_density``)."""
    out = material_parameters(materials, cells, mesh, family, ELASTIC)
    if np.any(np.isnan(out["E"])) or np.any(np.isnan(out["NU"])):
        raise ElementError(f"the material of {family} elements needs E and NU (ELAS)")
    if need_density and np.any(np.isnan(out["RHO"])):
        raise ElementError(f"the mass of {family} elements needs RHO in the material (ELAS)")
    return out
