"""What every time loop does around its scheme's step, written once.

Each scheme's ``run_loop`` (and the general paths) is the same loop around
a different compiled ``step``::

    while K.unfinished(clock, counters, eps):
        paused = before_step(clock, counters, model, archive)
        if paused:
            return paused
        t, dt = K.plan_step(clock, counters, instants, eps)
        status, shock, dt_used, dt_next, rejected = step(t, dt, ...)
        if status != K.STATUS_DONE:
            return K.record_failure(clock, counters, status, shock, dt_used)
        after_step(clock, counters, state, model, ..., (dt_used, dt_next, rejected), ...)
    return K.STATUS_DONE

numba caches a function only when the functions it calls are globals, not
arguments: the loop is therefore a few lines in each scheme's module,
calling its own ``step``, and these helpers, inlined (``inline="always"``:
the compiled loop is the one written out by hand), hold what they share.
The loops shared by every scheme (:mod:`asterlite.dynamics.rotation`,
:mod:`asterlite.dynamics.implicit_shocks`) call :func:`before_step` too,
around :func:`asterlite.dynamics.dispatch.scheme_step`.
"""

from __future__ import annotations

from numba import njit

from asterlite.dynamics import energy as E
from asterlite.dynamics import kernel as K
from asterlite.dynamics.forces import loads_ready


@njit(cache=True, inline="always")
def before_step(clock, counters, model, archive):
    """The checks a loop makes before each step: 0 to go on, else the
    status to return (archive full, pause, next load window)."""
    paused = K.pause_status(counters, archive[0])
    if paused:
        return paused
    if not loads_ready(clock, model[2]):
        return K.STATUS_LOADS
    return 0


@njit(cache=True, inline="always")
def after_step(
    clock, counters, state, model, instants, pas_arch, eps, archive, result, balance, energy
):
    """Advance the clock over an accepted step ``result`` = (dt_used,
    dt_next, rejected), archive when due, and, with ``balance`` (ENERGIE:
    ``energy.is_active``, read once before the loop), add the step to the
    energy balance (:mod:`asterlite.dynamics.energy`)."""
    archived = counters[K.K_ARCHIVED]
    K.complete_step(clock, counters, state, instants, pas_arch, eps, archive, result)
    if balance:
        E.hook(energy, archived, counters, clock, result[0], state, model)
