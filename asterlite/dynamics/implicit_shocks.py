"""Shocks treated implicitly (DYNA_VIBRA's implicit treatment of the nonlinearities).

A DIS_CHOC normal force is piecewise linear in the modal coordinates: zero
while the gap is open, -k_n d - c_n v_n in contact. code_aster
(dtmprep_noli, dtmdetect, dtmupmat, dtmeigen, dtmproj) integrates each
contact configuration ("case") as a linear system: the contact stiffness
and damping of the shocks in contact join K and C, where every scheme
treats them as it treats the structure (implicitly for NEWMARK, TRBDF2,
DEVOGE), and the gap term becomes a constant force. The time loop detects
each change of configuration at the end of a step and, when the switch
lies well inside the step, integrates the step again up to it.

asterlite follows that algorithm with these choices:

- Linearisation (dtmupmat): for a shock in contact, with g the gradient of
  its gap d in modal coordinates (the normal at the node(s) projected on
  the modes, node 1 minus node 2), K gains k_n g gᵀ, C gains c_n g gᵀ and
  the force gains -k_n d_0 g, d_0 = d(q) - g·q the gap extrapolated to
  q = 0. code_aster obtains the same terms (exactly, for plane obstacles)
  by finite differences of the whole force and caches them per case;
  asterlite writes them in closed form and linearises again at every
  switch (curved obstacles: about the current contact point, and again
  whenever the normal has turned by more than NORMAL_TURN while in
  contact: a tube orbiting in a circular support). Friction and
  the other relations stay explicit and are not also differentiated into
  K (code_aster's finite differences count a sticking friction twice).
- While any shock is linearised, the other DIS_CHOC apply no explicit
  normal force (as code_aster's dtmforc with its implicit flag): a new
  contact is caught at the end of the step.
- Basis: code_aster re-diagonalises K + K_add with M and integrates in the
  new modal coordinates, archiving Φ q in the original ones. Every scheme
  here is invariant under such a linear change of coordinates, so asterlite
  integrates the same equations with full K and C in the original
  coordinates (same results up to round-off for the fixed-step schemes;
  the adaptive schemes measure their error on other coordinates).
- Detection (dtmdetect): a shock is in contact when its clipped normal
  force max(0, -k_n d - c_n v_n) exceeds 2.2e-16 (code_aster's test),
  evaluated here on the state at the end of the step for every scheme
  (code_aster's NEWMARK reads forces of the previous state and so sees
  each switch one step late).
- Cut (dtmupmat): the fraction of the step at which the switch occurs is
  the linear interpolation, between the step's start and end, of what
  changed sign: the gap for a contact entry, the unclipped force for an
  exit (code_aster projects a "critical point" of the linearised systems on
  the path; for one mode entering contact that is the same interpolation).
  A switch within 1 % of the planned step from its end is accepted there
  (code_aster's tolerance); one further inside is reached by integrating
  the step again up to it; one within 1 % of the planned step from its
  start (or 1e-10 s) is made at the start and the whole step integrated
  again in the new configuration. code_aster accepts those at the end of
  the step, so that, after a cut that stops just short of a contact exit,
  the next step runs whole with the contact spring in tension. At most
  MAX_TRIES integrations of one step; the step after a cut one is the
  user's step again (the time grid shifts, as in code_aster).
- Not with support motion (multiple supports, static corrections): the gap then moves with
  the supports and a constant force cannot carry it (refused upstream).

Everything runs in the compiled loop; the state of a step (scheme memory
included) is copied before it so that it can be integrated again.
"""

from __future__ import annotations

import numpy as np

from asterlite.dynamics import contact as C
from asterlite.dynamics import dispatch as D
from asterlite.dynamics import energy as E
from asterlite.dynamics import kernel as K
from asterlite.dynamics import loop as L
from asterlite.dynamics.contact import add_generalized_force, local_state, obstacle_gap
from asterlite.dynamics.jit import njit
from asterlite.dynamics.layouts import EXTRA, LINEAR, ROWS, SCALARS, SHOCKS, TABLE, Treatment

EPS = np.finfo(np.float64).eps
CONTACT_FORCE = EPS  # code_aster's r8prem: a shock is in contact above this force
CUT_TOLERANCE = 0.01  # a switch within 1 % of a step from its end is made there
SHORTEST_CUT = 1.0e-10  # s: no shorter re-integrated step
MAX_TRIES = 100  # code_aster stops after 100 re-integrations of one step

# ints[]: re-integrations of the current step, switches, re-integrations in
# all, linearisations again about a contact point that moved (curved obstacles)
I_TRIES, I_SWITCHES, I_CUTS, I_TURNS = range(4)
N_INTS = 4
# rows of ``kinematics`` (per shock): gap, normal velocity, unclipped force,
# normal (cos, sin) at the start, then at the end of the step
R_GAP0, R_VN0, R_FORCE0, R_COS0, R_SIN0 = range(5)
R_GAP1, R_VN1, R_FORCE1, R_COS1, R_SIN1 = range(5, 10)
N_KINEMATICS = 10
# a curved obstacle's normal may turn this much (rad) before the shock is
# linearised again about its current contact point
NORMAL_TURN = 1.0e-3


def prepare(scheme: str, memory, system, shocks):
    """(memory, run_loop) of a run with implicit shocks: the scheme's
    memory, then the implicit treatment's arrays: K0, C0 and their diagonal
    flag, the shocks in contact now and at the end of the step, counters
    (``I_*``), the shocks' kinematics, scratch, and the copies of a step's
    starting point (scheme rows and scalars, q v a f, internal variables)."""
    n, ns = system.n_modes, shocks.count
    base = D.full_matrices(scheme, memory)
    lin = system.bundle()
    treatment = Treatment(
        np.array(system.stiffness, dtype=float),  # K0
        np.array(system.damping, dtype=float),  # C0
        lin.diagonal.copy(),  # the diagonal flag of K0, C0
        np.zeros(ns, dtype=np.int64),  # in contact (linearised) now
        np.zeros(ns, dtype=np.int64),  # in contact at the end of the step
        np.zeros(N_INTS, dtype=np.int64),
        np.zeros((N_KINEMATICS, ns)),  # kinematics
        np.zeros((2, n)),  # gradient, scratch
        np.zeros((5, 3)),  # local positions and velocities
        (base[ROWS].copy(), base[SCALARS].copy()),  # the scheme's rows and scalars
        np.zeros((4, n)),  # q, v, a, f
        np.zeros((2, ns, shocks.vint_width)),  # internal variables and their save
        np.zeros(ns, dtype=np.int64),  # in contact at the start of the step
        np.zeros(1),  # the step as planned before any cut
    )
    code = D.code(scheme)

    def run_loop(clock, counters, state, memory, model, instants, pas_arch, eps, archive, energy):
        return implicit_loop(
            code, clock, counters, state, memory, model, instants, pas_arch, eps, archive, energy
        )

    return base + (treatment,), run_loop


def start(memory, model, q, v, t0):
    """Linearise the shocks already in contact at the initial state."""
    treatment = memory[EXTRA]
    shk, lin = model[SHOCKS], model[LINEAR]
    active, trial, kin = treatment.active, treatment.trial, treatment.kinematics
    indicators(q, v, shk, kin, R_GAP1, trial, treatment.work)
    if np.any(trial != active):
        switch(q, shk, lin, treatment)


@njit(cache=True)
def shock_kinematics(s, q, v, shk, work):
    """(gap, cos_n, sin_n, normal velocity) of DIS_CHOC ``s`` at (q, v)."""
    flags, params, rots, phis, polars = shk.flags, shk.params, shk.rots, shk.phis, shk.polars
    p = params[s]
    loc1, vel1, loc2, vel2 = work[0], work[1], work[2], work[3]
    origin = p[C.P_ORIGIN : C.P_ORIGIN + 3]
    local_state(
        rots[s], phis[s, 0], p[C.P_COORD1 : C.P_COORD1 + 3], p[C.P_DRIVE1 : C.P_DRIVE1 + 6],
        origin, q, v, loc1, vel1,
    )  # fmt: skip
    two_nodes = flags[s, C.F_TWO_NODES] == 1
    if two_nodes:
        local_state(
            rots[s], phis[s, 1], p[C.P_COORD2 : C.P_COORD2 + 3], p[C.P_DRIVE2 : C.P_DRIVE2 + 6],
            origin, q, v, loc2, vel2,
        )  # fmt: skip
    else:
        for i in range(3):
            loc2[i] = 0.0
            vel2[i] = 0.0
    gap, cos_n, sin_n = obstacle_gap(
        flags[s, C.F_GEOMETRY], loc1[1], loc1[2], loc2[1], loc2[2], p[C.P_GAP], p[C.P_DIST1],
        p[C.P_DIST2], p[C.P_SIGN_Y], p[C.P_SIGN_Z], polars, s, flags[s, C.F_NPOLAR],
    )  # fmt: skip
    vy, vz = vel1[1], vel1[2]
    if two_nodes:
        vy -= vel2[1]
        vz -= vel2[2]
    return gap, cos_n, sin_n, vy * cos_n + vz * sin_n


@njit(cache=True)
def indicators(q, v, shk, kinematics, first_row, in_contact, work):
    """Gap, normal velocity, unclipped normal force and normal of every
    DIS_CHOC at (q, v) into ``kinematics[first_row:first_row + 5]``, and whether
    each is in contact (clipped force above :data:`CONTACT_FORCE`)."""
    flags, params = shk.flags, shk.params
    for s in range(flags.shape[0]):
        in_contact[s] = 0
        if flags[s, C.F_LAW] != 0:
            continue
        gap, cos_n, sin_n, vn = shock_kinematics(s, q, v, shk, work)
        force = -params[s, C.P_KN] * gap - params[s, C.P_CN] * vn
        kinematics[first_row, s] = gap
        kinematics[first_row + 1, s] = vn
        kinematics[first_row + 2, s] = force
        kinematics[first_row + 3, s] = cos_n
        kinematics[first_row + 4, s] = sin_n
        if gap <= 0.0 and force > CONTACT_FORCE:
            in_contact[s] = 1


@njit(cache=True)
def switch_fraction(active, trial, kinematics):
    """The fraction of the step at which the first shock that changed state
    did so: linear interpolation of its gap (entry from an open gap), of
    its unclipped force (entry of a closed but separating shock, exit), or
    of its gap (an exit through the gap with the force still pushing)."""
    ratio = 1.0
    for s in range(active.shape[0]):
        if active[s] == trial[s]:
            continue
        gap0, gap1 = kinematics[R_GAP0, s], kinematics[R_GAP1, s]
        force0, force1 = kinematics[R_FORCE0, s], kinematics[R_FORCE1, s]
        if trial[s] == 1:  # entry: distance to the switch, positive at the start
            x0, x1 = (gap0, gap1) if gap0 > 0.0 else (-force0, -force1)
        elif gap1 <= 0.0 or force1 <= 0.0:  # exit through the force
            x0, x1 = (force0, force1) if force1 <= 0.0 else (-gap0, -gap1)
        else:
            x0, x1 = -gap0, -gap1
        if x0 - x1 > 0.0:
            ratio = min(ratio, x0 / (x0 - x1))
    return ratio


@njit(cache=True)
def normal_turned(active, params, kinematics):
    """Whether the normal of a linearised shock (a curved obstacle: CERCLE,
    BI_CERCLE, BI_CERC_INT, DISCRET facets) has turned by more than
    NORMAL_TURN since its linearisation, at the end of the step."""
    for s in range(active.shape[0]):
        if active[s] == 0:
            continue
        p = params[s]
        cross = p[C.P_LIN_COS] * kinematics[R_SIN1, s] - p[C.P_LIN_SIN] * kinematics[R_COS1, s]
        dot = p[C.P_LIN_COS] * kinematics[R_COS1, s] + p[C.P_LIN_SIN] * kinematics[R_SIN1, s]
        if abs(cross) > NORMAL_TURN or dot < 0.0:
            return True
    return False


@njit(cache=True)
def switch(q, shk, lin, treatment):
    """Linearise the shocks in contact at ``q`` (``treatment.trial``): K = K0 +
    Σ k_n g gᵀ, C = C0 + Σ c_n g gᵀ into the model's bundle, the gap term
    and normal into each shock's parameters, every DIS_CHOC's treatment
    flag set; they become the active set."""
    stiffness0, damping0, diagonal0, active, trial = (
        treatment.stiffness0,
        treatment.damping0,
        treatment.diagonal0,
        treatment.active,
        treatment.trial,
    )
    ints, vectors, work = treatment.ints, treatment.gradient, treatment.work
    flags, params, rots, phis = shk.flags, shk.params, shk.rots, shk.phis
    stiffness, damping, flag = lin.stiffness, lin.damping, lin.diagonal
    n = q.shape[0]
    stiffness[:, :] = stiffness0
    damping[:, :] = damping0
    gradient, normal = vectors[0], work[4]
    linearised = 0
    for s in range(flags.shape[0]):
        active[s] = trial[s]
        if flags[s, C.F_LAW] != 0 or trial[s] == 0:
            continue
        linearised += 1
        gap, cos_n, sin_n, _ = shock_kinematics(s, q, q, shk, work)
        normal[0], normal[1], normal[2] = 0.0, cos_n, sin_n
        gradient[:] = 0.0
        add_generalized_force(rots[s], phis[s, 0], normal, 1.0, gradient)
        if flags[s, C.F_TWO_NODES] == 1:
            add_generalized_force(rots[s], phis[s, 1], normal, -1.0, gradient)
        p = params[s]
        projected = 0.0
        for i in range(n):
            projected += gradient[i] * q[i]
        p[C.P_LIN_GAP] = gap - projected
        p[C.P_LIN_COS], p[C.P_LIN_SIN] = cos_n, sin_n
        k_n, c_n = p[C.P_KN], p[C.P_CN]
        for i in range(n):
            for j in range(n):
                stiffness[i, j] += k_n * gradient[i] * gradient[j]
                damping[i, j] += c_n * gradient[i] * gradient[j]
    for s in range(flags.shape[0]):
        if flags[s, C.F_LAW] != 0:
            continue
        if linearised == 0:
            flags[s, C.F_IMPLICIT] = C.NORMAL_EXPLICIT
        elif active[s] == 1:
            flags[s, C.F_IMPLICIT] = C.NORMAL_LINEARISED
        else:
            flags[s, C.F_IMPLICIT] = C.NORMAL_LEFT_OUT
    flag[0] = diagonal0[0] if linearised == 0 else 0
    ints[I_SWITCHES] += 1


@njit(cache=True)
def save(clock, counters, state, memory, treatment, clock_copy, counters_copy):
    backup_rows, backup_scalars = treatment.backup
    backup_rows[:, :] = memory[ROWS]
    backup_scalars[:] = memory[SCALARS]
    clock_copy[:] = clock
    counters_copy[:] = counters
    # q, v, a, f then the internal variables (and their save) in the state rows
    keep = treatment.keep
    keep[0, :] = state.q
    keep[1, :] = state.v
    keep[2, :] = state.a
    keep[3, :] = state.f
    vint_keep = treatment.vint_keep
    vint_keep[0, :, :] = state.vint
    vint_keep[1, :, :] = state.vint_save


@njit(cache=True)
def restore(clock, counters, state, memory, treatment, clock_copy, counters_copy):
    backup_rows, backup_scalars = treatment.backup
    memory[ROWS][:, :] = backup_rows
    memory[SCALARS][:] = backup_scalars
    clock[:] = clock_copy
    counters[:] = counters_copy
    keep = treatment.keep
    state.q[:] = keep[0]
    state.v[:] = keep[1]
    state.a[:] = keep[2]
    state.f[:] = keep[3]
    vint_keep = treatment.vint_keep
    state.vint[:, :] = vint_keep[0]
    state.vint_save[:, :] = vint_keep[1]


@njit(cache=True)
def implicit_loop(
    code, clock, counters, state, memory, model, instants, pas_arch, eps, archive, energy
):
    """The time loop of the scheme ``code`` with the implicit treatment:
    each step is saved, integrated, checked for a change of contact
    configuration and, when the switch lies inside it, integrated again up
    to the switch; an accepted switch linearises the new configuration."""
    base = (memory[ROWS], memory[SCALARS], memory[TABLE])
    treatment = memory[EXTRA]
    active, trial, ints, kinematics, work = (
        treatment.active,
        treatment.trial,
        treatment.ints,
        treatment.kinematics,
        treatment.work,
    )
    clock_copy = np.empty_like(clock)
    counters_copy = np.empty_like(counters)
    keep = treatment.keep
    reference = treatment.planned
    n = state.q.shape[0]
    balance = E.is_active(energy)
    while K.unfinished(clock, counters, eps):
        paused = L.before_step(clock, counters, model, archive)
        if paused:
            return paused
        save(clock, counters, state, base, treatment, clock_copy, counters_copy)
        t, dt = K.plan_step(clock, counters, instants, eps)
        status, shock, dt_used, dt_next, rejected = D.scheme_step(
            code, t, dt, counters[K.K_STEP], state, base, model
        )
        if status != K.STATUS_DONE:
            return K.record_failure(clock, counters, status, shock, dt_used)
        q, v = state.q, state.v
        indicators(q, v, model[SHOCKS], kinematics, R_GAP1, trial, work)
        changed = False
        for s in range(trial.shape[0]):
            if trial[s] != active[s]:
                changed = True
        if changed:
            if ints[I_TRIES] == 0:
                reference[0] = dt_used  # the step as planned, before any cut
            indicators(
                keep[0], keep[1], model[SHOCKS], kinematics, R_GAP0, treatment.active_at_start, work
            )
            ratio = switch_fraction(active, trial, kinematics)
            early, late = ratio * dt_used, (1.0 - ratio) * dt_used
            if late > CUT_TOLERANCE * reference[0]:  # not at the end of the step
                if ints[I_TRIES] >= MAX_TRIES:
                    return K.record_failure(clock, counters, K.STATUS_SWITCH_NOT_LOCATED, -1, dt)
                restore(clock, counters, state, base, treatment, clock_copy, counters_copy)
                ints[I_TRIES] += 1
                ints[I_CUTS] += 1
                if early > CUT_TOLERANCE * reference[0] and early > SHORTEST_CUT:
                    clock[K.C_STEP] = early  # integrate up to the switch
                else:  # the switch is at the start: the whole step in the new configuration
                    switch(state.q, model[SHOCKS], model[LINEAR], treatment)
                    D.refresh_operators(code, base, model[LINEAR], n)
                continue
        result = (dt_used, dt_next, rejected)
        archived = counters[K.K_ARCHIVED]
        K.complete_step(clock, counters, state, instants, pas_arch, eps, archive, result)
        if changed or normal_turned(active, model[SHOCKS].params, kinematics):
            switch(q, model[SHOCKS], model[LINEAR], treatment)
            D.refresh_operators(code, base, model[LINEAR], n)
            if not changed:
                ints[I_SWITCHES] -= 1
                ints[I_TURNS] += 1
        if ints[I_TRIES] > 0:  # after a cut step, the user's step again
            clock[K.C_STEP] = clock[K.C_STEP0]
            ints[I_TRIES] = 0
        if balance:
            E.hook(energy, archived, counters, clock, dt_used, state, model)
    return K.STATUS_DONE
