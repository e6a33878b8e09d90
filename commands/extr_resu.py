"""EXTR_RESU: a transient result restricted to some archived states
(ARCHIVAGE: NUME_ORDRE / LIST_ORDRE / INST / LIST_INST / PAS_ARCH /
LIST_ARCH) and fields (NOM_CHAM / CHAM_EXCLU)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from asterlite.concepts.transient import DynaTrans, TranGene
from asterlite.errors import CommandError
from asterlite.post.restitution import FIELDS, as_tuple, nearest_archived, values_of


def run(ctx, kw):
    result = kw["RESULTAT"]
    if kw.factor("RESTREINT"):
        ctx.unsupported("EXTR_RESU/RESTREINT", "RESTREINT", kw)
    if not isinstance(result, DynaTrans | TranGene):
        ctx.unsupported(f"EXTR_RESU of a {result.aster_type}", "RESULTAT", kw)
    occurrences = kw.factor("ARCHIVAGE")
    occ = occurrences[0] if occurrences else {}
    try:
        kept = archived_indices(result, occ)
    except CommandError as exc:
        ctx.error(exc.message, "ARCHIVAGE", kw)
    fields = kept_fields(occ)
    if isinstance(result, DynaTrans):
        return DynaTrans(
            numbering=result.numbering,
            times=result.times[kept],
            order=result.order[kept],
            fields={k: v[kept] for k, v in result.fields.items() if k in fields},
        )
    out = replace(
        result,
        times=result.times[kept],
        order=result.order[kept],
        depl=_kept_or_zero(result.depl, kept, "DEPL" in fields),
        vite=_kept_or_zero(result.vite, kept, "VITE" in fields),
        acce=_kept_or_zero(result.acce, kept, "ACCE" in fields),
        shocks=[
            replace(s, fields={k: np.asarray(v)[kept] for k, v in s.fields.items()})
            for s in result.shocks
        ],
        info=dict(result.info, extracted_fields=sorted(fields)),
    )
    out.name = None
    return out


def _kept_or_zero(states, kept, keep: bool):
    return states[kept] if keep else np.zeros_like(states[kept])


def kept_fields(occ) -> set[str]:
    if occ.get("NOM_CHAM") is not None:
        return set(as_tuple(occ["NOM_CHAM"]))
    return set(FIELDS) - set(as_tuple(occ.get("CHAM_EXCLU")))


def archived_indices(result, occ) -> np.ndarray:
    times, order = np.asarray(result.times), np.asarray(result.order)
    if occ.get("PAS_ARCH") is not None:
        return np.arange(0, times.size, int(occ["PAS_ARCH"]))
    numbers = None
    if occ.get("NUME_ORDRE") is not None:
        numbers = as_tuple(occ["NUME_ORDRE"])
    elif occ.get("LIST_ORDRE") is not None:
        numbers = occ["LIST_ORDRE"].values
    elif occ.get("LIST_ARCH") is not None:
        numbers = occ["LIST_ARCH"].values
    if numbers is not None:
        lookup = {int(o): i for i, o in enumerate(order)}
        missing = [int(n) for n in numbers if int(n) not in lookup]
        if missing:
            raise CommandError(f"NUME_ORDRE {missing[0]} is not archived")
        return np.array([lookup[int(n)] for n in numbers], dtype=int)
    instants = None
    if occ.get("INST") is not None:
        instants = values_of(occ["INST"])
    elif occ.get("LIST_INST") is not None:
        instants = values_of(occ["LIST_INST"])
    if instants is not None:
        return nearest_archived(
            times, instants, float(occ.get("PRECISION", 1e-6)), occ.get("CRITERE", "RELATIF")
        )
    return np.arange(times.size)
