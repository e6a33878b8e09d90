"""Time loops compiled when asterlite is installed: C++ (``_loops``, built by
pip from the headers of this folder), run without waiting for a compiler.

They do what the numba kernels of the same names do, operation for
operation in the same order (no fused multiply-add, no reassociation:
``-ffp-contract=off``, no fast-math), so that a run gives the same bits on
either; tests/test_native_loops.py checks both on every obstacle, load and
matrix kind. What they cover now:

- DIFF_CENTRE's specialised loop on diagonal or full matrices
  (:func:`asterlite.dynamics.scheme_diff_centre.fast_loop`) with DIS_CHOC
  shocks, tabulated and formula loads, support motions; without the energy
  balance (the numba loop keeps it);
- the total force and acceleration at the start of such a run
  (:func:`asterlite.dynamics.forces.total_force`, ``acceleration``).

Every other loop is numba's. ``ASTERLITE_NATIVE=0`` runs numba's
everywhere (comparisons); a checkout whose extension was not built (no C++
compiler at install) runs numba's too.
"""

from __future__ import annotations

import os

from asterlite.dynamics.layouts import LINEAR, LOADS, LOCAL, ROWS, SHOCKS

try:
    from asterlite.dynamics.native import _loops
except ImportError:  # not built: the numba kernels serve
    _loops = None

SWITCH = "ASTERLITE_NATIVE"  # "0": numba's loops everywhere
RESIDUAL = 0  # the memory row of DIFF_CENTRE's residual (scheme_diff_centre.RESIDUAL)


def available() -> bool:
    """Whether the compiled loops are built and not switched off."""
    return _loops is not None and os.environ.get(SWITCH, "1") != "0"


def covers_diff_centre(energy: bool, rotation, implicit: bool, legacy: bool) -> bool:
    """Whether DIFF_CENTRE's specialised loop (diagonal or full matrices,
    DIS_CHOC shocks only: the loop integrate.loop_kernel names) runs here."""
    return available() and not (energy or rotation is not None or implicit or legacy)


def diff_centre_loop(
    clock, counters, state, memory, model, instants, pas_arch, eps, archive, energy
):
    """scheme_diff_centre.fast_loop on the same bundles (``energy``
    inactive): a ``K.STATUS_*``, the arrays advanced in place."""
    exc, shk = model[LOADS], model[SHOCKS]
    mass_inverse, stiffness, damping, shapes, rest, drive = model[LOCAL]
    return _loops.diff_centre_loop(
        clock, counters, instants,
        state.q, state.v, state.a, state.f, state.vint, memory[ROWS][RESIDUAL],
        mass_inverse, stiffness, damping,
        shk.flags, shk.params, shk.rots, shk.polars, shapes, rest, drive,
        *_loads(exc), *_supports(exc),
        *archive,
        int(pas_arch), float(eps),
    )  # fmt: skip


def start(t, q, v, a, f, vint, work, residual, model) -> int:
    """f = forces.total_force(t, ...) and a = forces.acceleration(f, ...):
    a diverging shock's index or -1."""
    lin, shk, exc = model[LINEAR], model[SHOCKS], model[LOADS]
    return _loops.start(
        float(t), q, v, a, f, vint, residual, work,
        lin.minv, lin.stiffness, lin.damping, lin.diagonal,
        shk.flags, shk.params, shk.rots, shk.polars, shk.phis,
        *_loads(exc), *_supports(exc),
    )  # fmt: skip


def _loads(exc) -> tuple:
    return (
        exc.vectors, exc.abscissas, exc.ordinates, exc.layout, exc.pending, exc.cursors,
        exc.codes, exc.constants, exc.stack,
    )  # fmt: skip


def _supports(exc) -> tuple:
    return (
        exc.drive_shapes, exc.drive_abscissas, exc.drive_ordinates, exc.drive_layout,
        exc.drive_pending, exc.drive_cursors,
    )  # fmt: skip


def layout() -> dict:
    """The positions and constants the extension was built with."""
    return _loops.layout()
