"""The step a transient can take: code_aster's step check estimate (the
shortest period, each mode stiffened by the shocks), the damped limit of
an explicit velocity update, the stability limit of a shock's damping in
explicit stages, and a round step to suggest in messages.

Everything here runs once, in numpy, on the model of :mod:`model`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from asterlite.dynamics import contact as C
from asterlite.dynamics.model import (
    COMPONENTS,
    MODAL,
    NORMAL,
    TANGENTIAL,
    LinearSystem,
    ShockSet,
    parameter_name,
)


@dataclass(frozen=True)
class StabilityLimit:
    """What sets the shortest period of code_aster's step check estimate.

    ``period`` is the shortest period (s); ``mode`` the 1-based index of
    the mode it belongs to (0 when no mode has a nonzero frequency); when a
    shock stiffens that mode, ``shock`` / ``node`` name the connection and
    the node, ``stiffness`` says which of its stiffnesses (``"normal"`` or
    ``"tangential"``), ``stiffness_value`` its value and ``component`` the global component
    (DX, DY, DZ) of the mode shape it acts on.
    """

    period: float
    mode: int = 0
    mode_frequency: float = 0.0
    shock: str | None = None
    node: str | None = None
    stiffness: str | None = None
    stiffness_value: float = 0.0
    component: str | None = None

    @property
    def frequency(self) -> float:
        """Frequency (Hz) of the shortest period (stiffened by the shock, if any)."""
        return 1.0 / self.period

    def cause(self, names: Mapping[str, str] | None = None) -> str:
        """A sentence naming what sets the period, for messages; ``names``:
        how to name the shock's stiffnesses (the caller's words for
        ``"normal"`` and ``"tangential"``; default "normal stiffness"...)."""
        if self.mode == 0:
            return "no mode with a nonzero frequency"
        if self.shock is None:
            return f"mode {self.mode} ({self.mode_frequency:.6g} Hz), no shock stiffens it more"
        node = f" (node {self.node})" if self.node else ""
        return (
            f"shock {self.shock!r}{node}: {parameter_name(self.stiffness, 'stiffness', names)}"
            f"={self.stiffness_value:.6g} N/m "
            f"on the {self.component} component of mode {self.mode} "
            f"({self.mode_frequency:.6g} Hz) raises it to {self.frequency:.6g} Hz"
        )


def stability_limit(system: LinearSystem, shocks: ShockSet) -> StabilityLimit:
    """Smallest period among the modes, each stiffened by every shock's normal
    and tangential stiffness on each of its shape components (code_aster's
    step check estimate), with what sets it (see :class:`StabilityLimit`)."""
    omega = np.sqrt(system.omega2)
    masses = np.diag(system.mass)
    eps = np.finfo(float).eps * 1.0e5
    best = StabilityLimit(period=1.0e10)
    for j, w in enumerate(omega):
        if abs(w) > eps:
            period = 2.0 * math.pi / w
            if best.mode == 0 or period < best.period:
                best = StabilityLimit(period, j + 1, w / (2.0 * math.pi))
    for s in range(shocks.count):
        k_n, k_t = shocks.params[s, C.P_KN], shocks.params[s, C.P_KT]
        nodes = 2 if shocks.flags[s, C.F_TWO_NODES] else 1
        spec = shocks.specs[s]
        for node in range(nodes):
            phi = shocks.phis[s, node]
            for j in range(system.n_modes):
                if abs(omega[j]) <= eps or abs(masses[j]) <= eps:
                    continue
                for direction, k in ((NORMAL, k_n), (TANGENTIAL, k_t)):
                    if abs(k) > eps:
                        for c in range(3):
                            period = (
                                2.0
                                * math.pi
                                / math.sqrt(omega[j] ** 2 + k * phi[c, j] ** 2 / masses[j])
                            )
                            if period < best.period:
                                best = StabilityLimit(
                                    period,
                                    j + 1,
                                    omega[j] / (2.0 * math.pi),
                                    spec.name,
                                    spec.node_1 if node == 0 else spec.node_2,
                                    direction,
                                    float(k),
                                    COMPONENTS[c],
                                )
    return best


def contact_limit(system: LinearSystem, shocks: ShockSet) -> StabilityLimit:
    """:func:`stability_limit` with only the DIS_CHOC normal stiffnesses:
    the shortest period of a mode while a shock is in contact
    (``mode == 0`` when no shock has a normal stiffness)."""
    dis_choc = [s for s in range(shocks.count) if shocks.specs[s].relation == "DIS_CHOC"]
    normal_only = ShockSet(
        [shocks.specs[s] for s in dis_choc],
        shocks.flags[dis_choc],
        shocks.params[dis_choc].copy(),
        shocks.rots[dis_choc],
        shocks.phis[dis_choc],
        shocks.polars[dis_choc],
    )
    normal_only.params[:, C.P_KT] = 0.0
    limit = stability_limit(system, normal_only)
    return limit if limit.shock is not None else StabilityLimit(period=limit.period)


def stability_period(system: LinearSystem, shocks: ShockSet) -> float:
    """Smallest period among the modes, each stiffened by every shock's normal
    and tangential stiffness on each of its shape components (code_aster's
    step check estimate); :func:`stability_limit` also says what sets it."""
    return stability_limit(system, shocks).period


@dataclass(frozen=True)
class DampedLimit:
    """The largest stable step of code_aster's explicit DIFF_CENTRE
    (v += dt a, then q += dt v) once damping is counted, and what sets it.

    For one mode of pulsation ω (stiffened as in :func:`stability_limit`)
    and damping c per unit mass (modal 2 ξ ω, plus the normal or tangential damping
    times the squared shape component over the modal mass), the update is
    stable while (ω dt)² + 2 c dt <= 4, i.e. dt <= 4 / (c + sqrt(c² + 4 ω²))
    (2/ω without damping, about 1/(ξ ω) for heavy damping). ``shock`` is
    None when the mode's own damping sets it; ``damping`` says which
    damping: ``"normal"`` or ``"tangential"`` (a shock's), ``"modal"``."""

    step: float
    mode: int = 0
    ratio: float = 0.0  # equivalent reduced damping c / (2 ω)
    shock: str | None = None
    node: str | None = None
    damping: str | None = None
    damping_value: float = 0.0
    component: str | None = None
    per_mass: float = 0.0  # the damping per unit mass c (1/s): c·dt is the stage's figure

    def cause(self, names: Mapping[str, str] | None = None) -> str:
        """A sentence naming what sets the step; ``names``: the caller's
        words for the shock's ``"normal"`` and ``"tangential"`` dampings."""
        if self.mode == 0:
            return "no mode with a nonzero frequency"
        if self.shock is None:
            return f"the modal damping of mode {self.mode} (reduced damping {self.ratio:.6g})"
        node = f" (node {self.node})" if self.node else ""
        return (
            f"shock {self.shock!r}{node}: {parameter_name(self.damping, 'damping', names)}"
            f"={self.damping_value:.6g} N.s/m on "
            f"the {self.component} component of mode {self.mode} (equivalent reduced "
            f"damping {self.ratio:.6g})"
        )


def explicit_step(omega2: float, damping: float) -> float:
    """Largest stable step of v += dt (-ω² q - c v), q += dt v."""
    return 4.0 / (damping + math.sqrt(damping * damping + 4.0 * omega2))


def damped_step_limit(system: LinearSystem, shocks: ShockSet) -> DampedLimit:
    """The damping-aware stability limit of the explicit DIFF_CENTRE update
    (see :class:`DampedLimit`): modal damping (diagonal terms) and each
    shock's normal / tangential damping with its stiffness on each shape
    component of each mode. Without damping it is 2/ω = T/π, far above
    the step check's T/20: it only binds for heavy damping (an equivalent reduced
    damping above about 3)."""
    omega2 = system.omega2
    masses = np.diag(system.mass)
    damping = np.diag(system.damping)
    eps = np.finfo(float).eps * 1.0e5
    best = DampedLimit(step=math.inf)
    usable = [
        j for j in range(system.n_modes) if math.sqrt(omega2[j]) > eps and abs(masses[j]) > eps
    ]
    for j in usable:
        c = damping[j] / masses[j]
        step = explicit_step(omega2[j], c)
        if step < best.step:
            ratio = c / (2.0 * math.sqrt(omega2[j]))
            best = DampedLimit(step, j + 1, ratio, damping=MODAL)
    for s in range(shocks.count):
        p = shocks.params[s]
        pairs = ((NORMAL, p[C.P_KN], p[C.P_CN]), (TANGENTIAL, p[C.P_KT], p[C.P_CT]))
        nodes = 2 if shocks.flags[s, C.F_TWO_NODES] else 1
        spec = shocks.specs[s]
        for node in range(nodes):
            phi = shocks.phis[s, node]
            for j in usable:
                for direction, k, c_shock in pairs:
                    if abs(c_shock) <= eps:
                        continue
                    for c in range(3):
                        share = phi[c, j] ** 2 / masses[j]
                        w2 = omega2[j] + abs(k) * share
                        c_total = damping[j] / masses[j] + c_shock * share
                        step = explicit_step(w2, c_total)
                        if step < best.step:
                            best = DampedLimit(
                                step,
                                j + 1,
                                c_total / (2.0 * math.sqrt(w2)),
                                spec.name,
                                spec.node_1 if node == 0 else spec.node_2,
                                direction,
                                float(c_shock),
                                COMPONENTS[c],
                            )
    return best


def shock_damping_limit(
    system: LinearSystem, shocks: ShockSet, radius: float, modal: bool = True
) -> DampedLimit:
    """Largest step at which the explicit stages of an adaptive scheme stay
    stable once a shock's normal or tangential damping acts (what sets it, see
    :class:`DampedLimit`), ``math.inf`` without shock damping.

    For each mode and each shape component of each damped shock, with
    ω² stiffened by the shocks' normal / tangential stiffness and c the shock damping per unit
    mass (plus the modal damping when ``modal``: RUNGE_KUTTA_* treat it
    explicitly, DEVOGE implicitly), the step is ``radius / 2`` times
    :func:`explicit_step`: ``radius / c`` for a heavy damping, where the
    stiff real eigenvalue -c must stay inside the scheme's real stability
    interval [-radius, 0] (2.51 for RUNGE_KUTTA_32, 3.31 for
    RUNGE_KUTTA_54, 2 for DEVOGE's finite-difference shock velocities).
    Error control alone does not keep the step there: entering a stiffly
    damped contact after a long free flight, an over-large step can
    amplify the stages so much that code_aster's estimate misjudges it.
    The same numbers as the kernels' cap (:func:`asterlite.dynamics.
    adapt_control.shock_damping_step`), for diagonal mass matrices."""
    omega2 = system.omega2
    masses = np.diag(system.mass)
    damping = np.diag(system.damping)
    eps = np.finfo(float).eps * 1.0e5
    best = DampedLimit(step=math.inf)
    usable = [j for j in range(system.n_modes) if abs(masses[j]) > eps]
    for s in range(shocks.count):
        p = shocks.params[s]
        pairs = ((NORMAL, p[C.P_KN], p[C.P_CN]), (TANGENTIAL, p[C.P_KT], p[C.P_CT]))
        nodes = 2 if shocks.flags[s, C.F_TWO_NODES] else 1
        spec = shocks.specs[s]
        for node in range(nodes):
            phi = shocks.phis[s, node]
            for j in usable:
                own = damping[j] / masses[j] if modal else 0.0
                for direction, k, c_shock in pairs:
                    if abs(c_shock) <= eps:
                        continue
                    for c in range(3):
                        share = phi[c, j] ** 2 / masses[j]
                        if share <= 0.0:
                            continue
                        w2 = omega2[j] + abs(k) * share
                        c_total = own + c_shock * share
                        step = 0.5 * radius * explicit_step(w2, c_total)
                        if step < best.step:
                            best = DampedLimit(
                                step,
                                j + 1,
                                c_total / (2.0 * math.sqrt(w2)),
                                spec.name,
                                spec.node_1 if node == 0 else spec.node_2,
                                direction,
                                float(c_shock),
                                COMPONENTS[c],
                                c_total,
                            )
    return best


def suggested_step(limit: float) -> float:
    """A round step at or below ``limit``: the largest 1, 2, 2.5 or 5 × 10^k
    not above it (``limit`` itself when it is not a positive finite number)."""
    if not (limit > 0.0 and math.isfinite(limit)):
        return limit
    decade = 10.0 ** math.floor(math.log10(limit))
    for mantissa in (10.0, 5.0, 2.5, 2.0, 1.0):
        step = mantissa * decade
        if step <= limit * (1.0 + 1.0e-12):
            return min(step, limit)
    return limit
