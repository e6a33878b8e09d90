"""Fixed-step GENE transients stand on the grid INST_INIT + n PAS (code_aster's
list of instants): the instant of each step comes from its index, never from
a running sum, which drifts (1000 s in steps of 1e-3 s summed one by one end
4.5e-11 s short, hence one more, tiny, step, and archived instants such as
99.99999999999986). Adaptive schemes keep accumulating their steps."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.dynamics.kernel import grid_step_count
from tests.test_dynamics_vibra import kws, one_mode, run_vibra, vector


def test_grid_step_count_rounds_near_integers_and_covers_the_rest():
    assert grid_step_count(0.0, 2000.0, 1.0e-5) == 200_000_000
    assert grid_step_count(0.0, 1000.0, 1.0e-3) == 1_000_000
    assert grid_step_count(0.3, 0.7, 0.1) == 4  # 3.9999999999999996: round-off
    assert grid_step_count(0.0, 1.0, 0.3) == 4  # the last step shortened to 0.1
    assert grid_step_count(0.0, 1.0e-9, 1.0) == 1


def running_sum_steps(t_end: float, dt: float) -> int:
    """How many steps the former loop took: instants summed step by step,
    the last step shortened to land on t_end (code_aster's tolerance i·eps)."""
    eps = 10.0 * np.finfo(float).eps
    t, i = 0.0, 0
    while t_end - t > (i + 1) * eps:
        step = t_end - t if t + dt - t_end > (i + 1) * eps else dt
        t, i = t + step, i + 1
    return i


@pytest.mark.parametrize("scheme", ["DIFF_CENTRE", "NEWMARK"])
def test_a_long_run_takes_n_steps_and_archives_exact_instants(scheme):
    """INST_FIN=1000, PAS=1e-3: 10^6 steps, the archived instants k 100 s as
    the products n PAS give them (the former running sum took 1000001 steps)."""
    assert running_sum_steps(1000.0, 1.0e-3) == 1_000_001
    gnum, m, kk = one_mode(100.0)
    arch = [kws("DYNA_VIBRA/ARCHIVAGE", PAS_ARCH=100_000)]
    damping = [kws("DYNA_VIBRA/AMOR_MODAL", AMOR_REDUIT=(0.05,))]
    result = run_vibra(
        m, kk, scheme, 1.0e-3, 1000.0, etat={"DEPL": vector(gnum, 1.0)}, ARCHIVAGE=arch,
        AMOR_MODAL=damping,
    )  # fmt: skip
    assert result.info["steps"] == 1_000_000
    assert result.info["min_step"] == pytest.approx(1.0e-3, rel=1e-9)
    expected = np.arange(0, 1_000_001, 100_000) * 1.0e-3
    np.testing.assert_array_equal(result.times, expected)
    assert result.times[-1] == 1000.0
    np.testing.assert_array_equal(result.order, np.arange(0, 1_000_001, 100_000))


def test_archiving_instants_between_grid_points_keep_the_grid():
    """An ARCHIVAGE instant between two grid points cuts one step in two; the
    steps after it are on the grid again, their instants n PAS exactly."""
    gnum, m, kk = one_mode(100.0)
    arch = [kws("DYNA_VIBRA/ARCHIVAGE", INST=(0.0105, 0.0505), PAS_ARCH=10)]
    result = run_vibra(
        m, kk, "DIFF_CENTRE", 1.0e-3, 0.1, etat={"DEPL": vector(gnum, 1.0)}, ARCHIVAGE=arch
    )
    assert 0.0105 in result.times and 0.0505 in result.times
    regular = result.times[~np.isin(result.times, (0.0105, 0.0505))]
    steps = np.rint(regular / 1.0e-3)
    np.testing.assert_array_equal(regular, steps * 1.0e-3)
    assert result.info["steps"] == 102  # 100 grid steps, two of them cut in two
    assert result.times[-1] == 0.1


def test_adaptive_runs_still_sum_their_steps():
    """RUNGE_KUTTA_32 chooses its steps: its instants are the running sum of
    the steps it took (the archived step sizes add up to them)."""
    gnum, m, kk = one_mode(100.0)
    result = run_vibra(m, kk, "RUNGE_KUTTA_32", 1.0e-3, 0.05, etat={"DEPL": vector(gnum, 1.0)})
    assert result.info["adaptive"]
    np.testing.assert_allclose(np.cumsum(result.step_sizes[1:]), result.times[1:], rtol=1e-12)
