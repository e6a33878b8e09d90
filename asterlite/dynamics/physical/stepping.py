"""The fixed-step loop shared by NEWMARK, WILSON and DIFF_CENTRE: loads
evaluated exactly at every step instant, by blocks of instants (one
vectorised evaluation per block), archiving by a precomputed mask."""

from __future__ import annotations

import numpy as np

BLOCK = 512


def fixed_step_loop(system, times, q, v, a, mask, archive, step, monitor=None, modal=None) -> None:
    """``step(dt, F_{n+1}, q, v, a) -> (q, v, a)`` advanced over ``times``;
    ``monitor(t, F_{n+1}, q_n, v_n, q_{n+1}, v_{n+1})`` after each step
    (the energy balance) when given. ``modal`` (AMOR_MODAL, a
    ``ModalDamping``): the step receives F_{n+1} - f_am(v_n), explicit in
    the velocity at the start of the step as code_aster's dlnew0."""
    if mask[0]:
        archive.add(times[0], q, v, a)
    n_steps = times.size - 1
    for start in range(1, n_steps + 1, BLOCK):
        stop = min(start + BLOCK, n_steps + 1)
        forces = system.forces(times[start:stop])
        for k in range(start, stop):
            q_old, v_old = q, v
            force = forces[k - start]
            if modal is not None:
                force = force - modal.force(v, times[k])
            q, v, a = step(times[k] - times[k - 1], force, q, v, a)
            if monitor is not None:
                monitor(times[k], forces[k - start], q_old, v_old, q, v)
            if not np.all(np.isfinite(q)):
                raise FloatingPointError(f"the solution became non-finite at t={times[k]:.6g}")
            if mask[k]:
                archive.add(times[k], q, v, a)
