"""The friction oscillator at the numerical extremes: contact stiffness,
friction coefficient, tangential stiffness and time step far from their
usual values. Every run either ends with finite, bounded results or stops
early with a located error that names the cause; nothing partial is left
as a result and no NaN reaches a check."""

from __future__ import annotations

import math

import pytest

from asterlite.runtime.runner import run_deck
from asterlite.runtime.session import KeywordOverride
from tests.conftest import SAMPLES

DECK = SAMPLES / "friction_oscillator" / "friction_oscillator.export"
U0 = 3.0e-3  # the sample's initial displacement


def finite_and_bounded(report) -> bool:
    values = [t.value for t in report.tests if isinstance(t.value, float)]
    # the stick phase is a penalised spring: a few % of elastic slip is allowed
    return bool(values) and all(math.isfinite(v) and abs(v) <= 1.05 * U0 for v in values)


def refused_with_a_suggestion(report, tmp_path) -> bool:
    """An early, located error naming the step to use, with nothing saved."""
    return (
        report.exit_code == 2
        and "friction_oscillator.comm" in report.message
        and "use PAS <=" in report.message
        and not (tmp_path / "out" / "results.h5").exists()
    )


@pytest.mark.parametrize(
    "overrides",
    [
        {"KN": 1.0e2},  # a soft stop: FN = 10 N, weak friction
        {"KN": 1.0e12},  # a hard stop: beyond the explicit limit, refused up front
        {"MU": 0.0},  # no friction: free oscillation
        {"MU": 2.0},  # friction far above the spring force: sticks
    ],
    ids=lambda o: ",".join(f"{k}={v:g}" for k, v in o.items()),
)
def test_extreme_parameters_give_bounded_results(tmp_path, overrides):
    report = run_deck(DECK, tmp_path / "out", overrides=overrides)
    if report.status in ("PASS", "NOOK"):
        assert finite_and_bounded(report)
        for shock in report.shocks:
            assert all(math.isfinite(shock[key]) for key in ("max_FN", "wear_power"))
    else:
        assert refused_with_a_suggestion(report, tmp_path), report.message


@pytest.mark.parametrize("tangential", [1.0e0, 1.0e12])
def test_extreme_tangential_stiffness(tmp_path, tangential):
    override = KeywordOverride("DYNA_VIBRA", {"COMPORTEMENT/RIGI_TAN": tangential})
    report = run_deck(DECK, tmp_path / "out", keyword_overrides=[override])
    if report.status in ("PASS", "NOOK"):
        assert finite_and_bounded(report)
    else:  # a stiff stick spring beyond the explicit limit is refused up front
        assert refused_with_a_suggestion(report, tmp_path), report.message


def test_step_beyond_the_stability_limit_is_refused_with_a_suggestion(tmp_path):
    override = KeywordOverride("DYNA_VIBRA", {"INCREMENT/PAS": 5.0e-2})
    report = run_deck(DECK, tmp_path / "out", keyword_overrides=[override])
    assert refused_with_a_suggestion(report, tmp_path), report.message
    assert report.tests == []  # nothing after the refused integration ran
