"""Energy balance of generalized transients (DYNA_VIBRA TRAN/GENE
ENERGIE=_F(), asterlite.dynamics.energy): each term against an analytic
value, the residual as an accuracy oracle for the schemes."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.dynamics import energy as E
from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.integrate import integrate
from asterlite.dynamics.model import LinearSystem, ShockSpec, build_shocks
from tests.conftest import SAMPLES
from tests.validated import scheme_options

ALL_SCHEMES = (
    "DIFF_CENTRE",
    "NEWMARK",
    "DEVOGE",
    "RUNGE_KUTTA_32",
    "RUNGE_KUTTA_54",
    "ADAPT_ORDRE1",
    "ADAPT_ORDRE2",
    "TRBDF2",
)


def oscillator(mass=2.0, freq=5.0, xi=0.0):
    omega = 2.0 * np.pi * freq
    return LinearSystem(
        np.eye(1) * mass, np.eye(1) * mass * omega**2, np.eye(1) * 2.0 * xi * omega * mass
    )


def balance(system, scheme, dt, t_end, q0=0.0, v0=1.0, shocks=None, loads=(), fixed=True):
    """(archived rows of the balance, run result), archiving every step."""
    shocks = shocks if shocks is not None else build_shocks([], system)
    excitation = tabulate_excitation(system.n_modes, list(loads), 0.0, t_end, dt / 2.0)
    options = (
        scheme_options(scheme, dt_min=dt, dt_max=dt)
        if fixed
        else scheme_options(scheme, tolerance=1.0e-7)
    )
    result = integrate(
        system, shocks, excitation, scheme, initial(q0, system), initial(v0, system),
        0.0, t_end, dt, np.array([]), 1, options, energy=True,
    )  # fmt: skip
    assert result.energy.shape == (len(result.times), E.N_COLUMNS)
    np.testing.assert_allclose(result.energy[:, E.C_INST], result.times)
    return result.energy, result


def initial(value, system):
    return np.broadcast_to(np.asarray(value, dtype=float), (system.n_modes,)).copy()


def max_residual(rows):
    return float(np.max(np.abs(rows[:, E.C_RESIDU])))


def mechanical(rows):
    return rows[:, E.C_ENER_CIN] + rows[:, E.C_ENER_POT]


# ----------------------------------------------------------------- (a) free vibration


@pytest.mark.parametrize("scheme", ["DIFF_CENTRE", "NEWMARK"])
def test_free_vibration_energy_is_kept_and_the_residual_is_second_order(scheme):
    """½ v M v + ½ q K q stays at its initial value ½ m v0² = 1 J; RESIDU is
    exactly its drift (nothing else moves) and falls as dt² (DIFF_CENTRE:
    the synchronous velocity v + dt/2 a; NEWMARK, the trapezoidal rule,
    keeps the energy of a linear undamped system to rounding)."""
    system = oscillator()
    residuals = []
    for dt in (2.0e-3, 1.0e-3, 5.0e-4):
        rows, _ = balance(system, scheme, dt, 1.0)
        assert rows[0, E.C_ENER_CIN] == pytest.approx(1.0)
        drift = mechanical(rows) - 1.0
        np.testing.assert_allclose(rows[:, E.C_RESIDU], drift, atol=1.0e-14)
        for column in (E.C_TRAV_EXT, E.C_DISS_AMOR, E.C_DISS_CHOC, E.C_DISS_FROT, E.C_TRAV_NL):
            assert np.all(rows[:, column] == 0.0)
        residuals.append(max_residual(rows))
    if scheme == "NEWMARK":
        assert max(residuals) < 1.0e-12
    else:
        orders = np.log2(np.array(residuals[:-1]) / np.array(residuals[1:]))
        assert np.all(np.abs(orders - 2.0) < 0.15), orders
        assert residuals[-1] < 1.0e-4


def test_damped_free_vibration_residual_orders():
    """With modal damping DISS_AMOR = the mechanical energy lost; NEWMARK's
    residual stays second order, DIFF_CENTRE's becomes first order: code_aster's
    form evaluates the damping force with the velocity of the previous half
    step (the oracle shows the scheme's order, not the quadrature's)."""
    system = oscillator(xi=0.05)
    orders = {}
    for scheme in ("NEWMARK", "DIFF_CENTRE"):
        residuals = []
        for dt in (2.0e-3, 1.0e-3, 5.0e-4):
            rows, _ = balance(system, scheme, dt, 1.0)
            lost = 1.0 - mechanical(rows)[-1]
            assert rows[-1, E.C_DISS_AMOR] == pytest.approx(lost, rel=2.0e-2)
            assert lost > 0.9  # 5 periods at 5 % damping
            residuals.append(max_residual(rows))
        orders[scheme] = np.log2(np.array(residuals[:-1]) / np.array(residuals[1:]))
    assert np.all(np.abs(orders["NEWMARK"] - 2.0) < 0.15), orders
    assert np.all(np.abs(orders["DIFF_CENTRE"] - 1.0) < 0.15), orders


# ----------------------------------------------------------------- (b) bouncing mass


def bouncing_mass(zeta, mass=2.0, k_n=1.0e6, gap=0.01):
    """A free mass along Y against a PLAN_Y obstacle at distance ``gap``
    (NORM_OBST = Z, so y_loc = Y), contact damping ratio ``zeta``."""
    system = LinearSystem(np.eye(1) * mass, np.zeros((1, 1)), np.zeros((1, 1)))
    omega = np.sqrt(k_n / mass)
    spec = ShockSpec(
        name="PLANE", obstacle_type="PLAN_Y", node_1="N1", node_2=None,
        coord_1=np.zeros(3), coord_2=None, phi_1=np.array([[0.0], [1.0], [0.0]]), phi_2=None,
        norm_obst=np.array([0.0, 0.0, 1.0]), orig_obst=np.zeros(3), gap=gap,
        k_n=k_n, c_n=2.0 * zeta * omega * mass,
    )  # fmt: skip
    return system, build_shocks([spec], system), omega


def restitution_loss(zeta, omega, mass=2.0, v0=1.0):
    """Energy lost in one impact of m p'' + C p' + K p = 0 from p = 0, p' = v0,
    until the force K p + C p' reaches zero (eq. 11's positive part): the
    mass leaves with the velocity it has then."""
    wd = omega * np.sqrt(1.0 - zeta**2)
    t_cut = (np.pi - np.arctan2(2.0 * zeta * np.sqrt(1.0 - zeta**2), 1.0 - 2.0 * zeta**2)) / wd
    v_exit = (
        v0
        * np.exp(-zeta * omega * t_cut)
        * (np.cos(wd * t_cut) - zeta * omega / wd * np.sin(wd * t_cut))
    )
    return 0.5 * mass * (v0**2 - v_exit**2)


@pytest.mark.parametrize("zeta", [0.1, 0.3])
def test_contact_damping_dissipates_the_energy_lost_in_the_impact(zeta):
    system, shocks, omega = bouncing_mass(zeta)
    lost = restitution_loss(zeta, omega)
    rows, result = balance(system, "RUNGE_KUTTA_54", 5.0e-7, 0.02, shocks=shocks)
    last = rows[-1]
    assert result.vite[-1, 0] < 0.0  # bounced back
    assert last[E.C_ENER_CHOC] == 0.0  # out of contact again
    assert last[E.C_DISS_CHOC] == pytest.approx(lost, rel=1.0e-3)
    assert 1.0 - last[E.C_ENER_CIN] == pytest.approx(lost, rel=1.0e-3)
    assert np.max(rows[:, E.C_ENER_CHOC]) > 0.3  # the contact spring held energy meanwhile
    assert max_residual(rows) < 1.0e-3


def test_elastic_impact_dissipates_nothing_and_the_oracle_flags_lagged_shock_forces():
    """AMOR_NOR = 0: DISS_CHOC is exactly zero, ENER_CHOC takes the kinetic
    energy and gives it back. NEWMARK and TRBDF2 apply the shock force of the
    previous step (code_aster's treatment): each impact creates energy, about
    2π²/N of it with N steps per contact period, and RESIDU says so."""
    system, shocks, omega = bouncing_mass(0.0)
    dt = 2.0 * np.pi / omega / 100.0
    for scheme in ALL_SCHEMES:
        rows, _ = balance(system, scheme, dt, 0.02, shocks=shocks)
        assert np.all(rows[:, E.C_DISS_CHOC] == 0.0)
        peak = np.max(rows[:, E.C_ENER_CHOC])
        assert 0.9 < peak <= 1.0 + max_residual(rows) + 1.0e-12, scheme
        gained = rows[-1, E.C_ENER_CIN] - 1.0
        assert rows[-1, E.C_RESIDU] == pytest.approx(gained, abs=1.0e-12)
        if scheme in ("NEWMARK", "TRBDF2"):
            assert rows[-1, E.C_RESIDU] > 0.05, scheme
        else:
            assert max_residual(rows) < 3.0e-3, scheme


# ----------------------------------------------------------------- (c) friction oscillator


def friction_session(tmp_path, extra=""):
    """The friction sample with ENERGIE=_F() (and ``extra`` DYNA_VIBRA keywords)."""
    from asterlite.io.export import describe_run
    from asterlite.runtime.session import Session

    folder = SAMPLES / "friction_oscillator"
    text = (folder / "friction_oscillator.comm").read_text()
    anchor = '    BASE_CALCUL="GENE",\n'
    text = text.replace(anchor, f"{anchor}    ENERGIE=_F(),\n{extra}", 1)
    text = text.replace("FIN()", 'BILAN = RECU_TABLE(CO=RESUGENE, NOM_TABLE="PARA_CALC")\nFIN()')
    assert "ENERGIE" in text
    (tmp_path / "deck.comm").write_text(text)
    (tmp_path / "deck.mail").write_text((folder / "friction_oscillator.mail").read_text())
    export = tmp_path / "deck.export"
    export.write_text("P ncpus 1\nF comm deck.comm D 1\nF mail deck.mail D 20\n")
    session = Session(describe_run(export), output_dir=tmp_path / "out")
    (tmp_path / "out").mkdir()
    session.run_all()
    assert all(t.ok for t in session.tests)
    return session


def test_friction_dissipation_follows_the_coulomb_decay(tmp_path):
    """Released from U0 with dry friction F = μ m g, the swing shrinks by
    2C = 2 μ m g / K each half period, and half period k dissipates
    μ m g (A_k + A_{k+1}) (the distance slid): after n half periods
    DISS_FROT = μ m g (2 n U0 - 2 n² C), the mechanical energy lost."""
    session = friction_session(tmp_path)
    table = session.namespace["BILAN"]
    assert session.namespace["RESUGENE"].tables["PARA_CALC"] is table
    rows = np.array([[row[name] for name in E.COLUMNS] for row in table.rows])
    m, k, g, mu, u0 = 2.0, 8.0e3, 9.81, 0.15, 3.0e-3
    c = mu * m * g / k
    omega = np.sqrt(k / m)
    times = rows[:, E.C_INST]
    mech = mechanical(rows)
    assert mech[0] == pytest.approx(0.5 * k * u0**2)
    for n in (1, 2, 3):
        t_n = n * np.pi / omega
        expected = mu * m * g * (2.0 * n * u0 - 2.0 * n * n * c)
        assert np.interp(t_n, times, rows[:, E.C_DISS_FROT]) == pytest.approx(expected, rel=1.0e-2)
        lost = mech[0] - np.interp(t_n, times, mech)
        assert lost == pytest.approx(expected, rel=2.0e-2)
    # the constant normal penetration (the weight) stays stored, dissipating nothing
    assert np.all(rows[:, E.C_DISS_CHOC] == 0.0)
    np.testing.assert_allclose(rows[:, E.C_ENER_CHOC], rows[0, E.C_ENER_CHOC], rtol=1.0e-3)
    assert max_residual(rows) < 1.0e-3 * mech[0]


def test_the_run_summary_reports_the_residual(tmp_path):
    session = friction_session(tmp_path)
    transients, _ = session.summaries.results()
    (run,) = transients
    assert abs(run["energy_residual"]) < 1.0e-4
    assert 0.0 <= run["energy_residual_ratio"] < 1.0e-3


# ----------------------------------------------------------------- (d) forced damped oscillator


class Sine:
    """A linear DEFI_FONCTION sampling sin(Ω t) finely (the kernel keeps its points)."""

    INTERPOL = ("LIN", "LIN")
    PROL_GAUCHE = PROL_DROITE = "CONSTANT"

    def __init__(self, omega, t_end):
        self.abscissas = np.linspace(0.0, t_end, 20001)
        self.ordinates = np.sin(omega * self.abscissas)

    def evaluate(self, t):
        return np.interp(t, self.abscissas, self.ordinates)


@pytest.mark.parametrize("scheme", ["NEWMARK", "RUNGE_KUTTA_54", "DEVOGE"])
def test_forced_damped_oscillator_work_minus_damping_is_the_energy_change(scheme):
    system = oscillator(xi=0.02)
    t_end, force = 2.0, 10.0
    load = (np.array([force]), Sine(2.0 * np.pi * 4.0, t_end))
    rows, result = balance(system, scheme, 2.5e-4, t_end, v0=0.0, loads=[load])
    change = mechanical(rows) - mechanical(rows)[0]
    work, damping = rows[:, E.C_TRAV_EXT], rows[:, E.C_DISS_AMOR]
    np.testing.assert_allclose(work - damping, change, atol=2.0e-4 * np.max(np.abs(work)))
    # each term on its own: the trapezoid of f(t) v and c v² over the archived states
    t, v = result.times, result.vite[:, 0]
    f = force * np.interp(t, load[1].abscissas, load[1].ordinates)
    assert work[-1] == pytest.approx(np.trapezoid(f * v, t), rel=1.0e-6)
    assert damping[-1] == pytest.approx(np.trapezoid(system.damping[0, 0] * v * v, t), rel=1.0e-6)
    assert damping[-1] > 0.5 * work[-1] > 0.0


# ----------------------------------------------------------------- (e) every scheme on shocks


def shock_problem(t_end):
    """The four-mode CERCLE problem of the specialised-loop tests (friction,
    contact damping, modal damping) released from a displaced state, with a
    harmonic load on the first shape: (system, shocks, loads)."""
    from tests.test_dynamics_specialised import small_shock_problem

    system, shocks, vectors = small_shock_problem()
    return system, shocks, [(vectors[0] * 2.0, Sine(190.0, t_end))]


# a reasonable step for each scheme on it: NEWMARK and TRBDF2 apply the shock
# forces of the previous step, a first-order error that needs finer steps
REASONABLE_STEPS = {"NEWMARK": 2.0e-6, "TRBDF2": 4.0e-6}


@pytest.mark.parametrize("scheme", ALL_SCHEMES)
def test_residual_is_small_for_every_scheme_at_a_reasonable_step(scheme):
    system, shocks, loads = shock_problem(0.1)
    dt = REASONABLE_STEPS.get(scheme, 1.0e-5)
    rows, _ = balance(system, scheme, dt, 0.1, q0=2.0e-4, v0=0.0, shocks=shocks, loads=loads)
    scale = np.max(mechanical(rows) + rows[:, E.C_ENER_CHOC])
    assert np.max(rows[:, E.C_ENER_CHOC]) > 0.0  # impacts
    assert rows[-1, E.C_DISS_FROT] > 1.0e-3 and rows[-1, E.C_DISS_CHOC] > 1.0e-4
    assert rows[-1, E.C_DISS_AMOR] > 0.0
    assert max_residual(rows) < 1.0e-3 * scale


@pytest.mark.parametrize("scheme", ["DIFF_CENTRE", "NEWMARK", "RUNGE_KUTTA_32"])
def test_residual_flags_a_step_beyond_the_scheme_accuracy(scheme):
    """A step VERI_PAS accepts (just below 1/20 of the shortest period with the
    shock stiffness) but far too coarse for the impacts: the balance is off
    by more than 1 % of the energy, ten times the fine run's residual."""
    from asterlite.dynamics.integrate import step_limit

    system, shocks, loads = shock_problem(0.1)
    coarse_step = 0.95 * step_limit(system, shocks, "DIFF_CENTRE")
    runs = [
        balance(system, scheme, dt, 0.1, q0=2.0e-4, v0=0.0, shocks=shocks, loads=loads)[0]
        for dt in (coarse_step, REASONABLE_STEPS.get(scheme, 1.0e-5))
    ]
    coarse, fine = runs
    scale = np.max(mechanical(coarse) + coarse[:, E.C_ENER_CHOC])
    assert max_residual(coarse) > 1.0e-2 * scale
    assert max_residual(coarse) > 10.0 * max_residual(fine)


def test_energy_off_computes_nothing():
    system = oscillator()
    excitation = tabulate_excitation(1, [], 0.0, 0.1, 1.0e-3)
    result = integrate(
        system, build_shocks([], system), excitation, "DIFF_CENTRE", np.zeros(1), np.ones(1),
        0.0, 0.1, 1.0e-3, np.array([]), 1, scheme_options("DIFF_CENTRE"),
    )  # fmt: skip
    assert result.energy is None


@pytest.mark.parametrize("scheme", ["DIFF_CENTRE", "RUNGE_KUTTA_54"])
def test_work_of_a_law_relation_is_trav_nl(scheme):
    """RELA_EFFO_DEPL F(u) = -300 u on the mode: its work is minus the
    energy of that spring, TRAV_NL = -(150 u² - 150 u0²), and the balance holds."""
    from tests.test_dynamics_laws_wiring import one_mode, spring_spec

    system = one_mode(100.0)
    shocks = build_shocks([spring_spec(300.0)], system)
    rows, result = balance(system, scheme, 1.0e-4, 0.5, q0=0.01, v0=0.0, shocks=shocks)
    u = result.depl[:, 0]
    np.testing.assert_allclose(
        rows[:, E.C_TRAV_NL], -150.0 * (u**2 - 0.01**2), atol=1.0e-3 * 150.0 * 0.01**2
    )
    assert np.all(rows[:, E.C_ENER_CHOC] == 0.0) and np.all(rows[:, E.C_DISS_CHOC] == 0.0)
    assert max_residual(rows) < 1.0e-3 * 0.5 * 400.0 * 0.01**2
