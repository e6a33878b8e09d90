"""The state's acceleration with the shocks in their local frames, for the
steps of DEVOGE, TRBDF2, RUNGE_KUTTA_32/54 and ADAPT_ORDRE1/2.

Those schemes' ``step`` evaluates the forces through :func:`evaluate` (or
:func:`total_force_at`, DEVOGE), always a call to one compiled function:
the force code is compiled once for every scheme, not inlined into each
step (numba's inlining copies a callee's IR at every site, and a step
with the shock forces inlined took minutes to compile). Which function
follows from the model tuple's type, when numba compiles the step:

- ``(lin, shk, exc)``: :func:`forces.evaluate` (shock kinematics in the
  global frame, rotated at each call; the relations of laws/) -- the
  scheme's general path, and the loops shared by every scheme (rotation,
  implicit shocks);
- ``(lin, shk, exc, (shapes, rest, drive))``: the model of the kernels of
  ``integrate.local_frame_bundle`` (``model.local_bundle``'s last three
  arrays): the mode shapes already rotated into each shock's frame, as
  NEWMARK's and DIFF_CENTRE's specialised loops evaluate them
  (:func:`contact.local_shock_forces` inlined in :func:`local_evaluate`,
  the external force as DIFF_CENTRE's loop computes it, formula programs
  through :func:`formula.program_value`).

So one source per step and two compiled copies of it (the scheme's loop
and its general path). The results are the same to the last bit when the
shock frames are the global one, and differ by rounding otherwise.
"""

from __future__ import annotations

from asterlite.dynamics import forces as F
from asterlite.dynamics import jit
from asterlite.dynamics.contact import local_shock_forces
from asterlite.dynamics.jit import njit
from asterlite.dynamics.layouts import LINEAR, LOADS, LOCAL, SHOCKS
from asterlite.dynamics.scheme_diff_centre import external_force_into


def takes_local_frames(model) -> bool:
    """Whether a model tuple's numba type carries the local-frame bundle."""
    from numba.core import types

    return isinstance(model, types.BaseTuple) and len(model) == 4


@njit(cache=True, inline="always")
def local_total_force(t, q, v, vint, f, model):
    """f = F_ext(t) + the shock forces at (q, v) in the shocks' local frames
    (:func:`forces.total_force`'s sums, without relations of laws/)."""
    shk, exc = model[SHOCKS], model[LOADS]
    shapes, rest, drive = model[LOCAL]
    # f[:] = 0 then forces.external_force, as DIFF_CENTRE's loop writes them
    # (formula programs through formula.program_value): the same value
    external_force_into(
        t, exc.vectors, exc.abscissas, exc.ordinates, exc.layout, exc.cursors, exc.codes,
        exc.constants, exc.stack, f,
    )  # fmt: skip
    F.local_support_motion(
        t,
        shk.rots,
        exc.drive_shapes,
        exc.drive_abscissas,
        exc.drive_ordinates,
        exc.drive_layout,
        exc.drive_cursors,
        drive,
    )
    return local_shock_forces(q, v, shk.flags, shk.params, shapes, rest, shk.polars, drive, vint, f)


@njit(cache=True, _nrt=False)
def local_total_force_at(t, q, v, vint, f, model):
    """:func:`local_total_force` as a function of its own (DEVOGE evaluates
    at two sites)."""
    return local_total_force(t, q, v, vint, f, model)


@njit(cache=True, inline="always")
def local_state_acceleration(t, q, v, out, f, residual, vint, model):
    """:func:`forces.state_acceleration` with the shock kinematics and
    forces in each shock's local frame (no relation of laws/: those runs
    take the general path)."""
    shock = local_total_force(t, q, v, vint, f, model)
    lin = model[LINEAR]
    if lin.diagonal[0] == 1:
        diagonal_acceleration(f, q, v, lin.minv, lin.stiffness, lin.damping, residual, out)
    else:
        F.acceleration(f, q, v, lin, residual, out)
    return shock


@njit(cache=True, inline="always")
def diagonal_acceleration(f, q, v, minv, stiffness, damping, residual, out):
    """:func:`forces.acceleration` for diagonal (n, n) matrices in one pass:
    the same operations in the same order (residual = f - K q - C v, then
    0 + M⁻¹ residual), so the same values to the last bit."""
    for i in range(f.shape[0]):
        x = f[i]
        x += -1.0 * stiffness[i, i] * q[i]
        x += -1.0 * damping[i, i] * v[i]
        residual[i] = x
        out[i] = 0.0 + 1.0 * minv[i, i] * x


@njit(cache=True, _nrt=False)
def local_evaluate(t, q, v, out, f, residual, vint, model):
    """:func:`local_state_acceleration` as a function of its own (one
    compiled copy for a step that evaluates at several sites)."""
    return local_state_acceleration(t, q, v, out, f, residual, vint, model)


def total_force_at(t, q, v, vint, work, f, model):
    """f = F_ext(t) + Φᵀ F_shock(q, v), ``vint`` updated; a diverging
    shock's index or -1. Through a call (not inlined). Compiled code only."""
    raise NotImplementedError("compiled code only")


def evaluate(t, q, v, out, f, residual, vint, work, model):
    """out = M⁻¹ (F_ext(t) + F_shock(q, v) - K q - C v), ``vint`` updated,
    ``f`` the total force; a diverging shock's index or -1. A call to
    :func:`local_evaluate` or :func:`forces.evaluate`. Compiled code only."""
    raise NotImplementedError("compiled code only")


def _evaluate(t, q, v, out, f, residual, vint, work, model):
    if takes_local_frames(model):

        def local(t, q, v, out, f, residual, vint, work, model):
            return local_evaluate(t, q, v, out, f, residual, vint, model)

        return local

    def general(t, q, v, out, f, residual, vint, work, model):
        return F.evaluate(t, q, v, out, f, residual, vint, work, model)

    return general


def _total_force_at(t, q, v, vint, work, f, model):
    if takes_local_frames(model):

        def local(t, q, v, vint, work, f, model):
            return local_total_force_at(t, q, v, vint, f, model)

        return local

    def general(t, q, v, vint, work, f, model):
        return F.total_force_at(t, q, v, model[SHOCKS], vint, model[LOADS], work, f)

    return general


def _register() -> None:
    """Which function :func:`evaluate` and :func:`total_force_at` call,
    told numba once it is imported (asterlite.dynamics.jit)."""
    from numba.extending import overload

    overload(evaluate, inline="always")(_evaluate)
    overload(total_force_at, inline="always")(_total_force_at)


jit.on_load(_register)


@njit(cache=True, inline="always")
def copy_vector(target, source):
    """target[:] = source for 1-D arrays: :func:`forces.copy_into` without
    its reshapes (each a call into numba's C helpers: ~5 % of a step)."""
    for i in range(source.shape[0]):
        target[i] = source[i]
