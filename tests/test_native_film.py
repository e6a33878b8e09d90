"""The loops with fluid films compiled in C++ (asterlite/dynamics/native/film.hpp:
fluid_film.run_loop, code_aster 11's EULER, and fluid_film.run_adapt_loop, its
ADAPT_ORDRE2 under mdadap's step control) against numba's: the same
integrate_film run with either pair of loops (put in place of fluid_film's
as the routing of integrate_film does, through native.film_loops), to the
last bit, on every obstacle geometry, with dry DIS_CHOC shocks beside the
films, tabulated, formula and sampled loads, windowed support motions,
fixed and adaptive steps, the boundary layer entered and left, the dry
force inside it, the added-mass stand-in (relaxation, no added mass), pauses
every few steps, the archive grown, and the same error where a run fails."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pytest

from asterlite.concepts.function import Formula
from asterlite.dynamics import contact as C
from asterlite.dynamics import excitation as EX
from asterlite.dynamics import fluid_film as FF
from asterlite.dynamics import integrate as I
from asterlite.dynamics import kernel as K
from asterlite.dynamics import native
from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.fluid_film import FluidFilm, film_row, integrate_film
from asterlite.dynamics.model import build_shocks
from asterlite.errors import NumericalError
from tests.native_runs import FORMULAS, GEOMETRIES, N_MODES, shock_of, system_of
from tests.native_runs import compared as run_fields
from tests.numba_reference import assert_same, reference
from tests.test_dynamics_specialised import Sampled, Table
from tests.validated import scheme_options

# numba's side is its stored fingerprints (tests.numba_reference)
pytestmark = pytest.mark.usefixtures("needs_native")

DT = 2.0e-5
# α (added mass), β, χ (squeeze), δ: a film that pushes back hard enough on
# this problem to enter and leave its boundary layer, and a weaker one
FILM = (-1.0e-8, 1.0e-9, -1.0e-18, -1.0e-9)
STRONG = (-1.0e-7, 1.0e-8, -1.0e-17, 1.0e-8)
CONTROLS = (50, 1.0e-6, 10.0)  # at most, tolerance, relaxation
# numba's loops and start, and the C++ ones' getter, before any test replaces them
NUMBA_LOOPS = (FF.run_loop, FF.run_adapt_loop, FF.start)
FILM_LOOPS = native.film_loops


@dataclass
class FilmRun:
    result: object  # integrate.RunResult
    calls: int  # calls of the loop (pauses and resumptions included)
    layers: list  # the film rows' boundary-layer columns after each call
    film_rows: np.ndarray  # the film rows at the end
    state: list  # clock, counters, q, v, a, vint at the end


LAST: list[FilmRun] = []  # the record of the last run, kept when it fails


def film_run(monkeypatch, compiled, geometry="PLAN_Z", coefficients=FILM, dry="BI_CERCLE",
             adapt=False, formula=0, supports=False, controls=CONTROLS, t_end=0.04, pas_arch=7,
             options=None, chunk=None, second_film=False):  # fmt: skip
    """integrate_film on a five-mode system: a film shock of ``geometry``
    (optionally a second one, BI_PLAN_Z), a dry DIS_CHOC shock ``dry`` with
    friction (or none), three loads (a formula, a table, a sampled
    multiplier), optionally two support motions (the film loops only wait
    for their windows); ``compiled``: the C++ loops, else numba's;
    ``chunk``: pause every ``chunk`` steps."""
    monkeypatch.setenv(native.SWITCH, "1" if compiled else "0")
    loops = FILM_LOOPS() if compiled else NUMBA_LOOPS
    assert loops is not None and (compiled or loops[0].__module__ == FF.__name__)
    record = FilmRun(None, 0, [], None, [])
    LAST[:] = [record]

    def recorded(loop, model_at, state):
        def run(*args):
            status = loop(*args)
            record.calls += 1
            record.layers.append(args[model_at][5][:, FF.FL_LAYER].copy())
            record.film_rows = args[model_at][5].copy()
            record.state = [np.copy(x) for x in args[:2] + state(args)]
            record.state[1][K.K_PAUSE_AT] = 0  # the driver's
            return status

        return run

    chosen = (
        recorded(loops[0], 7, lambda args: args[2:6]),
        recorded(loops[1], 5, lambda args: tuple(args[2][:3]) + (args[2].vint,)),
        loops[2],
    )
    # integrate_film takes them from native.film_loops once routed there, else
    # (and for numba's) as fluid_film's functions
    monkeypatch.setattr(native, "film_loops", lambda: chosen if compiled else None)
    monkeypatch.setattr(FF, "run_loop", chosen[0])
    monkeypatch.setattr(FF, "run_adapt_loop", chosen[1])
    monkeypatch.setattr(FF, "start", chosen[2])
    # pauses every ``chunk`` steps (20000 by default), not after a wall-clock time:
    # the same calls with either loop
    monkeypatch.setattr(I.StepBudget, "resize_chunk", lambda self, seconds: None)
    if chunk is not None:
        monkeypatch.setattr(I.StepBudget, "FIRST_CHUNK", chunk)
    rng = np.random.default_rng(11)
    system = system_of(True, rng)
    specs = [shock_of(geometry, rng, "none", (0.3, 0.9, 0.3))]
    if second_film:
        specs.append(shock_of("BI_PLAN_Z", rng, "none", (1.0, 0.0, 0.0)))
    if dry is not None:
        specs.append(shock_of(dry, rng, "both", (1.0, 0.0, 0.0)))
    shocks = build_shocks(specs, system)
    rows = np.zeros((len(specs), FF.N_FILM))
    rows[0] = film_row(*coefficients)
    if second_film:
        rows[1] = film_row(*coefficients)
    film = FluidFilm(rows, *controls)
    times = np.linspace(0.0, t_end, 97)
    text, extra = FORMULAS[formula] if isinstance(formula, int) else formula
    loads = [
        (rng.standard_normal(N_MODES), Formula(VALE=text, NOM_PARA="INST", extra=extra)),
        (rng.standard_normal(N_MODES), Table(times, np.sin(60.0 * times) ** 2)),
        (rng.standard_normal(N_MODES), Sampled()),
    ]
    excitation = tabulate_excitation(N_MODES, loads, 0.0, t_end, DT / 2.0)
    if supports:
        shapes = rng.standard_normal((len(specs), 2, 3, 2))
        displacement = Table(times, 1.0e-5 * np.sin(90.0 * times))
        velocity = Table(times, 9.0e-4 * np.cos(90.0 * times))
        motions = [(displacement, velocity), (Sampled(), Sampled())]
        excitation.add_support_motion(shapes, motions, 0.0, t_end, DT / 2.0)
    if options is None:
        options = (
            scheme_options("ADAPT_ORDRE2", adapt_v11=True, dt_max=4.0e-5)
            if adapt
            else scheme_options("DIFF_CENTRE")
        )
    instants = np.array([0.0123, 0.0123 + 0.3 * DT, t_end])
    record.result = integrate_film(
        system, shocks, film, excitation, np.full(N_MODES, 2.0e-4), np.zeros(N_MODES), 0.0,
        t_end, DT, instants, pas_arch, options,
    )  # fmt: skip
    loop = record.result.info.get("loop")  # once integrate_film names its loop
    assert loop is None or loop.endswith("[C++]" if compiled else "[numba]")
    return record


def records(run: FilmRun) -> dict:
    """What the comparison of two runs' records reads: the loop calls, film
    rows, boundary-layer columns and final state (clock and counters included)."""
    names = ("clock", "counters", "q", "v", "a", "vint")
    fields = {"calls": run.calls, "film_rows": run.film_rows, "layers": np.array(run.layers)}
    fields["state"] = dict(zip(names, run.state, strict=True))
    return fields


def compared(run: FilmRun) -> dict:
    """What the comparison of two runs reads: the records, the run's
    information and archives as native_runs.compared reads them."""
    return {"records": records(run), **run_fields(run.result)}


def both(request, monkeypatch, **args) -> FilmRun:
    """The run with the C++ loops, checked bit for bit against numba's
    (its fingerprint, tests.numba_reference); the C++ run."""
    compiled = film_run(monkeypatch, True, **args)
    assert compiled.calls > 0
    numba = reference(request, lambda: compared(film_run(monkeypatch, False, **args)))
    assert_same(compared(compiled), numba, "the C++ film run")
    return compiled


def both_fail(request, monkeypatch, match, **args) -> dict:
    """Both loops (or both starts) stop the run with the same error, in the same state."""

    def outcome(compiled: bool) -> dict:
        with pytest.raises(NumericalError, match=match) as failure:
            film_run(monkeypatch, compiled, **args)
        record = LAST[0]
        return {
            "message": str(failure.value),
            "calls": record.calls,
            "records": records(record) if record.calls else None,
        }

    compiled = outcome(True)
    assert_same(compiled, reference(request, lambda: outcome(False)), "the failure")
    return compiled


def film_works(run: FilmRun) -> bool:
    """The film pushes (its normal force at some archived instant) and
    iterates (more iterations than steps)."""
    info = run.result.info
    return bool((run.result.vint[:, 0, C.V_FN] != 0.0).any()) and (
        info["film_iterations"] > info["steps"] and info["film_worst_iterations"] >= 2
    )


def dry_impacts(run: FilmRun) -> bool:
    return bool((run.result.vint[:, -1, C.V_FN] > 0.0).any())


@pytest.mark.parametrize("adapt", [False, True])
@pytest.mark.parametrize("geometry", GEOMETRIES)
def test_every_obstacle_gives_numbas_bits(request, monkeypatch, geometry, adapt):
    run = both(request, monkeypatch, geometry=geometry, adapt=adapt)
    assert film_works(run) and dry_impacts(run)
    assert (run.result.vint[:, -1, C.V_FT1] != 0.0).any()  # the dry shock's friction
    if adapt:
        assert run.result.info["adaptive"] and run.result.info["rejected_steps"] > 0


@pytest.mark.parametrize("adapt", [False, True])
@pytest.mark.parametrize("coefficients", [FILM, STRONG])
def test_the_boundary_layer_gives_numbas_bits(request, monkeypatch, coefficients, adapt):
    """Paused every 25 steps: the layer's state seen between pauses is entered
    and left; inside it, through the wall (gap <= 0), the dry force pushes."""
    run = both(request, monkeypatch, coefficients=coefficients, adapt=adapt, chunk=25)
    layers = np.array(run.layers)[:, 0]
    assert run.calls > 40 and (layers == 1.0).any()
    if coefficients == FILM:
        assert ((layers[:-1] == 1.0) & (layers[1:] == 0.0)).any()  # left again
    vint = run.result.vint[:, 0]
    gap = 1.0e-5 - np.abs(vint[:, C.V_LOC1 + 2])  # PLAN_Z: P_GAP - |z|
    assert ((gap <= 0.0) & (vint[:, C.V_FN] > 0.0)).any()
    assert ((gap > 0.0) & (vint[:, C.V_FN] != 0.0)).any()


@pytest.mark.parametrize("adapt", [False, True])
def test_two_films_and_no_dry_shock_give_numbas_bits(request, monkeypatch, adapt):
    both(request, monkeypatch, geometry="CERCLE", second_film=True, adapt=adapt)
    run = both(request, monkeypatch, geometry="BI_CERCLE", dry=None, adapt=adapt)
    assert film_works(run)


@pytest.mark.parametrize("adapt", [False, True])
@pytest.mark.parametrize(
    "coefficients",
    [
        (0.0, 1.0e-9, -1.0e-18, -1.0e-9),  # no added mass: M' = M
        (-1.0e-8, 0.0, 0.0, 0.0),  # the added mass alone
        (0.0, 0.0, 0.0, 0.0),  # no film force: the layer's dry law alone
    ],
)
def test_each_term_of_the_film_gives_numbas_bits(request, monkeypatch, coefficients, adapt):
    run = both(request, monkeypatch, coefficients=coefficients, adapt=adapt)
    assert dry_impacts(run)


@pytest.mark.parametrize("adapt", [False, True])
@pytest.mark.parametrize("relaxation", [1.0, 3.0, 30.0])
def test_the_mass_modification_gives_numbas_bits(request, monkeypatch, relaxation, adapt):
    """λ scales the diagonal added-mass stand-in: other iterations, same bits."""
    run = both(request, monkeypatch, controls=(200, 1.0e-8, relaxation), adapt=adapt)
    assert film_works(run)


@pytest.mark.parametrize("adapt", [False, True])
@pytest.mark.parametrize("formula", range(len(FORMULAS)))
def test_formula_loads_give_numbas_bits(request, monkeypatch, formula, adapt):
    both(request, monkeypatch, formula=formula, adapt=adapt)


@pytest.fixture
def refills(monkeypatch) -> list:
    """Sampling windows of 64 samples; the instants of each refill after the first."""
    calls = []
    refill = EX.Excitation.refill

    def counted(self, t, dt):
        calls.append(t)
        return refill(self, t, dt)

    monkeypatch.setattr(EX, "SAMPLES_PER_WINDOW", 64)
    monkeypatch.setattr(EX.Excitation, "refill", counted)
    return calls


@pytest.mark.parametrize("adapt", [False, True])
@pytest.mark.parametrize("supports", [False, True])
def test_sampling_windows_give_numbas_bits(request, monkeypatch, refills, supports, adapt):
    """The loops stop for the next window of the sampled loads and, with
    supports, of the support motions (loads_ready), and resume."""
    run = both(request, monkeypatch, supports=supports, adapt=adapt)
    assert film_works(run)
    assert len([t for t in refills if t > 0.0]) > 20 and run.calls > 20


@pytest.mark.parametrize("pas_arch", [1, 3, 50])
def test_archiving_gives_numbas_bits(request, monkeypatch, pas_arch):
    both(request, monkeypatch, pas_arch=pas_arch)
    both(request, monkeypatch, pas_arch=pas_arch, adapt=True)


def test_adapt_archive_grid_denser_than_the_buffers_gives_numbas_bits(request, monkeypatch):
    """A step's upper bound below the step: code_aster's slots outnumber the
    archive's first capacity (the buffers grow, the loop resumes)."""
    options = scheme_options("ADAPT_ORDRE2", adapt_v11=True, dt_max=5.0e-6)
    run = both(request, monkeypatch, adapt=True, options=options, pas_arch=2)
    capacity = 2 + 3 + 2000 // 2
    assert len(run.result.times) > capacity and run.calls > 1


def test_adapt_steps_kept_at_the_largest_number_of_trials_give_numbas_bits(request, monkeypatch):
    options = scheme_options("ADAPT_ORDRE2", adapt_v11=True, dt_max=4.0e-5, nmax_iter_pas=1)
    run = both(request, monkeypatch, adapt=True, options=options)
    assert run.result.info["steps_kept_at_nmax_iter_pas"] > 0


@pytest.mark.parametrize("vite_min", ["NORM", "MAXI"])
def test_adapt_reference_velocities_give_numbas_bits(request, monkeypatch, vite_min):
    options = scheme_options("ADAPT_ORDRE2", adapt_v11=True, dt_max=4.0e-5, vite_min=vite_min)
    run = both(request, monkeypatch, adapt=True, options=options, chunk=100)
    assert run.result.info["rejected_steps"] > 0


@pytest.mark.parametrize("adapt", [False, True])
def test_iterations_not_converging_stop_both_alike(request, monkeypatch, adapt):
    failure = both_fail(
        request, monkeypatch, "did not converge", controls=(2, 1.0e-12, 10.0), adapt=adapt
    )
    assert "max_iterations=2" in failure["message"]


def test_adapt_step_underflow_stops_both_alike(request, monkeypatch):
    options = scheme_options("ADAPT_ORDRE2", adapt_v11=True, dt_max=4.0e-5, dt_min=1.9e-5)
    both_fail(request, monkeypatch, "adaptive step fell below", adapt=True, options=options)


@pytest.mark.parametrize("adapt", [False, True])
@pytest.mark.parametrize(
    ("dry", "match"),
    [("PLAN_Y", "velocity at a shock diverged"), ("BI_CERCLE", "became non-finite")],
)
def test_a_diverging_run_stops_both_alike(request, monkeypatch, dry, match, adapt):
    """A load that overflows at t = 0.0237: the dry shock's velocity
    diverges while it is in contact (its check), else the acceleration becomes
    non-finite. The same error, the same instant, the same state."""
    both_fail(request, monkeypatch, match, dry=dry, formula=("exp(30000*INST)", {}), adapt=adapt)


@pytest.mark.parametrize("adapt", [False, True])
def test_a_non_finite_start_stops_both_alike(request, monkeypatch, adapt):
    """fluid_film.start: a load infinite at t0 (1/INST)."""
    failure = both_fail(
        request, monkeypatch, "non-finite initial acceleration", formula=("1/INST", {}), adapt=adapt
    )
    assert failure["calls"] == 0


def test_the_start_gives_numbas_bits(request, monkeypatch):
    """fluid_film.start alone, its film in the boundary layer at t0: the
    acceleration, the internal variables and the film rows."""
    monkeypatch.setenv(native.SWITCH, "1")
    rng = np.random.default_rng(5)
    system = system_of(True, rng)
    shocks = build_shocks([shock_of("PLAN_Z", rng, "none", (1.0, 0.0, 0.0))], system)
    shapes, rest = shocks.local_arrays()
    linear = tuple(np.ascontiguousarray(np.diag(m)) for m in (system.mass, system.stiffness,
                                                                 system.damping))  # fmt: skip
    rows = np.array([film_row(*FILM)])
    film = FluidFilm(rows, *CONTROLS)
    weights = FF.mass_weights(shapes, shocks.flags, film)
    excitation = tabulate_excitation(N_MODES, [], 0.0, 0.01, DT / 2.0)
    # node 1 at z = 0.95e-5 (a gap of 0.5e-6) closing at 1 cm/s: a film force of ~0.9 N,
    # a layer 4.4e-6 thick
    q = np.linalg.lstsq(shapes[0, 0], np.array([0.0, 0.0, 0.95e-5]), rcond=None)[0]
    v = np.linalg.lstsq(shapes[0, 0], np.array([0.0, 0.0, 1.0e-2]), rcond=None)[0]

    def started(start) -> tuple:
        model = (shocks.flags, shocks.params, shapes, rest, shocks.polars, rows.copy(), weights)
        a, vint = np.zeros(N_MODES), shocks.initial_vint(0.0)
        work = (np.zeros(N_MODES), np.zeros(N_MODES), np.zeros(N_MODES), np.zeros(FF.N_KIN))
        returned = start(0.0, q, v, a, linear, model, excitation.bundle(), vint, work)
        return (tuple(returned), a, vint, model[5], *work)

    compiled = started(FILM_LOOPS()[2])
    assert compiled[0] == (-1, True)
    assert compiled[3][0, FF.FL_LAYER] == 1.0  # in the boundary layer from the start
    numba = reference(request, lambda: started(NUMBA_LOOPS[2]))
    assert_same(compiled, numba, "the start")
