"""NEWMARK on the physical system (code_aster's dlnewi): implicit, the
effective stiffness K + a0 M + a1 C factorised once per distinct step.

    a0 = 1/(β dt²)  a1 = γ/(β dt)  a2 = 1/(β dt)  a3 = 1/(2β) - 1
    a4 = γ/β - 1    a5 = dt/2 (γ/β - 2)   a6 = dt (1 - γ)   a7 = γ dt
    K_eff q_{n+1} = F_{n+1} + M (a0 q + a2 v + a3 a) + C (a1 q + a4 v + a5 a)
    a_{n+1} = a0 (q_{n+1} - q) - a2 v - a3 a,  v_{n+1} = v + a6 a + a7 a_{n+1}
"""

from __future__ import annotations

from asterlite.dynamics.physical.imposed import newmark_states
from asterlite.dynamics.physical.stepping import fixed_step_loop
from asterlite.fem.factorization import definite_solver


def integrate(
    system, times, q, v, a, mask, archive, beta=0.25, gamma=0.5, monitor=None, modal=None
):
    factors = {}
    if system.imposed is not None:
        system.follow_imposed(newmark_states(system.imposed.values(times), times, beta, gamma))

    def operator(dt):
        key = round(dt, 15)
        if key not in factors:
            c = coefficients(dt, beta, gamma)
            factors.clear()  # one factor at a time, refactorised when the step changes (dlnewi)
            # built inside the solver, which keeps only its lower triangle
            factors[key] = (c, definite_solver(lambda: step_matrix(system, c[0], c[1], True)))
        return factors[key]

    def step(dt, force, q, v, a):
        c, solve = operator(dt)
        rhs = force + system.mass @ (c[0] * q + c[2] * v + c[3] * a)
        if system.damping is not None:
            rhs += system.damping @ (c[1] * q + c[4] * v + c[5] * a)
        q_new = solve(rhs)
        a_new = c[0] * (q_new - q) - c[2] * v - c[3] * a
        v_new = v + c[6] * a + c[7] * a_new
        return q_new, v_new, a_new

    fixed_step_loop(system, times, q, v, a, mask, archive, step, monitor, modal)


def step_matrix(system, mass_factor: float, damping_factor: float, release: bool = False):
    """K + mass_factor M + damping_factor C on the reduced unknowns;
    ``release``: the reduced K is let go of once used (the steps read M and
    C only), so that it is not held while the step matrix factorises."""
    matrix = system.reduced_stiffness() + mass_factor * system.mass
    if release:
        system.release_stiffness()
    if system.damping is not None:
        matrix = matrix + damping_factor * system.damping
    return matrix


def coefficients(dt, beta, gamma):
    return (
        1.0 / (beta * dt * dt),
        gamma / (beta * dt),
        1.0 / (beta * dt),
        1.0 / (2.0 * beta) - 1.0,
        gamma / beta - 1.0,
        dt / 2.0 * (gamma / beta - 2.0),
        dt * (1.0 - gamma),
        gamma * dt,
    )
