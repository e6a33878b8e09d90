"""The relations of laws/ (laws.kernel.law_forces, native/laws.hpp) in the compiled
general paths give numba's bits: every relation, the branches of each law, mixed with
DIS_CHOC rows, on every scheme whose general path is C++, and the energy balance."""

from __future__ import annotations

import math

import numpy as np
import pytest

from asterlite.concepts.function import Formula
from asterlite.dynamics import energy as E
from asterlite.dynamics import integrate as I
from asterlite.dynamics import native
from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.geometry import local_frame, rotation_matrix
from asterlite.dynamics.integrate import integrate
from asterlite.dynamics.laws import anti_sism as AS
from asterlite.dynamics.laws import choc_elas_trac as CET
from asterlite.dynamics.laws import dis_ecro_trac as DET
from asterlite.dynamics.laws import dis_visc as DV
from asterlite.dynamics.laws import flambage as FL
from asterlite.dynamics.laws import kernel as LK
from asterlite.dynamics.laws import rela_effo_depl as RED
from asterlite.dynamics.laws import rotor_fiss as RF
from asterlite.dynamics.laws.connections import axis_frame
from asterlite.dynamics.laws.tabulated import Curve
from asterlite.dynamics.model import ShockSpec, build_shocks
from asterlite.errors import NumericalError
from tests.native_runs import (
    N_MODES,
    Sampled,
    Table,
    assert_same_bits,
    numba_run,
    shock_of,
    system_of,
)
from tests.numba_reference import assert_same, reference
from tests.validated import scheme_options

# the schemes whose general path (the relations' path) is a compiled loop
GENERAL = sorted(
    name
    for name in ("RUNGE_KUTTA_54", "RUNGE_KUTTA_32", "DEVOGE", "ADAPT_ORDRE1", "ADAPT_ORDRE2",
                 "TRBDF2", "DIFF_CENTRE", "NEWMARK")
    if I.GENERAL_PATH.format(I.SCHEMES[name].kernel) in native.LOOPS
)  # fmt: skip
COORD_1 = np.array([0.5, 0.01, -0.02])
COORD_2 = COORD_1 + np.array([2.0e-3, 3.0e-4, -1.0e-4])


def shapes(rng, scale=0.3):
    return rng.standard_normal((3, N_MODES)) * scale


def law_row(rng, relation, code, law, obstacle="BI_PLAN_Y", frame=None, state=None, **more):
    """A shock row of relation ``relation`` (``code``: its branch in laws.kernel), the
    mode shapes (translations and rotations) of its nodes drawn from ``rng``."""
    two = obstacle.startswith("BI_")
    return ShockSpec(
        name=relation[:8], obstacle_type=obstacle, node_1="N1", node_2="N2" if two else None,
        coord_1=COORD_1.copy(), coord_2=COORD_2.copy() if two else None,
        phi_1=shapes(rng), phi_2=shapes(rng, 0.1) if two else None,
        norm_obst=np.asarray(more.pop("norm_obst", (1.0, 0.0, 0.0)), dtype=float),
        relation=relation, law_code=code, law=law, law_state=state, frame=frame,
        rphi_1=shapes(rng), rphi_2=shapes(rng, 0.2) if two else None, **more,
    )  # fmt: skip


# --- the relations, as laws/connections.py builds their rows ------------------


def rela_effo_depl(rng, component="DY", left="LINEAIRE", right="CONSTANT", span=6.0e-5):
    """F(u) = a stiffening spring on [-span, span], prolonged as asked."""
    x = np.linspace(-span, span, 7)
    law = RED.prepare_rela_effo_depl(
        RED.RelationParameters(component, Curve(x, -4.0e3 * x - 3.0e12 * x**3, left, right))
    )
    return law_row(rng, "RELA_EFFO_DEPL", LK.RELA_EFFO_DEPL, law, obstacle="PLAN_Y")


def rela_effo_vite(rng, component="DRZ", left="CONSTANT", right="LINEAIRE", span=0.02, points=5):
    """F(v) = a damper on [-span, span] (one point: a constant force, prolonged)."""
    x = np.linspace(-span, span, points) if points > 1 else np.array([span])
    law = RED.prepare_relation(
        RED.RelationParameters(component, Curve(x, -3.0 * x + 40.0 * np.abs(x) * x, left, right)),
        "RELA_EFFO_VITE",
    )
    return law_row(rng, "RELA_EFFO_VITE", LK.RELA_EFFO_VITE, law, obstacle="PLAN_Y")


def rotor_fiss(rng, angle="constant"):
    """A crack whose stiffness depends on its opening angle; the rotor's angle from a
    constant speed, a table of the instant or a formula of it."""
    phi = np.linspace(0.0, 2.0 * math.pi, 9)
    stiffness = Curve(phi, 4.0e5 * (1.2 + np.cos(phi)), "CONSTANT", "CONSTANT")
    derivative = Curve(phi, -4.0e5 * np.sin(phi), "CONSTANT", "CONSTANT")
    table = Curve(np.array([0.0, 0.01, 0.05]), np.array([0.3, 1.0, 9.0]), "LINEAIRE", "LINEAIRE")
    program = Formula(VALE="0.3 + 80.0*INST + 900.0*INST**2", NOM_PARA="INST")
    given = {"constant": None, "table": table, "formula": program}[angle]
    law = RF.prepare_rotor_fiss(
        RF.RotorFissParameters(stiffness, derivative, 30.0, given),
        rotation_speed=120.0,
        variable_speed=angle != "constant",
    )
    frame = rotation_matrix(0.4, -0.3, 0.0)
    return law_row(rng, "ROTOR_FISS", LK.ROTOR_FISS, law, frame=frame)


def buckling_curves(**changes):
    data = dict(
        rigi_nor=1.0e4, fnor_crit=0.5, fnor_post_fl=0.25, larg_plat=1.0e-5, enfo_fl=2.0e-5,
        depl_post_fl=[1.0e-4, 2.0e-4], rigi_post_fl=[5.0e3, 4.0e3], amor_nor=0.5,
        points_per_segment=20,
    )  # fmt: skip
    return FL.legacy_buckling_curves(**{**data, **changes})


def flambage(rng, obstacle="PLAN_Y", included=True, scalar=False, gap=3.0e-5, branches=2):
    """A buckling support (code_aster 17's functions of the crushing, or code_aster
    15's scalar law with ``branches`` post-buckling branches after the first) on an
    obstacle of one or two nodes."""
    if scalar:
        data = FL.ScalarFlambageParameters(
            stiffness=1.0e4, damping=0.5, critical_force=0.5, post_buckling_force=0.25,
            drop=2.0e-5, plateau=1.0e-5, crushings=(1.0e-4, 2.0e-4)[:branches],
            post_stiffnesses=(5.0e3, 4.0e3)[:branches], post_dampings=(),
            buckling_damping=0.8, damping_in_criterion=included,
        )  # fmt: skip
        law = FL.prepare_scalar_flambage(data)
    else:
        fx, rigi, amor = buckling_curves()
        law = FL.prepare_flambage(FL.FlambageParameters(fx, rigi, amor, included))
    spec = law_row(
        rng, "FLAMBAGE", LK.FLAMBAGE, law, obstacle=obstacle, state=FL.initial_state(law),
        norm_obst=(1.0, 0.0, 0.0), angl_vril=25.0, orig_obst=COORD_1.copy(), gap=gap,
    )  # fmt: skip
    if obstacle == "DISCRET":
        angles = np.linspace(0.0, 360.0, 7)
        spec.polar = np.column_stack([angles, np.full(7, gap)])
    if obstacle == "BI_PLAN_Y":  # the planes ``gap`` apart at rest
        rot = local_frame(obstacle, spec.norm_obst, spec.angl_vril, COORD_1, COORD_2)
        apart = abs((rot @ (COORD_2 - COORD_1))[1])
        spec.dist_1 = spec.dist_2 = 0.5 * (apart - gap)
    return spec


def anti_sism(rng, threshold=0.5):
    data = AS.AntiSismParameters(
        initial_stiffness=1.0e4, final_stiffness=1.0e3, threshold=threshold, viscosity=0.2,
        exponent=0.5, stroke=1.0e-3,
    )  # fmt: skip
    law = AS.prepare_anti_sism(data)
    frame = axis_frame(COORD_1, COORD_2)
    half = 0.5 * AS.reference_distance(COORD_1, COORD_2, 2)
    return law_row(
        rng, "ANTI_SISM", LK.ANTI_SISM, law, frame=np.array([frame[1], frame[0], -frame[2]]),
        dist_1=half, dist_2=half,
    )  # fmt: skip


def choc_elas_trac(rng, clearance=2.0e-5, right="LINEAIRE"):
    rest = float(np.linalg.norm(COORD_2 - COORD_1))
    curve = Curve(np.array([0.0, 5.0e-5, 1.0e-4]), np.array([0.0, 1.0, 1.5]), "EXCLU", right)
    each = 0.5 * (rest - clearance)
    law = CET.prepare_choc_elas_trac(CET.ChocElasTracParameters(curve, each, each), rest)
    return law_row(rng, "CHOC_ELAS", LK.CHOC_ELAS_TRAC, law, frame=axis_frame(COORD_1, COORD_2))


def dis_visc(rng, exponent=0.6, iterations=20, tolerance=1.0e-6):
    data = DV.DisViscParameters(
        series_flexibility=1.0 / 2.0e4, parallel_stiffness=5.0e3, branch_flexibility=1.0 / 1.0e4,
        viscosity=50.0, exponent=exponent, max_iterations=iterations, tolerance=tolerance,
    )  # fmt: skip
    law = DV.prepare_dis_visc(data)
    return law_row(rng, "DIS_VISC", LK.DIS_VISC, law, frame=axis_frame(COORD_1, COORD_2))


WIDE = ([0.0, 3.0e-5, 6.0e-5, 5.0e-3], [0.0, 0.3, 0.4, 0.9])  # never exhausted here
NARROW = ([0.0, 3.0e-5, 6.0e-5, 4.0e-4], [0.0, 0.3, 0.4, 0.6])  # exhausted after 2.5 ms
KINEMATIC = ([0.0, 3.0e-5, 5.0e-3], [0.0, 0.3, 0.9])


def dis_ecro_trac(rng, axial=True, kinematic=False, points=None, iterations=20):
    if points is None:
        points = KINEMATIC if kinematic else WIDE
    data = DET.DisEcroTracParameters(
        curve=Curve(np.array(points[0]), np.array(points[1])), axial=axial, kinematic=kinematic,
        max_iterations=iterations, tolerance=1.0e-6, curve_label="FX" if axial else "FTAN",
    )  # fmt: skip
    law = DET.prepare_dis_ecro_trac(data)
    return law_row(rng, "DIS_ECRO", LK.DIS_ECRO_TRAC, law, frame=axis_frame(COORD_1, COORD_2))


def dis_choc(rng, geometry="CERCLE"):
    """A DIS_CHOC row with friction (tests/native_runs.py's)."""
    spec = shock_of(geometry, rng, "both", (1.0, 0.0, 0.0))
    if geometry.startswith("BI_PLAN"):  # the planes 1e-5 apart at rest
        rot = local_frame(geometry, spec.norm_obst, spec.angl_vril, spec.coord_1, spec.coord_2)
        apart = rot @ (spec.coord_2 - spec.coord_1)
        spec.dist_1 = spec.dist_2 = (abs(apart[1 if geometry == "BI_PLAN_Y" else 2]) - 1.0e-5) / 2
    return spec


# --- runs ----------------------------------------------------------------------


class Slight(Sampled):
    """A support motion known only through ``evaluate`` (sampled by windows), of the
    size of the relations' strokes."""

    def evaluate(self, t):
        return 4.0e-5 * super().evaluate(t)


def run(monkeypatch, compiled, rows, scheme="RUNGE_KUTTA_54", diagonal=True, t_end=0.02,
        supports=False, energy=False, amplitude=1.0, pas_arch=5):  # fmt: skip
    """One run of ``scheme``'s general path on a five-mode system with the shock rows
    ``rows(rng)`` (the same draws in both runs), three loads scaled by ``amplitude``,
    optionally two support motions; ``compiled``: the C++ loops, else numba's."""
    monkeypatch.setenv(native.SWITCH, "1" if compiled else "0")
    rng = np.random.default_rng(5)
    system = system_of(diagonal, rng)
    specs = rows(rng)
    shocks = build_shocks(specs, system)
    dt = 2.0e-5
    times = np.linspace(0.0, t_end, 97)
    wave = Formula(VALE="3*sin(190*INST)", NOM_PARA="INST")
    loads = [
        (amplitude * rng.standard_normal(N_MODES), wave),
        (amplitude * rng.standard_normal(N_MODES), Table(times, np.sin(60.0 * times) ** 2)),
        (amplitude * rng.standard_normal(N_MODES), Sampled()),
    ]  # fmt: skip
    excitation = tabulate_excitation(N_MODES, loads, 0.0, t_end, dt / 2.0)
    if supports:
        moved = rng.standard_normal((len(specs), 2, 3, 2))
        displacement = Table(times, 1.0e-5 * np.sin(90.0 * times))
        velocity = Table(times, 9.0e-4 * np.cos(90.0 * times))
        excitation.add_support_motion(
            moved, [(displacement, velocity), (Slight(), Slight())], 0.0, t_end, dt / 2.0
        )
    q0 = np.full(N_MODES, 2.0e-4)
    instants = np.array([0.0123, 0.0123 + 0.3 * dt, t_end])
    return integrate(
        system, shocks, excitation, scheme, q0, np.zeros(N_MODES), 0.0, t_end, dt,
        instants, pas_arch, scheme_options(scheme), energy=energy,
    )  # fmt: skip


def both(request, monkeypatch, rows, **kw):
    """The run with the C++ loops, checked bit for bit against numba's (its
    fingerprint, tests.numba_reference); the C++ run's result."""
    compiled = run(monkeypatch, True, rows, **kw)
    numba = numba_run(request, monkeypatch, rows, runner=run, **kw)
    assert_same_bits(compiled, numba)
    return compiled


def column(result, s, j):
    """Archived internal variable j of row s."""
    return result.vint[:, s, j]


# --- every relation and its branches, with RUNGE_KUTTA_54's general path -------


def check_relation(result, span):
    u, f = column(result, 0, RED.V_VALUE), column(result, 0, RED.V_FORCE)
    assert u.min() < -span and u.max() > span  # both prolongations
    assert np.any(f != 0.0) and np.any(column(result, 0, RED.V_ACTIVE) == 1.0)


def check_rotor(result):
    angle = column(result, 0, RF.V_ANGLE)
    assert np.ptp(angle) > 90.0 and np.all(column(result, 0, RF.V_MY) != 0.0)


def check_buckling(result):
    fn, crushing = column(result, 0, FL.V_FN), column(result, 0, FL.V_DEFPLA)
    assert fn.max() > 0.0 and crushing[-1] > 1.0e-6  # buckled
    after = crushing > 1.0e-6
    assert np.any(fn[after] == 0.0)  # unloaded, or inside the gap the crushing opened


def check_anti_sism(result):
    force = column(result, 0, AS.V_FORCE)
    assert force.min() < 0.0 < force.max()  # the device pulled and pushed


def check_elastic_shock(result):
    force = column(result, 0, CET.V_FORCE)
    assert np.any(force > 0.0) and np.any(force == 0.0)  # in and out of contact


def check_viscous(result):
    assert np.all(column(result, 0, LK.V_TIME) == result.times)  # the state of each instant
    assert np.ptp(column(result, 0, DV.V_FORCE)) > 0.0
    assert np.ptp(column(result, 0, DV.V_EPS_VISC)) > 0.0 and column(result, 0, DV.V_DISSIP)[-1] > 0


def check_hardening(kinematic):
    def check(result):
        assert column(result, 0, DET.V_PCUM)[-1] > 0.0  # plastic flow
        assert np.ptp(result.vint[:, 0, DET.V_FORCE : DET.V_FORCE + 3]) > 0.0
        back = result.vint[:, 0, DET.V_BACK_FORCE : DET.V_BACK_FORCE + 3]
        assert np.any(back != 0.0) == kinematic

    return check


CASES = {
    "RELA_EFFO_DEPL DY": (lambda r: [rela_effo_depl(r)], lambda x: check_relation(x, 6.0e-5), {}),
    "RELA_EFFO_DEPL DRX": (
        lambda r: [rela_effo_depl(r, "DRX", "CONSTANT", "LINEAIRE", 2.0e-5)],
        lambda x: check_relation(x, 2.0e-5),
        {},
    ),
    "RELA_EFFO_VITE DRZ": (lambda r: [rela_effo_vite(r)], lambda x: check_relation(x, 0.02), {}),
    "RELA_EFFO_VITE DZ": (
        lambda r: [rela_effo_vite(r, "DZ", "LINEAIRE", "CONSTANT")],
        lambda x: check_relation(x, 0.02),
        {},
    ),
    "RELA_EFFO_VITE one point": (
        lambda r: [rela_effo_vite(r, "DY", "CONSTANT", "CONSTANT", points=1)],
        lambda x: check_relation(x, 0.02),
        {},
    ),
    "ROTOR_FISS constant speed": (lambda r: [rotor_fiss(r)], check_rotor, {}),
    "ROTOR_FISS angle table": (lambda r: [rotor_fiss(r, "table")], check_rotor, {}),
    "ROTOR_FISS angle formula": (lambda r: [rotor_fiss(r, "formula")], check_rotor, {}),
    "FLAMBAGE PLAN_Y": (lambda r: [flambage(r)], check_buckling, {}),
    "FLAMBAGE CERCLE, damping out of the criterion": (
        lambda r: [flambage(r, "CERCLE", included=False)],
        check_buckling,
        {},
    ),
    "FLAMBAGE BI_PLAN_Y": (
        lambda r: [flambage(r, "BI_PLAN_Y", included=False)],
        check_buckling,
        {},
    ),
    "FLAMBAGE scalar DISCRET": (
        lambda r: [flambage(r, "DISCRET", scalar=True)],
        check_buckling,
        {"amplitude": 4.0},
    ),
    "FLAMBAGE scalar PLAN_Z, damping out of the criterion": (
        lambda r: [flambage(r, "PLAN_Z", scalar=True, included=False)],
        check_buckling,
        {"amplitude": 4.0},
    ),
    "FLAMBAGE scalar, one branch": (
        lambda r: [flambage(r, "PLAN_Y", scalar=True, branches=0)],
        check_buckling,
        {"amplitude": 4.0},
    ),
    "ANTI_SISM": (lambda r: [anti_sism(r)], check_anti_sism, {}),
    "ANTI_SISM without threshold": (lambda r: [anti_sism(r, 0.0)], check_anti_sism, {}),
    "CHOC_ELAS_TRAC": (lambda r: [choc_elas_trac(r)], check_elastic_shock, {}),
    "DIS_VISC": (lambda r: [dis_visc(r)], check_viscous, {}),
    "DIS_VISC linear dashpot": (lambda r: [dis_visc(r, exponent=1.0)], check_viscous, {}),
    "DIS_ECRO_TRAC axial": (lambda r: [dis_ecro_trac(r)], check_hardening(False), {}),
    "DIS_ECRO_TRAC transverse": (
        lambda r: [dis_ecro_trac(r, axial=False)],
        check_hardening(False),
        {},
    ),
    "DIS_ECRO_TRAC kinematic": (
        lambda r: [dis_ecro_trac(r, axial=False, kinematic=True)],
        check_hardening(True),
        {},
    ),
}


@pytest.mark.parametrize("case", list(CASES))
def test_each_relation_gives_numbas_bits(request, monkeypatch, case):
    rows, check, options = CASES[case]
    result = both(request, monkeypatch, rows, **options)
    check(result)


# --- all relations at once, with DIS_CHOC rows, on every compiled general path ---


def every_relation(rng):
    return [
        dis_choc(rng, "CERCLE"),
        rela_effo_depl(rng),
        rela_effo_vite(rng),
        rotor_fiss(rng, "formula"),
        flambage(rng),
        flambage(rng, "BI_PLAN_Y", included=False),
        anti_sism(rng),
        dis_choc(rng, "BI_PLAN_Z"),
        choc_elas_trac(rng),
        dis_visc(rng),
        dis_ecro_trac(rng),
        dis_ecro_trac(rng, axial=False, kinematic=True),
    ]


@pytest.mark.parametrize("variant", ["diagonal", "full matrices, supports"])
@pytest.mark.parametrize("scheme", GENERAL)
def test_every_relation_with_shocks_on_every_general_path(request, monkeypatch, scheme, variant):
    diagonal = variant == "diagonal"
    result = both(request, monkeypatch, every_relation, scheme=scheme, diagonal=diagonal,
                  supports=not diagonal)  # fmt: skip
    # the DIS_CHOC rows hit their obstacles, every law row has a force or a moment
    assert np.any(column(result, 0, 0) > 0.0) and np.any(column(result, 7, 0) > 0.0)
    forces = {1: RED.V_FORCE, 2: RED.V_FORCE, 3: RF.V_MY, 4: FL.V_FN, 5: FL.V_FN, 6: AS.V_FORCE,
              8: CET.V_FORCE, 9: DV.V_FORCE, 10: DET.V_FORCE, 11: DET.V_FORCE + 1}  # fmt: skip
    for s, j in forces.items():
        assert np.any(column(result, s, j) != 0.0), s


# --- a law that cannot be evaluated ends the run as numba's does --------------

FAILURES = {
    "DIS_VISC not converging": lambda r: [dis_choc(r), dis_visc(r, iterations=2, tolerance=1.0e-9)],
    "DIS_ECRO_TRAC beyond its curve": lambda r: [dis_ecro_trac(r, points=NARROW)],
    "RELA_EFFO_DEPL outside EXCLU": lambda r: [rela_effo_depl(r, left="EXCLU", right="EXCLU")],
    "CHOC_ELAS_TRAC beyond EXCLU": lambda r: [choc_elas_trac(r, right="EXCLU")],
}


def failing_run(monkeypatch, compiled, rows, scheme):
    """The error of a run that fails, the internal variables and the instant it names,
    and whether the compiled loop ran."""
    seen = {}
    route = native.run_loop
    name_law = I.law_error

    def routed(*args):
        seen["loop"] = route(*args)
        return seen["loop"]

    def named(shocks, vint, t):
        seen["vint"], seen["t"] = vint.copy(), t
        return name_law(shocks, vint, t)

    monkeypatch.setattr(native, "run_loop", routed)
    monkeypatch.setattr(I, "law_error", named)
    with pytest.raises(NumericalError) as error:
        run(monkeypatch, compiled, rows, scheme=scheme)
    monkeypatch.setattr(native, "run_loop", route)
    monkeypatch.setattr(I, "law_error", name_law)
    return str(error.value), seen


def failure(monkeypatch, compiled: bool, rows, scheme) -> dict:
    """What the comparison of the failing runs reads: the error, the instant it
    names and the internal variables, the C++ loop run when ``compiled``
    (else numba's)."""
    message, seen = failing_run(monkeypatch, compiled, rows, scheme)
    assert (seen["loop"] is not None) == compiled  # C++, else numba's
    return {"message": message, "t": seen["t"], "vint": seen["vint"]}


@pytest.mark.parametrize("scheme", ["RUNGE_KUTTA_54", "DEVOGE"])
@pytest.mark.parametrize("case", list(FAILURES))
def test_a_law_that_fails_ends_the_run_as_numbas(request, monkeypatch, case, scheme):
    compiled = failure(monkeypatch, True, FAILURES[case], scheme)
    numba = reference(request, lambda: failure(monkeypatch, False, FAILURES[case], scheme))
    assert_same(compiled, numba, "the failure")
    assert "could not be evaluated" in compiled["message"] and compiled["t"] > 0.0
    assert np.isnan(compiled["vint"]).any()


# --- the energy balance: the laws' work (TRAV_NL) -----------------------------


@pytest.mark.parametrize("scheme", ["RUNGE_KUTTA_54", "TRBDF2"])
def test_energy_balance_with_laws(request, monkeypatch, scheme):
    result = both(request, monkeypatch, every_relation, scheme=scheme, energy=True)
    work = result.energy[:, E.C_TRAV_NL]
    assert np.all(np.isfinite(result.energy)) and np.ptp(work) > 0.0
