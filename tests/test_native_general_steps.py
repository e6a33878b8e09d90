"""The schemes' general paths compiled as C++ (``integrate(...,
specialised=False)``: loop.time_loop around each scheme's ``step`` on the
three bundles, the shocks in the global frame) against numba's, bit for bit:
DIFF_CENTRE's and NEWMARK's (asterlite/dynamics/native/general.cpp,
scheme_diff_centre_step.hpp, scheme_newmark_step.hpp) on every obstacle
geometry, diagonal and full matrices, each friction kind, support motions,
formula loads, NEWMARK's β, γ and forces of the step's start, archives
resumed when full, failures (the same status, time and state) and the energy
balance; then the general paths of RUNGE_KUTTA_32/54, DEVOGE, ADAPT_ORDRE1/2
and TRBDF2 (their own modules' loops on the general model), with adaptive
and fixed steps. No relation of laws/ here (tests/test_native_laws.py)."""

from __future__ import annotations

import functools

import numpy as np
import pytest

import tests.native_runs as runs
from asterlite.dynamics import contact as C
from asterlite.dynamics import integrate as I
from asterlite.dynamics import kernel as K
from asterlite.dynamics import native
from asterlite.dynamics import scheme_diff_centre as DC
from asterlite.dynamics import scheme_newmark as NM
from asterlite.dynamics import scheme_trbdf2 as T
from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.model import LinearSystem, build_shocks
from asterlite.dynamics.schemes import GENERAL_PATH, SCHEMES
from tests.native_runs import (
    FORMULAS,
    GEOMETRIES,
    N_MODES,
    divided_by_zero,
    shock_of,
    system_of,
)
from tests.numba_reference import assert_same, reference
from tests.validated import scheme_options

# numba's side is its stored fingerprints (tests.numba_reference)
pytestmark = pytest.mark.usefixtures("needs_native")

DT = 2.0e-5  # tests/native_runs.py's step
PORTED = ("DIFF_CENTRE", "NEWMARK")  # general.cpp
OTHERS = ("RUNGE_KUTTA_32", "RUNGE_KUTTA_54", "DEVOGE", "ADAPT_ORDRE1", "ADAPT_ORDRE2", "TRBDF2")
ADAPTIVE = tuple(scheme for scheme in OTHERS if SCHEMES[scheme].adaptive)
# the options of PORTED's runs: each scheme's defaults, NEWMARK's forces of the step's start
CASES = [("DIFF_CENTRE", {}), ("NEWMARK", {}), ("NEWMARK", {"force_at_step_start": True})]
CASE_IDS = ["DIFF_CENTRE", "NEWMARK", "NEWMARK-at-start"]


@pytest.fixture(autouse=True)
def general_paths(monkeypatch):
    """Every run of native_runs.run on its scheme's general path."""
    monkeypatch.setattr(runs, "integrate", functools.partial(I.integrate, specialised=False))


def general_path(scheme: str) -> str:
    return GENERAL_PATH.format(SCHEMES[scheme].kernel)


def both(request, monkeypatch, scheme, loops=None, **args):
    """The run with the C++ loop, checked bit for bit against numba's (its
    fingerprint, tests.numba_reference), with the calls of the loop
    ``loops`` recorded when given; the C++ run's result."""

    def outcome(result, kind) -> dict:
        fields = runs.compared(result)
        if loops is not None:
            fields["loop calls"] = loops.recorded_calls(kind)
        return fields

    def numbas():
        result = runs.run(monkeypatch, False, scheme=scheme, **args)
        assert result.info["loop"] == f"{general_path(scheme)} [numba]"
        return outcome(result, "numba")

    compiled = runs.run(monkeypatch, True, scheme=scheme, **args)
    assert compiled.info["loop"] == f"{general_path(scheme)} [C++]"
    assert loops is None or loops.of("C++")
    assert_same(outcome(compiled, "C++"), reference(request, numbas), "the C++ run")
    return compiled


def options(scheme, **fields):
    return scheme_options(scheme, **fields)


def impacts(result) -> bool:
    return bool((result.vint[:, 0, C.V_FN] > 0).any())


def rebuilt(result) -> bool:
    """Whether the run took steps of several lengths (NEWMARK's operators
    rebuilt for the step cut short on a requested instant, then again)."""
    return len(np.unique(result.step_info[1:, K.INFO_STEP])) > 1


class Loops:
    """Each call of a run's loop, the C++ one (native.run_loop) or numba's
    (integrate.scheme_run_loop): its kind, status and, after it, the clock,
    the counters and the state (compared as :meth:`recorded_calls`)."""

    def __init__(self, monkeypatch):
        self.calls = []
        compiled, numba = native.run_loop, I.scheme_run_loop

        def native_loop(*args):
            loop = compiled(*args)
            return None if loop is None else self.recorded(loop, "C++")

        def numba_loop(*args):
            return self.recorded(numba(*args), "numba")

        monkeypatch.setattr(native, "run_loop", native_loop)
        monkeypatch.setattr(I, "scheme_run_loop", numba_loop)

    def recorded(self, loop, kind):
        def run(clock, counters, state, *rest):
            status = loop(clock, counters, state, *rest)
            arrays = tuple(np.copy(x) for x in state)
            self.calls.append((kind, status, clock.copy(), counters.copy(), arrays))
            return status

        return run

    def of(self, kind):
        return [call[1:] for call in self.calls if call[0] == kind]

    def statuses(self, kind="C++"):
        return [status for status, *_ in self.of(kind)]

    def recorded_calls(self, kind) -> list:
        """What the comparison of the C++ calls with numba's reads: each
        call's status, clock, counters and state."""
        return [
            {"status": int(status), "clock": clock, "counters": counters, "state": list(state)}
            for status, clock, counters, state in self.of(kind)
        ]


def test_the_general_paths_are_compiled():
    assert native._loops.KERNELS["DIFF_CENTRE (general path)"] == "diff_centre_step_loop"
    assert native._newmark.KERNELS["NEWMARK (general path)"] == "newmark_step_loop"
    for scheme in PORTED + OTHERS:
        assert general_path(scheme) in native.LOOPS


def test_the_memory_positions_are_the_python_ones():
    assert DC.RESIDUAL == 0
    assert (NM.Q_INDEX2, NM.V_INDEX2, NM.RHS, NM.PIVOTS, NM.VECTOR_ROWS) == (0, 1, 2, 3, 4)
    assert (NM.S_BETA, NM.S_GAMMA, NM.S_DT_BUILT, NM.S_DIAGONAL, NM.A1) == (0, 1, 2, 3, 4)
    assert (NM.S_FORCE_AT_START, NM.N_SCALARS) == (12, 13)


# --- DIFF_CENTRE's and NEWMARK's general paths (general.cpp) ---


@pytest.mark.parametrize("scheme", PORTED)
@pytest.mark.parametrize("geometry", GEOMETRIES)
@pytest.mark.parametrize("diagonal", [True, False])
def test_every_obstacle_gives_numbas_bits(request, monkeypatch, scheme, geometry, diagonal):
    result = both(
        request,
        monkeypatch,
        scheme,
        geometry=geometry,
        diagonal=diagonal,
        norm_obst=(0.3, 0.9, 0.3),
    )
    assert impacts(result)
    assert scheme != "NEWMARK" or rebuilt(result)


@pytest.mark.parametrize("scheme", PORTED)
@pytest.mark.parametrize("friction", ["none", "one-way", "both"])
@pytest.mark.parametrize("diagonal", [True, False])
def test_every_friction_gives_numbas_bits(request, monkeypatch, scheme, friction, diagonal):
    result = both(
        request, monkeypatch, scheme, geometry="BI_CERCLE", friction=friction, diagonal=diagonal
    )
    assert impacts(result)
    if friction != "none":
        assert (result.vint[:, 0, C.V_FT1] != 0).any()


@pytest.mark.parametrize("scheme, fields", CASES, ids=CASE_IDS)
@pytest.mark.parametrize("geometry", ["CERCLE", "BI_PLAN_Z"])
@pytest.mark.parametrize("diagonal", [True, False])
def test_support_motions_give_numbas_bits(request, monkeypatch, scheme, fields, geometry, diagonal):
    result = both(
        request, monkeypatch, scheme, geometry=geometry, diagonal=diagonal, supports=True,
        pas_arch=1, options=options(scheme, **fields),
    )  # fmt: skip
    assert impacts(result)


@pytest.mark.parametrize("scheme, fields", CASES, ids=CASE_IDS)
@pytest.mark.parametrize("formula", range(len(FORMULAS)))
def test_formula_loads_give_numbas_bits(request, monkeypatch, scheme, fields, formula):
    result = both(
        request, monkeypatch, scheme, formula=formula, diagonal=formula % 2 == 0,
        options=options(scheme, **fields),
    )  # fmt: skip
    assert impacts(result)


# β, γ: the defaults' neighbours, a dissipative pair (γ > 1/2), a
# conditionally stable one (β < γ/2) and the linear acceleration method
PAIRS = [(0.3025, 0.6), (0.2, 0.5), (1.0 / 6.0, 0.5), (0.4, 0.7)]


@pytest.mark.parametrize("beta, gamma", PAIRS)
@pytest.mark.parametrize("diagonal", [True, False])
def test_newmarks_beta_and_gamma_give_numbas_bits(request, monkeypatch, beta, gamma, diagonal):
    args = dict(geometry="CERCLE", diagonal=diagonal, supports=True)
    result = both(
        request, monkeypatch, "NEWMARK", options=options("NEWMARK", beta=beta, gamma=gamma), **args
    )
    assert impacts(result) and rebuilt(result)
    default = runs.run(monkeypatch, True, scheme="NEWMARK", **args)
    assert not np.array_equal(default.depl, result.depl)  # the pair was used


@pytest.mark.parametrize("geometry", ["PLAN_Z", "DISCRET", "BI_PLAN_Y", "BI_CERC_INT"])
@pytest.mark.parametrize("diagonal", [True, False])
def test_newmarks_forces_at_the_step_start_give_numbas_bits(
    request, monkeypatch, geometry, diagonal
):
    """code_aster 13-15's NEWMARK: the forces evaluated after each update,
    for the next step."""
    args = dict(geometry=geometry, diagonal=diagonal, norm_obst=(0.3, 0.9, 0.3))
    chosen = options("NEWMARK", force_at_step_start=True)
    result = both(request, monkeypatch, "NEWMARK", options=chosen, **args)
    assert impacts(result) and rebuilt(result)
    today = runs.run(monkeypatch, True, scheme="NEWMARK", **args)
    assert not np.array_equal(today.depl, result.depl)  # the option was followed


@pytest.mark.parametrize("scheme, fields", CASES, ids=CASE_IDS)
def test_archiving_every_step_gives_numbas_bits(request, monkeypatch, scheme, fields):
    result = both(
        request, monkeypatch, scheme, geometry="BI_CERCLE", diagonal=False, pas_arch=1,
        options=options(scheme, **fields),
    )  # fmt: skip
    assert len(result.times) > 1000 and impacts(result)


@pytest.mark.parametrize("scheme, fields", CASES, ids=CASE_IDS)
@pytest.mark.parametrize("diagonal", [True, False])
def test_runs_resumed_after_a_full_archive_give_numbas_bits(
    request, monkeypatch, scheme, fields, diagonal
):
    """A small archive in memory: the loop returns each time it is full and
    resumes with the memory (NEWMARK's index-2 state, operators) as it left it."""
    loops = Loops(monkeypatch)
    chosen = options(scheme, max_archive_bytes=20000, **fields)
    result = both(
        request, monkeypatch, scheme, loops, diagonal=diagonal, supports=True, pas_arch=1,
        options=chosen,
    )  # fmt: skip
    statuses = loops.statuses()
    assert statuses.count(K.STATUS_FULL) > 2 and statuses[-1] == K.STATUS_DONE
    assert impacts(result)


def failure(monkeypatch, compiled: bool, scheme, system, spec, chosen, dt=DT, t_end=0.01,
            specialised=False):  # fmt: skip
    """The exception of a run expected to fail: (type, message); the C++
    loop of its general path (its own loop when ``specialised``) ran when
    ``compiled``."""
    monkeypatch.setenv(native.SWITCH, "1" if compiled else "0")
    served = []
    route = native.run_loop

    def run_loop(entry, loop, *rest):
        found = route(entry, loop, *rest)
        served.append((loop, found is not None))
        return found

    monkeypatch.setattr(native, "run_loop", run_loop)
    shocks = build_shocks([spec], system)
    excitation = tabulate_excitation(N_MODES, [], 0.0, t_end, 1.0e-5)
    with pytest.raises(Exception) as raised:
        I.integrate(
            system, shocks, excitation, scheme, np.full(N_MODES, 2.0e-4), np.zeros(N_MODES),
            0.0, t_end, dt, np.array([t_end]), 1, chosen, specialised=specialised,
        )  # fmt: skip
    monkeypatch.setattr(native, "run_loop", route)
    assert served == [(I.loop_kernel(scheme, system, shocks, specialised), compiled)]
    return type(raised.value), str(raised.value)


def same_failure(request, monkeypatch, *args, **kw):
    """:func:`failure` of the C++ loop, checked against numba's (its
    fingerprint, tests.numba_reference): the C++ loop's (type, message)."""
    compiled = failure(monkeypatch, True, *args, **kw)
    numba = reference(request, lambda: failure(monkeypatch, False, *args, **kw))
    assert_same(compiled, numba, "the failure")
    return compiled


def failures(request, monkeypatch, scheme, system, spec, chosen, **args):
    """The failure of the run with the C++ loop, checked against numba's
    (its fingerprint): the same exception, the same calls of the loop
    (statuses, clock, counters, state); the C++ loop's failure and calls."""
    loops = Loops(monkeypatch)

    def outcome(compiled: bool) -> dict:
        kind, message = failure(monkeypatch, compiled, scheme, system, spec, chosen, **args)
        calls = loops.recorded_calls("C++" if compiled else "numba")
        return {"type": kind, "message": message, "loop calls": calls}

    compiled = outcome(True)
    assert compiled["loop calls"]
    assert_same(compiled, reference(request, lambda: outcome(False)), "the failure")
    return (compiled["type"], compiled["message"]), loops


@pytest.mark.parametrize("scheme, fields", CASES, ids=CASE_IDS)
def test_a_diverging_shock_stops_both_alike(request, monkeypatch, scheme, fields):
    """Absurd shock stiffness: the run stops at the same step, same error."""
    rng = np.random.default_rng(3)
    system = system_of(True, rng)
    spec = shock_of("PLAN_Y", rng, "both", (1.0, 0.0, 0.0))
    spec.k_n, spec.c_n = 1.0e30, 1.0e20
    (_, message), loops = failures(
        request, monkeypatch, scheme, system, spec, options(scheme, **fields)
    )
    assert loops.statuses() == [K.STATUS_SHOCK_DIVERGED]
    assert "diverged" in message


@pytest.mark.parametrize("diagonal", [True, False])
def test_an_unstable_diff_centre_run_stops_both_alike(request, monkeypatch, diagonal):
    """A step far past DIFF_CENTRE's stability limit, the shock touched: the
    state overflows, the run stops on the same step (STATUS_NOT_FINITE)."""
    rng = np.random.default_rng(5)
    stable = system_of(diagonal, rng)
    system = LinearSystem(stable.mass, stable.stiffness * 1.0e4, stable.damping)
    spec = shock_of("CERCLE", rng, "none", (1.0, 0.0, 0.0))
    (_, message), loops = failures(
        request, monkeypatch, "DIFF_CENTRE", system, spec, options("DIFF_CENTRE")
    )
    status, _, counters, state = loops.of("C++")[-1]
    assert status == K.STATUS_NOT_FINITE and counters[K.K_STEP] > 10
    assert (state[4][:, C.V_FN] > 0).any()  # in contact when it overflowed
    assert "non-finite values" in message


@pytest.mark.parametrize("diagonal", [True, False])
@pytest.mark.parametrize("at_start", [False, True])
def test_an_unstable_newmark_run_stops_both_alike(request, monkeypatch, diagonal, at_start):
    """β near 0 far past the stability limit: q overflows, the run stops
    (STATUS_NOT_FINITE) on the same step."""
    rng = np.random.default_rng(5)
    stable = system_of(diagonal, rng)
    system = LinearSystem(stable.mass, stable.stiffness * 1.0e8, stable.damping)
    spec = shock_of("CERCLE", rng, "none", (1.0, 0.0, 0.0))
    spec.gap = 1.0  # never touched
    chosen = options("NEWMARK", beta=1.0e-4, gamma=0.5, force_at_step_start=at_start)
    (_, message), loops = failures(request, monkeypatch, "NEWMARK", system, spec, chosen)
    assert loops.statuses() == [K.STATUS_NOT_FINITE]
    assert "non-finite values" in message


DT_EXACT = 2.0**-15  # 4 / (dt * dt) and 2 / dt exact


def singular_newmark_system(diagonal: bool) -> LinearSystem:
    """K = -a1 M on the first mode (C = 0 there): K_eff's first row and
    column exactly zero for β = 1/4, γ = 1/2 at DT_EXACT."""
    stiffness = np.diag(np.linspace(1.0e6, 2.0e7, N_MODES))
    stiffness[0, 0] = -4.0 / (DT_EXACT * DT_EXACT)
    damping = np.diag(np.full(N_MODES, 10.0))
    damping[0, 0] = 0.0
    if not diagonal:
        stiffness[1, 2] = stiffness[2, 1] = 1.0e4  # full matrices: the LU path
    system = LinearSystem(np.eye(N_MODES), stiffness, damping)
    assert system.diagonal == diagonal
    return system


def test_a_singular_full_effective_stiffness_stops_both_alike(request, monkeypatch):
    """Full matrices: the LU factorisation fails on the first step."""
    rng = np.random.default_rng(3)
    spec = shock_of("PLAN_Y", rng, "both", (1.0, 0.0, 0.0))
    system = singular_newmark_system(False)
    (_, message), loops = failures(
        request, monkeypatch, "NEWMARK", system, spec, options("NEWMARK"), dt=DT_EXACT
    )
    [(status, _, counters, _)] = loops.of("C++")
    assert (status, counters[K.K_STEP]) == (K.STATUS_NOT_FINITE, 0)
    assert "non-finite values" in message


@pytest.mark.parametrize("specialised", [False, True], ids=["general", "own-loop"])
@pytest.mark.parametrize("at_start", [False, True])
def test_a_zero_diagonal_effective_stiffness_raises_as_numba_does(
    request, monkeypatch, at_start, specialised
):
    """Diagonal matrices: numba's division by the zero entry of K_eff raises
    ZeroDivisionError (error_model "python"); so does the C++ loop (the run then
    stops with the worded NumericalError), the
    general path's and NEWMARK's own."""
    rng = np.random.default_rng(3)
    spec = shock_of("PLAN_Y", rng, "both", (1.0, 0.0, 0.0))
    system = singular_newmark_system(True)
    chosen = options("NEWMARK", force_at_step_start=at_start)
    outcome = same_failure(
        request, monkeypatch, "NEWMARK", system, spec, chosen, dt=DT_EXACT,
        specialised=specialised,
    )  # fmt: skip
    assert divided_by_zero(outcome)


@pytest.mark.parametrize("specialised", [False, True], ids=["general", "own-loop"])
@pytest.mark.parametrize("diagonal", [True, False])
def test_newmarks_beta_zero_raises_as_numba_does(request, monkeypatch, diagonal, specialised):
    """BETA=0 (the catalogue allows it): numba's 1 / (β dt²) raises
    ZeroDivisionError when the operators are built; so does the C++ loop."""
    rng = np.random.default_rng(3)
    spec = shock_of("PLAN_Y", rng, "both", (1.0, 0.0, 0.0))
    system = system_of(diagonal, rng)
    chosen = options("NEWMARK", beta=0.0)
    outcome = same_failure(
        request, monkeypatch, "NEWMARK", system, spec, chosen, specialised=specialised
    )
    assert divided_by_zero(outcome)


class Arguments:
    """The arguments of a general path's C++ function, kept from its first call."""

    def __init__(self, monkeypatch, scheme):
        name = general_path(scheme)
        module = native._newmark if scheme == "NEWMARK" else native._loops
        self.function = getattr(module, module.KERNELS[name])
        self.args = None
        monkeypatch.setitem(native.LOOPS, name, native.time_loop(self))

    def __call__(self, *args):
        if self.args is None:
            self.args = list(args)
        return self.function(*args)


@pytest.mark.parametrize("scheme", PORTED)
def test_a_memory_of_another_size_is_refused(monkeypatch, scheme):
    kept = Arguments(monkeypatch, scheme)
    runs.run(monkeypatch, True, scheme=scheme, t_end=0.001)
    args = list(kept.args)
    rows, scalars = 10, 11  # clock, counters, instants, the state (7), then the memory
    assert args[rows].shape[1] == N_MODES
    args[rows] = np.zeros((args[rows].shape[0], N_MODES + 1))
    with pytest.raises(ValueError, match="inconsistent arrays: memory rows"):
        kept.function(*args)
    if scheme == "NEWMARK":
        args[rows] = np.zeros((args[rows].shape[0] - 1, N_MODES))
        with pytest.raises(ValueError, match="inconsistent arrays: memory rows"):
            kept.function(*args)
        args[rows] = np.zeros((NM.VECTOR_ROWS + 7 * N_MODES, N_MODES))  # implicit.new_rows
        args[scalars] = np.zeros(NM.N_SCALARS - 1)
        with pytest.raises(ValueError, match="inconsistent arrays: memory scalars"):
            kept.function(*args)
    else:
        args[rows] = np.zeros((0, N_MODES))
        with pytest.raises(ValueError, match="inconsistent arrays: memory rows"):
            kept.function(*args)


# --- the energy balance on every general path ---


@pytest.mark.parametrize("scheme", PORTED + OTHERS)
@pytest.mark.parametrize("geometry, diagonal", [("CERCLE", True), ("BI_PLAN_Y", False)])
def test_the_energy_balance_gives_numbas_bits(request, monkeypatch, scheme, geometry, diagonal):
    """ENERGIE: the balance's rows bit for bit, with impacts, friction and
    support motions in the powers."""
    args = dict(geometry=geometry, diagonal=diagonal, supports=True, t_end=0.02)
    result = both(request, monkeypatch, scheme, energy=True, **args)
    assert result.energy is not None and len(result.energy) == len(result.times)
    assert impacts(result)


# --- the other schemes' general paths (their modules' C++ loops) ---


def fixed(scheme, **fields):
    """A fixed step: equal step bounds (integrate.loop_adapts)."""
    return options(scheme, dt_min=DT, dt_max=DT, **fields)


def assert_steps_as_asked(result, scheme, adaptive: bool):
    assert result.info["adaptive"] == (adaptive and SCHEMES[scheme].adaptive)
    if not result.info["adaptive"]:  # the step of the grid, cut short on the requested instants
        assert result.info["max_step"] == DT


@pytest.mark.parametrize("scheme", OTHERS)
@pytest.mark.parametrize("geometry", GEOMETRIES)
@pytest.mark.parametrize("diagonal", [True, False])
def test_every_obstacle_on_the_other_general_paths(
    request, monkeypatch, scheme, geometry, diagonal
):
    result = both(
        request,
        monkeypatch,
        scheme,
        geometry=geometry,
        diagonal=diagonal,
        norm_obst=(0.3, 0.9, 0.3),
    )
    assert impacts(result)
    assert_steps_as_asked(result, scheme, True)


@pytest.mark.parametrize("scheme", ADAPTIVE)
@pytest.mark.parametrize("geometry", ["CERCLE", "DISCRET", "BI_PLAN_Y", "BI_CERC_INT"])
@pytest.mark.parametrize("diagonal", [True, False])
def test_fixed_steps_on_the_other_general_paths(request, monkeypatch, scheme, geometry, diagonal):
    result = both(
        request, monkeypatch, scheme, geometry=geometry, diagonal=diagonal,
        norm_obst=(0.3, 0.9, 0.3), options=fixed(scheme),
    )  # fmt: skip
    assert impacts(result)
    assert_steps_as_asked(result, scheme, False)


@pytest.mark.parametrize("scheme", ADAPTIVE)
def test_rejected_steps_on_the_other_general_paths(request, monkeypatch, scheme):
    """A tight tolerance: the adaptive schemes reject steps alike."""
    chosen = options(scheme, tolerance=1.0e-6)
    result = both(
        request, monkeypatch, scheme, geometry="BI_CERCLE", diagonal=False, options=chosen
    )
    assert impacts(result)
    assert result.info["adaptive"] and result.info["rejected_steps"] > 0


@pytest.mark.parametrize("scheme", OTHERS)
@pytest.mark.parametrize("friction", ["none", "one-way", "both"])
def test_every_friction_on_the_other_general_paths(request, monkeypatch, scheme, friction):
    result = both(
        request, monkeypatch, scheme, geometry="BI_CERCLE", friction=friction, diagonal=False
    )
    assert impacts(result)
    if friction != "none":
        assert (result.vint[:, 0, C.V_FT1] != 0).any()


@pytest.mark.parametrize("scheme", OTHERS)
@pytest.mark.parametrize("formula", range(len(FORMULAS)))
def test_formula_loads_on_the_other_general_paths(request, monkeypatch, scheme, formula):
    result = both(request, monkeypatch, scheme, formula=formula, diagonal=formula % 2 == 1)
    assert impacts(result)


@pytest.mark.parametrize("scheme", OTHERS)
@pytest.mark.parametrize("geometry", ["CERCLE", "BI_PLAN_Z"])
@pytest.mark.parametrize("adaptive", [True, False])
def test_support_motions_on_the_other_general_paths(
    request, monkeypatch, scheme, geometry, adaptive
):
    chosen = options(scheme) if adaptive else fixed(scheme)
    result = both(
        request, monkeypatch, scheme, geometry=geometry, diagonal=geometry == "CERCLE",
        supports=True, pas_arch=1, options=chosen,
    )  # fmt: skip
    assert impacts(result)
    assert_steps_as_asked(result, scheme, adaptive)


@pytest.mark.parametrize("scheme", OTHERS)
@pytest.mark.parametrize("adaptive", [True, False])
def test_full_archives_on_the_other_general_paths(request, monkeypatch, scheme, adaptive):
    loops = Loops(monkeypatch)
    chosen = options(scheme, max_archive_bytes=20000)
    if not adaptive:
        chosen = fixed(scheme, max_archive_bytes=20000)
    result = both(
        request, monkeypatch, scheme, loops, diagonal=False, supports=True, pas_arch=1,
        options=chosen,
    )  # fmt: skip
    statuses = loops.statuses()
    assert statuses.count(K.STATUS_FULL) > 2 and statuses[-1] == K.STATUS_DONE
    assert impacts(result)
    assert_steps_as_asked(result, scheme, adaptive)


@pytest.mark.parametrize("scheme", OTHERS)
def test_a_diverging_shock_on_the_other_general_paths(request, monkeypatch, scheme):
    """Absurd shock stiffness and damping, a fixed step: the same failure
    (status, time, state) on both."""
    rng = np.random.default_rng(3)
    system = system_of(True, rng)
    spec = shock_of("PLAN_Y", rng, "both", (1.0, 0.0, 0.0))
    spec.k_n, spec.c_n = 1.0e30, 1.0e20
    (_, message), loops = failures(request, monkeypatch, scheme, system, spec, fixed(scheme))
    [status] = loops.statuses()  # RUNGE_KUTTA_54's stages overflow before the test
    assert status in (K.STATUS_SHOCK_DIVERGED, K.STATUS_NOT_FINITE)
    assert ("diverged" if status == K.STATUS_SHOCK_DIVERGED else "non-finite") in message


@pytest.mark.parametrize("operator", ["H0", "H1", "H2"])
def test_a_zero_diagonal_devoge_operator_raises_as_numba_does(request, monkeypatch, operator):
    """DEVOGE, diagonal matrices, C' making H0 = 4I - dt C', H1 = 4I + dt C'
    or H2 = 6I + dt C' zero on the first mode: ZeroDivisionError on both."""
    damping = np.diag(np.full(N_MODES, 10.0))
    damping[0, 0] = {"H0": 4.0, "H1": -4.0, "H2": -6.0}[operator] / DT_EXACT
    stiffness = np.diag(np.linspace(1.0e6, 2.0e7, N_MODES))
    system = LinearSystem(np.eye(N_MODES), stiffness, damping)
    rng = np.random.default_rng(3)
    spec = shock_of("PLAN_Y", rng, "both", (1.0, 0.0, 0.0))
    chosen = options("DEVOGE", dt_min=DT_EXACT, dt_max=DT_EXACT)
    outcome = same_failure(request, monkeypatch, "DEVOGE", system, spec, chosen, dt=DT_EXACT)
    assert divided_by_zero(outcome)


@pytest.mark.parametrize("specialised", [False, True], ids=["general", "own-loop"])
def test_a_zero_diagonal_trbdf2_effective_stiffness_raises_as_numba_does(
    request, monkeypatch, specialised
):
    """TRBDF2, diagonal matrices, K_eff = a1 M + K + a2 C zero on the first
    mode: numba's I.solve_effective raises ZeroDivisionError; so does the
    C++ loop, the general path's and TRBDF2's own."""
    h = T.STAGE_FRACTION * DT
    stiffness = np.diag(np.linspace(1.0e6, 2.0e7, N_MODES))
    stiffness[0, 0] = -4.0 / (h * h)
    system = LinearSystem(np.eye(N_MODES), stiffness, np.zeros((N_MODES, N_MODES)))
    assert system.diagonal
    rng = np.random.default_rng(3)
    spec = shock_of("PLAN_Y", rng, "both", (1.0, 0.0, 0.0))
    chosen = options("TRBDF2")
    outcome = same_failure(
        request, monkeypatch, "TRBDF2", system, spec, chosen, specialised=specialised
    )
    assert divided_by_zero(outcome)
