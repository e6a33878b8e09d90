"""DEPL, VITE and ACCE of a harmonic state, as code_aster derives them."""

from __future__ import annotations

import numpy as np

TWO_PI = 2.0 * np.pi


def omega2(frequencies) -> np.ndarray:
    """code_aster's omega2(f): f² (2π)², negative for a negative frequency."""
    f = np.asarray(frequencies, dtype=float)
    return np.where(f >= 0.0, 1.0, -1.0) * (f * f * (TWO_PI * TWO_PI))


def derived_fields(depl: np.ndarray, frequencies, names) -> dict[str, np.ndarray]:
    """The fields ``names`` (DEPL, VITE, ACCE) from the amplitudes ``depl``
    (n_freq, n): VITE = iω u with ω = 2πf, ACCE = -omega2(f) u (comdlh)."""
    f = np.asarray(frequencies, dtype=float)
    out = {}
    for name in names:
        if name == "DEPL":
            out[name] = depl
        elif name == "VITE":
            out[name] = (1j * (TWO_PI * f))[:, None] * depl
        elif name == "ACCE":
            out[name] = (-omega2(f))[:, None] * depl
        else:
            raise ValueError(name)
    return out
