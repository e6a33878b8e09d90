"""asterlite sensitivity: checks under a last-bit change of the time step."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from asterlite.runtime import sensitivity as S

ROOT = Path(__file__).resolve().parents[1]
SAMPLE = ROOT / "samples" / "friction_oscillator" / "friction_oscillator.export"
SHARED = ROOT.parent / "shared" / "aster-corpus"


def test_offsets_alternate_and_grow():
    assert S.ulp_offsets(5) == [1, -1, 2, -2, 3]


def test_moved_by_ulps_is_next_representable():
    assert S.moved_by_ulps(1.0e-5, 1) == math.nextafter(1.0e-5, 1.0)
    assert S.moved_by_ulps(1.0e-5, -2) == math.nextafter(math.nextafter(1.0e-5, 0.0), 0.0)
    assert S.moved_by_ulps(1.0e-5, 0) == 1.0e-5


def _spread(values, value=10.0, tolerance=1e-3, criterion="RELATIF"):
    return S.CheckSpread("c", value, tolerance, criterion, values=list(values))


def test_classification_against_the_check_tolerance():
    assert _spread([10.0, 10.0 + 1e-12]).classification == S.STABLE
    assert _spread([10.0 + 5e-3]).classification == S.MARGINAL  # 5e-4 relative
    assert _spread([10.02]).classification == S.SENSITIVE  # 2e-3 relative
    # absolute criterion: the departure itself is compared
    assert _spread([0.5e-3], value=0.0, criterion="ABSOLU").classification == S.MARGINAL
    assert _spread([2e-3], value=0.0, criterion="ABSOLU").classification == S.SENSITIVE


def test_perturbed_overrides_touch_only_the_step():
    transients = [{"command": "DYNA_VIBRA", "call": 2, "step": 1e-4}]
    (override,) = S.perturbed_overrides(transients, -1)
    assert override.call == 2
    assert override.keywords == {"INCREMENT/PAS": math.nextafter(1e-4, 0.0)}


def test_smooth_sample_is_stable():
    study = S.run_sensitivity(SAMPLE, runs=2)
    assert study.checks and not study.failed_runs
    assert all(len(c.values) == 2 for c in study.checks)
    assert {c.classification for c in study.checks} == {S.STABLE}


def test_deck_without_transient_is_refused(tmp_path):
    deck = tmp_path / "static.comm"
    deck.write_text(
        "DEBUT()\nA = DEFI_CONSTANTE(VALE=1.0)\n"
        "TEST_FONCTION(VALEUR=_F(FONCTION=A, VALE_PARA=0.0, VALE_CALC=1.0))\nFIN()\n"
    )
    with pytest.raises(S.ConvergeError, match="no DYNA_VIBRA"):
        S.run_sensitivity(deck, runs=1)


@pytest.mark.slow
@pytest.mark.skipif(not (SHARED / "sdnl301a").is_dir(), reason="corpus not beside the project")
def test_sdnl301a_ritz_check_is_round_off_sensitive():
    """The Ritz-basis RMS normal force of sdnl301a moves by more than its
    tolerance when PAS moves by one ulp; the classical-basis one does not
    (issue 14: why the deck's last check is a draw, not a measure)."""
    study = S.run_sensitivity(SHARED / "sdnl301a" / "sdnl301a.export", runs=2)
    by_label = {c.label.split()[0]: c for c in study.checks if "RMS_T_TOTAL" in c.label}
    assert by_label["POST"].classification == S.STABLE
    assert by_label["POST2"].classification == S.SENSITIVE


def test_reference_check_is_also_judged_by_its_vale_calc():
    """sdnd107e: VALE_REFE 2.81e-4 at PRECISION 5e-3 (ABSOLU) and VALE_CALC
    7.2105e-4; one ulp on TOLERANCE moves the value by up to 2.6e-6, far
    inside the reference's tolerance but beyond the VALE_CALC comparison's
    1e-6 (absolute here): the verdict is a draw."""
    check = _spread([7.2e-4 + 2.4e-6], value=7.2e-4, tolerance=5e-3, criterion="ABSOLU")
    assert check.classification == S.STABLE
    check.calc_tolerance, check.calc_scale = 1.0e-6, 1.0
    assert check.calc_spread == pytest.approx(2.4e-6)
    assert check.classification == S.SENSITIVE
    check.calc_tolerance = 1.0e-3  # relative comparison: scale |VALE_CALC|
    check.calc_scale = 7.2e-4
    assert check.classification == S.SENSITIVE  # 3.3e-3 relative


def test_fixed_step_bounds_move_with_the_step():
    """PAS_MINI = PAS_MAXI = PAS (a fixed-step RUNGE_KUTTA run): moving PAS
    alone would put PAS above PAS_MAXI, which DYNA_VIBRA refuses."""
    transients = [
        {"command": "DYNA_VIBRA", "call": 1, "step": 1e-4, "pas_mini": 1e-4, "pas_maxi": 1e-4},
        {"command": "DYNA_VIBRA", "call": 2, "step": 1e-4, "pas_mini": None, "pas_maxi": 5e-4},
    ]
    fixed, adaptive = S.perturbed_overrides(transients, 1)
    up = math.nextafter(1e-4, 1.0)
    assert fixed.keywords == {
        "INCREMENT/PAS": up, "SCHEMA_TEMPS/PAS_MINI": up, "SCHEMA_TEMPS/PAS_MAXI": up,
    }  # fmt: skip
    assert adaptive.keywords == {"INCREMENT/PAS": up}


def test_shock_statistics_are_judged_too():
    """A shock statistic no check tests: 1e-3 relative, and 'zero' for the
    round-off of a quantity that vanishes in exact arithmetic (tube_planar23:
    wear powers of 1e-17 W whose relative spread is 10-75 %)."""
    whirl = S.ShockSpread("TRAN/SUPPORT_2:wear_power", 1.439e-3, [1.420e-3, 1.445e-3])
    assert whirl.classification == S.SENSITIVE
    assert S.ShockSpread("T/S:max_FN", 64.0, [64.0 + 6e-8]).classification == S.STABLE
    planar = S.ShockSpread("TRAN/SUPPORT_2:wear_power", 1.34e-17, [1.1e-17, 1.6e-17])
    assert planar.spread > 0.1 and planar.classification == S.ZERO
    study = S.Sensitivity("d", [1], [], [], [whirl, planar])
    assert study.sensitive_shocks() == [whirl]
    assert "chaotic" in S.format_table(study) and "'zero'" in S.format_table(study)
