"""EXTR_MODE: keep some modes of one or more bases (FILTRE_MODE occurrences)."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.modes import ComplexModeResult, GeneralizedModes, ModeResult
from asterlite.fem.selection import as_tuple
from asterlite.modal.calc import filter_modes


def _indices(ctx, occ, modes: ModeResult) -> np.ndarray:
    n = modes.n_modes
    if occ.get("TOUT_ORDRE") == "OUI":
        return np.arange(n)
    if occ.get("NUME_ORDRE") is not None:
        order = np.asarray(as_tuple(occ["NUME_ORDRE"]), dtype=int)
        if np.any((order < 1) | (order > n)):
            ctx.error(f"NUME_ORDRE must be between 1 and {n}", "NUME_ORDRE", occ)
        return order - 1
    numbers = modes.mode_numbers
    if occ.get("NUME_MODE") is not None:
        wanted = as_tuple(occ["NUME_MODE"])
        missing = [m for m in wanted if m not in set(numbers.tolist())]
        if missing:
            ctx.error(f"no mode number {missing[0]} in the basis", "NUME_MODE", occ)
        return np.array([int(np.flatnonzero(numbers == m)[0]) for m in wanted], dtype=int)
    if occ.get("NUME_MODE_EXCLU") is not None:
        excluded = set(as_tuple(occ["NUME_MODE_EXCLU"]))
        return np.array([i for i in range(n) if numbers[i] not in excluded], dtype=int)
    if occ.get("FREQ_MIN") is not None or occ.get("FREQ_MAX") is not None:
        f = np.asarray(modes.frequencies)
        lo = float(occ.get("FREQ_MIN", -np.inf))
        hi = float(occ.get("FREQ_MAX", np.inf))
        prec = float(occ.get("PRECISION", 1e-3) or 0.0)
        return np.flatnonzero((f >= lo - prec * abs(lo)) & (f <= hi + prec * abs(hi)))
    if occ.get("CRIT_EXTR") is not None:
        return filter_modes(modes, occ["CRIT_EXTR"], float(occ.get("SEUIL", 1e-3)))
    return np.arange(n)


def run(ctx, kw):
    parts = []
    for occ in kw.factor("FILTRE_MODE"):
        modes = occ["MODE"]
        idx = _indices(ctx, occ, modes)
        if occ.get("CRIT_EXTR") is not None and occ.get("NUME_MODE") is not None:
            keep = set(filter_modes(modes, occ["CRIT_EXTR"], float(occ.get("SEUIL", 1e-3))))
            idx = np.array([i for i in idx if i in keep], dtype=int)
        parts.append(modes.select(idx))
    if not parts:
        ctx.error("FILTRE_MODE is required", "FILTRE_MODE", kw)
    numbering = parts[0].numbering
    if any(p.numbering is not numbering for p in parts[1:]):
        ctx.error("the bases use different DOF numberings", "FILTRE_MODE", kw)
    if len(parts) == 1:
        result = parts[0]
    elif all(isinstance(p, GeneralizedModes) for p in parts):
        result = GeneralizedModes.concatenate(parts)
    else:
        keys = set.intersection(*(set(p.parameters) for p in parts))
        extra = {}
        cls = ModeResult
        if all(isinstance(p, ComplexModeResult) for p in parts):
            cls = ComplexModeResult
            extra = {
                "eigenvalues": np.concatenate([p.eigenvalues for p in parts]),
                "damping": parts[0].damping,
            }
        result = cls(
            numbering=numbering,
            shapes=np.hstack([p.shapes for p in parts]),
            frequencies=np.concatenate([p.frequencies for p in parts]),
            generalized_mass=np.concatenate([p.generalized_mass for p in parts]),
            generalized_stiffness=np.concatenate([p.generalized_stiffness for p in parts]),
            mass=parts[0].mass,
            stiffness=parts[0].stiffness,
            kind=parts[0].kind,
            parameters={
                k: np.concatenate([np.asarray(p.parameters[k]) for p in parts]) for k in keys
            },
            norm=parts[0].norm,
            mode_labels=[lab for p in parts for lab in p.mode_labels],
            **extra,
        )
    if result.n_modes == 0:
        ctx.error("no mode is left after filtering", "FILTRE_MODE", kw)
    ctx.log(f"EXTR_MODE: {result.n_modes} modes kept")
    return result
