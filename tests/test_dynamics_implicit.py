"""TRAITEMENT_NONL='IMPLICITE' (asterlite.dynamics.implicit_shocks): each
contact configuration integrated as a linear system, the switches located
in time. Without DIS_CHOC the run is the explicit one (code_aster's
dtmprep_noli). Oracles: the exact piecewise-harmonic bounce of a mass on a
stop, energy conservation of elastic impacts, the explicit run at a small
step, and the archived forces against the contact law."""

import math

import numpy as np
import pytest

from asterlite.errors import UnsupportedError
from tests.test_dynamics_vibra import friction_shock, kws, one_mode, run_vibra, vector
from tests.test_extremes_contact import chain3, completed, relative_spread, simulate
from tests.test_extremes_decks import Chain, Shock

IMPLICIT = ', TRAITEMENT_NONL="IMPLICITE"'
M, K, K_N, JEU, V0 = 1.0, 1.0e4, 1.0e6, 5.0e-4, 0.1


def test_implicit_without_shocks_is_the_explicit_run():
    gnum, m, kk = one_mode(400.0)
    load = [kws("DYNA_VIBRA/EXCIT", VECT_ASSE_GENE=vector(gnum, 2.0, "FORC"), COEF_MULT=1.5)]
    runs = [
        run_vibra(
            m,
            kk,
            "NEWMARK",
            1.0e-3,
            0.5,
            etat={"DEPL": vector(gnum, 0.01)},
            EXCIT=load,
            TRAITEMENT_NONL=treatment,
        )  # fmt: skip
        for treatment in ("EXPLICITE", "IMPLICITE")
    ]
    np.testing.assert_array_equal(runs[1].depl, runs[0].depl)
    assert np.max(np.abs(runs[0].depl)) > 5e-3


def test_implicit_with_friction_runs_and_reports_its_switches():
    gnum, m, kk = one_mode(1.0e4)
    result = run_vibra(
        m, kk, "NEWMARK", 1.0e-4, 0.05, etat={"DEPL": vector(gnum, 1e-3)},
        comportement=[friction_shock()], TRAITEMENT_NONL="IMPLICITE",
    )  # fmt: skip
    assert result.shocks and np.all(np.isfinite(result.depl))
    assert result.info["contact_switches"] >= 1


def test_implicit_refuses_a_varying_rotation_speed():
    gnum, m, kk = one_mode(1.0e4)
    with pytest.raises(UnsupportedError, match="IMPLICITE' with VITESSE_VARIABLE"):
        run_vibra(
            m, kk, "NEWMARK", 1.0e-4, 0.01, etat={"DEPL": vector(gnum, 1e-3)},
            comportement=[friction_shock()], TRAITEMENT_NONL="IMPLICITE",
            VITESSE_VARIABLE="OUI",
        )  # fmt: skip


def test_implicit_refuses_support_motions_seen_by_the_shocks():
    from commands.dyna_vibra_shocks import refuse_moving_gaps

    class Context:
        def unsupported(self, what, keyword=None, kw=None):
            raise UnsupportedError(what, None, keyword)

    refuse_moving_gaps(Context(), {}, [])  # no support motion: nothing to say
    with pytest.raises(UnsupportedError, match="MULT_APPUI or CORR_STAT"):
        refuse_moving_gaps(Context(), {}, [{"DEPL": None, "VITE": None}])


# ----------------------------------------------------------------------------- the exact bounce


def exact_bounce(times: np.ndarray) -> np.ndarray:
    """Displacement of a mass on a spring, launched from rest position at V0
    towards a stop at JEU on both sides (PLAN_Y: |y| >= JEU): flights are
    arcs of pulsation w = sqrt(K/M), contacts arcs of pulsation
    w_c = sqrt((K + K_N)/M) about y_eq = K_N JEU / (K + K_N); elastic, so
    every impact has the same speed and duration."""
    w, w_c = math.sqrt(K / M), math.sqrt((K + K_N) / M)
    t_in = math.asin(JEU * w / V0) / w  # first arrival at the stop
    v_in = V0 * math.cos(w * t_in)
    y_eq = K_N * JEU / (K + K_N)
    # contact arc: y = y_eq + (JEU - y_eq) cos(w_c s) + v_in/w_c sin(w_c s), until y = JEU again
    phase = math.atan2(v_in / w_c, JEU - y_eq)
    amplitude = math.hypot(JEU - y_eq, v_in / w_c)
    contact = 2.0 * phase / w_c  # back at JEU with speed -v_in
    flight = 2.0 * t_in  # between the stops: from +JEU through 0 to -JEU
    out = np.empty_like(times)
    for k, t in enumerate(times):
        s = t - t_in
        if s < 0.0:
            out[k] = V0 / w * math.sin(w * t)
            continue
        cycle = contact + flight
        n, r = divmod(s, cycle)
        side = 1.0 if int(n) % 2 == 0 else -1.0
        if r < contact:
            out[k] = side * (y_eq + amplitude * math.cos(w_c * r - phase))
        else:  # flight from the stop (speed -v_in) to the other one
            u = r - contact
            out[k] = side * V0 / w * math.sin(w * (t_in - u))
    return out


@pytest.mark.parametrize("scheme", ["NEWMARK", "TRBDF2", "DIFF_CENTRE", "RUNGE_KUTTA_54"])
def test_implicit_bounce_follows_the_exact_solution(tmp_path, scheme):
    """At w_c dt = 0.02, the implicit treatment follows the exact bounce to
    second order (NEWMARK: 4e-5 of the amplitude over 0.05 s and four
    impacts; explicit: 17 %); explicit NEWMARK and TRBDF2 gain energy at
    every impact."""
    keywords = ", TOLERANCE=1.0e-8" if scheme == "RUNGE_KUTTA_54" else ""
    runs = {}
    for treatment in ("", IMPLICIT):
        chain = Chain(
            vite={1: (0.0, V0, 0.0)}, shocks=[Shock(1, JEU, K_N)], pas=2.0e-5, inst_fin=0.05,
            scheme=scheme, scheme_keywords=keywords, dyna_keywords=treatment,
        )  # fmt: skip
        outcome = completed(simulate(tmp_path, chain, name=f"run{len(runs)}"))
        runs[treatment] = np.max(np.abs(outcome.physical("N1 DY") - exact_bounce(outcome.times)))
    amplitude = V0 / math.sqrt(K / M)
    error = runs[IMPLICIT] / amplitude
    print(f"{scheme}: implicit {error:.3g}, explicit {runs[''] / amplitude:.3g}")
    assert error < 5.0e-4  # measured: NEWMARK 3.8e-5, TRBDF2 1.9e-5, DIFF_CENTRE 2.4e-4
    if scheme in ("NEWMARK", "TRBDF2"):
        assert runs[""] > 10.0 * runs[IMPLICIT]


@pytest.mark.parametrize(
    "scheme, tolerance",
    [
        ("NEWMARK", 1.0e-5),
        ("TRBDF2", 1.0e-5),
        ("DEVOGE", 1.0e-5),
        ("RUNGE_KUTTA_32", 1.0e-5),
        ("RUNGE_KUTTA_54", 1.0e-5),
        ("DIFF_CENTRE", 2.0e-3),  # half-step velocity, as without the treatment
    ],
)
def test_implicit_elastic_impacts_keep_the_energy(tmp_path, scheme, tolerance):
    """Three supports hit in turn (23 impacts): the energy of the motion is
    kept to 1e-5 by the schemes that, explicit, gain it at each impact
    (NEWMARK +130 %, TRBDF2 +46 % at this step) or lose it at tolerance."""
    keywords = ", TOLERANCE=1.0e-8" if scheme in ("RUNGE_KUTTA_32", "RUNGE_KUTTA_54") else ""
    keywords += ", TOLERANCE=1.0e-8" if scheme == "DEVOGE" else ""
    chain = chain3(
        (0.1, -0.05, 0.02), 2.0e-4, pas=2.0e-5, inst_fin=0.1, scheme=scheme,
        scheme_keywords=keywords, dyna_keywords=IMPLICIT,
    )  # fmt: skip
    outcome = completed(simulate(tmp_path, chain))
    assert sum(s["impacts"] for s in outcome.report.shocks) >= 20
    spread = relative_spread(outcome.energy())
    print(f"{scheme}: energy spread {spread:.3g}")
    assert spread <= tolerance


def test_implicit_agrees_with_explicit_at_a_small_step(tmp_path):
    """DIFF_CENTRE at w_c dt = 1e-3: both treatments converge to the same
    motion; their difference is far below the motion."""
    runs = []
    for k, treatment in enumerate(("", IMPLICIT)):
        chain = chain3(
            (0.1, -0.05, 0.02), 2.0e-4, pas=1.0e-6, inst_fin=0.02, pas_arch=10,
            dyna_keywords=treatment, post=False,
        )  # fmt: skip
        outcome = completed(simulate(tmp_path, chain, name=f"run{k}"))
        runs.append((outcome.times, outcome.physical("N1 DY")))
    (times, explicit), (shifted, implicit) = runs  # the cut steps shift the implicit grid
    difference = np.max(np.abs(np.interp(times, shifted, implicit) - explicit))
    displacements = [explicit]
    assert difference < 1.0e-3 * np.max(np.abs(displacements[0]))


def test_archived_normal_force_is_the_contact_law_and_switches_are_logged(tmp_path):
    chain = Chain(
        vite={1: (0.0, V0, 0.0)}, shocks=[Shock(1, JEU, K_N, c_n=20.0)], pas=2.0e-5,
        inst_fin=0.05, dyna_keywords=IMPLICIT,
    )  # fmt: skip
    outcome = completed(simulate(tmp_path, chain))
    shock = next(iter(outcome.shocks.values()))
    y = outcome.physical("N1 DY")
    v = outcome.physical_velocity("N1 DY")
    expected = np.where(
        np.abs(y) >= JEU, np.maximum(0.0, K_N * (np.abs(y) - JEU) + 20.0 * v * np.sign(y)), 0.0
    )
    # DIFF_CENTRE archives the velocity that led to the state: compare where it is in contact
    in_contact = shock["FN"] > 0.0
    assert np.count_nonzero(in_contact) > 20
    np.testing.assert_allclose(shock["FN"][in_contact], expected[in_contact], rtol=0.05)
    log = (outcome.out / "message.log").read_text()
    switches = int(log.split("TRAITEMENT_NONL='IMPLICITE': ")[1].split()[0])
    assert switches >= 6  # two per impact


def test_explicit_newmark_warns_of_the_energy_its_impacts_gain(tmp_path):
    """code_aster's explicit treatment inside NEWMARK's implicit step: the
    run goes on, with a warning naming the shock, the gain per impact and
    the remedies; the energy grows about as announced."""
    chain = Chain(
        vite={1: (0.0, V0, 0.0)}, shocks=[Shock(1, JEU, K_N)], pas=2.0e-5, inst_fin=0.1,
        scheme="NEWMARK",
    )  # fmt: skip
    outcome = completed(simulate(tmp_path, chain))
    log = (outcome.out / "message.log").read_text()
    assert "TRAITEMENT_NONL='IMPLICITE'" in log and "shock 'C1' (node N1)" in log
    gain = float(log.split("each elastic impact gains about ")[1].split()[0]) / 100.0
    impacts = sum(s["impacts"] for s in outcome.report.shocks)
    energy = outcome.energy()
    measured = energy[-1] / energy[0]
    assert (1.0 + gain / 2.0) ** impacts < measured < (1.0 + 2.0 * gain) ** impacts


def test_tube_orbiting_in_circular_supports(tmp_path):
    """The tube sample (CERCLE supports, friction, a rotating force): the
    first impacts of its second run (DEBUT_CHOCS) with NEWMARK at PAS
    2e-5 s. Implicit, the peak normal force at support 1 is within 7 % of
    the sample's independent reference (4.3141 N) and the shocks are
    linearised again as the contact point moves round the circle;
    explicit, it is 37 % off."""
    from asterlite.runtime.runner import run_deck
    from asterlite.runtime.session import KeywordOverride
    from tests.conftest import SAMPLES

    deck = SAMPLES / "tube_supports" / "tube_supports.export"
    peaks = {}
    for treatment in ("EXPLICITE", "IMPLICITE"):
        overrides = [
            KeywordOverride("DYNA_VIBRA", {"INCREMENT/INST_FIN": 0.002}, call=1),
            KeywordOverride(
                "DYNA_VIBRA", {"SCHEMA_TEMPS/SCHEMA": "NEWMARK", "TRAITEMENT_NONL": treatment}
            ),
        ]
        out = tmp_path / treatment
        report = run_deck(deck, out, keyword_overrides=overrides)
        assert report.status in ("PASS", "NOOK", "DONE"), report.message
        first = [s for s in report.shocks if s["result"] == "DEBUT_CHOCS"]
        peaks[treatment] = max(s["max_FN"] for s in first if s["shock"] == "SUPP1")
        if treatment == "IMPLICITE":
            log = (out / "message.log").read_text()
            moved = log.split("steps integrated again up to a switch, ")[-1].split()[0]
            assert int(moved) > 100
    reference = 4.3141
    assert abs(peaks["IMPLICITE"] / reference - 1.0) < 0.07
    assert abs(peaks["EXPLICITE"] / reference - 1.0) > 0.3
