"""DIS_VISC under RUNGE_KUTTA_32 with an adaptive step (sdnd107e's setting).

code_aster's sequence, which asterlite follows:

- intruku32 evaluates the relation at the stages t + dt/2, t + 3dt/4, t + dt
  (the last one first-same-as-last) with STEP = dt (c_k+1 - c_k): the
  relation's internal state moves from stage to stage (dtmforc_dvis, rk5adp
  over that sub-interval with the stage's relative velocity held), a retried
  step restores it (NL_SAVES copied back at label 10);
- dtmcalc shortens a step to land on each archived instant and takes the
  rest of the step it had proposed next (``dt - newdt``): steps of 1e-7 s
  in sdnd107e come from there, not from the error control.

The relation's force is therefore first-order accurate in the step (its
velocity is held over each stage interval) whatever TOLERANCE asks: on a
mass held by a linear Zener element the error halves when the steps double
(closed form: the augmented exponential of the linear system). And the
adaptive run of sdnd107e is round-off sensitive: rejected steps decide the
step sequence, on which the first-order quantities DEPL and FORCE depend.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from asterlite.commands.dyna_vibra_relations import read_dis_visc
from scipy.linalg import expm

from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.forces import acceleration, state_acceleration, total_force
from asterlite.dynamics.integrate import integrate
from asterlite.dynamics.laws import dis_visc, rk54
from asterlite.dynamics.laws import kernel as LK
from asterlite.dynamics.model import LinearSystem, ShockSpec, build_shocks
from tests.validated import relation, scheme_options

M, KS, X0 = 1.0, 100.0, 0.01  # the mass on its spring, released from X0
K1, K2, K3, C = 120.0, 10.0, 60.0, 1.7  # sdnd107e's Zener, with a linear dashpot
INSTANTS = np.linspace(0.05, 1.0, 20)


def model(t_end=1.0, dt=1.0e-3):
    params = dis_visc.prepare_dis_visc(
        read_dis_visc(
            relation("DIS_VISC", {"K1": K1, "K2": K2, "K3": K3, "C": C, "PUIS_ALPHA": 1.0})
        )
    )
    phi = np.array([[1.0], [0.0], [0.0]])
    spec = ShockSpec(
        name="V", obstacle_type="BI_PLAN_Y", node_1="N1", node_2="N2",
        coord_1=np.zeros(3), coord_2=np.array([1.0, 0.0, 0.0]), phi_1=phi,
        phi_2=np.zeros((3, 1)), norm_obst=np.array([1.0, 0.0, 0.0]), relation="DIS_VISC",
        law_code=LK.DIS_VISC, law=params, frame=np.eye(3),
    )  # fmt: skip
    system = LinearSystem(M * np.eye(1), KS * np.eye(1), np.zeros((1, 1)))
    return system, build_shocks([spec], system), tabulate_excitation(1, [], 0.0, t_end, dt / 2)


def engine_run(tol, t_end=1.0, dt=1.0e-3):
    system, shocks, excitation = model(t_end, dt)
    return integrate(
        system, shocks, excitation, "RUNGE_KUTTA_32", np.array([X0]), np.zeros(1), 0.0, t_end,
        dt, INSTANTS, 10**8, scheme_options("RUNGE_KUTTA_32", tolerance=tol),
    )  # fmt: skip


def exact(times):
    """(x, v, σ) of the mass: x'' = (-KS x + σ)/M, the element's elongation
    ε = X0 - x (unstrained at the start), σ' from the Zener rates."""
    s1, s3 = 1.0 / K1, 1.0 / K3
    d = s1 + s3 + K2 * s1 * s3
    a = np.zeros((4, 4))  # (x, v, σ, 1)
    a[0, 1] = 1.0
    a[1, 0], a[1, 2] = -KS / M, 1.0 / M
    a[2, 0] = -K2 / (C * d)
    a[2, 1] = -(1.0 + K2 * s3) / d
    a[2, 2] = -(1.0 + K2 * s1) / (C * d)
    a[2, 3] = K2 * X0 / (C * d)
    y0 = np.array([X0, 0.0, 0.0, 1.0])
    return np.array([(expm(a * t) @ y0)[:3] for t in times])


def errors(result):
    reference = exact(INSTANTS)
    x = result.depl[1:, 0]
    sigma = result.vint[1:, 0, dis_visc.V_FORCE]
    return (
        np.max(np.abs(x - reference[:, 0])) / X0,
        np.max(np.abs(sigma - reference[:, 2])) / np.max(np.abs(reference[:, 2])),
    )


def test_first_order_in_the_step_whatever_the_tolerance():
    """TOLERANCE 1e-5 ... 1e-9: the steps double per decade and the errors
    on the displacement and on the element's force halve (measured: x 4.2e-3,
    9.3e-4, 2.0e-4 at 230, 1039, 4783 steps); an error controlled to the
    tolerance would fall 10 times per decade."""
    runs = [engine_run(tol) for tol in (1.0e-5, 1.0e-7, 1.0e-9)]
    np.testing.assert_array_equal(runs[0].times[1:], INSTANTS)
    steps = np.array([r.info["steps"] for r in runs], dtype=float)
    err = np.array([errors(r) for r in runs])
    assert np.all(err[-1] < 5.0e-4)
    for k in range(2):  # error x steps stays put: first order
        for col in range(2):
            ratio = err[k, col] / err[k + 1, col]
            assert 0.7 * steps[k + 1] / steps[k] < ratio < 1.4 * steps[k + 1] / steps[k]
    assert np.all(steps[1:] / steps[:-1] < 6.0)  # far from the 100x of a 1e-2 / decade


# -------------------------------------------------------- code_aster's sequence, transcribed


def code_aster_run(tol, t_end=1.0, dt0=1.0e-3):
    """dtmcalc (landing on each archived instant, then the rest of the step it
    had proposed) around intruku32, transcribed; the relation and the
    acceleration are the engine's (dtmacce). Returns (archived x, archived
    internal variables, steps, rejected, smallest step)."""
    system, shocks, excitation = model(t_end, dt0)
    mdl = (system.bundle(), shocks.bundle(), excitation.bundle())
    c = (0.0, 0.5, 0.75, 1.0)
    a = ((0.5,), (0.0, 0.75), (2 / 9, 1 / 3, 4 / 9))
    e = (5 / 72, -1 / 12, -1 / 9, 1 / 8)
    epsi = 100.0 * np.finfo(float).eps
    loop_eps = 10.0 * np.finfo(float).eps
    dtmin, dtmax = 1.0e-10 * dt0, 1.0e10 * dt0
    depl1, vite1 = np.array([X0]), np.zeros(1)
    acce1, f, residual, work = np.zeros(1), np.zeros(1), np.zeros(1), np.zeros((5, 3))
    vint = shocks.initial_vint(0.0)
    total_force(0.0, depl1, vite1, mdl[1], vint, mdl[2], work, f)
    acceleration(f, depl1, vite1, mdl[0], residual, acce1)
    time, step, i, iarch, force_arch, newdt = 0.0, dt0, 1, 0, 0, 0.0
    steps = rejected = 0
    smallest = math.inf
    out_x, out_vint = [], []
    while t_end - time > i * loop_eps:
        dt = step  # dtmcalc's dt: the step stored before the landing
        if iarch < len(INSTANTS):
            if time + dt - INSTANTS[iarch] > i * loop_eps:
                newdt, force_arch = INSTANTS[iarch] - time, 1
                step = newdt
            elif abs(time + dt - INSTANTS[iarch]) < i * loop_eps:
                newdt, force_arch = dt, 1
        # --- intruku32 from (time, step)
        h, nlsav0, errt0 = step, vint.copy(), np.finfo(float).max
        while True:
            vint[:] = nlsav0
            kde, kvi = np.zeros((3, 1)), np.zeros((3, 1))
            depl2, vite2, acce2 = depl1.copy(), vite1.copy(), acce1.copy()
            for ee in range(3):
                kde[ee], kvi[ee] = vite2, acce2
                dq = sum(a[ee][ss] * kde[ss] for ss in range(ee + 1))
                dv = sum(a[ee][ss] * kvi[ss] for ss in range(ee + 1))
                depl2, vite2 = depl1 + h * dq, vite1 + h * dv  # the engine's order
                t2 = time + h * c[ee + 1]
                state_acceleration(t2, depl2, vite2, acce2, f, residual, vint, work, mdl)
            errde = e[3] * vite2 + sum(e[k] * kde[k] for k in range(3))
            errvi = e[3] * acce2 + sum(e[k] * kvi[k] for k in range(3))
            skd = max(tol * abs(depl1[0]), tol * abs(depl2[0] - depl1[0]), epsi)
            skv = max(tol * abs(vite1[0]), tol * abs(vite2[0] - vite1[0]), epsi)
            errt = max(h * math.sqrt(((errde[0] / skd) ** 2 + (errvi[0] / skv) ** 2) / 2), epsi)
            if errt * 1.01 > errt0:
                errt = 0.99
            if errt < (0.9 / 5.0) ** 4:
                coeff = 5.0
            elif errt > (0.9 / 0.2) ** 4:
                coeff = 0.2
            else:
                coeff = 0.9 * errt ** (-1.0 / 4.0)
            dt2 = min(dtmax, h * coeff)
            if errt >= 1.0 and dt2 >= dtmin:
                h, errt0 = dt2, errt
                rejected += 1
                continue
            break
        depl1, vite1, acce1 = depl2, vite2, acce2.copy()
        time += h
        step = dt2
        steps += 1
        smallest = min(smallest, h)
        # --- dtmcalc's archiving
        if force_arch == 2:
            force_arch = 0
        if force_arch == 1 and abs(time - INSTANTS[iarch]) <= i * loop_eps:
            time = INSTANTS[iarch]  # asterlite stores the instant itself (code_aster: t1 + dt)
            out_x.append(depl1[0])
            out_vint.append(vint[0].copy())
            iarch += 1
            force_arch = 0
            if abs(dt - newdt) > i * loop_eps:
                step, force_arch = dt - newdt, 2
        i += 1
    return np.array(out_x), np.array(out_vint), steps, rejected, smallest


def test_engine_takes_code_aster_steps_between_archived_instants():
    result = engine_run(1.0e-7)
    x, vint, steps, rejected, smallest = code_aster_run(1.0e-7)
    assert result.info["steps"] == steps
    assert result.info["rejected_steps"] == rejected > 0
    assert result.info["min_step"] == pytest.approx(smallest, rel=1e-12)
    assert smallest < 0.1 * 1.0 / steps  # a remainder after a landing
    # the same steps; the states agree to rounding (the sums of the transcription
    # and of the compiled loop are not grouped alike everywhere)
    np.testing.assert_allclose(result.depl[1:, 0], x, rtol=0.0, atol=1e-11 * X0)
    np.testing.assert_allclose(result.vint[1:, 0, :11], vint[:, :11], rtol=1e-9, atol=1e-13)


def test_relation_integration_ends_within_1e8_s_of_the_step_end():
    """rk5adp: a converged sub-step that ends within 1e-8 s of the end ends the
    integration, even short of it. A 5e-9 s step whose first try fails is
    integrated over its first converged sub-step only."""
    zener = {"K1": 1.0, "K2": 1.0, "K3": 1.0, "C": 1.0, "PUIS_ALPHA": 1.0}
    # a dashpot below the catalogue's smallest C (1e-8), given to the law directly
    record = replace(read_dis_visc(relation("DIS_VISC", zener)), viscosity=1.0e-9)
    params = dis_visc.prepare_dis_visc(record)
    model_params = params[dis_visc.P_MODEL : dis_visc.P_MODEL + 5]
    y0 = np.array([1.0, 0.0, 0.0, 0.0])
    rate = np.array([1.0e3, 0.0, 0.0])
    work = np.zeros((rk54.N_WORK, 4))
    dt = 5.0e-9
    assert rk54.cash_karp_step(rk54.ZENER, model_params, y0, rate, dt, 4, work)
    error = math.sqrt(sum((work[8, i] / (abs(y0[i]) if abs(y0[i]) > 1e-8 else 1.0)) ** 2
                          for i in range(4)))  # fmt: skip
    tol = 0.5 * error  # the first try fails by a factor 2
    h = max(0.1 * dt, 0.9 * dt * 2.0**-0.25)
    assert rk54.cash_karp_step(rk54.ZENER, model_params, y0, rate, h, 4, work)
    expected = work[7].copy()
    out = np.zeros(4)
    assert rk54.adaptive_integrate(
        rk54.ZENER, model_params, y0, rate, dt, 20, tol, np.zeros(0), out, work
    )
    np.testing.assert_array_equal(out, expected)  # the state at 0.76 dt, as code_aster
    assert out[2] == pytest.approx(1.0e3 * h, rel=1e-12)  # ε = rate x the integrated time
