"""POST_USURE numerics (asterlite.post.wear) and command, on hand-computed data."""

from __future__ import annotations

import math

import numpy as np
import pytest
from asterlite.commands import post_usure

from asterlite.concepts.transient import ShockHistory
from asterlite.errors import CommandError
from asterlite.post import wear
from tests.test_post_support import context, kw, small_transient


def test_archard_power_of_constant_sliding():
    t = np.linspace(0.0, 2.0, 21)
    fn, vt1, vt2 = np.full(21, 3.0), np.full(21, 0.3), np.full(21, 0.4)
    assert wear.wear_power(t, fn, vt1, vt2) == pytest.approx(1.5)  # 3 N × 0.5 m/s
    # sticking half of the time: half the power
    sticking = (t >= 1.0 - 1e-12).astype(int)
    assert wear.wear_power(t, fn, vt1, vt2, sticking) == pytest.approx(0.75)
    assert wear.wear_power(t, fn, vt1, vt2, None, 4) == pytest.approx(1.5)


def test_archard_volume_is_linear_in_time():
    v = wear.archard_volume(1e-13, 2.0, [1.0, 10.0])
    assert v.tolist() == pytest.approx([2e-13, 2e-12])


def test_edf_mz_volume_limits():
    t = np.array([0.0, 1.0, 1e12])
    a, b, n, s, p = 1e-13, 1.2, 2.44e-8, 1.14e-16, 0.5
    v = wear.edf_mz_volume(p, t, a, b, n, s)
    v0 = a * p**b
    assert v[0] == 0.0
    assert v[1] == pytest.approx(v0, rel=1e-6)  # initial rate A·P^B
    assert v[2] / t[2] == pytest.approx(s, rel=1e-3)  # long-term rate: the threshold
    with pytest.raises(CommandError):
        wear.edf_mz_volume(p, t, a, b, n, s=10 * v0)


def test_tube_bar_depth_closed_form():
    # V = 4/3 · sqrt(2R) · D^(3/2) · L / 3... checked through the inverse relation
    g = wear.ContactGeometry("TUBE_BAV", r_mobile=1.0, width=10.0)
    volume = np.array([1e-6])
    depth = wear.tube_depth(g, volume, np.zeros(1))
    expected = (1 / 2.0) ** (1 / 3) * (3.0 / 40.0 * 1e-6) ** (2 / 3)
    assert depth[0] == pytest.approx(expected)
    # an obstacle taking as much volume halves the tube's share of a larger depth
    both = wear.tube_depth(g, volume, volume)
    assert both[0] == pytest.approx(0.5 * (1 / 2.0) ** (1 / 3) * (3.0 / 40.0 * 2e-6) ** (2 / 3))


def test_tube_hole_uniform_wear():
    g = wear.ContactGeometry("TUBE_ALESAGE", r_mobile=0.5, width=2.0)
    depth = wear.tube_depth(g, np.array([2 * math.pi * 2.0 * 0.5 * 1e-3]), np.zeros(1))
    assert depth[0] == pytest.approx(1e-3)


def test_tube_hole_lens_depth_solves_volume():
    g = wear.ContactGeometry("TUBE_ALESAGE", r_mobile=1.0, r_obstacle=2.0, width=10.0)
    target = wear.tube_hole_volume(0.01, 1.0, 2.0, 10.0)
    depth = wear.tube_depth(g, np.array([target]), np.zeros(1))
    assert depth[0] == pytest.approx(0.01, rel=1e-5)


def test_lens_area_small_depth_matches_circle_overlap():
    # two circles (r=1 inside r=2) shifted by d: exact overlap of the outside part
    d = 0.05
    area = wear.lens_area(d, 1.0, 2.0)
    # numerical area of the part of the unit disk (centre at 1 + d) outside the big circle
    y = np.linspace(-1, 1, 200001)
    half = np.sqrt(np.clip(1 - y**2, 0, None))
    outer = np.sqrt(np.clip(4 - y**2, 0, None))
    right = np.clip((1 + d) + half, None, None) - np.maximum(outer, (1 + d) - half)
    numeric = np.trapezoid(np.clip(right, 0, None), y)
    assert area == pytest.approx(numeric, rel=1e-3)


def test_rod_notch_cubic_depth():
    g = wear.ContactGeometry("GRAPPE_2_ENCO")
    a, b, c = wear.ROD_NOTCH_FIT
    d = 5e-4
    volume = ((a * d + b) * d + c) * d
    assert wear.tube_depth(g, np.array([volume]), np.zeros(1))[0] == pytest.approx(d, rel=1e-8)
    assert wear.tube_depth(g, np.array([1.0]), np.zeros(1))[0] == wear.WORN_THROUGH


def test_bisection_follows_code_aster_criterion():
    x = wear.bisect_for(lambda d: d**2, 4.0, 0.0, 10.0)
    assert abs(x**2 - 4.0) <= 4e-6


def test_sector_power_splits_by_contact_angle():
    t = np.linspace(0.0, 1.0, 11)
    fn = np.ones(11)
    vt1, vt2 = np.full(11, 2.0), np.zeros(11)
    angle = np.where(t < 0.5, -90.0, 90.0)
    split = wear.sector_power(t, fn, vt1, vt2, angle, [-180.0, 0.0, 180.0])
    assert split.power.tolist() == pytest.approx([2.0, 2.0])
    assert split.occurrences.tolist() == [5, 5]
    assert split.weighted([1.0, 3.0]) == pytest.approx(4.0)


def test_kwu_weight_classes():
    # all couples in the lowest velocity class: pure impact, S_g from the first class only
    fn = np.array([10.0, 30.0, 50.0])
    vg = np.array([0.0, 0.0, 1.0])
    w = wear.kwu_weight(fn, vg, coef_fnor=1.0, coef_vtan=1e-6)
    assert 0.0 < w < 1e-6
    with pytest.raises(CommandError):
        wear.kwu_weight(np.array([1.0]), np.array([1.0]), 1.0, 1.0)


def test_post_usure_table_from_power():
    ctx = context("POST_USURE")
    table = post_usure.run(
        ctx,
        kw(
            PUIS_USURE=0.5, LOI_USURE="ARCHARD", MOBILE=[{"COEF_USURE": 1e-13}],
            CONTACT="TUBE_TUBE", RAYON_MOBILE=1.0, ANGL_INCLI=7.0, INST=(1.0, 2.0),
            COEF_INST=10.0,
        ),
    )  # fmt: skip
    assert table.rows[0] == {"PUIS_USUR_GLOBAL": 0.5}
    assert table.value("V_USUR_TUBE", 3) == pytest.approx(1e-12)
    assert table.value("V_USUR_OBST", 2) == 0.0
    theta = math.radians(7.0)
    expected = 0.5**0.2 * (15 * theta / 8 * 1e-12) ** 0.4
    assert table.value("P_USUR_TUBE", 3) == pytest.approx(expected)


def test_post_usure_from_shock_history_and_new_tube():
    result = small_transient()
    t = result.times
    result.shocks = [
        ShockHistory("C1", "DIS_CHOC", "NO2", None, {
            "FN": np.full(t.size, 2.0), "VT1": np.full(t.size, 1.0), "VT2": np.zeros(t.size),
            "DYLOC": np.where(t < 0.5, 1.0, -1.0), "DZLOC": np.full(t.size, 1.0),
            "ADHERENCE": np.zeros(t.size),
        })
    ]  # fmt: skip
    ctx = context("POST_USURE")
    sectors = [
        {"ANGL_INIT": -180.0, "ANGL_FIN": 0.0, "COEF_USUR_MOBILE": 1e-10, "COEF_USUR_OBST": 0.0},
        {"ANGL_FIN": 180.0, "COEF_USUR_MOBILE": 2e-10, "COEF_USUR_OBST": 0.0},
    ]
    table = post_usure.run(
        ctx,
        kw(RESU_GENE=result, NOEUD="N2", LOI_USURE="ARCHARD", SECTEUR=sectors,
           RAYON_MOBILE=1.0, RAYON_OBST=2.0, INST=(1.0,), COEF_INST=1.0, NB_BLOC=1),
    )  # fmt: skip
    assert table.value("PUIS_USUR_GLOBAL", 1) == pytest.approx(2.0)
    sect = [r for r in table.rows if r.get("SECTEUR") is not None]
    # contact angle 45° for t < 0.5 (sector 2), 135° after (sector 2 too): all in sector 2
    assert sect[0]["V_USUR_TUBE_SECT"] == 0.0
    assert sect[1]["V_USUR_TUBE_SECT"] == pytest.approx(2e-10 * 2.0)
    ctx = context("POST_USURE")
    ctx.reuse = table
    post_usure.run(ctx, kw(TUBE_NEUF="OUI", TABL_USURE=table, INST=1.0))
    assert all(r["V_USUR_TUBE_CUMU"] == 0.0 for r in table.rows if "V_USUR_TUBE_CUMU" in r)


def test_rod_notch_small_volumes_stop_where_code_aster_stops():
    """At depths near the fit's zero, code_aster's guarded Newton stops on its
    absolute step test: zzzz405a's depth 8.38630e-6 m, not the exact root."""
    g = wear.ContactGeometry("GRAPPE_2_ENCO")
    a, b, c = wear.ROD_NOTCH_FIT
    exact = (-b + np.sqrt(b * b - 4 * a * c)) / (2 * a)
    depth = wear.tube_depth(g, np.array([1e-16]), np.zeros(1))[0]
    assert depth == pytest.approx(8.38630e-6, rel=1e-5)
    assert abs(depth / exact - 1) > 5e-3
    assert wear.guarded_newton(lambda x: (x * x - 4.0, 2 * x), 0.0, 10.0) == pytest.approx(2.0)
