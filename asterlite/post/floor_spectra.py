"""Floor response spectra corrected for the interaction with the equipment
(CALC_SPECTRE_IPM's numerics; the oscillator spectrum itself is
:func:`asterlite.post.functions.response_spectrum`).

The floor acceleration was computed with the equipment lumped into the
support (model A: one oscillator of mass 1 + λ, frequency f_s, damping ξ_s).
The equipment is really a set of oscillators of mass fractions μ_i of λ,
frequencies f_i and dampings ξ_i hung on the support (model B). The floor
acceleration of model B is that of model A times a transfer function of
the frequency, applied through an FFT of the signal.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.concepts.function import Function
from asterlite.post import functions as fops


@dataclass(frozen=True)
class Equipment:
    """One EQUIPEMENT occurrence: the support and the oscillators on it."""

    mass_ratio: float  # RAPPORT_MASSE_TOTALE λ: equipment mass / support mass
    support_frequency: float  # FREQ_SUPPORT (model A)
    support_damping: float  # AMOR_SUPPORT
    mass_fractions: tuple[float, ...]  # COEF_MASS_EQUIP μ_i (sum 1)
    frequencies: tuple[float, ...]  # FREQ_EQUIP
    dampings: tuple[float, ...]  # AMOR_EQUIP


def _oscillator_denominator(w, omega, damping):
    """ω² - w² + 2iξωw: the dynamic stiffness per unit mass of an oscillator."""
    return omega**2 - w**2 + 2j * w * omega * damping


def interaction_transfer(freqs, equipment: Equipment) -> np.ndarray:
    """Ratio of the floor acceleration of model B to that of model A at each
    frequency (1 at zero frequency)."""
    w = 2 * np.pi * np.asarray(freqs, dtype=float)
    lam = equipment.mass_ratio
    numerator = np.zeros(w.size, dtype=complex)
    denominator = np.zeros(w.size, dtype=complex)
    for fraction, freq, damping in zip(
        equipment.mass_fractions, equipment.frequencies, equipment.dampings, strict=True
    ):
        delta = _oscillator_denominator(w, 2 * np.pi * freq, damping)
        stiffness = delta + w**2  # ω² + 2iξωw
        mass = lam * fraction
        numerator += mass * stiffness / delta
        denominator += mass * stiffness - mass * stiffness**2 / delta
    omega_a = 2 * np.pi * equipment.support_frequency
    # the support alone (mass 1) with the same stiffness and damping coefficient
    stretch = np.sqrt(1 + lam)
    support_b = _oscillator_denominator(w, omega_a * stretch, equipment.support_damping * stretch)
    support_a = _oscillator_denominator(w, omega_a, equipment.support_damping)
    return (1 + w**2 * (1 + numerator) / (support_b + denominator)) / (1 + w**2 / support_a)


def corrected_acceleration(accel: Function, equipment: Equipment) -> Function:
    """The floor acceleration of model B: FFT of every sample, product with
    :func:`interaction_transfer`, then the inverse FFT of the positive half
    mirrored as code_aster does (its time step is therefore that of the
    input times N / (2 (N // 2)))."""
    spectrum = fops.fft(accel, "COMPLET")
    freqs = spectrum.abscissas
    corrected = spectrum.ordinates * interaction_transfer(freqs, equipment)
    half = freqs.size // 2
    positive = spectrum.with_values(freqs[:half], corrected[:half])
    return fops.inverse_fft(positive, "COMPLET", symmetric=False)
