"""What became non-finite when a transient stops, and when.

The compiled loops test the state at every step (:func:`forces.all_finite`:
a magnitude of 1e300 or more, or NaN) and stop at the first step that
fails, leaving the values of that step in the state arrays (the schemes
that integrate on trial rows copy them into the state before returning).
Nothing here runs in the loop: once a run has stopped, these functions read
what it left and say which quantity went wrong (the external load of an
load of the excitation, the force of a nonlinearity, or the generalized
displacement / velocity / acceleration themselves), at which instant, and
which instant was the last one computed with a finite state.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.dynamics import contact as C
from asterlite.dynamics.forces import multiplier_at
from asterlite.dynamics.formula import run_program
from asterlite.dynamics.jit import interpreted
from asterlite.errors import field as named

# the loops' test (forces.all_finite): beyond this magnitude a value counts
# as non-finite, so that it is caught before it overflows
LIMIT = 1.0e300
SHOWN_MODES = 6  # mode numbers listed in a message


def bad(values) -> np.ndarray:
    """Mask of the entries of ``values`` that are not finite (NaN, inf or
    beyond LIMIT in magnitude)."""
    values = np.asarray(values, dtype=float)
    with np.errstate(invalid="ignore"):
        return ~(np.abs(values) < LIMIT)


def modes_text(mask: np.ndarray, unit: str = "mode") -> str:
    """'mode 3', 'modes 1, 2', 'all 20 modes' or 'modes 1, 2, ... (12 of 40)'
    (``unit``: what the entries are, e.g. 'free DOF')."""
    numbers = np.flatnonzero(mask) + 1
    if numbers.size == mask.size and mask.size > 1:
        return f"all {mask.size} {unit}s"
    if numbers.size == 1:
        return f"{unit} {numbers[0]}"
    shown = ", ".join(str(k) for k in numbers[:SHOWN_MODES])
    if numbers.size > SHOWN_MODES:
        return f"{unit}s {shown}, ... ({numbers.size} of {mask.size})"
    return f"{unit}s {shown}"


def state_text(q, v, a, unit: str = "mode", qualifier: str = "generalized ") -> str:
    """Which of the displacement, velocity and acceleration are non-finite,
    and on which modes (or DOFs); '' when all are finite."""
    parts = []
    for name, values in (("displacement", q), ("velocity", v), ("acceleration", a)):
        mask = bad(values)
        if mask.any():
            parts.append(f"{name} ({modes_text(mask, unit)})")
    if not parts:
        return ""
    joined = parts[0] if len(parts) == 1 else ", ".join(parts[:-1]) + " and " + parts[-1]
    return f"the {qualifier}{joined}"


def value_text(x: float) -> str:
    return "nan" if np.isnan(x) else f"{x:.6g}"


@dataclass
class Culprit:
    """What a failed run points at: a sentence, what is at fault (the
    load's label, or a field mark the command words as its keyword path) and
    whether the step size is the likely cause (then the advice is a smaller step)."""

    text: str
    path: str
    step_related: bool


def load_multipliers(excitation, t: float) -> np.ndarray:
    """The multiplier of each excitation row at t, evaluated as the loops
    evaluate them (formula programs, tables, sampled functions): by the
    kernels' Python while numba is not imported (a run on the C++ loops
    compiles nothing to word its error)."""

    rows = excitation.vectors.shape[0]
    values = np.zeros(rows)
    cursors = np.zeros(max(rows, 1), dtype=np.int64)
    stack = np.zeros_like(excitation.program_stack)
    for e in range(rows):
        sampled = excitation.sampled[e] if e < len(excitation.sampled) else None
        if excitation.program_codes[e, 0] > 0:
            values[e] = interpreted(run_program)(
                excitation.program_codes, excitation.program_constants, e, t, stack
            )
        elif sampled is not None:
            values[e] = float(np.asarray(sampled.function.evaluate(np.array([t])))[0])
        else:
            count, left, right = (int(x) for x in excitation.layout[e])
            values[e] = interpreted(multiplier_at)(
                excitation.abscissas, excitation.ordinates, e, count, left, right, t, cursors
            )
    return values


def load_culprit(excitation, t: float, labels) -> Culprit | None:
    """The first excitation row whose load is non-finite at t, or None."""
    try:
        multipliers = load_multipliers(excitation, t)
    except Exception:  # a function that cannot be evaluated there: say nothing of loads
        return None
    return first_bad_load(multipliers, excitation.vectors, labels, t)


def first_bad_load(multipliers, vectors, labels, t: float) -> Culprit | None:
    """The first load ``multipliers[e] * vectors[e]`` that is not finite."""
    for e, c in enumerate(multipliers):
        with np.errstate(invalid="ignore", over="ignore"):
            load = c * vectors[e]
        if bad([c]).any() or bad(load).any():
            label = labels[e] if labels and e < len(labels) else f"load {e + 1}"
            path = label.split(" ")[0]
            return Culprit(
                f"the external load of {label} is not finite (NaN, inf or beyond "
                f"{LIMIT:.0e} in magnitude) at t={t:.9g} (its multiplier is {value_text(c)})",
                path,
                False,
            )
    return None


def shock_culprit(shocks, vint) -> Culprit | None:
    """The first DIS_CHOC whose force is non-finite in ``vint``, or None."""
    for s, spec in enumerate(shocks.specs):
        if spec.relation != "DIS_CHOC":
            continue
        forces = vint[s, [C.V_FN, C.V_FT1, C.V_FT2]]
        mask = bad(forces)
        if mask.any():
            names = [n for n, m in zip(("FN", "FT1", "FT2"), mask, strict=True) if m]
            values = ", ".join(
                f"{n}={value_text(x)}" for n, x in zip(("FN", "FT1", "FT2"), forces, strict=True)
            )
            return Culprit(
                f"the force of the DIS_CHOC {spec.name.strip()!r} (node {spec.node_1}) "
                f"became non-finite ({', '.join(names)}: {values})",
                spec.source,
                True,
            )
    return None


def nonfinite_culprit(state, shocks, excitation, t_fail: float, labels=None) -> Culprit:
    """Why the state of a run became non-finite at ``t_fail``: a load
    first (the state at the start of the step was finite), then the force of
    a nonlinearity, then the generalized state itself."""
    q, v, a, f, vint = state[:5]
    found = load_culprit(excitation, t_fail, labels)
    if found is None:
        found = shock_culprit(shocks, vint)
    described = state_text(q, v, a)
    if found is None:
        if not described and bad(f).any():
            described = f"the generalized force ({modes_text(bad(f))})"
        return Culprit(
            (described or "the generalized state") + " diverged",
            named("grid.step"),
            True,
        )
    if described:
        found.text += f", and then {described}"
    return found


def when_text(t_fail: float, t_good: float, step: int, t_archived: float | None) -> str:
    """The failing instant, the last finite one and the last archived one."""
    text = (
        f"non-finite values at t={t_fail:.9g} (step {step}, from t={t_good:.9g}, the last "
        "instant computed with a finite state"
    )
    if t_archived is not None:
        text += f"; last archived instant t={t_archived:.9g}"
    return text + "; the run stops and keeps no result)"


__all__ = ["nonfinite_culprit", "when_text", "state_text", "load_multipliers", "Culprit"]
