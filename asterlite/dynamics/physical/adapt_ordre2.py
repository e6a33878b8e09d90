"""ADAPT_ORDRE2 on the physical system (code_aster's dladap): central
differences with a step that follows the apparent frequency of the motion,
diagonal (lumped) mass.

Each trial step dt2 from t (previous step dt1, 0 on the first one):

    v_mid = v_{n-1/2} + (dt1 + dt2)/2 a_n        (v_{-1/2} = v_0 - dt/2 a_0)
    q'    = q_n + dt2 v_mid
    a'    = M⁻¹ (F(t + dt2) - K q' - C v_mid)
    v'    = v_mid + dt2/2 a'                     (the archived velocity)

The error err = N · f · dt2 (N points per period) uses the apparent frequency
f = sqrt(max_i |a'_i - a_i| / max(v_min,i dt2, |q'_i - q_i|)) / 2π; while
err > 1 the step is divided by the division factor (at most the largest
number of trials). After five calm steps (err < 0.75) it is multiplied by
the growth factor, never beyond dt. Reference velocities: 'MAXI'
keeps the running maximum of 1 % of |v_{n-1/2}| per DOF, 'NORM' takes 1 %
of the mid-step velocity of the neighbouring equations carrying the same
component. An archive instant (every archiving period · dt from the start) stores
whichever end of the step that brackets it is closer, plus the last one.
"""

from __future__ import annotations

import math

import numpy as np

from asterlite.dynamics.physical.stepping import finite, non_finite_state
from asterlite.errors import NumericalError
from asterlite.errors import field as named

EPS = np.finfo(float).eps
TINY = np.finfo(float).tiny


def same_component_neighbours(numbering, free: np.ndarray):
    """For each free DOF, the reduced index of the previous and of the next
    DOF of the numbering with the same component (-1: a blocked DOF or none,
    whose velocity counts as zero)."""
    components = numbering.dof_components
    reduced = -np.ones(numbering.n_dofs, dtype=int)
    reduced[free] = np.arange(free.size)
    before = -np.ones(free.size, dtype=int)
    after = -np.ones(free.size, dtype=int)
    last_seen: dict[str, int] = {}
    for i, comp in enumerate(components):
        if comp in last_seen and reduced[i] >= 0:
            before[reduced[i]] = reduced[last_seen[comp]]
        last_seen[comp] = i
    last_seen.clear()
    for i in range(len(components) - 1, -1, -1):
        comp = components[i]
        if comp in last_seen and reduced[i] >= 0:
            after[reduced[i]] = reduced[last_seen[comp]]
        last_seen[comp] = i
    return before, after


def apparent_frequency(dt, q1, q2, a1, a2, vmin) -> float:
    reference = vmin * dt
    dq = np.abs(q2 - q1)
    b = np.where(reference >= dq, reference, dq)
    b = np.where(b <= TINY, EPS, b)
    return math.sqrt(max(EPS, float(np.max(np.abs((a2 - a1) / b), initial=0.0)))) / (2.0 * math.pi)


def integrate(system, t0, t_end, dt_max, q, v, a, archive, inverse_mass, options, neighbours, log):
    """``options``: vite_min, coef_mult_pas, coef_divi_pas, dt_min,
    nb_poin_periode, nmax_iter_pas, pas_arch."""
    n = q.size
    vmin = np.full(n, 1.0e-15)
    vmin_before = np.full(n, 1.0e-15)
    vmin_after = np.full(n, 1.0e-15)
    massive = inverse_mass != 0.0
    before, after = neighbours
    zero = np.zeros(1)
    dt_min = options["dt_min"] if options.get("dt_min") is not None else 1.0e-6 * dt_max
    n_per = options["nb_poin_periode"]
    n_trials_max = options["nmax_iter_pas"]
    mult, divi = options["coef_mult_pas"], options["coef_divi_pas"]
    dt_archive = dt_max * options["pas_arch"]

    depl, vite, acce = q.copy(), v - 0.5 * dt_max * a, a.copy()
    vip1 = v.copy()
    archive.add(t0, depl, vip1, acce)
    temps, dt1, dt2, calm = t0, 0.0, dt_max, 0
    archived_periods = 1  # the archiving instants are t0 + k dt period, never a running sum
    t_archive = t0 + dt_archive
    steps = trials_total = warned = 0
    while temps < t_end:
        err, trials = 100.0, 0
        if temps + dt2 > t_end:
            dt2 = t_end - temps
        while err > 1.0 and trials < n_trials_max:
            trials_total += 1
            vit2 = vite + 0.5 * (dt1 + dt2) * acce
            dep2 = depl + dt2 * vit2
            rhs = system.forces([temps + dt2])[0] - system.reduced_stiffness() @ dep2
            if system.damping is not None:
                rhs -= system.damping @ vit2
            acc2 = inverse_mass * rhs
            vip2 = vit2 + 0.5 * dt2 * acc2
            if options["vite_min"] == "MAXI":
                np.maximum(vmin, np.abs(vite * 1.0e-2), out=vmin)
            else:
                padded = np.concatenate([vit2, zero])
                vmin_before[massive] = 1.0e-2 * padded[before][massive]
                vmin_after[massive] = 1.0e-2 * padded[after][massive]
                vmin = np.maximum(1.0e-15, np.maximum(vmin_before, vmin_after))
            err = n_per * apparent_frequency(dt2, depl, dep2, acce, acc2, vmin) * dt2
            if err > 1.0:
                dt2 = dt2 / divi
            if dt2 <= dt_min and abs(t_end - (temps + dt2)) > EPS:
                raise NumericalError(
                    f"ADAPT_ORDRE2: the step fell below {named('options.dt_min')}={dt_min:.6g} "
                    f"at t={temps:.6g}"
                )
            trials += 1
        if err > 1.0:
            dt2 = dt2 * divi
            warned += 1
        if not (finite(dep2) and finite(vip2) and finite(acc2)):
            raise non_finite_state(system, temps + dt2, temps, steps + 1, dep2, vip2, acc2, archive)
        dt1 = dt2
        temp2 = temps + dt2
        if err < 0.75:
            if calm == 5:
                dt2 = min(mult * dt2, dt_max)
                calm = 4
            calm += 1
        else:
            calm = 0
        steps += 1
        if (temps <= t_archive <= temp2) or temp2 == t_end:
            if (temp2 - t_archive) <= (t_archive - temps):
                archive.add(temp2, dep2, vip2, acc2)
            else:
                archive.add(temps, depl, vip1, acce)
            archived_periods += 1
            t_archive = t0 + archived_periods * dt_archive
        temps = temp2
        depl, vite, vip1, acce = dep2, vit2, vip2, acc2
    if warned:
        log(
            f"warning: {warned} steps kept after {named('options.nmax_iter_pas')} trials above the "
            "apparent-frequency criterion (code_aster's ALGORITH3_16)"
        )
    return {"steps": steps, "trials": trials_total}
