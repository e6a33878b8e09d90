"""FLAMBAGE: shock on a support that buckles (plastic crushing with memory).

code_aster 17 describes the support by three functions of the crushing
(DX, the penetration into the obstacle): the force threshold Fc, the
stiffness K and the damping C. With d_N < 0 the normal distance
(penetration -d_N), v_N the normal velocity and u_max the largest
penetration reached so far, the force is elastic from the plastic
crushing ``defpla`` on:

    F = K (-d_N - defpla) - C v_N,   K, C, Fc read at u_max

capped by Fc; when the cap is reached the crushing grows so that the force
stays on the threshold (defpla = -d_N - Fc/K). When the damping is left out
of the buckling criterion the
damping is added after the cap (it is not bounded by Fc). No force while
the penetration is below the crushing (a gap has opened) or out of contact.

The functions are evaluated at the maximum penetration, so unloading is
linear with the stiffness reached (a crushed support does not recover):
code_aster's buckling curves (e.g. those built from the historical scalar
parameters, see ``legacy_buckling_curves``) are designed for that reading.

Decks of code_aster 15 give the support by scalars instead
(``ScalarFlambageParameters``: stiffness K, damping, critical force Fcr,
post-buckling force Fp, drop e, plateau width l, post-buckling crushings
u_i, stiffnesses K_i and dampings, buckling damping; see
asterlite.legacy.v15), which code_aster 15 ran with its own scalar law
(``scalar_buckling_force``): elastic up to Fcr, a plateau up to the
penetration Fcr/K + l, a linear drop to Fp over e, then branches at Fp
whose crushing and damping are interpolated between the crushings u_i
(reached at the penetrations u_i + Fp/K_i); unloading and reloading below the
largest penetration are elastic with the stiffness and crushing reached.
code_aster 17's functions of the crushing do not give the same history.

Internal variables (code_aster's 12-value layout, VINT1..VINT12): the
normal force, local coordinates of both nodes, the normal velocity, the
crushing (VINT9, POST_DYNA_MODA_T's ECRAS_RESI), then the stiffness, the
maximum penetration and the damping in use.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.dynamics.jit import interpreted, njit
from asterlite.dynamics.laws.tabulated import Curve, LawError, function_table, unpack, value
from asterlite.errors import field as named

CRUSHINGS, POST_STIFFNESSES = named("crushings"), named("post_stiffnesses")

# Parameters: flags, then where each packed function starts in the same array
P_DAMPING_IN_CRITERION = 0  # 1: the damping counts in the buckling criterion, 0: not
P_AT_FX, P_AT_RIGI, P_AT_AMOR = 1, 2, 3
P_SCALAR = 4  # 1: code_aster 15's scalar law, its parameters from S_KNORM on
HEADER = 5
# the scalar law: stiffness, damping, critical and post-buckling forces, drop
# width, penetration at the end of the plateau, number of post-buckling points,
# then the crushings, the total penetrations and the dampings of those points
S_KNORM, S_CNORM, S_FLIM, S_FPOST, S_ENFO, S_DEFT0, S_COUNT = range(HEADER, HEADER + 7)
S_POINTS = HEADER + 7

# Internal variables
V_FN = 0
V_LOC1 = 1  # local coordinates of node 1 (3)
V_LOC2 = 4  # local coordinates of node 2 (3)
V_VN = 7
V_DEFPLA = 8  # plastic crushing (VINT9)
V_RIGI = 9  # stiffness in use
V_DEFMAX = 10  # maximum penetration reached
V_AMOR = 11  # damping in use
N_VINT = 12
VINT_NAMES = (
    "FN", "DXLOC_1", "DYLOC_1", "DZLOC_1", "DXLOC_2", "DYLOC_2", "DZLOC_2",
    "VN", "ECRAS", "RIGI", "ENFO_MAX", "AMOR",
)  # fmt: skip


@njit(cache=True)
def buckling_force(params, gap, vn, state_in, state_out):
    """Normal force magnitude F >= 0 (applied along the normal on node 1,
    opposite on node 2); updates the memory from ``state_in`` into
    ``state_out`` (the same array is allowed). NaN when a curve is
    evaluated outside its EXCLU domain."""
    if params[P_SCALAR] == 1.0:
        return scalar_buckling_force(params, gap, vn, state_in, state_out)
    defpla = state_in[V_DEFPLA]
    umax = state_in[V_DEFMAX]
    rigi = state_in[V_RIGI]
    amor = state_in[V_AMOR]
    fn = 0.0
    if gap <= 0.0:
        if -gap > umax:
            umax = -gap
        crit = value(params, int(params[P_AT_FX]), umax)
        rigi = value(params, int(params[P_AT_RIGI]), umax)
        amor = value(params, int(params[P_AT_AMOR]), umax)
        included = params[P_DAMPING_IN_CRITERION] != 0.0
        fn = -rigi * (gap + defpla) - (amor * vn if included else 0.0)
        if fn >= crit:
            fn = crit
            defpla = -gap - crit / rigi  # crushing follows, the force stays on the threshold
        if defpla < 0.0:
            defpla = 0.0
        if not included:
            fn -= amor * vn
        if fn < 0.0 or -gap < defpla:
            fn = 0.0  # the support only pushes, and not across the gap its crushing opened
    else:
        vn = 0.0
    state_out[V_FN] = fn
    state_out[V_VN] = vn
    state_out[V_DEFPLA] = defpla
    state_out[V_DEFMAX] = umax
    state_out[V_RIGI] = rigi
    state_out[V_AMOR] = amor
    return fn


@njit(cache=True)
def scalar_buckling_force(params, gap, vn, state_in, state_out):
    """buckling_force with code_aster 15's scalar law (its mdflam, step for step)."""
    included = params[P_DAMPING_IN_CRITERION] != 0.0
    defpla = state_in[V_DEFPLA]
    rigi = state_in[V_RIGI]
    umax = state_in[V_DEFMAX]
    amor = state_in[V_AMOR]
    fn = 0.0
    if gap <= 0.0:
        u = -gap
        fn, defpla, rigi, amor = _scalar_law(params, u, vn, included, defpla, rigi, umax, amor)
        if defpla < 0.0:
            defpla = 0.0
        if u > umax:
            umax = u
        if not included:
            fn -= amor * vn
            if fn < 0.0 or u < defpla:
                fn = 0.0
    else:
        vn = 0.0
    state_out[V_FN] = fn
    state_out[V_VN] = vn
    state_out[V_DEFPLA] = defpla
    state_out[V_DEFMAX] = umax
    state_out[V_RIGI] = rigi
    state_out[V_AMOR] = amor
    return fn


@njit(cache=True)
def _scalar_law(params, u, vn, included, defpla, rigi, umax, amor):
    """(force, crushing, stiffness, damping) at the penetration u >= 0."""
    knorm, cnorm = params[S_KNORM], params[S_CNORM]
    flim, fpost, enfo, deft0 = params[S_FLIM], params[S_FPOST], params[S_ENFO], params[S_DEFT0]
    damping = amor if included else 0.0
    fn = 0.0
    if defpla <= 0.0:  # not buckled yet
        c0 = cnorm if included else 0.0
        if u < (flim + c0 * vn) / knorm:
            fn = max(knorm * u - c0 * vn, 0.0)
        else:  # buckling starts
            fn, defpla = flim, 1.0e-20
        return fn, defpla, knorm, cnorm
    if u < defpla:  # inside the gap the crushing opened
        return 0.0, defpla, rigi, amor
    n = int(params[S_COUNT])
    crush = params[S_POINTS : S_POINTS + n]
    total = params[S_POINTS + n : S_POINTS + 2 * n]
    damps = params[S_POINTS + 2 * n : S_POINTS + 3 * n]
    if vn > 0.0 or u <= umax:  # unloading, or reloading below the largest penetration
        fn = -rigi * (defpla - u) - damping * vn
        if included:
            ramp = flim + ((fpost - flim) / enfo) * (u - deft0)
            if u < deft0 and fn >= flim:
                fn = flim
            elif fn >= ramp and u < total[0]:
                fn = ramp
            elif fn >= fpost and u >= total[0]:
                fn = fpost
            fn = max(fn, 0.0)
        return fn, defpla, rigi, amor
    if u < deft0:  # on the plateau: the crushing follows
        fn = flim
        defpla = u - flim / rigi
    if deft0 <= u < total[0]:  # the drop to the post-buckling force
        fn = flim + ((fpost - flim) / enfo) * (u - deft0)
        rigi = fn / (u - defpla)
        defpla = crush[0]
        amor = cnorm + ((damps[0] - cnorm) / enfo) * (u - deft0)
    if u >= total[0] and n < 2:
        fn = fpost
        rigi = fpost / (total[0] - crush[0])
        defpla = u - fpost / rigi
        amor = damps[0]
    else:
        for j in range(n - 1):
            if total[j] <= u < total[j + 1]:
                alpha = (u - total[j]) / (total[j + 1] - total[j])
                fn = fpost
                defpla = crush[j] + alpha * (crush[j + 1] - crush[j])
                amor = damps[j] + alpha * (damps[j + 1] - damps[j])
                rigi = fpost / (u - defpla)
        if u > total[n - 1]:  # beyond the last point: its branch continued
            fn = fpost
            rigi = fpost / (total[n - 1] - crush[n - 1])
            defpla = u - fpost / rigi
            amor = damps[n - 1]
    return fn, defpla, rigi, amor


@dataclass(frozen=True)
class ScalarFlambageParameters:
    """code_aster 15's scalar buckling law: the elastic stiffness and its
    damping, the critical and post-buckling forces, the width of the drop
    between them and of the plateau before it, the post-buckling branches
    (crushings, stiffnesses, dampings; empty when not given), the damping
    right after buckling (None: the elastic one) and whether the damping
    force counts in the buckling criterion."""

    stiffness: float
    damping: float
    critical_force: float
    post_buckling_force: float
    drop: float
    plateau: float
    crushings: tuple[float, ...]
    post_stiffnesses: tuple[float, ...]
    post_dampings: tuple[float, ...]
    buckling_damping: float | None
    damping_in_criterion: bool


def prepare_scalar_flambage(data: ScalarFlambageParameters) -> np.ndarray:
    """Parameter array of code_aster 15's scalar law (the checks of its
    dtmprep_noli_flam)."""
    knorm = float(data.stiffness)
    if knorm <= 0.0:
        raise LawError(f"FLAMBAGE/{named('stiffness')}: the stiffness must be > 0")
    cnorm = float(data.damping)
    flim, fpost = float(data.critical_force), float(data.post_buckling_force)
    enfo = float(data.drop)
    plateau = float(data.plateau)
    deft0 = flim / knorm + plateau
    crush = np.array([plateau, *_reals(data.crushings)])
    stiff = np.array([fpost / (deft0 + enfo - plateau), *_reals(data.post_stiffnesses)])
    damped = _reals(data.post_dampings)
    if np.any(np.diff(crush) < 0.0):
        raise LawError(f"FLAMBAGE/{CRUSHINGS}: the crushings must increase")
    if stiff.size != crush.size or (damped and len(damped) != crush.size - 1):
        raise LawError(
            f"FLAMBAGE: {CRUSHINGS}, {POST_STIFFNESSES} and {named('post_dampings')}: same length"
        )
    if np.any(crush < 0.0):
        raise LawError(f"FLAMBAGE/{CRUSHINGS}: the crushings must be >= 0")
    total = crush + fpost / stiff
    if np.any(np.diff(total) < 0.0):
        raise LawError(
            f"FLAMBAGE: the penetrations {CRUSHINGS} + {named('post_buckling_force')}/"
            f"{POST_STIFFNESSES} must increase"
        )
    first = float(data.buckling_damping) if data.buckling_damping is not None else cnorm
    damps = np.array([first, *(damped or [first] * (crush.size - 1))])
    header = np.zeros(HEADER)
    header[P_DAMPING_IN_CRITERION] = 1.0 if data.damping_in_criterion else 0.0
    header[P_SCALAR] = 1.0
    scalars = [knorm, cnorm, flim, fpost, enfo, deft0, float(crush.size)]
    return np.concatenate([header, scalars, crush, total, damps])


def _reals(values) -> list:
    return [float(v) for v in values]


@dataclass(frozen=True)
class FlambageParameters:
    """The buckling law as three functions of the crushing: the force
    threshold, the stiffness and the damping; and whether the damping force
    counts in the buckling criterion."""

    force_threshold: object
    stiffness: object
    damping: object
    damping_in_criterion: bool


def prepare_flambage(data: FlambageParameters, sample=None) -> np.ndarray:
    """Parameter array of the buckling law (functions checked as code_aster does)."""
    blocks = []
    for label, function in (
        (f"FLAMBAGE/{named('force_threshold')}", data.force_threshold),
        (f"FLAMBAGE/{named('stiffness')}", data.stiffness),
        (f"FLAMBAGE/{named('damping')}", data.damping),
    ):
        if function is None:
            raise LawError(f"{label}: a function of the crushing DX is missing")
        blocks.append(function_table(function, label, sample=sample))
    x, y, _, _ = unpack(blocks[1])
    if np.any(y <= 0.0):
        raise LawError(f"FLAMBAGE/{named('stiffness')}: the stiffness must be > 0 everywhere")
    x, y, _, _ = unpack(blocks[0])
    if np.any(y < 0.0):
        raise LawError(f"FLAMBAGE/{named('force_threshold')}: the force threshold must be >= 0")
    header = np.zeros(HEADER)
    header[P_DAMPING_IN_CRITERION] = 1.0 if data.damping_in_criterion else 0.0
    at = HEADER
    for slot, block in zip((P_AT_FX, P_AT_RIGI, P_AT_AMOR), blocks, strict=True):
        header[slot] = at
        at += block.size
    return np.concatenate([header, *blocks])


def initial_state(params) -> np.ndarray:
    """Internal variables before the first contact (stiffness/damping at zero crushing;
    code_aster 15's scalar law starts from zeros)."""
    state = np.zeros(N_VINT)
    if params[P_SCALAR] == 1.0:
        return state
    at_zero = interpreted(value)  # two values: no reason to compile
    state[V_RIGI] = at_zero(params, int(params[P_AT_RIGI]), 0.0)
    state[V_AMOR] = at_zero(params, int(params[P_AT_AMOR]), 0.0)
    return state


def legacy_buckling_curves(
    rigi_nor,
    fnor_crit,
    fnor_post_fl,
    larg_plat,
    enfo_fl,
    depl_post_fl,
    rigi_post_fl,
    amor_nor=0.0,
    amor_fl=None,
    amor_post_fl=None,
    points_per_segment=200,
):
    """The force threshold, stiffness and damping curves (``Curve``, CONSTANT both sides)
    equivalent to the historical scalar description of a buckling support:
    elastic up to the critical force ``fnor_crit``, a plateau of width
    ``larg_plat``, a drop to the post-buckling force ``fnor_post_fl`` over
    ``enfo_fl``, then post-buckling branches of stiffness ``rigi_post_fl``
    reached at the crushings ``depl_post_fl`` (increasing)."""
    if rigi_nor <= 0.0 or fnor_crit <= 0.0 or fnor_post_fl <= 0.0 or enfo_fl <= 0.0:
        raise LawError(
            "FLAMBAGE: the stiffness, the critical force, the post-buckling force and the "
            "drop must be > 0"
        )
    depl = np.asarray(depl_post_fl, float)
    rigi = np.asarray(rigi_post_fl, float)
    if depl.size == 0 or depl.size != rigi.size or np.any(rigi <= 0.0):
        raise LawError(
            "FLAMBAGE: crushings and post-buckling stiffnesses: same length, stiffness > 0"
        )
    amor_fl = amor_nor if amor_fl is None else amor_fl
    amor_post = np.full(depl.size, amor_fl) if amor_post_fl is None else np.asarray(amor_post_fl)
    total = depl + fnor_post_fl / rigi  # total penetration reached on each branch
    u_plateau = fnor_crit / rigi_nor
    u_drop = u_plateau + larg_plat
    u_buckled = u_drop + enfo_fl
    if np.any(np.diff(depl) < 0.0) or np.any(np.diff(total) <= 0.0) or total[0] <= u_buckled:
        raise LawError("FLAMBAGE: post-buckling crushings and total penetrations must increase")
    rows = [(0.0, fnor_crit, rigi_nor, amor_nor), (u_plateau, fnor_crit, rigi_nor, amor_nor)]
    if larg_plat > 0.0:
        rows.append((u_drop, fnor_crit, rigi_nor, amor_nor))
    # the drop: threshold linear in the penetration, crushing frozen at the plateau width
    for u in np.linspace(u_drop, u_buckled, points_per_segment + 1)[1:]:
        w = (u - u_drop) / enfo_fl
        f = fnor_crit + w * (fnor_post_fl - fnor_crit)
        rows.append((u, f, f / (u - larg_plat), amor_nor + w * (amor_fl - amor_nor)))
    # post-buckling: crushing interpolated between the branches, force the post-buckling one
    starts = np.concatenate([[u_buckled], total])
    crush = np.concatenate([[larg_plat], depl])
    damps = np.concatenate([[amor_fl], amor_post])
    for k in range(depl.size):
        for u in np.linspace(starts[k], starts[k + 1], points_per_segment + 1)[1:]:
            w = (u - starts[k]) / (starts[k + 1] - starts[k])
            crushing = crush[k] + w * (crush[k + 1] - crush[k])
            damping = damps[k] + w * (damps[k + 1] - damps[k])
            rows.append((u, fnor_post_fl, fnor_post_fl / (u - crushing), damping))
    table = np.asarray(rows)
    return tuple(Curve(table[:, 0], table[:, j], "CONSTANT", "CONSTANT") for j in (1, 2, 3))
