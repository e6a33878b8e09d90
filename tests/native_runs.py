"""Runs of the time loops on small shock problems, with the compiled C++
loops (asterlite.dynamics.native) or numba's, for the tests that compare them
bit for bit (tests/test_native_*.py)."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.function import Formula
from asterlite.dynamics import native
from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.integrate import integrate
from asterlite.dynamics.model import LinearSystem, ShockSpec, build_shocks
from asterlite.errors import NumericalError
from tests.numba_reference import assert_same, reference
from tests.test_dynamics_specialised import Sampled, Table  # the tests' multipliers
from tests.validated import scheme_options

N_MODES = 5
GEOMETRIES = (
    "PLAN_Y", "PLAN_Z", "CERCLE", "DISCRET", "BI_PLAN_Y", "BI_PLAN_Z", "BI_CERCLE", "BI_CERC_INT",
)  # fmt: skip


def system_of(diagonal: bool, rng) -> LinearSystem:
    omega = np.array([25.0, 70.0, 160.0, 290.0, 410.0]) * 2.0 * np.pi
    mass = np.diag(rng.uniform(0.7, 1.3, N_MODES))
    stiffness = np.diag(omega**2 * np.diag(mass))
    damping = np.diag(2.0 * 0.02 * omega * np.diag(mass))
    if not diagonal:
        coupling = 0.01 * rng.standard_normal((N_MODES, N_MODES))
        coupling = coupling + coupling.T
        stiffness = stiffness + coupling * omega[0] ** 2
        damping = damping + 1.0e-3 * coupling
    return LinearSystem(mass, stiffness, damping)


def shock_of(geometry: str, rng, friction: str, norm_obst) -> ShockSpec:
    two_nodes = geometry.startswith("BI_")
    coord_1 = np.array([0.5, 0.01, -0.02])
    coord_2 = coord_1 + (np.array([0.0, 2.0e-3, -1.0e-3]) if two_nodes else 0.0)
    dist = {"BI_PLAN_Y": 1.0e-3, "BI_PLAN_Z": 5.0e-4, "BI_CERCLE": 1.1e-3, "BI_CERC_INT": 4.0e-3}
    polar = None
    if geometry == "DISCRET":  # an octagon of radius 1e-5
        angles = np.linspace(0.0, 360.0, 9)
        polar = np.column_stack([angles, np.full(9, 1.0e-5)])
    return ShockSpec(
        name="S",
        obstacle_type=geometry,
        node_1="N1",
        node_2="N2" if two_nodes else None,
        coord_1=coord_1,
        coord_2=coord_2 if two_nodes else None,
        phi_1=rng.standard_normal((3, N_MODES)) * 0.3,
        phi_2=rng.standard_normal((3, N_MODES)) * 0.1 if two_nodes else None,
        norm_obst=np.asarray(norm_obst, dtype=float),
        angl_vril=17.0,
        orig_obst=coord_1.copy(),
        gap=1.0e-5,
        dist_1=dist.get(geometry, 0.0),
        dist_2=dist.get(geometry, 0.0) if geometry != "BI_CERC_INT" else 5.1e-3,
        k_n=2.0e5,
        c_n=5.0,
        k_t=5.0e4 if friction != "none" else 0.0,
        c_t=2.0,
        mu_dyn=0.25 if friction != "none" else 0.0,
        mu_stat=0.3 if friction != "none" else 0.0,
        unidirectional=friction == "one-way",
        polar=polar,
    )


FORMULAS = (
    ("F0*sin(W*INST)", {"F0": 2.0, "W": 190.0}),
    ("-INST**2 + 3*INST - 1/(INST+1) + cos(INST*50)", {}),
    ("(INST > 0.01) * 2.0 + (1 if INST < 0.02 else -1) + tanh(INST) + floor(100*INST)", {}),
    ("max(INST, 0.02, 0.01) + abs(INST - 0.5) + sqrt(INST) + exp(-INST) + log(1 + INST)", {}),
    ("INST % 0.003 + atan2(INST, 1) + sign(INST - 0.02) + int(300 * INST) + hypot(INST, 2)", {}),
)


def run(monkeypatch, compiled: bool, geometry="CERCLE", diagonal=True, friction="both",
        norm_obst=(1.0, 0.0, 0.0), formula=0, supports=False, t_end=0.04, pas_arch=7,
        scheme="DIFF_CENTRE", options=None, energy=False):  # fmt: skip
    """One run of ``scheme`` on a five-mode system with one shock of
    ``geometry``, three loads (a formula, a table, a sampled multiplier),
    optionally two support motions; ``compiled``: the C++ loops, else numba's."""
    monkeypatch.setenv(native.SWITCH, "1" if compiled else "0")
    rng = np.random.default_rng(11)
    system = system_of(diagonal, rng)
    spec = shock_of(geometry, rng, friction, norm_obst)
    shocks = build_shocks([spec], system)
    if geometry.startswith("BI_PLAN"):  # the planes 1e-5 apart at rest
        apart = shocks.rots[0] @ (spec.coord_2 - spec.coord_1)
        spec.dist_1 = spec.dist_2 = (abs(apart[1 if geometry == "BI_PLAN_Y" else 2]) - 1.0e-5) / 2
        shocks = build_shocks([spec], system)
    dt = 2.0e-5
    times = np.linspace(0.0, t_end, 97)
    text, extra = FORMULAS[formula]
    loads = [
        (rng.standard_normal(N_MODES), Formula(VALE=text, NOM_PARA="INST", extra=extra)),
        (rng.standard_normal(N_MODES), Table(times, np.sin(60.0 * times) ** 2)),
        (rng.standard_normal(N_MODES), Sampled()),
    ]
    excitation = tabulate_excitation(N_MODES, loads, 0.0, t_end, dt / 2.0)
    if supports:
        shapes = rng.standard_normal((1, 2, 3, 2))
        displacement = Table(times, 1.0e-5 * np.sin(90.0 * times))
        velocity = Table(times, 9.0e-4 * np.cos(90.0 * times))
        motions = [(displacement, velocity), (Sampled(), Sampled())]
        excitation.add_support_motion(shapes, motions, 0.0, t_end, dt / 2.0)
    q0 = np.full(N_MODES, 2.0e-4)
    instants = np.array([0.0123, 0.0123 + 0.3 * dt, t_end])
    return integrate(
        system, shocks, excitation, scheme, q0, np.zeros(N_MODES), 0.0, t_end, dt,
        instants, pas_arch, options or scheme_options(scheme), energy=energy,
    )  # fmt: skip


def compared(result) -> dict:
    """What the comparison of two runs reads: the run's information but its
    timings and loop name, and every archive."""
    timing = ("integration_seconds", "compile_seconds", "loop")
    fields = {"info": {k: v for k, v in result.info.items() if k not in timing}}
    for name in ("times", "order", "depl", "vite", "acce", "vint", "step_info", "energy"):
        fields[name] = getattr(result, name)
    return fields


def numba_run(request, monkeypatch, *args, runner=None, **kwargs) -> dict:
    """The fingerprint of numba's run ``runner(monkeypatch, False, *args,
    **kwargs)`` (``runner``: this module's :func:`run` unless given), for
    :func:`assert_same_bits` (tests.numba_reference)."""

    def compute():
        result = (runner or run)(monkeypatch, False, *args, **kwargs)
        assert result.info["loop"].endswith("[numba]")
        return compared(result)

    return reference(request, compute)


def assert_same_bits(compiled, numba):
    """The C++ run ``compiled`` against numba's fingerprint (:func:`numba_run`)."""
    assert compiled.info["loop"].endswith("[C++]")
    assert_same(compared(compiled), numba, "the C++ run")


def divided_by_zero(outcome) -> bool:
    """Whether (type, message) is a run stopped by a step that divided by
    zero (numba raises ZeroDivisionError, the C++ loops alike; integrate words it)."""
    kind, message = outcome
    return kind is NumericalError and "a division by zero" in message


def assert_same_failures(request, monkeypatch, run):
    """A state that becomes non-finite (DIFF_CENTRE past its stability
    limit) and NEWMARK with β = 0 (a step dividing by zero) end with the same
    worded error on the C++ loop and on numba's; ``run(monkeypatch,
    compiled, **args)``: the run of a test file."""

    def failure(compiled, **args) -> str:
        with pytest.raises(NumericalError) as raised:
            run(monkeypatch, compiled, **args)
        return str(raised.value)

    unstable = dict(scheme="DIFF_CENTRE", dt=2.0e-3, t_end=0.3)
    numba = reference(request, lambda: failure(False, **unstable))
    assert_same(failure(True, **unstable), numba, "DIFF_CENTRE past its limit")
    zero = dict(scheme="NEWMARK", options=scheme_options("NEWMARK", beta=0.0))
    numba = reference(request, lambda: failure(False, **zero))
    assert_same(failure(True, **zero), numba, "NEWMARK with BETA=0")
    assert "division by zero" in failure(True, **zero)
