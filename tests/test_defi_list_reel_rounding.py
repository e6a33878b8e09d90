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
