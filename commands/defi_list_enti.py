"""DEFI_LIST_ENTI: VALE, or DEBUT + INTERVALLE(JUSQU_A with PAS or NOMBRE).

OPERATION='NUME_ORDRE' (orders of a result within instant intervals) is
supported for physical transient results.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.lists import ListInt
from asterlite.post.restitution import as_tuple


def run(ctx, kw):
    operation = kw.get("OPERATION", "DEFI")
    if operation == "NUME_ORDRE":
        return _orders_in_intervals(ctx, kw)
    if kw.get("VALE") is not None:
        return ListInt(np.asarray(as_tuple(kw["VALE"]), dtype=int))
    points = [int(kw["DEBUT"])]
    for occ in kw.factor("INTERVALLE"):
        end, here = int(occ["JUSQU_A"]), points[-1]
        if end < here:
            ctx.error(f"JUSQU_A={end} is below the previous bound {here}", "JUSQU_A", occ)
        if occ.get("NOMBRE") is not None:
            count = max(int(occ["NOMBRE"]), 1)
            step = (end - here) // count
            if step * count != end - here:
                ctx.error("NOMBRE must divide the interval", "NOMBRE", occ)
        else:
            step = int(occ.get("PAS", 1))
            if step <= 0 or (end - here) % step:
                ctx.error(f"PAS={step} does not divide [{here}, {end}]", "PAS", occ)
        points.extend(range(here + step, end + 1, step))
    return ListInt(np.asarray(points, dtype=int))


def _orders_in_intervals(ctx, kw):
    result = kw["RESULTAT"]
    if kw.get("PARAMETRE", "INST") != "INST":
        ctx.unsupported(f"PARAMETRE={kw['PARAMETRE']!r}", "PARAMETRE", kw)
    times, order = np.asarray(result.times), np.asarray(result.order)
    keep = np.zeros(times.size, bool)
    for occ in kw.factor("INTERVALLE"):
        low, high = as_tuple(occ["VALE"])[:2]
        keep |= (times >= low) & (times <= high)
    return ListInt(order[keep])
