"""Fluid-film shocks (CHOC/LAME_FLUIDE='OUI' of code_aster 10-12,
asterlite.dynamics.fluid_film) against an independent integration of the same
one-degree-of-freedom squeeze film, and their path from a code_aster 11 deck."""

from __future__ import annotations

import numpy as np
import pytest
from asterlite.commands.dyna_vibra_words import transient_words
from scipy.integrate import solve_ivp

from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.fluid_film import FluidFilm, film_row, integrate_film
from asterlite.dynamics.model import LinearSystem, ShockSpec, build_shocks
from asterlite.errors import NumericalError
from asterlite.legacy import v11
from tests.validated import scheme_options

# sdnd110a's first case: a 1000 kg mass released at 0.1 m/s towards a fixed
# node across a 6 mm gap filled with a Poiseuille film
MASS, STIFFNESS, GAP, V0 = 1000.0, 1.0e-4, 0.006, -0.1
ALPHA, BETA, CHI, DELTA = -0.0833, 0.19992, -0.9996e-6, 0.0
DT, T_END = 2.5e-5, 0.19


def squeeze_film_reference(times):
    """(m - ALPHA/d) x'' = -k x + BETA (x'/d)^2 + CHI x'/d^3 (+ DELTA x'|x'|/d^2),
    d = GAP + x: the film's added mass solved exactly, integrated by Radau."""

    def rhs(t, y):
        x, v = y
        d = GAP + x
        force = BETA * (v / d) ** 2 + CHI * v / d**3 + DELTA * v * abs(v) / d**2
        return [v, (-STIFFNESS * x + force) / (MASS - ALPHA / d)]

    sol = solve_ivp(rhs, (0.0, T_END), [0.0, V0], method="Radau", rtol=1e-11, atol=1e-14,
                    dense_output=True)  # fmt: skip
    return sol.sol(times)[0]


def film_run(tolerance=1.0e-8, relaxation=10.0, max_iterations=2000):
    """The same system through asterlite: one mode (DX of node 1, generalized
    mass MASS), a BI_PLAN_Z shock to a fixed node 1 m away, DIST_1 + DIST_2 =
    1 - GAP, and the film of the shock."""
    system = LinearSystem(np.array([[MASS]]), np.array([[STIFFNESS]]), np.zeros((1, 1)))
    spec = ShockSpec(
        name="LIAISON", obstacle_type="BI_PLAN_Z", node_1="NO1", node_2="NO2",
        coord_1=np.array([1.0, 0.0, 0.0]), coord_2=np.zeros(3),
        phi_1=np.array([[1.0], [0.0], [0.0]]), phi_2=np.zeros((3, 1)),
        norm_obst=np.array([0.0, 0.0, 1.0]), angl_vril=0.0,
        dist_1=(1.0 - GAP) / 2, dist_2=(1.0 - GAP) / 2, k_n=2.0e10,
    )  # fmt: skip
    shocks = build_shocks([spec], system)
    film = FluidFilm(
        np.array([film_row(ALPHA, BETA, CHI, DELTA)]),
        max_iterations=max_iterations,
        tolerance=tolerance,
        relaxation=relaxation,
    )
    excitation = tabulate_excitation(1, [], 0.0, T_END, DT / 2)
    return integrate_film(system, shocks, film, excitation, [0.0], [V0], 0.0, T_END, DT,
                          np.zeros(0), 40, scheme_options("DIFF_CENTRE"))  # fmt: skip


def test_squeeze_film_follows_the_exact_equation():
    """The converged film gives the exact squeeze-film motion up to the scheme's
    first-order error: the mass stops short of the wall, 0.1 mm away."""
    result = film_run()
    times, x = result.times, result.depl[:, 0]
    reference = squeeze_film_reference(times)
    assert times[-1] == pytest.approx(T_END)
    assert np.max(np.abs(x - reference)) < 2.0e-3 * np.max(np.abs(reference))
    assert -GAP < x[-1] < -0.95 * GAP  # never reaches the wall (no dry contact)
    closing = result.vite[:, 0] < -1.0e-3
    assert closing.any() and np.all(result.vint[closing, 0, 0] > 0.0)  # the film pushes back


def test_relaxation_does_not_change_the_converged_motion():
    """LAMBDA only makes the iterations contract: converged runs agree."""
    a, b = film_run(relaxation=10.0), film_run(relaxation=3.0)
    assert np.allclose(a.depl, b.depl, rtol=1e-5, atol=1e-10)
    assert a.info["film_iterations"] != b.info["film_iterations"]


def test_no_convergence_is_an_error():
    with pytest.raises(NumericalError, match="NMAX_ITER=1"), transient_words():
        film_run(max_iterations=1)


class _Call:
    command = "DYNA_TRAN_MODAL"

    def __init__(self):
        self.notes = []

    def note(self, old, new, level=None, keyword=None):
        self.notes.append((old, new))

    def where(self, level=None, keyword=None):
        return None

    def unsupported(self, message, level=None, keyword=None, path=""):
        raise v11.UnsupportedError(message, None, f"{self.command}/{path or keyword}")

    @property
    def site(self):
        class Site:
            location = None

        return Site()


def test_code_aster_11_iterations_become_para_lame_flui():
    """Top-level NMAX_ITER/RESI_RELA/LAMBDA of a film deck: PARA_LAME_FLUI with
    code_aster 11's defaults for those not given; without a film, dropped."""
    film = {"LAME_FLUIDE": "OUI", "ALPHA": ALPHA, "BETA": BETA, "CHI": CHI, "DELTA": DELTA}
    call = {"SCHEMA_TEMPS": {"SCHEMA": "EULER"}, "CHOC": film, "NMAX_ITER": 7}
    adjusted = v11.fluid_film(call, _Call())
    assert "NMAX_ITER" not in adjusted
    assert dict(adjusted["PARA_LAME_FLUI"]) == {"NMAX_ITER": 7, "RESI_RELA": 1e-3, "LAMBDA": 10.0}
    dry = {"SCHEMA_TEMPS": {"SCHEMA": "EULER"}, "CHOC": {"RIGI_NOR": 1.0}, "LAMBDA": 5.0}
    assert "LAMBDA" not in v11.fluid_film(dry, _Call())


def test_code_aster_11_adapt_ordre1_with_a_film_is_refused():
    """ADAPT_ORDRE2 runs the film (tests/test_fluid_film_adapt.py), ADAPT_ORDRE1 not."""
    call = {"SCHEMA_TEMPS": {"SCHEMA": "ADAPT_ORDRE1"}, "CHOC": {"LAME_FLUIDE": "OUI"}}
    with pytest.raises(v11.UnsupportedError, match="ADAPT_ORDRE1.*code_aster 11"):
        v11.fluid_film(call, _Call())
