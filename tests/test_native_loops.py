"""The compiled C++ loops (asterlite.dynamics.native) against the numba
kernels they replace: the same positions and constants, and the same run to
the last bit on every obstacle geometry, friction kind, matrix kind, load
kind (tables, formula programs, sampled windows), support motion and scheme
covered."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.dynamics import contact as C
from asterlite.dynamics import kernel as K
from asterlite.dynamics import native
from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.integrate import integrate
from asterlite.dynamics.model import build_shocks
from asterlite.lang import numeric
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


def test_the_extension_was_built_with_the_python_positions():
    built = native.layout()
    python = {}
    for module in (K, C, numeric):
        python.update({k: getattr(module, k) for k in built if hasattr(module, k)})
    assert set(python) == set(built)  # every name of the extension is found on the Python side
    assert python == built


@pytest.mark.parametrize("geometry", GEOMETRIES)
@pytest.mark.parametrize("diagonal", [True, False])
def test_every_obstacle_gives_numbas_bits(request, monkeypatch, geometry, diagonal):
    compiled = run(monkeypatch, True, geometry, diagonal, norm_obst=(0.3, 0.9, 0.3))
    numba = numba_run(request, monkeypatch, geometry, diagonal, norm_obst=(0.3, 0.9, 0.3))
    fn = compiled.vint[:, 0, C.V_FN]
    assert (fn > 0).any()  # impacts
    assert_same_bits(compiled, numba)


@pytest.mark.parametrize("friction", ["none", "one-way", "both"])
def test_every_friction_gives_numbas_bits(request, monkeypatch, friction):
    compiled = run(monkeypatch, True, "BI_CERCLE", friction=friction)
    numba = numba_run(request, monkeypatch, "BI_CERCLE", friction=friction)
    if friction != "none":
        assert (compiled.vint[:, 0, C.V_FT1] != 0).any()
    assert_same_bits(compiled, numba)


@pytest.mark.parametrize("formula", range(len(FORMULAS)))
def test_formula_loads_give_numbas_bits(request, monkeypatch, formula):
    compiled = run(monkeypatch, True, formula=formula, diagonal=False)
    numba = numba_run(request, monkeypatch, formula=formula, diagonal=False)
    assert_same_bits(compiled, numba)


@pytest.mark.parametrize("geometry", ["CERCLE", "BI_PLAN_Z"])
def test_support_motions_give_numbas_bits(request, monkeypatch, geometry):
    compiled = run(monkeypatch, True, geometry, supports=True, pas_arch=1)
    numba = numba_run(request, monkeypatch, geometry, supports=True, pas_arch=1)
    assert_same_bits(compiled, numba)


def test_a_diverging_shock_stops_both_alike(request, monkeypatch):
    """Absurd stiffness: the run stops with the same error on both."""

    def outcome(compiled: bool) -> str:
        monkeypatch.setenv(native.SWITCH, "1" if compiled else "0")
        rng = np.random.default_rng(3)
        system = system_of(True, rng)
        spec = shock_of("PLAN_Y", rng, "both", (1.0, 0.0, 0.0))
        spec.k_n, spec.c_n = 1.0e30, 1.0e20
        shocks = build_shocks([spec], system)
        excitation = tabulate_excitation(N_MODES, [], 0.0, 0.01, 1.0e-5)
        with pytest.raises(Exception) as failure:
            integrate(
                system, shocks, excitation, "DIFF_CENTRE", np.full(N_MODES, 2.0e-4),
                np.zeros(N_MODES), 0.0, 0.01, 2.0e-5, np.array([0.01]), 1,
                scheme_options("DIFF_CENTRE"),
            )  # fmt: skip
        return str(failure.value)

    assert_same(outcome(True), reference(request, lambda: outcome(False)), "the failure")


def test_arrays_of_another_kind_are_refused_by_name():
    args = [np.zeros(3)] * 53
    with pytest.raises(TypeError, match="counters must be int64 values"):
        native._loops.diff_centre_loop(*args)
    with pytest.raises(TypeError, match="argument counters missing"):
        native._loops.diff_centre_loop(np.zeros(8))
    with pytest.raises(TypeError, match="argument clock must be a writable C-ordered array"):
        native._loops.diff_centre_loop(np.zeros((8, 2))[:, 0])


# the schemes whose own loop is compiled C++ besides DIFF_CENTRE (native.LOOPS)
PORTED_SCHEMES = ("RUNGE_KUTTA_32", "RUNGE_KUTTA_54")


@pytest.mark.parametrize("scheme", PORTED_SCHEMES)
@pytest.mark.parametrize("geometry, diagonal", [("CERCLE", True), ("BI_PLAN_Y", False)])
def test_every_ported_scheme_gives_numbas_bits(request, monkeypatch, scheme, geometry, diagonal):
    args = dict(geometry=geometry, diagonal=diagonal, scheme=scheme, supports=True, t_end=0.02)
    compiled = run(monkeypatch, True, **args)
    numba = numba_run(request, monkeypatch, **args)
    assert (compiled.vint[:, 0, C.V_FN] > 0).any()
    assert_same_bits(compiled, numba)


ENERGY_SCHEMES = ("DIFF_CENTRE", "NEWMARK", "DEVOGE", "RUNGE_KUTTA_54", "ADAPT_ORDRE1", "TRBDF2")


@pytest.mark.parametrize("scheme", ENERGY_SCHEMES)
@pytest.mark.parametrize("geometry, diagonal", [("CERCLE", True), ("BI_PLAN_Y", False)])
def test_the_energy_balance_gives_numbas_bits(request, monkeypatch, scheme, geometry, diagonal):
    """ENERGIE on every loop kind: the balance's rows bit for bit, with
    impacts, friction and support motions in the powers."""
    args = dict(geometry=geometry, diagonal=diagonal, scheme=scheme, supports=True, t_end=0.02)
    compiled = run(monkeypatch, True, energy=True, **args)
    numba = numba_run(request, monkeypatch, energy=True, **args)
    assert compiled.energy is not None and len(compiled.energy) == len(compiled.times)
    assert (compiled.vint[:, 0, C.V_FN] > 0).any()
    assert_same_bits(compiled, numba)
