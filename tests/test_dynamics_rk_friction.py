"""RUNGE_KUTTA_32 / RUNGE_KUTTA_54 with DIS_CHOC friction (stick spring RIGI_TAN and
Coulomb slip on a PLAN_Y floor).

The engine is code_aster's intruku32 / intruku54 step for step: a Python transcription
of those routines (retries from the step-start state *and* internal variables, error
on q and v only, the same scales, thresholds and exponents) driving the engine's own
force evaluation takes the same steps, rejects the same attempts and ends in the same
state. Rejected attempts leave no trace, the internal variables kept after a step are
those of the solution point (both pairs are first-same-as-last), and on a friction
oscillator without grazing slip the schemes converge to DIFF_CENTRE's answer.
Why they do not converge on the tube's stick-slip window: docs/accuracy.md,
*Runge-Kutta on stick-slip*."""

from __future__ import annotations

import math

import numpy as np
import pytest

from asterlite.concepts.function import Formula
from asterlite.dynamics import contact as C
from asterlite.dynamics import scheme_runge_kutta as RK
from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.forces import acceleration, state_acceleration, total_force
from asterlite.dynamics.integrate import integrate
from asterlite.dynamics.model import LinearSystem, ShockSpec, build_shocks
from tests.validated import scheme_options

# the friction sample's oscillator: 2 kg on 8000 N/m, pressed on a PLAN_Y floor by
# RIGI_NOR * 0.1 = M G, Coulomb 0.15, stick spring 4e5 N/m; forced at 0.8 W0
M, K, G, MU, K_T = 2.0, 8.0e3, 9.81, 0.15, 4.0e5
W_FORCE = 0.8 * math.sqrt(K / M)
U0 = 3.0e-3


def oscillator(force, c_t, t_end, h):
    """(system, shocks, excitation) of the one-DOF friction oscillator; ``c_t`` is
    AMOR_TAN (None: code_aster's optimal value)."""
    mass, stiffness = np.array([[M]]), np.array([[K]])
    system = LinearSystem(mass, stiffness, np.zeros((1, 1)))
    shape = np.array([[1.0], [0.0], [0.0]])  # DX of the node: tangential to the floor
    spec = ShockSpec(
        name="FLOOR",
        obstacle_type="PLAN_Y",
        node_1="N1",
        node_2=None,
        coord_1=np.zeros(3),
        coord_2=None,
        phi_1=shape,
        phi_2=None,
        norm_obst=np.array([0.0, 0.0, 1.0]),
        orig_obst=np.array([0.0, 1.0, 0.0]),
        gap=0.9,
        k_n=M * G / 0.1,
        k_t=K_T,
        c_t=c_t,
        mu_dyn=MU,
        mu_stat=MU,
    )
    shocks = build_shocks([spec], system)
    sine = Formula(VALE="A*sin(W*INST)", NOM_PARA="INST", extra={"A": force, "W": W_FORCE})
    excitation = tabulate_excitation(1, [(shape[0], sine)], 0.0, t_end, h)
    return system, shocks, excitation


def engine_run(scheme, force, c_t, t_end, dt, tol, alpha=0.0, instants=None):
    system, shocks, excitation = oscillator(force, c_t, t_end, dt / 2.0)
    q0, v0 = np.array([U0]), np.zeros(1)
    instants = np.array([t_end]) if instants is None else instants
    options = scheme_options(scheme, tolerance=tol, alpha=alpha)
    return integrate(
        system, shocks, excitation, scheme, q0, v0, 0.0, t_end, dt, instants, 1, options
    )


# ---------------------------------------------------------------- code_aster's algorithm

BOGACKI_SHAMPINE = {  # intruku32: cdp, adp, edp; step factor 0.9 err^(-1/4)
    "c": (0.0, 0.5, 0.75, 1.0),
    "a": ((0.5,), (0.0, 0.75), (2 / 9, 1 / 3, 4 / 9)),
    "e": (5 / 72, -1 / 12, -1 / 9, 1 / 8),
    "p": 4.0,
}
DORMAND_PRINCE = {  # intruku54: cdp, adp, b4b5; step factor 0.9 err^(-1/6)
    "c": (0.0, 0.2, 0.3, 0.8, 8 / 9, 1.0, 1.0),
    "a": (
        (0.2,),
        (3 / 40, 9 / 40),
        (44 / 45, -56 / 15, 32 / 9),
        (19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729),
        (9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656),
        (35 / 384, 0.0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84),
    ),
    "e": (71 / 57600, 0.0, -71 / 16695, 71 / 1920, -17253 / 339200, 22 / 525, -1 / 40),
    "p": 6.0,
}
PAIRS = {"RUNGE_KUTTA_32": BOGACKI_SHAMPINE, "RUNGE_KUTTA_54": DORMAND_PRINCE}


def code_aster_run(scheme, force, c_t, t_end, dt, tol, alpha=0.0):
    """intruku32 / intruku54 (with dtmcalc's landing on INST_FIN) transcribed line by
    line, dtmacce being the engine's state_acceleration. Returns (q, v, vint, steps,
    rejected)."""
    pair = PAIRS[scheme]
    c, a, e, p = pair["c"], pair["a"], pair["e"], pair["p"]
    system, shocks, excitation = oscillator(force, c_t, t_end, dt / 2.0)
    model = (system.bundle(), shocks.bundle(), excitation.bundle())
    n, levels = system.n_modes, len(a)
    depl1, vite1 = np.array([U0]), np.zeros(1)
    acce1, fext, work, residual = np.zeros(n), np.zeros(n), np.zeros((5, 3)), np.zeros(n)
    vint = shocks.initial_vint(0.0)
    total_force(0.0, depl1, vite1, model[1], vint, model[2], work, fext)
    acceleration(fext, depl1, vite1, model[0], residual, acce1)
    epsi = 100.0 * np.finfo(float).eps
    dtmin, dtmax = 1.0e-10 * dt, 1.0e10 * dt  # PAS_MINI / PAS_MAXI defaults
    t1, steps, rejected = 0.0, 0, 0
    loop_eps = 10.0 * np.finfo(float).eps
    while t_end - t1 > (steps + 1) * loop_eps:
        if t1 + dt - t_end > (steps + 1) * loop_eps:
            dt = t_end - t1
        nlsav0 = vint.copy()
        errt0 = np.finfo(float).max
        while True:  # label 10: every trial restarts from the step-start state
            vint[:] = nlsav0
            depl2, vite2, acce2 = depl1.copy(), vite1.copy(), acce1.copy()
            kde, kvi = np.zeros((levels, n)), np.zeros((levels, n))
            for ee in range(levels):
                kde[ee], kvi[ee] = vite2, acce2
                depl2, vite2 = depl1.copy(), vite1.copy()
                for ss in range(ee + 1):
                    depl2 = depl2 + dt * a[ee][ss] * kde[ss]
                    vite2 = vite2 + dt * a[ee][ss] * kvi[ss]
                t2 = t1 + dt * c[ee + 1]
                state_acceleration(t2, depl2, vite2, acce2, fext, residual, vint, work, model)
            errde = sum(e[k] * kde[k] for k in range(levels)) + e[levels] * vite2
            errvi = sum(e[k] * kvi[k] for k in range(levels)) + e[levels] * acce2
            skd = np.maximum(tol * np.abs(depl1 + alpha), tol * (np.abs(depl2 - depl1) + alpha))
            skv = np.maximum(tol * np.abs(vite1 + alpha), tol * (np.abs(vite2 - vite1) + alpha))
            errd = np.sum((errde / np.maximum(skd, epsi)) ** 2)
            errv = np.sum((errvi / np.maximum(skv, epsi)) ** 2)
            errt = max(dt * math.sqrt((errd + errv) / (2 * n)), epsi)
            if errt * 1.01 > errt0:
                errt = 0.99
            if errt < (0.9 / 5.0) ** p:
                coeff = 5.0
            elif errt > (0.9 / 0.2) ** p:
                coeff = 0.2
            else:
                coeff = 0.9 * errt ** (-1.0 / p)
            dt2 = min(dtmax, dt * coeff)
            if errt >= 1.0 and dt2 >= dtmin:
                dt, errt0 = dt2, errt
                rejected += 1
                continue
            assert dt2 >= dtmin
            break
        depl1, vite1, acce1 = depl2, vite2, acce2.copy()
        t1 += dt
        dt = dt2
        steps += 1
    return depl1, vite1, vint, steps, rejected


@pytest.mark.parametrize(
    "scheme, force, tol, alpha",
    [
        ("RUNGE_KUTTA_32", 2.0, 1.0e-3, 0.0),
        ("RUNGE_KUTTA_32", 6.0, 1.0e-3, 1.0e-3),
        ("RUNGE_KUTTA_54", 2.0, 1.0e-3, 0.0),
        ("RUNGE_KUTTA_54", 6.0, 1.0e-5, 1.0e-3),
    ],
)
def test_engine_is_code_aster_step_for_step(scheme, force, tol, alpha):
    """AMOR_TAN = 0: asterlite's damping cap (not in code_aster) is inactive. The
    transcription sums the stages as code_aster does (depl2 += dt a k, term by term),
    the engine as q + dt (sum a k): the cases are ones where that rounding difference
    stays at rounding level (with an undamped stick spring and a tight tolerance it
    does not: the stick-slip decisions at near-zero slip velocity amplify it)."""
    t_end, dt = 0.3, 2.5e-4
    result = engine_run(scheme, force, 0.0, t_end, dt, tol, alpha)
    q, v, vint, steps, rejected = code_aster_run(scheme, force, 0.0, t_end, dt, tol, alpha)
    assert result.info["steps"] == steps
    assert result.info["rejected_steps"] == rejected
    switches = np.count_nonzero(np.diff(result.vint[:, 0, C.V_STICK]))
    assert switches >= 2  # the run goes through stick-slip transitions
    np.testing.assert_allclose(result.depl[-1], q, rtol=1.0e-6)
    np.testing.assert_allclose(result.vite[-1], v, rtol=1.0e-5, atol=1.0e-9)
    np.testing.assert_allclose(result.vint[-1], vint, rtol=1.0e-5, atol=1.0e-7)


def step_inputs(scheme, dt, q0, v0, force=6.0):
    """What integrate() hands to a scheme's step: state, memory, model (1-DOF oscillator)."""
    system, shocks, excitation = oscillator(force, 0.0, 1.0, 1.0e-4)
    model = (system.bundle(), shocks.bundle(), excitation.bundle())
    q, v = np.array([q0]), np.array([v0])
    f, a, work = np.zeros(1), np.zeros(1), np.zeros((5, 3))
    vint = shocks.initial_vint(0.0)
    total_force(0.0, q, v, model[1], vint, model[2], work, f)
    acceleration(f, q, v, model[0], np.zeros(1), a)
    state = (q, v, a, f, vint, np.zeros_like(vint), work)
    memory, _ = RK.prepare_with(
        RK.TABLEAUX[scheme], system, dt, scheme_options(scheme, tolerance=1e-6)
    )
    return state, memory, model, shocks


def copy_state(state):
    return tuple(x.copy() for x in state)


@pytest.mark.parametrize("scheme", ["RUNGE_KUTTA_32", "RUNGE_KUTTA_54"])
def test_rejected_attempts_leave_no_trace(scheme):
    """A step whose first trials go through slip -> stick and are rejected ends exactly
    as one trial of the accepted length from the step-start internal variables."""
    # sliding at 5 mm/s: a 5 ms trial reaches the velocity reversal and ends sticking
    state, memory, model, _ = step_inputs(scheme, 5.0e-3, 1.0e-4, -0.005)
    start = copy_state(state)
    s = memory[2].shape[0] - 2
    probe = copy_state(start)
    RK.attempt(0.0, 5.0e-3, probe, memory, model, s)
    assert probe[4][0, C.V_STICK] == 1.0  # the too-long trial ends sticking
    status, _, dt_used, _, rejected = RK.step(0.0, 5.0e-3, 0, state, memory, model)
    assert status == 0 and rejected >= 1 and dt_used < 5.0e-3
    assert state[4][0, C.V_STICK] == 0.0  # the accepted step still slides
    replay = copy_state(start)
    RK.attempt(0.0, dt_used, replay, memory, model, s)
    rows = memory[0]  # now the replay's solution
    np.testing.assert_array_equal(state[0], rows[RK.Q_STAGE])
    np.testing.assert_array_equal(state[1], rows[RK.V_STAGE])
    np.testing.assert_array_equal(state[4], replay[4])


@pytest.mark.parametrize("scheme", ["RUNGE_KUTTA_32", "RUNGE_KUTTA_54"])
def test_internal_variables_are_those_of_the_solution_point(scheme):
    """Both pairs are first-same-as-last: their last evaluation is at (q, v) of t + dt,
    so the kept contact state (local position, forces) is the solution's."""
    tableau = RK.TABLEAUX[scheme]
    assert tableau.c[-1] == 1.0
    state, memory, model, shocks = step_inputs(scheme, 1.0e-3, 1.0e-4, -0.02)
    status, _, dt_used, _, _ = RK.step(0.0, 1.0e-3, 0, state, memory, model)
    assert status == 0
    q, vint = state[0], state[4]
    rot, origin = shocks.rots[0], shocks.params[0, C.P_ORIGIN : C.P_ORIGIN + 3]
    position = shocks.params[0, C.P_COORD1 : C.P_COORD1 + 3] + shocks.phis[0, 0] @ q
    np.testing.assert_allclose(vint[0, C.V_LOC1 : C.V_LOC1 + 3], rot @ (position - origin))
    # and the tangential velocity kept (the friction law's "previous velocity") is the
    # solution's, not that of the sixth stage (also at t + dt for the 5(4) pair)
    vt = vint[0, C.V_VT1]
    u = rot @ (shocks.phis[0, 0] @ state[1])
    assert abs(vt) == pytest.approx(math.hypot(u[1], u[2]), rel=1.0e-12, abs=1.0e-15)
    assert 0.0 < dt_used <= 1.0e-3


def test_error_norm_is_code_aster_s():
    """err = max(dt sqrt((sum (E_q/s_q)^2 + sum (E_v/s_v)^2) / 2n), 100 eps), with
    E = sum e_k k_k over the stages and the solution, s = max(tol|x_n + alpha|,
    tol(|x_n+1 - x_n| + alpha), 100 eps): q and v only."""
    rng = np.random.default_rng(3)
    for scheme in ("RUNGE_KUTTA_32", "RUNGE_KUTTA_54"):
        tableau = RK.TABLEAUX[scheme]
        s, n = tableau.stages, 4
        options = scheme_options(scheme, tolerance=1.0e-4, alpha=2.0e-3)
        system = LinearSystem(np.eye(n), np.eye(n), np.zeros((n, n)))
        memory, _ = RK.prepare_with(tableau, system, 1.0e-3, options)
        rows = memory[0]
        rows[:] = rng.normal(size=rows.shape)
        q, v, dt = rng.normal(size=n), rng.normal(size=n), 3.0e-3
        e = tableau.e
        eq = sum(e[k] * rows[RK.VECTOR_ROWS + k] for k in range(s)) + e[s] * rows[RK.V_STAGE]
        ev = sum(e[k] * rows[RK.VECTOR_ROWS + s + k] for k in range(s)) + e[s] * rows[RK.A_STAGE]
        tol, alpha = 1.0e-4, 2.0e-3
        sq = np.maximum(tol * np.abs(q + alpha), tol * (np.abs(rows[RK.Q_STAGE] - q) + alpha))
        sv = np.maximum(tol * np.abs(v + alpha), tol * (np.abs(rows[RK.V_STAGE] - v) + alpha))
        expected = dt * math.sqrt((np.sum((eq / sq) ** 2) + np.sum((ev / sv) ** 2)) / (2 * n))
        assert RK.scaled_error(dt, q, v, memory, s) == pytest.approx(expected, rel=1.0e-12)


@pytest.mark.parametrize("scheme, tol", [("RUNGE_KUTTA_32", 1.0e-6), ("RUNGE_KUTTA_54", 1.0e-7)])
def test_converges_on_a_friction_oscillator_without_grazing(scheme, tol):
    """Forced oscillator with stick phases (default AMOR_TAN): at a tight tolerance the
    motion is DIFF_CENTRE's at a tiny step, checked every 1 ms (computed instants)."""
    t_end, force = 0.5, 2.0
    grid = np.linspace(0.0, t_end, 501)[1:]
    reference = engine_run("DIFF_CENTRE", force, None, t_end, 2.0e-6, 1.0e-5)
    result = engine_run(scheme, force, None, t_end, 2.5e-4, tol, instants=grid)
    assert np.count_nonzero(np.diff(result.vint[:, 0, C.V_STICK])) >= 2
    archived = np.searchsorted(result.times, grid - 1.0e-12)
    expected = np.interp(grid, reference.times, reference.depl[:, 0])
    error = np.abs(result.depl[archived, 0] - expected).max() / np.abs(expected).max()
    assert error < 2.0e-4
