"""DEFI_LIST_REEL: VALE (taken as given), or DEBUT + INTERVALLE(JUSQU_A with PAS or NOMBRE)."""

from __future__ import annotations

import math

import numpy as np

from asterlite.concepts.lists import ListReal
from asterlite.post.restitution import values_of


def run(ctx, kw):
    if kw.get("VALE") is not None:
        # any order: a VALE list also holds modal dampings (AMOR_REDUIT lists
        # repeat a value); the commands that need increasing instants check them
        return ListReal(values_of(kw["VALE"]))
    return ListReal(build_intervals(ctx, kw, float(kw["DEBUT"]), kw.factor("INTERVALLE"), float))


# code_aster's tolerance on the number of PAS steps in an interval
_STEP_TOLERANCE = 1.0e-3


def _steps_then_remainder(ctx, here, end, step, count, occ) -> list[float]:
    """A PAS that does not divide its interval: code_aster takes the whole
    steps that stay within it (the last at DEBUT + n PAS, a product) and then
    one shorter step to JUSQU_A, with an alarm."""
    if here + count * step > end:
        count -= 1
    new = accumulate_steps(here, step, count)
    new[-1] = here + step * count
    ctx.log(
        f"alarm: DEFI_LIST_REEL: PAS={step:g} does not divide [{here:g}, {end:g}]: "
        f"{count} steps, then one of {end - new[-1]:g}"
    )
    return [float(v) for v in new] + [float(end)]


def build_intervals(ctx, kw, start, intervals, kind):
    """Points from DEBUT through each JUSQU_A by PAS or NOMBRE steps."""
    points = [start]
    for occ in intervals:
        end = kind(occ["JUSQU_A"])
        here = points[-1]
        if end <= here:
            ctx.error(f"JUSQU_A={end} does not exceed the previous bound {here}", "JUSQU_A", occ)
        if not np.isfinite(float(end) - float(here)):  # finite bounds, overflowing span
            ctx.error(f"[{here:g}, {end:g}] exceeds the floating-point range", "JUSQU_A", occ)
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
            if not np.isfinite(ratio):  # a subnormal PAS
                ctx.error(f"PAS={step:g} is too small for [{here:g}, {end:g}]", "PAS", occ)
            if ratio <= 1.0 - _STEP_TOLERANCE:
                ctx.error(f"PAS={step:g} is longer than [{here:g}, {end:g}]", "PAS", occ)
            count = math.floor(ratio + 0.5)  # Fortran's nint
            last_step = end - (here + (count - 1) * step)
            if abs((last_step - step) / step) > _STEP_TOLERANCE:
                points.extend(_steps_then_remainder(ctx, here, end, step, count, occ))
                continue
        new = accumulate_steps(here, step, count)
        new[-1] = end  # land exactly on JUSQU_A
        points.extend(kind(v) for v in new)
    return np.asarray(points)


def accumulate_steps(start, step, count):
    """start + step, + step, ... (count points) added one step at a time, as
    code_aster builds its lists: the round-off then grows along the interval
    (15.000000000007807 rather than 15.0 for 22500 steps of 0.02/30), and
    that decides on which side of a kink a sampled formula falls. Values
    within machine epsilon of zero are set to zero, as code_aster does."""
    steps = np.full(count + 1, float(step))
    steps[0] = start
    points = np.add.accumulate(steps)[1:]  # sequential, not pairwise
    points[np.abs(points) <= np.finfo(float).eps] = 0.0
    return points
