"""Fluid films under code_aster 10-12's ADAPT_ORDRE2 (mdadap with LAME_FLUIDE:
asterlite.dynamics.fluid_film.run_adapt_loop) against the film-less legacy
loop, an independent integration of sdnd112a's two masses, and the deck's
reference values; and the way a code_aster 11 deck reaches it."""

from __future__ import annotations

import numpy as np
import pytest
from asterlite.commands.dyna_vibra_words import transient_words
from scipy.integrate import solve_ivp

from asterlite import progress
from asterlite.dynamics import warmup
from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.fluid_film import FluidFilm, film_row, integrate_film
from asterlite.dynamics.integrate import integrate
from asterlite.dynamics.model import LinearSystem, ShockSpec, build_shocks
from asterlite.dynamics.scheme_adapt_ordre2_v11 import default_step_max
from asterlite.dynamics.step_limits import stability_limit
from asterlite.errors import NumericalError
from asterlite.legacy import v11
from tests.test_lame_fluide import _Call
from tests.validated import film_controls, scheme_options

# sdnd112a: two 25 kg masses on 98696 N/m springs (10 Hz), 1 mm apart across
# a fluid film (BI_PLAN_Z between NO2 at x = 0.1 and NO12 at x = 1.0); NO12
# starts 1 mm away from NO2
MASS, STIFFNESS, GAP, X0 = 25.0, 98696.0, 0.001, 0.001
ALPHA, BETA, CHI, DELTA = -0.08325, 0.07493, -0.9996e-6, -0.1665
RIGI_NOR, PAS, T_END = 2.88e10, 1.0e-5, 1.0
# its first TEST_RESU (ADAPT_ORDRE2): instant, NO2 and NO12 DX, their PRECISION
REFERENCES = (
    (0.05, -0.675e-3, -0.322e-3, 0.001, 0.008),
    (0.1, 0.544e-3, 0.450e-3, 0.006, 0.007),
    (0.45, -0.473e-3, -0.497e-3, 0.04, 0.04),
    (0.95, -0.468e-3, -0.468e-3, 0.07, 0.07),
)


def two_masses(angle: float, damping: float = 0.0, k_n: float = RIGI_NOR):
    """The system on a basis of the degenerate 10 Hz pair turned by ``angle``
    from the nodal modes (column j: mode j's DX at NO2, NO12), and its shock."""
    c, s = np.cos(angle), np.sin(angle)
    modes = np.array([[c, -s], [s, c]])
    system = LinearSystem(
        MASS * np.eye(2), STIFFNESS * np.eye(2), damping * np.eye(2)
    )  # fmt: skip
    spec = ShockSpec(
        name="NO2/NO12", obstacle_type="BI_PLAN_Z", node_1="NO2", node_2="NO12",
        coord_1=np.array([0.1, 0.0, 0.0]), coord_2=np.array([1.0, 0.0, 0.0]),
        phi_1=np.vstack([modes[0], np.zeros((2, 2))]),
        phi_2=np.vstack([modes[1], np.zeros((2, 2))]),
        norm_obst=np.array([0.0, 0.0, 1.0]), angl_vril=0.0,
        dist_1=0.4495, dist_2=0.4495, k_n=k_n,
    )  # fmt: skip
    return modes, system, build_shocks([spec], system)


def film_adapt_run(angle, coefficients=(ALPHA, BETA, CHI, DELTA), tolerance=1.0e-5,
                   max_iterations=100, t_end=T_END, x0=X0, dt_max=None, damping=0.0):  # fmt: skip
    """sdnd112a's first transient (ADAPT_ORDRE2, PAS_MAXI by default, PAS_ARCH
    100), physical DX of NO2 and NO12 at the archived instants."""
    modes, system, shocks = two_masses(angle, damping)
    if dt_max is None:
        dt_max = default_step_max(stability_limit(system, shocks).period)
    film = FluidFilm(np.array([film_row(*coefficients)]), max_iterations, tolerance, 10.0)
    excitation = tabulate_excitation(2, [], 0.0, t_end, PAS / 2)
    result = integrate_film(
        system, shocks, film, excitation, modes.T @ [0.0, x0], [0.0, 0.0], 0.0, t_end, PAS,
        np.zeros(0), 100, scheme_options("ADAPT_ORDRE2", adapt_v11=True, dt_max=dt_max),
    )  # fmt: skip
    return result, result.depl @ modes.T


def exact_two_masses(times):
    """The two masses with the film's added mass solved exactly (Radau):
    d = GAP + x2 - x1, F = ALPHA d''/d + BETA (d'/d)^2 + CHI d'/d^3
    + DELTA d'|d'|/d^2 pushing them apart."""

    def rhs(t, y):
        x1, x2, v1, v2 = y
        d, dv = GAP + x2 - x1, v2 - v1
        rest = BETA * (dv / d) ** 2 + CHI * dv / d**3 + DELTA * dv * abs(dv) / d**2
        c = ALPHA / d  # F = c (a2 - a1) + rest; M a1 = -K x1 - F, M a2 = -K x2 + F
        lhs = np.array([[MASS - c, c], [c, MASS - c]])
        a1, a2 = np.linalg.solve(lhs, [-STIFFNESS * x1 - rest, -STIFFNESS * x2 + rest])
        return [v1, v2, a1, a2]

    sol = solve_ivp(rhs, (0.0, max(times)), [0.0, X0, 0.0, 0.0], method="Radau", rtol=1e-10,
                    atol=1e-14, dense_output=True)  # fmt: skip
    return sol.sol(times)[:2].T


def at(result, x, t):
    """REST_GENE_PHYS INTERPOL='LIN': linear between archived instants."""
    return np.array([np.interp(t, result.times, x[:, j]) for j in range(2)])


def test_without_film_forces_the_loop_is_the_legacy_adapt_loop():
    """A film of zero coefficients adds nothing (its boundary layer is empty:
    the dry DIS_CHOC law of the normal stiffness): the run is that of the
    film-less code_aster 10-12 ADAPT_ORDRE2, step for step."""
    modes, system, shocks = two_masses(0.0, damping=5.0, k_n=1.0e8)
    options = scheme_options("ADAPT_ORDRE2", adapt_v11=True, dt_max=2.0e-5)
    args = (modes.T @ [0.0, 2.0 * X0], [0.0, 0.0], 0.0, 0.3, PAS, np.zeros(0), 10)
    plain = integrate(system, shocks, tabulate_excitation(2, [], 0.0, 0.3, PAS / 2),
                      "ADAPT_ORDRE2", *args, options)  # fmt: skip
    film = FluidFilm(np.array([film_row(0.0, 0.0, 0.0, 0.0)]), *film_controls())
    filmed = integrate_film(system, shocks, film, tabulate_excitation(2, [], 0.0, 0.3, PAS / 2),
                            *args, options)  # fmt: skip
    assert np.max(plain.vint[:, 0, 0]) > 100.0  # the masses hit each other
    assert filmed.info["steps"] == plain.info["steps"]
    assert filmed.info["rejected_steps"] == plain.info["rejected_steps"] > 0
    assert np.array_equal(filmed.times, plain.times)
    assert np.allclose(filmed.depl, plain.depl, rtol=0.0, atol=1e-15)
    assert np.allclose(filmed.vint[:, 0, 0], plain.vint[:, 0, 0], rtol=1e-9, atol=1e-9)


def test_converged_film_follows_the_exact_motion_on_any_basis():
    """Iterated to convergence, the film's diagonal added-mass stand-in (mdmasf)
    cancels: nodal or mixed modes, the motion is that of the exact equations."""
    times = np.array([0.05, 0.1])
    exact = exact_two_masses(times)
    for angle in (0.0, np.pi / 4):
        result, x = film_adapt_run(angle, tolerance=1.0e-14, max_iterations=5000, t_end=0.1)
        assert result.info["adaptive"]
        computed = np.array([at(result, x, t) for t in times])
        assert np.allclose(computed, exact, rtol=3.0e-3, atol=0.0)


def test_adapt_agrees_with_euler_under_the_decks_iterations():
    """Same film, same loose iterations (RESI_RELA=1e-5): mdadap's ADAPT_ORDRE2
    and mdeul1's EULER agree within 0.1 % of the amplitude."""
    result, x = film_adapt_run(np.pi / 4, t_end=0.1)
    modes, system, shocks = two_masses(np.pi / 4)
    film = FluidFilm(np.array([film_row(ALPHA, BETA, CHI, DELTA)]), 100, 1.0e-5, 10.0)
    euler = integrate_film(
        system, shocks, film, tabulate_excitation(2, [], 0.0, 0.1, PAS / 2),
        modes.T @ [0.0, X0], [0.0, 0.0], 0.0, 0.1, PAS, np.array([0.05, 0.1]), 10**9,
        scheme_options("DIFF_CENTRE"),
    )  # fmt: skip
    x_euler = euler.depl @ modes.T
    for t in (0.05, 0.1):
        assert np.allclose(at(result, x, t), at(euler, x_euler, t), rtol=0.0, atol=1.0e-6)


def test_sdnd112a_depends_on_the_basis_of_its_degenerate_modes():
    """With RESI_RELA=1e-5 the iterations stop far from their fixed point
    when the diagonal stand-in is poor: on the nodal modes (what CALC_MODES
    gives with another METHODE) they fail at t = 0.625; on the
    symmetric/antisymmetric pair (what code_aster 11's subspace JACOBI,
    started from diag(M), returns) the run meets every reference of the deck's first TEST_RESU."""
    with pytest.raises(NumericalError, match="NMAX_ITER=100"), transient_words():
        film_adapt_run(0.0)
    result, x = film_adapt_run(np.pi / 4)
    # PAS_MAXI: 1/20 of the period of a mode (shape 1/sqrt(2) at each node)
    # stiffened by RIGI_NOR, larger than PAS: the step grows to it
    omega2 = STIFFNESS / MASS + RIGI_NOR * 0.5 / MASS
    assert result.info["max_step"] == pytest.approx(2.0 * np.pi / np.sqrt(omega2) / 20.0)
    for t, no2, no12, precision_2, precision_12 in REFERENCES:
        errors = np.abs(at(result, x, t) / [no2, no12] - 1.0)
        assert errors[0] <= precision_2 and errors[1] <= precision_12


def test_code_aster_11_adapt_with_a_film_reaches_the_film_loop():
    """code_aster 11's ADAPT_ORDRE2 (mdadap) honoured the film: its top-level
    iterations become PARA_LAME_FLUI; ADAPT_ORDRE1 (mdadap too) and the
    schemes that took no film stay refused by name."""
    film = {"LAME_FLUIDE": "OUI", "ALPHA": ALPHA, "BETA": BETA, "CHI": CHI, "DELTA": DELTA}
    call = {"SCHEMA_TEMPS": {"SCHEMA": "ADAPT_ORDRE2"}, "CHOC": film, "NMAX_ITER": 100}
    adjusted = v11.fluid_film(call, _Call())
    assert dict(adjusted["PARA_LAME_FLUI"])["NMAX_ITER"] == 100
    for scheme in ("ADAPT_ORDRE1", "DEVOGE", "NEWMARK"):
        call = {"SCHEMA_TEMPS": {"SCHEMA": scheme}, "CHOC": film}
        with pytest.raises(v11.UnsupportedError, match=f"{scheme}.*code_aster 11"):
            v11.fluid_film(call, _Call())


def test_the_warmed_up_kernel_serves_a_film_run_without_compiling():
    """``asterlite warmup`` compiles the film's ADAPT_ORDRE2 loop with the
    argument types of any deck's (here sdnd112a's two-node BI_PLAN_Z)."""
    assert warmup.warm_one(warmup.FILM_ADAPT).error is None
    before = progress.compiled_seconds()
    film_adapt_run(np.pi / 4, t_end=0.01)
    assert progress.compiled_seconds() == before
