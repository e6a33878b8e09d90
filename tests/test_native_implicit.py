"""The loop with implicit shocks compiled in C++ (asterlite/dynamics/native/
implicit_shocks.hpp, dispatch.hpp: implicit_shocks.implicit_loop, every
scheme's step through the dispatch) against numba's: the same integrate run
with either loop (put in place of implicit_shocks.prepare's, as the routing of
integrate does through native.shared_loops), to the last bit, for every
scheme's code, on diagonal and full matrices: contact switches located and
the step integrated again up to them (or at its start), shocks linearised
again as a circle's normal turns, shocks left out while another is
linearised, friction, the energy balance, pauses, and the same error where
a run fails."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.function import Formula
from asterlite.dynamics import contact as C
from asterlite.dynamics import implicit_shocks as IS
from asterlite.dynamics import integrate as I
from asterlite.dynamics import native
from asterlite.dynamics import schemes as S
from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.model import build_shocks
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
NUMBA_PREPARE = IS.prepare  # numba's, before any test replaces it


def implicit_run(monkeypatch, compiled, scheme="NEWMARK", geometries=("CERCLE",), diagonal=True,
                 friction="both", formula=0, t_end=0.03, pas_arch=7, options=None, chunk=None,
                 q0=5.0e-5, dt=DT, energy=False, k_n=2.0e4, c_n=5.0, rows=None):  # fmt: skip
    """One integrate run with implicit shocks of ``scheme`` on a five-mode
    system, one shock per entry of ``geometries`` (or the rows ``rows(rng)``),
    three loads; ``compiled``:
    the C++ loop (native.shared_loops), else numba's. Returns (result, calls
    of the loop, the shock flags' treatment column at the end of each call)."""
    monkeypatch.setenv(native.SWITCH, "1" if compiled else "0")
    calls, modes, shock_sets = [], [], []

    def counted(loop):
        def run(*args):
            status = loop(*args)
            calls.append(status)
            modes.append(shock_sets[0].flags[:, C.F_IMPLICIT].copy())
            return status

        return run

    if compiled:  # integrate takes the C++ loop from native.shared_loops
        shared_loops = native.shared_loops

        def compiled_loops():  # None in the same test's numba run (switched off)
            loops = shared_loops()
            if loops is None:
                return None
            rotating, implicit, start = loops
            return rotating, counted(implicit), start

        monkeypatch.setattr(native, "shared_loops", compiled_loops)
    else:

        def prepare(name, memory, system, shocks):
            memory, loop = NUMBA_PREPARE(name, memory, system, shocks)
            return memory, counted(loop)

        monkeypatch.setattr(IS, "prepare", prepare)
    # pauses every ``chunk`` steps, not after a wall-clock time: the same calls either way
    monkeypatch.setattr(I.StepBudget, "resize_chunk", lambda self, seconds: None)
    if chunk is not None:
        monkeypatch.setattr(I.StepBudget, "FIRST_CHUNK", chunk)
    rng = np.random.default_rng(7)
    system = system_of(diagonal, rng)
    specs = [shock_of(geometry, rng, friction, (1.0, 0.0, 0.0)) for geometry in geometries]
    for spec in specs:
        spec.k_n, spec.c_n = k_n, c_n
    if rows is not None:
        specs = rows(rng)
    shocks = build_shocks(specs, system)
    for s, spec in enumerate(specs):
        if spec.coord_2 is None or rows is not None:
            continue
        apart = shocks.rots[s] @ (spec.coord_2 - spec.coord_1)
        if spec.obstacle_type.startswith("BI_PLAN"):  # the planes 1e-5 apart at rest
            axis = 1 if spec.obstacle_type == "BI_PLAN_Y" else 2
            spec.dist_1 = spec.dist_2 = (abs(apart[axis]) - 1.0e-5) / 2
        elif spec.obstacle_type == "BI_CERC_INT":  # 1e-5 inside at rest
            spec.dist_2 = spec.dist_1 + float(np.hypot(apart[1], apart[2])) + 1.0e-5
    shocks = build_shocks(specs, system)
    shock_sets.append(shocks)  # the loop's calls record its treatment flags
    times = np.linspace(0.0, t_end, 97)
    text, extra = FORMULAS[formula]
    loads = [
        (rng.standard_normal(N_MODES), Formula(VALE=text, NOM_PARA="INST", extra=extra)),
        (rng.standard_normal(N_MODES), Table(times, np.sin(60.0 * times) ** 2)),
        (rng.standard_normal(N_MODES), Sampled()),
    ]
    excitation = tabulate_excitation(N_MODES, loads, 0.0, t_end, dt / 2.0)
    instants = np.array([0.0123, 0.0123 + 0.3 * dt, t_end])
    result = I.integrate(
        system, shocks, excitation, scheme, np.full(N_MODES, q0), np.zeros(N_MODES), 0.0, t_end,
        dt, instants, pas_arch, options or scheme_options(scheme), energy=energy,
        implicit_shocks=True,
    )  # fmt: skip
    assert result.info["loop"].startswith(S.IMPLICIT_LOOP)
    return result, calls, modes


def compared(run) -> dict:
    """What the comparison of two runs reads: the loop's calls (their
    statuses), the treatment flags after each, the run's information and
    archives as native_runs.compared reads them."""
    result, calls, modes = run
    return {"calls": calls, "modes": np.array(modes), **run_fields(result)}


def both(request, monkeypatch, **args):
    """The run with the C++ loop, checked bit for bit against numba's (its
    fingerprint, tests.numba_reference); the C++ run's result."""
    compiled = implicit_run(monkeypatch, True, **args)
    assert len(compiled[1]) > 0
    numba = reference(request, lambda: compared(implicit_run(monkeypatch, False, **args)))
    assert_same(compared(compiled), numba, "the C++ run")
    return compiled[0]


def switches(result) -> bool:
    """Contacts switched and steps integrated again up to a switch."""
    info = result.info
    return info["contact_switches"] >= 2 and info["reintegrated_steps"] >= 1


@pytest.mark.parametrize("diagonal", [True, False], ids=["diagonal", "full"])
@pytest.mark.parametrize("scheme", SCHEMES)
def test_every_scheme_gives_numbas_bits(request, monkeypatch, scheme, diagonal):
    """Every scheme's code through the dispatch, its operators refreshed at
    every switch, impacts with friction on a circle."""
    result = both(request, monkeypatch, scheme=scheme, diagonal=diagonal)
    assert switches(result)


@pytest.mark.parametrize("friction", ["both", "one-way", "none"])
@pytest.mark.parametrize("geometry", GEOMETRIES)
def test_every_obstacle(request, monkeypatch, geometry, friction):
    scheme = {"both": "NEWMARK", "one-way": "TRBDF2", "none": "DEVOGE"}[friction]
    result = both(request, monkeypatch, scheme=scheme, geometries=(geometry,), friction=friction)
    assert switches(result)


@pytest.mark.parametrize("scheme", ["NEWMARK", "DIFF_CENTRE", "RUNGE_KUTTA_54"])
def test_the_normal_of_a_circle_turns(request, monkeypatch, scheme):
    """A node pressed into a circle and carried round: the shock is
    linearised again about its new contact point."""
    result = both(request, monkeypatch, scheme=scheme, geometries=("CERCLE",), q0=6.0e-4, k_n=2.0e4)
    assert result.info["relinearisations"] > 0


@pytest.mark.parametrize("scheme", ["NEWMARK", "ADAPT_ORDRE1", "TRBDF2"])
def test_shocks_left_out_while_another_is_linearised(request, monkeypatch, scheme):
    geometries = ("CERCLE", "BI_PLAN_Y", "PLAN_Z", "DISCRET")
    result = both(request, monkeypatch, scheme=scheme, geometries=geometries, diagonal=False)
    assert switches(result)


@pytest.mark.parametrize("scheme", SCHEMES)
def test_energy_balance(request, monkeypatch, scheme):
    both(request, monkeypatch, scheme=scheme, energy=True, geometries=("CERCLE", "BI_CERCLE"))


@pytest.mark.parametrize("scheme", ["NEWMARK", "RUNGE_KUTTA_32", "DEVOGE"])
def test_pauses_and_a_growing_archive(request, monkeypatch, scheme):
    """A pause every 97 steps and an archive at every step (grown as it fills)."""
    result = both(request, monkeypatch, scheme=scheme, chunk=97, pas_arch=1, formula=3)
    assert switches(result)


@pytest.mark.parametrize(
    "scheme, fields",
    [
        ("NEWMARK", {"beta": 0.3025, "gamma": 0.6}),
        ("NEWMARK", {"force_at_step_start": True}),
        ("DEVOGE", {"dt_min": DT, "dt_max": DT}),
        ("RUNGE_KUTTA_54", {"dt_min": DT, "dt_max": DT}),
        ("RUNGE_KUTTA_32", {"tolerance": 1.0e-8, "dt_max": 4.0 * DT}),
        ("ADAPT_ORDRE2", {"nmax_iter_pas": 3, "coef_divi_pas": 1.7, "dt_max": 2.0 * DT}),
    ],
)
def test_scheme_options(request, monkeypatch, scheme, fields):
    options = scheme_options(scheme, **fields)
    result = both(request, monkeypatch, scheme=scheme, options=options, diagonal=False, formula=4)
    assert switches(result)


def test_the_same_failures(request, monkeypatch):
    assert_same_failures(request, monkeypatch, implicit_run)


@pytest.mark.parametrize("scheme", ["NEWMARK", "RUNGE_KUTTA_32", "TRBDF2", "ADAPT_ORDRE2"])
def test_every_relation_of_laws(request, monkeypatch, scheme):
    """The relations of laws/ (laws.hpp, explicit) beside the DIS_CHOC rows linearised."""
    from tests.test_native_laws import every_relation

    result = both(
        request, monkeypatch, scheme=scheme, rows=every_relation, energy=scheme == "NEWMARK"
    )
    assert switches(result)
