"""Orbit plots scale to physics, not round-off, and their gap label is readable.

A PLAN_Z shock moves along the normal (local z) only: its local y is
round-off, 3e-17 m. Autoscaled, the lateral axis spanned those 3e-17 m
and the orbit looked like large lateral motion; the ``JEU =`` label sat on
the arrow, under the curve. Now each axis spans at least a fraction of the
plot's scale (the gap or the largest motion), and the label sits in a
corner on an opaque box, above the curves.
"""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.transient import ShockHistory, TranGene

pytest.importorskip("matplotlib")

from asterlite.post import plots  # noqa: E402

GAP = 1.0e-4


def plan_z_result() -> TranGene:
    times = np.linspace(0.0, 0.1, 2001)
    z = 1.5 * GAP * np.sin(2.0 * np.pi * 30.0 * times)  # in and out of contact
    y = 3.0e-17 * np.sin(2.0 * np.pi * 1234.0 * times)  # round-off
    shock = ShockHistory(
        "DIS_CHOC        00000001",
        "DIS_CHOC",
        "N2",
        None,
        {"DYLOC": y, "DZLOC": z, "FN": np.maximum(np.abs(z) - GAP, 0.0) * 1e6},
        {"OBSTACLE": "PLAN_Z", "JEU": GAP},
    )
    n = len(times)
    return TranGene(
        basis=None,
        times=times,
        order=np.arange(n),
        depl=np.zeros((n, 1)),
        vite=np.zeros((n, 1)),
        acce=np.zeros((n, 1)),
        shocks=[shock],
    )


def test_lateral_round_off_is_drawn_flat():
    figure = plots.orbit_figure(plan_z_result(), "DIS_CHOC00000001")
    axes = figure.axes[0]
    low, high = axes.get_xlim()
    assert high - low >= plots.ORBIT_AXIS_FLOOR * 1.5 * GAP  # not 6e-17 m
    z_low, z_high = axes.get_ylim()
    assert z_low <= -1.5 * GAP and z_high >= 1.5 * GAP  # the real motion keeps its scale


def test_real_motion_keeps_its_autoscaled_axis():
    tran = plan_z_result()
    tran.shocks[0].fields["DYLOC"] = 0.2 * GAP * np.cos(np.linspace(0.0, 20.0, 2001))
    figure = plots.orbit_figure(tran, "DIS_CHOC00000001")
    low, high = figure.axes[0].get_xlim()
    assert 0.4 * GAP <= high - low <= 1.0 * GAP


def test_gap_label_is_above_the_curves_on_an_opaque_box():
    figure = plots.orbit_figure(plan_z_result(), "DIS_CHOC00000001")
    axes = figure.axes[0]
    (label,) = [text for text in axes.texts if text.get_text().startswith("JEU =")]
    assert label.get_zorder() > max(line.get_zorder() for line in axes.lines)
    box = label.get_bbox_patch()
    assert box is not None and box.get_alpha() >= 0.8
    assert label.get_transform() is axes.transAxes  # in a corner, not on the arrow
