"""Where asterlite's DIFF_CENTRE loop spends its time on the tube benchmark.

Ablations through the engine entry point (dynamics.integrate.integrate),
each timed as the best of a few warm runs of the same number of steps:

- the full benchmark, archiving every step and every 1000 steps, through
  the specialised DIFF_CENTRE loop and through the general path;
- the force multipliers sampled by windows (a function known only by
  ``evaluate``) instead of FORMULE programs;
- the force multipliers tabulated with 2 points;
- no shocks at all (linear modal system + excitation);
- the shocks only (no excitation), from an initial state in contact.

Run: python benchmarks/profile_engine.py [n_steps]
"""

from __future__ import annotations

import os
import sys
import time

# scipy's BLAS threads (used once by the eigen solver) would otherwise spin
# beside the timed loops on small machines.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np  # noqa: E402
import tube_floor  # noqa: E402
import tube_model as T
from asterlite.commands.dyna_vibra_problem import catalogue_options

from asterlite.dynamics.excitation import Excitation
from asterlite.dynamics.integrate import integrate
from asterlite.dynamics.model import ShockSet


def best_of(function, repeats=5) -> float:
    times = []
    for _ in range(repeats):
        started = time.perf_counter()
        function()
        times.append(time.perf_counter() - started)
    return min(times)


def integrate_with(system, shocks, excitation, n_steps, dt, pas_arch, q0=None, specialised=True):
    n = system.n_modes
    t_end = n_steps * dt
    q0 = np.zeros(n) if q0 is None else q0
    return integrate(
        system,
        shocks,
        excitation,
        "DIFF_CENTRE",
        q0,
        np.zeros(n),
        0.0,
        t_end,
        dt,
        np.array([t_end]),
        pas_arch,
        catalogue_options("DIFF_CENTRE"),
        specialised=specialised,
    )


def two_point_excitation(problem, t_end) -> Excitation:
    """The same vectors with multipliers known at 2 points only (cheap lookup)."""
    vectors = np.array([problem.force_y, problem.force_z])
    abscissas = np.array([[0.0, t_end], [0.0, t_end]])
    ordinates = np.array([[0.0, 1.0], [1.0, 0.0]]) * T.FORCE_AMPLITUDE
    layout = np.array([[2, 0, 0], [2, 0, 0]], dtype=np.int64)
    return Excitation(vectors, abscissas, ordinates, layout)


def no_shocks(shocks) -> ShockSet:
    return ShockSet(
        [],
        shocks.flags[:0].copy(),
        shocks.params[:0].copy(),
        shocks.rots[:0].copy(),
        shocks.phis[:0].copy(),
        shocks.polars[:0].copy(),
    )


def no_excitation(n_modes) -> Excitation:
    return Excitation(
        np.zeros((0, n_modes)), np.zeros((0, 1)), np.zeros((0, 1)), np.zeros((0, 3), np.int64)
    )


def main() -> None:
    n_steps = int(sys.argv[1]) if len(sys.argv) > 1 else 200_000
    problem = T.tube_problem()
    dt = T.stable_step(problem)
    t_end = n_steps * dt
    system, shocks, excitation = T.engine_inputs(problem, t_end, dt)
    n = system.n_modes
    # a displaced state pressing the mid support (to time the shock law in contact)
    pressed = np.linalg.lstsq(problem.phi_supports[1], np.array([0.0, 1.5 * T.GAP, 0.0]))[0]

    cases = {
        "full benchmark, PAS_ARCH=1": lambda: integrate_with(
            system, shocks, excitation, n_steps, dt, 1
        ),
        "full benchmark, PAS_ARCH=1000": lambda: integrate_with(
            system, shocks, excitation, n_steps, dt, 1000
        ),
        "general path, PAS_ARCH=1000": lambda: integrate_with(
            system, shocks, excitation, n_steps, dt, 1000, specialised=False
        ),
        "multipliers sampled by windows": lambda: integrate_with(
            system, shocks, T.engine_inputs(problem, t_end, dt, "sampled")[2], n_steps, dt, 1000
        ),
        "2-point multipliers, PAS_ARCH=1000": lambda: integrate_with(
            system, shocks, two_point_excitation(problem, t_end), n_steps, dt, 1000
        ),
        "no shocks, PAS_ARCH=1000": lambda: integrate_with(
            system, no_shocks(shocks), excitation, n_steps, dt, 1000
        ),
        "no shocks, 2-point multipliers": lambda: integrate_with(
            system, no_shocks(shocks), two_point_excitation(problem, t_end), n_steps, dt, 1000
        ),
        "no shocks, no excitation": lambda: integrate_with(
            system, no_shocks(shocks), no_excitation(n), n_steps, dt, 1000
        ),
        "shocks only (no excitation)": lambda: integrate_with(
            system, shocks, no_excitation(n), n_steps, dt, 1000, q0=pressed
        ),
        "floor (hand-written loop)": lambda: tube_floor.run_floor(problem, n_steps, dt, 1000),
    }
    for function in cases.values():
        function()  # JIT / cache load
    print(f"{n_steps} DIFF_CENTRE steps of the tube benchmark ({n} modes, 3 shocks), best of 5")
    for name, function in cases.items():
        seconds = best_of(function)
        print(f"  {name:<38} {seconds:8.4f} s  {1e9 * seconds / n_steps:7.0f} ns/step")


if __name__ == "__main__":
    main()
