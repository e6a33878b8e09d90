"""Every GENE scheme behind one integer code, for the time loops whose
linear operators change during a run (variable rotation speed in
:mod:`asterlite.dynamics.rotation`, implicit shocks in
:mod:`asterlite.dynamics.implicit_shocks`).

A scheme's loop (:func:`asterlite.dynamics.loop.scheme_loop`) calls its
``step`` directly; these loops serve every scheme and branch on the code
instead (numba caches them like any other function, which first-class
function arguments would prevent). Every scheme's memory is ``(rows, scalars, table)`` with the same
array types, so one compiled loop serves them all.

After the generalized K and C of the model's ``(M⁻¹, K, C, flag)`` bundle
have been rewritten, :func:`refresh_operators` makes the scheme take them
into account, as code_aster's integrators do on MAT_UPDT: NEWMARK and
TRBDF2 rebuild their effective operators, DEVOGE its M⁻¹C, M⁻¹K and H1,
H2 (intdevo_oper); the other schemes read the bundle at every
acceleration.
"""

from __future__ import annotations

from asterlite.dynamics import implicit as I
from asterlite.dynamics import scheme_adapt_ordre1 as A1
from asterlite.dynamics import scheme_adapt_ordre2 as A2
from asterlite.dynamics import scheme_devoge as DV
from asterlite.dynamics import scheme_diff_centre as DC
from asterlite.dynamics import scheme_newmark as N
from asterlite.dynamics import scheme_runge_kutta as RK
from asterlite.dynamics import scheme_trbdf2 as TR
from asterlite.dynamics.jit import njit
from asterlite.dynamics.layouts import ROWS, SCALARS
from asterlite.dynamics.schemes import (
    ADAPT_ORDRE1,
    DEVOGE,
    DIFF_CENTRE,
    NEWMARK,
    RUNGE_KUTTA,
    SCHEMES,
    TRBDF2,
)


def code(scheme: str) -> int:
    """The branch of ``scheme`` in the loops shared by every scheme
    (``Scheme.code``; the RUNGE_KUTTA pairs share one: the tableau is in
    the memory)."""
    entry = SCHEMES[scheme]
    if not entry.shared_loops:
        raise ValueError(f"{scheme} does not run in the loops shared by every scheme")
    return entry.code


def full_matrices(scheme: str, memory):
    """The memory of a scheme whose K and C will stop being diagonal: the
    schemes with a diagonal fast path (``Scheme.diagonal_fast_path``, a
    ``S_DIAGONAL`` scalar in their memory) drop it."""
    rows, scalars, table = memory[:3]
    entry = SCHEMES[scheme]
    if entry.diagonal_fast_path:
        scalars[entry.implementation().S_DIAGONAL] = 0.0
    return rows, scalars, table


@njit(cache=True)
def scheme_step(code, t, dt, index, state, memory, model):
    """The ``step`` of the scheme ``code``."""
    if code == NEWMARK:
        return N.step(t, dt, index, state, memory, model)
    if code == TRBDF2:
        return TR.step(t, dt, index, state, memory, model)
    if code == DEVOGE:
        return DV.step(t, dt, index, state, memory, model)
    if code == DIFF_CENTRE:
        return DC.step(t, dt, index, state, memory, model)
    if code == RUNGE_KUTTA:
        return RK.step(t, dt, index, state, memory, model)
    if code == ADAPT_ORDRE1:
        return A1.step(t, dt, index, state, memory, model)
    return A2.step(t, dt, index, state, memory, model)  # ADAPT_ORDRE2


@njit(cache=True)
def refresh_operators(code, memory, lin, n):
    """Make the scheme use the K and C now in ``lin`` from its next step."""
    if code == NEWMARK:
        copy_blocks(memory[ROWS], N.VECTOR_ROWS, lin, n)
        memory[SCALARS][N.S_DT_BUILT] = -1.0
    elif code == TRBDF2:
        copy_blocks(memory[ROWS], TR.VECTOR_ROWS, lin, n)
        memory[SCALARS][TR.S_DT_BUILT] = -1.0
    elif code == DEVOGE:
        devoge_operators(memory[ROWS], memory[SCALARS], lin, n)


@njit(cache=True)
def copy_blocks(rows, vector_rows, lin, n):
    """Copy K, C of the bundle into an implicit scheme's matrix blocks (its
    effective operators are rebuilt on the next step)."""
    stiffness = I.block(rows, vector_rows, I.B_STIFF, n)
    damping = I.block(rows, vector_rows, I.B_DAMP, n)
    for i in range(n):
        for j in range(n):
            stiffness[i, j] = lin.stiffness[i, j]
            damping[i, j] = lin.damping[i, j]


@njit(cache=True)
def devoge_operators(mem, smem, lin, n):
    """M⁻¹C, M⁻¹K and, once the scheme has started, H1 = 4I + dt M⁻¹C,
    H2 = 6I + dt M⁻¹C for the step it stands at (intdevo on MAT_UPDT)."""
    minv, stiffness, damping = lin.minv, lin.stiffness, lin.damping
    invm_c, invm_k, h1, h2 = DV.operators(mem, n)
    for i in range(n):
        for j in range(n):
            sc = 0.0
            sk = 0.0
            for k in range(n):
                sc += minv[i, k] * damping[k, j]
                sk += minv[i, k] * stiffness[k, j]
            invm_c[i, j] = sc
            invm_k[i, j] = sk
    DV.fill_diagonal_rows(mem, minv, n)
    if smem[DV.S_READY] == 1.0:  # a singular H1 or H2 makes the step non-finite: reported
        DV.update_implicit_operators(mem, invm_c, h1, h2, smem[DV.S_HDT], False)
