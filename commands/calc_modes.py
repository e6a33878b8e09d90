"""CALC_MODES: real eigenmodes of (K, M) under the numbering's kinematic relations."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import AssembledMatrix
from asterlite.fem.constraints import ConstraintError
from asterlite.fem.selection import as_tuple
from asterlite.modal.calc import (
    apply_norm,
    build_mode_result,
    constrained_pencil,
    filter_modes,
    residuals,
    select_modes,
)
from asterlite.modal.eigen import EigenError

_DEFAULT_NMAX = {"PLUS_PETITE": 10, "CENTRE": 10, "PLUS_GRANDE": 1, "TOUT": 10}


def run(ctx, kw):
    if kw.get("TYPE_RESU", "DYNAMIQUE") != "DYNAMIQUE":
        ctx.unsupported(f"CALC_MODES TYPE_RESU={kw['TYPE_RESU']!r}", "TYPE_RESU", kw)
    stiffness, mass = kw["MATR_RIGI"], kw["MATR_MASS"]
    if not isinstance(stiffness, AssembledMatrix) or not isinstance(mass, AssembledMatrix):
        ctx.unsupported("CALC_MODES on generalized matrices", "MATR_RIGI", kw)
    if kw.get("MATR_AMOR") is not None:
        ctx.unsupported("CALC_MODES with MATR_AMOR (complex modes)", "MATR_AMOR", kw)
    if mass.numbering is not stiffness.numbering:
        ctx.error("MATR_RIGI and MATR_MASS use different numberings", "MATR_MASS", kw)
    option = kw.get("OPTION", "PLUS_PETITE")
    calc_freq = (kw.factor("CALC_FREQ") or [{}])[0]
    freq = as_tuple(calc_freq.get("FREQ"))
    nmax = calc_freq.get("NMAX_FREQ")
    if not nmax:
        nmax = _DEFAULT_NMAX.get(option, 10)
    if option == "TOUT":
        nmax = None
    if option in ("CENTRE", "BANDE", "PROCHE", "AJUSTE", "SEPARE") and not freq:
        ctx.error(f"OPTION={option!r} needs CALC_FREQ/FREQ", "CALC_FREQ", kw)
    try:
        pencil = constrained_pencil(stiffness, mass)
        omega2, vecs = select_modes(pencil, option, freq, nmax or 10)
    except (EigenError, ConstraintError) as exc:
        ctx.error(str(exc), "OPTION", kw)
    if option == "BANDE" and calc_freq.get("NMAX_FREQ"):
        omega2, vecs = omega2[: calc_freq["NMAX_FREQ"]], vecs[:, : calc_freq["NMAX_FREQ"]]
    if omega2.size == 0:
        ctx.error("no eigenmode found for this selection", "CALC_FREQ", kw)
    res = residuals(pencil, omega2, vecs)
    modes = build_mode_result(stiffness, mass, omega2, pencil.expand(vecs))
    modes.parameters["ERREUR"] = res
    veri = (kw.factor("VERI_MODE") or [{}])[0]
    tolerance = float(veri.get("SEUIL", 1e-6) or 1e-6)
    # rigid-body modes (below SEUIL_FREQ) have K φ ≈ 0: their relative residual means nothing
    elastic = np.abs(modes.frequencies) >= float(calc_freq.get("SEUIL_FREQ", 1e-2) or 1e-2)
    checked = np.where(elastic, res, 0.0)
    if veri.get("STOP_ERREUR", "OUI") == "OUI" and np.any(checked > max(tolerance, 1e-6)):
        worst = int(np.argmax(checked))
        ctx.error(
            f"mode {worst + 1} ({modes.frequencies[worst]:.6g} Hz) has a residual "
            f"{res[worst]:.3g} above {tolerance:g}",
            "VERI_MODE",
            kw,
        )
    norm = kw.factor("NORM_MODE")
    if norm:
        apply_norm(modes, norm[0].get("NORME", "TRAN_ROTA"))
    filtre = kw.factor("FILTRE_MODE")
    if filtre:
        keep = filter_modes(
            modes, filtre[0].get("CRIT_EXTR", "MASS_EFFE_UN"), float(filtre[0].get("SEUIL", 1e-3))
        )
        modes = modes.select(keep)
        modes.parameters["NUME_MODE"] = np.arange(1, modes.n_modes + 1)
    for k, f in enumerate(modes.frequencies, start=1):
        ctx.log(f"mode {k:4d}  {f:14.6e} Hz  gen. mass {modes.generalized_mass[k - 1]:12.5e}")
    return modes
