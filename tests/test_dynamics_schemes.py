"""Every SCHEMA_TEMPS of a GENE transient: convergence orders on a smooth
oscillator, adaptive control, shocks, defaults, and compiled-code caching."""

import math
import os
import subprocess
import sys

import numpy as np
import pytest
from asterlite.catalogues.dyna_vibra import ADAPTIVE

from asterlite.dynamics.schemes import SCHEMES
from tests.test_dynamics_vibra import kws, obstacle, one_mode, run_vibra, vector

OMEGA = 2.0 * math.pi


def oscillator_error(scheme, pas, schema=None):
    """Undamped oscillator (1 Hz) launched from its rest position, error after one period."""
    gnum, m, kk = one_mode(OMEGA**2, coords=(0.0, 0.0, 0.0), shape=(1.0, 0.0, 0.0))
    result = run_vibra(
        m, kk, scheme, pas, 1.0, etat={"VITE": vector(gnum, OMEGA, "VITE")}, schema=schema or {}
    )
    assert result.times[-1] == pytest.approx(1.0)
    return abs(result.depl[-1, 0]) + abs(result.vite[-1, 0] - OMEGA) / OMEGA, result


@pytest.mark.parametrize(
    "scheme, order, steps",
    [
        ("NEWMARK", 2.0, (0.004, 0.002)),
        ("TRBDF2", 2.0, (0.004, 0.002)),
        ("RUNGE_KUTTA_32", 3.0, (0.004, 0.002)),
        ("RUNGE_KUTTA_54", 5.0, (0.02, 0.01)),
        ("ADAPT_ORDRE1", 2.0, (0.004, 0.002)),
        ("ADAPT_ORDRE2", 2.0, (0.004, 0.002)),
    ],
)
def test_convergence_order_at_fixed_step(scheme, order, steps):
    fixed = (
        (lambda pas: {"PAS_MINI": pas, "PAS_MAXI": pas}) if scheme in ADAPTIVE else (lambda pas: {})
    )
    errors = [oscillator_error(scheme, pas, fixed(pas))[0] for pas in steps]
    assert math.log2(errors[0] / errors[1]) == pytest.approx(order, abs=0.3)


def test_newmark_beta_gamma_are_used():
    base, _ = oscillator_error("NEWMARK", 0.002)
    damped, _ = oscillator_error("NEWMARK", 0.002, {"BETA": 0.3025, "GAMMA": 0.6})
    assert damped > 10 * base  # gamma > 1/2 brings numerical damping (first order)


@pytest.mark.parametrize("scheme, tolerances", [
    ("RUNGE_KUTTA_32", (1e-4, 1e-6)),
    ("RUNGE_KUTTA_54", (1e-5, 1e-7)),
])  # fmt: skip
def test_runge_kutta_adapts_the_step_to_the_tolerance(scheme, tolerances):
    errors, steps = [], []
    for tol in tolerances:
        err, result = oscillator_error(scheme, 1.0e-3, {"TOLERANCE": tol})
        errors.append(err)
        steps.append(result.info["steps"])
        assert result.info["adaptive"]
        assert result.info["max_step"] > 1.0e-3  # grew from PAS
        assert result.info["min_step"] <= result.info["max_step"]
        assert err < 200 * tol
    assert errors[1] < errors[0] / 10 and steps[1] > steps[0]


def test_runge_kutta_rejects_steps_when_pas_is_too_large():
    err, result = oscillator_error("RUNGE_KUTTA_32", 0.2, {"TOLERANCE": 1e-6})
    assert result.info["rejected_steps"] > 0
    assert result.info["min_step"] < 0.2
    assert err < 1e-3


@pytest.mark.parametrize("scheme", ["ADAPT_ORDRE1", "ADAPT_ORDRE2"])
def test_adapt_schemes_follow_the_apparent_frequency(scheme):
    """About NB_POIN_PERIODE steps per period: the step settles below T/50."""
    err, result = oscillator_error(scheme, 1.0e-3)
    assert result.info["adaptive"]
    assert 0.01 < result.info["max_step"] < 1.0 / 50.0
    assert err < 0.05
    err2, result2 = oscillator_error(scheme, 1.0e-3, {"NB_POIN_PERIODE": 200})
    assert result2.info["max_step"] < 1.0 / 200.0 and err2 < err


def test_adapt_rejects_a_step_too_long_for_the_period():
    _, result = oscillator_error("ADAPT_ORDRE2", 0.05, {"COEF_DIVI_PAS": 2.0})
    assert result.info["rejected_steps"] > 0
    assert result.info["min_step"] < 1.0 / 50.0


def contact_duration(result, gap):
    """First contact's duration from the interpolated crossings of the gap."""
    y = result.shocks[0].fields["DYLOC"] - gap
    t = result.times
    cross = np.nonzero(np.sign(y[1:]) != np.sign(y[:-1]))[0]
    enter, leave = cross[0], cross[1]
    t_in = t[enter] - y[enter] * (t[enter + 1] - t[enter]) / (y[enter + 1] - y[enter])
    t_out = t[leave] - y[leave] * (t[leave + 1] - t[leave]) / (y[leave + 1] - y[leave])
    return t_out - t_in


@pytest.mark.parametrize("scheme", sorted(SCHEMES))
def test_bouncing_contact_lasts_half_a_shock_period(scheme):
    k, kn, gap = 1.0, 1.0e6, 0.01
    gnum, m, kk = one_mode(k, coords=(0.0, 0.0, 0.0), shape=(0.0, 1.0, 0.0))
    origin, axis = (0.0, 0.0, 0.0), (1.0, 0.0, 0.0)
    stop = dict(RELATION="DIS_CHOC", NOEUD_1="NO1", OBSTACLE=obstacle("PLAN_Y"),
                ORIG_OBST=origin, NORM_OBST=axis, JEU=gap, RIGI_NOR=kn)  # fmt: skip
    schema = {"PAS_MAXI": 2.0e-5} if scheme in ("RUNGE_KUTTA_32", "RUNGE_KUTTA_54") else {}
    if scheme == "DEVOGE":
        schema = {"PAS_MINI": 2.0e-5, "PAS_MAXI": 2.0e-5}
    result = run_vibra(m, kk, scheme, 2.0e-5, 0.016, etat={"VITE": vector(gnum, 1.0, "VITE")},
                       comportement=[stop], schema=schema)  # fmt: skip
    expected = math.pi * math.sqrt(1.0 / (kn + k))
    assert contact_duration(result, gap) == pytest.approx(expected, rel=0.01)
    assert result.shocks[0].fields["FN"].max() == pytest.approx(kn * 1.0 / 1.0e3, rel=0.05)
    after = np.nonzero(result.times > 0.0145)[0][0]
    # elastic bounce; the implicit schemes see the shock force one step late
    # (code_aster's explicit treatment), which feeds a little energy in
    lagged = scheme in ("NEWMARK", "TRBDF2")
    assert result.vite[after, 0] == pytest.approx(-1.0, rel=0.05 if lagged else 0.01)


def test_default_scheme_is_runge_kutta_32():
    """A call without SCHEMA_TEMPS integrates with the catalogue's default scheme."""
    from asterlite.catalogues.dyna_vibra import DYNA_VIBRA

    from asterlite.catalog.validator import validate
    from commands import dyna_vibra
    from tests.test_dynamics_vibra import ctx

    gnum, m, kk = one_mode(OMEGA**2, coords=(0.0, 0.0, 0.0), shape=(1.0, 0.0, 0.0))
    kw = validate(DYNA_VIBRA, dict(
        TYPE_CALCUL="TRAN", BASE_CALCUL="GENE", MATR_MASS=m, MATR_RIGI=kk,
        INCREMENT=dict(PAS=1.0e-3, INST_FIN=1.0),
        ETAT_INIT=dict(VITE=vector(gnum, OMEGA, "VITE")),
    ))  # fmt: skip
    result = dyna_vibra.run(ctx(), kw)
    assert result.scheme == "RUNGE_KUTTA_32"
    assert result.depl[-1, 0] == pytest.approx(0.0, abs=1e-3)


@pytest.mark.parametrize("scheme", ["RUNGE_KUTTA_32", "ADAPT_ORDRE2", "NEWMARK", "TRBDF2"])
def test_requested_instants_are_reached_exactly(scheme):
    gnum, m, kk = one_mode(OMEGA**2)
    arch = [kws("DYNA_VIBRA/ARCHIVAGE", INST=(0.0123, 0.5), PAS_ARCH=10**6)]
    result = run_vibra(m, kk, scheme, 1.0e-3, 1.0, etat={"DEPL": vector(gnum, 1.0)},
                       ARCHIVAGE=arch)  # fmt: skip
    assert list(result.times) == [0.0, 0.0123, 0.5, pytest.approx(1.0)]
    assert result.info["steps"] >= 3 and np.all(np.diff(result.order) > 0)


def test_compiled_loops_are_cached_across_processes(monkeypatch):
    """A fresh process loads every numba loop from numba's cache: no
    recompilation (numba's loops here, not the C++ ones that serve by default)."""
    monkeypatch.setenv("ASTERLITE_NATIVE", "0")  # this process and the child
    oscillator_error("DIFF_CENTRE", 0.01)  # make sure the cache is written
    code = (
        "import numpy as np\n"
        "from asterlite.commands.dyna_vibra_problem import catalogue_options\n"
        "from asterlite.dynamics.integrate import integrate\n"
        "from asterlite.dynamics.schemes import SCHEMES\n"
        "from asterlite.dynamics.excitation import tabulate_excitation\n"
        "from asterlite.dynamics.model import LinearSystem, build_shocks\n"
        "s = LinearSystem(np.eye(1), np.eye(1), np.zeros((1, 1)))\n"
        "integrate(s, build_shocks([], s), tabulate_excitation(1, [], 0, 1, 0.1),\n"
        "          'DIFF_CENTRE', np.ones(1), np.zeros(1), 0.0, 1.0, 0.01, np.array([1.0]), 1,\n"
        "          catalogue_options('DIFF_CENTRE'))\n"
        "loop = SCHEMES['DIFF_CENTRE'].implementation().fast_loop\n"
        "print(sum(loop.stats.cache_hits.values()), sum(loop.stats.cache_misses.values()))\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    hits, misses = (int(x) for x in out.stdout.split())
    assert hits == 1 and misses == 0


@pytest.mark.parametrize("scheme", ["ADAPT_ORDRE1", "NEWMARK"])
def test_the_one_time_loop_is_cached_per_step_across_processes(scheme):
    """loop.scheme_loop's loop around a scheme's step (its own loop, its
    general path: here the general one, no 4th bundle) is cached like a
    function of the step's module: a fresh process loads it (a loop taking
    the step as an argument would be compiled again in every process)."""
    code = (
        "import numpy as np\n"
        "from asterlite.commands.dyna_vibra_problem import catalogue_options\n"
        "from asterlite.dynamics.integrate import integrate\n"
        "from asterlite.dynamics.loop import scheme_loop\n"
        "from asterlite.dynamics.schemes import SCHEMES\n"
        "from asterlite.dynamics.excitation import tabulate_excitation\n"
        "from asterlite.dynamics.model import LinearSystem, build_shocks\n"
        "s = LinearSystem(np.eye(1), np.eye(1), np.zeros((1, 1)))\n"
        "integrate(s, build_shocks([], s), tabulate_excitation(1, [], 0, 1, 0.1),\n"
        f"          {scheme!r}, np.ones(1), np.zeros(1), 0.0, 1.0, 0.01, np.array([1.0]), 1,\n"
        f"          catalogue_options({scheme!r}), specialised=False)\n"
        f"loop = scheme_loop(SCHEMES[{scheme!r}].implementation().step)\n"
        "print(sum(loop.stats.cache_hits.values()), sum(loop.stats.cache_misses.values()))\n"
    )
    numba_loops = {**os.environ, "ASTERLITE_NATIVE": "0"}  # else the C++ loop serves the run
    for _ in range(2):
        out = subprocess.run(
            [sys.executable, "-c", code],
            capture_output=True,
            text=True,
            check=True,
            env=numba_loops,
        )
    hits, misses = (int(x) for x in out.stdout.split())
    assert hits == 1 and misses == 0


# ----------------------------------------------------------------- shock damping cap


def test_stage_stability_radius_of_the_tableaux():
    """The real stability interval [-radius, 0] of the explicit stages, from
    the stability function of the weights (1 + x + x²/2 + x³/6 for the 3(2)
    pair: radius 2.5127)."""
    from asterlite.dynamics.scheme_runge_kutta import TABLEAUX, stability_function

    expected = {"RUNGE_KUTTA_32": 2.5127453, "RUNGE_KUTTA_54": 3.3065679}
    for name, tableau in TABLEAUX.items():
        radius = tableau.radius
        assert radius == pytest.approx(expected[name], abs=1.0e-6)
        assert abs(stability_function(tableau.a, -radius)) == pytest.approx(1.0, abs=1.0e-9)
        assert abs(stability_function(tableau.a, -1.01 * radius)) > 1.0
    x = 1.3
    bs3 = stability_function(TABLEAUX["RUNGE_KUTTA_32"].a, -x)
    assert bs3.real == pytest.approx(1.0 - x + x**2 / 2.0 - x**3 / 6.0, abs=1.0e-14)


def test_kernel_damping_cap_matches_the_named_limit():
    """The step cap the RUNGE_KUTTA_* and DEVOGE kernels compute from their
    model equals step_limits.shock_damping_limit (the number checked_step names):
    modal damping counted for the Runge-Kutta stages, not for DEVOGE
    (implicit there); no cap without shock damping."""
    from asterlite.dynamics.adapt_control import shock_damping_step
    from asterlite.dynamics.model import LinearSystem, ShockSpec, build_shocks
    from asterlite.dynamics.step_limits import shock_damping_limit

    mass = np.diag([2.0, 0.5])
    stiffness = np.diag([4.0e4, 9.0e6])
    damping = np.diag([8.0, 600.0])
    system = LinearSystem(mass, stiffness, damping)

    shape = np.array([[0.1, 0.0], [1.0, -0.7], [0.0, 0.3]])

    def spec(c_n, c_t=None):
        return ShockSpec(
            name="S", obstacle_type="PLAN_Y", node_1="N1", node_2=None,
            coord_1=np.zeros(3), coord_2=None, phi_1=shape, phi_2=None,
            norm_obst=np.array([0.0, 0.0, 1.0]), orig_obst=np.zeros(3), gap=1.0e-3,
            k_n=1.0e7, c_n=c_n, k_t=1.0e5 if c_t else 0.0, c_t=c_t,
        )  # fmt: skip

    for c_n, c_t in ((3.0e4, None), (10.0, 5.0e5)):
        shocks = build_shocks([spec(c_n, c_t)], system)
        for radius, modal in ((3.3065679, True), (2.5127453, True), (2.0, False)):
            named = shock_damping_limit(system, shocks, radius, modal=modal)
            cap = shock_damping_step(system.bundle(), shocks.bundle(), modal, radius)
            assert math.isfinite(named.step) and cap == pytest.approx(named.step, rel=1.0e-12)
            assert named.shock == "S" and named.node == "N1"
            # heavy damping: radius over the damping per unit mass
            assert named.step <= radius / named.per_mass * (1.0 + 1.0e-12)
    free = build_shocks([spec(0.0)], system)
    assert shock_damping_step(system.bundle(), free.bundle(), True, 3.3) == math.inf
    assert shock_damping_limit(system, free, 3.3).step == math.inf


# ------------------------------------------------- TRBDF2 with modal damping


class SineMultiplier:
    """FONC_MULT sin(w t) as a fine linear table (the kernels interpolate its
    points exactly as a DEFI_FONCTION's; spacing 1e-5 s: error ~1e-10)."""

    INTERPOL = ("LIN", "LIN")

    def __init__(self, w, t_end):
        self.abscissas = np.linspace(0.0, t_end, int(round(t_end / 1.0e-5)) + 1)
        self.ordinates = np.sin(w * self.abscissas)

    def evaluate(self, t):
        return np.interp(t, self.abscissas, self.ordinates)


def damped_exact(k, c, force, w, q0, v0, t):
    """(q, v) at t of q'' + c q' + k q = force sin(w t) (unit mass): the
    forcing generated by (s, r)' = (w r, -w s), the whole system exact by expm."""
    import scipy.linalg as sla

    a = np.array([[0.0, 1.0, 0.0, 0.0], [-k, -c, force, 0.0],
                  [0.0, 0.0, 0.0, w], [0.0, 0.0, -w, 0.0]])  # fmt: skip
    y = sla.expm(a * t) @ np.array([q0, v0, 0.0, 1.0])
    return y[0], y[1]


def damped_trbdf2(xi, pas, t_end, q0=0.0, v0=0.0, force=0.0, w=3.0):
    """TRBDF2 on the unit-mass 1 Hz mode with AMOR_REDUIT=xi; errors (q, v)
    against the exact solution at t_end, and the result."""
    gnum, m, kk = one_mode(OMEGA**2, coords=(0.0, 0.0, 0.0), shape=(1.0, 0.0, 0.0))
    etat = {"DEPL": vector(gnum, q0), "VITE": vector(gnum, v0, "VITE")}
    extra = {"AMOR_MODAL": [kws("DYNA_VIBRA/AMOR_MODAL", AMOR_REDUIT=(xi,))]} if xi else {}
    if force:
        load = vector(gnum, force, "FORC")
        mult = SineMultiplier(w, t_end + 0.01)
        extra["EXCIT"] = [kws("DYNA_VIBRA/EXCIT", VECT_ASSE_GENE=load, FONC_MULT=mult)]
    result = run_vibra(m, kk, "TRBDF2", pas, t_end, etat=etat, **extra)  # a fixed-step scheme
    assert result.times[-1] == pytest.approx(t_end)
    q, v = damped_exact(OMEGA**2, 2.0 * xi * OMEGA, force, w, q0, v0, result.times[-1])
    return abs(result.depl[-1, 0] - q), abs(result.vite[-1, 0] - v), result


@pytest.mark.parametrize("xi", [0.05, 0.5])
def test_trbdf2_is_second_order_with_modal_damping_from_rest(xi):
    """Forced from rest (K q_0 + C v_0 = 0): the TR-BDF2 steps are exact on
    the damped system, order 2 on displacement and velocity."""
    errors = [damped_trbdf2(xi, pas, 1.0, force=1.0)[:2] for pas in (0.002, 0.001)]
    for coarse, fine in zip(*errors, strict=True):
        assert math.log2(coarse / fine) == pytest.approx(2.0, abs=0.1)


@pytest.mark.parametrize("xi, q0, v0", [(0.05, 0.0, 1.0), (0.5, 0.0, 1.0), (0.0, 1.0, 0.0)])
def test_trbdf2_first_step_seed_is_code_asters_zero_state(xi, q0, v0):
    """code_aster's inttrbdf2 evaluates the first step's stage accelerations
    on the zeroed index-2 state (intinivec): with e = K q_0 + C v_0 ≠ 0 the
    first step gains v += (1 - √2/4) dt e, q += (1 - √2/2) dt² e, and the
    velocity converges at order 1 (damped or not)."""
    k, c = OMEGA**2, 2.0 * xi * OMEGA
    e = k * q0 + c * v0
    dt = 1.0e-4
    dq, dv, result = damped_trbdf2(xi, dt, dt, q0=q0, v0=v0)
    q1, v1 = result.depl[-1, 0], result.vite[-1, 0]
    q_exact, v_exact = damped_exact(k, c, 0.0, 3.0, q0, v0, dt)
    assert v1 - v_exact == pytest.approx((1.0 - math.sqrt(2.0) / 4.0) * dt * e, rel=2.0e-3)
    assert q1 - q_exact == pytest.approx((1.0 - math.sqrt(2.0) / 2.0) * dt**2 * e, rel=2.0e-3)
    errors = [damped_trbdf2(xi, pas, 1.0, q0=q0, v0=v0)[1] for pas in (0.002, 0.001)]
    assert math.log2(errors[0] / errors[1]) == pytest.approx(1.0, abs=0.1)
