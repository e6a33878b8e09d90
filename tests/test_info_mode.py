"""INFO_MODE (TYPE_MODE='DYNAMIQUE') against closed forms: a free chain of
three unit masses joined by two springs has, in each direction d with spring
stiffness k_d, ω² = 0, k_d, 3 k_d; Sturm counts per band, a lower bound of 0
moved below the rigid-body modes (to -SEUIL_FREQ) and a bound on an
eigenvalue moved out of the band by PREC_SHIFT (code_aster's vpfopr)."""

from __future__ import annotations

import math

import numpy as np
import pytest
import scipy.sparse as sp

from asterlite.errors import CommandError
from asterlite.fem.constraints import Elimination
from asterlite.modal.eigen import ReducedPencil
from asterlite.modal.sturm import ShiftRule, band_counts
from tests.test_fem_support import chain_matrices, run

TWO_PI = 2.0 * math.pi
# springs giving 1, 2, 3 Hz (and √3 times those) in x, y, z
K_VALUES = tuple((TWO_PI * f) ** 2 for f in (1.0, 2.0, 3.0))


def _info_mode(freq, **counting):
    session, _, k, m = chain_matrices(3, K_VALUES, 1.0)
    keywords = {"MATR_RIGI": k, "MATR_MASS": m, "FREQ": freq}
    if counting:
        keywords["COMPTAGE"] = counting
    return run(session, "INFO_MODE", **keywords)


def test_counts_per_band_with_rigid_body_modes_at_the_lower_bound():
    table = _info_mode((0.0, 1.5, 2.5, 6.0))
    # 0 0 0 1 | 1.732 2 | 3 3.464 5.196
    assert table.column("NB_MODE") == [4, 2, 3]
    assert table.column("FREQ_MIN") == [0.0, 1.5, 2.5]
    assert table.column("FREQ_MAX") == [1.5, 2.5, 6.0]
    # K is singular at 0: the bound moves to -SEUIL_FREQ (default 0.01 Hz)
    assert table.column("BORNE_MIN_EFFECT")[0] == pytest.approx(-0.01, rel=1e-12)
    assert table.column("BORNE_MIN_EFFECT")[1:] == table.column("BORNE_MAX_EFFECT")[:-1]


def test_a_bound_on_an_eigenvalue_moves_out_of_the_band():
    table = _info_mode((0.5, 2.0, 4.0), PREC_SHIFT=0.05)
    assert table.column("NB_MODE") == [3, 2]  # 1, 1.732, 2 | 3, 3.464
    # ω² = (2π 2)² moved up by 5 %: f = 2 √1.05
    assert table.column("BORNE_MAX_EFFECT")[0] == pytest.approx(2.0 * math.sqrt(1.05), rel=1e-12)
    assert table.column("BORNE_MAX_EFFECT")[1] == 4.0


def test_decreasing_frequencies_are_refused():
    with pytest.raises(CommandError, match="strictly increasing"):
        _info_mode((2.0, 1.0))


def test_sparse_pencil_counts_match_its_eigenvalues():
    n = 600  # past the dense limit: counts from the inertia of K - σ M
    rng = np.random.default_rng(3)
    values = np.sort(rng.uniform(1.0, 100.0, n))
    mass = rng.uniform(0.5, 2.0, n)
    identity = Elimination(
        sp.identity(n, format="csr"), np.zeros(n), np.arange(n), np.array([], dtype=int)
    )
    pencil = ReducedPencil(sp.diags(values * mass), sp.diags(mass), identity)
    bounds = np.array([0.5, 10.0, 50.0, 99.0, 200.0])
    bands = band_counts(pencil, bounds, ShiftRule(threshold=1e-3))
    pairs = zip(bounds[:-1], bounds[1:], strict=True)
    expected = [np.count_nonzero((values > a) & (values < b)) for a, b in pairs]
    assert list(bands.counts) == expected and bands.counts.sum() == n


def test_rigid_body_modes_near_a_small_threshold_are_counted_with_an_alarm():
    """Stiff springs and SEUIL_FREQ=0.001: the bound moved to -ω_c² is still
    within round-off of the rigid-body modes; code_aster counts there anyway."""
    stiff = tuple(1e8 * k for k in K_VALUES)  # 1e4 times the frequencies
    session, _, k, m = chain_matrices(3, stiff, 1.0)
    table = run(
        session,
        "INFO_MODE",
        MATR_RIGI=k,
        MATR_MASS=m,
        FREQ=(0.0, 1.5e4, 6.0e4),
        COMPTAGE={"SEUIL_FREQ": 0.001},
    )
    assert table.column("NB_MODE") == [4, 5]  # 0 0 0 1e4 | 1.7e4 2e4 3e4 3.5e4 5.2e4
    assert any("alarm" in line for line in session.lines)


def test_calc_modes_band_from_an_info_mode_table():
    """CALC_MODES OPTION='BANDE' with TABLE_FREQ (vptabl): the bands of the
    table within FREQ give the effective band and the number of modes."""
    session, _, k, m = chain_matrices(3, K_VALUES, 1.0)
    table = run(session, "INFO_MODE", MATR_RIGI=k, MATR_MASS=m, FREQ=(0.5, 1.5, 2.5, 6.0))
    common = {"MATR_RIGI": k, "MATR_MASS": m, "OPTION": "BANDE"}
    with_table = run(
        session, "CALC_MODES", **common, CALC_FREQ={"FREQ": (0.5, 2.5), "TABLE_FREQ": table}
    )
    plain = run(session, "CALC_MODES", **common, CALC_FREQ={"FREQ": (0.5, 2.5)})
    np.testing.assert_allclose(with_table.frequencies, [1.0, math.sqrt(3.0), 2.0], rtol=1e-10)
    np.testing.assert_allclose(with_table.frequencies, plain.frequencies, rtol=1e-12)
    with pytest.raises(CommandError, match="do not tile"):
        run(session, "CALC_MODES", **common, CALC_FREQ={"FREQ": (0.5, 2.0), "TABLE_FREQ": table})
