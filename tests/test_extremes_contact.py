"""Shock decks at the extremes (issue 7): gaps from pre-stressed to never
touching, grazing and skimming contact, simultaneous contact on several
supports, zero and heavy damping, energy consistency, and the step check
(VERI_PAS) naming its cause.

Every deck is written on the fly (:mod:`tests.test_extremes_decks`: point
masses on ground springs, PLAN_Y stops on some nodes) and run through the
runner like any study. Each run either completes with finite, bounded,
energy-consistent results (checked from the saved ``results.h5`` and every
file written: tables, functions, logs), or stops early with exit status 2,
a message naming the cause and a step, and no result saved as complete.

The model's scales: M = 1 kg on K = 1e4 N/m (ω = 100 rad/s, 15.9 Hz), gaps
of a fraction of a millimetre, contact stiffness 1e6 N/m (ω = 1000 rad/s).
DIFF_CENTRE's energy error with the synchronised velocity
(:meth:`Outcome.velocity`) is second order: tolerances below are written
as (ω_max·dt)², ω_max bounding every pulsation of the deck.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from tests.test_extremes_decks import (
    Chain,
    Shock,
    nothing_complete,
    outputs_are_finite,
    run,
    write,
)

M, K = 1.0, 1.0e4
W0 = math.sqrt(K / M)  # 100 rad/s
U0 = 1.0e-3


def simulate(tmp_path, chain: Chain, name: str = "deck"):
    outcome = run(write(chain, tmp_path / name), tmp_path / name / "out")
    bad = outputs_are_finite(outcome.out)
    assert not bad, f"non-finite values written: {bad[:5]}"
    return outcome


def completed(outcome):
    assert outcome.complete, outcome.report.message
    return outcome


def relative_spread(energy: np.ndarray) -> float:
    return float((energy.max() - energy.min()) / energy[0])


def omega_max(chain: Chain) -> float:
    """Gershgorin bound of every pulsation: ground + coupling + contact
    stiffness over the smallest mass."""
    ground = max(max(g) for g in chain.ground)
    contact = max([abs(s.k_n) for s in chain.shocks] + [abs(s.k_t) for s in chain.shocks] + [0.0])
    coupling = 2.0 * chain.coupling if chain.n > 1 else 0.0
    return math.sqrt((ground + 2.0 * coupling + contact) / min(chain.masses))


# ----------------------------------------------------------------------------- gaps


def test_zero_gap_is_a_linear_spring(tmp_path):
    """JEU = 0 on PLAN_Y: the node is in contact at rest (d_N = -|y| <= 0) and
    the stop is a two-sided spring K_N: the run must be the linear
    oscillator of stiffness K + K_N (here ω doubles), step for step."""
    k_n = 3.0 * K
    common = dict(depl={1: (0.0, U0, 0.0)}, pas=1.0e-4, inst_fin=0.2)
    contact = completed(simulate(tmp_path, Chain(shocks=[Shock(1, 0.0, k_n)], **common), "gap0"))
    linear = completed(simulate(tmp_path, Chain(ground=((K, K + k_n, K),), **common), "linear"))
    y_contact, y_linear = contact.physical("N1 DY"), linear.physical("N1 DY")
    # the same arithmetic up to the order of two additions: round-off only
    assert np.max(np.abs(y_contact - y_linear)) <= 1.0e-12 * U0
    assert np.all(contact.shocks["C1"]["FN"] >= 0.0)
    assert np.allclose(contact.shocks["C1"]["FN"], k_n * np.abs(y_contact), rtol=1e-12, atol=0.0)
    # the oscillation is the analytic one at 2 ω0 (DIFF_CENTRE's phase error
    # and its first-step velocity offset: a few ω·dt of the amplitude)
    assert np.max(np.abs(y_contact - U0 * np.cos(2.0 * W0 * contact.times))) <= 0.05 * U0
    # energy with the contact spring: second order in ω·dt = 0.02
    assert relative_spread(contact.energy()) <= (2.0 * W0 * 1.0e-4) ** 2


def test_tiny_gap_is_continuous_with_zero_gap(tmp_path):
    """A gap of 1e-12 m (1e-9 of the amplitude) changes the motion by a few
    gaps: the response depends continuously on JEU, no switch of regime."""
    gap = 1.0e-12
    runs = [
        completed(
            simulate(
                tmp_path,
                Chain(
                    depl={1: (0.0, U0, 0.0)},
                    shocks=[Shock(1, jeu, 3.0 * K)],
                    pas=1.0e-4,
                    inst_fin=0.2,
                ),
                f"gap{k}",
            )
        )
        for k, jeu in enumerate((0.0, gap))
    ]
    difference = np.max(np.abs(runs[0].physical("N1 DY") - runs[1].physical("N1 DY")))
    # a force error K_N·gap over 40 radians of a linear oscillation: at most
    # a few tens of gaps (measured ≈ 19); 1000 gaps still 1e-9 of U0
    assert difference <= 1.0e3 * gap
    assert relative_spread(runs[1].energy()) <= (2.0 * W0 * 1.0e-4) ** 2


def test_prestressed_contact_at_rest_stays_in_a_small_band(tmp_path):
    """JEU < 0 (accepted by code_aster, no val_min): PLAN_Y pushes the node
    from both sides with the preload F = K_N·|JEU| (d_N = JEU - |y| < 0).
    The exact motion from rest is rest; the force flips sign at y = 0, so an
    explicit step leaves the node chattering in a band of a few F·dt²/M.
    The band must stay far below the gap and never grow into a blow-up."""
    jeu, k_n, dt = -1.0e-3, 3.0 * K, 1.0e-4
    preload = k_n * abs(jeu)
    outcome = completed(
        simulate(tmp_path, Chain(shocks=[Shock(1, jeu, k_n)], pas=dt, inst_fin=1.0))
    )
    y = outcome.physical("N1 DY")
    fn = outcome.shocks["C1"]["FN"]
    band = preload * dt**2 / M  # 3e-7 m; measured max |y| ≈ 20 bands over 1e4 steps
    assert np.max(np.abs(y)) <= 100.0 * band  # 3e-5 m, 3 % of |JEU|
    assert np.all(fn >= preload) and np.max(fn) <= preload + k_n * 100.0 * band


def test_prestressed_contact_keeps_its_energy(tmp_path):
    """Released from U0 in the preloaded stop, the node swings in the V-shaped
    potential K_N(|JEU|·|y| + y²/2) + K y²/2: conservative. The force jumps
    by 2F at each crossing of y = 0, where a fixed step misplaces the
    crossing by up to v·dt: each crossing may shift the energy by at most
    2F·v_max·dt, with no systematic sign."""
    jeu, k_n, dt = -1.0e-3, 3.0 * K, 1.0e-5
    outcome = completed(
        simulate(
            tmp_path,
            Chain(depl={1: (0.0, U0, 0.0)}, shocks=[Shock(1, jeu, k_n)], pas=dt, inst_fin=0.2),
        )
    )
    energy = outcome.energy()
    v_max = np.max(np.abs(outcome.velocity()))
    per_crossing = 2.0 * k_n * abs(jeu) * v_max * dt
    crossings = np.count_nonzero(np.diff(np.sign(outcome.physical("N1 DY"))) != 0)
    assert crossings >= 10  # the run does cross the kink many times
    # within 4 crossings' worth (measured: about 1), not their sum
    assert np.max(np.abs(energy - energy[0])) <= 4.0 * per_crossing
    assert 4.0 * per_crossing <= 0.02 * energy[0]  # and that is a tight check


@pytest.mark.parametrize("scheme", ["DIFF_CENTRE", "DEVOGE", "NEWMARK", "RUNGE_KUTTA_54"])
def test_never_touching_shock_changes_nothing(tmp_path, scheme):
    """A stop 1000 amplitudes away (and a stiff one: it sets VERI_PAS) leaves
    the run identical to the deck without it."""
    common = dict(depl={1: (0.0, U0, 0.0)}, pas=1.0e-4, inst_fin=0.2, scheme=scheme)
    far = completed(simulate(tmp_path, Chain(shocks=[Shock(1, 1.0, 1.0e6)], **common), "far"))
    free = completed(simulate(tmp_path, Chain(**common), "free"))
    assert far.depl.shape == free.depl.shape
    assert np.max(np.abs(far.depl - free.depl)) <= 1.0e-12 * np.max(np.abs(free.depl))
    assert np.max(np.abs(far.vite - free.vite)) <= 1.0e-12 * np.max(np.abs(free.vite))
    assert not np.any(far.shocks["C1"]["FN"])
    assert far.report.shocks[0]["impacts"] == 0


# ----------------------------------------------------------------------------- grazing


@pytest.mark.parametrize("scheme", ["DIFF_CENTRE", "RUNGE_KUTTA_54"])
@pytest.mark.parametrize("excess", [-1.0e-9, 0.0, 1.0e-9])
def test_grazing_contact(tmp_path, scheme, excess):
    """The free swing reaches the stop within 1e-9 (relative) of the gap:
    at most one light touch per extreme, forces bounded by the tiny
    overshoot, no chattering, energy kept. DIFF_CENTRE's discrete orbit
    exceeds its initial amplitude by (ω·dt)²/8 relative (code_aster's
    update v += dt a, q += dt v), so it grazes with that overshoot."""
    jeu, k_n, dt, t_end = 1.0e-3, 1.0e8, 2.5e-5, 0.5
    outcome = completed(
        simulate(
            tmp_path,
            Chain(
                depl={1: (0.0, jeu * (1.0 + excess), 0.0)},
                shocks=[Shock(1, jeu, k_n)],
                pas=dt,
                inst_fin=t_end,
                scheme=scheme,
            ),
        )
    )
    overshoot = abs(excess) + (W0 * dt) ** 2 / 4.0  # twice the discrete overshoot
    fn = outcome.shocks["C1"]["FN"]
    assert np.max(fn) <= k_n * jeu * overshoot  # 0.16 N at most, vs K·JEU = 10 N
    assert np.max(np.abs(outcome.physical("N1 DY"))) <= jeu * (1.0 + overshoot)
    extremes = 2.0 * t_end * W0 / (2.0 * math.pi) + 1.0  # one touch per extreme at most
    assert outcome.report.shocks[0]["impacts"] <= extremes
    if scheme == "RUNGE_KUTTA_54" and excess <= 0.0:
        assert not np.any(fn)  # an accurate orbit never reaches the stop
    # adaptive RK54 at its default tolerance: about 1e-4 over 8 periods
    assert relative_spread(outcome.energy()) <= 1.0e-3


def skimming_chain(mu: float | None, y0: float, jeu: float) -> Chain:
    """A node free in Y and Z (distinct frequencies, so that the modes are
    pure Y and pure Z) on a PLAN_Y stop, sliding along Z."""
    shocks = [] if mu is None else [Shock(1, jeu, 1.0e6, mu=mu, k_t=1.0e6)]
    return Chain(
        ground=((K, K, 2.5 * K),),
        free=("DY", "DZ"),
        depl={1: (0.0, y0, U0)},
        shocks=shocks,
        pas=2.0e-5,
        inst_fin=0.2,
    )


@pytest.mark.parametrize("mu", [0.3, 2.0])
def test_skimming_along_the_obstacle_at_zero_force(tmp_path, mu):
    """The node rests exactly on the obstacle surface (JEU = 0, y = 0: in
    contact with d_N = 0, F_N = 0) and slides along it: Coulomb friction
    under a zero normal force is zero, whatever the stick stiffness, and the
    sliding motion is the frictionless one."""
    skim = completed(simulate(tmp_path, skimming_chain(mu, 0.0, 0.0), "skim"))
    free = completed(simulate(tmp_path, skimming_chain(None, 0.0, 0.0), "free"))
    fields = skim.shocks["C1"]
    for name in ("FN", "FT1", "FT2"):
        assert not np.any(fields[name]), name
    assert np.array_equal(skim.physical("N1 DZ"), free.physical("N1 DZ"))


@pytest.mark.parametrize("mu", [0.3, 2.0])
def test_grazing_while_sliding_with_friction(tmp_path, mu):
    """The node swings in Y up to the gap exactly while sliding along Z, with
    strong friction: the light touches may only brake the sliding (Coulomb
    cap μ·F_N, energy non-increasing) and leave it bounded."""
    jeu = U0
    outcome = completed(simulate(tmp_path, skimming_chain(mu, jeu, jeu)))
    fields = outcome.shocks["C1"]
    tangential = np.hypot(fields["FT1"], fields["FT2"])
    assert np.all(tangential <= mu * fields["FN"] * (1.0 + 1.0e-12) + 1.0e-15)
    dt = 2.0e-5
    overshoot = (math.sqrt(2.5) * W0 * dt) ** 2 / 4.0
    assert np.max(fields["FN"]) <= 1.0e6 * jeu * overshoot
    energy = outcome.energy()
    # energy may only decrease, within the estimator's own (ω·dt)² error
    assert np.max(energy) <= energy[0] * (1.0 + (omega_max(skimming_chain(mu, 0, 0)) * dt) ** 2)


# ----------------------------------------------------------------------------- several supports


def chain3(velocities, jeu: float = 5.0e-4, **kwargs) -> Chain:
    return Chain(
        masses=(M, M, M),
        ground=((K, K, K),) * 3,
        coupling=0.5 * K,
        vite={i + 1: (0.0, v, 0.0) for i, v in enumerate(velocities)},
        shocks=[Shock(i + 1, jeu, 1.0e6) for i in range(3)],
        **kwargs,
    )


@pytest.mark.parametrize(
    "velocities",
    [(0.1, 0.1, 0.1), (0.1, 0.0, 0.1), (0.1, -0.1, 0.1)],
    ids=["uniform", "ends", "alternate"],
)
def test_simultaneous_contact_on_three_supports(tmp_path, velocities):
    """A chain of three masses, mirror-symmetric about its middle, hits stops
    at its ends at the same instants (and, moving as one block, all three
    at once): the end forces stay equal to round-off, the antisymmetric
    mode is never excited, the energy is kept."""
    dt = 2.0e-5
    chain = chain3(velocities, pas=dt, inst_fin=0.1)
    outcome = completed(simulate(tmp_path, chain))
    fn = [outcome.shocks[f"C{i}"]["FN"] for i in (1, 2, 3)]
    peak = max(np.max(f) for f in fn)
    assert peak > 10.0  # real impacts (tens of newtons)
    # mirror symmetry: the same arithmetic on mirrored mode shapes (1e-9:
    # the eigensolver's symmetry of the shapes, measured 1e-13)
    assert np.max(np.abs(fn[0] - fn[2])) <= 1.0e-9 * peak
    starts = [np.flatnonzero(f > 0.0) for f in fn]
    assert starts[0][0] == starts[2][0]  # same first impact instant
    if velocities[0] == velocities[1]:  # the block: three supports at once
        assert np.max(np.abs(fn[0] - fn[1])) <= 1.0e-9 * peak
        assert starts[0][0] == starts[1][0]
    # the antisymmetric mode (N1 = -N3, N2 = 0) stays at round-off
    shapes = outcome.shapes
    rows = [outcome.dof_labels.index(f"N{i} DY") for i in (1, 2, 3)]
    antisymmetric = [
        j for j in range(shapes.shape[1]) if abs(shapes[rows[0], j] + shapes[rows[2], j]) < 1e-9
    ]
    assert len(antisymmetric) == 1
    assert np.max(np.abs(outcome.depl[:, antisymmetric[0]])) <= 1.0e-9 * np.max(
        np.abs(outcome.depl)
    )
    assert relative_spread(outcome.energy()) <= (omega_max(chain) * dt) ** 2


# ----------------------------------------------------------------------------- damping


@pytest.mark.parametrize("scheme", ["DIFF_CENTRE", "NEWMARK", "DEVOGE", "RUNGE_KUTTA_54"])
@pytest.mark.parametrize("xi", [1.0, 5.0, 50.0])
def test_heavy_modal_damping_only_dissipates(tmp_path, scheme, xi):
    """Critical and heavier modal damping with shocks: the energy never
    grows between archived instants and most of it is gone by the end."""
    dt = 2.0e-5
    chain = chain3((0.1, -0.05, 0.02), xi=xi, pas=dt, inst_fin=0.1, scheme=scheme)
    outcome = completed(simulate(tmp_path, chain))
    energy = outcome.energy()
    # no increase beyond the estimator's second-order error
    assert np.max(np.diff(energy)) <= (omega_max(chain) * dt) ** 2 * energy[0]
    assert energy[-1] <= 0.1 * energy[0]


def test_modal_damping_beyond_the_explicit_limit_is_refused(tmp_path):
    """ξ = 150 at ω = 100 rad/s: DIFF_CENTRE's explicit velocity update
    (stable while (ω dt)² + 4 ξ ω dt <= 4) diverges at dt = 1e-4 although
    VERI_PAS (T/20 = 3.1e-3 s) accepts it: refused before integrating,
    naming the mode and the damping, with a step."""
    outcome = simulate(tmp_path, Chain(vite={1: (0.0, 0.1, 0.0)}, xi=150.0, pas=1.0e-4))
    assert nothing_complete(outcome), outcome.report.message
    message = outcome.report.message
    assert "DYNA_VIBRA/INCREMENT/PAS" in message
    assert "modal damping of mode 1" in message and "reduced damping 150" in message
    limit = 2.0 / (W0 * (150.0 + math.sqrt(1.0 + 150.0**2)))
    assert f"use PAS <= {limit:.6g}" in message


def test_heavy_modal_damping_is_fine_with_an_implicit_scheme(tmp_path):
    """The same deck with NEWMARK (damping implicit): bounded, decaying."""
    outcome = completed(
        simulate(tmp_path, Chain(vite={1: (0.0, 0.1, 0.0)}, xi=150.0, pas=1.0e-4, scheme="NEWMARK"))
    )
    energy = outcome.energy()
    assert np.all(np.diff(energy) <= 1.0e-12 * energy[0])
    assert energy[-1] <= 1.0e-3 * energy[0]


@pytest.mark.parametrize(
    "scheme",
    ["DIFF_CENTRE", "NEWMARK", "RUNGE_KUTTA_32", "DEVOGE", "RUNGE_KUTTA_54"],
)
@pytest.mark.parametrize("c_n", [1.0e2, 1.0e4, 1.0e5])
def test_contact_damping_only_dissipates(tmp_path, c_n, scheme):
    """AMOR_NOR from light to c_n·dt/M = 1 (half DIFF_CENTRE's explicit
    limit): every impact loses energy, none gains; the energy stored in the
    contact spring is counted. The adaptive schemes grow their step in the
    free flight but never beyond the damped contact's stability limit (at
    c_n = 1e5, before the cap: 4x (DEVOGE) / 20x (RUNGE_KUTTA_54) the
    initial energy at the contact entry)."""
    dt = 1.0e-5
    chain = Chain(
        vite={1: (0.0, 0.1, 0.0)},
        shocks=[Shock(1, 5.0e-4, 1.0e6, c_n=c_n)],
        pas=dt,
        inst_fin=0.05,
        scheme=scheme,
    )
    outcome = completed(simulate(tmp_path, chain))
    energy = outcome.energy()
    assert outcome.report.shocks[0]["impacts"] >= 1  # (adaptive archives see fewer)
    assert np.max(energy) <= energy[0] * (1.0 + (omega_max(chain) * dt) ** 2)
    assert energy[-1] < energy[0]


def test_contact_damping_beyond_the_explicit_limit_is_refused(tmp_path):
    """AMOR_NOR·dt/M = 3 > 2: the damped contact would throw the node back
    faster than it came (then diverge); refused up front naming the shock."""
    outcome = simulate(
        tmp_path,
        Chain(
            vite={1: (0.0, 0.1, 0.0)},
            shocks=[Shock(1, 5.0e-4, 1.0e6, c_n=3.0e5)],
            pas=1.0e-5,
            inst_fin=0.05,
        ),
    )
    assert nothing_complete(outcome), outcome.report.message
    message = outcome.report.message
    assert "shock 'C1' (node N1)" in message and "AMOR_NOR=300000" in message
    assert re.search(r"use PAS <= [0-9.e+-]+ \(e\.g\. PAS=[0-9.e+-]+\)", message)


@pytest.mark.parametrize(
    ("scheme", "radius"),
    [("RUNGE_KUTTA_32", 2.5127), ("RUNGE_KUTTA_54", 3.3066), ("DEVOGE", 2.0)],
)
@pytest.mark.parametrize("c_n", [1.0e6, 1.0e8])
def test_contact_damping_beyond_the_stage_limit_is_refused(tmp_path, scheme, radius, c_n):
    """AMOR_NOR·PAS/M = 10 and 1000: beyond the real stability interval of
    the explicit stages (the damped contact would multiply the energy by
    3e8..6e30 before the cap). Refused up front naming the shock, the
    figure and a step."""
    outcome = simulate(
        tmp_path,
        Chain(
            vite={1: (0.0, 0.1, 0.0)},
            shocks=[Shock(1, 5.0e-4, 1.0e6, c_n=c_n)],
            pas=1.0e-5,
            inst_fin=0.05,
            scheme=scheme,
        ),
    )
    assert nothing_complete(outcome), outcome.report.message
    message = outcome.report.message
    assert "DYNA_VIBRA/INCREMENT/PAS" in message and scheme in message
    assert "shock 'C1' (node N1)" in message and f"AMOR_NOR={c_n:.6g}" in message
    assert f"AMOR_NOR*dt/M = {c_n * 1.0e-5:.6g} beyond the {radius:.4g}" in message
    limit = float(re.search(r"use PAS <= ([0-9.e+-]+)", message).group(1))
    assert limit == pytest.approx(radius / c_n, rel=1.0e-3)
    assert re.search(r"\(e\.g\. PAS=[0-9.e+-]+\)", message)


# ----------------------------------------------------------------------------- energy


@pytest.mark.parametrize(
    ("scheme", "tolerance"),
    [
        ("DIFF_CENTRE", None),  # (ω_max·dt)²
        # error-controlled schemes at TOLERANCE 1e-8: each impact is resolved
        # by the step control to about 1e-4 of the energy (measured 3e-5)
        pytest.param("RUNGE_KUTTA_54", 1.0e-3, id="RUNGE_KUTTA_54"),
        pytest.param("DEVOGE", 1.0e-3, id="DEVOGE"),
    ],
)
def test_conservative_shocks_keep_the_energy(tmp_path, scheme, tolerance):
    """No damping, no friction, elastic stops on three supports hit in
    turn: kinetic + modal elastic + contact spring energy is a constant of
    the motion, read from the archived states. NEWMARK and TRBDF2 keep it
    with TRAITEMENT_NONL='IMPLICITE' (tests/test_dynamics_implicit.py);
    with the explicit shock forces they gain energy at each impact, as the
    run's warning says."""
    dt = 2.0e-5
    keywords = ", TOLERANCE=1.0e-8" if scheme in ("RUNGE_KUTTA_54", "DEVOGE") else ""
    chain = chain3(
        (0.1, -0.05, 0.02), 2.0e-4, pas=dt, inst_fin=0.1, scheme=scheme, scheme_keywords=keywords
    )
    outcome = completed(simulate(tmp_path, chain))
    assert sum(s["impacts"] for s in outcome.report.shocks) >= 10
    if tolerance is None:
        tolerance = (omega_max(chain) * dt) ** 2  # 1.6e-3; measured 1e-4
    spread = relative_spread(outcome.energy())
    print(f"{scheme}: energy spread {spread:.3g}")
    assert spread <= tolerance


# ----------------------------------------------------------------------------- the step check


def test_step_refusal_names_the_shock_its_frequency_and_a_step(tmp_path):
    """RIGI_NOR = 1e10 on a 1 kg node: shortest period 2π/1e5 s. The refusal
    names the shock, its node, the stiffness, the frequency, the critical
    step and a round step below it."""
    outcome = simulate(
        tmp_path,
        Chain(vite={1: (0.0, 0.1, 0.0)}, shocks=[Shock(1, 5.0e-4, 1.0e10)], pas=1.0e-5),
    )
    assert nothing_complete(outcome), outcome.report.message
    message = outcome.report.message
    frequency = math.sqrt(K + 1.0e10) / (2.0 * math.pi)
    limit = 1.0 / frequency / 20.0
    assert "shock 'C1' (node N1): RIGI_NOR=1e+10 N/m on the DY component of mode 1" in message
    assert f"{frequency:.6g} Hz" in message
    assert f"the critical step is {limit:.6g} s" in message
    suggested = float(re.search(r"e\.g\. PAS=([0-9.e+-]+)\)", message).group(1))
    assert 0.4 * limit <= suggested <= limit


def test_step_refusal_names_the_mode_without_shock(tmp_path):
    outcome = simulate(tmp_path, Chain(vite={1: (0.0, 0.1, 0.0)}, pas=0.01))
    assert nothing_complete(outcome), outcome.report.message
    message = outcome.report.message
    assert "set by mode 1 (15.9155 Hz)" in message
    assert f"use PAS <= {2.0 * math.pi / W0 / 20.0:.6g} (e.g. PAS=0.0025)" in message


def test_step_refusal_names_the_tangential_stiffness(tmp_path):
    """A stick spring stiffer than the normal one sets the period."""
    chain = skimming_chain(0.3, 0.0, 0.0)
    chain.shocks[0].k_t = 1.0e9
    outcome = simulate(tmp_path, chain)
    assert nothing_complete(outcome), outcome.report.message
    assert "RIGI_TAN=1e+09 N/m on the DZ component of mode 2" in outcome.report.message


def test_stability_limit_matches_the_period_and_rounds_steps():
    from asterlite.dynamics.model import LinearSystem, build_shocks
    from asterlite.dynamics.step_limits import stability_limit, stability_period, suggested_step

    system = LinearSystem(np.diag([1.0, 2.0]), np.diag([1.0e4, 8.0e4]), np.zeros((2, 2)))
    assert stability_limit(system, build_shocks([], system)).mode == 2
    assert stability_period(system, build_shocks([], system)) == pytest.approx(
        2.0 * math.pi / 200.0, rel=1e-15
    )
    for limit, step in [(3.88327e-5, 2.5e-5), (1.0e-5, 1.0e-5), (9.9e-4, 5.0e-4), (0.0031, 0.0025)]:
        assert suggested_step(limit) == pytest.approx(step, rel=1e-12)
        assert suggested_step(limit) <= limit
