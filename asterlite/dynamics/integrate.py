"""Driver of a transient run: initial state, scheme set-up, compiled loop,
buffer growth, and translation of kernel status codes into errors."""

from __future__ import annotations

import math
import time as wallclock
from dataclasses import dataclass, field

import numpy as np

from asterlite.dynamics import (
    adapt_control,
    scheme_adapt_ordre1,
    scheme_adapt_ordre2,
    scheme_devoge,
    scheme_diff_centre,
    scheme_newmark,
    scheme_rk32,
    scheme_rk54,
    scheme_trbdf2,
)
from asterlite.dynamics import kernel as K
from asterlite.dynamics.contact import N_VINT
from asterlite.dynamics.forces import acceleration, total_force
from asterlite.dynamics.model import Excitation, LinearSystem, ShockSet, local_bundle
from asterlite.errors import NumericalError

# Each scheme module offers prepare(system, dt, options) -> (memory, adaptive)
# and a compiled run_loop calling its own step function.
SCHEMES = {
    "DIFF_CENTRE": scheme_diff_centre,
    "DEVOGE": scheme_devoge,
    "NEWMARK": scheme_newmark,
    "RUNGE_KUTTA_32": scheme_rk32,
    "RUNGE_KUTTA_54": scheme_rk54,
    "ADAPT_ORDRE1": scheme_adapt_ordre1,
    "ADAPT_ORDRE2": scheme_adapt_ordre2,
    "TRBDF2": scheme_trbdf2,
    # asterlite extension for legacy decks: code_aster 10's EULER (mdeul1,
    # v += dt a_n then q += dt v) is the arithmetic code_aster 14+ runs as the
    # GENE DIFF_CENTRE (dtmprep maps it to its Euler routine), so one module serves
    "EULER": scheme_diff_centre,
}
ADAPTIVE_FAMILY = ("RUNGE_KUTTA_32", "RUNGE_KUTTA_54", "ADAPT_ORDRE1", "ADAPT_ORDRE2", "DEVOGE")


@dataclass
class SchemeOptions:
    """SCHEMA_TEMPS parameters (code_aster 17 defaults)."""

    tolerance: float = 1.0e-5
    alpha: float = 0.0
    dt_min: float | None = None
    dt_max: float | None = None
    beta: float = 0.25
    gamma: float = 0.5
    nmax_iter_pas: int = 16
    vite_min: str = "NORM"
    coef_mult_pas: float = 1.1
    coef_divi_pas: float = 1.3333334
    pas_limi_rela: float = 1.0e-6
    nb_poin_periode: int = 50


@dataclass
class RunResult:
    times: np.ndarray
    order: np.ndarray
    depl: np.ndarray
    vite: np.ndarray
    acce: np.ndarray
    vint: np.ndarray  # (n_archived, n_shocks, N_VINT)
    info: dict = field(default_factory=dict)


def integrate(
    system: LinearSystem,
    shocks: ShockSet,
    excitation: Excitation,
    scheme: str,
    q0: np.ndarray,
    v0: np.ndarray,
    t0: float,
    t_end: float,
    dt: float,
    instants: np.ndarray,
    pas_arch: int,
    options: SchemeOptions | None = None,
    specialised: bool = True,
    rotation=None,
) -> RunResult:
    """Integrate from t0 to t_end. ``specialised=False`` runs a scheme's
    ``general_loop`` when it has one (DIFF_CENTRE: the general path, same
    results as its specialised ``run_loop``; kept for comparison)."""
    options = options or SchemeOptions()
    n = system.n_modes
    module = SCHEMES[scheme]
    model = (system.bundle(), shocks.bundle(), excitation.bundle())
    if hasattr(module, "general_loop"):  # a specialised run_loop: its local arrays
        model = model + (local_bundle(system, shocks),)
    q, v = np.array(q0, dtype=float), np.array(v0, dtype=float)
    f, a = np.zeros(n), np.zeros(n)
    vint = shocks.initial_vint(t0)
    work = np.zeros((5, 3))
    shock = total_force(t0, q, v, model[1], vint, model[2], work, f)
    acceleration(f, q, v, model[0], np.zeros(n), a)
    if shock >= 0 or not np.all(np.isfinite(a)):
        raise law_error(shocks, vint, t0) or NumericalError(
            f"non-finite initial acceleration at t={t0:g}"
        )
    state = (q, v, a, f, vint, np.zeros_like(vint), work)

    memory, _ = module.prepare(system, dt, options)
    rotating_loop = None
    if rotation is not None:  # VITESSE_VARIABLE='OUI': matrices updated every step
        from asterlite.dynamics import rotation as R

        memory, rotating_loop = R.prepare(scheme, memory, rotation)
        if rotation.initial_acceleration is not None:  # a restart keeps its acceleration
            a[:] = rotation.initial_acceleration
    adaptive = loop_adapts(scheme, dt, options)
    eps = 10.0 * np.finfo(float).eps
    instants = np.asarray(instants, dtype=float)
    n_steps = max(1, int(round((t_end - t0) / dt)))
    capacity = 2 + len(instants) + n_steps // max(pas_arch, 1)
    if adaptive:
        capacity = min(capacity, 4096)
    buffers = new_buffers(capacity, n, shocks.count, shocks.vint_width)
    K.archive(0, t0, 0, q, v, a, vint, *buffers)
    clock, counters = K.new_clock(t0, dt, t_end), K.new_counters(adaptive)
    counters[K.K_ARCHIVED] = 1
    run_loop = module.run_loop
    if not specialised or shocks.has_laws:  # other relations: the general path
        run_loop = getattr(module, "general_loop", module.run_loop)
    if rotating_loop is not None:
        run_loop = rotating_loop
    started = wallclock.perf_counter()
    while True:
        status = run_loop(clock, counters, state, memory, model, instants, pas_arch, eps, buffers)
        if status == K.STATUS_FULL:
            buffers = grow(buffers)
        elif status == K.STATUS_LOADS:  # next window of the sampled multipliers
            excitation.refill(clock[K.C_TIME], clock[K.C_STEP])
            model = (model[0], model[1], excitation.bundle()) + model[3:]
        else:
            break
    elapsed = wallclock.perf_counter() - started
    if status != K.STATUS_DONE:
        failed = law_error(shocks, vint, clock[K.C_TIME] + clock[K.C_STEP])
        raise failed or divergence_error(status, clock, counters, shocks, system, scheme)
    count = counters[K.K_ARCHIVED]
    out_t, out_order, out_q, out_v, out_a, out_vint = (b[:count].copy() for b in buffers)
    steps = int(counters[K.K_STEP])
    info = {
        "steps": steps,
        "rejected_steps": int(counters[K.K_REJECTED]),
        "archived": int(count),
        "integration_seconds": elapsed,
        "initial_step": dt,
        "adaptive": adaptive,
        "min_step": float(clock[K.C_MIN_STEP]) if steps else dt,
        "max_step": float(clock[K.C_MAX_STEP]) if steps else dt,
        "mean_step": (float(clock[K.C_TIME]) - t0) / steps if steps else dt,
        "last_step": float(clock[K.C_STEP]),
    }
    if scheme in ("ADAPT_ORDRE1", "ADAPT_ORDRE2"):
        kept = int(memory[1][adapt_control.S_KEPT_AT_MAX_TRIALS])
        info["steps_kept_at_nmax_iter_pas"] = kept
    return RunResult(out_t, out_order, out_q, out_v, out_a, out_vint, info)


def loop_adapts(scheme: str, dt: float, options: SchemeOptions) -> bool:
    """Whether the time loop follows the step proposed by the scheme
    (code_aster's dtmprep: adaptive families with PAS_MINI != PAS_MAXI,
    defaults 1e-6 and 1e6 times PAS)."""
    if scheme not in ADAPTIVE_FAMILY:
        return False
    dt_min = options.dt_min if options.dt_min is not None else 1.0e-6 * dt
    dt_max = options.dt_max if options.dt_max is not None else 1.0e6 * dt
    return abs(dt_max / dt_min - 1.0) > 100.0 * np.finfo(float).eps


def new_buffers(capacity: int, n_modes: int, n_shocks: int, width: int = N_VINT):
    return (
        np.zeros(capacity),
        np.zeros(capacity, dtype=np.int64),
        np.zeros((capacity, n_modes)),
        np.zeros((capacity, n_modes)),
        np.zeros((capacity, n_modes)),
        np.zeros((capacity, n_shocks, width)),
    )


def law_error(shocks: ShockSet, vint: np.ndarray, t: float) -> NumericalError | None:
    """The error naming a nonlinearity of laws/ whose evaluation failed
    (NaN in its internal variables), or None."""
    from asterlite.dynamics.laws.kernel import failed_law

    s = failed_law(shocks.flags, vint)
    if s < 0:
        return None
    spec = shocks.specs[s]
    return NumericalError(
        f"COMPORTEMENT {spec.relation} {spec.name.strip()!r} (node {spec.node_1}) could not be "
        f"evaluated at t={t:.6g}: a function was evaluated outside its domain "
        "(PROL_GAUCHE/PROL_DROITE='EXCLU') or the local integration did not converge "
        "(ITER_INTE_MAXI, RESI_INTE)"
    )


def grow(buffers):
    return tuple(np.concatenate([b, np.zeros_like(b)]) for b in buffers)


def divergence_error(status, clock, counters, shocks: ShockSet, system: LinearSystem, scheme: str):
    t = clock[K.C_TIME]
    dt = clock[K.C_STEP]
    shock = counters[K.K_SHOCK]
    if status == K.STATUS_SHOCK_DIVERGED and 0 <= shock < shocks.count:
        where = f" at shock {shocks.specs[shock].name} (node {shocks.specs[shock].node_1})"
    elif shocks.count:
        where = " (shocks: " + ", ".join(s.name for s in shocks.specs) + ")"
    else:
        where = ""
    from asterlite.dynamics.model import stability_period

    suggested = stability_period(system, shocks) / 20.0
    what = {
        K.STATUS_NOT_FINITE: "the solution became non-finite",
        K.STATUS_SHOCK_DIVERGED: "relative velocity at a shock diverged",
        K.STATUS_STEP_UNDERFLOW: "the adaptive step fell below PAS_MINI",
    }.get(status, f"integration failed (status {status})")
    return NumericalError(
        f"{scheme}: {what} at t={t:.6g}{where} with step {dt:.3g}; "
        f"try PAS <= {suggested:.3g} (1/20 of the shortest period including shock stiffness)"
    )


def suggested_step(system: LinearSystem, shocks: ShockSet, scheme: str) -> float:
    from asterlite.dynamics.model import stability_period

    fraction = 10.0 if scheme in ("DEVOGE", "NEWMARK") else 20.0
    return stability_period(system, shocks) / fraction


__all__ = ["integrate", "RunResult", "SchemeOptions", "SCHEMES", "suggested_step", "math"]
