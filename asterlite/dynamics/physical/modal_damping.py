"""Modal damping of a physical transient (DYNA_VIBRA PHYS TRAN, NEWMARK and
WILSON): an equivalent modal damping applied as an explicit force.

code_aster (nmmoam / fmodam, used by dlnew0) keeps, for each mode i of
the given modes (the first k of them), b_i = K φ_i with K the stiffness the modes
were computed with (REF_RIGI_PREM), its MASS_GENE m_i, ω_i = 2π FREQ_i and
the reduced damping ξ_i, and applies

    f_am(v) = Σ_i 2 ξ_i / (m_i ω_i³) · b_i (b_iᵀ v)

(= Σ_i 2 ξ_i ω_i / m_i · (M φ_i)(M φ_i)ᵀ v for exact modes). The force is
not put in the effective matrix: each step subtracts f_am(v_n), v_n the
velocity at the start of the step (plus the support velocities at t_{n+1}
with multiple supports), from the load F(t_{n+1}); a damping matrix, when
also given,
keeps its implicit treatment. The initial acceleration ignores it.

B is n × k (k modes), so a step costs two thin products; no n × n matrix
is formed. Reduced damping ratios shorter than the modes repeat their last
value, longer ones are cut to the modes.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np


@dataclass
class ModalDamping:
    """``basis``: (n_free, k) reduced b_i = Tᵀ K φ_i; ``coefficients``:
    2 ξ_i / (m_i ω_i³). ``supports``: (b_iᵀ ψ_s over the modes, velocity
    function) pairs of the multiple supports: the support velocity ψ_s v_s(t) (on all
    DOFs, the support ones included) is added to the relative one."""

    basis: np.ndarray
    coefficients: np.ndarray
    supports: list = field(default_factory=list)

    @property
    def n_modes(self) -> int:
        return self.basis.shape[1]

    def force(self, v: np.ndarray, t: float | None = None) -> np.ndarray:
        projected = self.basis.T @ v
        if self.supports and t is not None:
            for support, velocity in self.supports:
                value = float(np.asarray(velocity.evaluate(np.array([t])), dtype=float)[0])
                projected = projected + value * support
        return self.basis @ (self.coefficients * projected)

    def matrix(self):
        """The equivalent damping B diag(c) Bᵀ (dense; tests and small systems)."""
        return (self.basis * self.coefficients) @ self.basis.T


def damping_ratios(values, n_modes: int) -> tuple[np.ndarray, bool]:
    """The ratio of each mode (padded with the last value); True when more
    values than modes were given (code_aster's MECANONLINE5_19 alarm)."""
    values = np.atleast_1d(np.asarray(values, dtype=float))
    if values.size == 0:
        raise ValueError("no damping ratio")
    too_many = values.size > n_modes
    if values.size < n_modes:
        values = np.concatenate([values, np.full(n_modes - values.size, values[-1])])
    return values[:n_modes], too_many


def build_modal_damping(
    elimination, stiffness_shapes, frequencies, masses, ratios, supports=()
) -> ModalDamping:
    """``stiffness_shapes``: (n_dofs, k) K φ_i on the numbering of the
    transient (all DOFs); ``frequencies`` in Hz, ``masses`` MASS_GENE;
    ``supports``: (ψ_s on all DOFs, velocity function) of the multiple supports."""
    frequencies = np.asarray(frequencies, dtype=float)
    masses = np.asarray(masses, dtype=float)
    # ω keeps the frequency's sign, as code_aster's dampModalPreparation takes it: a
    # free structure's rigid-body modes come out at ±1e-6 Hz, their sign set
    # by round-off (it differs between factorisations), and each gives a force
    # of order 2 ξ ω / m either way
    omega = 2.0 * np.pi * frequencies
    if np.any(omega == 0.0) or np.any(masses <= 0.0):
        bad = int(np.flatnonzero((omega == 0.0) | (masses <= 0.0))[0]) + 1
        raise ValueError(
            f"mode {bad} has a zero frequency or generalized mass: 2ξ/(m ω³) is undefined"
        )
    full = np.asarray(stiffness_shapes, dtype=float).reshape(elimination.T.shape[0], -1)
    basis = np.asarray(elimination.T.T @ full)
    coefficients = 2.0 * np.asarray(ratios, dtype=float) / (masses * omega**3)
    projected = [
        (full.T @ np.asarray(shape, dtype=float), velocity) for shape, velocity in supports
    ]
    return ModalDamping(basis=basis, coefficients=coefficients, supports=projected)
