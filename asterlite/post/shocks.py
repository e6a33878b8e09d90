"""Shock statistics of POST_DYNA_MODA_T (``CHOC``), from archived local
histories of the nonlinearities.

Definitions follow code_aster (R7.10.02 / its Fortran):

- *impacts* (OPTION='IMPACT'): a global impact starts when |FN| rises above
  SEUIL_FORCE and ends at the first sample where |FN| is back below it and
  stays below for DUREE_REPOS (looked ahead in samples). Per impact: the
  maximum force F_MAX and its instant INSTANT, the impulse (trapezoid rule),
  the duration T_CHOC (end sample minus start sample), the normal velocity at
  the start V_IMPACT, and the number of sub-impacts NB_IMPACT (returns below
  the threshold inside the global impact, the final one included). GLOBAL:
  largest F_MAX, mean and standard deviation of the F_MAX of completed
  impacts. PROBA: histogram of F_MAX over NB_CLASSE classes.
- *wear* (OPTION='USURE'): mean/std/RMS/max/min of the local displacements,
  of the radial displacement and polar angle (in the plane of the 2nd and
  3rd local axes), of the tangential forces; mean/RMS of FN over the whole
  time and over contact time; shock counts and durations. The Archard wear
  power is :func:`asterlite.post.wear.wear_power`.

Every function here is plain numpy on 1-D arrays, testable by hand.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np


@dataclass
class Impact:
    number: int
    instant: float  # instant of the maximum force
    f_max: float
    impulse: float
    duration: float
    v_impact: float
    n_sub_impacts: int


#: the figures of an impact, in the order of :class:`Impact`'s fields
IMPACT_FIELDS = (
    "number", "instant", "f_max", "impulse", "duration", "v_impact", "n_sub_impacts",
)  # fmt: skip


@dataclass
class ImpactSummary:
    # the impacts' figures as columns: {field of Impact: list of Python numbers}
    columns: dict[str, list] = field(default_factory=lambda: {k: [] for k in IMPACT_FIELDS})
    f_max_abs: float = 0.0
    f_max_mean: float = 0.0
    f_max_std: float = 0.0
    # F_MAX of each completed impact (the histogram's sample)
    peaks: np.ndarray = field(default_factory=lambda: np.zeros(0))

    @property
    def impacts(self) -> list[Impact]:
        """One :class:`Impact` per row of ``columns``."""
        return [Impact(*row) for row in zip(*self.columns.values(), strict=True)]

    def append(self, impact: Impact) -> None:
        for name in IMPACT_FIELDS:
            self.columns[name].append(getattr(impact, name))


def trapezoid_weights(t: np.ndarray) -> np.ndarray:
    """Quadrature weights of the trapezoid rule on (possibly uneven) samples:
    w_i = dt_i / 2 + dt_(i-1) / 2 (dt_i = t_(i+1) - t_i), one half-step at
    either end."""
    t = np.asarray(t, dtype=float)
    w = np.zeros_like(t)
    if t.size > 1:
        half = np.diff(t) / 2
        w[0], w[-1] = half[0], half[-1]
        np.add(half[1:], half[:-1], out=w[1:-1])
    return w


def _rest_samples(t: np.ndarray, rest_time: float, minimum: int = 0) -> int:
    """DUREE_REPOS as a number of samples (code_aster uses the 3rd step)."""
    if t.size < 4:
        dt = t[1] - t[0] if t.size > 1 else 1.0
    else:
        dt = t[3] - t[2]
    return max(minimum, int(np.floor(rest_time / dt + 0.5))) if dt > 0 else minimum  # Fortran NINT


def contact_runs(in_contact: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(starts, stops) of the runs of consecutive samples in contact (stops
    exclusive)."""
    padded = np.concatenate([[False], in_contact, [False]]).astype(np.int8)
    edges = np.diff(padded)
    return np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)


def detect_impacts(
    t: np.ndarray,
    fn: np.ndarray,
    vn: np.ndarray,
    threshold: float = 0.0,
    rest_time: float = 0.0,
    weights: np.ndarray | None = None,
) -> ImpactSummary:
    """Global impacts of one shock history (OPTION='IMPACT').

    Computed on the runs of samples in contact rather than sample by sample
    (10^5 archived instants hold a few hundred runs): the gap after a run is
    a sub-impact boundary, and closes the impact when it reaches the end or
    lasts more than DUREE_REPOS (more samples than its look-ahead); a run
    reaching the last sample leaves its impact open. The figures are those
    of a pass over the samples in order (tests/test_post_shocks_runs.py):
    the impulse adds F_N w_i one sample after the other from 0, F_MAX is
    the running maximum from 0 (taken at the last sample reaching it).
    ``weights``: the trapezoid weights of ``t`` when the caller has them
    (shocks of one result share their instants)."""
    t, fn, vn = (np.asarray(a, dtype=float) for a in (t, fn, vn))
    n = t.size
    in_contact = np.abs(fn) > threshold
    summary = ImpactSummary()
    starts, stops = contact_runs(in_contact)
    if starts.size == 0:  # code_aster still writes one row (impact 0)
        summary.append(Impact(0, 0.0, 0.0, 0.0, 0.0, 0.0, 0))
        return summary
    look_ahead = _rest_samples(t, rest_time)
    next_starts = np.append(starts[1:], n)
    closing = (stops < n) & (np.minimum(stops + look_ahead, n - 1) < next_starts)
    last_run = np.flatnonzero(closing)
    if not closing[-1]:  # in contact at the end: an impact left open
        last_run = np.append(last_run, starts.size - 1)
    first_run = np.concatenate([[0], last_run[:-1] + 1])
    begin, end = starts[first_run], stops[last_run]
    force = np.where(in_contact, fn, -np.inf)
    f_max, t_max = impact_peaks(t, force, begin, end)
    weights = trapezoid_weights(t) if weights is None else weights
    contact_impulse = np.multiply(fn, weights, out=np.zeros(n), where=in_contact)
    impulse = sequential_sums(contact_impulse, begin, end)
    closed = int(closing[-1]) + last_run.size - 1  # completed impacts come first
    durations = t[np.minimum(end, n - 1)] - t[begin]
    f_max_list, t_max_list, impulse_list = f_max.tolist(), t_max.tolist(), impulse.tolist()
    v_start, durations, n_sub = vn[begin].tolist(), durations.tolist(), last_run - first_run + 1
    summary.columns = dict(
        zip(IMPACT_FIELDS, (list(range(1, closed + 1)), t_max_list[:closed], f_max_list[:closed],
            impulse_list[:closed], durations[:closed], v_start[:closed], n_sub[:closed].tolist()),
            strict=True)
    )  # fmt: skip
    largest = float(f_max.max())
    summary.f_max_abs = largest if largest > 0.0 else 0.0
    if closed:
        summary.peaks = f_max[:closed].copy()
        summary.f_max_mean = float(np.mean(summary.peaks))
        # population standard deviation, as code_aster (sqrt(E[x²] - E[x]²))
        summary.f_max_std = float(np.sqrt(abs(np.mean(summary.peaks**2) - summary.f_max_mean**2)))
    else:
        # no completed impact: code_aster still writes one row (impact 0), with
        # the figures of the impact still open, and an empty histogram
        summary.append(Impact(0, t_max_list[-1], f_max_list[-1], impulse_list[-1], 0.0,
                              v_start[-1], 0))  # fmt: skip
    return summary


def impact_peaks(t, force, begin, end):
    """(F_MAX, its instant) of each impact [begin, end) of ``force`` (-inf out
    of contact): the running maximum from 0 updated by every sample not
    below it, so the last sample reaching a non-negative peak gives the
    instant; an impact whose forces are all negative keeps F_MAX = 0 and
    the previous impact's instant (0 before any)."""
    peak = np.maximum.reduceat(force, begin)  # segments to the next begin: out of contact
    first = int(begin[0])
    spans = np.diff(np.append(begin, force.size))
    at_peak = force[first:] == np.repeat(peak, spans)
    index = np.arange(first, force.size)
    last = np.maximum.reduceat(np.where(at_peak, index, -1), begin - first)
    reached = peak >= 0.0
    f_max = np.where(reached, peak, 0.0)
    source = np.maximum.accumulate(np.where(reached, np.arange(begin.size), -1))
    t_max = np.where(source >= 0, t[last[np.maximum(source, 0)]], 0.0)
    del end  # the peak of a segment past its end is out of contact (-inf)
    return f_max, t_max


SHORT = 64  # impacts of at most this many samples are summed side by side


def sequential_sums(values, begin, end):
    """Σ values[begin_k:end_k] added one after the other from 0 (the rounding
    of a sample-by-sample pass, which numpy's pairwise ``sum`` does not keep):
    short segments as the rows of one padded array accumulated along them,
    long ones one by one."""
    lengths = end - begin
    sums = np.zeros(begin.size)
    short = np.flatnonzero(lengths <= SHORT)
    # sample j of every short segment at once: one vector add per position
    order = short[np.argsort(-lengths[short], kind="stable")]
    longest = int(lengths[order[0]]) if order.size else 0
    alive = np.searchsorted(-lengths[order], -np.arange(longest), side="left")
    partial = np.zeros(order.size)
    starts = begin[order]
    for j in range(longest):  # segments longer than j: a prefix of ``order``
        m = alive[j]
        partial[:m] += values[starts[:m] + j]
    sums[order] = partial
    for k in np.flatnonzero(lengths > SHORT).tolist():
        sums[k] = np.add.accumulate(np.concatenate([[0.0], values[begin[k] : end[k]]]))[-1]
    return sums


def histogram(values: np.ndarray, n_classes: int):
    """Class bounds and probabilities of ``values`` over ``n_classes`` equal
    classes between their min and max (the max falls in the last class)."""
    values = np.asarray(values, dtype=float)
    n_classes = n_classes or 10
    if values.size == 0:
        return np.zeros(n_classes), np.zeros(n_classes), np.zeros(n_classes)
    vmin, vmax = float(values.min()), float(values.max())
    width = (vmax - vmin) / n_classes
    if width > 0:
        cls = np.minimum((values - vmin) // width, n_classes - 1).astype(int)
    else:
        cls = np.zeros(values.size, dtype=int)
    counts = np.bincount(cls, minlength=n_classes)[:n_classes]
    upper = vmin + width * np.arange(1, n_classes + 1)
    lower = np.concatenate([[vmin], upper[:-1]])
    return lower, upper, counts / values.size


@dataclass
class SignalStats:
    mean: float
    std: float
    rms: float
    max: float
    min: float


def signal_stats(x: np.ndarray) -> SignalStats:
    """Mean, standard deviation, RMS and extrema of a sampled signal
    (sample averages, not time integrals, as code_aster)."""
    x = np.asarray(x, dtype=float)
    if x.size == 0:
        return SignalStats(0.0, 0.0, 0.0, 0.0, 0.0)
    mean = float(x.mean())
    return SignalStats(
        mean,
        float(np.sqrt(np.mean((x - mean) ** 2))),
        float(np.sqrt(np.mean(x**2))),
        float(x.max()),
        float(x.min()),
    )


@dataclass
class NormalForceStats:
    mean_total: float  # MOYEN_T_TOTAL: sum over contact samples / all samples
    mean_contact: float  # MOYEN_T_CHOC: over contact samples
    rms_total: float
    rms_contact: float
    max: float


def normal_force_stats(fn: np.ndarray, threshold: float = 0.0) -> NormalForceStats:
    """Statistics of the normal force, counting only samples above SEUIL_FORCE."""
    fn = np.asarray(fn, dtype=float)
    contact = fn[np.abs(fn) > threshold]
    n = max(fn.size, 1)
    total, squares = float(contact.sum()), float((contact**2).sum())
    if contact.size:
        return NormalForceStats(
            total / n,
            total / contact.size,
            np.sqrt(squares / n),
            np.sqrt(squares / contact.size),
            max(0.0, float(contact.max())),
        )
    return NormalForceStats(total / n, 0.0, np.sqrt(squares / n), 0.0, 0.0)


@dataclass
class ShockCounts:
    n_shocks: int
    n_rebounds: int
    mean_duration: float
    max_duration: float
    min_duration: float
    mean_rebound: float
    total_contact_time: float


def count_shocks(
    t: np.ndarray, fn: np.ndarray, threshold: float = 0.0, rest_time: float = 0.0
) -> ShockCounts:
    """Global shocks (closed after DUREE_REPOS without contact, at least one
    sample) and rebounds (every return below the threshold) with durations."""
    t, fn = np.asarray(t, dtype=float), np.asarray(fn, dtype=float)
    in_contact = np.abs(fn) > threshold
    look_ahead = _rest_samples(t, rest_time, minimum=1)
    durations, rebounds = [], []
    active = in_rebound = False
    start = rebound_start = 0
    for i in range(t.size):
        if in_contact[i]:
            if not active:
                start = i
            if not in_rebound:
                rebound_start = i
            active = in_rebound = True
            continue
        if in_rebound:
            rebounds.append(t[i] - t[rebound_start])
        stop = min(i + look_ahead, t.size - 1)
        quiet = stop <= i + 1 or not in_contact[i + 1 : stop + 1].any()
        if quiet and active:
            durations.append(t[i] - t[start])
            active = False
        in_rebound = False
    d = np.array(durations)
    return ShockCounts(
        n_shocks=len(durations),
        n_rebounds=len(rebounds),
        mean_duration=float(d.mean()) if d.size else 0.0,
        max_duration=float(d.max()) if d.size else 0.0,
        min_duration=float(d.min()) if d.size else 1.0e20,
        mean_rebound=float(np.mean(rebounds)) if rebounds else 0.0,
        total_contact_time=float(d.sum()),
    )


def polar(dy: np.ndarray, dz: np.ndarray):
    """Radial displacement and polar angle (degrees, 0 where both are 0)."""
    radius = np.hypot(dy, dz)
    angle = np.where((dy != 0) | (dz != 0), np.degrees(np.arctan2(dz, dy)), 0.0)
    return radius, angle


# ----------------------------------------------------------------------------- RELA_EFFO_DEPL


@dataclass
class NonlinearPhase:
    """One stretch of time a RELA_EFFO_DEPL relation spends in its nonlinear
    zone (its force non-zero), as a row of POST_DYNA_MODA_T/RELA_EFFO_DEPL."""

    number: int  # PHASE (1-based)
    start: float  # INST_INIT: first archived instant in the zone
    end: float  # INST_FIN: first archived instant back out (last instant if never)
    extreme: float  # MAXI: the signed value of largest magnitude in the phase
    instant: float  # INST_MAXI: its instant (the first one on ties)


def nonlinear_phases(t: np.ndarray, value: np.ndarray, active: np.ndarray) -> list[NonlinearPhase]:
    """Phases where ``active`` (the relation's archived non-zero-force flag)
    holds, with the extreme of ``value`` (the displacement component) in each.

    A phase opens at an active sample following an inactive one (or the
    first sample) and closes at the next inactive sample, whose instant is
    INST_FIN; a phase still open at the end closes at the last instant.
    No active sample: no phase.
    """
    t = np.asarray(t, dtype=float)
    value = np.asarray(value, dtype=float)
    active = np.asarray(active) != 0
    phases: list[NonlinearPhase] = []
    if not active.any():
        return phases
    # edges of the runs of active samples: starts (inclusive), stops (exclusive)
    padded = np.concatenate([[False], active, [False]]).astype(np.int8)
    edges = np.diff(padded)
    starts = np.flatnonzero(edges == 1)
    stops = np.flatnonzero(edges == -1)
    for number, (i0, i1) in enumerate(zip(starts, stops, strict=True), start=1):
        k = i0 + int(np.argmax(np.abs(value[i0:i1])))  # argmax: first of ties
        end = t[i1] if i1 < t.size else t[-1]
        phases.append(
            NonlinearPhase(number, float(t[i0]), float(end), float(value[k]), float(t[k]))
        )
    return phases
