"""Physical harmonic sweeps of large symmetric systems on MUMPS
(asterlite.harmonic.physical with asterlite.fem.sparse_direct's
MumpsPatternFactor): one analysis of the pattern, a factorisation a
frequency, checked on the whole matrix."""

from __future__ import annotations

import os

import numpy as np
import pytest
import scipy.sparse as sp
from scipy.sparse.linalg import spsolve

from asterlite.fem import sparse_direct
from asterlite.fem.constraints import eliminate
from asterlite.harmonic import physical
from asterlite.harmonic.fields import omega2
from asterlite.harmonic.modal import SingularSystem
from tests.test_harmonic_ordering import _grid_laplacian


def _hysteretic_grid(k: int):
    """Complex stiffness (loss factor 0.05) and a banded mass on a k³ grid."""
    stiffness = _grid_laplacian(k) * complex(1.0e4, 5.0e2)
    n = stiffness.shape[0]
    mass = sp.csc_matrix(sp.identity(n) * 2.0 + sp.eye(n, k=1) * 0.1 + sp.eye(n, k=-1) * 0.1)
    return stiffness, mass


def test_a_large_symmetric_sweep_factorises_on_mumps_to_a_stable_solve(needs_mumps):
    stiffness, mass = _hysteretic_grid(16)  # 4 096 unknowns: sparse_direct.LARGE_LIMIT
    n = stiffness.shape[0]
    assert n >= sparse_direct.LARGE_LIMIT
    clamped = sp.csr_matrix(([1.0], ([0], [0])), shape=(1, n))
    elimination = eliminate(clamped, np.zeros(1), n)
    sweep = physical.prepare(elimination, stiffness, mass)
    assert sweep.backend == "mumps"
    force = np.random.default_rng(1).standard_normal((1, n))
    frequencies = np.array([3.0, 11.0, 40.0])
    depl, info = physical.solve(sweep, frequencies, force, np.ones((3, 1), dtype=complex))
    assert info["mumps"] == 3 and info["ldl"] == 0 and info["superlu"] == 0
    assert sweep.mumps is None  # closed after the last frequency
    for row, frequency in zip(depl, frequencies, strict=True):
        # the whole system's residual on the free unknowns (a SuperLU solve
        # of this 3D pattern would take seconds a frequency)
        whole = sp.csr_matrix(stiffness - omega2(frequency) * mass)[1:, 1:]
        assert row[0] == 0.0
        residual = whole @ row[1:] - force[0, 1:]
        scale = abs(whole).sum(axis=1).max() * abs(row).max() + abs(force).max()
        assert abs(residual).max() <= 1e-13 * scale


def test_the_solver_choice_follows_asterlite_sparse_solver(needs_mumps, monkeypatch):
    stiffness, mass = _hysteretic_grid(16)
    elimination = eliminate(sp.csr_matrix((0, stiffness.shape[0])), np.zeros(0), stiffness.shape[0])
    monkeypatch.setenv("ASTERLITE_SPARSE_SOLVER", "superlu")
    assert physical.prepare(elimination, stiffness, mass).backend == "ldl"
    monkeypatch.setattr(sparse_direct, "mumps_available", lambda: False)
    monkeypatch.setenv("ASTERLITE_SPARSE_SOLVER", "auto")
    assert physical.prepare(elimination, stiffness, mass).backend == "ldl"


def test_one_analysis_serves_every_set_of_values(needs_mumps, monkeypatch):
    stiffness, mass = _hysteretic_grid(10)
    pencil = physical.aligned_pencil(stiffness, mass, None, upper=True)
    rhs = np.random.default_rng(2).standard_normal(pencil.n) + 0j
    indices_before = pencil.indices.copy()
    factors = {}
    for name, headroom in (("in core", None), ("on disk", 1024)):
        # the analysis (at the first factorisation) decides where the factor lives
        monkeypatch.setattr(sparse_direct.watchdog, "memory_headroom", lambda h=headroom: h)
        factor = factors[name] = sparse_direct.MumpsPatternFactor(
            pencil.n, pencil.indptr, pencil.indices
        )
        for frequency in (0.0, 8.0, 15.0):
            expected = spsolve(pencil.at(frequency), rhs)
            factor.factorise(pencil.data(frequency))
            np.testing.assert_allclose(factor.solve(rhs), expected, rtol=1e-9, atol=1e-14)
    in_core, on_disk = factors["in core"], factors["on disk"]
    np.testing.assert_array_equal(pencil.indices, indices_before)  # the caller's pattern
    assert on_disk.out_of_core and not in_core.out_of_core
    folder = on_disk._folder
    assert os.path.isdir(folder)
    on_disk.close()
    in_core.close()
    assert not os.path.exists(folder)


def test_a_singular_frequency_is_refused_by_name(needs_mumps):
    grid, _ = _hysteretic_grid(16)
    # a pair of unknowns whose stiffness [[1, 1], [1, 1]] is singular, and no mass
    stiffness = sp.csc_matrix(sp.block_diag([grid, np.ones((2, 2))]))
    n = stiffness.shape[0]
    elimination = eliminate(sp.csr_matrix((0, n)), np.zeros(0), n)
    sweep = physical.prepare(elimination, stiffness, sp.csc_matrix((n, n)))
    assert sweep.backend == "mumps"
    with pytest.raises(SingularSystem):
        physical.solve(sweep, [5.0], np.ones((1, n)), np.ones((1, 1), dtype=complex))
    assert sweep.mumps is None
    # singular at a frequency before its last: the factor is closed as well
    sweep = physical.prepare(elimination, stiffness, sp.csc_matrix((n, n)))
    with pytest.raises(SingularSystem):
        physical.solve(sweep, [5.0, 6.0], np.ones((1, n)), np.ones((2, 1), dtype=complex))
    assert sweep.mumps is None


def test_a_banded_sweep_stays_on_the_ldlt_when_mumps_plans_small_fronts(needs_mumps):
    """A line of 6 000 unknowns: MUMPS's analysis plans a factor of about two
    entries a column, where the LDLᵀ's column loop is faster than fronts."""
    n = 6000
    stiffness = sp.csc_matrix(
        sp.diags([-np.ones(n - 1), 2.0 * np.ones(n), -np.ones(n - 1)], [-1, 0, 1])
        * complex(1.0e4, 2.0e2)
    )
    mass = sp.csc_matrix(sp.identity(n))
    elimination = eliminate(sp.csr_matrix((0, n)), np.zeros(0), n)
    sweep = physical.prepare(elimination, stiffness, mass)
    assert sweep.backend == "mumps"  # by size, until the analysis
    force = np.random.default_rng(4).standard_normal((1, n))
    depl, info = physical.solve(sweep, [2.0, 7.0], force, np.ones((2, 1), dtype=complex))
    assert sweep.backend == "ldl" and info["ldl"] == 2 and info["mumps"] == 0
    expected = spsolve(sp.csc_matrix(stiffness - omega2(7.0) * mass), force[0].astype(complex))
    np.testing.assert_allclose(depl[1], expected, rtol=1e-9, atol=1e-12 * abs(expected).max())
    # a sweep of one frequency: its first is its last, whose matrices are
    # dropped once its values are built, after the choice of solver
    alone = physical.prepare(elimination, stiffness, mass)
    depl, info = physical.solve(alone, [7.0], force, np.ones((1, 1), dtype=complex))
    assert info["ldl"] == 1
    np.testing.assert_allclose(depl[0], expected, rtol=1e-9, atol=1e-12 * abs(expected).max())
