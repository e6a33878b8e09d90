"""Driver of a transient run: initial state, scheme set-up, compiled loop,
buffer growth, and translation of kernel status codes into errors."""

from __future__ import annotations

import functools
import math
import time as wallclock
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from asterlite import progress, watchdog
from asterlite.dynamics import adapt_control, compile_estimate, diagnosis, native
from asterlite.dynamics import contact as C
from asterlite.dynamics import energy as E
from asterlite.dynamics import kernel as K
from asterlite.dynamics.archive_store import ArchiveStore, memory_budget
from asterlite.dynamics.contact import N_VINT
from asterlite.dynamics.excitation import Excitation
from asterlite.dynamics.forces import acceleration, total_force
from asterlite.dynamics.laws.kernel import failed_law
from asterlite.dynamics.layouts import EXTRA, LINEAR, LOADS, SCALARS, SHOCKS, Archive, State
from asterlite.dynamics.loop import scheme_loop
from asterlite.dynamics.model import LinearSystem, ShockSet, local_bundle
from asterlite.dynamics.schemes import (
    GENERAL_PATH,
    IMPLICIT_LOOP,
    ROTATING_LOOP,
    SCHEMES,
    Scheme,
)
from asterlite.dynamics.step_limits import (
    damped_step_limit,
    stability_limit,
    stability_period,
    suggested_step,
)
from asterlite.errors import NumericalError
from asterlite.errors import field as named


@dataclass(frozen=True)
class SchemeOptions:
    """The scheme's parameters as the command read them from the validated
    call (the catalogue fills their defaults; none is restated here). A
    parameter of another family of schemes is None and never read; the step
    bounds are None where the deck leaves them to the scheme."""

    tolerance: float | None
    alpha: float | None
    dt_min: float | None
    dt_max: float | None
    beta: float | None
    gamma: float | None
    nmax_iter_pas: int | None
    vite_min: str | None
    coef_mult_pas: float | None
    coef_divi_pas: float | None
    pas_limi_rela: float | None
    nb_poin_periode: int | None
    # NEWMARK with the forces of the step's start (code_aster 13-15 decks:
    # asterlite.legacy.v15.OLD_BEHAVIOURS)
    force_at_step_start: bool
    # ADAPT_ORDRE2 as code_aster 10-12 ran it (mdadap: scheme_adapt_ordre2_v11;
    # asterlite.legacy.v15.OLD_BEHAVIOURS["ADAPT_ORDRE2_MDADAP"])
    adapt_v11: bool
    # asterlite's guards (no keyword): steps an adaptive run may take, bytes
    # the archive may hold in memory (past them it goes to disk); None:
    # StepBudget's own limit, archive_store.memory_budget
    max_steps: int | None = None
    max_archive_bytes: int | None = None
    # where an archive past its memory budget is written (the run's folder;
    # None: the system's temporary folder)
    archive_folder: Path | None = None


@dataclass
class RunResult:
    times: np.ndarray
    order: np.ndarray
    depl: np.ndarray
    vite: np.ndarray
    acce: np.ndarray
    vint: np.ndarray  # (n_archived, n_shocks, N_VINT)
    # (n_archived, kernel.N_INFO): the step that led to each archived
    # instant and the steps rejected so far (code_aster's PTEM and more)
    step_info: np.ndarray = field(default_factory=lambda: np.zeros((0, K.N_INFO)))
    info: dict = field(default_factory=dict)
    # (n_archived, energy.N_COLUMNS): the energy balance, or None
    energy: np.ndarray | None = None


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
    options: SchemeOptions,
    specialised: bool = True,
    rotation=None,
    label: str | None = None,
    energy: bool = False,
    implicit_shocks: bool = False,
    load_labels: list[str] | None = None,
) -> RunResult:
    """Integrate from t0 to t_end. ``specialised=False`` runs a scheme's
    general path (the time loop around its step on the three bundles, shocks
    in the global frame), as the relations of laws/ do; kept for comparison.
    ``label`` names the run on the progress bar. ``energy``: accumulate the
    energy balance in the loop (:mod:`asterlite.dynamics.energy`), returned
    as ``RunResult.energy``. ``implicit_shocks``: the implicit shock treatment
    (:mod:`asterlite.dynamics.implicit_shocks`). ``load_labels``: how the
    deck names each excitation row (the command's label of a load), for the message of a
    load that becomes non-finite; the error's ``path`` then names it.

    A kernel numba has not compiled yet (``asterlite warmup`` compiles them
    all) is announced on standard error; ``info['compile_seconds']`` is the
    time compiling took, left out of ``info['integration_seconds']``."""
    legacy = options.adapt_v11
    name = loop_kernel(scheme, system, shocks, specialised, rotation, implicit_shocks, legacy)
    with progress.kernel(name, compile_estimate(name)) as notice:
        return run_kernel(
            notice, system, shocks, excitation, scheme, q0, v0, t0, t_end, dt, instants,
            pas_arch, options, specialised, rotation, label, energy, implicit_shocks, load_labels,
        )  # fmt: skip


def loop_kernel(
    scheme, system, shocks, specialised=True, rotation=None, implicit=False, legacy_adapt=False
) -> str:
    """The name of the compiled loop a run takes: its scheme's, or the loop
    shared by every scheme (variable rotation speed, implicit shocks), and
    the variants its description lists (:meth:`schemes.Scheme.loop_names`:
    DIFF_CENTRE's specialised loop on diagonal or full matrices, the general
    path for the relations of laws/); ``legacy_adapt``: code_aster 10-12's
    variant asked (``SchemeOptions.adapt_v11``)."""
    if rotation is not None:
        return ROTATING_LOOP
    if implicit and shocks.count:
        return IMPLICIT_LOOP
    entry = SCHEMES[scheme]
    if legacy_adapt and entry.legacy_kernel is not None:
        return entry.legacy_kernel
    general = not specialised or shocks.has_laws
    if entry.loops == "specialised":
        if general:
            return GENERAL_PATH.format(entry.kernel)
        return entry.kernel if system.diagonal else entry.loop_names()[1]
    if entry.loops == "local_frame" and general:
        return GENERAL_PATH.format(entry.kernel)
    return entry.kernel


def local_frame_bundle(entry: Scheme, loop: str, system, shocks) -> tuple:
    """The 4th bundle of the model for the loops that take the shocks in
    their local frames (:mod:`asterlite.dynamics.local_frame`), else ():
    the whole ``local_bundle`` for DIFF_CENTRE's specialised loops; its
    shapes, rest positions and support-motion scratch for a scheme's own
    loop (the same types on diagonal and full matrices). The general paths
    and the loops shared by every scheme compile once for the 3-bundle model."""
    if entry.loops == "specialised" and loop in entry.loop_names()[:2]:
        return (local_bundle(system, shocks),)
    if entry.loops == "local_frame" and loop == entry.kernel:
        return (local_bundle(system, shocks)[3:],)
    return ()


def run_kernel(
    notice,
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
    options: SchemeOptions,
    specialised: bool,
    rotation,
    label: str | None,
    energy: bool,
    implicit_shocks: bool,
    load_labels: list[str] | None,
) -> RunResult:
    """:func:`integrate` inside its kernel block (``notice``: what was compiled)."""
    n = system.n_modes
    entry = SCHEMES[scheme]
    module = entry.implementation()
    model = (system.bundle(), shocks.bundle(), excitation.bundle())
    if options.adapt_v11 and entry.legacy_module is not None:
        module = legacy_adapt_module(entry, rotation, implicit_shocks and shocks.count, energy)
    else:
        model = model + local_frame_bundle(entry, notice.name, system, shocks)
    q, v = np.array(q0, dtype=float), np.array(v0, dtype=float)
    f, a = np.zeros(n), np.zeros(n)
    vint = shocks.initial_vint(t0)
    work = np.zeros((5, 3))
    native_loop = native.run_loop(
        entry, notice.name, rotation, implicit_shocks and shocks.count, options.adapt_v11
    )
    # the loops shared by every scheme (variable rotation speed, implicit
    # shocks), compiled: called as numba's are (native.shared_loops)
    shared = None
    if rotation is not None or (implicit_shocks and shocks.count):
        shared = native.shared_loops()
    compiled_loop = native_loop is not None or shared is not None
    if compiled_loop:
        shock = native.start(t0, q, v, a, f, vint, work, np.zeros(n), model)
    else:
        shock = total_force(t0, q, v, model[SHOCKS], vint, model[LOADS], work, f)
        acceleration(f, q, v, model[LINEAR], np.zeros(n), a)
    if shock >= 0 or diagnosis.bad(a).any():
        raise law_error(shocks, vint, t0) or initial_error(
            (q, v, a, f, vint), shocks, excitation, t0, load_labels
        )
    state = State(q, v, a, f, vint, np.zeros_like(vint), work)

    memory, _ = module.prepare(system, dt, options)
    rotating_loop = None
    if rotation is not None:  # variable rotation speed: matrices updated every step
        from asterlite.dynamics import rotation as R

        memory, rotating_loop = R.prepare(scheme, memory, rotation)
        if shared is not None:
            rotating_loop = shared[0]
        if rotation.initial_acceleration is not None:  # a restart keeps its acceleration
            a[:] = rotation.initial_acceleration
    implicit_loop = None
    if implicit_shocks and shocks.count:  # K and C change at each contact switch
        from asterlite.dynamics import dispatch
        from asterlite.dynamics import implicit_shocks as IS

        lin = system.bundle()
        lin = lin._replace(
            stiffness=lin.stiffness.copy(), damping=lin.damping.copy(), diagonal=lin.diagonal.copy()
        )
        model = (lin, model[SHOCKS], model[LOADS])
        memory, implicit_loop = IS.prepare(scheme, memory, system, shocks)
        if shared is not None:  # IS.prepare's run_loop and IS.start, compiled
            implicit_loop = functools.partial(shared[1], dispatch.code(scheme))
            shared[2](memory, model, q, v, t0)
        else:
            IS.start(memory, model, q, v, t0)
    adaptive = loop_adapts(entry, dt, options)
    eps = 10.0 * np.finfo(float).eps
    instants = np.asarray(instants, dtype=float)
    n_steps = K.grid_step_count(t0, t_end, dt)
    capacity = 2 + len(instants) + n_steps // max(pas_arch, 1)
    if adaptive:
        capacity = min(capacity, 4096)
    clock, counters = K.new_clock(t0, dt, t_end), K.new_counters(adaptive)
    budget = StepBudget(t0, t_end, dt, adaptive, options)
    row_bytes = 8 * (2 + 3 * n + shocks.count * shocks.vint_width + K.N_INFO)
    row_bytes += 8 * E.N_COLUMNS if energy else 0
    # past its memory budget the archive is written out by chunks (archive_store)
    resumable = not (options.adapt_v11 and entry.legacy_module is not None)
    in_memory = min(memory_budget(options.max_archive_bytes), budget.archive_bytes)
    store = ArchiveStore(row_bytes, in_memory, options.archive_folder, resumable)
    capacity = store.first_capacity(capacity, 8 * max(n, shocks.count * shocks.vint_width))
    budget.check_archive(capacity, row_bytes, pas_arch, clock, counters)
    buffers = new_buffers(capacity, n, shocks.count, shocks.vint_width)
    archive_start(buffers, t0, q, v, a, vint, dt)
    counters[K.K_ARCHIVED] = 1
    run_loop = (
        implicit_loop or rotating_loop or native_loop or scheme_run_loop(entry, module, notice.name)
    )
    if energy and rotating_loop is not None:
        raise NumericalError(
            f"the energy balance ({named('energy')}) at variable rotation speed "
            f"({named('rotation.variable')}='OUI')"
        )
    balance = E.new_energy(system, shocks, capacity, entry.staggered_velocity, energy)
    if energy and compiled_loop:
        native.energy_start(balance, t0, q, v, a, vint, model)
    elif energy:
        E.start(balance, t0, q, v, a, vint, model[SHOCKS], model[LOADS])
    bar = progress.time_bar(label or f"DYNA_VIBRA {scheme}", t0, t_end)
    model_parts = (system, shocks, excitation, load_labels)
    started, compiled_before = wallclock.perf_counter(), notice.seconds
    try:
        while True:
            counters[K.K_PAUSE_AT] = budget.next_pause(int(counters[K.K_STEP]))
            chunk_started = wallclock.perf_counter()
            try:
                status = run_loop(
                    clock, counters, state, memory, model, instants, pas_arch, eps, buffers,
                    balance,
                )  # fmt: skip
            except ZeroDivisionError:  # numba's error model, which the C++ loops follow
                raise zero_division_error(scheme, clock) from None
            if status == K.STATUS_FULL:
                count = int(counters[K.K_ARCHIVED])
                if store.write_out_when_full(buffers, count):
                    store.write_out(buffers, balance, count)
                    counters[K.K_ARCHIVED] = 0  # the loop fills the same buffers again
                    continue
                budget.check_archive(2 * len(buffers.times), row_bytes, pas_arch, clock, counters)
                buffers = grow(buffers)
                balance = E.grown(balance, len(buffers.times))
            elif status == K.STATUS_LOADS:  # next window of the sampled multipliers
                excitation.refill(clock[K.C_TIME], clock[K.C_STEP])
                model = (model[LINEAR], model[SHOCKS], excitation.bundle()) + model[3:]
            elif status == K.STATUS_PAUSE:
                budget.check_steps(clock, counters, scheme)
                watchdog.check_limits()  # the run's time and memory limits (export P lines)
                budget.resize_chunk(wallclock.perf_counter() - chunk_started)
                bar.update(clock[K.C_TIME], int(counters[K.K_STEP]))
            else:
                break
    finally:
        bar.close()
        if implicit_loop is not None:  # the shock set is the caller's: explicit again
            shocks.flags[:, C.F_IMPLICIT] = C.NORMAL_EXPLICIT
    compiled = notice.seconds - compiled_before  # the loop's first call compiles it
    elapsed = wallclock.perf_counter() - started - compiled
    if status != K.STATUS_DONE:
        failed = law_error(shocks, vint, clock[K.C_TIME] + clock[K.C_STEP])
        if failed is None and status == K.STATUS_NOT_FINITE:
            held = int(counters[K.K_ARCHIVED])
            last = buffers.times[held - 1] if held else store.last_time
            failed = nonfinite_error(state, clock, counters, last, model_parts, scheme)
        raise failed or divergence_error(status, clock, counters, shocks, system, scheme)
    count = int(counters[K.K_ARCHIVED])
    archived, rows = store.finish(buffers, balance, count)
    out_t, out_order, out_q, out_v, out_a, out_vint, out_info = archived
    info = run_info(clock, counters, t0, dt, elapsed, adaptive)
    info["archived"] = len(out_t)
    info["archive_on_disk"] = store.on_disk
    info["compile_seconds"] = notice.seconds
    # the loop that ran: its kernel's name and what compiled it
    info["loop"] = f"{notice.name} [{'C++' if compiled_loop else 'numba'}]"
    if implicit_loop is not None:
        ints = memory[EXTRA].ints
        info["contact_switches"] = int(ints[IS.I_SWITCHES])
        info["reintegrated_steps"] = int(ints[IS.I_CUTS])
        info["relinearisations"] = int(ints[IS.I_TURNS])
    if entry.frequency_control:
        kept = int(memory[SCALARS][adapt_control.S_KEPT_AT_MAX_TRIALS])
        info["steps_kept_at_nmax_iter_pas"] = kept
    return RunResult(out_t, out_order, out_q, out_v, out_a, out_vint, out_info, info, rows)


def archive_start(buffers: Archive, t0: float, q, v, a, vint, dt: float) -> None:
    """The archive's first row, the initial state (kernel.archive's values)."""
    buffers.times[0], buffers.order[0] = t0, 0
    buffers.depl[0], buffers.vite[0], buffers.acce[0] = q, v, a
    buffers.vint[0] = vint
    buffers.info[0, K.INFO_STEP], buffers.info[0, K.INFO_REJECTED] = dt, 0.0


def scheme_run_loop(entry: Scheme, module, loop: str):
    """The compiled loop named ``loop`` (:func:`loop_kernel`) of the scheme
    ``entry`` whose implementation is ``module``: code_aster 10-12's own
    loop for the legacy variant; the module's ``fast_loop``, when it has one
    (DIFF_CENTRE, NEWMARK), for any loop but the general path; else the one
    time loop around the scheme's step (:func:`asterlite.dynamics.loop.scheme_loop`)."""
    if loop == entry.legacy_kernel:
        return module.run_loop
    fast = getattr(module, "fast_loop", None)
    if fast is not None and loop != GENERAL_PATH.format(entry.kernel):
        return fast
    return scheme_loop(module.step)


def legacy_adapt_module(entry: Scheme, rotation, implicit, energy):
    """code_aster 10-12's variant of the scheme (its ADAPT_ORDRE2), which had
    no varying rotation speed, no implicit shocks and no energy balance."""
    for asked, what in ((rotation, "a varying rotation speed"), (implicit, "implicit shocks"),
                        (energy, "an energy balance")):  # fmt: skip
        if asked:
            raise NumericalError(f"{what} with code_aster 10-12's ADAPT_ORDRE2")
    return entry.legacy_implementation()


def loop_adapts(entry: Scheme, dt: float, options: SchemeOptions) -> bool:
    """Whether the time loop follows the step proposed by the scheme
    (code_aster's dtmprep: adaptive families whose step bounds differ,
    defaults 1e-6 and 1e6 times dt)."""
    if not entry.adaptive:
        return False
    dt_min = options.dt_min if options.dt_min is not None else 1.0e-6 * dt
    dt_max = options.dt_max if options.dt_max is not None else 1.0e6 * dt
    return abs(dt_max / dt_min - 1.0) > 100.0 * np.finfo(float).eps


def new_buffers(capacity: int, n_modes: int, n_shocks: int, width: int = N_VINT):
    return Archive(
        np.zeros(capacity),
        np.zeros(capacity, dtype=np.int64),
        np.zeros((capacity, n_modes)),
        np.zeros((capacity, n_modes)),
        np.zeros((capacity, n_modes)),
        np.zeros((capacity, n_shocks, width)),
        np.zeros((capacity, K.N_INFO)),
    )


class StepBudget:
    """What the driver checks when the compiled loop pauses: the number of
    steps (an adaptive scheme whose step collapses, e.g. on a stick-slip
    transition, would otherwise run for ever), the memory of the archive,
    and the size of the next chunk of steps (about CHUNK_SECONDS of work,
    so that progress is reported often and pauses cost nothing)."""

    CHUNK_SECONDS = 0.25
    FIRST_CHUNK = 20_000
    # an adaptive run may take this many times the steps of its initial step
    STEP_FACTOR = 1000
    MIN_STEPS = 10_000_000
    ARCHIVE_BYTES = 4 * 1024**3

    def __init__(self, t0, t_end, dt, adaptive, options):
        nominal = K.grid_step_count(t0, t_end, dt)
        self.max_steps = options.max_steps or (
            max(self.STEP_FACTOR * nominal, self.MIN_STEPS) if adaptive else None
        )
        self.archive_bytes = options.max_archive_bytes or self.ARCHIVE_BYTES
        self.chunk = self.FIRST_CHUNK

    def next_pause(self, steps: int) -> int:
        """The step index at which the loop pauses next (on the budget at the latest)."""
        pause = steps + self.chunk
        return pause if self.max_steps is None else min(pause, self.max_steps)

    def resize_chunk(self, seconds: float) -> None:
        scale = self.CHUNK_SECONDS / max(seconds, 1.0e-6)
        self.chunk = int(min(max(self.chunk * min(max(scale, 0.2), 5.0), 1_000), 10**9))

    def check_steps(self, clock, counters, scheme: str) -> None:
        steps = int(counters[K.K_STEP])
        if self.max_steps is None or steps < self.max_steps:
            return
        raise NumericalError(
            f"{scheme}: step budget exhausted: {steps} steps taken and t={clock[K.C_TIME]:.6g} "
            f"of {clock[K.C_END]:.6g} reached ({int(counters[K.K_REJECTED])} rejected, "
            f"smallest step {clock[K.C_MIN_STEP]:.3g}); the adaptive step collapsed, as "
            f"it does on stick-slip or stiff contact switches: raise {named('options.dt_min')}, "
            f"loosen {named('options.tolerance')}, give {named('options.alpha')} (a floor under "
            "the error scale of modes nearly at rest), or use a fixed-step scheme "
            "(DIFF_CENTRE, NEWMARK)"
        )

    def check_archive(self, capacity: int, row_bytes: int, pas_arch: int, clock, counters):
        """Refuse an archive of ``capacity`` instants beyond the memory limit
        when its loop cannot write it out to disk (code_aster 10-12's
        ADAPT_ORDRE2, the fluid film; the others never reach the limit:
        archive_store): before the run for the instants a fixed step will
        archive, during it when the buffers of an adaptive run have to grow."""
        needed = capacity * row_bytes
        if needed <= self.archive_bytes:
            return
        t, archived, steps = clock[K.C_TIME], int(counters[K.K_ARCHIVED]), int(counters[K.K_STEP])
        where = (
            f"at t={t:.6g} of {clock[K.C_END]:.6g}, {archived} instants archived in {steps} steps"
        )
        raise NumericalError(
            f"archive memory limit: {capacity} archived instants would take "
            f"{needed / 1024**3:.2f} GB (limit {self.archive_bytes / 1024**3:.2f} GB; "
            f"{where}, {named('archive.period')}={pas_arch}): archive less often "
            f"({named('archive')} {named('archive.period')} or {named('archive.instants')})"
        )


# what to check when a load is not finite (its multiplier: function, coefficient)
LOAD_ADVICE = (
    f"check the function that defines it ({named('excitation.function')}, "
    f"{named('excitation.coefficient')}, the formula)"
)


def law_error(shocks: ShockSet, vint: np.ndarray, t: float) -> NumericalError | None:
    """The error naming a nonlinearity of laws/ whose evaluation failed
    (NaN in its internal variables), or None."""

    s = failed_law(shocks.flags, vint)
    if s < 0:
        return None
    spec = shocks.specs[s]
    return NumericalError(
        f"{named('relations')} {spec.relation} {spec.name.strip()!r} (node {spec.node_1}) "
        f"could not be evaluated at t={t:.6g}: a function was evaluated outside its domain "
        "(PROL_GAUCHE/PROL_DROITE='EXCLU') or the local integration did not converge "
        f"({named('relation.max_iterations')}, {named('relation.tolerance')})"
    )


def grow(buffers):
    """Buffers of twice the rows, the old ones first. np.zeros maps a page
    only when it is first written: the half the loop has not filled yet
    costs nothing until it does (a concatenation with zeros wrote it all
    while the old buffers were still held)."""
    return Archive(*(doubled(b) for b in buffers))


def doubled(buffer: np.ndarray) -> np.ndarray:
    rows = len(buffer)
    grown = np.zeros((2 * rows, *buffer.shape[1:]), dtype=buffer.dtype)
    grown[:rows] = buffer
    return grown


def run_info(clock, counters, t0: float, dt: float, elapsed: float, adaptive: bool) -> dict:
    """What the run summary says of a finished loop: steps, rejections and
    the range of the step sizes taken."""
    steps = int(counters[K.K_STEP])
    return {
        "steps": steps,
        "rejected_steps": int(counters[K.K_REJECTED]),
        "archived": int(counters[K.K_ARCHIVED]),
        "integration_seconds": elapsed,
        "initial_step": dt,
        "adaptive": adaptive,
        "min_step": float(clock[K.C_MIN_STEP]) if steps else dt,
        "max_step": float(clock[K.C_MAX_STEP]) if steps else dt,
        "mean_step": (float(clock[K.C_TIME]) - t0) / steps if steps else dt,
        "last_step": float(clock[K.C_STEP]),
    }


def initial_error(state, shocks, excitation, t0: float, labels) -> NumericalError:
    """The error of an initial state whose acceleration is not finite."""
    culprit = diagnosis.nonfinite_culprit(state, shocks, excitation, t0, labels)
    return NumericalError(
        f"non-finite values in the initial state at t={t0:.9g}: {culprit.text}", path=culprit.path
    )


def nonfinite_error(state, clock, counters, last_archived, model_parts, scheme: str):
    """The error of a run whose state became non-finite: which quantity
    (a load of the excitation, the force of a shock, the generalized
    displacement / velocity / acceleration), at which instant, the last
    finite and the last archived instants, and what to change; its
    ``path`` names the keyword at fault below DYNA_VIBRA."""
    system, shocks, excitation, labels = model_parts
    t_good, dt = float(clock[K.C_TIME]), float(clock[K.C_STEP])
    culprit = diagnosis.nonfinite_culprit(state, shocks, excitation, t_good + dt, labels)
    when = diagnosis.when_text(t_good + dt, t_good, int(counters[K.K_STEP]) + 1, last_archived)
    if culprit.step_related:
        advice = step_advice(system, shocks, scheme, dt)
    else:
        advice = LOAD_ADVICE
    return NumericalError(f"{scheme}: {when}: {culprit.text}; {advice}", path=culprit.path)


def zero_division_error(scheme: str, clock) -> NumericalError:
    """The error of a step that divided by zero: an effective operator of
    the scheme with a zero entry (NEWMARK's beta zero, an effective
    stiffness a M + K + b C vanishing on a mode)."""
    t = clock[K.C_TIME]
    return NumericalError(
        f"{scheme}: a division by zero in the step from t={t:.6g} (with step "
        f"{clock[K.C_STEP]:.3g}): an operator of the scheme vanishes (NEWMARK with "
        f"{named('options.beta')}=0, or an effective stiffness a M + K + b C that is zero "
        "on a mode: check the scheme's coefficients and the generalized matrices)"
    )


def divergence_error(status, clock, counters, shocks: ShockSet, system: LinearSystem, scheme: str):
    """The error of a run that failed: when, where (the shock), with which
    step, and a smaller step to try with what sets it."""
    t = clock[K.C_TIME]
    dt = clock[K.C_STEP]
    shock = counters[K.K_SHOCK]
    if status == K.STATUS_SHOCK_DIVERGED and 0 <= shock < shocks.count:
        where = f" at shock {shocks.specs[shock].name} (node {shocks.specs[shock].node_1})"
    elif shocks.count:
        where = " (shocks: " + ", ".join(s.name for s in shocks.specs) + ")"
    else:
        where = ""
    what = {
        K.STATUS_NOT_FINITE: "the solution became non-finite",
        K.STATUS_SHOCK_DIVERGED: "relative velocity at a shock diverged",
        K.STATUS_STEP_UNDERFLOW: f"the adaptive step fell below {named('options.dt_min')}",
        K.STATUS_SWITCH_NOT_LOCATED: "a step was integrated again 100 times without "
        f"locating its contact switch ({named('implicit')}='IMPLICITE')",
    }.get(status, f"integration failed (status {status})")
    advice = step_advice(system, shocks, scheme, dt)
    return NumericalError(f"{scheme}: {what} at t={t:.6g}{where} with step {dt:.3g}; {advice}")


def step_advice(system: LinearSystem, shocks: ShockSet, scheme: str, dt: float) -> str:
    """A smaller step to try, with what sets the stability limit."""

    period = stability_limit(system, shocks)
    limit, cause = step_limit(system, shocks, scheme), period.cause()
    damped = damped_step_limit(system, shocks)
    if damped.step < limit:  # heavy damping binds before the period does
        limit, cause = damped.step, damped.cause()
    if limit >= dt:  # the step already resolves the model: halving is all one can say
        advice = (
            f"the step is already below the stability estimate {limit:.3g} s ({cause}); "
            f"try {named('grid.step')}={suggested_step(dt / 2.0):.3g} and check the "
            "stiffness, damping and loads"
        )
    else:
        step = named("grid.step")
        advice = f"try {step} <= {limit:.3g} (e.g. {step}={suggested_step(limit):.3g}; {cause})"
    return advice


def step_limit(system: LinearSystem, shocks: ShockSet, scheme: str) -> float:
    """The largest step code_aster's step check accepts for ``scheme``: the
    fraction of its description (:mod:`asterlite.dynamics.schemes`) of the
    shortest period with the shock stiffness."""

    return stability_period(system, shocks) / SCHEMES[scheme].step_fraction


__all__ = ["integrate", "RunResult", "SchemeOptions", "step_limit", "math"]
