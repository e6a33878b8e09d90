"""The fixed-step loop shared by NEWMARK, WILSON and DIFF_CENTRE: loads
evaluated exactly at every step instant, by blocks of instants (one
vectorised evaluation per block, a block sized in bytes), archiving by a
precomputed mask.

Each block of loads is tested once (a load is non-finite from the first
instant where it is), every step tests the displacement (NaN propagates: a
non-finite velocity reaches it within the step or the next), every archived
state its velocity and acceleration too, so that no archived state is
non-finite. "Non-finite" is the GENE loops' test: NaN, inf, or a magnitude
of 1e300 or more (:data:`asterlite.dynamics.diagnosis.LIMIT`). The first
failure stops the run with :class:`NonFiniteState`, saying what is
non-finite and when."""

from __future__ import annotations

import numpy as np

from asterlite.dynamics import diagnosis as D
from asterlite.dynamics.diagnosis import LIMIT
from asterlite.dynamics.integrate import LOAD_ADVICE
from asterlite.errors import field as named

#: the loads of a block of instants take at most this many bytes (and as
#: much again for the temporaries that evaluate and test them), whatever
#: the number of unknowns; a block has at most MAX_BLOCK instants
BLOCK_BYTES = 4 * 2**20
MAX_BLOCK = 512


class NonFiniteState(FloatingPointError):
    """The state of a physical transient became non-finite; ``path``: the
    problem field at fault, a mark the command words (:func:`asterlite.errors.field`)."""

    def __init__(self, message: str, path: str = ""):
        super().__init__(message)
        self.path = path


def fixed_step_loop(system, times, q, v, a, mask, archive, step, monitor=None, modal=None) -> None:
    """``step(dt, F_{n+1}, q, v, a) -> (q, v, a)`` advanced over ``times``;
    ``monitor(t, F_{n+1}, q_n, v_n, q_{n+1}, v_{n+1})`` after each step
    (the energy balance) when given. ``modal`` (modal damping, a
    ``ModalDamping``): the step receives F_{n+1} - f_am(v_n), explicit in
    the velocity at the start of the step as code_aster's dlnew0."""
    if mask[0]:
        archive.add(times[0], q, v, a)
    n_steps = times.size - 1
    block = block_instants(system.n_free)
    for start in range(1, n_steps + 1, block):
        stop = min(start + block, n_steps + 1)
        forces = system.forces(times[start:stop])
        if system.imposed is not None:
            forces = forces + system.imposed_forces(start, stop)
        bad_load = first_bad_row(forces)
        for k in range(start, stop):
            if k - start == bad_load:  # the state at times[k - 1] is the last finite one
                raise non_finite_state(system, times[k], times[k - 1], k, q, v, a, archive)
            q_old, v_old = q, v
            force = forces[k - start]
            if modal is not None:
                force = force - modal.force(v, times[k])
            q, v, a = step(times[k] - times[k - 1], force, q, v, a)
            if monitor is not None:
                monitor(times[k], forces[k - start], q_old, v_old, q, v)
            if not finite(q) or (mask[k] and not (finite(v) and finite(a))):
                raise non_finite_state(system, times[k], times[k - 1], k, q, v, a, archive)
            if mask[k]:
                archive.add(times[k], q, v, a)


def block_instants(n_free: int) -> int:
    """Instants per block of loads: ``BLOCK_BYTES`` of (n_free,) rows."""
    return max(1, min(MAX_BLOCK, BLOCK_BYTES // (8 * max(n_free, 1))))


def finite(values) -> bool:
    return bool(np.all(np.abs(values) < LIMIT))


def first_bad_row(forces) -> int:
    """Index of the first row of ``forces`` that is not finite, or -1."""
    rows = ~np.all(np.abs(forces) < LIMIT, axis=1)
    return int(np.argmax(rows)) if rows.any() else -1


def non_finite_state(system, t, t_good, step, q, v, a, archive) -> NonFiniteState:
    """The error of a state found non-finite at ``t``: a load first (the
    state at ``t_good`` was finite), else the displacement, velocity and
    acceleration themselves (an unstable step)."""

    multipliers = []
    for load in system.loads:
        try:
            multipliers.append(float(load.coefficients([t])[0]))
        except Exception:  # a function refusing to be evaluated there: not finite
            multipliers.append(np.nan)
    vectors = [system.load_vector(load, t) for load in system.loads]
    labels = [f"{named('excitation')}[{e}]" for e in range(1, len(vectors) + 1)]
    culprit = D.first_bad_load(multipliers, vectors, labels, t)
    described = D.state_text(q, v, a, unit="free DOF", qualifier="")
    if culprit is None:
        step = named("grid.step")
        culprit = D.Culprit((described or "the state") + " diverged", step, True)
        advice = f"try a smaller {step}, and check the stiffness, damping and loads"
    else:
        if described:
            culprit.text += f", and then {described}"
        advice = LOAD_ADVICE
    last = archive.times[archive.count - 1] if archive.count else None
    when = D.when_text(t, t_good, step, last)
    return NonFiniteState(f"{when}: {culprit.text}; {advice}", culprit.path)
