"""One wear power: code_aster's PUIS_USURE (statpu / pusure: FN·|V_T|
integrated by the trapezoid rule over the intervals that start sliding,
divided by the duration, averaged over NB_BLOC blocks), used alike by
POST_DYNA_MODA_T, POST_USURE, the run summary and ``asterlite plot``."""

from __future__ import annotations

import math

import numpy as np
import pytest

from asterlite.post import plots
from asterlite.post.wear import history_wear_power, wear_power
from tests.conftest import SAMPLES


def test_sticking_intervals_do_not_wear_and_blocks_are_averaged():
    """Hand-integrated: FN = 2 N; |V_T| = 0.5 m/s on [0, 1], 0.2 m/s (elastic,
    sticking) on [1, 2], 0.5 m/s on [2, 4]; samples every 0.5 s."""
    t = np.arange(0.0, 4.01, 0.5)
    fn = np.full(t.size, 2.0)
    vt1 = np.where((t > 1.0) & (t < 2.0), 0.2, 0.5) * 0.6
    vt2 = np.where((t > 1.0) & (t < 2.0), 0.2, 0.5) * 0.8
    sticking = ((t >= 1.0) & (t < 2.0)).astype(float)  # the flag of each interval's start
    # sliding intervals: [0, 1] and [2, 4], all at 2 N × 0.5 m/s = 1 W: 3 J in 4 s
    assert wear_power(t, fn, vt1, vt2, sticking) == pytest.approx(3.0 / 4.0)
    # no stick flag: every interval counts, [1, 2] at its elastic speed
    power = 2.0 * np.hypot(vt1, vt2)
    every = np.sum((power[1:] + power[:-1]) * np.diff(t)) / 2.0 / 4.0
    assert wear_power(t, fn, vt1, vt2) == pytest.approx(every)
    # NB_BLOC=2: blocks of 4 samples, [0, 1.5] and [2, 3.5] (the interval between
    # them and the last sample left out); [1, 1.5] sticks: 1 J in 1.5 s, then 1 W
    assert wear_power(t, fn, vt1, vt2, sticking, 2) == pytest.approx((1.0 / 1.5 + 1.0) / 2.0)


FRICTION = SAMPLES / "friction_oscillator"
POST = """
USURE = POST_DYNA_MODA_T(RESU_GENE=RESUGENE, CHOC=_F(OPTION="USURE"))
USURE2 = POST_DYNA_MODA_T(RESU_GENE=RESUGENE, CHOC=_F(OPTION="USURE", NB_BLOC=2))

FIN()
"""


@pytest.fixture(scope="module")
def friction_session(tmp_path_factory):
    """The friction oscillator sample (a mass sliding with Coulomb friction
    under a constant normal force) followed by POST_DYNA_MODA_T."""
    from asterlite.io.export import describe_run
    from asterlite.runtime.session import Session

    folder = tmp_path_factory.mktemp("friction")
    text = (FRICTION / "friction_oscillator.comm").read_text()
    head, _ = text.rsplit("FIN()", 1)
    (folder / "deck.comm").write_text(head + POST)
    (folder / "deck.mail").write_text((FRICTION / "friction_oscillator.mail").read_text())
    (folder / "deck.export").write_text("F comm deck.comm D 1\nF mail deck.mail D 20\n")
    (folder / "out").mkdir()
    session = Session(describe_run(folder / "deck.export"), output_dir=folder / "out")
    session.run_all()
    return session


def puis_usure(table) -> float:
    rows = [r for r in table.rows if r.get("CALCUL") == "PUIS_USURE"]
    assert len(rows) == 1
    return float(rows[0]["PUIS_USURE"])


def test_friction_oscillator_wear_power_is_the_hand_integrated_sliding(friction_session):
    """While it slides, the mass moves from swing A_n to A_{n+1} = -(A_n - 2C)
    each half period (C = MU M G / K) under FN = M G; it sticks once
    |A_n| <= C. The wear power is FN times the distance slid over the run,
    divided by the 0.25 s of the run; the summary, POST_DYNA_MODA_T (one and
    two blocks) and the plot's rates agree with it and with one another."""
    ns = friction_session.namespace
    m, k, g, mu, u0 = ns["M"], ns["K"], ns["G"], ns["MU"], ns["U0"]
    offset = mu * m * g / k
    swings = [u0]
    while abs(swings[-1]) > offset:
        swings.append(abs(swings[-1]) - 2.0 * offset)
    distance = sum(a + b for a, b in zip(swings[:-1], swings[1:], strict=True))
    assert len(swings) == 5 and math.isclose(distance, 12.2255e-3, rel_tol=1e-3)
    expected = m * g * distance / 0.25

    tran = ns["RESUGENE"]
    from_table = puis_usure(ns["USURE"])
    assert from_table == pytest.approx(expected, rel=5e-3)
    _, shocks = friction_session.summaries.results()
    (summary,) = [s for s in shocks if s["result"] == "RESUGENE"]
    assert summary["wear_power"] == pytest.approx(from_table, rel=1e-12)
    assert plots.wear_work_rates(tran)["FLOOR"] == pytest.approx(from_table, rel=1e-12)
    # the stick phases (elastic RIGI_TAN motion flagged ADHERENCE=1) do not wear
    fields = tran.shocks[0].fields
    assert np.any(fields["ADHERENCE"][:-1] != 0)
    no_flag = {k: v for k, v in fields.items() if k != "ADHERENCE"}
    assert history_wear_power(tran.times, no_flag) > from_table * (1.0 + 1e-6)
    # NB_BLOC=2: the mean of the two halves (the first slides 4 half periods' worth)
    halves = [
        history_wear_power(tran.times[b], {k: v[b] for k, v in fields.items()})
        for b in (
            slice(0, tran.times.size // 2),
            slice(tran.times.size // 2, 2 * (tran.times.size // 2)),
        )
    ]
    assert puis_usure(ns["USURE2"]) == pytest.approx(np.mean(halves), rel=1e-12)
