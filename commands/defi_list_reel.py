"""DEFI_LIST_REEL: VALE (taken as given), or DEBUT + INTERVALLE(JUSQU_A with PAS or NOMBRE)."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.lists import ListReal
from asterlite.post.restitution import values_of


def run(ctx, kw):
    if kw.get("VALE") is not None:
        # any order: a VALE list also holds modal dampings (AMOR_REDUIT lists
        # repeat a value); the commands that need increasing instants check them
        return ListReal(values_of(kw["VALE"]))
    return ListReal(build_intervals(ctx, kw, float(kw["DEBUT"]), kw.factor("INTERVALLE"), float))


def build_intervals(ctx, kw, start, intervals, kind):
    """Points from DEBUT through each JUSQU_A by PAS or NOMBRE steps."""
    points = [start]
    for occ in intervals:
        end = kind(occ["JUSQU_A"])
        here = points[-1]
        if end <= here:
            ctx.error(f"JUSQU_A={end} does not exceed the previous bound {here}", "JUSQU_A", occ)
        if occ.get("NOMBRE") is not None:
            count = int(occ["NOMBRE"])
            if count < 1:
                ctx.error("NOMBRE must be at least 1", "NOMBRE", occ)
            step = (end - here) / count
        else:
            step = kind(occ["PAS"])
            if step <= 0:
                ctx.error("PAS must be positive", "PAS", occ)
            ratio = (end - here) / step
            count = int(round(ratio))
            # code_aster accepts a step that divides the interval up to round-off
            if abs(ratio - count) > 1e-3 * max(1.0, abs(ratio)) or count < 1:
                ctx.error(
                    f"PAS={step:g} does not divide [{here:g}, {end:g}] into whole steps",
                    "PAS",
                    occ,
                )
        new = here + step * np.arange(1, count + 1)
        new[-1] = end  # land exactly on JUSQU_A
        points.extend(kind(v) for v in new)
    return np.asarray(points)
