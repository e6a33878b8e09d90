"""DEFI_LIST_FREQ: the list of DEFI_LIST_REEL (VALE, or DEBUT and
INTERVALLE), refined around the frequencies of RAFFINEMENT as code_aster's
defi_list_freq_ops does:

- LIST_RAFFINE is thinned of values within PAS_MINI of the previous one;
- with LARGEUR_3DB, each frequency has a damping (AMOR_REDUIT or LIST_AMOR,
  the last repeated) and is moved to the resonance of its oscillator,
  f sqrt(1 - 2 a²) (a > 1e-12); the band around it is 2 a f wide (0.01 f
  without damping); with RELATIF it is DISPERSION f, with ABSOLU DISPERSION;
- NB_POINTS evenly spaced points cover each band, centred on its frequency;
  an even count adds the centre and f / sqrt(1 - 2 a²);
- the bands join the initial list, sorted, and points within PAS_MINI of the
  previous one are dropped.
"""

from __future__ import annotations

import numpy as np
from asterlite.commands.defi_list_reel import build_intervals

from asterlite.concepts.lists import ListReal
from asterlite.post.restitution import values_of

_EPSILON = 1.0e-12


def _thinned(values: np.ndarray, delta: float, other: np.ndarray | None = None):
    keep = np.ones(values.size, dtype=bool)
    keep[1:] = np.diff(values) > delta
    return values[keep], (other[keep] if other is not None and other.size else other)


def refined(ctx, initial: np.ndarray, occ) -> np.ndarray:
    criterion = occ["CRITERE"]
    step_min = float(occ["PAS_MINI"])
    count = int(occ["NB_POINTS"])
    if count < 2:
        ctx.error("NB_POINTS must be at least 2", "NB_POINTS", occ)
    freq = np.atleast_1d(np.asarray(values_of(occ["LIST_RAFFINE"]), dtype=float))
    damping = np.zeros(0)
    if criterion == "LARGEUR_3DB":
        given = occ.get("AMOR_REDUIT")
        if given is None:
            given = occ["LIST_AMOR"]
        damping = np.atleast_1d(np.asarray(values_of(given), dtype=float))
        extended = np.full(freq.size, damping[-1])
        extended[: min(damping.size, freq.size)] = damping[: freq.size]
        damping = extended
    elif count % 2 == 0:
        ctx.error(
            f"an even NB_POINTS with CRITERE={criterion!r} (code_aster needs the dampings "
            "of LARGEUR_3DB to place its extra points)",
            "NB_POINTS",
            occ,
        )
    freq, damping = _thinned(freq, step_min, damping)
    if damping.size:
        damped = damping > _EPSILON
        freq = freq * np.where(damped, np.sqrt(1.0 - 2.0 * damping**2), 1.0)
    points = []
    for i, frequency in enumerate(freq):
        if criterion == "ABSOLU":
            width = float(occ["DISPERSION"])
        elif criterion == "RELATIF":
            width = float(occ["DISPERSION"]) * frequency
        elif damping[i] > _EPSILON:
            width = 2.0 * damping[i] * frequency
        else:
            width = 0.01 * frequency
        if points and max(points) > frequency - width / 2.0:
            ctx.log(f"DEFI_LIST_FREQ: the bands around {freq[i - 1]:g} and {frequency:g} overlap")
        points.extend(frequency + (np.arange(count) / (count - 1) - 0.5) * width)
    every = np.asarray(points, dtype=float)
    if count % 2 == 0:
        every = np.hstack([every, freq, freq / np.sqrt(1.0 - 2.0 * damping**2)])
    every = np.sort(np.hstack([every, initial]))
    return _thinned(every, step_min)[0]


def run(ctx, kw):
    if kw.get("VALE") is not None:
        initial = np.asarray(values_of(kw["VALE"]), dtype=float)
    else:
        initial = build_intervals(ctx, kw, float(kw["DEBUT"]), kw.factor("INTERVALLE"), float)
    occs = kw.factor("RAFFINEMENT")
    if not occs:
        return ListReal(initial)
    values = refined(ctx, initial, occs[0])
    ctx.log(f"DEFI_LIST_FREQ: {initial.size} frequencies, {values.size} once refined")
    return ListReal(values)
