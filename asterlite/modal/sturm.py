"""Sturm counts of a real symmetric pencil (K, M), as INFO_MODE takes them.

The number of eigenvalues ω² below a shift σ is the number of negative
pivots of K - σ M (Sylvester's law of inertia, M positive definite). A shift
on an eigenvalue makes K - σ M singular: code_aster then moves it (vpfopr):
a bound closer to 0 than the threshold ω_c² goes to ∓ω_c², any other
one moves away from the band by max(ω_c², p |σ|), p doubling from
PREC_SHIFT at each try, NMAX_ITER_SHIFT tries at most. The count in a
band is the difference of the counts at its two (moved) bounds; a band's
lower bound is the previous band's upper one.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.modal.eigen import EigenError, ReducedPencil

# a dense pencil's shift is on an eigenvalue when it is this close to it,
# relative to the spectrum's scale (code_aster's factorisation loses its
# NPREC=8 digits there)
_SINGULAR = 1e-8


@dataclass
class ShiftRule:
    """How a singular shift is moved (COMPTAGE: SEUIL_*, PREC_SHIFT, NMAX_ITER_SHIFT)."""

    threshold: float  # ω_c², in the pencil's eigenvalue unit
    precision: float = 5e-2
    max_tries: int = 3


@dataclass
class BandCounts:
    counts: np.ndarray  # eigenvalues in each band
    lower: np.ndarray  # each band's bounds once moved off eigenvalues
    upper: np.ndarray


def count_below(pencil: ReducedPencil, sigma: float, forced: bool = False) -> int | None:
    """Eigenvalues below σ, or None when K - σ M is singular (``forced``: the
    count of a dense pencil all the same, as code_aster goes on with the
    pivots of its last factorisation)."""
    if pencil.dense:
        values = pencil.all_modes()[0]
        if values.size == 0:
            return 0
        scale = max(float(np.abs(values).max()), abs(sigma), 1e-300)
        if not forced and np.min(np.abs(values - sigma)) <= _SINGULAR * scale:
            return None
        return int(np.count_nonzero(values < sigma))
    return pencil.count_below(sigma)


def moved_count(pencil: ReducedPencil, sigma: float, rule: ShiftRule, direction: float, log=None):
    """(count, shift) at σ, moved by ``direction`` (-1 down, +1 up) while singular;
    after NMAX_ITER_SHIFT moves (or once moved to ∓ω_c²) the count is taken
    there anyway, with an alarm, as code_aster does."""
    precision = rule.precision
    tries = 0
    while True:
        last = tries >= rule.max_tries
        count = count_below(pencil, sigma, forced=last)
        if count is not None:
            if last and tries and log is not None:
                log(f"alarm: the shift {sigma:.6g} is still close to an eigenvalue: counted there")
            return count, sigma
        if last:
            raise EigenError(
                f"the shift {sigma:.6g} stays on an eigenvalue after {rule.max_tries} moves "
                "(raise NMAX_ITER_SHIFT or PREC_SHIFT)"
            )
        tries += 1
        if abs(sigma) < rule.threshold:
            sigma = direction * rule.threshold
            tries = rule.max_tries  # code_aster tries this shift once more, then stops
        else:
            sigma += direction * max(rule.threshold, precision * abs(sigma))
            precision *= 2.0


def band_counts(pencil: ReducedPencil, bounds, rule: ShiftRule, log=None) -> BandCounts:
    """Eigenvalues in each band [bounds[k], bounds[k+1]] (increasing bounds,
    in the pencil's eigenvalue unit)."""
    bounds = np.asarray(bounds, dtype=float)
    below, shift = moved_count(pencil, float(bounds[0]), rule, -1.0, log)
    counts, lower, upper = [], [], []
    for top in bounds[1:]:
        above, top_shift = moved_count(pencil, float(top), rule, +1.0, log)
        counts.append(above - below)
        lower.append(shift)
        upper.append(top_shift)
        below, shift = above, top_shift
    return BandCounts(np.array(counts, dtype=int), np.array(lower), np.array(upper))
