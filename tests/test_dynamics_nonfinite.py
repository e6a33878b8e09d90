"""A transient whose state or forces become non-finite stops there with a
located error (the DYNA_VIBRA call's line and the keyword at fault) saying
which quantity went wrong, at which instant, and which instant was the last
one computed with a finite state; no result is kept. Every GENE scheme
tests its state at each step (a NaN or a magnitude of 1e300 or more), the
PHYS loops each block of loads, each step's displacement and each archived
state."""

from __future__ import annotations

import re

import numpy as np
import pytest

from asterlite.dynamics import diagnosis
from asterlite.dynamics.model import ShockSpec
from asterlite.runtime.runner import run_deck
from tests.conftest import SAMPLES

OSCILLATOR = SAMPLES / "friction_oscillator"
# a 2 kg mass on a 8000 N/m spring (10.07 Hz), no friction here
HEAD_END = "SOL = DEFI_OBSTACLE"
# a load that jumps to 1e305 N after 0.1 s: beyond the 1e300 the loops accept
HUGE = (
    'HUGE = DEFI_FONCTION(NOM_PARA="INST", VALE=(0.0, 0.0, 0.1, 0.0, 0.1001, 1.0e305), '
    'PROL_DROITE="CONSTANT")\n'
    "FGENE = PROJ_VECT_BASE(BASE=MODES, VECT_ASSE=VECTASS, NUME_DDL_GENE=NUMEGE, "
    'TYPE_VECT="FORC")\n'
)


def gene_call(scheme: str, pas: float, t_end: float, load: bool, schema: str = "") -> str:
    excit = "    EXCIT=_F(VECT_ASSE_GENE=FGENE, FONC_MULT=HUGE),\n" if load else ""
    return (
        "RESU = DYNA_VIBRA(\n"
        '    TYPE_CALCUL="TRAN", BASE_CALCUL="GENE",\n'
        f'    SCHEMA_TEMPS=_F(SCHEMA="{scheme}"{schema}),\n'
        "    MATR_MASS=MASSEGEN, MATR_RIGI=RIGIDGEN, AMOR_MODAL=_F(AMOR_REDUIT=0.0),\n"
        "    ETAT_INIT=_F(DEPL=DEPINI),\n"
        f"{excit}"
        f'    INCREMENT=_F(INST_INIT=0.0, INST_FIN={t_end}, PAS={pas}, VERI_PAS="NON"),\n'
        "    ARCHIVAGE=_F(PAS_ARCH=10),\n"
        ")\nFIN()\n"
    )


PHYS_CALL = (
    "RESU = DYNA_VIBRA(\n"
    '    TYPE_CALCUL="TRAN", BASE_CALCUL="PHYS", SCHEMA_TEMPS=_F(SCHEMA="NEWMARK"),\n'
    "    MATR_MASS=MATRMASS, MATR_RIGI=MATRRIGI,\n"
    "    EXCIT=_F(VECT_ASSE=VECTASS, FONC_MULT=HUGE),\n"
    "    INCREMENT=_F(INST_INIT=0.0, INST_FIN=0.25, PAS=2.5e-4),\n"
    "    ARCHIVAGE=_F(PAS_ARCH=10),\n"
    ")\nFIN()\n"
)


def run_failing(tmp_path, call: str):
    """Run the oscillator's front end then ``call``; returns (report, the
    DYNA_VIBRA call's line)."""
    text = (OSCILLATOR / "friction_oscillator.comm").read_text()
    deck = text.split(HEAD_END)[0] + HUGE + call
    (tmp_path / "deck.comm").write_text(deck)
    (tmp_path / "deck.mail").write_text((OSCILLATOR / "friction_oscillator.mail").read_text())
    (tmp_path / "deck.export").write_text("F comm deck.comm D 1\nF mail deck.mail D 20\n")
    report = run_deck(tmp_path / "deck.export", tmp_path / "out")
    line = deck[: deck.index("RESU = DYNA_VIBRA")].count("\n") + 1
    return report, line


def instants(message: str) -> tuple[float, float, float]:
    """(failing instant, last finite instant, last archived instant)."""
    found = re.search(
        r"non-finite values at t=(\S+) \(step \d+, from t=(\S+), the last instant computed "
        r"with a finite state; last archived instant t=(\S+);",
        message,
    )
    assert found, message
    return tuple(float(x) for x in found.groups())


def assert_stopped_without_result(report, tmp_path, line: int, path: str) -> str:
    assert report.status == "ERROR" and report.exit_code == 2
    message = report.message
    assert f"deck.comm:{line}:" in message and "numerical error" in message
    assert f"DYNA_VIBRA/{path}:" in message
    assert "the run stops and keeps no result" in message
    assert not report.transients  # no result of the failed call is reported
    return message


@pytest.mark.parametrize(
    "scheme, schema, quantities",
    [
        ("DIFF_CENTRE", "", "the generalized acceleration (mode 1) diverged"),
        (
            "RUNGE_KUTTA_54",
            ", PAS_MINI=0.05, PAS_MAXI=0.05",
            "the generalized velocity (mode 1) and acceleration (mode 1) diverged",
        ),
    ],
)
def test_a_step_far_beyond_stability_stops_at_the_first_non_finite_state(
    tmp_path, scheme, schema, quantities
):
    """PAS = 0.05 s on a 10 Hz oscillator (limit 0.005 s), VERI_PAS='NON':
    the state grows by a constant factor per step until it passes 1e300."""
    report, line = run_failing(tmp_path, gene_call(scheme, 0.05, 200.0, False, schema))
    message = assert_stopped_without_result(report, tmp_path, line, "INCREMENT/PAS")
    assert quantities in message and "try PAS <=" in message
    failing, last_finite, last_archived = instants(message)
    assert failing == pytest.approx(last_finite + 0.05, rel=1e-12)
    assert last_archived <= last_finite < 200.0


@pytest.mark.parametrize("scheme", ["DIFF_CENTRE", "NEWMARK", "RUNGE_KUTTA_54"])
def test_a_load_becoming_huge_is_named_with_its_instant(tmp_path, scheme):
    """The load jumps to 1e305 between 0.1 and 0.1001 s: the first step ending
    after 0.1 s fails, naming EXCIT[1]; NEWMARK, unconditionally stable,
    fails there too."""
    report, line = run_failing(tmp_path, gene_call(scheme, 2.5e-4, 0.25, True))
    message = assert_stopped_without_result(report, tmp_path, line, "EXCIT[1]")
    assert "the external load of EXCIT[1] is not finite" in message
    failing, last_finite, last_archived = instants(message)
    assert last_finite <= 0.1 + 1e-12 < failing
    if scheme != "RUNGE_KUTTA_54":  # fixed steps of 2.5e-4 s: 0.1 is the 400th
        assert (failing, last_finite, last_archived) == (0.10025, 0.1, 0.1)


def test_a_physical_transient_names_the_load_and_keeps_no_result(tmp_path):
    report, line = run_failing(tmp_path, PHYS_CALL)
    message = assert_stopped_without_result(report, tmp_path, line, "EXCIT[1]")
    assert "NEWMARK" in message and "the external load of EXCIT[1] is not finite" in message
    assert instants(message) == (0.10025, 0.1, 0.1)


def test_a_shock_force_is_named():
    """A DIS_CHOC whose archived force is NaN is named with its node."""

    class Shocks:
        specs = [
            ShockSpec(name="STOP", obstacle_type="PLAN_Y", node_1="N7", node_2=None,
                      coord_1=np.zeros(3), coord_2=None, phi_1=np.zeros((3, 1)), phi_2=None,
                      norm_obst=np.array([1.0, 0.0, 0.0]), source="COMPORTEMENT[2]")
        ]  # fmt: skip

    vint = np.zeros((1, 20))
    assert diagnosis.shock_culprit(Shocks(), vint) is None
    vint[0, 0] = np.nan
    culprit = diagnosis.shock_culprit(Shocks(), vint)
    assert culprit.path == "COMPORTEMENT[2]" and "'STOP' (node N7)" in culprit.text
    assert "FN=nan" in culprit.text


def test_state_text_lists_the_modes():
    q = np.array([1.0, np.inf, 2.0])
    v = np.array([np.nan, np.nan, np.nan])
    a = np.array([1.0e301, 0.0, 0.0])
    assert diagnosis.state_text(q, v, a) == (
        "the generalized displacement (mode 2), velocity (all 3 modes) and acceleration (mode 1)"
    )
    assert diagnosis.state_text(np.zeros(2), np.zeros(2), np.zeros(2)) == ""


@pytest.mark.parametrize("scheme", ["NEWMARK", "RUNGE_KUTTA_32"])
def test_the_rotating_loop_stops_likewise(scheme):
    """VITESSE_VARIABLE='OUI' runs its own loop: a load jumping to 1e305 at
    0.1 s stops it at the first step past 0.1 s, naming the load."""
    from asterlite.dynamics.excitation import tabulate_excitation
    from asterlite.dynamics.integrate import integrate
    from asterlite.dynamics.model import LinearSystem, build_shocks
    from asterlite.dynamics.rotation import Rotation
    from asterlite.errors import NumericalError
    from tests.test_dynamics_rotation_energy import Table, rotor
    from tests.validated import scheme_options

    mass, stiffness, damping, gyro, rigy = rotor()
    dt, t_end = 1.0e-3, 0.3
    rotation = Rotation(damping, stiffness, gyro, rigy, Table([0.0, 1.0], [0.0, 2000.0]))
    rotation.tabulate(0.0, t_end, dt / 2)
    c0, k0 = rotation.matrices_at(0.0)
    system = LinearSystem(mass, k0, c0)
    jump = Table([0.0, 0.1, 0.1001, 1.0], [0.0, 0.0, 1.0e305, 1.0e305])
    excitation = tabulate_excitation(2, [(np.array([1.0, 0.5]), jump)], 0.0, t_end, dt / 2)
    options = scheme_options(scheme, dt_min=dt, dt_max=dt)  # fixed steps for RUNGE_KUTTA_32 too
    with pytest.raises(NumericalError) as raised:
        integrate(
            system, build_shocks([], system), excitation, scheme, np.array([1e-3, 0.0]),
            np.zeros(2), 0.0, t_end, dt, np.array([t_end]), 10, options, rotation=rotation,
            load_labels=["EXCIT[1]"],
        )  # fmt: skip
    assert raised.value.path == "EXCIT[1]"
    message = raised.value.message
    assert message.startswith(f"{scheme}: non-finite values at t=0.101 (step 101, from t=0.1,")
    assert "last archived instant t=0.1;" in message and "EXCIT[1] is not finite" in message
