"""DEFI_INTE_SPEC: a spectral matrix (``interspectre``) term by term.

As code_aster's op0115: PAR_FONCTION terms keep their function's values (a
diagonal term its real part, an off-diagonal term of a real function a zero
imaginary part), all on the abscissas of the last function given;
KANAI_TAJIMI and CONSTANT terms are sampled from FREQ_MIN to FREQ_MAX by
PAS (the last point exactly FREQ_MAX). DIMENSION is not read (code_aster
reads it nowhere either): the terms define the matrix.
"""

from __future__ import annotations

import math

import numpy as np

from asterlite.concepts.interspectrum import InterSpectrum


def run(ctx, kw):
    kw.mark_used("DIMENSION")  # op0115 never reads it
    keys, values, disc = [], [], None
    for occ in kw.factor("PAR_FONCTION"):
        func = occ["FONCTION"]
        key = term_key(occ)
        if values and func.abscissas.size != values[-1].size:
            ctx.error("every function must have the same number of points", "FONCTION", occ)
        keys.append(key)
        values.append(stored_values(func.ordinates, is_diagonal(key)))
        disc = func.abscissas
    for name, formula in (("KANAI_TAJIMI", kanai_tajimi), ("CONSTANT", None)):
        for occ in kw.factor(name):
            if occ["FREQ_MAX"] < occ["FREQ_MIN"]:
                ctx.error("FREQ_MAX is below FREQ_MIN", "FREQ_MAX", occ)
            occ.mark_used("INTERPOL", "PROL_DROITE", "PROL_GAUCHE")  # op0115 stores samples only
            freqs = analytic_frequencies(occ["FREQ_MIN"], occ["FREQ_MAX"], occ["PAS"])
            key = term_key(occ)
            keys.append(key)
            values.append(analytic_values(occ, key, freqs, formula))
            if disc is None:
                disc = freqs
    _check_keys(ctx, kw, keys)
    return InterSpectrum("FREQ", disc, keys, values, title=kw.get("TITRE", ""))


def term_key(occ):
    if occ.get("NUME_ORDRE_I") is not None:
        return (int(occ["NUME_ORDRE_I"]), int(occ["NUME_ORDRE_J"]))
    return (str(occ["NOEUD_I"]), occ["NOM_CMP_I"], str(occ["NOEUD_J"]), occ["NOM_CMP_J"])


def is_diagonal(key) -> bool:
    half = len(key) // 2
    return key[:half] == key[half:]


def stored_values(ordinates: np.ndarray, diagonal: bool) -> np.ndarray:
    """A diagonal term is real (code_aster keeps the real part of a complex
    function), an off-diagonal one complex."""
    if diagonal:
        return np.asarray(ordinates.real, dtype=float).copy()
    return np.asarray(ordinates, dtype=complex).copy()


def analytic_frequencies(fmin: float, fmax: float, step: float) -> np.ndarray:
    count = int((fmax - fmin) / step) + 1
    freqs = np.array([fmin + step * float(k) for k in range(count)])
    freqs[-1] = fmax
    return freqs


def kanai_tajimi(occ, freqs: np.ndarray, level: float) -> np.ndarray:
    """code_aster's Kanai-Tajimi density (2 pi S0 (fg^4 + 4 xi^2 fg^2 f^2) / ...)."""
    fmoy, xi = occ["FREQ_MOY"], occ["AMOR_REDUIT"]
    out = np.empty(freqs.size)
    for k, freq in enumerate(freqs):
        rbid = 4.0 * xi * xi * fmoy * fmoy * freq * freq
        num = rbid + fmoy * fmoy * fmoy * fmoy
        den = fmoy * fmoy - freq * freq
        den = den * den + rbid
        out[k] = 2.0 * math.pi * level * num / den
    return out


def analytic_values(occ, key, freqs, formula) -> np.ndarray:
    diagonal = is_diagonal(key)
    if occ.get("VALE_R") is not None:
        level = complex(float(occ["VALE_R"]))
    else:
        level = complex(occ["VALE_C"])
    if formula is not None:
        # code_aster keeps the real part of VALE_C, and stores the density as real
        return formula(occ, freqs, level.real)
    if diagonal:
        return np.full(freqs.size, level.real)
    return np.full(freqs.size, level, dtype=complex)


def _check_keys(ctx, kw, keys) -> None:
    kinds = {len(k) for k in keys}
    if len(kinds) > 1:
        ctx.error("terms are given both by order numbers and by nodes", None, kw)
    if len(set(keys)) != len(keys):
        ctx.error("a term of the matrix is given twice", None, kw)
