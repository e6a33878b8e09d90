"""Imposed motion of a physical transient: kinematic relations (DDL_IMPO,
LIAISON_DDL) of a load of the excitation multiplied by a function of time.

code_aster (dlnew0) integrates the full vector of unknowns, the constrained
DOFs included: their displacement is the imposed value at each step and
their velocity and acceleration follow from it by the scheme's own update
formulas. With the relations eliminated, u = T q + Σ_l c_l(t) w_l + u0,
where w_l solves B w = b_l for load l. Projected by Tᵀ (which cancels the
reactions), the equation of the free unknowns keeps the Newmark update on
q alone if its force gains -Tᵀ (K w c_l + C w ċ_l + M w c̈_l), with (c_l,
ċ_l, c̈_l) the scheme's state of the scalar c_l(t_n): the imposed part is
linear in the multipliers, so the scheme's recurrence runs on scalars, one
per load, not on vectors.

The state at the first instant is (c_l(t0), 0, 0): no initial state gives the
constrained DOFs a velocity or acceleration, as code_aster's zero initial
fields.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass
class ImposedMotion:
    """Shapes ``w`` (n_dofs, k) of the relations' right-hand sides of k loads
    and their multipliers (functions of time)."""

    shapes: np.ndarray
    multipliers: list

    def values(self, times: np.ndarray) -> np.ndarray:
        """c_l(t) at each instant: (n_times, k)."""
        times = np.atleast_1d(np.asarray(times, dtype=float))
        columns = [
            np.asarray(m.evaluate(times), dtype=float).reshape(times.shape)
            for m in self.multipliers
        ]
        return np.stack(columns, axis=1)


@dataclass
class ScaledInTime:
    """A load multiplier (a function, or a float coefficient) times a
    right-hand side given in time (AFFE_CHAR_MECA_F of the time, ``INST``)."""

    scale: object
    value: object

    def evaluate(self, times) -> np.ndarray:
        times = np.atleast_1d(np.asarray(times, dtype=float))
        scale = self.scale
        if not isinstance(scale, (int, float)):
            scale = np.asarray(scale.evaluate(times), dtype=float).reshape(times.shape)
        return scale * self.value.evaluate(times)


def newmark_states(values: np.ndarray, times: np.ndarray, beta: float, gamma: float):
    """Newmark's (c, ċ, c̈) of scalar displacements ``values`` (n_times, k)
    given at every step instant, starting from velocity and acceleration 0:

        c̈_{n+1} = (c_{n+1} - c_n - dt ċ_n) / (β dt²) - (1/(2β) - 1) c̈_n
        ċ_{n+1} = ċ_n + dt ((1 - γ) c̈_n + γ c̈_{n+1})
    """
    velocity = np.zeros_like(values)
    acceleration = np.zeros_like(values)
    for n in range(times.size - 1):
        dt = times[n + 1] - times[n]
        acceleration[n + 1] = (values[n + 1] - values[n] - dt * velocity[n]) / (beta * dt * dt) - (
            1.0 / (2.0 * beta) - 1.0
        ) * acceleration[n]
        velocity[n + 1] = velocity[n] + dt * (
            (1.0 - gamma) * acceleration[n] + gamma * acceleration[n + 1]
        )
    return values, velocity, acceleration


@dataclass
class ConstantInTime:
    """The constant coefficient of a load whose imposed values do not vary
    in time: the multiplier of their relations at every instant."""

    value: float

    def evaluate(self, times) -> np.ndarray:
        return np.full(np.atleast_1d(np.asarray(times, dtype=float)).shape, self.value)
