"""The practical floor: the tube benchmark as one hand-written numba loop.

DIFF_CENTRE (v += dt a, q += dt v, a from the equations of motion) on a
diagonal modal system, three CERCLE supports whose local frame is the
global one (NORM_OBST = X, ORIG_OBST at the node), the shock law of
asterlite.dynamics.contact written out for that case only, the force
evaluated with sin/cos. No generality, no dispatch, no archiving logic
beyond "every pas_arch steps".
"""

from __future__ import annotations

import math

import numpy as np
import tube_model as T
from numba import njit

SLIP_VELOCITY_FLOOR = 1.0e-6
EPS = np.finfo(np.float64).eps


@njit(cache=True, fastmath=False)
def floor_loop(
    n_steps, dt, stiffness, damping, phi, force_y, force_z, f0, w, params, pas_arch, out_q, out_fn
):
    """params: gap, k_n, c_n, k_t, c_t, mu. Returns (q, v, max normal force per support)."""
    gap0, k_n, c_n, k_t, c_t, mu = params[0], params[1], params[2], params[3], params[4], params[5]
    n = stiffness.shape[0]
    ns = phi.shape[0]
    q, v, a, f = np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n)
    # friction memory per support: sticking flag, F_ref (2), x_ref (3), v_t old (2)
    stick = np.zeros(ns)
    f_ref = np.zeros((ns, 2))
    x_ref = np.zeros((ns, 3))
    vt_old = np.zeros((ns, 2))
    fn_max = np.zeros(ns)
    fn_now = np.zeros(ns)
    for i in range(n):  # initial acceleration at rest: the force at t = 0
        a[i] = f0 * (math.sin(0.0) * force_y[i] + math.cos(0.0) * force_z[i])
    for step in range(1, n_steps + 1):
        t = step * dt
        for i in range(n):
            v[i] += dt * a[i]
            q[i] += dt * v[i]
        sy, cy = f0 * math.sin(w * t), f0 * math.cos(w * t)
        for i in range(n):
            f[i] = sy * force_y[i] + cy * force_z[i]
        for s in range(ns):
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
            fn = 0.0
            if gap <= 0.0:
                cos_n, sin_n = -y / r, -z / r
                vn = vy * cos_n + vz * sin_n
                fn = max(0.0, -k_n * gap - c_n * vn)
                vt1 = -sin_n * vy + cos_n * vz
                vt2 = vx
                vnorm = math.sqrt(vt1 * vt1 + vt2 * vt2)
                same = vt1 * vt_old[s, 0] + vt2 * vt_old[s, 1] >= 0.0
                if same and stick[s] == 0.0 and vnorm > SLIP_VELOCITY_FLOOR:
                    ft1 = -mu * fn * vt1 / vnorm
                    ft2 = -mu * fn * vt2 / vnorm
                    f_ref[s, 0], f_ref[s, 1] = ft1, ft2
                    x_ref[s, 0], x_ref[s, 1], x_ref[s, 2] = x, y, z
                else:
                    dx1 = -(y - x_ref[s, 1]) * sin_n + (z - x_ref[s, 2]) * cos_n
                    dx2 = x - x_ref[s, 0]
                    stick[s] = 1.0
                    ft1 = f_ref[s, 0] - k_t * dx1 - c_t * vt1
                    ft2 = f_ref[s, 1] - k_t * dx2 - c_t * vt2
                    if math.sqrt(ft1 * ft1 + ft2 * ft2) > mu * fn:
                        stick[s] = 0.0
                        if vnorm <= EPS:
                            ft1, ft2 = 0.0, 0.0
                        else:
                            ft1 = -mu * fn * vt1 / vnorm
                            ft2 = -mu * fn * vt2 / vnorm
                        f_ref[s, 0], f_ref[s, 1] = ft1, ft2
                        x_ref[s, 0], x_ref[s, 1], x_ref[s, 2] = x, y, z
                vt_old[s, 0], vt_old[s, 1] = vt1, vt2
                gx = ft2
                gy = fn * cos_n - ft1 * sin_n
                gz = fn * sin_n + ft1 * cos_n
                for m in range(n):
                    f[m] += phi[s, 0, m] * gx + phi[s, 1, m] * gy + phi[s, 2, m] * gz
                if fn > fn_max[s]:
                    fn_max[s] = fn
            else:
                stick[s] = 0.0
                f_ref[s, 0] = f_ref[s, 1] = 0.0
                vt_old[s, 0] = vt_old[s, 1] = 0.0
                x_ref[s, 0], x_ref[s, 1], x_ref[s, 2] = x, y, z
            fn_now[s] = fn
        for i in range(n):
            a[i] = f[i] - stiffness[i] * q[i] - damping[i] * v[i]  # unit modal masses
        if step % pas_arch == 0:
            k = step // pas_arch
            if k < out_q.shape[0]:
                out_q[k] = q
                out_fn[k] = fn_now
    return q, v, fn_max


def run_floor(problem: T.TubeProblem, n_steps: int, dt: float, pas_arch: int = 1):
    """(final q, final v, max FN per support, archived q, archived FN)."""
    params = np.array([T.GAP, T.K_NORMAL, T.C_NORMAL, T.K_TANGENT, T.C_TANGENT, T.MU])
    n_archived = n_steps // pas_arch + 1
    out_q = np.zeros((n_archived, T.N_MODES))
    out_fn = np.zeros((n_archived, len(T.SUPPORT_NODES)))
    q, v, fn_max = floor_loop(
        n_steps,
        dt,
        problem.stiffness,
        problem.damping,
        np.ascontiguousarray(problem.phi_supports),
        problem.force_y,
        problem.force_z,
        T.FORCE_AMPLITUDE,
        problem.forcing_omega,
        params,
        pas_arch,
        out_q,
        out_fn,
    )
    return q, v, fn_max, out_q, out_fn
