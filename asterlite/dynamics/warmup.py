"""Compile numba's kernels of the transient engine ahead of the first run
(``asterlite warmup``).

The compiled C++ loops (:mod:`asterlite.dynamics.native`, built by pip)
serve every run when they are built: then there is nothing to compile.
numba's kernels serve the runs with ``ASTERLITE_NATIVE=0`` (and an install
without a C++ compiler); ``asterlite warmup --numba`` compiles them all,
as the tests need them for their bit-for-bit comparisons.

numba compiles a kernel the first time it is called with a new combination
of argument types and keeps the machine code in its cache (``cache=True``,
in the folder :func:`asterlite.dynamics.kernel_cache_folder` names after
the sources; the folders of older sources are deleted here); later
processes load it in milliseconds. The engine keeps those combinations few
and independent of the deck: one loop per scheme whatever its features
(shocks, laws, loads, energy balance are runtime data of the same types), plus
DIFF_CENTRE's specialised loop on diagonal or full matrices, its general
path, and the loops shared by every scheme (variable rotation speed,
implicit shocks, fluid films). Running each of them once on a tiny problem
through the same constructors as DYNA_VIBRA compiles exactly what any deck
will use, so that a deck's first run does not wait for the compiler.

The kernels are compiled by ``jobs`` worker processes, in the stages of
:data:`STAGES`; each worker says on standard error what it compiles
(:func:`asterlite.progress.kernel`).
"""

from __future__ import annotations

import compileall
import importlib
import os
import re
import shutil
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from asterlite import dynamics, progress
from asterlite.dynamics import compile_estimate, native, schemes
from asterlite.dynamics import kernel as K
from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.fluid_film import (
    FILM_ADAPT_LOOP,
    FILM_LOOP,
    FluidFilm,
    film_row,
    integrate_film,
)
from asterlite.dynamics.forces import acceleration, total_force
from asterlite.dynamics.integrate import SchemeOptions, integrate, law_error, new_buffers
from asterlite.dynamics.model import LinearSystem, ShockSpec, build_shocks
from asterlite.dynamics.rotation import Rotation

# the kernels, in three stages: the force functions every loop calls (and
# the film loop, which needs none of them); each scheme's own loop; the two
# loops shared by every scheme, which call every scheme's step and so find
# them compiled (run side by side before that, both compiled all the steps:
# 15 min each on a busy machine instead of 1.5), and the film's ADAPT_ORDRE2
# loop, which needs both the film functions and the legacy ADAPT step control
SHARED = "shared force functions"
LEGACY_ADAPT = schemes.LEGACY_ADAPT_LOOP
FILM = FILM_LOOP
# the film under code_aster 10-12's ADAPT_ORDRE2: calls the film functions and
# the legacy ADAPT loop's step control, so it comes after both
FILM_ADAPT = FILM_ADAPT_LOOP
# each scheme's loops (as asterlite.dynamics.schemes describes them),
# longest compile first (compile_seconds.json) so that the two workers finish
# the stage together; ADAPT_ORDRE1, among the first, compiles the local-frame
# evaluation the later schemes call
SCHEME_LOOPS = tuple(
    sorted(
        schemes.kernels(),
        key=lambda name: -(compile_estimate(name) or 0.0),
    )
)
EVERY_SCHEME_LOOPS = (schemes.ROTATING_LOOP, schemes.IMPLICIT_LOOP)
LOOPS = SCHEME_LOOPS + EVERY_SCHEME_LOOPS
STAGES = ((SHARED, FILM), SCHEME_LOOPS, EVERY_SCHEME_LOOPS + (FILM_ADAPT,))
KERNELS = tuple(name for stage in STAGES for name in stage)
STALE_NAME = re.compile(r"kernels-[0-9a-f]{16}")  # asterlite.dynamics.kernel_cache_folder
# numba's index and code files written beside the sources' bytecode before the
# digest folders (``<module>.<function>-<line>.py311[.N].nbi|nbc``)
OLD_KERNEL_FILE = re.compile(r"[A-Za-z0-9_]+\.[A-Za-z0-9_.<>]+-\d+\.py\d+(\.\d+)?\.nb[ic]")


@dataclass
class Warmed:
    """One kernel made ready: wall seconds, how many of them compiling, and
    the CPU seconds of that compilation."""

    name: str
    seconds: float
    compile_seconds: float
    compile_cpu: float = 0.0
    error: str | None = None  # what went wrong (then the kernel is not ready)


def tiny_system(diagonal: bool = True):
    """Two modes (10 and 30 rad/s), lightly damped; coupled when not ``diagonal``."""
    mass = np.diag([1.0, 2.0])
    stiffness = np.diag([100.0, 1800.0])
    damping = np.diag([0.2, 0.6])
    if not diagonal:
        stiffness[0, 1] = stiffness[1, 0] = 10.0
        damping[0, 1] = damping[1, 0] = 0.01
    return LinearSystem(mass, stiffness, damping)


def tiny_shocks(system, obstacle: str = "PLAN_Y"):
    """One DIS_CHOC with friction, touching within a few steps."""
    shape = np.array([[0.0, 0.0], [1.0, 0.5], [0.0, 0.2]])
    spec = ShockSpec(
        name="WARMUP",
        obstacle_type=obstacle,
        node_1="N1",
        node_2=None,
        coord_1=np.zeros(3),
        coord_2=None,
        phi_1=shape,
        phi_2=None,
        norm_obst=np.array([1.0, 0.0, 0.0]),
        orig_obst=np.zeros(3),
        gap=1.0e-4,
        k_n=1.0e4,
        c_n=1.0,
        k_t=1.0e3,
        c_t=0.5,
        mu_dyn=0.2,
        mu_stat=0.3,
    )
    return build_shocks([spec], system)


def tiny_loads(system, t_end: float, dt: float):
    """A constant load and a tabulated multiplier (the loops' two kinds of rows)."""

    class Table:  # a DEFI_FONCTION with linear interpolation
        INTERPOL = ("LIN", "LIN")
        PROL_GAUCHE = PROL_DROITE = "CONSTANT"
        abscissas = np.array([0.0, t_end])
        ordinates = np.array([0.0, 1.0])

        def evaluate(self, t):
            return np.interp(t, self.abscissas, self.ordinates)

    loads = [(np.array([1.0, 0.0]), 0.5), (np.array([0.0, 1.0]), Table())]
    return tabulate_excitation(system.n_modes, loads, 0.0, t_end, dt / 2.0)


def run_loop_kernel(name: str) -> None:
    """Run the loop ``name`` (a :data:`LOOPS` entry, as
    :func:`asterlite.dynamics.integrate.loop_kernel` names them) on a tiny
    problem, with and without the energy balance where the loop offers it."""
    runs = {loop: entry.name for loop, entry in schemes.kernels().items()}
    # the shared loops run NEWMARK's step (every step compiles with them)
    runs.update({loop: "NEWMARK" for loop in EVERY_SCHEME_LOOPS})
    scheme = runs[name]
    full = schemes.FULL_MATRICES.format(schemes.SCHEMES[scheme].kernel)
    system = tiny_system(diagonal=name != full)
    shocks = tiny_shocks(system)
    t_end, dt = 0.01, 1.0e-4
    rotation = tiny_rotation(system, t_end, dt) if name == schemes.ROTATING_LOOP else None
    options = warmup_options()
    if name == LEGACY_ADAPT:  # mdadap: no energy balance, the step's upper bound given
        options = warmup_options(adapt_v11=True, dt_max=dt)
    energies = (False, True) if rotation is None and name != LEGACY_ADAPT else (False,)
    for energy in energies:
        integrate(
            system,
            shocks,
            tiny_loads(system, t_end, dt),
            scheme,
            np.zeros(2),
            np.array([0.0, 0.1]),
            0.0,
            t_end,
            dt,
            np.zeros(0),
            5,
            options,
            specialised=name != schemes.GENERAL_PATH.format(schemes.SCHEMES[scheme].kernel),
            rotation=rotation,
            energy=energy,
            implicit_shocks=name == schemes.IMPLICIT_LOOP,
            label=f"warmup {name}",
        )


# the film's iterations on the tiny problem: at most, tolerance, relaxation
FILM_CONTROLS = (10, 1.0e-2, 5.0)


def warmup_options(**given):
    """Options of every scheme for the tiny problem. The kernels are
    compiled for the types, so these are values of the warm-up's own, not
    the catalogue's defaults, which only a deck's validated call gives."""
    values = dict(
        tolerance=1.0e-4, alpha=0.0, dt_min=None, dt_max=None, beta=0.25, gamma=0.5,
        nmax_iter_pas=10, vite_min="NORM", coef_mult_pas=1.2, coef_divi_pas=1.5,
        pas_limi_rela=1.0e-5, nb_poin_periode=20, force_at_step_start=False, adapt_v11=False,
    )  # fmt: skip
    return SchemeOptions(**{**values, **given})


def tiny_rotation(system, t_end: float, dt: float):
    gyro = np.array([[0.0, 1.0], [-1.0, 0.0]])
    rotation = Rotation(system.damping, system.stiffness, gyro, np.zeros((2, 2)), 10.0, 0.0)
    rotation.tabulate(0.0, t_end, dt / 2.0)
    rotation.matrices_at(0.0)  # DYNA_VIBRA's initial C(t0), K(t0): a compiled call too
    return rotation


def warm_shared() -> None:
    """The functions every loop calls, compiled once before the loops (so
    that parallel workers do not each compile them): the forces and the
    acceleration of the initial state, the archiving, the law diagnosis."""
    system = tiny_system()
    shocks = tiny_shocks(system)
    excitation = tiny_loads(system, 0.01, 1.0e-4)
    q, v, f, a = np.zeros(2), np.zeros(2), np.zeros(2), np.zeros(2)
    vint = shocks.initial_vint(0.0)
    with progress.kernel(SHARED, compile_estimate(SHARED)):
        total_force(0.0, q, v, shocks.bundle(), vint, excitation.bundle(), np.zeros((5, 3)), f)
        acceleration(f, q, v, system.bundle(), np.zeros(2), a)
        K.archive(0, 0.0, 0, q, v, a, vint, 1.0e-4, 0, *new_buffers(1, 2, 1))
        law_error(shocks, vint, 0.0)


def warm_film(adapt: bool = False) -> None:
    """code_aster 10-14's fluid film loop (its own kernel), or with ``adapt``
    the film under code_aster 10-12's ADAPT_ORDRE2 (another one)."""
    system = tiny_system()
    shocks = tiny_shocks(system)
    film = FluidFilm(np.array([film_row(1.0, 1.0, 0.1, 1.0)]), *FILM_CONTROLS)
    options = warmup_options()
    if adapt:  # a physical film (added mass, squeeze): the adaptive step does not collapse
        film = FluidFilm(np.array([film_row(-0.01, 0.01, -1.0e-6, 0.0)]), *FILM_CONTROLS)
        options = warmup_options(adapt_v11=True, dt_max=1.0e-4)
    name = FILM_ADAPT if adapt else FILM
    with progress.kernel(name, compile_estimate(name)):
        integrate_film(
            system, shocks, film, tiny_loads(system, 0.01, 1.0e-4), np.zeros(2),
            np.array([0.0, 0.1]), 0.0, 0.01, 1.0e-4, np.zeros(0), 5, options, label="warmup",
        )  # fmt: skip


def warm_one(name: str) -> Warmed:
    """Make the kernel ``name`` ready in this process (compiled, or loaded
    from the cache)."""

    progress.enable(False)  # no progress bars for the tiny runs
    progress.listen_to_compiles()
    started, compiled = time.perf_counter(), progress.compiled_seconds()
    cpu = progress.compiled_seconds(cpu=True)
    error = None
    try:
        if name == SHARED:
            warm_shared()
        elif name in (FILM, FILM_ADAPT):
            warm_film(adapt=name == FILM_ADAPT)
        else:
            run_loop_kernel(name)
    except Exception as exc:  # reported with the others; runs needing it will fail too
        error = f"{type(exc).__name__}: {str(exc).strip().splitlines()[0] if str(exc) else ''}"
    return Warmed(
        name,
        time.perf_counter() - started,
        progress.compiled_seconds() - compiled,
        progress.compiled_seconds(cpu=True) - cpu,
        error,
    )


def warm(names=KERNELS, jobs: int | None = None) -> list[Warmed]:
    """Make every kernel of ``names`` ready, with ``jobs`` worker processes
    (default: one per core; 1: in this process)."""
    jobs = max(1, jobs or os.cpu_count() or 1)
    names = list(names)
    if jobs == 1 or len(names) == 1:
        return [warm_one(name) for name in names]
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    context = multiprocessing.get_context("spawn")  # no state inherited from this process
    done = []
    with ProcessPoolExecutor(max_workers=jobs, mp_context=context) as pool:
        for stage in STAGES:  # each stage finds the previous ones' kernels in the cache
            done += list(pool.map(warm_one, [name for name in stage if name in names]))
        done += list(pool.map(warm_one, [name for name in names if name not in KERNELS]))
    return done


def compile_bytecode() -> int:
    """Byte-compile asterlite's sources (as pip does for a regular install;
    an editable install leaves it to the first run, or to nobody where
    PYTHONDONTWRITEBYTECODE is set): every run then imports them without
    parsing them again. Returns the number of folders that failed (a
    read-only install, say: runs just parse the sources)."""

    failed = 0
    for package in ("asterlite", "asterlite.catalogues", "asterlite.commands"):
        for folder in importlib.import_module(package).__path__:
            if not compileall.compile_dir(folder, quiet=2):
                failed += 1
    return failed


def prune_stale_kernels(folder: Path, in_tree: bool) -> list[Path]:
    """Delete the kernel folders of older sources beside ``folder`` (named
    ``kernels-<digest>`` by :mod:`asterlite.dynamics`), and the kernel files
    numba kept there before those folders, and return them; only in this
    package's own ``__pycache__`` (``in_tree``): a NUMBA_CACHE_DIR the user
    gave may be shared by other installs."""
    if not in_tree:
        return []
    stale = []
    for sibling in sorted(folder.parent.iterdir()):
        if sibling != folder and sibling.is_dir() and STALE_NAME.fullmatch(sibling.name):
            shutil.rmtree(sibling, ignore_errors=True)
            stale.append(sibling)
    package = folder.parent.parent  # and its subpackages' (laws/)
    for cache in sorted(package.rglob("__pycache__")):
        if STALE_NAME.fullmatch(cache.parent.name):
            continue
        for path in sorted(cache.iterdir()):
            if path.is_file() and OLD_KERNEL_FILE.fullmatch(path.name):
                path.unlink(missing_ok=True)
                stale.append(path)
    return stale


def main(jobs: int | None = None, stream=None, verbose: bool = False) -> int:
    """``asterlite warmup``: compile what is not compiled yet, then say so
    (``verbose``: each kernel's wall and compile CPU seconds)."""
    stream = stream or sys.stderr
    started = time.perf_counter()

    folder = dynamics.kernel_cache_folder()
    prune_stale_kernels(folder, in_tree=folder.parent == dynamics.PACKAGE / "__pycache__")
    compile_bytecode()
    if native.available():
        print(
            "asterlite warmup: the compiled C++ loops serve every run: no numba kernel to "
            f"compile ({native.SWITCH}=0 runs numba's loops: asterlite warmup --numba "
            "compiles them)",
            file=stream,
        )
        return 0
    done = warm(KERNELS, jobs)
    compiled = [w for w in done if w.compile_seconds > 0.0]
    wall = time.perf_counter() - started
    for w in done if verbose else ():
        print(
            f"  {w.name}: {w.seconds:.1f} s, compiling {w.compile_seconds:.1f} s "
            f"({w.compile_cpu:.1f} s CPU)",
            file=stream,
        )
    failed = [w for w in done if w.error]
    for w in failed:
        print(f"asterlite warmup: the {w.name} kernel failed: {w.error}", file=stream)
    print(
        f"asterlite warmup: {len(done) - len(failed)} kernels ready in {wall:.1f} s "
        f"({len(compiled)} compiled now, the others already in numba's cache)",
        file=stream,
    )
    return 1 if failed else 0
