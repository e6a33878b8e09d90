"""Frequency band and time step of a linear dynamic study (DYNA_LINE).

The band [f_min, f_max] selects the dynamic modes. Given BANDE_ANALYSE it is
that band (one value: [0, value]); otherwise the cutoff frequency f_c of the
excitation is the frequency below which PCENT_COUP percent of the energy of
its spectrum lies (the largest over the excitations), and the band is
[0, 2 f_c]. The default time step is 1 / (5 f_c), f_c being BANDE_ANALYSE's
upper bound when given.
"""

from __future__ import annotations

import numpy as np


def cutoff_from_spectrum(freqs, spectrum, percent: float) -> float:
    """Frequency at which the cumulated |X(f)|² over the non-negative half of a
    discrete spectrum first reaches ``percent`` of its total."""
    freqs = np.asarray(freqs, dtype=float)
    half = max(len(freqs) // 2, 1)
    energy = np.cumsum(np.abs(np.asarray(spectrum)[:half]) ** 2)
    target = energy[-1] * float(percent) / 100.0
    index = min(int(np.searchsorted(energy, target, side="left")), half - 1)
    return float(freqs[index])


def band(bande_analyse, cutoff: float | None = None) -> tuple[float, float]:
    """(f_min, f_max): BANDE_ANALYSE when given, else [0, 2 f_c]."""
    values = tuple(bande_analyse or ())
    if values:
        return (float(values[0]) if len(values) == 2 else 0.0, float(values[-1]))
    if cutoff is None:
        raise ValueError("no BANDE_ANALYSE and no cutoff frequency")
    return 0.0, 2.0 * float(cutoff)


def default_step(cutoff: float) -> float:
    """1 / (5 f_c): five steps per period of the highest frequency retained."""
    return 1.0 / (5.0 * float(cutoff))
