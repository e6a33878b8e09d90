"""DIFF_CENTRE: explicit central differences in code_aster's form
(v_{n+1} = v_n + dt a_n, q_{n+1} = q_n + dt v_{n+1}, then a_{n+1} from the
equations of motion at the new state). Order 2, conditionally stable.

Two loops share the arithmetic:

- the general path every scheme has (:func:`loop.scheme_loop` around
  :func:`step`, on the ``(lin, shk, exc)`` bundles): the relations of
  laws/, and kept for comparison;
- :func:`fast_loop` (:func:`specialised_loop`), what
  :func:`integrate.integrate` runs otherwise: the loop of :mod:`loop` with
  the step written into it, one compiled loop on plain arrays with
  every helper inlined and no reference counting, the shock
  kinematics in each shock's local frame (:func:`contact.local_shock_forces`),
  the acceleration in one pass (diagonal matrices as 1-D arrays, the
  finiteness test folded in), multipliers searched from their last
  interval, formula loads run by :func:`formula.program_value` and written
  into the force in one pass per load (:func:`external_force_into`). The
  diagonal and full cases are two compiled specialisations of the same
  source (``mass_inverse.ndim`` is a compile-time constant). It stays a
loop of its own because it is faster than the general path (tube, 20
modes, three CERCLE supports: docs/performance.md) and numba can neither
inline a step into a loop that receives it nor cache such a loop.
"""

from __future__ import annotations

import numpy as np

from asterlite.dynamics import energy as E
from asterlite.dynamics import kernel as K
from asterlite.dynamics.contact import local_shock_forces
from asterlite.dynamics.forces import (
    all_finite,
    diagonal_acceleration,
    full_acceleration,
    loads_cover,
    local_support_motion,
    multiplier_at,
    state_acceleration,
)
from asterlite.dynamics.formula import program_value
from asterlite.dynamics.jit import njit
from asterlite.dynamics.layouts import LOADS, LOCAL, ROWS, SHOCKS

RESIDUAL = 0  # memory row: residual scratch


def prepare(system, dt, options):
    """(memory, adaptive): one scratch row, no parameters."""
    n = system.n_modes
    return (np.zeros((1, n)), np.zeros(1), np.zeros((1, 1))), False


@njit(cache=True)
def step(t, dt, index, state, memory, model):
    q, v, a, f, vint, vint_save, work = state
    rows = memory[ROWS]
    for i in range(q.shape[0]):
        v[i] += dt * a[i]
        q[i] += dt * v[i]
    shock = state_acceleration(t + dt, q, v, a, f, rows[RESIDUAL], vint, work, model)
    if shock >= 0:
        return K.STATUS_SHOCK_DIVERGED, shock, dt, dt, 0
    if not all_finite(a):
        return K.STATUS_NOT_FINITE, -1, dt, dt, 0
    return K.STATUS_DONE, -1, dt, dt, 0


@njit(cache=True, _nrt=False)
def fast_loop(clock, counters, state, memory, model, instants, pas_arch, eps, archive, energy):
    """The specialised DIFF_CENTRE loop on the engine's bundles. Compiled
    without reference counting (``_nrt=False``: nothing here allocates),
    so that the arrays handed to the inlined helpers cost nothing.
    ``energy``: the energy balance's bundle (:mod:`energy`), inactive without it."""
    exc = model[LOADS]
    flags, params, rots, polars = (
        model[SHOCKS].flags,
        model[SHOCKS].params,
        model[SHOCKS].rots,
        model[SHOCKS].polars,
    )
    mass_inverse, stiffness, damping, shapes, rest, drive = model[LOCAL]
    out_t, out_order, out_q, out_v, out_a, out_vint, out_info = archive
    return specialised_loop(
        clock,
        counters,
        instants,
        pas_arch,
        eps,
        state.q,
        state.v,
        state.a,
        state.f,
        state.vint,
        memory[ROWS][RESIDUAL],
        mass_inverse,
        stiffness,
        damping,
        flags,
        params,
        rots,
        shapes,
        rest,
        polars,
        drive,
        exc.vectors,
        exc.abscissas,
        exc.ordinates,
        exc.layout,
        exc.pending,
        exc.cursors,
        exc.codes,
        exc.constants,
        exc.stack,
        exc.drive_shapes,
        exc.drive_abscissas,
        exc.drive_ordinates,
        exc.drive_layout,
        exc.drive_pending,
        exc.drive_cursors,
        out_t,
        out_order,
        out_q,
        out_v,
        out_a,
        out_vint,
        out_info,
        energy,
        model[SHOCKS],
        exc,
    )


@njit(cache=True, inline="always")
def external_force_into(
    t, vectors, abscissas, ordinates, layout, cursors, codes, constants, stack, out
):
    """out = Σ_e f_e(t) vector_e: :func:`forces.add_external_force` on a
    zeroed ``out``, the zeroing folded into the first load's pass (0.0 + x
    as there) and the formula programs run by :func:`formula.program_value`.
    Same operations in the same order: the same force to the last bit."""
    for e in range(vectors.shape[0]):
        if codes[e, 0] > 0:
            c = program_value(codes, constants, e, t, stack)
        else:
            c = multiplier_at(
                abscissas, ordinates, e, layout[e, 0], layout[e, 1], layout[e, 2], t, cursors
            )
        if e == 0:
            for m in range(out.shape[0]):
                out[m] = 0.0 + c * vectors[0, m]
        else:
            for m in range(out.shape[0]):
                out[m] += c * vectors[e, m]
    if vectors.shape[0] == 0:
        for m in range(out.shape[0]):
            out[m] = 0.0


@njit(cache=True, _nrt=False)
def specialised_loop(
    clock,
    counters,
    instants,
    pas_arch,
    eps,
    q,
    v,
    a,
    f,
    vint,
    residual,
    mass_inverse,
    stiffness,
    damping,
    shock_flags,
    shock_params,
    shock_rots,
    shock_shapes,
    shock_rest,
    shock_polars,
    shock_drive,
    load_vectors,
    load_abscissas,
    load_ordinates,
    load_layout,
    load_pending,
    load_cursors,
    load_codes,
    load_constants,
    load_stack,
    support_shapes,
    support_abscissas,
    support_ordinates,
    support_layout,
    support_pending,
    support_cursors,
    out_t,
    out_order,
    out_q,
    out_v,
    out_a,
    out_vint,
    out_info,
    energy,
    shk,
    exc,
):
    """The DIFF_CENTRE loop on plain arrays (see the module docstring);
    same status codes and archiving rules as :func:`loop.time_loop`.

    ``mass_inverse``, ``stiffness``, ``damping``: 1-D diagonals or (n, n)
    matrices (:meth:`model.LinearSystem.kernel_matrices`); ``shock_shapes``,
    ``shock_rest``: :meth:`model.ShockSet.local_arrays`; ``shock_drive``:
    (n_shocks, 2, 6) scratch for the support motion in the local frames.
    """
    n = q.shape[0]
    balance = E.is_active(energy)  # energy balance: energy.after_step on the bundles
    while K.unfinished(clock, counters, eps):
        paused = K.pause_status(counters, out_t)
        if paused:
            return paused
        t_ahead = clock[K.C_TIME] + 2.0 * clock[K.C_STEP]
        if not (
            loads_cover(t_ahead, load_abscissas, load_layout, load_pending)
            and loads_cover(t_ahead, support_abscissas, support_layout, support_pending)
        ):
            return K.STATUS_LOADS
        t, dt = K.plan_step(clock, counters, instants, eps)
        for i in range(n):
            v[i] += dt * a[i]
            q[i] += dt * v[i]
        t_new = t + dt
        external_force_into(
            t_new, load_vectors, load_abscissas, load_ordinates, load_layout, load_cursors,
            load_codes, load_constants, load_stack, f,
        )  # fmt: skip
        local_support_motion(
            t_new,
            shock_rots,
            support_shapes,
            support_abscissas,
            support_ordinates,
            support_layout,
            support_cursors,
            shock_drive,
        )
        shock = local_shock_forces(
            q, v, shock_flags, shock_params, shock_shapes, shock_rest, shock_polars,
            shock_drive, vint, f,
        )  # fmt: skip
        if shock >= 0:
            return K.record_failure(clock, counters, K.STATUS_SHOCK_DIVERGED, shock, dt)
        if mass_inverse.ndim == 1:
            finite = diagonal_acceleration(a, f, q, v, mass_inverse, stiffness, damping)
        else:
            finite = full_acceleration(a, f, q, v, mass_inverse, stiffness, damping, residual)
        if not finite:
            return K.record_failure(clock, counters, K.STATUS_NOT_FINITE, -1, dt)
        archived = counters[K.K_ARCHIVED] if balance else 0
        K.advance_clock(
            clock, counters, q, v, a, vint, instants, pas_arch, eps,
            out_t, out_order, out_q, out_v, out_a, out_vint, out_info, dt, dt, 0,
        )  # fmt: skip
        if balance:
            E.after_step(
                energy, archived, counters[K.K_ARCHIVED], clock[K.C_TIME], dt,
                q, v, a, vint, shk, exc,
            )  # fmt: skip
    return K.STATUS_DONE
