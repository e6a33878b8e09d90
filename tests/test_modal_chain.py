"""Analytic checks of the eigen solver, normalisations and static modes on
spring-mass chains."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

from tests.test_fem_support import chain_matrices, run

K, M = 1.0e4, 2.0


def fixed_fixed_frequencies(n_free: int, k: float, m: float) -> np.ndarray:
    j = np.arange(1, n_free + 1)
    return 2.0 * np.sqrt(k / m) * np.sin(j * np.pi / (2 * (n_free + 1))) / (2 * np.pi)


@pytest.fixture
def axial_chain():
    # 12 nodes, ends clamped, only DX free: 10 axial modes
    return chain_matrices(
        12,
        (K, K, K),
        M,
        ddl_impo=[
            {"GROUP_NO": "ENDS", "DX": 0.0},
            {"TOUT": "OUI", "DY": 0.0, "DZ": 0.0},
        ],
    )


def test_smallest_modes_match_the_analytic_chain(axial_chain):
    session, model, k, m = axial_chain
    modes = run(
        session,
        "CALC_MODES",
        MATR_RIGI=k,
        MATR_MASS=m,
        OPTION="PLUS_PETITE",
        CALC_FREQ={"NMAX_FREQ": 4},
    )
    np.testing.assert_allclose(modes.frequencies, fixed_fixed_frequencies(10, K, M)[:4], rtol=1e-10)
    # default normalisation: largest component is +1
    np.testing.assert_allclose(modes.shapes.max(axis=0), 1.0)
    np.testing.assert_allclose(np.abs(modes.shapes).max(axis=0), 1.0)
    # generalized quantities and M-orthogonality
    gm = modes.shapes.T @ (m.matrix @ modes.shapes)
    np.testing.assert_allclose(np.diag(gm), modes.generalized_mass, rtol=1e-12)
    np.testing.assert_allclose(gm - np.diag(np.diag(gm)), 0.0, atol=1e-9 * gm.max())
    np.testing.assert_allclose(
        modes.generalized_stiffness / modes.generalized_mass,
        (2 * np.pi * modes.frequencies) ** 2,
        rtol=1e-10,
    )
    assert np.all(modes.shapes[modes.numbering.dof_indices([0, 11], "DX")] == 0.0)


@pytest.mark.parametrize(
    "option, calc_freq, expected",
    [
        ("BANDE", {"FREQ": (5.0, 18.0)}, lambda f: f[(f >= 5.0) & (f <= 18.0)]),
        (
            "CENTRE",
            {"FREQ": 15.0, "NMAX_FREQ": 3},
            lambda f: np.sort(f[np.argsort(abs(f - 15))[:3]]),
        ),
        (
            "PROCHE",
            {"FREQ": (3.0, 20.0)},
            lambda f: np.sort([f[np.argmin(abs(f - 3))], f[np.argmin(abs(f - 20))]]),
        ),
        ("TOUT", {}, lambda f: f),
    ],
)
def test_selections(axial_chain, option, calc_freq, expected):
    session, model, k, m = axial_chain
    modes = run(session, "CALC_MODES", MATR_RIGI=k, MATR_MASS=m, OPTION=option, CALC_FREQ=calc_freq)
    np.testing.assert_allclose(
        modes.frequencies, expected(fixed_fixed_frequencies(10, K, M)), rtol=1e-10
    )


def test_norm_mode_and_extr_mode(axial_chain):
    session, model, k, m = axial_chain
    modes = run(
        session,
        "CALC_MODES",
        MATR_RIGI=k,
        MATR_MASS=m,
        OPTION="PLUS_PETITE",
        CALC_FREQ={"NMAX_FREQ": 5},
    )
    normed = run(session, "NORM_MODE", MODE=modes, NORME="MASS_GENE")
    np.testing.assert_allclose(normed.generalized_mass, 1.0)
    np.testing.assert_allclose(np.einsum("ij,ij->j", normed.shapes, m.matrix @ normed.shapes), 1.0)
    np.testing.assert_allclose(modes.generalized_mass.max() > 1.0, True)  # source untouched
    eucl = run(session, "NORM_MODE", MODE=modes, NORME="EUCL")
    np.testing.assert_allclose(np.linalg.norm(eucl.shapes, axis=0), 1.0)
    at_node = run(session, "NORM_MODE", MODE=modes, GROUP_NO="FIRST", NOM_CMP="DX")
    # FIRST is clamped: the component is zero, the modes are left as they are
    np.testing.assert_allclose(at_node.shapes, modes.shapes)
    some = run(session, "EXTR_MODE", FILTRE_MODE={"MODE": modes, "NUME_MODE": (2, 4)})
    np.testing.assert_allclose(some.frequencies, modes.frequencies[[1, 3]])
    assert list(some.mode_numbers) == [2, 4]
    band = run(session, "EXTR_MODE", FILTRE_MODE={"MODE": modes, "FREQ_MIN": 5.0, "FREQ_MAX": 15.0})
    f = modes.frequencies
    np.testing.assert_allclose(band.frequencies, f[(f >= 5) & (f <= 15)])


def test_constrained_static_modes_of_a_chain():
    # free-free chain along x, support at N1 in DX: MODE_STAT of N1 DX is the rigid motion
    session, model, k, m = chain_matrices(
        6,
        (K, K, K),
        M,
        ddl_impo=[{"GROUP_NO": "FIRST", "DX": 0.0}, {"TOUT": "OUI", "DY": 0.0, "DZ": 0.0}],
    )
    modes = run(
        session,
        "MODE_STATIQUE",
        MATR_RIGI=k,
        MATR_MASS=m,
        MODE_STAT={"GROUP_NO": "FIRST", "AVEC_CMP": "DX"},
    )
    assert modes.n_modes == 1 and modes.mode_labels == ["N1 DX"]
    dx = modes.numbering.dof_indices(range(6), "DX")
    np.testing.assert_allclose(modes.shapes[dx, 0], 1.0)
    np.testing.assert_allclose(modes.frequencies, 0.0)
    # attachment mode: unit force at the free end of the same clamped chain
    att = run(session, "MODE_STATIQUE", MATR_RIGI=k, FORCE_NODALE={"NOEUD": "N6", "AVEC_CMP": "DX"})
    np.testing.assert_allclose(att.shapes[dx, 0], np.arange(6) / K)
    pseudo = run(session, "MODE_STATIQUE", MATR_RIGI=k, MATR_MASS=m, PSEUDO_MODE={"AXE": "X"})
    # K u = M·1 along x: end load accumulates the masses beyond each spring
    springs_force = M * np.arange(5, 0, -1)
    np.testing.assert_allclose(np.diff(pseudo.shapes[dx, 0]), springs_force / K)


def test_mode_stat_on_a_free_dof_is_an_error():
    from asterlite.errors import CommandError

    session, model, k, m = chain_matrices(
        3, (K, K, K), M, ddl_impo=[{"GROUP_NO": "FIRST", "DX": 0.0, "DY": 0.0, "DZ": 0.0}]
    )
    with pytest.raises(CommandError, match="no blocked DOF"):
        run(session, "MODE_STATIQUE", MATR_RIGI=k, MODE_STAT={"NOEUD": "N3", "TOUT_CMP": "OUI"})


def test_comb_matr_asse_and_assemblage(axial_chain):

    session, model, k, m = axial_chain
    combo = run(
        session,
        "COMB_MATR_ASSE",
        COMB_R=[{"MATR_ASSE": k, "COEF_R": 2.0}, {"MATR_ASSE": m, "COEF_R": -1.0}],
    )
    np.testing.assert_allclose(combo.matrix.toarray(), 2 * k.matrix.toarray() - m.matrix.toarray())


SCRIPT = r"""
import time
import numpy as np
from tests.test_fem_support import chain_matrices
from tests.test_fem_support import run
t0 = time.perf_counter()
n = 50_000  # 2D_DIS_T: DX and DY on each node -> 100 000 DOFs
session, model, k, m = chain_matrices(
    n, (1.0e4, 4.0e4), 2.0, modelisation="2D_DIS_T",
    ddl_impo=[{"GROUP_NO": "ENDS", "DX": 0.0, "DY": 0.0}],
)
t1 = time.perf_counter()
modes = run(session, "CALC_MODES", MATR_RIGI=k, MATR_MASS=m, OPTION="PLUS_PETITE",
            CALC_FREQ={"NMAX_FREQ": 50})
t2 = time.perf_counter()
j = np.arange(1, 51)
free = n - 2
base = 2 * np.sqrt(1.0e4 / 2.0) * np.sin(j * np.pi / (2 * (free + 1))) / (2 * np.pi)
analytic = np.sort(np.concatenate([base, 2.0 * base]))[:50]  # DX chain k, DY chain 4k
assert modes.n_modes == 50, modes.n_modes
assert k.numbering.n_dofs == 100_000
err = np.max(np.abs(modes.frequencies - analytic) / analytic)
assert err < 1e-6, err
print(f"100000 DOFs: front end {t1 - t0:.2f} s, 50 modes {t2 - t1:.2f} s, max rel. error {err:.1e}")
"""


@pytest.mark.slow
def test_hundred_thousand_dof_chain_in_a_subprocess():
    from tests.conftest import ROOT

    out = subprocess.run(
        [sys.executable, "-c", SCRIPT], cwd=ROOT, capture_output=True, text=True, timeout=600
    )
    assert out.returncode == 0, out.stderr
    print(out.stdout)
