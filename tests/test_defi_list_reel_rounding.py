"""DEFI_LIST_REEL builds PAS lists as code_aster does, one step added at a
time, so sampled formulas fall on the same side of their kinks (sdnd124d:
an excitation sampled on a 0.02/30 grid has a ramp kink at t = 15 s)."""

import numpy as np
import pytest
from asterlite.commands import calc_fonc_interp, defi_list_reel

from asterlite.concepts.function import Formula

from .test_post_support import context, kw


def fine_grid():
    occ = [{"JUSQU_A": 20.0, "PAS": 0.02 / 30.0}]
    return np.asarray(defi_list_reel.run(context(), kw(DEBUT=0.0, INTERVALLE=occ)).Valeurs())


def test_pas_points_carry_code_aster_cumulated_round_off():
    grid = fine_grid()
    assert grid.size == 30001 and grid[-1] == 20.0  # the bound itself closes the list
    # code_aster's point 22500 is the sum of 22500 steps, a little past 15
    assert grid[22500] == 15.000000000007807
    assert grid[7500] == 4.999999999999583


def test_points_within_epsilon_of_zero_become_zero():
    occ = [{"JUSQU_A": 0.5, "PAS": 0.1}]
    grid = defi_list_reel.run(context(), kw(DEBUT=-1.0, INTERVALLE=occ)).Valeurs()
    assert grid[10] == 0.0  # -1 + 10 x 0.1 is -1.4e-16 before the snap
    assert grid == pytest.approx(np.linspace(-1.0, 0.5, 16))


def test_ramp_derivative_sampled_past_its_kink():
    # DRampe of sdnd124d: 0 on the plateau up to t = 15, then -1/5
    slope = Formula("D(INST)", ("INST",), extra={"D": lambda t: 0.0 if t <= 15.0 else -0.2})
    grid = fine_grid()
    sampled = calc_fonc_interp.run(
        context(), kw(FONCTION=slope, VALE_PARA=tuple(grid), NOM_RESU="D", PROL_DROITE="CONSTANT")
    )
    assert sampled.ordinates[22500] == -0.2
    assert sampled(15.0) == pytest.approx(-0.2 * (15.0 - grid[22499]) / (grid[22500] - grid[22499]))


def test_pas_that_does_not_divide_ends_with_a_shorter_step():
    # code_aster (op0024): the whole steps within [0, 1.9985] (133 of 0.015, the
    # last at 133 x 0.015), then one step of 0.0035 to JUSQU_A; then 1.9985 -> 2.0
    occ = [{"JUSQU_A": 1.9985, "PAS": 0.015}, {"JUSQU_A": 2.0, "PAS": 0.0015}]
    grid = np.asarray(defi_list_reel.run(context(), kw(DEBUT=0.0, INTERVALLE=occ)).Valeurs())
    assert grid.size == 1 + 133 + 1 + 1
    assert grid[133] == 133 * 0.015
    assert grid[134] == 1.9985 and grid[135] == 2.0
    assert np.diff(grid)[:133] == pytest.approx(0.015)
    # nint(2.6) = 3 steps of 1.0 would pass 2.6: code_aster keeps 2 and adds 0.6
    grid = defi_list_reel.run(context(), kw(DEBUT=0.0, INTERVALLE=[{"JUSQU_A": 2.6, "PAS": 1.0}]))
    assert grid.Valeurs() == pytest.approx([0.0, 1.0, 2.0, 2.6])


def test_pas_longer_than_its_interval_is_an_error():
    from asterlite.errors import CommandError

    occ = [{"JUSQU_A": 1.0, "PAS": 1.5}]
    with pytest.raises(CommandError, match="longer than"):
        defi_list_reel.run(context(), kw(DEBUT=0.0, INTERVALLE=occ))
