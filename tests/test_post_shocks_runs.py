"""detect_impacts walks runs of contact samples: its figures must be those of
the sample-by-sample definition (every field, to the last bit), on random
histories with thresholds, rest times, sub-impacts, contact at either end,
uneven steps and negative forces."""

from __future__ import annotations

from dataclasses import astuple

import numpy as np
import pytest

from asterlite.post import shocks


def sample_by_sample(t, fn, vn, threshold=0.0, rest_time=0.0):
    """The definition, one sample after the other (the former implementation)."""
    weights = shocks.trapezoid_weights(t)
    in_contact = np.abs(fn) > threshold
    look_ahead = shocks._rest_samples(t, rest_time)
    impacts, peaks = [], []
    f_max_abs = 0.0
    active = in_sub = False
    start = n_sub = 0
    f_max = impulse = t_max = v_start = 0.0
    for i in range(t.size):
        if not in_contact[i]:
            if in_sub:
                n_sub += 1
            stop = min(i + look_ahead, t.size - 1) + 1
            if active and not in_contact[i:stop].any():
                impacts.append(
                    (len(peaks) + 1, t_max, f_max, impulse, t[i] - t[start], v_start, n_sub)
                )
                peaks.append(f_max)
                active = False
            in_sub = False
            continue
        if not active:
            active, start, v_start = True, i, vn[i]
            f_max = impulse = 0.0
            n_sub = 0
        impulse += fn[i] * weights[i]
        if fn[i] >= f_max:
            f_max, t_max = fn[i], t[i]
        f_max_abs = max(f_max_abs, f_max)
        in_sub = True
    if not peaks:
        impacts.append((0, t_max, f_max, impulse, 0.0, v_start, 0))
    return impacts, f_max_abs


def history(seed: int, n: int, uneven: bool, negative: bool, burst: int = 8):
    rng = np.random.default_rng(seed)
    steps = rng.uniform(0.5, 1.5, n) if uneven else np.ones(n)
    t = 1.0e-3 * np.cumsum(steps)
    # contact in bursts: a smoothed random signal above a level
    smooth = np.ones(burst) / np.sqrt(burst)
    signal = np.convolve(rng.normal(size=n + 20), smooth, mode="same")[10 : n + 10]
    fn = np.where(signal > 0.2, rng.uniform(0.0, 30.0, n), 0.0)
    fn[rng.random(n) < 0.05] = 0.3  # small forces near a threshold
    if negative:
        fn[rng.random(n) < 0.05] = -2.0
    return t, fn, rng.normal(size=n)


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("threshold,rest_time", [(0.0, 0.0), (0.5, 0.0), (0.0, 0.004), (1.0, 0.01)])
@pytest.mark.parametrize("burst", [8, 150])  # impacts of a few samples, and of hundreds
def test_runs_match_sample_by_sample(seed, threshold, rest_time, burst):
    t, fn, vn = history(seed, 3000, uneven=seed % 2 == 1, negative=seed >= 4, burst=burst)
    if seed == 2:
        fn[:5] = 7.0  # in contact from the first sample
    if seed == 3:
        fn[-5:] = 7.0  # still in contact at the end
    summary = shocks.detect_impacts(t, fn, vn, threshold, rest_time)
    expected, f_max_abs = sample_by_sample(t, fn, vn, threshold, rest_time)
    got = [astuple(impact) for impact in summary.impacts]
    assert len(got) == len(expected) > 1 or burst > 8 and rest_time > 0
    for row, reference in zip(got, expected, strict=True):
        assert row == reference  # exact: same sums in the same order
    assert summary.f_max_abs == f_max_abs


def test_no_completed_impact_keeps_the_open_one():
    t = np.arange(10.0)
    fn = np.array([0, 0, 0, 1.0, 2.0, 0, 3.0, 3.0, 1.0, 2.0])
    vn = np.arange(10.0)
    summary = shocks.detect_impacts(t, fn, vn, rest_time=5.0)
    expected, f_max_abs = sample_by_sample(t, fn, vn, rest_time=5.0)
    assert [astuple(i) for i in summary.impacts] == expected
    assert summary.impacts[0].number == 0 and summary.impacts[0].instant == 7.0
    assert summary.f_max_abs == f_max_abs == 3.0
