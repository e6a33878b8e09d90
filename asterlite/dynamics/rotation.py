"""Rotating machinery at variable speed.

The generalized damping and stiffness depend on the rotation speed Ω(t)
and acceleration Ω'(t) (code_aster's dtmupmat)::

    C(t) = C + Ω(t) G          (damping matrix or modal damping, gyroscopic matrix G)
    K(t) = K + Ω'(t) K_gy      (stiffness, gyroscopic stiffness K_gy; none: K)

code_aster (dtmcalc) updates the matrices at the start of every step, the
instant t_i of the state the step leaves, whatever the scheme (dtmintg
dispatches every GENE scheme the same way); a step retried by an adaptive
scheme keeps the matrices of t_i. The schemes then work with them as
their integrators do on MAT_UPDT: the accelerations use C(t_i), K(t_i);
NEWMARK and TRBDF2 rebuild their effective operators, DEVOGE its M⁻¹C,
M⁻¹K and H1, H2 (intdevo_oper). The initial acceleration uses the
matrices at the initial instant. Ω and Ω' are multipliers of the
excitation machinery (tables, formula programs), evaluated in the loop.

One loop serves every scheme: :mod:`asterlite.dynamics.loop`'s around
:func:`rotating_step`, the scheme's step (branching on its code, see
:mod:`asterlite.dynamics.dispatch`) with the update before it. The
generalized matrices are written in place in the (M⁻¹, K, C, diagonal
flag) bundle of the model (the flag set to full: G couples the modes).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.dynamics import dispatch as D
from asterlite.dynamics import loop as L
from asterlite.dynamics import native
from asterlite.dynamics.excitation import (
    PROL_CONSTANT,
    SampledMultiplier,
    kernel_program,
    multiplier_points,
    tabulate_excitation,
)
from asterlite.dynamics.forces import multiplier_at
from asterlite.dynamics.formula import run_program
from asterlite.dynamics.jit import njit
from asterlite.dynamics.layouts import EXTRA, LINEAR, ROTATION_CODE, ROWS, SCALARS, TABLE


@dataclass
class Rotation:
    """C, K at rest, the gyroscopic matrix G, K_gy, and Ω(t), Ω'(t)."""

    damping: np.ndarray
    stiffness: np.ndarray
    gyro: np.ndarray
    rigy: np.ndarray
    speed: object  # function of time
    acceleration: object | None = None  # function of time, or None (0)

    def __post_init__(self) -> None:
        self.excitation = None
        # a run continuing a result: code_aster (dtminit) restarts from the archived
        # acceleration instead of solving the equilibrium at the new start
        self.initial_acceleration = None

    def tabulate(self, t0: float, t_end: float, h: float) -> None:
        """Ω (row 0) and Ω' (row 1) as kernel multipliers; functions the
        kernels cannot evaluate (no points, no program) are sampled every h
        over the whole run (one table, no windows)."""
        mults = [self.speed, self.acceleration if self.acceleration is not None else 0.0]
        loads = []
        full = []
        for mult in mults:
            if kernel_program(mult) is None and isinstance(
                multiplier_points(mult, t0, t_end, h), SampledMultiplier
            ):
                count = max(2, int(np.ceil((t_end - t0) / h)) + 3)
                xs = t0 + h * np.arange(count)
                full.append((xs, np.asarray(mult.evaluate(xs), dtype=float)))
                loads.append((np.zeros(1), 0.0))
            else:
                full.append(None)
                loads.append((np.zeros(1), mult))
        excitation = tabulate_excitation(1, loads, t0, t_end, h)
        width = max([excitation.abscissas.shape[1]] + [len(f[0]) for f in full if f is not None])
        if width > excitation.abscissas.shape[1]:
            for name in ("abscissas", "ordinates"):
                old = getattr(excitation, name)
                new = np.zeros((old.shape[0], width))
                new[:, : old.shape[1]] = old
                setattr(excitation, name, new)
        for row, table in enumerate(full):
            if table is None:
                continue
            xs, ys = table
            excitation.abscissas[row, : len(xs)] = xs
            excitation.ordinates[row, : len(xs)] = ys
            excitation.layout[row] = (len(xs), PROL_CONSTANT, PROL_CONSTANT)
        self.excitation = excitation

    def matrices_at(self, t: float) -> tuple[np.ndarray, np.ndarray]:
        """(C(t), K(t)) evaluated in Python (initial state)."""
        exc = self.excitation.bundle()
        multipliers = native.rotation_multipliers() or speed_and_acceleration
        speed, accel = multipliers(exc, t)
        return self.damping + speed * self.gyro, self.stiffness + accel * self.rigy

    def bundle(self):
        return (
            np.ascontiguousarray(self.damping, dtype=float),
            np.ascontiguousarray(self.stiffness, dtype=float),
            np.ascontiguousarray(self.gyro, dtype=float),
            np.ascontiguousarray(self.rigy, dtype=float),
            self.excitation.bundle(),
        )


@njit(cache=True)
def multiplier_value(exc, e, t):
    codes, constants, stack = exc.codes, exc.constants, exc.stack
    if codes[e, 0] > 0:
        return run_program(codes, constants, e, t, stack)
    layout = exc.layout
    return multiplier_at(
        exc.abscissas, exc.ordinates, e, layout[e, 0], layout[e, 1], layout[e, 2], t, exc.cursors
    )


@njit(cache=True)
def speed_and_acceleration(exc, t):
    return multiplier_value(exc, 0, t), multiplier_value(exc, 1, t)


@njit(cache=True)
def update_linear(lin, rot, t):
    """C(t), K(t) into the model's (M⁻¹, K, C, flag) bundle, the flag set to
    full matrices."""
    stiffness, damping, flag = lin.stiffness, lin.damping, lin.diagonal
    damping0, stiffness0, gyro, rigy, exc = rot
    speed, accel = speed_and_acceleration(exc, t)
    n = damping.shape[0]
    for i in range(n):
        for j in range(n):
            damping[i, j] = damping0[i, j] + speed * gyro[i, j]
            stiffness[i, j] = stiffness0[i, j] + accel * rigy[i, j]
    flag[0] = 0


@njit(cache=True)
def rotating_step(t, dt, index, state, memory, model):
    """The step of the scheme whose code (:mod:`asterlite.dynamics.dispatch`)
    ends ``memory``, with C(t), K(t) written into the model and the
    scheme's operators refreshed before it; ``memory[EXTRA]`` is
    :meth:`Rotation.bundle`. :func:`asterlite.dynamics.loop.scheme_loop`
    runs it."""
    base, rot, code = (
        (memory[ROWS], memory[SCALARS], memory[TABLE]),
        memory[EXTRA],
        memory[ROTATION_CODE][0],
    )
    update_linear(model[LINEAR], rot, t)
    D.refresh_operators(code, base, model[LINEAR], state.q.shape[0])
    return D.scheme_step(code, t, dt, index, state, base, model)


def prepare(scheme: str, memory, rotation: Rotation):
    """(memory, run_loop) of a scheme run with variable rotation speed: the
    time loop around :func:`rotating_step`."""
    code = np.array([D.code(scheme)], dtype=np.int64)
    memory = D.full_matrices(scheme, memory) + (rotation.bundle(), code)

    def run_loop(*args):  # numba's loop, made at its first call (the C++ one may serve)
        return L.scheme_loop(rotating_step)(*args)

    return memory, run_loop
