"""Hand-written loops of every GENE scheme on the tube problem: the floors
asterlite's loops are compared with (tube_floor.py is DIFF_CENTRE's).

Each loop is one numba function on plain arrays, fixed step, the physics
of tube_floor.py (20 mass-normalised modes with modal damping, the force
turning at mid-span as sin/cos, three CERCLE supports with Coulomb
friction written out for that case) in one inlined ``acceleration``
helper, and each scheme's own arithmetic per step:

- NEWMARK (β = 1/4, γ = 1/2, code_aster's displacement form): the shock
  forces of the previous step's state, one diagonal solve;
- DEVOGE (Devogelaere-Fu, order 4): two evaluations per step (half and
  whole step), finite-difference velocities for the shocks, the damping
  implicit in the velocity updates;
- RUNGE_KUTTA_32 (Bogacki-Shampine) and RUNGE_KUTTA_54 (Dormand-Prince):
  their stages and the embedded error norm (not used to adapt: fixed step);
- ADAPT_ORDRE1 (symplectic Euler) and ADAPT_ORDRE2 (leapfrog): one
  evaluation and the apparent-frequency estimate per step;
- TRBDF2 (γ = 2 - √2): three evaluations and two diagonal solves.

No generality, no dispatch, archiving q and F_N every ``pas_arch`` steps.
The floors are not asterlite's results bit for bit (the stick-slip
response is chaotic); they do the same work per step.

Run: python benchmarks/scheme_floors.py [--steps 200000] [--dt 1e-5] [--engine [--general]]
[SCHEME...] (prints each floor's ns/step; ``--engine``: asterlite's
``integrate`` on the same problem, best CPU time, and the ratio;
``--general``: its general path, shocks in the global frame; the whole
run's marginal cost comes from ``tube_marginal.py --scheme NAME``).
"""

from __future__ import annotations

import argparse
import math
import time
from dataclasses import replace

import numpy as np
import tube_model as T
from numba import njit

SLIP_VELOCITY_FLOOR = 1.0e-6
EPS = np.finfo(np.float64).eps
# friction memory per support: sticking flag, F_ref (2), x_ref (3), v_t old (2), F_N now
M_STICK, M_FREF, M_XREF, M_VTOLD, M_FN = 0, 1, 3, 6, 8
N_MEMORY = 9


@njit(cache=True, inline="always")
def acceleration(t, q, v, out, stiffness, damping, phi, force_y, force_z, f0, w, params, memory):
    """out = f(t) + shock forces - K q - C v (unit modal masses)."""
    gap0, k_n, c_n, k_t, c_t, mu = params[0], params[1], params[2], params[3], params[4], params[5]
    n = q.shape[0]
    sy, cy = f0 * math.sin(w * t), f0 * math.cos(w * t)
    for i in range(n):
        out[i] = sy * force_y[i] + cy * force_z[i]
    for s in range(phi.shape[0]):
        x = y = z = vx = vy = vz = 0.0
        for m in range(n):
            x += phi[s, 0, m] * q[m]
            y += phi[s, 1, m] * q[m]
            z += phi[s, 2, m] * q[m]
            vx += phi[s, 0, m] * v[m]
            vy += phi[s, 1, m] * v[m]
            vz += phi[s, 2, m] * v[m]
        r = math.sqrt(y * y + z * z)
        gap = gap0 - r
        mem = memory[s]
        fn = 0.0
        if gap <= 0.0:
            cos_n, sin_n = -y / r, -z / r
            vn = vy * cos_n + vz * sin_n
            fn = max(0.0, -k_n * gap - c_n * vn)
            vt1 = -sin_n * vy + cos_n * vz
            vt2 = vx
            vnorm = math.sqrt(vt1 * vt1 + vt2 * vt2)
            same = vt1 * mem[M_VTOLD] + vt2 * mem[M_VTOLD + 1] >= 0.0
            if same and mem[M_STICK] == 0.0 and vnorm > SLIP_VELOCITY_FLOOR:
                ft1 = -mu * fn * vt1 / vnorm
                ft2 = -mu * fn * vt2 / vnorm
                mem[M_FREF], mem[M_FREF + 1] = ft1, ft2
                mem[M_XREF], mem[M_XREF + 1], mem[M_XREF + 2] = x, y, z
            else:
                dx1 = -(y - mem[M_XREF + 1]) * sin_n + (z - mem[M_XREF + 2]) * cos_n
                dx2 = x - mem[M_XREF]
                mem[M_STICK] = 1.0
                ft1 = mem[M_FREF] - k_t * dx1 - c_t * vt1
                ft2 = mem[M_FREF + 1] - k_t * dx2 - c_t * vt2
                if math.sqrt(ft1 * ft1 + ft2 * ft2) > mu * fn:
                    mem[M_STICK] = 0.0
                    if vnorm <= EPS:
                        ft1, ft2 = 0.0, 0.0
                    else:
                        ft1 = -mu * fn * vt1 / vnorm
                        ft2 = -mu * fn * vt2 / vnorm
                    mem[M_FREF], mem[M_FREF + 1] = ft1, ft2
                    mem[M_XREF], mem[M_XREF + 1], mem[M_XREF + 2] = x, y, z
            mem[M_VTOLD], mem[M_VTOLD + 1] = vt1, vt2
            gx = ft2
            gy = fn * cos_n - ft1 * sin_n
            gz = fn * sin_n + ft1 * cos_n
            for m in range(n):
                out[m] += phi[s, 0, m] * gx + phi[s, 1, m] * gy + phi[s, 2, m] * gz
        else:
            mem[M_STICK] = 0.0
            mem[M_FREF] = mem[M_FREF + 1] = 0.0
            mem[M_VTOLD] = mem[M_VTOLD + 1] = 0.0
            mem[M_XREF], mem[M_XREF + 1], mem[M_XREF + 2] = x, y, z
        mem[M_FN] = fn
    for i in range(n):
        out[i] -= stiffness[i] * q[i] + damping[i] * v[i]


@njit(cache=True, inline="always")
def archive(step, pas_arch, q, memory, out_q, out_fn):
    if step % pas_arch == 0:
        k = step // pas_arch
        if k < out_q.shape[0]:
            for i in range(q.shape[0]):
                out_q[k, i] = q[i]
            for s in range(memory.shape[0]):
                out_fn[k, s] = memory[s, M_FN]


@njit(cache=True)
def newmark_loop(n_steps, dt, k, c, phi, fy, fz, f0, w, params, pas_arch, out_q, out_fn):
    n = k.shape[0]
    q, v, a, f = np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n)
    q2, v2 = np.zeros(n), np.zeros(n)  # the state the shocks see (index 2)
    memory = np.zeros((phi.shape[0], N_MEMORY))
    beta, gamma = 0.25, 0.5
    a1, a2, a3 = 1.0 / (beta * dt * dt), gamma / (beta * dt), 1.0 / (beta * dt)
    a4, a5 = 1.0 / (2.0 * beta) - 1.0, gamma / beta - 1.0
    a6, a7, a8 = dt / 2.0 * (gamma / beta - 2.0), dt * (1.0 - gamma), gamma * dt
    keff = np.empty(n)
    for i in range(n):
        keff[i] = a1 + a2 * c[i] + k[i]
    acceleration(0.0, q, v, a, k, c, phi, fy, fz, f0, w, params, memory)
    for step in range(1, n_steps + 1):
        t = step * dt
        acceleration(t, q2, v2, f, k, c, phi, fy, fz, f0, w, params, memory)
        for i in range(n):  # acceleration() subtracted K q2 + C v2: add them back
            f[i] += k[i] * q2[i] + c[i] * v2[i]
            rhs = f[i] + (a3 + a5 * c[i]) * v[i] + (a1 + a2 * c[i]) * q[i]
            rhs += (a4 + a6 * c[i]) * a[i]
            q_new = rhs / keff[i]
            a_new = -a4 * a[i] + a1 * (q_new - q[i] - dt * v[i])
            v[i] = v[i] + a7 * a[i] + a8 * a_new
            a[i] = a_new
            q[i] = q_new
            q2[i] = q_new
            v2[i] = v[i]
        archive(step, pas_arch, q, memory, out_q, out_fn)
    return q


@njit(cache=True)
def devoge_loop(n_steps, dt, k, c, phi, fy, fz, f0, w, params, pas_arch, out_q, out_fn):
    """Devogelaere-Fu with r = f - K q (the damping apart, implicit)."""
    n = k.shape[0]
    q1, v1, r1 = np.zeros(n), np.zeros(n), np.zeros(n)
    q3, v3, r3, q4, r4 = np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n)
    v2, r2, u = np.zeros(n), np.zeros(n), np.zeros(n)
    zero = np.zeros(n)
    memory = np.zeros((phi.shape[0], N_MEMORY))
    acceleration(0.0, q1, v1, r1, k, zero, phi, fy, fz, f0, w, params, memory)
    h = dt / 2.0
    for step in range(1, n_steps + 1):
        t = step * dt
        for i in range(n):
            q3[i] = (
                q1[i]
                + h * v1[i]
                + dt * dt / 24.0 * (4.0 * r1[i] - r2[i] - c[i] * (4.0 * v1[i] - v2[i]))
            )
            u[i] = (q3[i] - q1[i]) / h
        acceleration(t - h, q3, u, r3, k, zero, phi, fy, fz, f0, w, params, memory)
        for i in range(n):
            v3[i] = (v1[i] + dt / 4.0 * (r1[i] + r3[i] - c[i] * v1[i])) / (1.0 + dt / 4.0 * c[i])
            q4[i] = (
                q1[i]
                + dt * v1[i]
                + dt * dt / 6.0 * (r1[i] + 2.0 * r3[i] - c[i] * (v1[i] + 2.0 * v3[i]))
            )
            u[i] = (q4[i] - q3[i]) / h
        acceleration(t, q4, u, r4, k, zero, phi, fy, fz, f0, w, params, memory)
        for i in range(n):
            v_new = v1[i] + dt / 6.0 * (r1[i] + 4.0 * r3[i] + r4[i] - c[i] * (v1[i] + 4.0 * v3[i]))
            v_new /= 1.0 + dt / 6.0 * c[i]
            v2[i], r2[i] = v3[i], r3[i]
            q1[i], v1[i], r1[i] = q4[i], v_new, r4[i]
        archive(step, pas_arch, q1, memory, out_q, out_fn)
    return q1


# Bogacki-Shampine (3 stages used, FSAL) and Dormand-Prince (6 + FSAL)
RK32_C = np.array([0.0, 0.5, 0.75, 1.0])
RK32_A = np.array(
    [[0.0, 0.0, 0.0], [0.5, 0.0, 0.0], [0.0, 0.75, 0.0], [2.0 / 9.0, 1.0 / 3.0, 4.0 / 9.0]]
)
RK32_E = np.array([5.0 / 72.0, -1.0 / 12.0, -1.0 / 9.0, 1.0 / 8.0])
RK54_C = np.array([0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0])
RK54_A = np.array(
    [
        [0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
        [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
        [19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0, 0.0, 0.0],
        [9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0, 0.0],
        [35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0],
    ]
)
RK54_E = np.array(
    [
        71.0 / 57600.0,
        0.0,
        -71.0 / 16695.0,
        71.0 / 1920.0,
        -17253.0 / 339200.0,
        22.0 / 525.0,
        -1.0 / 40.0,
    ]
)


@njit(cache=True)
def runge_kutta_loop(
    n_steps, dt, k, c, phi, fy, fz, f0, w, params, pas_arch, out_q, out_fn, nodes, coefs, errs
):
    """An explicit tableau on (q, v), first-same-as-last: the last row of
    ``coefs`` is the solution; the error norm is computed, not used."""
    n = k.shape[0]
    stages = nodes.shape[0]
    kq, kv = np.zeros((stages, n)), np.zeros((stages, n))
    q, v, qs, vs = np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n)
    memory = np.zeros((phi.shape[0], N_MEMORY))
    acceleration(0.0, q, v, kv[0], k, c, phi, fy, fz, f0, w, params, memory)
    for i in range(n):
        kq[0, i] = v[i]
    error = 0.0
    for step in range(1, n_steps + 1):
        t = (step - 1) * dt
        for j in range(1, stages):
            for i in range(n):
                sq, sv = q[i], v[i]
                for m in range(j):
                    sq += dt * coefs[j, m] * kq[m, i]
                    sv += dt * coefs[j, m] * kv[m, i]
                qs[i], vs[i] = sq, sv
                kq[j, i] = sv
            acceleration(t + nodes[j] * dt, qs, vs, kv[j], k, c, phi, fy, fz, f0, w, params, memory)
        error = 0.0
        for i in range(n):
            eq = ev = 0.0
            for m in range(stages):
                eq += errs[m] * kq[m, i]
                ev += errs[m] * kv[m, i]
            sq = dt * eq / (1.0e-8 + abs(qs[i]))
            sv = dt * ev / (1.0e-8 + abs(vs[i]))
            error = max(error, sq * sq + sv * sv)
            q[i], v[i] = qs[i], vs[i]
            kq[0, i], kv[0, i] = kq[stages - 1, i], kv[stages - 1, i]
        archive(step, pas_arch, q, memory, out_q, out_fn)
    return q, error


@njit(cache=True)
def adapt_loop(n_steps, dt, k, c, phi, fy, fz, f0, w, params, pas_arch, out_q, out_fn, order):
    """ADAPT_ORDRE1 (order 1: symplectic Euler) or ADAPT_ORDRE2 (leapfrog):
    one evaluation and the apparent-frequency estimate per step."""
    n = k.shape[0]
    q, v, a = np.zeros(n), np.zeros(n), np.zeros(n)
    q_old, v_mid, a_new = np.zeros(n), np.zeros(n), np.zeros(n)
    memory = np.zeros((phi.shape[0], N_MEMORY))
    acceleration(0.0, q, v, a, k, c, phi, fy, fz, f0, w, params, memory)
    frequency = 0.0
    for step in range(1, n_steps + 1):
        t = step * dt
        p = dt / 2.0 if step == 1 and order == 2 else dt
        for i in range(n):
            q_old[i] = q[i]
            if order == 2:
                v_mid[i] += a[i] * p
                q[i] += v_mid[i] * dt
                v[i] = v_mid[i] + a[i] * dt / 2.0
            else:
                v[i] += a[i] * p
                q[i] += v[i] * dt
        acceleration(t, q, v, a_new, k, c, phi, fy, fz, f0, w, params, memory)
        # apparent frequency: max over modes of |Δa| / |Δq|
        frequency = 0.0
        for i in range(n):
            dq = abs(q[i] - q_old[i])
            if dq > 1.0e-15:
                frequency = max(frequency, math.sqrt(abs(a_new[i] - a[i]) / dq))
            a[i] = a_new[i]
        archive(step, pas_arch, q, memory, out_q, out_fn)
    return q, frequency


@njit(cache=True)
def trbdf2_loop(n_steps, dt, k, c, phi, fy, fz, f0, w, params, pas_arch, out_q, out_fn):
    n = k.shape[0]
    gamma = 2.0 - math.sqrt(2.0)
    h = gamma * dt
    a1, a2 = 4.0 / (h * h), 2.0 / h
    g1 = 1.0 / (gamma * (2.0 - gamma))
    g2 = -((1.0 - gamma) ** 2) / (gamma * (2.0 - gamma))
    g3 = (1.0 - gamma) / (2.0 - gamma)
    keff = np.empty(n)
    for i in range(n):
        keff[i] = a1 + a2 * c[i] + k[i]
    q, v, a = np.zeros(n), np.zeros(n), np.zeros(n)
    q2, v2, at, at2 = np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n)
    memory = np.zeros((phi.shape[0], N_MEMORY))
    acceleration(0.0, q, v, a, k, c, phi, fy, fz, f0, w, params, memory)
    for step in range(1, n_steps + 1):
        t = (step - 1) * dt
        acceleration(t + h, q2, v2, at, k, c, phi, fy, fz, f0, w, params, memory)
        acceleration(t + dt, q2, v2, at2, k, c, phi, fy, fz, f0, w, params, memory)
        for i in range(n):
            delta = h * ((a1 + a2 * c[i]) * v[i] + a2 * (a[i] + at[i]) / 2.0) / keff[i]
            qg, vg = q[i] + delta, 2.0 * delta / h - v[i]
            rq = q[i] - g1 * qg - g2 * q[i] - g3 * dt * v[i]
            rv = v[i] - g1 * vg - g2 * v[i] - g3 * dt * at2[i]
            delta = -(a2 * rv + (a1 + a2 * c[i]) * rq) / keff[i]
            q[i] += delta
            v[i] += (delta + rq) / (g3 * dt)
            q2[i], v2[i] = q[i], v[i]
        acceleration(t + dt, q, v, a, k, c, phi, fy, fz, f0, w, params, memory)
        archive(step, pas_arch, q, memory, out_q, out_fn)
    return q


SCHEMES = (
    "NEWMARK",
    "DEVOGE",
    "RUNGE_KUTTA_32",
    "RUNGE_KUTTA_54",
    "ADAPT_ORDRE1",
    "ADAPT_ORDRE2",
    "TRBDF2",
)


def run_floor(scheme: str, problem, n_steps: int, dt: float, pas_arch: int = 10):
    """The archived q of ``scheme``'s hand-written loop on the tube problem."""
    params = np.array([T.GAP, T.K_NORMAL, T.C_NORMAL, T.K_TANGENT, T.C_TANGENT, T.MU])
    out_q = np.zeros((n_steps // pas_arch + 1, T.N_MODES))
    out_fn = np.zeros((n_steps // pas_arch + 1, len(T.SUPPORT_NODES)))
    phi = np.ascontiguousarray(problem.phi_supports)
    common = (
        n_steps, dt, problem.stiffness, problem.damping, phi, problem.force_y, problem.force_z,
        T.FORCE_AMPLITUDE, problem.forcing_omega, params, pas_arch, out_q, out_fn,
    )  # fmt: skip
    if scheme == "NEWMARK":
        newmark_loop(*common)
    elif scheme == "DEVOGE":
        devoge_loop(*common)
    elif scheme == "RUNGE_KUTTA_32":
        runge_kutta_loop(*common, RK32_C, RK32_A, RK32_E)
    elif scheme == "RUNGE_KUTTA_54":
        runge_kutta_loop(*common, RK54_C, RK54_A, RK54_E)
    elif scheme in ("ADAPT_ORDRE1", "ADAPT_ORDRE2"):
        adapt_loop(*common, int(scheme[-1]))
    elif scheme == "TRBDF2":
        trbdf2_loop(*common)
    else:
        raise ValueError(scheme)
    return out_q, out_fn


def floor_seconds(scheme: str, problem, n_steps: int, dt: float, repeats: int = 3):
    """(wall, CPU) best seconds of ``n_steps`` of the floor (warm)."""
    run_floor(scheme, problem, 100, dt)
    best = [float("inf"), float("inf")]
    for _ in range(repeats):
        started, cpu = time.perf_counter(), time.process_time()
        run_floor(scheme, problem, n_steps, dt)
        best = [
            min(best[0], time.perf_counter() - started),
            min(best[1], time.process_time() - cpu),
        ]
    return best


def engine_cpu_seconds(
    scheme: str, problem, n_steps: int, dt: float, repeats: int = 3, specialised: bool = True
):
    """Best CPU seconds of asterlite's ``integrate`` (DYNA_VIBRA's entry
    point) for ``scheme`` on the tube, fixed step (PAS_MINI = PAS_MAXI);
    ``specialised=False``: the scheme's general path (shocks in the global
    frame, as for the relations of laws/)."""
    from asterlite.commands.dyna_vibra_problem import catalogue_options

    from asterlite.dynamics.integrate import integrate

    t_end = n_steps * dt
    zeros = np.zeros(T.N_MODES)
    options = replace(catalogue_options(scheme), dt_min=dt, dt_max=dt)
    best = float("inf")
    for _ in range(repeats + 1):  # the first run loads (or compiles) the kernel
        system, shocks, excitation = T.engine_inputs(problem, t_end, dt)
        started = time.process_time()
        integrate(
            system, shocks, excitation, scheme, zeros, zeros, 0.0, t_end, dt,
            np.array([t_end]), 10, options, specialised=specialised,
        )  # fmt: skip
        best = min(best, time.process_time() - started)
    return best


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=200_000)
    parser.add_argument("--dt", type=float, default=1.0e-5)
    parser.add_argument("--engine", action="store_true", help="also asterlite's loop, CPU")
    parser.add_argument(
        "--general", action="store_true", help="--engine: the general path (global frames)"
    )
    parser.add_argument("schemes", nargs="*", default=SCHEMES)
    args = parser.parse_args()
    problem = T.tube_problem()
    for scheme in args.schemes:
        out_q, out_fn = run_floor(scheme, problem, args.steps, args.dt)
        wall, cpu = floor_seconds(scheme, problem, args.steps, args.dt)
        finite = bool(np.isfinite(out_q).all())
        line = (
            f"{scheme:16s} floor wall {1e9 * wall / args.steps:6.0f} ns/step, cpu "
            f"{1e9 * cpu / args.steps:6.0f} ns/step; max F_N {out_fn.max(0).round(2)} "
            f"{'finite' if finite else 'NOT FINITE'}"
        )
        if args.engine:
            engine = engine_cpu_seconds(
                scheme, problem, args.steps, args.dt, specialised=not args.general
            )
            line += (
                f"; asterlite cpu {1e9 * engine / args.steps:6.0f} ns/step ({engine / cpu:.2f}x)"
            )
        print(line)


if __name__ == "__main__":
    main()
