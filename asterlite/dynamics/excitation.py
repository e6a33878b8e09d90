"""The loads of a transient for the kernels: generalized load vectors, each
times a multiplier tabulated (its own linear points, sampled windows) or
compiled to a program (a formula of time), and the support motions.

Everything here runs once (or once per sampling window), in numpy.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from asterlite.dynamics.formula import STACK_DEPTH, formula_program, program_tables
from asterlite.dynamics.layouts import Loads

SAMPLES_PER_WINDOW = 1 << 16  # samples of a windowed multiplier held at a time


@dataclass
class SampledMultiplier:
    """A multiplier without linear points of its own (a formula, a function
    with logarithmic interpolation...), sampled on the regular grid
    t0 + h k, k < count, one window of samples at a time."""

    function: object
    t0: float
    h: float
    count: int

    def window(self, t: float, dt: float):
        """(first index, end index) of the window for a loop standing at
        t with step dt: from two samples before t to at least 4 dt ahead."""
        first = max(0, int(math.floor((t - self.t0) / self.h)) - 2)
        ahead = int(math.ceil((t + 4.0 * abs(dt) - self.t0) / self.h)) + 3
        end = min(self.count, max(first + SAMPLES_PER_WINDOW, ahead))
        return first, end

    def samples(self, first: int, end: int):
        times = self.t0 + self.h * np.arange(first, end)
        return times, np.asarray(self.function.evaluate(times), dtype=float)


@dataclass
class Excitation:
    """Generalized load vectors, each times a piecewise-linear multiplier.

    Row e of ``abscissas``/``ordinates`` holds the multiplier's points
    (``layout[e] = (count, left, right)``, extension codes PROL_CONSTANT or
    PROL_LINEAIRE beyond the ends): a DEFI_FONCTION with linear
    interpolation keeps its own points, so the kernels evaluate it exactly
    as code_aster does at any instant; a formula of time becomes a program
    the kernels run at each instant (``programs``, :mod:`formula`); other
    multipliers (formulas calling functions, log interpolation) are
    sampled on a regular grid, one window at a time
    (``pending[e] == 1`` while samples follow the window: the time loops
    pause with STATUS_LOADS before stepping past it and :meth:`refill`
    tabulates the next window). ``cursors`` keep each row's last interval.
    """

    vectors: np.ndarray  # (n_exc, n_modes)
    abscissas: np.ndarray  # (n_exc, n_points)
    ordinates: np.ndarray  # (n_exc, n_points)
    layout: np.ndarray  # (n_exc, 3) int: count, left, right
    # support motion seen by the shocks: static modes at each
    # shock node (n_shocks, 2, 3, n_supports) and, rows 2k / 2k+1, the
    # displacement / velocity of support k tabulated as the multipliers
    drive_shapes: np.ndarray | None = None
    drive_abscissas: np.ndarray | None = None
    drive_ordinates: np.ndarray | None = None
    drive_layout: np.ndarray | None = None
    sampled: list = field(default_factory=list)  # per row: SampledMultiplier or None
    drive_sampled: list = field(default_factory=list)
    programs: list = field(default_factory=list)  # per row: formula program or None

    def __post_init__(self) -> None:
        n_exc = self.vectors.shape[0]
        self.programs = list(self.programs) or [None] * n_exc
        self.program_codes, self.program_constants = program_tables(self.programs)
        self.program_stack = np.zeros(STACK_DEPTH)
        self.pending = np.zeros(n_exc, dtype=np.int64)
        self.cursors = np.zeros(n_exc, dtype=np.int64)
        self.sampled = list(self.sampled) or [None] * n_exc
        if self.drive_shapes is None:
            self.drive_shapes = np.zeros((0, 2, 3, 0))
            self.drive_abscissas = np.zeros((0, 1))
            self.drive_ordinates = np.zeros((0, 1))
            self.drive_layout = np.zeros((0, 3), dtype=np.int64)
        n_drive = self.drive_layout.shape[0]
        self.drive_pending = np.zeros(n_drive, dtype=np.int64)
        self.drive_cursors = np.zeros(n_drive, dtype=np.int64)
        self.drive_sampled = list(self.drive_sampled) or [None] * n_drive

    def bundle(self):
        return Loads(
            self.vectors,
            self.abscissas,
            self.ordinates,
            self.layout,
            self.drive_shapes,
            self.drive_abscissas,
            self.drive_ordinates,
            self.drive_layout,
            self.pending,
            self.cursors,
            self.drive_pending,
            self.drive_cursors,
            self.program_codes,
            self.program_constants,
            self.program_stack,
        )

    def add_support_motion(self, shapes: np.ndarray, motions, t0, t_end, h) -> None:
        """``shapes``: (n_shocks, 2, 3, n_supports); ``motions``: one
        (displacement, velocity) pair of functions per support."""
        points = [multiplier_points(f, t0, t_end, h) for pair in motions for f in pair]
        width = table_width(points)
        self.drive_shapes = np.ascontiguousarray(shapes, dtype=float)
        self.drive_abscissas = np.zeros((len(points), width))
        self.drive_ordinates = np.zeros((len(points), width))
        self.drive_layout = np.zeros((len(points), 3), dtype=np.int64)
        self.drive_pending = np.zeros(len(points), dtype=np.int64)
        self.drive_cursors = np.zeros(len(points), dtype=np.int64)
        self.drive_sampled = [None] * len(points)
        for r, row in enumerate(points):
            if isinstance(row, SampledMultiplier):
                self.drive_sampled[r] = row
            else:
                xs, ys, left, right = row
                self.drive_abscissas[r, : len(xs)] = xs
                self.drive_ordinates[r, : len(xs)] = ys
                self.drive_layout[r] = (len(xs), left, right)
        self.refill(t0, 0.0)

    def refill(self, t: float, dt: float) -> bool:
        """Tabulate the window of every sampled row that does not cover
        [t, t + 2 dt] (all of them at the first call). Returns whether the
        tables were reallocated (then bundles must be rebuilt)."""
        grown = False
        for kind in ("", "drive_"):
            sampled = getattr(self, kind + "sampled")
            for row, source in enumerate(sampled):
                if source is None:
                    continue
                xs = getattr(self, kind + "abscissas")
                layout = getattr(self, kind + "layout")
                pending = getattr(self, kind + "pending")
                count = layout[row, 0]
                starts_before = count > 0 and xs[row, 0] <= max(t, source.t0)
                reaches = count > 0 and (pending[row] == 0 or t + 2.0 * dt < xs[row, count - 1])
                if starts_before and reaches:
                    continue
                first, end = source.window(t, dt)
                times, values = source.samples(first, end)
                if len(times) > xs.shape[1]:
                    grown = True
                    for name in ("abscissas", "ordinates"):
                        old = getattr(self, kind + name)
                        new = np.zeros((old.shape[0], len(times)))
                        new[:, : old.shape[1]] = old
                        setattr(self, kind + name, new)
                    xs = getattr(self, kind + "abscissas")
                ys = getattr(self, kind + "ordinates")
                xs[row, : len(times)] = times
                ys[row, : len(times)] = values
                layout[row] = (len(times), PROL_CONSTANT, PROL_CONSTANT)
                pending[row] = 1 if end < source.count else 0
                getattr(self, kind + "cursors")[row] = 0
        return grown


def table_width(points) -> int:
    widths = [1]
    for row in points:
        if isinstance(row, SampledMultiplier):
            widths.append(min(row.count, SAMPLES_PER_WINDOW))
        else:
            widths.append(len(row[0]))
    return max(widths)


PROL_CONSTANT, PROL_LINEAIRE = 0, 1


def multiplier_points(mult, t0: float, t_end: float, h: float):
    """(abscissas, ordinates, left, right) of one multiplier, or a
    :class:`SampledMultiplier` for one sampled every ``h`` by windows."""
    if isinstance(mult, (int, float)):
        return np.array([t0]), np.array([float(mult)]), PROL_CONSTANT, PROL_CONSTANT
    xs = getattr(mult, "abscissas", None)
    ys = getattr(mult, "ordinates", None)
    linear = tuple(getattr(mult, "INTERPOL", ("LIN", "LIN"))) == ("LIN", "LIN")
    if xs is not None and ys is not None and linear and np.isrealobj(ys) and len(xs) > 0:
        mult.evaluate(np.array([t0, t_end]))  # raises for PROL_*='EXCLU' outside the points
        left = PROL_LINEAIRE if getattr(mult, "PROL_GAUCHE", "") == "LINEAIRE" else PROL_CONSTANT
        right = PROL_LINEAIRE if getattr(mult, "PROL_DROITE", "") == "LINEAIRE" else PROL_CONSTANT
        return np.asarray(xs, dtype=float), np.asarray(ys, dtype=float), left, right
    n = max(2, int(math.ceil((t_end - t0) / h)) + 2)
    return SampledMultiplier(mult, t0, h, n)


def kernel_program(mult):
    """The formula program of a multiplier without points of its own, or None."""
    if isinstance(mult, (int, float)) or getattr(mult, "abscissas", None) is not None:
        return None
    return formula_program(mult)


def tabulate_excitation(n_modes: int, loads, t0: float, t_end: float, h: float) -> Excitation:
    """``loads``: list of (vector, multiplier) with multiplier a float, a
    tabulated function (``abscissas``, ``ordinates``, ``INTERPOL``,
    ``PROL_GAUCHE``/``PROL_DROITE``) or any object with ``evaluate(t_array)``
    (a formula of time runs as a program in the kernels; anything else is
    sampled every ``h`` over [t0, t_end], one window at a time)."""
    programs = [kernel_program(mult) for _, mult in loads]
    points = [
        (np.array([t0]), np.zeros(1), PROL_CONSTANT, PROL_CONSTANT)
        if program is not None
        else multiplier_points(mult, t0, t_end, h)
        for (_, mult), program in zip(loads, programs, strict=True)
    ]
    width = table_width(points)
    vectors = np.zeros((len(loads), n_modes))
    abscissas = np.zeros((len(loads), width))
    ordinates = np.zeros((len(loads), width))
    layout = np.zeros((len(loads), 3), dtype=np.int64)
    sampled = [None] * len(loads)
    for e, ((vector, _), row) in enumerate(zip(loads, points, strict=True)):
        vectors[e] = vector
        if isinstance(row, SampledMultiplier):
            sampled[e] = row
            continue
        xs, ys, left, right = row
        abscissas[e, : len(xs)] = xs
        ordinates[e, : len(xs)] = ys
        layout[e] = (len(xs), left, right)
    excitation = Excitation(
        vectors, abscissas, ordinates, layout, sampled=sampled, programs=programs
    )
    excitation.refill(t0, 0.0)
    return excitation
