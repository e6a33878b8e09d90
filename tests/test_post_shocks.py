import numpy as np
import pytest
from asterlite.commands import post_dyna_moda_t

from asterlite.post import shocks
from asterlite.post.wear import wear_power

from .test_post_support import context, kw, small_transient

T = np.round(np.arange(10) * 0.1, 12)
FN = np.array([0, 0, 1, 3, 1, 0, 0, 2, 0, 0], dtype=float)
VN = -np.arange(10, dtype=float)


def test_two_separate_impacts():
    summary = shocks.detect_impacts(T, FN, VN)
    first, second = summary.impacts
    assert (first.number, first.instant, first.f_max) == (1, pytest.approx(0.3), 3.0)
    assert first.impulse == pytest.approx(0.5)
    assert first.duration == pytest.approx(0.3)
    assert first.v_impact == -2.0 and first.n_sub_impacts == 1
    assert (second.instant, second.f_max, second.duration) == (
        pytest.approx(0.7),
        2.0,
        pytest.approx(0.1),
    )
    assert second.impulse == pytest.approx(0.2)
    assert summary.f_max_abs == 3.0
    assert summary.f_max_mean == pytest.approx(2.5)
    assert summary.f_max_std == pytest.approx(0.5)


def test_rest_time_merges_impacts():
    summary = shocks.detect_impacts(T, FN, VN, rest_time=0.3)
    (only,) = summary.impacts
    assert only.duration == pytest.approx(0.6)
    assert only.n_sub_impacts == 2
    assert only.impulse == pytest.approx(0.7)


def test_threshold_ignores_small_forces():
    summary = shocks.detect_impacts(T, FN, VN, threshold=1.5)
    assert [i.f_max for i in summary.impacts] == [3.0, 2.0]
    assert summary.impacts[0].duration == pytest.approx(0.1)


def test_no_impact_gives_one_empty_row():
    summary = shocks.detect_impacts(T, np.zeros(10), VN)
    assert len(summary.impacts) == 1 and summary.impacts[0].number == 0


def test_histogram_classes():
    lower, upper, proba = shocks.histogram(np.array([2.0, 3.0]), 2)
    assert lower.tolist() == [2.0, 2.5] and upper.tolist() == [2.5, 3.0]
    assert proba.tolist() == [0.5, 0.5]


def test_shock_counts_and_wear_power():
    counts = shocks.count_shocks(T, FN)
    assert counts.n_shocks == 2 and counts.n_rebounds == 2
    assert counts.mean_duration == pytest.approx(0.2)
    assert counts.max_duration == pytest.approx(0.3)
    assert counts.total_contact_time == pytest.approx(0.4)
    power = wear_power(T, FN, np.ones(10), np.zeros(10))
    assert power == pytest.approx(0.7 / 0.9)


def test_normal_force_stats_over_contact_and_total_time():
    s = shocks.normal_force_stats(FN)
    assert s.mean_total == pytest.approx(7 / 10)
    assert s.mean_contact == pytest.approx(7 / 4)
    assert s.rms_contact == pytest.approx(np.sqrt(15 / 4))
    assert s.max == 3.0


def test_post_dyna_moda_t_impact_table_uses_node_numbers():
    result = small_transient()
    result.times = np.round(np.arange(11) * 0.1, 12)
    result.shocks[0].fields = {"FN": np.append(FN, 0.0), "VN": np.zeros(11)}
    table = post_dyna_moda_t.run(
        context(), kw(RESU_GENE=result, CHOC=[{"OPTION": "IMPACT", "NB_CLASSE": 4}])
    )
    impacts = table.filtered("CALCUL", "EQ", "IMPACT").filtered("NOEUD", "EQ", "2")
    assert impacts.column("F_MAX") == [3.0, 2.0]
    assert impacts.filtered("CHOC", "EQ", 2).column("INSTANT") == [pytest.approx(0.7)]
    assert len(table.filtered("CALCUL", "EQ", "PROBA")) == 4
    (f_max_abs,) = table.filtered("CALCUL", "EQ", "GLOBAL").column("F_MAX_ABS")
    assert f_max_abs == 3.0


def test_post_dyna_moda_t_wear_table():
    result = small_transient()
    table = post_dyna_moda_t.run(context(), kw(RESU_GENE=result, CHOC=[{"OPTION": "USURE"}]))
    calculs = table.column("CALCUL")
    assert calculs[:5] == ["DEPL_X", "DEPL_Y", "DEPL_Z", "DEPL_RADIAL", "DEPL_ANGULAIRE"]
    force = table.filtered("CALCUL", "EQ", "FORCE_NORMALE")
    fn = np.sin(np.pi * result.times)
    assert force.column("RMS_T_TOTAL")[0] == pytest.approx(np.sqrt(np.mean(fn**2)))
    assert table.filtered("CALCUL", "EQ", "PUIS_USURE").column("PUIS_USURE") == [0.0]
