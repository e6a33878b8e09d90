"""Time loops compiled when asterlite is installed: C++ (one extension module
per ``.cpp`` of this folder, built by pip from its headers), run without
waiting for a compiler.

They do what the numba kernels of the same names do, operation for
operation in the same order (no fused multiply-add, no reassociation:
``-ffp-contract=off``, no fast-math), so that a run gives the same bits on
either; tests/test_native_*.py check both on every obstacle, relation, load,
matrix kind and scheme. They cover every loop of the engine:

- each scheme's own loop, with DIS_CHOC shocks in their local frames
  (DIFF_CENTRE's on diagonal or full matrices, NEWMARK, DEVOGE,
  RUNGE_KUTTA_32/54, ADAPT_ORDRE1/2, TRBDF2), and its general path on the
  global model with the relations of laws/ (:func:`run_loop`);
- code_aster 10-12's ADAPT_ORDRE2 (:func:`run_loop`);
- the loops shared by every scheme: varying rotation speed, implicit shocks
  (:func:`shared_loops`); the fluid film's (:func:`film_loops`);
- the total force and acceleration, and the energy balance, at a run's start;
- outside the time loops, the physical harmonic sweep's sparse LDLᵀ
  (``_ldl``, called by :mod:`asterlite.harmonic.ldl`).

``ASTERLITE_NATIVE=0`` runs numba's everywhere (comparisons); a checkout
whose modules were not built (no C++ compiler at install) runs numba's too.
"""

from __future__ import annotations

import importlib
import os
import pkgutil

import numpy as np

from asterlite.dynamics.layouts import EXTRA, LINEAR, LOADS, LOCAL, ROTATION_CODE, ROWS, SHOCKS

try:
    from asterlite.dynamics.native import _loops
except ImportError:  # not built: the numba kernels serve
    _loops = None

SWITCH = "ASTERLITE_NATIVE"  # "0": numba's loops everywhere
RESIDUAL = 0  # the memory row of DIFF_CENTRE's residual (scheme_diff_centre.RESIDUAL)
GENERAL_PATH = "{} (general path)"  # schemes.GENERAL_PATH


def available() -> bool:
    """Whether the compiled loops are built and not switched off."""
    return _loops is not None and os.environ.get(SWITCH, "1") != "0"


def run_loop(entry, loop: str, rotation, implicit, legacy: bool):
    """The compiled loop that does what numba's loop ``loop`` (as
    :func:`asterlite.dynamics.integrate.loop_kernel` names it) of the scheme
    ``entry`` would, or None when numba's serves (not built, switched off):
    a scheme's own loop, its general path, code_aster 10-12's ADAPT_ORDRE2.
    The loops with varying rotation or implicit shocks are :func:`shared_loops`'."""
    if not available() or rotation is not None or implicit:
        return None
    if legacy:  # code_aster 10-12's ADAPT_ORDRE2, on the general model
        return LOOPS.get(loop) if loop == entry.legacy_kernel else None
    if loop not in entry.loop_names():
        return None
    if loop == GENERAL_PATH.format(entry.kernel):
        return LOOPS.get(loop)
    return LOOPS.get(entry.kernel)


def diff_centre_loop(
    clock, counters, state, memory, model, instants, pas_arch, eps, archive, energy
):
    """scheme_diff_centre.fast_loop on the same bundles (``energy``
    inactive): a ``K.STATUS_*``, the arrays advanced in place."""
    mass_inverse, stiffness, damping = model[LOCAL][:3]
    return _loops.diff_centre_loop(
        clock, counters, instants, *state, memory[ROWS][RESIDUAL],
        mass_inverse, stiffness, damping, *model_arguments(model),
        *archive, *energy, int(pas_arch), float(eps),
    )  # fmt: skip


def time_loop(function):
    """loop.scheme_loop's loop around a ported step: the same call."""

    def run(clock, counters, state, memory, model, instants, pas_arch, eps, archive, energy):
        return function(
            clock, counters, instants, *state, *memory[:3], *model_arguments(model),
            *archive, *energy, int(pas_arch), float(eps),
        )  # fmt: skip

    return run


def start(t, q, v, a, f, vint, work, residual, model) -> int:
    """f = forces.total_force(t, q, v, ...), a = forces.acceleration(f, ...):
    a diverging shock's index or -1 (``vint`` updated, ``work`` scratch)."""
    state = (q, v, a, f, vint, vint, work)  # read_state's order; no trial copy here
    return _loops.start(float(t), *state, residual, *model_arguments(model))


def energy_start(balance, t, q, v, a, vint, model) -> None:
    """energy.start: the balance at the initial state (its row 0)."""
    state = (q, v, a, np.zeros_like(q), vint, vint, np.zeros((5, 3)))  # f, trial copy unused
    _loops.energy_start(float(t), *state, *model_arguments(model), *balance)


NO_LOCAL_FRAMES = np.zeros(1, dtype=np.int64)
WITH_LOCAL_FRAMES = np.ones(1, dtype=np.int64)


def model_arguments(model) -> tuple:
    """The 31 arrays of the model, in the order of arguments.hpp's read_model:
    a scheme's own loop has the shocks' local frames (a 4th bundle), the
    general model (3 bundles) empty ones."""
    lin, shk, exc = model[LINEAR], model[SHOCKS], model[LOADS]
    if len(model) > LOCAL:
        local_frames = WITH_LOCAL_FRAMES
        shapes, rest, drive = model[LOCAL][-3:]
    else:
        local_frames = NO_LOCAL_FRAMES
        shapes, rest, drive = no_local_frames(lin.minv.shape[0])
    return (
        lin.minv, lin.stiffness, lin.damping, lin.diagonal,
        shk.flags, shk.params, shk.rots, shk.phis, shk.polars, shk.laws, shk.rphis,
        shk.law_scratch,
        exc.vectors, exc.abscissas, exc.ordinates, exc.layout, exc.pending, exc.cursors,
        exc.codes, exc.constants, exc.stack,
        exc.drive_shapes, exc.drive_abscissas, exc.drive_ordinates, exc.drive_layout,
        exc.drive_pending, exc.drive_cursors,
        local_frames, shapes, rest, drive,
    )  # fmt: skip


def no_local_frames(n: int) -> tuple:
    """The empty local-frame arrays of the general model."""
    return np.zeros((0, 2, 3, n)), np.zeros((0, 2, 3)), np.zeros((0, 2, 6))


def layout() -> dict:
    """The positions and constants the extension was built with."""
    return _loops.layout()


def compiled_loops() -> dict:
    """The compiled loop of each scheme kernel (schemes.Scheme.kernel):
    DIFF_CENTRE's, and those every extension module of this folder lists in
    its ``KERNELS`` (called as loop.hpp's run_time_loop reads them)."""
    if _loops is None:
        return {}
    loops = {"DIFF_CENTRE": diff_centre_loop}
    for found in pkgutil.iter_modules(__path__):
        if not found.name.startswith("_"):
            continue
        try:
            module = importlib.import_module(f"{__name__}.{found.name}")
        except ImportError:  # another build's leftover: not this interpreter's
            continue
        for kernel, function in getattr(module, "KERNELS", {}).items():
            loops[kernel] = time_loop(getattr(module, function))
    return loops


LOOPS = compiled_loops()


def built_module(name: str):
    """The extension module ``_<name>`` of this folder, or None: not built,
    or switched off."""
    if not available():
        return None
    try:
        return importlib.import_module(f"{__name__}._{name}")
    except ImportError:  # not built
        return None


def multiplier_arrays(exc) -> tuple:
    """A multipliers' excitation bundle as the C++ functions read it: tables
    (abscissas, ordinates, layout, cursors), then formula programs."""
    return (
        exc.abscissas, exc.ordinates, exc.layout, exc.cursors, exc.codes, exc.constants,
        exc.stack,
    )  # fmt: skip


def film_loops():
    """The compiled loops with fluid films (``_film``) and their start, called
    as numba's fluid_film.run_loop, run_adapt_loop and start are (the same
    arguments, the arrays advanced in place, the same returns), or None: not
    built, or switched off."""
    _film = built_module("film")
    if _film is None:
        return None

    def run_loop(clock, counters, q, v, a, vint, linear, model, exc, controls, scalars, work,
                 archive, instants, pas_arch, eps):  # fmt: skip
        return _film.film_loop(
            clock, counters, q, v, a, vint, *linear, *model, *exc, controls, scalars, *work,
            *archive, instants, int(pas_arch), float(eps),
        )  # fmt: skip

    def run_adapt_loop(clock, counters, state, memory, linear, model, exc, controls, counts, work,
                       archive, pas_arch):  # fmt: skip
        return _film.film_adapt_loop(
            clock, counters, *state, *memory[:3], *linear, *model, *exc, controls, counts, *work,
            *archive, int(pas_arch),
        )  # fmt: skip

    def start(t0, q, v, a, linear, model, exc, vint, work):
        return _film.film_start(float(t0), q, v, a, *linear, *model, *exc, vint, *work)

    return run_loop, run_adapt_loop, start


def shared_loops():
    """The compiled loops shared by every scheme (``_shared``), called as
    numba's are: ``rotating_loop`` as rotation.prepare's run_loop (loop.time_loop
    around rotation.rotating_step), ``implicit_loop`` as
    implicit_shocks.implicit_loop (the scheme's dispatch code first) and
    ``implicit_start`` as implicit_shocks.start; the same arguments, the
    arrays advanced in place, the same returns (a ZeroDivisionError where
    numba's step raises one). None: not built, or switched off."""
    _shared = built_module("shared")
    if _shared is None:
        return None

    def written(model) -> tuple:
        # what the loops write that read_model takes read-only: K, C, the
        # diagonal flag, the shock flags (the model's own arrays)
        lin = model[LINEAR]
        return lin.stiffness, lin.damping, lin.diagonal, model[SHOCKS].flags

    def rotating_loop(clock, counters, state, memory, model, instants, pas_arch, eps, archive,
                      energy):  # fmt: skip
        damping, stiffness, gyro, rigy, exc = memory[EXTRA]  # Rotation.bundle()
        return _shared.rotating_loop(
            clock, counters, instants, *state, *memory[:3], damping, stiffness, gyro, rigy,
            *multiplier_arrays(exc), memory[ROTATION_CODE], *written(model),
            *model_arguments(model), *archive, *energy, int(pas_arch), float(eps),
        )  # fmt: skip

    def treatment(memory) -> tuple:
        tr = memory[EXTRA]  # layouts.Treatment, its backup pair flattened
        return (
            tr.stiffness0, tr.damping0, tr.diagonal0, tr.active, tr.trial, tr.ints,
            tr.kinematics, tr.gradient, tr.work, *tr.backup, tr.keep, tr.vint_keep,
            tr.active_at_start, tr.planned,
        )  # fmt: skip

    def implicit_loop(code, clock, counters, state, memory, model, instants, pas_arch, eps,
                      archive, energy):  # fmt: skip
        return _shared.implicit_loop(
            int(code), clock, counters, instants, *state, *memory[:3], *treatment(memory),
            *written(model), *model_arguments(model), *archive, *energy, int(pas_arch),
            float(eps),
        )  # fmt: skip

    def implicit_start(memory, model, q, v, t0):
        return _shared.implicit_start(
            q, v, *treatment(memory), *written(model), *model_arguments(model)
        )

    return rotating_loop, implicit_loop, implicit_start


def rotation_multipliers():
    """rotation.speed_and_acceleration compiled (called as it is, on the
    multipliers' excitation bundle), or None: not built, or switched off."""
    _shared = built_module("shared")
    if _shared is None:
        return None

    def speed_and_acceleration(exc, t):
        return _shared.rotation_multipliers(float(t), *multiplier_arrays(exc))

    return speed_and_acceleration
