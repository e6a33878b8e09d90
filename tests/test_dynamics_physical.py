"""PHYS transient (asterlite.dynamics.physical) and MULT_APPUI support
motion seen by the shocks of a GENE transient."""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp

from asterlite.dynamics import contact as C
from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.integrate import integrate
from asterlite.dynamics.model import LinearSystem, ShockSpec, build_shocks
from asterlite.dynamics.physical import diff_centre, newmark
from asterlite.dynamics.physical.archive import Archive, archived_steps
from asterlite.dynamics.physical.system import Load, PhysicalSystem
from asterlite.fem.constraints import eliminate
from tests.validated import scheme_options


def chain(n=3, k=1.0e4, m=2.0):
    stiffness = np.zeros((n, n))
    for i in range(n):
        stiffness[i, i] += k
        if i + 1 < n:
            stiffness[i, i] += k
            stiffness[i, i + 1] = stiffness[i + 1, i] = -k
    mass = m * np.eye(n)
    damping = 1.0e-4 * stiffness
    return mass, stiffness, damping


def physical_system(mass, stiffness, damping, force, mult=1.0):
    elimination = eliminate(sp.csr_matrix((0, mass.shape[0])), np.zeros(0), mass.shape[0])
    return PhysicalSystem(
        elimination=elimination,
        mass=sp.csr_matrix(mass),
        stiffness=sp.csr_matrix(stiffness),
        damping=sp.csr_matrix(damping),
        full_stiffness=sp.csr_matrix(stiffness),
        loads=[Load(force, mult)],
    )


def run_newmark(system, times, q, v):
    a = system.initial_acceleration(times[0], q, v)
    archive = Archive(system.n_free)
    newmark.integrate(system, times, q, v, a, np.ones(times.size, bool), archive)
    return archive.arrays()


def test_phys_newmark_equals_gene_newmark_with_all_modes():
    mass, stiffness, damping = chain()
    force = np.array([0.0, 0.0, 10.0])
    dt, n_steps = 1.0e-3, 400
    times = dt * np.arange(n_steps + 1)
    _, q_phys, _, _ = run_newmark(
        physical_system(mass, stiffness, damping, force), times, np.zeros(3), np.zeros(3)
    )
    _, phi = sla.eigh(stiffness, mass)
    system = LinearSystem(phi.T @ mass @ phi, phi.T @ stiffness @ phi, phi.T @ damping @ phi)
    shocks = build_shocks([], system)
    excitation = tabulate_excitation(3, [(phi.T @ force, 1.0)], 0.0, times[-1], dt / 2)
    gene = integrate(
        system,
        shocks,
        excitation,
        "NEWMARK",
        np.zeros(3),
        np.zeros(3),
        0.0,
        times[-1],
        dt,
        np.array([times[-1]]),
        1,
        scheme_options("NEWMARK"),
    )
    # code_aster's GENE NEWMARK takes the first step's shock forces at zero,
    # without shocks the two schemes are the same linear recurrence
    np.testing.assert_allclose(gene.depl @ phi.T, q_phys, rtol=1e-9, atol=1e-12)


def test_phys_continuation_equals_single_run():
    mass, stiffness, damping = chain()
    force = np.array([5.0, 0.0, 0.0])
    times = 1.0e-3 * np.arange(301)
    system = physical_system(mass, stiffness, damping, force)
    _, q_all, v_all, a_all = run_newmark(system, times, np.zeros(3), np.zeros(3))
    archive = Archive(3)
    mask = np.ones(151, bool)
    newmark.integrate(
        system,
        times[:151],
        np.zeros(3),
        np.zeros(3),
        system.initial_acceleration(0.0, np.zeros(3), np.zeros(3)),
        mask,
        archive,
    )
    _, q1, v1, a1 = archive.arrays()
    archive2 = Archive(3)
    newmark.integrate(system, times[150:], q1[-1], v1[-1], a1[-1], mask, archive2)
    _, q2, _, _ = archive2.arrays()
    np.testing.assert_allclose(np.vstack([q1, q2[1:]]), q_all, rtol=1e-12, atol=1e-15)


def test_phys_diff_centre_sdof_step_load_matches_analytic():
    k, m, f = 1.0e4, 1.0, 2.0
    system = physical_system(np.array([[m]]), np.array([[k]]), np.zeros((1, 1)), np.array([f]))
    system.damping = None
    dt = 1.0e-4
    times = dt * np.arange(2001)
    inverse = system.diagonal_mass_inverse()
    assert dt < diff_centre.stability_limit(system, inverse)
    a0 = system.initial_acceleration(0.0, np.zeros(1), np.zeros(1))
    archive = Archive(1)
    diff_centre.integrate(
        system, times, np.zeros(1), np.zeros(1), a0, np.ones(times.size, bool), archive, inverse
    )
    t, q, _, _ = archive.arrays()
    exact = f / k * (1.0 - np.cos(np.sqrt(k / m) * t))
    assert np.max(np.abs(q[:, 0] - exact)) < 2e-3 * f / k


def test_formula_multiplier_is_evaluated_exactly_at_each_step():
    class Formula:
        @staticmethod
        def evaluate(t):
            return np.sin(50.0 * np.asarray(t))

    load = Load(np.ones(1), Formula())
    times = np.array([0.0, 0.00123, 0.5, 0.777])
    np.testing.assert_allclose(load.coefficients(times), np.sin(50.0 * times), rtol=0, atol=0)


def test_archived_steps_union_of_period_and_instants():
    times = 0.1 * np.arange(11)
    mask = archived_steps(times, 4, [0.3, 0.7000001], 1e-6, True)
    assert list(np.flatnonzero(mask)) == [0, 3, 4, 7, 8, 10]


def test_mult_appui_support_motion_reaches_the_shock_node():
    """A mode that never moves, a far obstacle: the shock node's local
    position is its rest coordinate plus ψ d(t) (here d(t) = t)."""

    class Line:
        abscissas = np.array([0.0, 1.0])
        ordinates = np.array([0.0, 1.0])
        INTERPOL = ("LIN", "LIN")
        PROL_GAUCHE = PROL_DROITE = "LINEAIRE"

        def evaluate(self, t):
            return np.asarray(t, dtype=float)

    system = LinearSystem(np.eye(1), np.eye(1) * 100.0, np.zeros((1, 1)))
    spec = ShockSpec(
        name="S",
        obstacle_type="PLAN_Y",
        node_1="N1",
        node_2=None,
        coord_1=np.zeros(3),
        coord_2=None,
        phi_1=np.zeros((3, 1)),
        phi_2=None,
        norm_obst=np.array([1.0, 0.0, 0.0]),
        angl_vril=0.0,
        orig_obst=np.zeros(3),
        gap=1.0e3,
        k_n=1.0e6,
    )
    shocks = build_shocks([spec], system)
    excitation = tabulate_excitation(1, [(np.zeros(1), 0.0)], 0.0, 0.5, 1e-3)
    shapes = np.zeros((1, 2, 3, 1))
    shapes[0, 0, :, 0] = (0.0, 1.0, 0.0)  # unit static mode along global Y
    excitation.add_support_motion(shapes, [(Line(), Line())], 0.0, 0.5, 1e-3)
    run = integrate(
        system,
        shocks,
        excitation,
        "DIFF_CENTRE",
        np.zeros(1),
        np.zeros(1),
        0.0,
        0.5,
        1e-3,
        np.array([0.25, 0.5]),
        10**6,
        scheme_options("DIFF_CENTRE"),
    )
    local_y = run.vint[:, 0, C.V_LOC1 + 1]
    rot = shocks.rots[0]
    expected = [(rot @ np.array([0.0, t, 0.0]))[1] for t in run.times]
    np.testing.assert_allclose(local_y, expected, atol=1e-12)


def test_archive_of_known_size_never_grows_and_gives_views():
    archive = Archive(2, capacity=3)
    storage = list(archive.states)
    for k in range(3):
        archive.add(float(k), np.full(2, k), np.full(2, -k), np.zeros(2))
    assert all(a is b for a, b in zip(archive.states, storage, strict=True))  # no regrowth
    times, q, v, a = archive.arrays()
    assert np.shares_memory(q, storage[0]) and np.shares_memory(v, storage[1])
    np.testing.assert_array_equal(q[:, 0], [0.0, 1.0, 2.0])
    archive.add(3.0, np.ones(2), np.ones(2), np.ones(2))  # beyond it: grows, keeps the states
    np.testing.assert_array_equal(archive.arrays()[1][:, 1], [0.0, 1.0, 2.0, 1.0])
    velocities = archive.take(1)  # the archive lets go of them
    np.testing.assert_array_equal(velocities[:, 0], [0.0, -1.0, -2.0, 1.0])
    assert archive.states[1] is None


def test_expansion_by_blocks_equals_the_whole_product():
    from asterlite.dynamics.physical import system as physical_system

    rng = np.random.default_rng(3)
    transform = sp.random(7, 4, density=0.6, random_state=rng, format="csr")
    offset = rng.normal(size=7)

    class Elimination:
        T, u0 = transform, offset

    model = physical_system.PhysicalSystem.__new__(physical_system.PhysicalSystem)
    model.elimination = Elimination()
    reduced = rng.normal(size=(physical_system.EXPAND_ROWS * 2 + 5, 4))
    np.testing.assert_allclose(model.expand(reduced), reduced @ transform.T.toarray() + offset)
    np.testing.assert_allclose(model.expand_rate(reduced), reduced @ transform.T.toarray())


def test_an_archive_on_disk_gives_the_states_an_archive_in_memory_gives(tmp_path):
    in_memory, on_disk = Archive(2, capacity=2), Archive(2, capacity=2, disk=tmp_path)
    for archive in (in_memory, on_disk):
        for k in range(5):  # beyond the capacity: the memory archive grows
            archive.add(0.1 * k, np.full(2, k), np.full(2, -k), np.array([k, 2.0 * k]))
    for expected, stored in zip(in_memory.arrays(), on_disk.arrays(), strict=True):
        np.testing.assert_array_equal(stored, expected)
    accelerations = on_disk.take(2)
    assert isinstance(accelerations, np.memmap) and on_disk.states[2] is None
    accelerations[0, 0] = 99.0  # copy-on-write: the caller's copy only
    assert list(tmp_path.iterdir()) == []  # unnamed files: nothing left in the folder


def test_archive_goes_to_disk_past_its_share_of_the_memory_headroom(monkeypatch):
    from asterlite import watchdog
    from asterlite.dynamics.archive_store import ARCHIVE_MEMORY_SHARE
    from asterlite.dynamics.physical.archive import archive_on_disk

    assert not archive_on_disk(10**6, 10**3, 10**3)  # no limit: memory
    with watchdog.limits(None, 100.0):
        monkeypatch.setattr(watchdog, "memory_headroom", lambda: 100 * watchdog.MEGABYTE)
        share = ARCHIVE_MEMORY_SHARE * 100.0 * watchdog.MEGABYTE
        rows = int(share / (3 * 2 * 1000 * 8))
        assert not archive_on_disk(rows, 1000, 1000)
        assert archive_on_disk(rows + 1, 1000, 1000)


def test_loads_come_in_blocks_sized_in_bytes_with_the_results_of_one_block(monkeypatch):
    """The fixed-step loop asks for the loads of at most BLOCK_BYTES at a
    time (a number of instants that falls as the unknowns grow), and the
    run is the one with every instant's loads in one block, bit for bit."""
    from asterlite.dynamics.physical import stepping

    class Formula:
        @staticmethod
        def evaluate(t):
            return np.sin(40.0 * np.asarray(t))

    mass, stiffness, damping = chain()
    times = 1.0e-3 * np.arange(301)
    results, sizes = [], []
    for block_bytes in (stepping.MAX_BLOCK * 3 * 8, 7 * 3 * 8):
        monkeypatch.setattr(stepping, "BLOCK_BYTES", block_bytes)
        system = physical_system(mass, stiffness, damping, np.array([1.0, 0.0, 2.0]), Formula())
        forces = system.forces
        asked = []
        monkeypatch.setattr(system, "forces", lambda t, f=forces, a=asked: a.append(len(t)) or f(t))
        results.append(run_newmark(system, times, np.zeros(3), np.zeros(3)))
        sizes.append(asked[1:])  # the first: the initial acceleration's instant
    assert max(sizes[0]) == 300 and max(sizes[1]) == 7 and sum(sizes[1]) == 300
    assert stepping.block_instants(10**9) == 1
    for whole, blocked in zip(results[0], results[1], strict=True):
        assert np.array_equal(whole, blocked)


def test_the_reduced_stiffness_is_let_go_of_while_the_step_matrix_factorises(monkeypatch):
    """NEWMARK's steps read M and C only: the reduced K goes once the step
    matrix is built, so CHOLMOD factorises without it; it is reduced again,
    the same bits, when next asked for, and the run is the one that keeps it."""
    from cholespy import CholeskySolverD

    from asterlite.dynamics.physical.system import PhysicalSystem
    from asterlite.fem import factorization

    mass, stiffness, damping = chain(6)
    times = 1.0e-3 * np.arange(101)
    force = np.array([0.0, 1.0, 0.0, 0.0, 2.0, 0.0])
    held = []

    def recording(*args):
        held.append(system.stiffness is not None)
        return CholeskySolverD(*args)

    monkeypatch.setattr(factorization, "CholeskySolverD", recording)
    system = physical_system(mass, stiffness, damping, force)
    released = run_newmark(system, times, np.zeros(6), np.zeros(6))
    assert held == [False] and system.stiffness is None
    assert np.array_equal(system.reduced_stiffness().toarray(), stiffness)
    monkeypatch.setattr(PhysicalSystem, "release_stiffness", lambda self: None)
    system = physical_system(mass, stiffness, damping, force)
    kept = run_newmark(system, times, np.zeros(6), np.zeros(6))
    assert held == [False, True]
    for a, b in zip(released, kept, strict=True):
        assert np.array_equal(a, b)
