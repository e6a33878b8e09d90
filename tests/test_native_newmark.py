"""NEWMARK's own loop compiled as C++ (asterlite/dynamics/native/newmark.cpp,
scheme_newmark.hpp) against numba's (scheme_newmark.fast_loop), bit for bit:
every obstacle geometry on diagonal (the one-pass update) and full matrices
(the LU solve), each friction kind, β and γ other than the defaults, the
forces of the step's start (code_aster 13-15: ``force_at_step_start``),
support motions, formula loads, steps cut short on the requested instants
(operators rebuilt), and the same failures."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.dynamics import contact as C
from asterlite.dynamics import kernel as K
from asterlite.dynamics import native
from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.integrate import integrate
from asterlite.dynamics.model import LinearSystem, build_shocks
from tests.native_runs import (
    FORMULAS,
    GEOMETRIES,
    N_MODES,
    assert_same_bits,
    numba_run,
    run,
    shock_of,
    system_of,
)
from tests.numba_reference import assert_same, reference
from tests.validated import scheme_options

# numba's side is its stored fingerprints (tests.numba_reference)
pytestmark = pytest.mark.usefixtures("needs_native")

SCHEME = "NEWMARK"


def options(**fields):
    return scheme_options(SCHEME, **fields)


def both(request, monkeypatch, **args):
    """The run of ``args`` with the C++ loop, then numba's (its fingerprint,
    tests.native_runs.numba_run)."""
    args.setdefault("scheme", SCHEME)
    return run(monkeypatch, True, **args), numba_run(request, monkeypatch, **args)


def impacts(result) -> bool:
    return bool((result.vint[:, 0, C.V_FN] > 0).any())


def rebuilt(result) -> bool:
    """Whether the run took steps of several lengths (the operators rebuilt
    for the step cut short on a requested instant, then for the stored one)."""
    return len(np.unique(result.step_info[1:, K.INFO_STEP])) > 1


def test_newmark_is_compiled():
    assert "NEWMARK" in native.LOOPS


@pytest.mark.parametrize("geometry", GEOMETRIES)
@pytest.mark.parametrize("diagonal", [True, False])
def test_every_obstacle_gives_numbas_bits(request, monkeypatch, geometry, diagonal):
    compiled, numba = both(
        request, monkeypatch, geometry=geometry, diagonal=diagonal, norm_obst=(0.3, 0.9, 0.3)
    )
    assert impacts(compiled) and rebuilt(compiled)
    assert_same_bits(compiled, numba)


@pytest.mark.parametrize("friction", ["none", "one-way", "both"])
@pytest.mark.parametrize("diagonal", [True, False])
def test_every_friction_gives_numbas_bits(request, monkeypatch, friction, diagonal):
    compiled, numba = both(
        request, monkeypatch, geometry="BI_CERCLE", friction=friction, diagonal=diagonal
    )
    assert impacts(compiled)
    if friction != "none":
        assert (compiled.vint[:, 0, C.V_FT1] != 0).any()
    assert_same_bits(compiled, numba)


# β, γ: the defaults' neighbours, a dissipative pair (γ > 1/2), a
# conditionally stable one (β < γ/2) and the linear acceleration method
PAIRS = [(0.3025, 0.6), (0.2, 0.5), (1.0 / 6.0, 0.5), (0.4, 0.7)]


@pytest.mark.parametrize("beta, gamma", PAIRS)
@pytest.mark.parametrize("diagonal", [True, False])
def test_beta_and_gamma_give_numbas_bits(request, monkeypatch, beta, gamma, diagonal):
    chosen = options(beta=beta, gamma=gamma)
    args = dict(geometry="CERCLE", diagonal=diagonal, supports=True)
    compiled, numba = both(request, monkeypatch, options=chosen, **args)
    assert impacts(compiled) and rebuilt(compiled)
    assert_same_bits(compiled, numba)
    default = run(monkeypatch, True, scheme=SCHEME, **args)
    assert not np.array_equal(default.depl, compiled.depl)  # the pair was used


@pytest.mark.parametrize("geometry", ["PLAN_Z", "DISCRET", "BI_PLAN_Y", "BI_CERC_INT"])
@pytest.mark.parametrize("diagonal", [True, False])
def test_forces_at_the_step_start_give_numbas_bits(request, monkeypatch, geometry, diagonal):
    """code_aster 13-15's NEWMARK: the forces evaluated after each update,
    for the next step (scheme_newmark.start_force)."""
    args = dict(geometry=geometry, diagonal=diagonal, norm_obst=(0.3, 0.9, 0.3))
    compiled, numba = both(request, monkeypatch, options=options(force_at_step_start=True), **args)
    assert impacts(compiled) and rebuilt(compiled)
    assert_same_bits(compiled, numba)
    today = run(monkeypatch, True, scheme=SCHEME, **args)
    assert not np.array_equal(today.depl, compiled.depl)  # the option was followed


@pytest.mark.parametrize("at_start", [False, True])
@pytest.mark.parametrize("diagonal", [True, False])
@pytest.mark.parametrize("geometry", ["CERCLE", "BI_PLAN_Z"])
def test_support_motions_give_numbas_bits(request, monkeypatch, geometry, diagonal, at_start):
    compiled, numba = both(
        request, monkeypatch, geometry=geometry, diagonal=diagonal, supports=True, pas_arch=1,
        options=options(force_at_step_start=at_start),
    )  # fmt: skip
    assert impacts(compiled)
    assert_same_bits(compiled, numba)


@pytest.mark.parametrize("formula", range(len(FORMULAS)))
@pytest.mark.parametrize("at_start", [False, True])
def test_formula_loads_give_numbas_bits(request, monkeypatch, formula, at_start):
    diagonal = formula % 2 == 0
    compiled, numba = both(
        request, monkeypatch, formula=formula, diagonal=diagonal,
        options=options(force_at_step_start=at_start),
    )  # fmt: skip
    assert_same_bits(compiled, numba)


def test_archiving_every_step_gives_numbas_bits(request, monkeypatch):
    compiled, numba = both(request, monkeypatch, geometry="BI_CERCLE", diagonal=False, pas_arch=1)
    assert len(compiled.times) > 1000
    assert_same_bits(compiled, numba)


def failure(monkeypatch, compiled: bool, system, spec, chosen) -> str:
    monkeypatch.setenv(native.SWITCH, "1" if compiled else "0")
    shocks = build_shocks([spec], system)
    excitation = tabulate_excitation(N_MODES, [], 0.0, 0.01, 1.0e-5)
    with pytest.raises(Exception) as raised:
        integrate(
            system, shocks, excitation, SCHEME, np.full(N_MODES, 2.0e-4), np.zeros(N_MODES),
            0.0, 0.01, 2.0e-5, np.array([0.01]), 1, chosen,
        )  # fmt: skip
    return str(raised.value)


@pytest.mark.parametrize("at_start", [False, True])
def test_a_diverging_shock_stops_both_alike(request, monkeypatch, at_start):
    """Absurd shock stiffness: the run stops with the same error on both."""
    rng = np.random.default_rng(3)
    system = system_of(True, rng)
    spec = shock_of("PLAN_Y", rng, "both", (1.0, 0.0, 0.0))
    spec.k_n, spec.c_n = 1.0e30, 1.0e20
    chosen = options(force_at_step_start=at_start)
    compiled = failure(monkeypatch, True, system, spec, chosen)
    numba = reference(request, lambda: failure(monkeypatch, False, system, spec, chosen))
    assert_same(compiled, numba, "the failure")


@pytest.mark.parametrize("diagonal", [True, False])
def test_an_unstable_run_stops_both_alike(request, monkeypatch, diagonal):
    """β near 0 far past the stability limit: q overflows, the run stops
    (STATUS_NOT_FINITE) with the same error on both."""
    rng = np.random.default_rng(5)
    stable = system_of(diagonal, rng)
    system = LinearSystem(stable.mass, stable.stiffness * 1.0e8, stable.damping)
    spec = shock_of("CERCLE", rng, "none", (1.0, 0.0, 0.0))
    spec.gap = 1.0  # never touched
    chosen = options(beta=1.0e-4, gamma=0.5)
    compiled = failure(monkeypatch, True, system, spec, chosen)
    numba = reference(request, lambda: failure(monkeypatch, False, system, spec, chosen))
    assert_same(compiled, numba, "the failure")
    assert "non-finite values" in compiled
