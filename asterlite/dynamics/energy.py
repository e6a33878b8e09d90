"""Energy balance of a generalized transient (DYNA_VIBRA TRAN/GENE with
asked by the deck, an asterlite extension), accumulated in the compiled time
loops: one :func:`accumulate` call per accepted step, one :func:`record`
per archived instant, nothing at all when the keyword is absent.

The balance is that of the projected system (seed eq. 27)

    M q'' + C q' + K q = F_ext(t) + Φᵀ F_shock + Φᵀ F_law

whose power theorem, with the contact forces split into a stored and a
dissipated part, reads

    d/dt (E_cin + E_pot + E_choc) = P_ext - P_amor - D_choc - D_frot + P_nl.

Definitions (all at the states the scheme produces, from local quantities,
never from the generalized force the scheme applied):

- ``ENER_CIN`` = ½ vᵀ M v, ``ENER_POT`` = ½ qᵀ K q (modal elastic energy).
- ``ENER_CHOC`` = Σ_shocks ½ K_N p² + ½ |F_el|² / K_T: p = max(-d_N, 0)
  the penetration, F_el the force held by the tangential spring (stick:
  F_T + C_T v_T, the force without its viscous part; slip: the sliding force,
  which the spring carries and a new stick phase starts from (eq. 13);
  nothing without tangential stiffness).
- ``TRAV_EXT`` = ∫ vᵀ F_ext dt - ∫ Σ F_loc · v_drive dt: the work of the
  generalized loads (the excitation's, also the -Φᵀ M ψ γ(t) loads of relative-motion
  seismic decks and loads given as results) and, with support motions
(multiple supports or static corrections), the work
  the moving supports do through the contacts (the shocks see the node's
  absolute motion Φ q + ψ d(t), the modal equations only Φ q).
- ``DISS_AMOR`` = ∫ vᵀ C v dt (modal or full damping matrix).
- ``DISS_CHOC`` = Σ ∫ (K_N p - F_N) v_N dt with F_N the normal force of
  eq. 11 and v_N = d(d_N)/dt: C_N v_N² while the force follows eq. 9,
  K_N p v_N while the positive part cuts it (a fast separation): >= 0.
- ``DISS_FROT`` = -Σ ∫ F_T · v_T dt - ΔE_tan: the friction work minus what
  the tangential springs stored (C_T |v_T|² in stick, the Coulomb work
  while sliding, the spring energy released at each stick-to-slip switch).
- ``TRAV_NL`` = ∫ vᵀ Φᵀ F_law dt, the work of the relations of ``laws/``
  (FLAMBAGE, ANTI_SISM, DIS_VISC, RELA_EFFO_DEPL...): no split into stored
  and dissipated parts.
- ``RESIDU`` = (ENER_CIN + ENER_POT + ENER_CHOC) - (the same at the start)
  - TRAV_EXT + DISS_AMOR + DISS_CHOC + DISS_FROT - TRAV_NL: zero for the
  exact solution; what the time discretisation adds to (or removes from)
  the energy.

Quadrature: the powers are evaluated at the end of every accepted step and
integrated with the trapezoidal rule over the step actually taken (second
order; the stored energies are exact functions of the state). The forces in
the powers are evaluated again at the end state: the normal force from the
kinematics, the friction force by the contact law (``contact.contact_law``)
run on a copy of the shock's internal variables (the scheme's friction
history; the copy leaves the scheme's own state untouched), the laws by
``laws.kernel.law_forces`` on a copy likewise, the external loads at the
step's end instant. A scheme that applies lagged forces (NEWMARK's shocks
at the previous state) or gets an impact wrong therefore shows it in
RESIDU.

Velocities: DIFF_CENTRE (and EULER) and ADAPT_ORDRE1 carry a velocity half a
step behind their displacement (v_{n+1} = v_n + dt a_n, q_{n+1} = q_n + dt
v_{n+1}: symplectic Euler, i.e. central differences). Their energies and
powers use the synchronous velocity v + dt/2 a (a the acceleration at the
new state), second-order accurate at t_{n+1}; the raw velocity would give
a first-order residual that says nothing about the scheme's accuracy.
"""

from __future__ import annotations

import math

import numpy as np

from asterlite.concepts.table import Table
from asterlite.dynamics.contact import (
    EPS,
    F_GEOMETRY,
    F_LAW,
    F_NPOLAR,
    F_TWO_NODES,
    F_UNIDIR,
    P_CN,
    P_COORD1,
    P_COORD2,
    P_CT,
    P_DIST1,
    P_DIST2,
    P_DRIVE1,
    P_DRIVE2,
    P_GAP,
    P_KN,
    P_KT,
    P_MU_DYN,
    P_MU_STAT,
    P_ORIGIN,
    P_SIGN_Y,
    P_SIGN_Z,
    V_FN,
    V_FT1,
    V_FT2,
    V_STICK,
    V_VN,
    V_VT1,
    V_VT2,
    contact_law,
    local_state,
    obstacle_gap,
)
from asterlite.dynamics.forces import external_force, support_motion
from asterlite.dynamics.jit import njit
from asterlite.dynamics.kernel import C_TIME, K_ARCHIVED
from asterlite.dynamics.laws.kernel import law_forces
from asterlite.dynamics.layouts import LOADS, SHOCKS, Balance

# columns of an archived row (the PARA_CALC table), in this order
COLUMNS = (
    "INST",
    "ENER_CIN",
    "ENER_POT",
    "ENER_CHOC",
    "TRAV_EXT",
    "DISS_AMOR",
    "DISS_CHOC",
    "DISS_FROT",
    "TRAV_NL",
    "RESIDU",
)
(
    C_INST,
    C_ENER_CIN,
    C_ENER_POT,
    C_ENER_CHOC,
    C_TRAV_EXT,
    C_DISS_AMOR,
    C_DISS_CHOC,
    C_DISS_FROT,
    C_TRAV_NL,
    C_RESIDU,
) = range(10)
N_COLUMNS = 10

# accumulator slots: switches, running integrals, powers and energies at the
# last state, initial energies
A_ON, A_STAGGERED, A_DIAGONAL = 0, 1, 2
A_EXT, A_AMOR, A_DCHOC, A_WFROT, A_NL = 3, 4, 5, 6, 7  # ∫ over the steps taken
A_P_EXT, A_P_AMOR, A_P_NL = 8, 9, 10  # powers at the last state
A_E_CIN, A_E_POT, A_E_N, A_E_TAN = 11, 12, 13, 14  # energies at the last state
A_E0, A_E_TAN0 = 15, 16  # at the start
N_ACC = 17
# per-shock columns of ``local[k, s]`` (k = 0: the previous state, 1: the last
# one): gap, normal velocity, normal force, normal dissipation power,
# friction power F_T·v_T, power of the contact force on the support motion
L_GAP, L_VN, L_FN, L_DCHOC, L_FROT, L_DRIVE = range(6)
N_LOCAL = 6

# rows of the vector scratch: synchronous velocity, external force, law force
R_VELOCITY, R_EXTERNAL, R_LAW = 0, 1, 2


def new_energy(system, shocks, capacity: int, staggered: bool, enabled: bool):
    """The bundle the time loops receive: ``(acc, matrices, vectors,
    vint_copy, work, out, local)``; ``staggered``: the scheme's velocity lags
    half a step (see the module docstring; ``Scheme.staggered_velocity``).
    Disabled, every array is empty (same types, so the loops compile once
    for both)."""
    if not enabled:
        return Balance(
            np.zeros(N_ACC),
            np.zeros((3, 0, 0)),
            np.zeros((3, 0)),
            np.zeros((0, 0)),
            np.zeros((5, 3)),
            np.zeros((0, N_COLUMNS)),
            np.zeros((2, 0, N_LOCAL)),
        )
    n = system.n_modes
    acc = np.zeros(N_ACC)
    acc[A_ON] = 1.0
    acc[A_STAGGERED] = 1.0 if staggered else 0.0
    acc[A_DIAGONAL] = 1.0 if system.diagonal else 0.0
    matrices = np.zeros((3, n, n))
    matrices[0], matrices[1], matrices[2] = system.mass, system.stiffness, system.damping
    return Balance(
        acc,
        matrices,
        np.zeros((3, n)),
        np.zeros((shocks.count, shocks.vint_width)),
        np.zeros((5, 3)),
        np.zeros((capacity, N_COLUMNS)),
        np.zeros((2, shocks.count, N_LOCAL)),
    )


def enabled(energy) -> bool:
    return energy.acc[A_ON] == 1.0


def grown(energy, capacity: int):
    """The bundle with room for ``capacity`` archived rows (the driver grows
    it with the archive buffers)."""
    out = energy.rows
    if not enabled(energy) or out.shape[0] >= capacity:
        return energy
    bigger = np.zeros((capacity, N_COLUMNS))
    bigger[: out.shape[0]] = out
    return energy._replace(rows=bigger)


@njit(cache=True, inline="always")
def copy_rows(source, target):
    """target[:, :] = source without a temporary (the DIFF_CENTRE loop runs
    without the runtime that would allocate one)."""
    for i in range(source.shape[0]):
        for j in range(source.shape[1]):
            target[i, j] = source[i, j]


@njit(cache=True)
def quadratic(matrix, x, y, diagonal):
    """xᵀ A y (only the diagonal of A when ``diagonal``)."""
    n = x.shape[0]
    s = 0.0
    if diagonal:
        for i in range(n):
            s += x[i] * matrix[i, i] * y[i]
    else:
        for i in range(n):
            row = 0.0
            for j in range(n):
                row += matrix[i, j] * y[j]
            s += x[i] * row
    return s


@njit(cache=True)
def shock_powers(q, v, vint, flags, params, rots, phis, polars, copy, work, local):
    """Per-state contact quantities of the DIS_CHOC rows, from the local
    kinematics of (q, v), into ``local[s]`` (L_* columns: gap, normal
    velocity, normal force, normal dissipation power, friction power, power
    on the support motion). Returns the (normal, tangential) stored energy."""
    loc1, vel1, loc2, vel2 = work[0], work[1], work[2], work[3]
    e_n, e_tan = 0.0, 0.0
    for s in range(flags.shape[0]):
        for j in range(N_LOCAL):
            local[s, j] = 0.0
        if flags[s, F_LAW] != 0:
            local[s, L_GAP] = 1.0
            continue  # a relation of laws/: TRAV_NL
        two_nodes = flags[s, F_TWO_NODES] == 1
        origin = params[s, P_ORIGIN : P_ORIGIN + 3]
        drive1 = params[s, P_DRIVE1 : P_DRIVE1 + 6]
        local_state(rots[s], phis[s, 0], params[s, P_COORD1 : P_COORD1 + 3], drive1, origin,
                    q, v, loc1, vel1)  # fmt: skip
        if two_nodes:
            drive2 = params[s, P_DRIVE2 : P_DRIVE2 + 6]
            local_state(rots[s], phis[s, 1], params[s, P_COORD2 : P_COORD2 + 3], drive2,
                        origin, q, v, loc2, vel2)  # fmt: skip
        else:
            for i in range(3):
                loc2[i] = 0.0
                vel2[i] = 0.0
        gap, cos_n, sin_n = obstacle_gap(
            flags[s, F_GEOMETRY], loc1[1], loc1[2], loc2[1], loc2[2], params[s, P_GAP],
            params[s, P_DIST1], params[s, P_DIST2], params[s, P_SIGN_Y], params[s, P_SIGN_Z],
            polars, s, flags[s, F_NPOLAR],
        )  # fmt: skip
        rx, ry, rz = loc1[0], loc1[1], loc1[2]
        vx, vy, vz = vel1[0], vel1[1], vel1[2]
        if two_nodes:
            rx, ry, rz = rx - loc2[0], ry - loc2[1], rz - loc2[2]
            vx, vy, vz = vx - vel2[0], vy - vel2[1], vz - vel2[2]
        local[s, L_GAP] = gap
        local[s, L_VN] = vy * cos_n + vz * sin_n
        if gap > 0.0:
            continue  # no force, nothing stored (the law's reset concerns the scheme only)
        for j in range(copy.shape[1]):
            copy[s, j] = vint[s, j]
        unidir = flags[s, F_UNIDIR] == 1
        _, _, fx, fy, fz = contact_law(
            params, unidir, copy, s, gap, cos_n, sin_n, rx, ry, rz, vx, vy, vz
        )
        fn, vn = copy[s, V_FN], copy[s, V_VN]
        ft1, ft2, vt1, vt2 = copy[s, V_FT1], copy[s, V_FT2], copy[s, V_VT1], copy[s, V_VT2]
        k_n = params[s, P_KN]
        penetration = -gap
        e_n += 0.5 * k_n * penetration * penetration
        local[s, L_FN] = fn
        local[s, L_DCHOC] = (k_n * penetration - fn) * vn
        local[s, L_FROT] = ft1 * vt1 + ft2 * vt2
        k_t = params[s, P_KT]
        friction = abs(params[s, P_MU_STAT]) > EPS or abs(params[s, P_MU_DYN]) > EPS
        if k_t > 0.0 and friction:
            el1, el2 = ft1, ft2
            if copy[s, V_STICK] == 1.0:  # stick: the spring holds F_T + C_T v_T
                el1 += params[s, P_CT] * vt1
                if not unidir:
                    el2 += params[s, P_CT] * vt2
            e_tan += 0.5 * (el1 * el1 + el2 * el2) / k_t
        # the support motion seen by the contact (supports, static corrections), local frame
        w1, w2, w3 = 0.0, 0.0, 0.0
        for i in range(3):
            g = drive1[3 + i]
            if two_nodes:
                g -= params[s, P_DRIVE2 + 3 + i]
            w1 += rots[s, 0, i] * g
            w2 += rots[s, 1, i] * g
            w3 += rots[s, 2, i] * g
        local[s, L_DRIVE] = fx * w1 + fy * w2 + fz * w3
    return e_n, e_tan


@njit(cache=True)
def contact_integrals(before, after, params, dt):
    """∫ over a step of the normal dissipation, friction and support powers
    of each shock (rows L_*, ``before``/``after``: the states at both ends).
    Trapezoidal rule while in contact; over the part of the step in contact
    when the gap changes sign (crossing by linear interpolation of the gap,
    the power there from eq. 11 at zero penetration: C_N v_N² entering, the
    other powers scaled by the normal force), so that the jump of the force
    at contact does not cost a first-order quadrature error."""
    d_choc, w_frot, w_drive = 0.0, 0.0, 0.0
    for s in range(before.shape[0]):
        g0, g1 = before[s, L_GAP], after[s, L_GAP]
        if g0 > 0.0 and g1 > 0.0:
            continue
        if g0 <= 0.0 and g1 <= 0.0:
            h = 0.5 * dt
            d_choc += h * (before[s, L_DCHOC] + after[s, L_DCHOC])
            w_frot += h * (before[s, L_FROT] + after[s, L_FROT])
            w_drive += h * (before[s, L_DRIVE] + after[s, L_DRIVE])
            continue
        inside = after if g1 <= 0.0 else before  # the end in contact
        theta = (g1 if g1 <= 0.0 else g0) / (g1 - g0)  # in-contact fraction (>= 0)
        if g0 <= 0.0:
            theta = -theta
        # at the crossing: v_N interpolated, F_N = <-C_N v_N>+ (zero penetration)
        vn = before[s, L_VN] + (after[s, L_VN] - before[s, L_VN]) * (
            g0 / (g0 - g1) if g0 != g1 else 0.0
        )
        fn_cross = max(-params[s, P_CN] * vn, 0.0)
        scale = fn_cross / inside[s, L_FN] if inside[s, L_FN] > 0.0 else 0.0
        h = 0.5 * theta * dt
        d_choc += h * (fn_cross * abs(vn) + inside[s, L_DCHOC])
        w_frot += h * (1.0 + scale) * inside[s, L_FROT]
        w_drive += h * (1.0 + scale) * inside[s, L_DRIVE]
    return d_choc, w_frot, w_drive


@njit(cache=True)
def evaluate(energy, t, q, v, a, dt, vint, shk, exc):
    """Powers and energies at the state (t, q, v); ``dt`` the step that led
    to it (0 at the start). Writes the A_P_* and A_E_* slots and the
    shocks' row ``local[1]``."""
    acc, matrices, vectors, copy, work = (
        energy.acc,
        energy.matrices,
        energy.vectors,
        energy.vint_copy,
        energy.work,
    )
    local = energy.local
    n = q.shape[0]
    diagonal = acc[A_DIAGONAL] == 1.0
    w = vectors[R_VELOCITY]
    half = 0.5 * dt if acc[A_STAGGERED] == 1.0 else 0.0
    for i in range(n):
        w[i] = v[i] + half * a[i]
    acc[A_E_CIN] = 0.5 * quadratic(matrices[0], w, w, diagonal)
    acc[A_E_POT] = 0.5 * quadratic(matrices[1], q, q, diagonal)
    acc[A_P_AMOR] = quadratic(matrices[2], w, w, diagonal)
    f = vectors[R_EXTERNAL]
    f[:] = 0.0
    external_force(t, exc, f)
    p_ext = 0.0
    for i in range(n):
        p_ext += f[i] * w[i]
    acc[A_P_EXT] = p_ext
    flags, params, rots, phis, polars = shk.flags, shk.params, shk.rots, shk.phis, shk.polars
    support_motion(t, exc, params)
    e_n, e_tan = shock_powers(q, w, vint, flags, params, rots, phis, polars, copy, work, local[1])
    acc[A_E_N] = e_n
    acc[A_E_TAN] = e_tan
    p_nl = 0.0
    if shk.laws.shape[1] > 0:  # relations of laws/, on a copy of their states
        copy_rows(vint, copy)
        g = vectors[R_LAW]
        g[:] = 0.0
        law_forces(
            t,
            q,
            w,
            flags,
            params,
            rots,
            phis,
            polars,
            shk.laws,
            shk.rphis,
            copy,
            shk.law_scratch,
            g,
        )
        for i in range(n):
            p_nl += g[i] * w[i]
    acc[A_P_NL] = p_nl


@njit(cache=True)
def start(energy, t, q, v, a, vint, shk, exc):
    """The balance at the initial state (row 0 of the archive)."""
    acc = energy.acc
    for k in range(A_EXT, A_NL + 1):
        acc[k] = 0.0
    evaluate(energy, t, q, v, a, 0.0, vint, shk, exc)
    copy_rows(energy.local[1], energy.local[0])
    acc[A_E0] = acc[A_E_CIN] + acc[A_E_POT] + acc[A_E_N] + acc[A_E_TAN]
    acc[A_E_TAN0] = acc[A_E_TAN]
    record(energy, 0, t)


@njit(cache=True)
def accumulate(energy, t, dt, q, v, a, vint, shk, exc):
    """After an accepted step of length dt ending at t: the powers at the new
    state, trapezoidal rule over the step."""
    acc = energy.acc
    local = energy.local
    p_ext, p_amor, p_nl = acc[A_P_EXT], acc[A_P_AMOR], acc[A_P_NL]
    evaluate(energy, t, q, v, a, dt, vint, shk, exc)
    d_choc, w_frot, w_drive = contact_integrals(local[0], local[1], shk.params, dt)
    copy_rows(local[1], local[0])
    h = 0.5 * dt
    acc[A_EXT] += h * (p_ext + acc[A_P_EXT]) - w_drive
    acc[A_AMOR] += h * (p_amor + acc[A_P_AMOR])
    acc[A_DCHOC] += d_choc
    acc[A_WFROT] += w_frot
    acc[A_NL] += h * (p_nl + acc[A_P_NL])


@njit(cache=True)
def record(energy, row, t):
    """Row ``row`` of the archived balance, at instant t."""
    acc, out = energy.acc, energy.rows
    e_choc = acc[A_E_N] + acc[A_E_TAN]
    diss_frot = -acc[A_WFROT] - (acc[A_E_TAN] - acc[A_E_TAN0])
    out[row, C_INST] = t
    out[row, C_ENER_CIN] = acc[A_E_CIN]
    out[row, C_ENER_POT] = acc[A_E_POT]
    out[row, C_ENER_CHOC] = e_choc
    out[row, C_TRAV_EXT] = acc[A_EXT]
    out[row, C_DISS_AMOR] = acc[A_AMOR]
    out[row, C_DISS_CHOC] = acc[A_DCHOC]
    out[row, C_DISS_FROT] = diss_frot
    out[row, C_TRAV_NL] = acc[A_NL]
    out[row, C_RESIDU] = (
        acc[A_E_CIN]
        + acc[A_E_POT]
        + e_choc
        - acc[A_E0]
        - acc[A_EXT]
        + acc[A_AMOR]
        + acc[A_DCHOC]
        + diss_frot
        - acc[A_NL]
    )


def active(energy) -> bool:
    """Whether the balance is computed (read once, before a time loop)."""
    return energy.acc[A_ON] == 1.0


@njit(cache=True, inline="always")
def is_active(energy):
    return energy.acc[A_ON] == 1.0


@njit(cache=True)
def after_step(energy, archived_before, archived_after, t, dt, q, v, a, vint, shk, exc):
    """The hook of the time loops, after the clock advanced over an accepted
    step of length dt: accumulate over the step and record the row when the
    step was archived. ``t`` is the loop's clock (the archived instant)."""
    accumulate(energy, t, dt, q, v, a, vint, shk, exc)
    if archived_after > archived_before:
        record(energy, archived_after - 1, t)


@njit(cache=True, inline="always")
def hook(energy, archived_before, counters, clock, dt, state, model):
    """:func:`after_step` on the general loops' bundles."""
    after_step(
        energy, archived_before, counters[K_ARCHIVED], clock[C_TIME], dt,
        state.q, state.v, state.a, state.vint, model[SHOCKS], model[LOADS],
    )  # fmt: skip


def table(rows: np.ndarray, previous=None, t0: float | None = None):
    """The PARA_CALC table of the archived rows; with ``previous`` (the
    table of a reused result) its rows before t0 come first (each run's
    balance starts from its own initial state, as the PHYS balance)."""

    out = Table(title="PARA_CALC")
    for name in COLUMNS:
        out.add_column(name, "R")
    if previous is not None and t0 is not None:
        tol = 1.0e-12 * max(1.0, abs(t0))
        for row in previous.rows:
            if row.get("INST", math.inf) < t0 - tol:
                out.add_row(dict(row))
    for values in rows:
        out.add_row({name: float(x) for name, x in zip(COLUMNS, values, strict=True)})
    return out


def summary(rows: np.ndarray) -> dict:
    """The final residual, its ratio to the largest total energy (ENER_CIN +
    ENER_POT + ENER_CHOC over the archived instants) and to the energy that
    went through the system (that largest total plus the largest |TRAV_EXT|
    and |TRAV_NL|: a forced run dissipates far more than it ever holds)."""
    if rows.shape[0] == 0:
        return {}
    total = rows[:, C_ENER_CIN] + rows[:, C_ENER_POT] + rows[:, C_ENER_CHOC]
    scale = float(np.max(np.abs(total)))
    flow = scale + float(np.max(np.abs(rows[:, C_TRAV_EXT])) + np.max(np.abs(rows[:, C_TRAV_NL])))
    residual = float(rows[-1, C_RESIDU])
    return {
        "energy_residual": residual,
        "energy_residual_ratio": abs(residual) / scale if scale > 0.0 else None,
        "energy_residual_flow_ratio": abs(residual) / flow if flow > 0.0 else None,
        "energy_max_total": scale,
        "energy_max_abs_residual": float(np.max(np.abs(rows[:, C_RESIDU]))),
    }
