"""CALC_INTE_SPEC: the spectral matrix of time functions.

code_aster's op0120: NB_POIN samples (a power of two) over each window of
DUREE_ANALYSE, windows shifted by DUREE_DECALAGE from INST_INIT (their count
int(|((INST_FIN - INST_INIT) - DUREE_ANALYSE) / DUREE_DECALAGE| + 1)), one
FFT per function and window, periodograms X_i conj(X_j) dt^2 / T averaged
over the windows, on frequencies k / T for k < NB_POIN / 2.
"""

from __future__ import annotations

from asterlite.concepts.function import Nappe, as_callable_values
from asterlite.concepts.interspectrum import InterSpectrum
from asterlite.post import spectral


def run(ctx, kw):
    n_points = int(kw["NB_POIN"])
    if not spectral.is_power_of_two(n_points):
        ctx.error(f"NB_POIN={n_points} must be a power of two", "NB_POIN", kw)
    functions = kw["FONCTION"]
    if not isinstance(functions, (list, tuple)):
        functions = [functions]
    for func in functions:
        if isinstance(func, Nappe):
            ctx.unsupported(
                "CALC_INTE_SPEC of a nappe (a function of INST alone is read)", "FONCTION", kw
            )
    evaluators = [_evaluator(f) for f in functions]
    estimate = spectral.estimate(
        evaluators,
        float(kw["INST_INIT"]),
        float(kw["INST_FIN"]),
        n_points,
        kw.get("DUREE_ANALYSE"),
        kw.get("DUREE_DECALAGE"),
    )
    ctx.log(
        f"{estimate.windows} windows, frequency step {estimate.frequencies[1]:.4e}, "
        f"from 0 to {estimate.frequencies[-1]:.4e}"
    )
    keys = list(estimate.spectra)
    values = [estimate.spectra[k] for k in keys]
    return InterSpectrum("FREQ", estimate.frequencies, keys, values, title=kw.get("TITRE", ""))


def _evaluator(func):
    return lambda times: as_callable_values(func, times)
