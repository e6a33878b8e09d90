"""DEFI_MATERIAU: material parameters (ELAS, ELAS_FO with constant functions,
ELAS_VISCO's complex G and NU, other behaviours kept as given)."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import Material

_FUNCTION_PARAMETERS = ("E", "NU", "RHO", "ALPHA", "AMOR_ALPHA", "AMOR_BETA", "AMOR_HYST")


def _constant_value(ctx, occ, name: str, func) -> float | None:
    """The value of a function that does not vary (ELAS_FO used with no
    temperature field): its ordinates must all be equal. None when it varies:
    the material is then kept, but has no value of ``name`` for the element
    computations (code_aster too needs a command variable field there)."""
    ordinates = getattr(func, "ordinates", None)
    if ordinates is None:
        if getattr(func, "NOM_PARA", None) is not None and callable(func):
            ctx.unsupported(f"ELAS_FO/{name} given by a formula", name, occ)
        ctx.error(f"{name} must be a function", name, occ)
    values = np.asarray(ordinates, dtype=float)
    if values.size == 0 or not np.allclose(values, values[0], rtol=1e-12, atol=0.0):
        ctx.log(
            f"ELAS_FO/{name} varies with {getattr(func, 'NOM_PARA', '?')}: no constant value "
            "for the element computations (asterlite applies no command variable field)"
        )
        return None
    return float(values[0])


def run(ctx, kw):
    base = kw.get("MATER")
    behaviours = {k: dict(v) for k, v in base.behaviours.items()} if base is not None else {}
    if ctx.reuse is not None and base is None:
        behaviours = {k: dict(v) for k, v in ctx.reuse.behaviours.items()}
    for occ in kw.factor("ELAS"):
        values = {k: v for k, v in occ.items() if v is not None}
        if "E" not in values:
            ctx.unsupported("ELAS without E (K/MU or CELE_P/CELE_S)", "E", occ)
        behaviours["ELAS"] = {k: float(v) for k, v in values.items()}
    for occ in kw.factor("ELAS_FO"):
        elas, varying = {}, {}
        for name, value in occ.items():
            if value is None:
                continue
            if name in _FUNCTION_PARAMETERS:
                constant = _constant_value(ctx, occ, name, value)
                if constant is not None:
                    elas[name] = constant
                else:
                    varying[name] = str(getattr(value, "NOM_PARA", "?"))
            elif isinstance(value, (int, float)):
                elas[name] = float(value)
        behaviours["ELAS"] = elas
        behaviours["ELAS_FO"] = dict(occ)
        # parameters without a constant value: refused where a computation needs them
        behaviours["ELAS_VARYING"] = varying
    for occ in kw.factor("ELAS_VISCO"):
        # complex moduli at one frequency: the 3D and plane elements build
        # RIGI_MECA from the real part of their Hooke matrix, RIGI_MECA_HYST
        # from the whole of it
        visco = {"G": complex(occ["G"]), "NU": complex(occ["NU"])}
        if occ.get("RHO") is not None:
            visco["RHO"] = float(occ["RHO"])
        behaviours["ELAS_VISCO"] = visco
        ctx.log("material ELAS_VISCO: " + ", ".join(f"{k}={v:g}" for k, v in visco.items()))
    for keyword in (
        *("ECRO_LINE", "ECRO_LINE_FO", "TRACTION", "THER", "THER_FO", "THER_NL"),
        *("Iwan", "Iwan_FO", "DIS_CONTACT"),
    ):
        for occ in kw.factor(keyword):
            behaviours[keyword] = dict(occ)
    for occ in kw.factor("FATIGUE"):
        behaviours["FATIGUE"] = dict(occ)
    elas = behaviours.get("ELAS", {})
    if elas:
        ctx.log(
            "material ELAS: "
            + ", ".join(
                f"{k}={elas[k]:g}"
                for k in ("E", "NU", "RHO", "AMOR_ALPHA", "AMOR_BETA")
                if k in elas
            )
        )
    return Material(behaviours=behaviours)
