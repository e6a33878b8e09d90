"""The loop at variable rotation speed compiled in C++ (asterlite/dynamics/native/
rotation.hpp, dispatch.hpp: loop.time_loop around rotation.rotating_step, every
scheme's step through the dispatch) against numba's: the same integrate run
with either loop (put in place of rotation.prepare's, as the routing of
integrate does through native.shared_loops), to the last bit, for every
scheme's code, on diagonal and full matrices, Ω and Ω' as tables, formulas and
sampled functions, DIS_CHOC shocks of every geometry with friction, support
motions, pauses, and the same error where a run fails."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.function import Formula
from asterlite.dynamics import contact as C
from asterlite.dynamics import dispatch as D
from asterlite.dynamics import implicit_shocks as IS
from asterlite.dynamics import integrate as I
from asterlite.dynamics import native
from asterlite.dynamics import rotation as R
from asterlite.dynamics import schemes as S
from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.model import LinearSystem, build_shocks
from asterlite.dynamics.rotation import Rotation
from tests.native_runs import (
    FORMULAS,
    GEOMETRIES,
    N_MODES,
    assert_same_failures,
    shock_of,
    system_of,
)
from tests.native_runs import compared as run_fields
from tests.numba_reference import assert_same, reference
from tests.test_dynamics_specialised import Sampled, Table
from tests.validated import scheme_options

# numba's side is its stored fingerprints (tests.numba_reference)
pytestmark = pytest.mark.usefixtures("needs_native")

DT = 2.0e-5
SCHEMES = [entry.name for entry in S.TABLE if entry.shared_loops]
NUMBA_PREPARE = R.prepare  # numba's, before any test replaces it
# Ω(t), Ω'(t): tables (the kernel's tables), formulas (its programs), a
# function it cannot evaluate (sampled over the whole run), and mixed
SPEEDS = ("table", "formula", "sampled", "mixed", "no acceleration")


class Ramp:
    """A speed known only through ``evaluate`` (Rotation.tabulate samples it)."""

    def evaluate(self, t):
        t = np.asarray(t)
        return 9000.0 * t + 40.0 * np.sin(700.0 * t)


def speeds(kind: str, t_end: float):
    """(Ω, Ω') of ``kind``: a ramp to 9000 t_end rad/s with a wobble."""
    times = np.linspace(0.0, t_end, 41)
    table = Table(times, 9000.0 * times + 40.0 * np.sin(700.0 * times))
    table_accel = Table(times, 9000.0 + 28000.0 * np.cos(700.0 * times))
    formula = Formula(VALE="9000*INST + 40*sin(700*INST)", NOM_PARA="INST", extra={})
    formula_accel = Formula(VALE="9000 + 28000*cos(700*INST)", NOM_PARA="INST", extra={})
    return {
        "table": (table, table_accel),
        "formula": (formula, formula_accel),
        "sampled": (Ramp(), Sampled()),
        "mixed": (table, formula_accel),
        "no acceleration": (formula, None),
    }[kind]


def gyroscopic(rng, diagonal: bool):
    """A skew gyroscopic matrix and a symmetric K_gy, coupling the modes
    unless ``diagonal`` (K_gy diagonal: with Ω(0) = 0, C(0) and K(0) stay
    diagonal, the loop makes them full at its first step)."""
    g = 0.02 * rng.standard_normal((N_MODES, N_MODES))
    k = 0.3 * rng.standard_normal((N_MODES, N_MODES))
    return g - g.T, np.diag(np.diag(k)) if diagonal else k + k.T


def rotating_run(monkeypatch, compiled, scheme="NEWMARK", geometry="CERCLE", diagonal=True,
                 friction="both", speed="table", supports=False, shocks=True, formula=0,
                 t_end=0.03, pas_arch=7, options=None, chunk=None, q0=2.0e-4, dt=DT,
                 rows=None):  # fmt: skip
    """One integrate run at variable rotation speed of ``scheme`` on a
    five-mode system (C(0), K(0) diagonal with ``diagonal``, full otherwise),
    one shock of ``geometry`` (or the rows ``rows(rng)``), three loads,
    optionally two support motions; ``compiled``: the C++ loop
    (native.shared_loops), else numba's. Returns (result, calls of the loop)."""
    monkeypatch.setenv(native.SWITCH, "1" if compiled else "0")
    calls = []

    def counted(loop):
        def run(*args):
            calls.append(1)
            return loop(*args)

        return run

    if compiled:  # integrate takes the C++ loop from native.shared_loops
        shared_loops = native.shared_loops

        def compiled_loops():  # None in the same test's numba run (switched off)
            loops = shared_loops()
            if loops is None:
                return None
            rotating, implicit, start = loops
            return counted(rotating), implicit, start

        monkeypatch.setattr(native, "shared_loops", compiled_loops)
    else:

        def prepare(name, memory, rotation):
            memory, loop = NUMBA_PREPARE(name, memory, rotation)
            return memory, counted(loop)

        monkeypatch.setattr(R, "prepare", prepare)
    # pauses every ``chunk`` steps, not after a wall-clock time: the same calls either way
    monkeypatch.setattr(I.StepBudget, "resize_chunk", lambda self, seconds: None)
    if chunk is not None:
        monkeypatch.setattr(I.StepBudget, "FIRST_CHUNK", chunk)
    rng = np.random.default_rng(5)
    base = system_of(diagonal, rng)
    gyro, rigy = gyroscopic(rng, diagonal)
    omega, accel = speeds(speed, t_end)
    rotation = Rotation(base.damping, base.stiffness, gyro, rigy, omega, accel)
    rotation.tabulate(0.0, t_end, dt / 2.0)
    c0, k0 = rotation.matrices_at(0.0)  # DYNA_VIBRA's system at t0
    system = LinearSystem(base.mass, k0, c0)
    assert system.diagonal == diagonal
    specs = [shock_of(geometry, rng, friction, (1.0, 0.0, 0.0))] if shocks else []
    if rows is not None:
        specs = rows(rng)
    shock_set = build_shocks(specs, system)
    if shocks and rows is None and geometry.startswith("BI_PLAN"):  # the planes 1e-5 apart at rest
        spec = specs[0]
        apart = shock_set.rots[0] @ (spec.coord_2 - spec.coord_1)
        spec.dist_1 = spec.dist_2 = (abs(apart[1 if geometry == "BI_PLAN_Y" else 2]) - 1.0e-5) / 2
        shock_set = build_shocks(specs, system)
    times = np.linspace(0.0, t_end, 97)
    text, extra = FORMULAS[formula]
    loads = [
        (rng.standard_normal(N_MODES), Formula(VALE=text, NOM_PARA="INST", extra=extra)),
        (rng.standard_normal(N_MODES), Table(times, np.sin(60.0 * times) ** 2)),
        (rng.standard_normal(N_MODES), Sampled()),
    ]
    excitation = tabulate_excitation(N_MODES, loads, 0.0, t_end, dt / 2.0)
    if supports:
        shapes = rng.standard_normal((len(specs), 2, 3, 2))
        displacement = Table(times, 1.0e-5 * np.sin(90.0 * times))
        velocity = Table(times, 9.0e-4 * np.cos(90.0 * times))
        motions = [(displacement, velocity), (Sampled(), Sampled())]
        excitation.add_support_motion(shapes, motions, 0.0, t_end, dt / 2.0)
    instants = np.array([0.0123, 0.0123 + 0.3 * dt, t_end])
    result = I.integrate(
        system, shock_set, excitation, scheme, np.full(N_MODES, q0), np.zeros(N_MODES), 0.0,
        t_end, dt, instants, pas_arch, options or scheme_options(scheme), rotation=rotation,
    )  # fmt: skip
    assert result.info["loop"].startswith(S.ROTATING_LOOP)
    return result, len(calls)


def compared(run) -> dict:
    """What the comparison of two runs reads: the loop's calls, the run's
    information and archives as native_runs.compared reads them."""
    result, calls = run
    return {"calls": calls, **run_fields(result)}


def both(request, monkeypatch, **args):
    """The run with the C++ loop, checked bit for bit against numba's (its
    fingerprint, tests.numba_reference); the C++ run's result."""
    compiled = rotating_run(monkeypatch, True, **args)
    assert compiled[1] > 0
    numba = reference(request, lambda: compared(rotating_run(monkeypatch, False, **args)))
    assert_same(compared(compiled), numba, "the C++ run")
    return compiled[0]


def impacts(result) -> bool:
    return bool((result.vint[:, 0, C.V_FN] > 0.0).any())


def test_the_codes_and_constants_are_pythons():
    from asterlite.dynamics.native import _shared

    built = _shared.constants()
    for name in ("NEWMARK", "TRBDF2", "DEVOGE", "DIFF_CENTRE", "RUNGE_KUTTA", "ADAPT_ORDRE1",
                 "ADAPT_ORDRE2"):  # fmt: skip
        assert built[name] == getattr(S, name)
    for name in ("P_LIN_GAP", "P_LIN_COS", "P_LIN_SIN", "NORMAL_EXPLICIT", "NORMAL_LINEARISED",
                 "NORMAL_LEFT_OUT"):  # fmt: skip
        assert built[name] == getattr(C, name)
    for name in ("CONTACT_FORCE", "CUT_TOLERANCE", "SHORTEST_CUT", "NORMAL_TURN", "MAX_TRIES",
                 "I_TRIES", "I_SWITCHES", "I_CUTS", "I_TURNS", "N_INTS", "R_GAP0", "R_GAP1",
                 "R_FORCE0", "R_FORCE1", "R_COS1", "R_SIN1", "N_KINEMATICS"):  # fmt: skip
        assert built[name] == getattr(IS, name), name
    assert {D.code(name) for name in SCHEMES} == set(range(7))


@pytest.mark.parametrize("diagonal", [True, False], ids=["diagonal", "full"])
@pytest.mark.parametrize("scheme", SCHEMES)
def test_every_scheme_gives_numbas_bits(request, monkeypatch, scheme, diagonal):
    """Every scheme's code through the dispatch, its operators refreshed at
    every step (NEWMARK's and TRBDF2's blocks, DEVOGE's M⁻¹C, M⁻¹K, H1, H2),
    impacts with friction on a circle."""
    result = both(request, monkeypatch, scheme=scheme, diagonal=diagonal)
    assert impacts(result)
    if scheme in ("RUNGE_KUTTA_32", "RUNGE_KUTTA_54", "DEVOGE", "ADAPT_ORDRE1", "ADAPT_ORDRE2"):
        assert result.info["steps"] != round(0.03 / DT)  # the step adapted


@pytest.mark.parametrize("speed", SPEEDS)
@pytest.mark.parametrize("scheme", ["NEWMARK", "DEVOGE", "RUNGE_KUTTA_54"])
def test_speeds_as_tables_formulas_and_samples(request, monkeypatch, scheme, speed):
    both(request, monkeypatch, scheme=scheme, speed=speed, diagonal=False)


@pytest.mark.parametrize("friction", ["both", "one-way", "none"])
@pytest.mark.parametrize("geometry", GEOMETRIES)
def test_every_obstacle(request, monkeypatch, geometry, friction):
    scheme = "TRBDF2" if friction == "both" else "ADAPT_ORDRE2"
    result = both(request, monkeypatch, scheme=scheme, geometry=geometry, friction=friction)
    assert impacts(result)


@pytest.mark.parametrize("scheme", ["DIFF_CENTRE", "NEWMARK", "ADAPT_ORDRE1"])
def test_support_motions_and_formulas(request, monkeypatch, scheme):
    for formula in range(len(FORMULAS)):
        diagonal = formula % 2 == 0
        both(request, monkeypatch, scheme=scheme, supports=True, formula=formula, diagonal=diagonal)


def test_without_shocks(request, monkeypatch):
    result = both(request, monkeypatch, scheme="DEVOGE", shocks=False)
    assert result.vint.shape[1] == 0


@pytest.mark.parametrize("scheme", ["NEWMARK", "RUNGE_KUTTA_32", "ADAPT_ORDRE2"])
def test_pauses_and_a_growing_archive(request, monkeypatch, scheme):
    """A pause every 97 steps and an archive at every step (grown as it fills)."""
    both(request, monkeypatch, scheme=scheme, chunk=97, pas_arch=1)


@pytest.mark.parametrize(
    "scheme, fields",
    [
        ("NEWMARK", {"beta": 0.3025, "gamma": 0.6}),
        ("NEWMARK", {"force_at_step_start": True}),
        ("DEVOGE", {"dt_min": DT, "dt_max": DT}),
        ("DEVOGE", {"tolerance": 1.0e-7}),
        ("RUNGE_KUTTA_54", {"dt_min": DT, "dt_max": DT}),
        ("RUNGE_KUTTA_32", {"tolerance": 1.0e-8, "dt_max": 4.0 * DT}),
        ("ADAPT_ORDRE1", {"dt_min": DT, "dt_max": DT}),
        ("ADAPT_ORDRE2", {"nmax_iter_pas": 3, "coef_divi_pas": 1.7, "dt_max": 2.0 * DT}),
        ("ADAPT_ORDRE2", {"vite_min": "MAXI"}),
    ],
)
def test_scheme_options(request, monkeypatch, scheme, fields):
    options = scheme_options(scheme, **fields)
    both(request, monkeypatch, scheme=scheme, options=options, diagonal=False)


def test_rejected_steps_are_retried_with_the_matrices_of_the_step_start(request, monkeypatch):
    options = scheme_options("RUNGE_KUTTA_54", tolerance=1.0e-9, dt_max=8.0 * DT)
    result = both(request, monkeypatch, scheme="RUNGE_KUTTA_54", options=options)
    assert result.info["rejected_steps"] > 0


def test_the_same_failures(request, monkeypatch):
    assert_same_failures(request, monkeypatch, rotating_run)


@pytest.mark.parametrize("scheme", ["RUNGE_KUTTA_54", "NEWMARK", "DEVOGE", "DIFF_CENTRE"])
def test_every_relation_of_laws(request, monkeypatch, scheme):
    """The relations of laws/ (laws.hpp) beside DIS_CHOC rows, at variable speed."""
    from tests.test_native_laws import every_relation

    result = both(request, monkeypatch, scheme=scheme, rows=every_relation, diagonal=False)
    assert impacts(result)
