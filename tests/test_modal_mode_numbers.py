"""NUME_MODE is a mode's rank in the whole spectrum, as code_aster numbers
it (the Sturm count of its shift plus its place from the shift: rectfr):
a band above lower modes starts past 1. The count is the inertia of
K - ω² M, checked against a chain's closed-form spectrum on the dense and
the sparse path."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp

from asterlite.errors import CommandError
from asterlite.fem.constraints import Elimination
from asterlite.modal.eigen import DENSE_LIMIT, ReducedPencil
from tests.test_fem_support import chain_matrices, run
from tests.test_modal_chain import K, M, axial_chain, fixed_fixed_frequencies  # noqa: F401

EXACT = fixed_fixed_frequencies(10, K, M)


def _ranks(selected) -> list[int]:
    return [int(np.argmin(abs(EXACT - f))) + 1 for f in selected]


@pytest.mark.parametrize(
    "option, calc_freq",
    [
        ("BANDE", {"FREQ": (5.0, 18.0)}),
        ("CENTRE", {"FREQ": 15.0, "NMAX_FREQ": 3}),
        ("PROCHE", {"FREQ": (3.0, 20.0)}),
        ("PLUS_PETITE", {"NMAX_FREQ": 4}),
    ],
)
def test_mode_numbers_are_ranks_in_the_spectrum(axial_chain, option, calc_freq):  # noqa: F811
    session, model, k, m = axial_chain
    modes = run(session, "CALC_MODES", MATR_RIGI=k, MATR_MASS=m, OPTION=option, CALC_FREQ=calc_freq)
    assert modes.mode_numbers.tolist() == _ranks(modes.frequencies)
    if option in ("BANDE", "CENTRE"):  # bands above the first mode
        assert modes.mode_numbers[0] > 1


def test_sturm_count_on_the_sparse_path():
    """A free-free chain of n unit masses and springs k (eigenvalues
    k (2 - 2 cos(j pi / n)), j = 0..n-1, one rigid mode): the inertia of
    K - ω² M counts the eigenvalues below ω² exactly."""
    n, k = DENSE_LIMIT + 500, 1.0e4
    main = 2.0 * np.ones(n)
    main[[0, -1]] = 1.0
    stiffness = k * sp.diags([-np.ones(n - 1), main, -np.ones(n - 1)], [-1, 0, 1]).tocsr()
    identity = Elimination(
        sp.identity(n, format="csr"), np.zeros(n), np.arange(n), np.array([], dtype=int)
    )
    pencil = ReducedPencil(stiffness, sp.identity(n, format="csr"), identity)
    assert not pencil.dense
    exact = k * (2.0 - 2.0 * np.cos(np.pi * np.arange(n) / n))
    for omega2 in (1.0e-3, 0.5, 40.0, 900.0):
        assert pencil.count_below(omega2) == np.count_nonzero(exact < omega2)


def test_a_band_from_zero_of_a_free_chain_counts_the_rigid_mode():
    """Free-free chain: a rigid mode at 0 Hz, whose computed ω² falls either
    side of 0; the elastic modes of BANDE (0, f) are modes 2, 3... whether
    the band kept the rigid mode or not."""
    session, model, k, m = chain_matrices(
        8, (K, K, K), M, ddl_impo=[{"TOUT": "OUI", "DY": 0.0, "DZ": 0.0}]
    )
    modes = run(
        session,
        "CALC_MODES",
        MATR_RIGI=k,
        MATR_MASS=m,
        OPTION="BANDE",
        CALC_FREQ={"FREQ": (0.0, 15.0)},
    )
    elastic = modes.frequencies > 1e-3
    # free-free chain of 8 masses: f_j = sqrt(k/m) sin(j pi / 16) / pi, j = 1..7
    exact = np.sqrt(K / M) * np.sin(np.arange(1, 8) * np.pi / 16) / np.pi
    np.testing.assert_allclose(modes.frequencies[elastic], exact[exact <= 15.0], rtol=1e-10)
    assert modes.mode_numbers[elastic].tolist() == list(range(2, 2 + int(elastic.sum())))


def test_an_empty_band_is_code_asters_solver_error(axial_chain):  # noqa: F811
    """code_aster stops an empty band with MODAL_1, a SolverError a deck may
    catch (sdll11j tests it)."""
    session, model, k, m = axial_chain
    band = {"FREQ": (1000.0, 2000.0)}
    with pytest.raises(CommandError, match="no eigenmode found") as caught:
        run(session, "CALC_MODES", MATR_RIGI=k, MATR_MASS=m, OPTION="BANDE", CALC_FREQ=band)
    assert caught.value.aster_exception == "SolverError"
