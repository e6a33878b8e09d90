"""The tube benchmark: asterlite's compiled DIFF_CENTRE loop against
scipy's solve_ivp and against a hand-written numba loop (the floor).

Prints
  (a) asterlite's integration time and steps per second (engine entry point
      asterlite.dynamics.integrate.integrate, the call DYNA_VIBRA makes;
      warm, best of a few runs) and the cold-process start-up (compiled
      kernels loaded from numba's cache);
  (b) solve_ivp (RK45, right-hand side in Python/numpy) on a shorter
      window, extrapolated per simulated second, its accuracy beside
      asterlite's against a fine-step reference, and the speed ratio;
  (c) the floor (tube_floor.py) and the ratio;
  (d) peak memory of 10^7 steps with PAS_ARCH=1000 (a fresh process).

Targets: asterlite >= 100x faster than solve_ivp, within 3x of the floor.

Run: python benchmarks/tube_benchmark.py [--steps N] [--ivp-window S] [--skip-memory]
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import time
from pathlib import Path

# scipy's BLAS threads (used once by the eigen solver) would otherwise spin
# beside the timed loops on small machines.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np  # noqa: E402
import tube_floor  # noqa: E402
import tube_model as T  # noqa: E402
import tube_scipy  # noqa: E402

HERE = Path(__file__).resolve().parent
ACCURACY_WINDOW = 0.05  # s: trajectories still comparable point by point (stick-slip)
IVP_RTOL, IVP_ATOL = 1.0e-5, 1.0e-9
REFERENCE_REFINEMENT = 100  # reference: the floor loop with dt / 100


def best_time(function, repeats: int) -> float:
    best = float("inf")
    for _ in range(repeats):
        started = time.perf_counter()
        function()
        best = min(best, time.perf_counter() - started)
    return best


def cold_start_seconds(n_runs: int = 2) -> list[float]:
    """Fresh processes: import asterlite + load the compiled kernels from the
    cache + a 10-step run (everything but the model set-up)."""
    code = (
        f"import time, sys; sys.path.insert(0, {str(HERE)!r})\n"
        "import tube_model as T\n"
        "p = T.tube_problem(); dt = T.stable_step(p)\n"
        "t = time.perf_counter(); T.run_engine(p, 10, dt, 1)\n"
        "print(time.perf_counter() - t)\n"
    )
    times = []
    for _ in range(n_runs):
        out = subprocess.run(
            [sys.executable, "-c", code], capture_output=True, text=True, check=True
        )
        times.append(float(out.stdout.strip().splitlines()[-1]))
    return times


def midspan_displacement(problem, q) -> np.ndarray:
    return problem.phi_supports[1] @ q


def accuracy_table(problem, dt) -> None:
    """Max FN per support and mid-span (DY, DZ) at the end of a short window,
    each method against the floor loop with dt / REFERENCE_REFINEMENT."""
    n = int(round(ACCURACY_WINDOW / dt))
    fine = REFERENCE_REFINEMENT
    ref_q, _, ref_fn, _, _ = tube_floor.run_floor(problem, n * fine, dt / fine, fine)
    engine = T.run_engine(problem, n, dt, 1)
    _, y_end, rhs = tube_scipy.run_solve_ivp(problem, n * dt, IVP_RTOL, IVP_ATOL)
    rows = [
        (f"reference (floor, dt/{fine})", ref_fn, midspan_displacement(problem, ref_q)),
        (
            "asterlite DIFF_CENTRE",
            engine.vint[:, :, 0].max(0),
            midspan_displacement(problem, engine.depl[-1]),
        ),
        (
            f"solve_ivp RK45 rtol={IVP_RTOL:g}",
            rhs.fn_max,
            midspan_displacement(problem, y_end[: T.N_MODES]),
        ),
    ]
    print(f"  accuracy over the first {ACCURACY_WINDOW} s ({n} steps), from rest:")
    print(f"    {'':34} {'max FN per support (N)':>28}   {'mid-span DY, DZ at end (um)':>28}")
    ref_d = rows[0][2]
    for name, fn, d in rows:
        fn_text = " ".join(f"{x:8.4f}" for x in fn)
        err = (
            ""
            if name.startswith("reference")
            else (
                f"  (FN err {100 * np.max(np.abs(fn - ref_fn) / ref_fn):.2f}%, "
                f"disp err {1e6 * np.max(np.abs(d[1:] - ref_d[1:])):.2f} um)"
            )
        )
        print(f"    {name:34} {fn_text:>28}   {1e6 * d[1]:12.3f} {1e6 * d[2]:12.3f}{err}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=200_000)
    parser.add_argument(
        "--ivp-window", type=float, default=0.05, help="seconds simulated by solve_ivp"
    )
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--skip-memory", action="store_true")
    args = parser.parse_args()

    # memory first, in a fresh process, while this one is still small
    multipliers = ("formula", "sampled", "table")
    memory_lines = [] if args.skip_memory else [memory_run(m) for m in multipliers]
    problem = T.tube_problem()
    dt = T.stable_step(problem)
    n_steps = args.steps
    t_end = n_steps * dt
    print("Tube benchmark: clamped tube, 40 POU_D_E, 20 modes, 3 CERCLE supports with friction")
    analytic = T.clamped_clamped_frequencies(3)
    print(
        f"  frequencies (Hz): {' '.join(f'{f:.3f}' for f in problem.frequencies[:6])} ... "
        f"{problem.frequencies[-1]:.1f}; analytic bending: {' '.join(f'{f:.3f}' for f in analytic)}"
    )
    print(
        f"  DIFF_CENTRE dt = {dt:g} s, {n_steps} steps = {t_end:g} s simulated; force "
        f"{T.FORCE_AMPLITUDE:g} N turning at {problem.forcing_omega / 2 / np.pi:.3f} Hz"
    )

    # (a) asterlite
    cold = cold_start_seconds()
    T.run_engine(problem, 100, dt, 1000)  # warm-up in this process
    engine_results = []

    def run_engine(pas_arch):
        result = T.run_engine(problem, n_steps, dt, pas_arch)
        engine_results[:] = [result]  # keep one: PAS_ARCH=1 archives ~200 MB
        return result.info["integration_seconds"]

    def best_engine(pas_arch):
        return min(run_engine(pas_arch) for _ in range(args.repeats))

    floor_seconds = float("inf")
    engine_seconds = float("inf")
    for _ in range(args.repeats):  # interleaved: both see the same machine load
        engine_seconds = min(engine_seconds, run_engine(1000))
        floor_seconds = min(
            floor_seconds, best_time(lambda: tube_floor.run_floor(problem, n_steps, dt, 1000), 1)
        )
    engine_every_step = best_engine(1)
    last = engine_results[-1]
    fn = last.vint[:, :, 0]
    print(
        "\n(a) asterlite (dynamics.integrate.integrate, DIFF_CENTRE), warm, best of", args.repeats
    )
    print(
        f"  PAS_ARCH=1000: {engine_seconds:.3f} s  {n_steps / engine_seconds:,.0f} steps/s  "
        f"{1e9 * engine_seconds / n_steps:.0f} ns/step"
    )
    print(f"  PAS_ARCH=1:    {engine_every_step:.3f} s  {n_steps / engine_every_step:,.0f} steps/s")
    print(
        f"  cold process (import + cached kernels load + 10 steps): "
        f"{', '.join(f'{c:.2f} s' for c in cold)}"
    )
    print(
        f"  max FN per support over the run: {' '.join(f'{x:.2f}' for x in fn.max(0))} N; "
        f"time in contact: {' '.join(f'{100 * x:.1f}%' for x in (fn > 0).mean(0))}"
    )

    # (b) solve_ivp
    window = args.ivp_window
    started = time.perf_counter()
    ivp_times, _, rhs = tube_scipy.run_solve_ivp(problem, window, IVP_RTOL, IVP_ATOL)
    ivp_seconds = time.perf_counter() - started
    ivp_per_second = ivp_seconds / window
    engine_per_second = engine_seconds / t_end
    print(
        f"\n(b) scipy RK45 (solve_ivp's solver and step loop, rtol={IVP_RTOL:g}, "
        f"atol={IVP_ATOL:g}), Python right-hand side"
    )
    print(
        f"  {window:g} s simulated in {ivp_seconds:.2f} s ({len(ivp_times) - 1} steps, "
        f"{rhs.calls} evaluations): {ivp_per_second:.2f} s per simulated second (extrapolated)"
    )
    print(f"  asterlite: {engine_per_second:.4f} s per simulated second")
    speedup = ivp_per_second / engine_per_second
    print(f"  ratio solve_ivp / asterlite: {speedup:,.0f}x  (target >= 100x)")
    accuracy_table(problem, dt)

    # (c) floor
    ratio = engine_seconds / floor_seconds
    print("\n(c) floor: hand-written numba loop (DIFF_CENTRE + 3 CERCLE shocks with friction)")
    print(
        f"  {floor_seconds:.3f} s  {n_steps / floor_seconds:,.0f} steps/s  "
        f"{1e9 * floor_seconds / n_steps:.0f} ns/step"
    )
    print(f"  ratio asterlite / floor: {ratio:.1f}x  (target <= 3x)")

    # (d) memory
    if not args.skip_memory:
        print("\n(d) memory: 10^7 steps, PAS_ARCH=1000, fresh process")
        print("\n".join(memory_lines))


def memory_run(multiplier: str) -> str:
    out = subprocess.run(
        [sys.executable, str(HERE / "tube_memory.py"), "10000000", "1000", multiplier],
        capture_output=True,
        text=True,
        check=True,
    )
    values = dict(item.split("=") for item in out.stdout.split())
    peak = float(values["peak_rss_mb"])
    what = {
        "formula": "force multipliers as FORMULE (compiled, evaluated at each step)",
        "sampled": "force multipliers known by evaluate() only (sampled every dt/2 by windows)",
        "table": "force multipliers as DEFI_FONCTION (64 points/period)",
    }[multiplier]
    return (
        f"  {what}:\n"
        f"    {values['archived']} instants archived; peak RSS {values['rss_before_mb']} MB "
        f"before the run, {peak:.0f} MB after ({'under' if peak < 1024 else 'OVER'} 1 GB); "
        f"integration {values['integration_s']} s, wall {values['wall_s']} s"
    )


if __name__ == "__main__":
    main()
