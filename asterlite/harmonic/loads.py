"""Harmonic loads: a vector times a complex coefficient of the frequency.

code_aster (cnvesl / ascomb) multiplies each EXCIT vector by

    c(f) = g(f) · e^{i φ π/180} · ω^p,   ω = 2πf,

g being COEF_MULT / COEF_MULT_C (constant) or FONC_MULT / FONC_MULT_C
(a function or formula of the frequency, evaluated at f), φ = PHAS_DEG and
p = PUIS_PULS (ω^p applied when p ≠ 0).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.harmonic.fields import TWO_PI


@dataclass
class HarmonicLoad:
    """One excitation: ``vector`` (real or complex, on the system's unknowns:
    physical DOFs or generalized coordinates) times ``c(f)``.

    ``multiplier`` is a number (real or complex) or an object with
    ``evaluate(frequencies) -> array`` (a function or a one-parameter
    formula of the frequency); ``phase_deg`` and ``power`` are PHAS_DEG and
    PUIS_PULS. ``label`` names the load in messages.
    """

    vector: np.ndarray
    multiplier: object = 1.0
    phase_deg: float = 0.0
    power: int = 0
    label: str = ""

    def coefficients(self, frequencies) -> np.ndarray:
        """c(f) at each frequency (complex)."""
        f = np.atleast_1d(np.asarray(frequencies, dtype=float))
        if isinstance(self.multiplier, (int, float, complex, np.number)):
            base = np.full(f.shape, complex(self.multiplier))
        else:
            base = np.asarray(self.multiplier.evaluate(f)).astype(complex).reshape(f.shape)
        coef = base * np.exp(1j * (self.phase_deg * np.pi / 180.0))
        if self.power:
            coef = coef * (TWO_PI * f) ** self.power
        return coef


def load_matrix(loads, frequencies, size: int) -> np.ndarray:
    """F(f) for every frequency: (n_freq, size) complex, Σ_k c_k(f) F_k."""
    f = np.atleast_1d(np.asarray(frequencies, dtype=float))
    out = np.zeros((f.size, size), dtype=complex)
    for load in loads:
        vector = np.asarray(load.vector)
        if vector.shape != (size,):
            raise ValueError(f"load {load.label}: {vector.shape[0]} values for {size} unknowns")
        out += np.outer(load.coefficients(f), vector)
    return out


@dataclass
class SweepLoads:
    """The right-hand sides of a sweep kept factored: F(f_i) = Σ_k
    coefficients[i, k] vectors[k] (+ extra[i] when given, e.g. EXCIT_RESU).
    Solvers that project F on a basis do it once per load vector instead
    of once per frequency."""

    vectors: np.ndarray  # (n_loads, n)
    coefficients: np.ndarray  # (n_freq, n_loads) complex
    extra: np.ndarray | None = None  # (n_freq, n) complex

    @classmethod
    def of(cls, loads, frequencies, size: int, extra=None) -> SweepLoads:
        f = np.atleast_1d(np.asarray(frequencies, dtype=float))
        if loads:
            vectors = np.array([np.asarray(load.vector) for load in loads])
            coefficients = np.column_stack([load.coefficients(f) for load in loads])
        else:
            vectors = np.zeros((0, size))
            coefficients = np.zeros((f.size, 0), dtype=complex)
        if vectors.shape[1] != size:
            raise ValueError(f"load vectors of {vectors.shape[1]} values for {size} unknowns")
        return cls(vectors, coefficients, extra)

    def dense(self) -> np.ndarray:
        """(n_freq, n) complex."""
        out = self.coefficients @ self.vectors.astype(complex)
        return out if self.extra is None else out + self.extra

    def project(self, matrix: np.ndarray) -> np.ndarray:
        """F(f) @ matrixᵀ for every frequency, through the load vectors."""
        out = self.coefficients @ (self.vectors @ matrix.T)
        return out if self.extra is None else out + self.extra @ matrix.T
