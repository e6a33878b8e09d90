"""The time loop, written once: :func:`time_loop` around a scheme's ``step``.

Every loop of the engine that advances one step at a time runs this body
(a scheme's own loop and its general path, the loop with a varying
rotation speed)::

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

``step`` is a global of the loop, not an argument: numba caches a loop
whose callee is an argument under a key naming that dispatcher's identity
in the process, so such a loop would compile again in every process
(numba 0.68: saved, never loaded). :func:`scheme_loop` therefore makes, for
each ``step``, a function of this body whose global ``step`` is that step
and which numba takes for a function of the step's module (its file, a
name of its own): numba caches it there, checks it against that file as it
does the step, and the package's digest folder
(:func:`asterlite.dynamics.kernel_cache_folder`) covers this template. The
machine code is the one a loop written out in the scheme's module had.

Not this body: DIFF_CENTRE's and NEWMARK's ``fast_loop`` (the same loop with
the step's arithmetic written into it on plain arrays: measured faster, see
their modules), code_aster 10-12's ADAPT_ORDRE2 and the fluid film (steps
that archive between instants), the implicit shocks (a step integrated
again up to a contact switch).
"""

from __future__ import annotations

import functools
import sys
import types

from asterlite.dynamics import energy as E
from asterlite.dynamics import jit
from asterlite.dynamics import kernel as K
from asterlite.dynamics.forces import loads_ready
from asterlite.dynamics.jit import njit
from asterlite.dynamics.layouts import LOADS


@njit(cache=True, inline="always")
def before_step(clock, counters, model, archive):
    """The checks a loop makes before each step: 0 to go on, else the
    status to return (archive full, pause, next load window)."""
    paused = K.pause_status(counters, archive.times)
    if paused:
        return paused
    if not loads_ready(clock, model[LOADS]):
        return K.STATUS_LOADS
    return 0


@njit(cache=True, inline="always")
def after_step(
    clock, counters, state, model, instants, pas_arch, eps, archive, result, balance, energy
):
    """Advance the clock over an accepted step ``result`` = (dt_used,
    dt_next, rejected), archive when due, and, with ``balance`` (the energy balance:
    ``energy.is_active``, read once before the loop), add the step to the
    energy balance (:mod:`asterlite.dynamics.energy`)."""
    archived = counters[K.K_ARCHIVED]
    K.complete_step(clock, counters, state, instants, pas_arch, eps, archive, result)
    if balance:
        E.hook(energy, archived, counters, clock, result[0], state, model)


def time_loop(clock, counters, state, memory, model, instants, pas_arch, eps, archive, energy):
    """The loop from the clock's time to its end around ``step`` (a global
    :func:`scheme_loop` binds). ``energy``: the energy balance's bundle
    (:mod:`asterlite.dynamics.energy`), inactive without it. Returns a
    ``K.STATUS_*``: done, or why it paused or failed."""
    balance = E.is_active(energy)
    while K.unfinished(clock, counters, eps):
        paused = before_step(clock, counters, model, archive)
        if paused:
            return paused
        t, dt = K.plan_step(clock, counters, instants, eps)
        status, shock, dt_used, dt_next, rejected = step(  # noqa: F821 (bound by scheme_loop)
            t, dt, counters[K.K_STEP], state, memory, model
        )
        if status != K.STATUS_DONE:
            return K.record_failure(clock, counters, status, shock, dt_used)
        result = (dt_used, dt_next, rejected)
        after_step(
            clock, counters, state, model, instants, pas_arch, eps, archive, result, balance, energy
        )
    return K.STATUS_DONE


def scheme_loop(step):
    """:func:`compiled_scheme_loop` of ``step``'s numba dispatcher."""
    return compiled_scheme_loop(jit.compiled(step))


@functools.cache
def compiled_scheme_loop(step):
    """The compiled :func:`time_loop` around ``step`` (a compiled
    ``step(t, dt, index, state, memory, model) -> (status, shock, dt_used,
    dt_next, rejected)``), one per step function.

    Compiled with the step's reference counting: without (``_nrt=False``:
    the loop allocates nothing, what it hands the step costs nothing) when
    the step is compiled so, else with (numba compiles a callee under its
    caller's setting, and a step that may allocate needs it); the step is
    called, not inlined (numba's inliner copies a callee's IR at each
    site, and steps are large: one compiled copy serves every loop calling
    it). numba names it ``<step's module file>.time_loop_of_<step>`` in its
    cache."""
    source = step.py_func
    home = sys.modules[source.__module__]
    name = "time_loop_of_" + source.__qualname__.replace(".", "_")
    code = time_loop.__code__.replace(co_filename=home.__file__, co_name=name, co_qualname=name)
    scope = dict(time_loop.__globals__, step=step)
    function = types.FunctionType(code, scope, name)
    function.__module__, function.__qualname__ = source.__module__, name
    where = f"{source.__module__}.{source.__qualname__}"
    function.__doc__ = f"{time_loop.__doc__}\n\n    ``step``: {where}."
    if step.targetoptions.get("_nrt", True):
        return njit(cache=True)(function)
    return njit(cache=True, _nrt=False)(function)
