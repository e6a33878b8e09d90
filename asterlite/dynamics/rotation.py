"""Rotating machinery at variable speed (DYNA_VIBRA VITESSE_VARIABLE='OUI').

The generalized damping and stiffness depend on the rotation speed Ω(t)
and acceleration Ω'(t) (code_aster's dtmupmat)::

    C(t) = C + Ω(t) G          (MATR_AMOR or modal damping, MATR_GYRO)
    K(t) = K + Ω'(t) K_gy      (MATR_RIGI, MATR_RIGY; no MATR_RIGY: K)

code_aster (dtmcalc) updates the matrices at the start of every step, the
instant t_i of the state the step leaves, whatever the scheme (dtmintg
dispatches every GENE scheme the same way); a step retried by an adaptive
scheme keeps the matrices of t_i. The schemes then work with them as
their integrators do on MAT_UPDT: the accelerations use C(t_i), K(t_i);
NEWMARK and TRBDF2 rebuild their effective operators, DEVOGE its M⁻¹C,
M⁻¹K and H1, H2 (intdevo_oper). The initial acceleration uses the
matrices at the initial instant. Ω and Ω' are multipliers of the
excitation machinery (tables, FORMULE programs), evaluated in the loop.

One loop serves every scheme (:func:`rotating_loop`, branching on the
scheme code of :mod:`asterlite.dynamics.dispatch`): the scheme's step with
the update before it. The generalized matrices are written in place in
the (M⁻¹, K, C, diagonal flag) bundle of the model (the flag set to full:
G couples the modes).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit

from asterlite.dynamics import dispatch as D
from asterlite.dynamics import kernel as K
from asterlite.dynamics import loop as L
from asterlite.dynamics.forces import multiplier_at
from asterlite.dynamics.formula import run_program
from asterlite.dynamics.model import (
    PROL_CONSTANT,
    SampledMultiplier,
    kernel_program,
    multiplier_points,
    tabulate_excitation,
)


@dataclass
class Rotation:
    """C, K at rest, the gyroscopic matrix G, K_gy, and Ω(t), Ω'(t)."""

    damping: np.ndarray
    stiffness: np.ndarray
    gyro: np.ndarray
    rigy: np.ndarray
    speed: object  # function of INST
    acceleration: object | None = None  # function of INST, or None (0)

    def __post_init__(self) -> None:
        self.excitation = None
        # ETAT_INIT RESULTAT: code_aster (dtminit) restarts from the archived
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
        speed, accel = speed_and_acceleration(exc, t)
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
    codes, constants, stack = exc[12], exc[13], exc[14]
    if codes[e, 0] > 0:
        return run_program(codes, constants, e, t, stack)
    layout = exc[3]
    return multiplier_at(exc[1], exc[2], e, layout[e, 0], layout[e, 1], layout[e, 2], t, exc[9])


@njit(cache=True)
def speed_and_acceleration(exc, t):
    return multiplier_value(exc, 0, t), multiplier_value(exc, 1, t)


@njit(cache=True)
def update_linear(lin, rot, t):
    """C(t), K(t) into the model's (M⁻¹, K, C, flag) bundle, the flag set to
    full matrices."""
    stiffness, damping, flag = lin[1], lin[2], lin[3]
    damping0, stiffness0, gyro, rigy, exc = rot
    speed, accel = speed_and_acceleration(exc, t)
    n = damping.shape[0]
    for i in range(n):
        for j in range(n):
            damping[i, j] = damping0[i, j] + speed * gyro[i, j]
            stiffness[i, j] = stiffness0[i, j] + accel * rigy[i, j]
    flag[0] = 0


@njit(cache=True)
def rotating_loop(code, clock, counters, state, memory, model, instants, pas_arch, eps, archive):
    """The time loop of the scheme ``code`` (:mod:`asterlite.dynamics.dispatch`)
    with C(t), K(t) written into the model and the scheme's operators
    refreshed before each step; ``memory[3]`` is :meth:`Rotation.bundle`."""
    base, rot = (memory[0], memory[1], memory[2]), memory[3]
    n = state[0].shape[0]
    while K.unfinished(clock, counters, eps):
        paused = L.before_step(clock, counters, model, archive)
        if paused:
            return paused
        t, dt = K.plan_step(clock, counters, instants, eps)
        update_linear(model[0], rot, t)
        D.refresh_operators(code, base, model[0], n)
        status, shock, dt_used, dt_next, rejected = D.scheme_step(
            code, t, dt, counters[K.K_STEP], state, base, model
        )
        if status != K.STATUS_DONE:
            return K.record_failure(clock, counters, status, shock, dt_used)
        result = (dt_used, dt_next, rejected)
        K.complete_step(clock, counters, state, instants, pas_arch, eps, archive, result)
    return K.STATUS_DONE


def prepare(scheme: str, memory, rotation: Rotation):
    """(memory, run_loop) of a scheme run with variable rotation speed."""
    code = D.code(scheme)
    memory = D.full_matrices(scheme, memory) + (rotation.bundle(),)

    def run_loop(clock, counters, state, memory, model, instants, pas_arch, eps, archive):
        return rotating_loop(
            code, clock, counters, state, memory, model, instants, pas_arch, eps, archive
        )

    return memory, run_loop
