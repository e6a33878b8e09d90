"""Fourier transforms of whole results, DOF by DOF (REST_SPEC_TEMP).

The lengths and the spectrum built for the inverse transform are code_aster's
(prefft/spdfft), so that values match its own to rounding:

- ``n`` is the smallest power (at least 1) with ``2**n`` at least the number of
  samples; PROL_ZERO pads to ``2**(n + N_PUIS)``; TRONCATURE, when the count is
  not a power of two, keeps ``2**(n-1)`` samples;
- time to frequency: the forward transform (no scaling) of the padded signal,
  of which SYMETRIE='NON' keeps the first half, at frequencies ``k / (N dt)``;
- frequency to time: the given (positive) half of the spectrum and its
  conjugates mirrored about the transform's end make a Hermitian spectrum of
  length ``2 N`` (SYMETRIE='NON') or ``N`` (SYMETRIE='OUI': only the first
  half of the values is read); the bin after the middle takes
  ``(4 Re X[N] - Re X[N-1]) / 3``, then the inverse transform (scaled by its
  length) gives the real signal at instants ``k / (length df)``.
"""

from __future__ import annotations

import numpy as np


def _power_above(count: int) -> int:
    """The smallest n >= 1 with 2**n >= count."""
    n = 1
    while 2**n < count:
        n += 1
    return n


def _lengths(count: int, method: str, extra_power: int) -> tuple[int, int]:
    """(transform length, samples read) before the symmetry rule."""
    n = _power_above(count)
    if method == "TRONCATURE" and 2**n != count:
        return 2 ** (n - 1), 2 ** (n - 1)
    return 2 ** (n + extra_power), count


def time_to_frequency(
    times: np.ndarray, values: np.ndarray, method: str, symmetric: bool, extra_power: int
) -> tuple[np.ndarray, np.ndarray]:
    """(frequencies, spectra): ``values`` is (n_instants, n_dofs) real."""
    count = len(times)
    if count < 2:
        raise ValueError("the transient result needs at least two instants")
    length, read = _lengths(count, method, extra_power)
    kept = length // 2 if not symmetric else (length if read == count else 2 * length)
    if kept > length:
        # code_aster reads past its transform there: no defined value to give
        raise ValueError(
            "METHODE='TRONCATURE' with SYMETRIE='OUI' on a transient whose number of "
            f"instants ({count}) is not a power of two has no defined result"
        )
    signal = np.zeros((length, values.shape[1]))
    signal[:read] = values[:read]
    spectrum = np.fft.fft(signal, axis=0)
    step = float(times[1] - times[0])
    frequencies = np.arange(kept) / (length * step)
    return frequencies, spectrum[:kept]


def frequency_to_time(
    frequencies: np.ndarray, spectra: np.ndarray, method: str, symmetric: bool, extra_power: int
) -> tuple[np.ndarray, np.ndarray]:
    """(instants, signals): ``spectra`` is (n_freq, n_dofs) complex."""
    count = len(frequencies)
    if count < 2:
        raise ValueError("the harmonic result needs at least two frequencies")
    n = _power_above(count)
    if method == "TRONCATURE" and 2**n != count:
        half = 2 ** (n - 1)
        length = 2 * half
    else:
        half = 2 ** (n + extra_power)
        length = half
    if not symmetric:
        length = 2 * half
    spectra = np.array(spectra, dtype=complex)
    # code_aster drops a negligible imaginary part of the last value, on the
    # first DOF of its numbering only
    last = spectra[-1, 0]
    if abs(last.imag) < 1e-6 * abs(last.real):
        spectra[-1, 0] = last.real
    used = min(count, length // 2)
    # one bin past the transform, where the conjugate of the first value falls
    work = np.zeros((length + 1, spectra.shape[1]), dtype=complex)
    work[:used] = spectra[:used]
    work[length - np.arange(used)] = np.conj(spectra[:used])
    if half + 1 <= length:
        if half > count and not symmetric:
            work[count:half] = 0.0
            work[length - half + 1 : length - count + 1] = 0.0
        work[half + 1] = (4.0 * work[half].real - work[half - 1].real) / 3.0
    signals = np.fft.ifft(work[:length], axis=0).real
    step = float(frequencies[1] - frequencies[0])
    instants = np.arange(length) / (length * step)
    return instants, signals
