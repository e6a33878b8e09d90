"""The GENE schemes of DYNA_VIBRA, each described once.

One :class:`Scheme` per scheme name asterlite integrates:
the module that implements it (``prepare(system, dt, options) -> (memory,
adaptive)`` and a compiled ``step``, which :mod:`asterlite.dynamics.loop`'s
one time loop runs; DIFF_CENTRE and NEWMARK add a ``fast_loop``), the name
of its compiled loop, and its properties as data. Every reader of a
scheme name asks this table: the command (which schemes exist, the step check,
the fluid film, the warnings), the driver
(:mod:`asterlite.dynamics.integrate`: module, loop, adaptivity), the loops
shared by every scheme (:mod:`asterlite.dynamics.dispatch`: the integer
code each branches on), the energy balance and the warmup (which loops to
compile). This module imports no numba: the catalogue reads the names.

Adding a scheme: write its module (``prepare``, ``step``),
add its :class:`Scheme` to :data:`TABLE`, and, for the loops shared by every
scheme (variable rotation speed, implicit shocks), a branch on its code in
:mod:`asterlite.dynamics.dispatch` (a scheme without one says
``shared_loops=False``); docs/architecture.md lists the places.
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass, replace
from types import ModuleType

# code_aster's step check: the step may not exceed this fraction of the shortest
# period (shock stiffness included), 1/10 for the schemes that say so
VERI_PAS_FRACTION = 20.0
VERI_PAS_FRACTION_IMPLICIT = 10.0

# how a loop of a scheme is named besides the scheme's own loop
GENERAL_PATH = "{} (general path)"
FULL_MATRICES = "{} (full matrices)"


@dataclass(frozen=True)
class Scheme:
    """One GENE scheme: where it lives and what it supports."""

    name: str  # the scheme's name in the deck
    module: str  # the dotted name of its module
    kernel: str  # the name of its compiled loop (shared by schemes of one module)
    code: int  # its branch in the loops shared by every scheme (dispatch)
    # the step check: dt <= shortest period / step_fraction (the step advice of
    # a failed run uses it too); step_checked False: the check skips it
    step_fraction: float = VERI_PAS_FRACTION
    step_checked: bool = True
    step_refused: bool = True  # above that limit: refused (else a warning only)
    # a step above the damped limit of its explicit velocity update is refused
    # (DIFF_CENTRE: about 1/(ξ ω), which the undamped period ignores)
    explicit_velocity: bool = False
    # shock forces explicit in its stages: a step above the stability limit of
    # a shock's damping refused, the adaptive step kept below it
    explicit_stages: bool = False
    adaptive: bool = False  # adapts its step when its bounds differ
    # the apparent-frequency step control of ADAPT_ORDRE1/2 (steps kept after
    # the largest number of trials)
    frequency_control: bool = False
    # its velocity lags half a step (asterlite.dynamics.energy)
    staggered_velocity: bool = False
    # film: integrates fluid films; film_legacy: only as code_aster 10-12 ran it
    film: bool = False
    film_legacy: bool = False
    # code_aster 10-12's variant (asterlite.legacy.v15 ADAPT_ORDRE2_MDADAP):
    # its module and the name of its compiled loop
    legacy_module: str | None = None
    legacy_kernel: str | None = None
    # "local_frame": its loop takes the shocks in their local frames (the
    # time loop around its step, or its module's fast_loop: NEWMARK), and a
    # general path serves the relations of laws/; "specialised": the same
    # with the fast_loop compiled for diagonal or full matrices (DIFF_CENTRE);
    # "own": one loop
    loops: str = "local_frame"
    # NEWMARK, TRBDF2: a diagonal fast path dropped when K, C stop being diagonal
    diagonal_fast_path: bool = False
    # energy an elastic impact gains per unit of ω_c·dt when the shock force
    # of the previous state enters its implicit step (EXPLICITE treatment)
    lagged_impact_gain: float | None = None
    shared_loops: bool = True  # runs in the loops shared by every scheme

    def implementation(self) -> ModuleType:
        return importlib.import_module(self.module)

    def legacy_implementation(self) -> ModuleType:
        return importlib.import_module(self.legacy_module)

    def loop_names(self) -> tuple[str, ...]:
        """The compiled loops this scheme's kernel has (the warmup compiles them)."""
        if self.loops == "specialised":
            full, general = FULL_MATRICES.format(self.kernel), GENERAL_PATH.format(self.kernel)
            return (self.kernel, full, general)
        if self.loops == "local_frame":
            return (self.kernel, GENERAL_PATH.format(self.kernel))
        return (self.kernel,)


# the integer codes of dispatch.scheme_step's branches
NEWMARK, TRBDF2, DEVOGE, DIFF_CENTRE, RUNGE_KUTTA, ADAPT_ORDRE1, ADAPT_ORDRE2 = range(7)

TABLE: tuple[Scheme, ...] = (
    Scheme(
        "DIFF_CENTRE",
        "asterlite.dynamics.scheme_diff_centre",
        "DIFF_CENTRE",
        DIFF_CENTRE,
        explicit_velocity=True,
        staggered_velocity=True,
        film=True,
        loops="specialised",
    ),
    Scheme(
        "DEVOGE",
        "asterlite.dynamics.scheme_devoge",
        "DEVOGE",
        DEVOGE,
        step_fraction=VERI_PAS_FRACTION_IMPLICIT,
        explicit_stages=True,
        adaptive=True,
    ),
    Scheme(
        "NEWMARK",
        "asterlite.dynamics.scheme_newmark",
        "NEWMARK",
        NEWMARK,
        step_fraction=VERI_PAS_FRACTION_IMPLICIT,
        step_refused=False,
        diagonal_fast_path=True,
        lagged_impact_gain=2.2,
    ),
    Scheme(
        "RUNGE_KUTTA_32",
        "asterlite.dynamics.scheme_rk32",
        "RUNGE_KUTTA",
        RUNGE_KUTTA,
        step_checked=False,
        explicit_stages=True,
        adaptive=True,
    ),
    Scheme(
        "RUNGE_KUTTA_54",
        "asterlite.dynamics.scheme_rk54",
        "RUNGE_KUTTA",
        RUNGE_KUTTA,
        step_checked=False,
        explicit_stages=True,
        adaptive=True,
    ),
    Scheme(
        "ADAPT_ORDRE1",
        "asterlite.dynamics.scheme_adapt_ordre1",
        "ADAPT_ORDRE1",
        ADAPT_ORDRE1,
        step_refused=False,
        adaptive=True,
        frequency_control=True,
        staggered_velocity=True,
    ),
    Scheme(
        "ADAPT_ORDRE2",
        "asterlite.dynamics.scheme_adapt_ordre2",
        "ADAPT_ORDRE2",
        ADAPT_ORDRE2,
        step_refused=False,
        adaptive=True,
        frequency_control=True,
        film_legacy=True,
        legacy_module="asterlite.dynamics.scheme_adapt_ordre2_v11",
        legacy_kernel="ADAPT_ORDRE2 (code_aster 10-12)",
    ),
    Scheme(
        "TRBDF2",
        "asterlite.dynamics.scheme_trbdf2",
        "TRBDF2",
        TRBDF2,
        diagonal_fast_path=True,
        lagged_impact_gain=1.1,
    ),
)

# other names of a scheme: asterlite extension for legacy decks, code_aster 10's
# EULER (mdeul1: v += dt a_n, then q += dt v) is the arithmetic code_aster 17
# runs for the GENE DIFF_CENTRE (dtmprep's first method, which dtmintg sends
# to its Euler integrator inteuler); code_aster 17 has no EULER value
ALIASES = {"EULER": "DIFF_CENTRE"}
TABLE += tuple(
    replace(next(e for e in TABLE if e.name == target), name=alias)
    for alias, target in ALIASES.items()
)

SCHEMES: dict[str, Scheme] = {scheme.name: scheme for scheme in TABLE}


def register(entry: Scheme) -> None:
    """Add a scheme to the table (an extension of asterlite, a test's toy
    scheme): the readers of :data:`TABLE` and :data:`SCHEMES` see it."""
    global TABLE
    if entry.name in SCHEMES:
        raise ValueError(f"scheme {entry.name} is already described")
    TABLE = TABLE + (entry,)
    SCHEMES[entry.name] = entry


# the loop of code_aster 10-12's ADAPT_ORDRE2 (Scheme.legacy_kernel)
LEGACY_ADAPT_LOOP = SCHEMES["ADAPT_ORDRE2"].legacy_kernel
# the loops shared by every scheme: variable rotation speed, implicit shocks
ROTATING_LOOP = "variable rotation speed"
IMPLICIT_LOOP = "implicit shocks"


def scheme(name: str) -> Scheme:
    return SCHEMES[name]


def kernels() -> dict[str, Scheme]:
    """Every compiled loop of the schemes (their variants of code_aster
    10-12 included), with the first scheme that runs it."""
    found: dict[str, Scheme] = {}
    for entry in TABLE:
        for loop in entry.loop_names() + ((entry.legacy_kernel,) if entry.legacy_kernel else ()):
            found.setdefault(loop, entry)
    return found


__all__ = ["Scheme", "SCHEMES", "TABLE", "scheme", "kernels", "register"]
