"""Operations on tabulated functions (CALC_FONCTION, INFO_FONCTION).

Each operation takes and returns :class:`~asterlite.concepts.function.Function`
objects and follows code_aster's conventions (t_fonction): combinations are
computed on the union of the abscissas, restricted to where every function is
defined (a PROL_*='EXCLU' side bounds the support); integrals and derivatives
keep the abscissas and become EXCLU on both sides; NOM_RESU follows
DEPL → VITE → ACCE when deriving (and back when integrating).
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.function import Function
from asterlite.errors import CommandError

# ---------------------------------------------------------------- supports


def common_support(functions: list[Function]) -> tuple[np.ndarray, str, str]:
    """Union of the abscissas, clipped to where all the functions can be
    evaluated, and the prolongations that go with the retained ends."""
    first = functions[0]
    xs, left, right = first.abscissas, first.PROL_GAUCHE, first.PROL_DROITE
    for other in functions[1:]:
        xs, left, right = _pair_support(xs, left, right, other)
    return xs, left, right


def _pair_support(xs, left, right, other: Function):
    ox = other.abscissas
    # left end: the later start wins when that side cannot be extended
    if ox[0] > xs[0]:
        x_min, left = (xs[0], left) if other.PROL_GAUCHE != "EXCLU" else (ox[0], other.PROL_GAUCHE)
    else:
        x_min, left = (ox[0], other.PROL_GAUCHE) if left != "EXCLU" else (xs[0], left)
    if xs[-1] > ox[-1]:
        x_max, right = (
            (xs[-1], right) if other.PROL_DROITE != "EXCLU" else (ox[-1], other.PROL_DROITE)
        )
    else:
        x_max, right = (ox[-1], other.PROL_DROITE) if right != "EXCLU" else (xs[-1], right)
    union = np.unique(np.clip(np.concatenate([xs, ox]), x_min, x_max))
    return union, left, right


def combine(functions: list[Function], coefficients: list) -> Function:
    """Σ coef_i · f_i on the common support (COMB, COMB_C)."""
    xs, left, right = common_support(functions)
    total = sum(c * f.evaluate(xs) for f, c in zip(functions, coefficients, strict=True))
    return functions[0].with_values(xs, total, PROL_GAUCHE=left, PROL_DROITE=right)


def multiply(functions: list[Function]) -> Function:
    """Π f_i on the common support (MULT)."""
    xs, left, right = common_support(functions)
    product = np.ones(xs.size, dtype=np.result_type(*[f.ordinates for f in functions], float))
    for f in functions:
        product = product * f.evaluate(xs)
    return functions[0].with_values(xs, product, PROL_GAUCHE=left, PROL_DROITE=right)


def envelope(functions: list[Function], criterion: str = "SUP") -> Function:
    """Pointwise max (SUP) or min (INF) on the union of the abscissas."""
    xs = np.unique(np.concatenate([f.abscissas for f in functions]))
    values = np.array([f.evaluate(xs) for f in functions])
    pick = np.max if criterion == "SUP" else np.min
    return functions[0].with_values(xs, pick(values, axis=0))


def power(func: Function, exponent: int) -> Function:
    return func.with_values(func.abscissas, func.ordinates**exponent)


def absolute(func: Function) -> Function:
    """|f|; a linear extension would no longer be meaningful: EXCLU instead."""
    return func.with_values(
        func.abscissas,
        np.abs(func.ordinates),
        PROL_GAUCHE="EXCLU" if func.PROL_GAUCHE == "LINEAIRE" else func.PROL_GAUCHE,
        PROL_DROITE="EXCLU" if func.PROL_DROITE == "LINEAIRE" else func.PROL_DROITE,
    )


def compose(outer: Function, inner: Function) -> Function:
    """outer(inner(x)) at the abscissas of inner (COMPOSE)."""
    return outer.with_values(
        inner.abscissas, outer.evaluate(inner.ordinates), NOM_PARA=inner.NOM_PARA
    )


def inverse(func: Function) -> Function:
    """x(y): abscissas and ordinates swapped (monotonic functions only)."""
    x, y = func.ordinates.astype(float), func.abscissas
    if np.all(np.diff(x) < 0):
        x, y = x[::-1], y[::-1]
    elif not np.all(np.diff(x) > 0):
        raise CommandError("INVERSE: the function is not strictly monotonic")
    return func.with_values(
        x,
        y,
        NOM_RESU="TOUTRESU",
        INTERPOL=tuple(reversed(func.INTERPOL)),
        PROL_GAUCHE="EXCLU" if func.PROL_GAUCHE == "CONSTANT" else func.PROL_GAUCHE,
        PROL_DROITE="EXCLU" if func.PROL_DROITE == "CONSTANT" else func.PROL_DROITE,
    )


def extract(func: Function, part: str) -> Function:
    """REEL, IMAG, MODULE or PHASE (degrees) of a complex function."""
    y = func.ordinates
    values = {
        "REEL": lambda: y.real,
        "IMAG": lambda: y.imag,
        "MODULE": lambda: np.abs(y),
        "PHASE": lambda: np.degrees(np.angle(y)),
    }[part]()
    return func.with_values(func.abscissas, np.asarray(values, dtype=float))


def concatenate(first: Function, second: Function, overwrite: str = "DROITE") -> Function:
    """ASSE: two functions end to end; where they overlap, the right one
    (SURCHARGE='DROITE') or the left one ('GAUCHE') is kept."""
    if tuple(first.INTERPOL) != tuple(second.INTERPOL):
        raise CommandError("ASSE: the two functions have different INTERPOL")
    f1, f2 = (first, second) if first.abscissas.min() < second.abscissas.min() else (second, first)
    if overwrite == "GAUCHE":
        i = np.searchsorted(f2.abscissas, f1.abscissas[-1])
        x = np.concatenate([f1.abscissas, f2.abscissas[i:]])
        y = np.concatenate([f1.ordinates, f2.ordinates[i:]])
        right = f2.PROL_DROITE if i != f2.abscissas.size else f1.PROL_DROITE
    else:
        i = np.searchsorted(f1.abscissas, f2.abscissas[0])
        x = np.concatenate([f1.abscissas[:i], f2.abscissas])
        y = np.concatenate([f1.ordinates[:i], f2.ordinates])
        right = f2.PROL_DROITE if i != f1.abscissas.size else f1.PROL_DROITE
    return first.with_values(x, y, PROL_GAUCHE=f1.PROL_GAUCHE, PROL_DROITE=right)


# ------------------------------------------------------- calculus


def _integrated_name(name: str) -> str:
    return {"VITE": "DEPL", "ACCE": "VITE"}.get(name[:4], name)


def _derived_name(name: str) -> str:
    return {"DEPL": "VITE", "VITE": "ACCE"}.get(name[:4], name)


def primitive_trapezoid(x, y, constant: float = 0.0) -> np.ndarray:
    steps = (y[1:] + y[:-1]) / 2 * np.diff(x)
    return constant + np.concatenate([[0.0], np.cumsum(steps)])


def primitive_simpson(x, y, constant: float = 0.0) -> np.ndarray:
    """code_aster's Simpson primitive: a trapezoid on the first step, then
    two interleaved Simpson sums over consecutive pairs of steps (each new
    point extends the sum that ended two points before), with the weights of
    a parabola through three unevenly spaced points."""
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    n = x.size
    out = np.empty(n)
    out[0] = constant
    if n == 1:
        return out
    out[1] = constant + (y[0] + y[1]) * (x[1] - x[0]) / 2
    sums = [out[0], out[1]]
    for i in range(2, n):
        h1, h2 = x[i - 1] - x[i - 2], x[i] - x[i - 1]
        delta = h2 - h1
        if h1 == 0 or h2 == 0 or abs(delta / h1) <= 1e-4:
            weights = (1.0, 4.0, 1.0)
        else:
            e = delta / (h1 * h2)
            weights = (1.0 - e * h2, 2.0 + e * delta, 1.0 + e * h1)
        k = i % 2  # the running sum that ended at i - 2
        sums[k] += (
            (h1 + h2) / 6 * (weights[0] * y[i - 2] + weights[1] * y[i - 1] + weights[2] * y[i])
        )
        out[i] = sums[k]
    return out


def integrate(func: Function, method: str = "TRAPEZE", constant: float = 0.0) -> Function:
    x, y = func.abscissas, func.ordinates
    if x.size < 2:
        raise CommandError("INTEGRE: the function needs at least two points")
    rule = primitive_simpson if method == "SIMPSON" else primitive_trapezoid
    return func.with_values(
        x, rule(x, y, constant), NOM_RESU=_integrated_name(func.NOM_RESU),
        PROL_GAUCHE="EXCLU", PROL_DROITE="EXCLU",
    )  # fmt: skip


def derivative(func: Function) -> Function:
    """Centred differences weighted by the step lengths; one-sided at the ends."""
    x, y = func.abscissas, func.ordinates
    if x.size < 2:
        raise CommandError("DERIVE: the function needs at least two points")
    steps = np.diff(x)
    slopes = np.diff(y) / steps
    inner = (slopes[1:] * steps[1:] + slopes[:-1] * steps[:-1]) / (steps[1:] + steps[:-1])
    values = np.concatenate([[slopes[0]], inner, [slopes[-1]]])
    return func.with_values(
        x, values, NOM_RESU=_derived_name(func.NOM_RESU), PROL_GAUCHE="EXCLU", PROL_DROITE="EXCLU"
    )


def _without_linear_trend(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """y minus its least-squares line a1 x + a0."""
    n = x.size
    sx, sy, sxy, sxx = x.sum(), y.sum(), (x * y).sum(), (x * x).sum()
    det = n * sxx - sx * sx
    a1 = (n * sxy - sx * sy) / det
    a0 = (sxx * sy - sx * sxy) / det
    return y - a1 * x - a0


def high_pass_clough_penzien(y: np.ndarray, dt: float, corner: float, damping: float = 1.0):
    """The signal through the second-order high-pass filter of Clough and
    Penzien, H(w) = -w^2 / (wc^2 - w^2 + 2 i xi wc w), applied on its real
    FFT (the signal is taken periodic over its length)."""
    n = y.size
    wc = 2.0 * np.pi * corner
    w = 2.0 * np.pi * np.fft.rfftfreq(n, d=dt)
    gain = -(w**2) / ((wc**2 - w**2) + 2.0j * damping * wc * w)
    return np.fft.irfft(np.fft.rfft(y) * gain, n=n)


def corrected_accelerogram(
    func: Function, method: str, corner: float = 0.05, correct_displacement: bool = False
) -> Function:
    """CORR_ACCE. FILTRAGE: the Clough-Penzien high-pass filter at ``corner``
    Hz (the step taken from the first two abscissas). POLYNOME: the linear
    trend of the acceleration removed, then that of its velocity (and, with
    ``correct_displacement``, of its displacement), each by integrating
    (trapezoids from 0) and differentiating back."""
    x, y = func.abscissas, func.ordinates
    if x.size < 3:
        raise CommandError("CORR_ACCE: the function needs at least three points")
    if method == "FILTRAGE":
        values = high_pass_clough_penzien(y, float(x[1] - x[0]), corner)
        return func.with_values(x, values)
    velocity = _without_linear_trend(x, primitive_trapezoid(x, _without_linear_trend(x, y)))
    if correct_displacement:
        displacement = _without_linear_trend(x, primitive_trapezoid(x, velocity))
        velocity = derivative(func.with_values(x, displacement)).ordinates
    values = derivative(func.with_values(x, velocity)).ordinates
    return func.with_values(x, values, PROL_GAUCHE="EXCLU", PROL_DROITE="EXCLU")


# ------------------------------------------------------------------ FFT


def _power_of_two_below(n: int) -> int:
    return int(np.floor(np.log2(n))) if n > 0 else 0


def _constant_step(x, tolerance: float, what: str) -> float:
    step = x[1] - x[0]
    if np.any(np.abs((np.diff(x) - step) / step) > tolerance):
        raise CommandError(f"FFT: the {what} function must have a constant step")
    return step


def _fft_length_rule(y: np.ndarray, method: str) -> np.ndarray:
    """METHODE: TRONCATURE keeps the largest power of two of samples,
    PROL_ZERO pads with zeros up to the next one (when not already one),
    COMPLET keeps every sample."""
    n = _power_of_two_below(y.size)
    if method == "TRONCATURE":
        return y[: 2**n]
    if method == "PROL_ZERO" and y.size > 2**n:
        return np.concatenate([y, np.zeros(2 ** (n + 1) - y.size, dtype=y.dtype)])
    return y


def fft(func: Function, method: str = "PROL_ZERO") -> Function:
    """Discrete Fourier transform of a real function of INST on an even grid."""
    if func.NOM_PARA != "INST":
        raise CommandError("FFT of a real function needs NOM_PARA='INST'")
    step = _constant_step(func.abscissas, 1e-2, "real")
    spectrum = np.fft.fft(_fft_length_rule(np.asarray(func.ordinates), method))
    freqs = np.arange(spectrum.size) / (step * spectrum.size)
    return func.with_values(freqs, spectrum, NOM_PARA="FREQ")


def inverse_fft(func: Function, method: str = "PROL_ZERO", symmetric: bool = True) -> Function:
    """Real signal of INST from a complex function of FREQ (code_aster's
    inverse FFT). symmetric: the function already holds the whole two-sided
    spectrum. Otherwise it holds the positive half, which is mirrored
    (complex conjugates) after the value at the Nyquist frequency; that value
    is extrapolated by a parabola with a horizontal tangent there,
    (4 Y[-1] - Y[-2]) / 3 on the real parts, except when an odd-length half
    already ends on a real value."""
    if func.NOM_PARA != "FREQ":
        raise CommandError("FFT of a complex function needs NOM_PARA='FREQ'")
    step = _constant_step(func.abscissas, 1e-3, "complex")
    y = np.asarray(func.ordinates, dtype=complex)
    if symmetric:
        full = y
    else:
        half = _fft_length_rule(y, method).copy()
        if half.size % 2 == 0:
            nyquist = (4 * half[-1].real - half[-2].real) / 3
            full = np.concatenate([half, [nyquist], np.conj(half[1:])[::-1]])
        else:
            if not abs(half[-1].imag) < abs(half[-1].real * 1e-6):
                half[-1] = (4 * half[-2].real - half[-3].real) / 3
            else:
                half[-1] = half[-1].real
            full = np.concatenate([half, np.conj(half[1:-1])[::-1]])
    signal = np.fft.ifft(full).real
    times = np.arange(signal.size) / (step * signal.size)
    return func.with_values(times, signal, NOM_PARA="INST")


# ---------------------------------------------------------- response spectra


def sdof_history(t, accel, freq: float, damping: float) -> tuple[np.ndarray, np.ndarray]:
    """Relative displacement and velocity of a damped oscillator at rest at
    t[0] under a base acceleration linear between samples (exact piecewise
    solution, Nigam & Jennings)."""
    w = 2 * np.pi * freq
    wd = w * np.sqrt(1 - damping * damping)
    u, v = np.zeros(len(t)), np.zeros(len(t))
    for k in range(len(t) - 1):
        u[k + 1], v[k + 1] = _sdof_step(
            u[k], v[k], -accel[k], -accel[k + 1], t[k + 1] - t[k], w, damping, wd
        )
    return u, v


def sdof_peak_response(t, accel, freq: float, damping: float) -> tuple[float, float, float]:
    """Peak |relative displacement|, |relative velocity| and |absolute
    acceleration| of the oscillator of :func:`sdof_history`."""
    u, v = sdof_history(t, accel, freq, damping)
    w = 2 * np.pi * freq
    absolute_acc = -2 * damping * w * v - w * w * u
    return float(np.abs(u).max()), float(np.abs(v).max()), float(np.abs(absolute_acc).max())


def _sdof_step(u0, v0, p0, p1, dt, w, xi, wd):
    """One step of u'' + 2ξω u' + ω² u = p(t), p linear on [0, dt]."""
    e = np.exp(-xi * w * dt)
    s, c = np.sin(wd * dt), np.cos(wd * dt)
    w2 = w * w
    slope = (p1 - p0) / dt
    # particular solution of the linear load: up(t) = (p0 + slope·t)/ω² - 2ξ slope/ω³
    up0 = p0 / w2 - 2 * xi * slope / (w2 * w)
    vp = slope / w2
    a = u0 - up0
    b = (v0 - vp + xi * w * a) / wd
    u1 = e * (a * c + b * s) + p1 / w2 - 2 * xi * slope / (w2 * w)
    v1 = e * ((-xi * w * a + wd * b) * c + (-xi * w * b - wd * a) * s) + vp
    return u1, v1


def peak_relative_displacements(t, accel, freqs, damping: float) -> np.ndarray:
    """max|u| over time for each oscillator frequency: the recurrence of
    :func:`sdof_history` run for all the frequencies at once."""
    w = 2 * np.pi * np.asarray(freqs, dtype=float)
    wd = w * np.sqrt(1 - damping * damping)
    u, v = np.zeros(w.size), np.zeros(w.size)
    peak = np.zeros(w.size)
    for k in range(len(t) - 1):
        u, v = _sdof_step(u, v, -accel[k], -accel[k + 1], t[k + 1] - t[k], w, damping, wd)
        np.maximum(peak, np.abs(u), out=peak)
    return peak


def response_spectrum(func: Function, freqs, damping: float, nature: str, norme: float):
    """Oscillator spectrum: pseudo-acceleration ω²·max|u| (ACCE), pseudo-velocity
    ω·max|u| (VITE) or max|u| (DEPL) under the function's acceleration, divided
    by NORME (code_aster scales the spectrum, not the accelerogram)."""
    peak_u = peak_relative_displacements(func.abscissas, func.ordinates, freqs, damping)
    w = 2 * np.pi * np.asarray(freqs, dtype=float)
    values = {"DEPL": peak_u, "VITE": w * peak_u, "ACCE": w * w * peak_u}[nature]
    return values / norme


# ------------------------------------------------------------ statistics


def extrema(func: Function, intervals=None) -> list[tuple[str, float, float]]:
    """(MINI/MAXI, abscissa, value) for each extreme value (ties kept), per interval."""
    x, y = func.abscissas, np.real(func.ordinates)
    windows = (
        [(x[0], x[-1])]
        if not intervals
        else list(zip(intervals[::2], intervals[1::2], strict=True))
    )
    rows = []
    for low, high in windows:
        inside = (x >= low) & (x <= high)
        xs, ys = x[inside], y[inside]
        if ys.size == 0:
            continue
        for kind, target in (("MINI", ys.min()), ("MAXI", ys.max())):
            for xi in xs[ys == target]:
                rows.append((kind, float(xi), float(target)))
    return rows


def _near(x: np.ndarray, bound: float, precision: float, criterion: str) -> np.ndarray:
    """Abscissas that code_aster takes as the bound itself (CRITERE/PRECISION;
    RELATIF scales by the bound as it does, so a bound of zero matches exactly)."""
    tolerance = precision if criterion == "ABSOLU" else precision * bound
    return ~(np.abs(x - bound) > tolerance)


def cut(
    func: Function, start=None, stop=None, precision: float = 1e-6, criterion: str = "RELATIF"
) -> Function:
    """The function restricted to [start, stop], interpolated at the ends; an
    abscissa within the tolerance of an end is taken as that end."""
    x = func.abscissas
    lo = x[0] if start is None else start
    hi = x[-1] if stop is None else stop
    keep = (x > lo) & (x < hi) & ~_near(x, lo, precision, criterion)
    keep &= ~_near(x, hi, precision, criterion)
    xs = np.concatenate([[lo], x[keep], [hi]])
    return func.with_values(xs, func.evaluate(xs), PROL_GAUCHE="EXCLU", PROL_DROITE="EXCLU")


def _window(func, method, start, stop, precision, criterion):
    part = cut(func, start, stop, precision, criterion)
    rule = primitive_simpson if method == "SIMPSON" else primitive_trapezoid
    return part.abscissas, np.real(part.ordinates), rule


def rms(
    func: Function, method="TRAPEZE", start=None, stop=None, precision=1e-6, criterion="RELATIF"
) -> float:
    """sqrt(∫ f² dt / duration) over [start, stop]."""
    x, y, rule = _window(func, method, start, stop, precision, criterion)
    return float(np.sqrt(rule(x, y * y)[-1] / (x[-1] - x[0])))


def standard_deviation(
    func: Function, method="TRAPEZE", start=None, stop=None, precision=1e-6, criterion="RELATIF"
) -> float:
    x, y, rule = _window(func, method, start, stop, precision, criterion)
    duration = x[-1] - x[0]
    mean = rule(x, y)[-1] / duration
    return float(np.sqrt(max(rule(x, (y - mean) ** 2)[-1] / duration, 0.0)))
