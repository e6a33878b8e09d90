"""WILSON θ on the physical system: the linear acceleration assumption
over the extended step θ dt (θ = 1.4 by default), implicit, the effective
stiffness K + 6/(θdt)² M + 3/(θdt) C factorised once per distinct step.
The load at t + θ dt is extrapolated linearly from F_n and F_{n+1}."""

from __future__ import annotations

from asterlite.dynamics.physical.newmark import step_matrix
from asterlite.dynamics.physical.stepping import fixed_step_loop
from asterlite.fem.factorization import definite_solver


def integrate(system, times, q, v, a, mask, archive, theta=1.4, modal=None):
    factors = {}
    previous_force = {"F": None}

    def operator(dt):
        key = round(dt, 15)
        if key not in factors:
            tau = theta * dt
            factors.clear()  # one factor at a time, refactorised when the step changes
            # built inside the solver, which keeps only its lower triangle
            mass_factor, damping_factor = 6.0 / tau**2, 3.0 / tau
            factors[key] = definite_solver(
                lambda: step_matrix(system, mass_factor, damping_factor, True)
            )
        return factors[key]

    def step(dt, force, q, v, a):
        solve = operator(dt)
        tau = theta * dt
        f_old = previous_force["F"]
        if f_old is None:
            f_old = system.forces([times[0]])[0]
        rhs = f_old + theta * (force - f_old)
        rhs = rhs + system.mass @ ((6.0 / tau**2) * q + (6.0 / tau) * v + 2.0 * a)
        if system.damping is not None:
            rhs += system.damping @ ((3.0 / tau) * q + 2.0 * v + (tau / 2.0) * a)
        q_theta = solve(rhs)
        a_new = (
            6.0 / (theta**3 * dt**2) * (q_theta - q)
            - 6.0 / (theta**2 * dt) * v
            + (1.0 - 3.0 / theta) * a
        )
        v_new = v + dt / 2.0 * (a_new + a)
        q_new = q + dt * v + dt**2 / 6.0 * (a_new + 2.0 * a)
        previous_force["F"] = force
        return q_new, v_new, a_new

    fixed_step_loop(system, times, q, v, a, mask, archive, step, modal=modal)
