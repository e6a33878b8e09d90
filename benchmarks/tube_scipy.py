"""The tube benchmark integrated by scipy.integrate.solve_ivp (RK45).

The state is y = (q, v) on the unit-mass modal basis; the right-hand side
is plain Python/numpy: modal damping and stiffness, the turning force, and
the three CERCLE supports with the shock law of asterlite.dynamics.contact
(penalised normal force, incremental tangential force capped by Coulomb).
The friction memory (stick reference, last tangential velocity) is
history: the right-hand side reads the memory committed at the last
accepted step and never changes it, and the driver commits it after each
accepted step. The driver is solve_ivp's own loop (``RK45(...).step()``
until the end, as ``solve_ivp(method='RK45')`` runs it) plus that commit;
solve_ivp itself gives no hook between steps, and updating the memory at
every evaluation (trial stages, rejected steps) made the result change by
several percent with the last digit of t_end.
"""

from __future__ import annotations

import math

import numpy as np
import tube_model as T
from scipy.integrate import RK45

SLIP_VELOCITY_FLOOR = 1.0e-6
EPS = np.finfo(np.float64).eps


class TubeRightHandSide:
    def __init__(self, problem: T.TubeProblem) -> None:
        self.problem = problem
        self.n = T.N_MODES
        self.phi = problem.phi_supports  # (3 supports, 3 components, n)
        n_supports = self.phi.shape[0]
        self.stick = np.zeros(n_supports, dtype=bool)
        self.f_ref = np.zeros((n_supports, 2))
        self.x_ref = np.zeros((n_supports, 3))
        self.vt_old = np.zeros((n_supports, 2))
        self.fn_max = np.zeros(n_supports)
        self.calls = 0
        self.committing = False

    def commit(self, t: float, y: np.ndarray) -> None:
        """Advance the friction memory to an accepted state."""
        self.committing = True
        self.__call__(t, y)
        self.committing = False

    def __call__(self, t: float, y: np.ndarray) -> np.ndarray:
        self.calls += 1
        if not self.committing:  # trial evaluation: work on a copy of the memory
            saved = (self.stick.copy(), self.f_ref.copy(), self.x_ref.copy(), self.vt_old.copy())
        p = self.problem
        q, v = y[: self.n], y[self.n :]
        w = p.forcing_omega
        force = T.FORCE_AMPLITUDE * (math.sin(w * t) * p.force_y + math.cos(w * t) * p.force_z)
        for s in range(self.phi.shape[0]):
            local_force = self.support_force(s, self.phi[s] @ q, self.phi[s] @ v)
            if local_force is not None:
                force += self.phi[s].T @ local_force
        acceleration = force - p.stiffness * q - p.damping * v
        if not self.committing:
            self.stick, self.f_ref, self.x_ref, self.vt_old = saved
        return np.concatenate([v, acceleration])

    def support_force(self, s: int, loc: np.ndarray, vel: np.ndarray):
        """Local force (x, y, z) of the obstacle on the node, or None out of contact."""
        r = math.hypot(loc[1], loc[2])
        gap = T.GAP - r
        if gap > 0.0:
            self.stick[s] = False
            self.f_ref[s] = 0.0
            self.vt_old[s] = 0.0
            self.x_ref[s] = loc
            return None
        cos_n, sin_n = -loc[1] / r, -loc[2] / r
        vn = vel[1] * cos_n + vel[2] * sin_n
        fn = max(0.0, -T.K_NORMAL * gap - T.C_NORMAL * vn)
        if self.committing:
            self.fn_max[s] = max(self.fn_max[s], fn)
        vt = np.array([-sin_n * vel[1] + cos_n * vel[2], vel[0]])
        vnorm = math.hypot(vt[0], vt[1])
        same_direction = vt @ self.vt_old[s] >= 0.0
        if same_direction and not self.stick[s] and vnorm > SLIP_VELOCITY_FLOOR:
            ft = -T.MU * fn * vt / vnorm
            self.f_ref[s], self.x_ref[s] = ft, loc
        else:
            d = loc - self.x_ref[s]
            dx = np.array([-d[1] * sin_n + d[2] * cos_n, d[0]])
            self.stick[s] = True
            ft = self.f_ref[s] - T.K_TANGENT * dx - T.C_TANGENT * vt
            if math.hypot(ft[0], ft[1]) > T.MU * fn:
                self.stick[s] = False
                ft = np.zeros(2) if vnorm <= EPS else -T.MU * fn * vt / vnorm
                self.f_ref[s], self.x_ref[s] = ft, loc
        self.vt_old[s] = vt
        return np.array([ft[1], fn * cos_n - ft[0] * sin_n, fn * sin_n + ft[0] * cos_n])


def run_solve_ivp(problem: T.TubeProblem, t_end: float, rtol: float, atol: float):
    """(times, final state y, right-hand side object): RK45 from rest over
    [0, t_end]. ``rhs.fn_max``: max normal force per support at accepted steps."""
    rhs = TubeRightHandSide(problem)
    solver = RK45(rhs, 0.0, np.zeros(2 * T.N_MODES), t_end, rtol=rtol, atol=atol)
    times = [0.0]
    while solver.status == "running":
        message = solver.step()
        if solver.status == "failed":
            raise RuntimeError(f"RK45 failed at t={solver.t}: {message}")
        rhs.commit(solver.t, solver.y)
        times.append(solver.t)
    return np.array(times), solver.y, rhs
