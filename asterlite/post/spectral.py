"""Random signals from spectral matrices, and spectral matrices from signals.

GENE_FONC_ALEA and CALC_INTE_SPEC as code_aster computes them, so that a
deck's non-regression values hold:

- the spectral matrix is sampled on the generation grid (code_aster's
  choice of step and point count from FREQ_INIT / FREQ_FIN / NB_POIN /
  DUREE_TIRAGE), linearly interpolated, zero outside [FREQ_INIT, FREQ_FIN];
- at each frequency it is factorized S = R R^H through its eigenvectors
  (each scaled so that its largest component is real positive, the
  eigenvalues ascending, negative ones set to zero: code_aster's
  convention, which fixes R uniquely);
- each draw takes, frequency by frequency, one uniform phase per component
  from Python's Mersenne Twister seeded as code_aster seeds it (0, or
  INIT_ALEA), forms V = R exp(i 2 pi u), completes the spectrum by Hermitian
  symmetry and transforms it back to time with code_aster's radix-2 FFT;
- CALC_INTE_SPEC averages periodograms of consecutive windows (no taper),
  with the same FFT.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass, field

import numpy as np

# -- code_aster's FFT -------------------------------------------------------


def radix2_fft(values: np.ndarray, inverse: bool = False) -> np.ndarray:
    """Decimation-in-time radix-2 FFT in code_aster's operation order (bit
    reversal, then per stage twiddles by recurrence u <- u w and butterflies
    t = s[i + half] u, s[i + half] = s[i] - t, s[i] = s[i] + t); the inverse
    is scaled by 1/n. Each stage's butterflies run at once on numpy arrays,
    with the same floating-point operations as code_aster's loops."""
    s = np.array(values, dtype=complex)
    n = s.size
    stages = int(round(math.log2(n))) if n > 0 else -1
    if n == 0 or 2**stages != n:
        raise ValueError(f"FFT length {n} is not a power of two")
    s = s[_bit_reversal(n)]
    sign = -1.0 if inverse else 1.0
    for stage in range(1, stages + 1):
        span = 2**stage
        half = span // 2
        angle = -sign * math.pi / half
        w = complex(math.cos(angle), math.sin(angle))
        twiddles = np.empty(half, dtype=complex)
        u = complex(1.0, 0.0)
        for offset in range(half):
            twiddles[offset] = u
            u = u * w
        blocks = s.reshape(n // span, span)
        t = blocks[:, half:] * twiddles
        top = blocks[:, :half].copy()
        blocks[:, half:] = top - t
        blocks[:, :half] = top + t
    if inverse:
        s = s * (1.0 / n)
    return s


def _bit_reversal(n: int) -> np.ndarray:
    """The permutation code_aster's swap loop applies (bit-reversed indices)."""
    bits = int(round(math.log2(n)))
    index = np.arange(n)
    reversed_index = np.zeros(n, dtype=int)
    for b in range(bits):
        reversed_index |= ((index >> b) & 1) << (bits - 1 - b)
    return reversed_index


# -- generation grid (code_aster's gefact) ---------------------------------


@dataclass
class Grid:
    """Frequencies at which the spectral matrix is sampled for generation."""

    frequencies: np.ndarray
    freq_min: float  # below or at: zero (index test as code_aster's)
    freq_max: float
    warnings: list[str] = field(default_factory=list)
    first_at_zero: bool = False  # INTERPOL='NON': code_aster stores 0 as the first frequency

    def stored_frequencies(self) -> np.ndarray:
        """The frequencies the generation's time step is derived from."""
        stored = self.frequencies.copy()
        if self.first_at_zero:
            stored[0] = 0.0
        return stored


def _is_power_of_two(count: int) -> tuple[bool, float]:
    exponent = math.log(float(count)) / math.log(2.0)
    frac = abs(exponent - math.trunc(exponent))
    return not (frac >= 1.0e-6 and abs(1.0 - frac) >= 1.0e-6), exponent


def is_power_of_two(count: int) -> bool:
    """code_aster's test (log2 within 1e-6 of an integer)."""
    return count > 0 and _is_power_of_two(count)[0]


def generation_grid(disc, interpolate: bool, freq_init, freq_fin, nb_poin, duree) -> Grid:
    """Step and point count of the generation, from the keywords as
    code_aster derives them (``duree`` < 0 when DUREE_TIRAGE is absent)."""
    disc = np.asarray(disc, dtype=float)
    warnings: list[str] = []
    if not interpolate:
        return _grid_without_interpolation(disc, nb_poin, warnings)
    freqf = freq_fin if freq_fin is not None else float(disc[-1])
    freqi = freq_init if freq_init is not None else float(disc[0])
    steps = np.abs(np.diff(disc))
    pmin = float(steps.min()) if steps.size else 1.0e10
    pmin = min(pmin, 1.0e10)
    if duree > 0.0:
        dfreq = 1.0 / duree
        if nb_poin is not None:
            nbpoin = nb_poin
            dt = duree / nbpoin / 2.0
            if 1.0 / dt < 2.0 * freqf:
                nbpoin = 2 ** int(math.log(2.0 * freqf * duree) / math.log(2.0))
                warnings.append(f"NB_POIN raised to {nbpoin} (Shannon)")
        else:
            nbpoin = 2 ** int(math.log(2.0 * freqf * duree) / math.log(2.0))
            if dfreq > 2 * pmin and pmin > 0.0:
                warnings.append(f"DUREE_TIRAGE shorter than 1/step of the spectrum ({1 / pmin})")
    else:
        if nb_poin is not None:
            nbpoin = nb_poin
            exact, exponent = _is_power_of_two(nbpoin)
            if not exact:
                nbpoin = 2 ** (int(exponent) + 1)
                warnings.append(f"NB_POIN rounded up to a power of two: {nbpoin}")
            dfreq = freqf / (nbpoin - 1)
            if dfreq > pmin and pmin > 0.0:
                warnings.append(f"NB_POIN {nbpoin} coarser than the spectrum's step")
        elif pmin > 0.0:
            dfreq = pmin
            nbpoin = max(2 ** int(math.log(2.0 * freqf / pmin) / math.log(2.0)), 256)
        else:
            nbpoin = 256
            dfreq = (freqf - freqi) / float(nbpoin - 1)
    if float(nbpoin - 1) * dfreq > (freqf - freqi):
        frinit = max(freqf - float(nbpoin) * dfreq, 0.0)
    else:
        frinit = freqi
    frequencies = np.array([frinit + float(k) * dfreq for k in range(nbpoin)])
    return Grid(frequencies, freqi, freqf, warnings)


def _grid_without_interpolation(disc, nb_poin, warnings) -> Grid:
    nbval = disc.size
    pas = (disc[-1] - disc[0]) / (nbval - 1)
    if np.any(np.abs(np.diff(disc) - pas) > 1.0e-6):
        raise ValueError("INTERPOL='NON' needs a spectrum on a constant frequency step")
    if nb_poin is not None and nb_poin < nbval:
        freqf = float(disc[nb_poin - 1])
        warnings.append(f"the spectrum is cut at {freqf}")
    else:
        freqf = float(disc[-1])
    dfreq = pas
    freqi = float(disc[0])
    frinit = math.fmod(freqi, dfreq)
    nbpoin = 2 ** (int(math.log(freqf / dfreq) / math.log(2.0)) + 1)
    if nb_poin is not None:
        if nbpoin > nb_poin:
            warnings.append(f"NB_POIN raised to {nbpoin}")
        else:
            exact, exponent = _is_power_of_two(nb_poin)
            nbpoin = nb_poin if exact else 2 ** (int(exponent) + 1)
    frequencies = np.array([frinit + float(k) * dfreq for k in range(nbpoin)])
    return Grid(frequencies, freqi, freqf, warnings, first_at_zero=True)


def _support(grid: Grid) -> tuple[int, int]:
    """code_aster's iinf / isup (1-based): the samples kept are iinf < k < isup."""
    iinf, isup = 0, grid.frequencies.size + 1
    for k, freq in enumerate(grid.frequencies, start=1):
        if freq < grid.freq_min:
            iinf = k
        if freq > grid.freq_max:
            isup = k
            break
    return iinf, isup


def _linear(disc: np.ndarray, values: np.ndarray, freq: float):
    """Linear interpolation, constant beyond both ends (code_aster's folocx 'CC')."""
    if freq <= disc[0]:
        return values[0]
    if freq >= disc[-1]:
        return values[-1]
    i = int(np.searchsorted(disc, freq, side="right")) - 1
    x1, x2 = disc[i], disc[i + 1]
    y1, y2 = values[i], values[i + 1]
    if np.iscomplexobj(values):
        re = y1.real + (freq - x1) * (y2.real - y1.real) / (x2 - x1)
        im = y1.imag + (freq - x1) * (y2.imag - y1.imag) / (x2 - x1)
        return complex(re, im)
    return y1 + (freq - x1) * (y2 - y1) / (x2 - x1)


def sampled_matrix(inter, grid: Grid, interpolate: bool) -> np.ndarray:
    """The Hermitian spectral matrix at each grid frequency, (n, dim, dim)."""
    numbers = inter.order_numbers()
    where = {n: k for k, n in enumerate(numbers)}
    count = grid.frequencies.size
    out = np.zeros((count, len(numbers), len(numbers)), dtype=complex)
    iinf, isup = _support(grid)
    for (i, j), vals in zip(inter.keys, inter.values, strict=True):
        column = np.zeros(count, dtype=complex)
        for k in range(iinf + 1, min(isup, count + 1)):
            if interpolate:
                column[k - 1] = _linear(inter.disc, vals, grid.frequencies[k - 1])
            else:
                index = k - iinf - 1
                if index >= vals.size:
                    raise ValueError("the spectrum has fewer points than the generation needs")
                column[k - 1] = vals[index]
        out[:, where[i], where[j]] = column
        if i != j:
            out[:, where[j], where[i]] = np.conj(column)
    return out


# -- factorization (code_aster's facint) -----------------------------------


def _largest_component(vector: np.ndarray) -> int:
    """First index of the largest |re| + |im| (BLAS izamax), ties within rounding."""
    size = np.abs(vector.real) + np.abs(vector.imag)
    return int(np.flatnonzero(size >= size.max() * (1.0 - 1.0e-12))[0])


def factor(matrix: np.ndarray) -> np.ndarray:
    """R with R R^H = S for one Hermitian matrix, in code_aster's convention."""
    if matrix[0, 0] == 0.0:
        if np.any(matrix != 0.0):
            raise ValueError(
                "a spectral matrix with a zero first diagonal term must be zero at that frequency"
            )
        return matrix.copy()
    eigenvalues, vectors = np.linalg.eigh(matrix)
    r = np.empty_like(vectors)
    for j in range(vectors.shape[1]):
        v = vectors[:, j] / vectors[_largest_component(vectors[:, j]), j]
        v = v / math.sqrt(float(np.sum(v.real**2 + v.imag**2)))
        r[:, j] = v * math.sqrt(max(float(eigenvalues[j]), 0.0))
    return r


# -- generation (code_aster's op0118 / genale) --------------------------------


def deck_phases(session, seed: int | None = None) -> PhaseSource:
    """The deck's random stream, kept on its session: created at first use
    (seed 0), re-seeded by INIT_ALEA."""
    stream = getattr(session, "random_phases", None)
    if seed is not None or stream is None:
        stream = PhaseSource(0 if seed is None else seed)
        session.random_phases = stream
    return stream


class PhaseSource:
    """code_aster's random numbers: Python's generator seeded with 0, or
    with INIT_ALEA; one stream per deck, as code_aster keeps one per run."""

    def __init__(self, seed: int = 0):
        self.generator = random.Random(100)
        self.generator.seed(seed)

    def uniform(self, count: int) -> np.ndarray:
        draw = self.generator.random
        return np.array([draw() for _ in range(count)])


@dataclass
class Signals:
    times: np.ndarray
    values: np.ndarray  # (dim, n_times)
    dt: float
    n_fft: int


def generate(factors: np.ndarray, frequencies: np.ndarray, draws: int, phases) -> Signals:
    """Time signals of ``draws`` concatenated draws from the factorized matrix
    ``factors`` (n_freq, dim, dim) sampled at ``frequencies``."""
    n_freq, dim, _ = factors.shape
    exact, exponent = _is_power_of_two(n_freq)
    ln = n_freq if exact else 2 ** int(exponent)
    ln2 = 2 * ln
    dfreq = (frequencies[ln - 1] - frequencies[0]) / (ln - 1)
    dt = (1.0 / dfreq) / ln2
    out = np.zeros((dim, ln2 * draws + 1))
    scale = math.sqrt(ln2 / dt)
    for draw in range(draws):
        u = phases.uniform(ln * dim) * 2.0 * math.pi
        # the C library's cos/sin, as code_aster's exp(i u)
        x = np.array([complex(math.cos(a), math.sin(a)) for a in u]).reshape(ln, dim)
        v = np.zeros((ln, dim), dtype=complex)
        for j in range(dim):  # code_aster's accumulation order
            v += factors[:ln, :, j] * x[:, j : j + 1]
        for comp in range(dim):
            spectrum = np.zeros(ln2, dtype=complex)
            spectrum[1:ln] = v[1:ln, comp]
            spectrum[ln + 1 :] = np.conj(v[1:ln, comp])[::-1]
            signal = radix2_fft(spectrum * scale, inverse=True)
            out[comp, 1 + ln2 * draw : 1 + ln2 * (draw + 1)] = signal.real
    times = dt * np.arange(ln2 * draws + 1, dtype=float)
    return Signals(times, out, dt, ln)


# -- spectral estimation (code_aster's op0120) --------------------------------


@dataclass
class Estimate:
    frequencies: np.ndarray
    spectra: dict  # (i, j) -> real (i == j) or complex values
    windows: int


def window_count(t_start: float, t_end: float, duration, shift) -> int:
    if duration is None:
        return 1
    return int(abs(((t_end - t_start) - duration) / shift) + 1)


def estimate(evaluators, t_start, t_end, n_points, duration=None, shift=None) -> Estimate:
    """Averaged periodograms of the functions (callables of time arrays)."""
    if not _is_power_of_two(n_points)[0]:
        raise ValueError(f"NB_POIN={n_points} is not a power of two")
    durana = t_end - t_start if duration is None else duration
    durdec = durana if shift is None else shift
    windows = window_count(t_start, t_end, duration, durdec)
    dt = durana / n_points
    half = n_points // 2
    count = len(evaluators)
    sums = {(i, j): np.zeros(half, dtype=complex) for j in range(count) for i in range(j + 1)}
    for window in range(windows):
        times = np.array(
            [t_start + float(window) * durdec + float(k) * dt for k in range(n_points)]
        )
        transforms = [radix2_fft(f(times).astype(complex))[:half] * dt for f in evaluators]
        for (i, j), acc in sums.items():
            product = transforms[i] * np.conj(transforms[j])
            acc += product.real / durana + 1j * (product.imag / durana)
    dfreq = 1.0 / durana
    frequencies = np.array([float(k) * dfreq for k in range(half)])
    spectra = {}
    for (i, j), acc in sums.items():
        mean = acc.real / float(windows) + 1j * (acc.imag / float(windows))
        spectra[(i + 1, j + 1)] = mean.real if i == j else mean
    return Estimate(frequencies, spectra, windows)
