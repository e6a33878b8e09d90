"""Shock and friction forces of DIS_CHOC connections (R5.06.03), compiled.

Conventions (the same as code_aster's, so archived quantities compare):

- Local frame: row vectors of ``rot`` (global -> local); local x is
  the obstacle's normal, the contact plane is (y_loc, z_loc).
- A node's local coordinates are ``rot @ (X0 + Φ q - origin)``: mesh
  coordinates plus modal displacement, relative to the obstacle's origin.
- ``gap`` (d_N) is negative when penetrating; the unit normal ``n``
  = (0, cos_n, sin_n) in the local frame is the direction of the force the
  obstacle (or node 2) exerts on node 1.
- The normal force is the magnitude F_N >= 0 (eq. 11); the tangential force
  has two components: FT1 along t1 = (0, -sin_n, cos_n), FT2 along x_loc.

Every function here works on one shock at a time with scalars and small
views, allocates nothing and is safe to call from the time loops.
"""

from __future__ import annotations

import math

import numpy as np

from asterlite.dynamics.jit import njit

# Obstacle geometry codes (kernel side); see OBSTACLE_CODES in obstacles.py.
PLAN_Y, PLAN_Z, CERCLE, DISCRET, BI_PLAN_Y, BI_PLAN_Z, BI_CERCLE, BI_CERC_INT = range(8)

# Columns of the per-shock real parameter rows (``params``).
P_GAP, P_DIST1, P_DIST2, P_KN, P_CN, P_KT, P_CT, P_MU_DYN, P_MU_STAT = range(9)
P_SIGN_Y, P_SIGN_Z = 9, 10
P_ORIGIN = 11  # 3 values
P_COORD1 = 14  # 3 values
P_COORD2 = 17  # 3 values
# support motion (multiple supports) of node 1 / node 2 at the current instant:
# global displacement then velocity (6 values each), refreshed by the kernel
P_DRIVE1 = 20
P_DRIVE2 = 26
# implicit shock treatment (implicit_shocks.py): the normal force of a
# linearised shock is -k_n (d_0 + g.q) - c_n g.v along the normal frozen at
# the switch; K and C take the terms in q and v, the force keeps -k_n d_0 n
P_LIN_GAP = 32  # d_0, the gap extrapolated to q = 0
P_LIN_COS, P_LIN_SIN = 33, 34  # the frozen normal
N_PARAMS = 35

# Columns of the per-shock integer rows (``flags``).
F_GEOMETRY, F_TWO_NODES, F_UNIDIR, F_NPOLAR = range(4)
F_LAW = 4  # 0 DIS_CHOC, else the branch of laws.kernel of a relation of laws/
# implicit shock treatment: how the normal force enters the equations
# (implicit_shocks.py): explicit, linearised in K and C, or left out (a
# shock out of contact while others are linearised: code_aster applies no
# explicit normal force then; a new contact is caught at the step's end)
F_IMPLICIT = 5
NORMAL_EXPLICIT, NORMAL_LINEARISED, NORMAL_LEFT_OUT = range(3)
N_FLAGS = 6

# Internal variables of one shock (code_aster's 20-value layout, same order).
V_FN, V_FT1, V_FT2 = 0, 1, 2
V_LOC1 = 3  # local coordinates of node 1 (3)
V_LOC2 = 6  # local coordinates of node 2 (3)
V_VN, V_VT1, V_VT2 = 9, 10, 11
V_STICK = 12  # 1 while sticking, 0 while sliding
V_FT_REF = 13  # tangential force at the start of the stick phase (2)
V_X_REF = 15  # relative local position at the start of the stick phase (3)
V_VT_OLD = 18  # tangential velocity at the previous evaluation (2)
N_VINT = 20

SLIP_VELOCITY_FLOOR = 1.0e-6  # below this, sliding cannot be confirmed (code_aster's value)
EPS = np.finfo(np.float64).eps
VELOCITY_DIVERGENCE = 0.5 * math.sqrt(np.finfo(np.float64).max)


@njit(cache=True, inline="always")
def sign_of(x):
    """Fortran SIGN(1, x): +1 for x >= 0 (including +0), -1 otherwise."""
    return 1.0 if x >= 0.0 else -1.0


@njit(cache=True)
def gap_and_normal(geometry, loc1, loc2, gap0, dist1, dist2, sign_y, sign_z, polar, npolar):
    """Normal distance d_N (< 0 in contact) and normal direction (cos_n, sin_n).

    ``loc1``/``loc2``: local coordinates of node 1 / node 2 (node 2 unused
    for single-node obstacles). ``sign_y``/``sign_z``: for BI_PLAN_*, the
    sign of node 2 - node 1 at rest (the side each body stays on).
    ``polar``: (angle rad, radius) rows of a DISCRET obstacle, increasing angles.
    """
    polars = polar.reshape((1, polar.shape[0], polar.shape[1]))
    return obstacle_gap(
        geometry,
        loc1[1],
        loc1[2],
        loc2[1],
        loc2[2],
        gap0,
        dist1,
        dist2,
        sign_y,
        sign_z,
        polars,
        0,
        npolar,
    )


@njit(cache=True, inline="always")
def obstacle_gap(geometry, y1, z1, y2, z2, gap0, dist1, dist2, sign_y, sign_z, polars, s, npolar):
    """:func:`gap_and_normal` on the local (y, z) coordinates of both nodes
    (``polars[s]``: the facets of a DISCRET obstacle)."""
    if geometry == CERCLE:  # eq. 19-20: concave circle of radius the gap
        r = math.sqrt(y1 * y1 + z1 * z1)
        if r != 0.0:
            return gap0 - r, -y1 / r, -z1 / r
        return gap0 - r, -1.0, 0.0
    if geometry == PLAN_Y:  # eq. 17-18
        return gap0 - abs(y1), -sign_of(y1), 0.0
    if geometry == PLAN_Z:
        return gap0 - abs(z1), 0.0, -sign_of(z1)
    if geometry == BI_PLAN_Y:  # eq. 22-23
        return (y2 - y1) * sign_y - dist1 - dist2, -sign_y, 0.0
    if geometry == BI_PLAN_Z:
        return (z2 - z1) * sign_z - dist1 - dist2, 0.0, -sign_z
    if geometry == BI_CERCLE:  # eq. 24-25: two rings, outer contact
        dy, dz = y1 - y2, z1 - z2
        r = math.sqrt(dy * dy + dz * dz)
        if r != 0.0:
            return r - dist1 - dist2, dy / r, dz / r
        return -dist1 - dist2, -1.0, 0.0
    if geometry == BI_CERC_INT:  # node 1's ring inside node 2's circle
        dy, dz = y1 - y2, z1 - z2
        r = math.sqrt(dy * dy + dz * dz)
        if r > 0.0:
            return dist2 - dist1 - r, -dy / r, -dz / r
        return dist2 - dist1 - r, -1.0, 0.0
    # DISCRET (eq. 21): facet of the polar polygon whose angular sector holds the node
    return discrete_gap(y1, z1, polars[s], npolar)


@njit(cache=True)
def discrete_gap(y, z, polar, npolar):
    r = math.sqrt(y * y + z * z)
    theta = math.atan2(z, y) if r != 0.0 else 0.0
    if theta < 0.0:
        theta += 2.0 * math.pi
    for i in range(npolar - 1):
        t1, t2 = polar[i, 0], polar[i + 1, 0]
        if t1 <= theta <= t2:
            ya, za = polar[i, 1] * math.cos(t1), polar[i, 1] * math.sin(t1)
            yb, zb = polar[i + 1, 1] * math.cos(t2), polar[i + 1, 1] * math.sin(t2)
            dy, dz = yb - ya, zb - za
            length = math.sqrt(dy * dy + dz * dz)
            if length != 0.0:
                cos_n, sin_n = -dz / length, dy / length  # inward normal of a CCW polygon
            else:
                cos_n, sin_n = -1.0, 0.0
            return (y - ya) * cos_n + (z - za) * sin_n, cos_n, sin_n
    return 1.0e300, -1.0, 0.0  # angle outside the described sectors: no contact


@njit(cache=True, inline="always")
def normal_force(gap, normal_velocity, k_n, c_n):
    """Penalised normal force, positive part only (eq. 11)."""
    if gap > 0.0:
        return 0.0
    fn = -k_n * gap - c_n * normal_velocity
    return fn if fn > 0.0 else 0.0


@njit(cache=True)
def tangential_force(fn, rel_loc, rel_vel, cos_n, sin_n, mu_dyn, mu_stat, k_t, c_t, unidir, vint):
    """Incremental tangential force with Coulomb cap (eq. 12-16).

    Updates the stick/slip state kept in ``vint`` and returns (FT1, FT2,
    VT1, VT2). Sliding continues while the tangential velocity keeps its
    direction; otherwise a stick predictor F = F_ref - K_T (x - x_ref) - C_T v
    is tried and capped by mu_stat * F_N (slip at mu_dyn * F_N against v).
    With ``unidir`` the obstacle's normal axis (FT2) carries no friction.
    """
    return friction_force(
        fn,
        rel_loc[0],
        rel_loc[1],
        rel_loc[2],
        rel_vel[0],
        rel_vel[1],
        rel_vel[2],
        cos_n,
        sin_n,
        mu_dyn,
        mu_stat,
        k_t,
        c_t,
        unidir,
        vint.reshape((1, vint.shape[0])),
        0,
    )


@njit(cache=True, inline="always")
def friction_force(
    fn, rx, ry, rz, vx, vy, vz, cos_n, sin_n, mu_dyn, mu_stat, k_t, c_t, unidir, vint, s
):
    """:func:`tangential_force` on the relative local position (rx, ry, rz)
    and velocity (vx, vy, vz); ``vint[s]`` holds the shock's internal
    variables (rows and indices rather than views: no reference counting
    in the time loops)."""
    vt1 = -sin_n * vy + cos_n * vz
    vt2 = vx
    if unidir:
        vnorm = abs(vt1)
    else:
        vnorm = math.sqrt(vt1 * vt1 + vt2 * vt2)
    same_direction = vt1 * vint[s, V_VT_OLD] + vt2 * vint[s, V_VT_OLD + 1] >= 0.0
    sliding = same_direction and vint[s, V_STICK] == 0.0 and vnorm > SLIP_VELOCITY_FLOOR
    if sliding:
        ft1, ft2 = slip_force(fn, mu_dyn, vt1, vt2, vnorm, unidir)
        start_stick_reference(vint, s, ft1, ft2, rx, ry, rz)
    else:
        dx1 = -(ry - vint[s, V_X_REF + 1]) * sin_n + (rz - vint[s, V_X_REF + 2]) * cos_n
        dx2 = rx - vint[s, V_X_REF]
        vint[s, V_STICK] = 1.0
        ft1 = vint[s, V_FT_REF] - k_t * dx1 - c_t * vt1
        ft2 = 0.0 if unidir else vint[s, V_FT_REF + 1] - k_t * dx2 - c_t * vt2
        if math.sqrt(ft1 * ft1 + ft2 * ft2) > mu_stat * fn:
            vint[s, V_STICK] = 0.0
            if vnorm <= EPS:
                ft1, ft2 = 0.0, 0.0
            else:
                ft1, ft2 = slip_force(fn, mu_dyn, vt1, vt2, vnorm, unidir)
            start_stick_reference(vint, s, ft1, ft2, rx, ry, rz)
    vint[s, V_VT_OLD] = vt1
    vint[s, V_VT_OLD + 1] = vt2
    return ft1, ft2, vt1, vt2


@njit(cache=True, inline="always")
def slip_force(fn, mu_dyn, vt1, vt2, vnorm, unidir):
    """Coulomb sliding force, opposed to the tangential velocity (eq. 16)."""
    ft1 = -mu_dyn * fn * vt1 / vnorm
    ft2 = 0.0 if unidir else -mu_dyn * fn * vt2 / vnorm
    return ft1, ft2


@njit(cache=True, inline="always")
def start_stick_reference(vint, s, ft1, ft2, rx, ry, rz):
    vint[s, V_FT_REF] = ft1
    vint[s, V_FT_REF + 1] = ft2
    vint[s, V_X_REF] = rx
    vint[s, V_X_REF + 1] = ry
    vint[s, V_X_REF + 2] = rz


@njit(cache=True, inline="always")
def contact_law(params, unidir, vint, s, gap, cos_n, sin_n, rx, ry, rz, vx, vy, vz):
    """The DIS_CHOC law of one shock from its relative local kinematics.

    ``params[s]``: the shock's parameters; ``vint[s]``: its internal variables,
    whose force, velocity and friction entries are updated (the local
    coordinates are the caller's). Returns (diverged, in_contact, fx, fy, fz)
    with (fx, fy, fz) the local force on node 1 (node 2 takes the opposite).
    """
    fn, ft1, ft2, vn, vt1, vt2 = 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    fx, fy, fz = 0.0, 0.0, 0.0
    in_contact = gap <= 0.0
    if in_contact:
        vn = vy * cos_n + vz * sin_n
        fn = normal_force(gap, vn, params[s, P_KN], params[s, P_CN])
        fy = fn * cos_n
        fz = fn * sin_n
        if abs(params[s, P_MU_STAT]) > EPS or abs(params[s, P_MU_DYN]) > EPS:
            if max(vx, vy, vz) > VELOCITY_DIVERGENCE:
                return True, in_contact, fx, fy, fz
            ft1, ft2, vt1, vt2 = friction_force(
                fn,
                rx,
                ry,
                rz,
                vx,
                vy,
                vz,
                cos_n,
                sin_n,
                params[s, P_MU_DYN],
                params[s, P_MU_STAT],
                params[s, P_KT],
                params[s, P_CT],
                unidir,
                vint,
                s,
            )
            fx += ft2
            fy += -ft1 * sin_n
            fz += ft1 * cos_n
    else:
        # out of contact: friction memory is reset, a new stick phase starts here
        vint[s, V_STICK] = 0.0
        for i in range(2):
            vint[s, V_FT_REF + i] = 0.0
            vint[s, V_VT_OLD + i] = 0.0
        vint[s, V_X_REF] = rx
        vint[s, V_X_REF + 1] = ry
        vint[s, V_X_REF + 2] = rz
    vint[s, V_FN] = fn
    vint[s, V_FT1] = ft1
    vint[s, V_FT2] = ft2
    vint[s, V_VN] = vn
    vint[s, V_VT1] = vt1
    vint[s, V_VT2] = vt2
    return False, in_contact, fx, fy, fz


@njit(cache=True, inline="always")
def local_state(rot, phi, coord, drive, origin, q, v, loc, vel):
    """Local position (with rest coordinates, from the obstacle's origin) and velocity of
    a node; ``drive`` adds the support motion (displacement, velocity)."""
    for i in range(3):
        xg = coord[i] - origin[i] + drive[i]
        vg = drive[3 + i]
        for m in range(q.shape[0]):
            xg += phi[i, m] * q[m]
            vg += phi[i, m] * v[m]
        # accumulate global components first, rotate below
        loc[i] = xg
        vel[i] = vg
    rotate_in_place(rot, loc)
    rotate_in_place(rot, vel)


@njit(cache=True, inline="always")
def rotate_in_place(rot, x):
    a = rot[0, 0] * x[0] + rot[0, 1] * x[1] + rot[0, 2] * x[2]
    b = rot[1, 0] * x[0] + rot[1, 1] * x[1] + rot[1, 2] * x[2]
    c = rot[2, 0] * x[0] + rot[2, 1] * x[1] + rot[2, 2] * x[2]
    x[0], x[1], x[2] = a, b, c


@njit(cache=True, inline="always")
def add_generalized_force(rot, phi, f_local, coef, out):
    """out += coef * Φᵀ (rotᵀ f_local): a local force at a node, projected on the modes."""
    g0 = rot[0, 0] * f_local[0] + rot[1, 0] * f_local[1] + rot[2, 0] * f_local[2]
    g1 = rot[0, 1] * f_local[0] + rot[1, 1] * f_local[1] + rot[2, 1] * f_local[2]
    g2 = rot[0, 2] * f_local[0] + rot[1, 2] * f_local[1] + rot[2, 2] * f_local[2]
    for m in range(out.shape[0]):
        out[m] += coef * (phi[0, m] * g0 + phi[1, m] * g1 + phi[2, m] * g2)


@njit(cache=True)  # not inlined: a step evaluates the forces up to 3 times (compile size)
def shock_forces(q, v, flags, params, rots, phis, polars, vint, work, out):
    """Add every shock's generalized force to ``out``; update ``vint``.

    The general path (mode shapes in the global frame, rotated at every
    call); the DIFF_CENTRE kernel uses :func:`local_shock_forces`.
    ``work`` is a (5, 3) scratch array (local positions/velocities, force).
    Returns the index of the first shock whose relative velocity became
    absurd (divergence), or -1.
    """
    loc1, vel1, loc2, vel2, f_local = work[0], work[1], work[2], work[3], work[4]
    for s in range(flags.shape[0]):
        if flags.shape[1] > F_LAW and flags[s, F_LAW] != 0:
            continue  # another relation: laws.kernel.law_forces
        p = params[s]
        geometry = flags[s, F_GEOMETRY]
        two_nodes = flags[s, F_TWO_NODES] == 1
        origin = p[P_ORIGIN : P_ORIGIN + 3]
        local_state(
            rots[s],
            phis[s, 0],
            p[P_COORD1 : P_COORD1 + 3],
            p[P_DRIVE1 : P_DRIVE1 + 6],
            origin,
            q,
            v,
            loc1,
            vel1,
        )
        if two_nodes:
            local_state(
                rots[s],
                phis[s, 1],
                p[P_COORD2 : P_COORD2 + 3],
                p[P_DRIVE2 : P_DRIVE2 + 6],
                origin,
                q,
                v,
                loc2,
                vel2,
            )
        else:
            for i in range(3):
                loc2[i] = 0.0
                vel2[i] = 0.0
        vs = vint[s]
        for i in range(3):
            vs[V_LOC1 + i] = loc1[i]
            vs[V_LOC2 + i] = loc2[i]
        gap, cos_n, sin_n = obstacle_gap(
            geometry,
            loc1[1],
            loc1[2],
            loc2[1],
            loc2[2],
            p[P_GAP],
            p[P_DIST1],
            p[P_DIST2],
            p[P_SIGN_Y],
            p[P_SIGN_Z],
            polars,
            s,
            flags[s, F_NPOLAR],
        )
        if two_nodes:  # relative quantities node 1 - node 2
            for i in range(3):
                loc2[i] = loc1[i] - loc2[i]
                vel2[i] = vel1[i] - vel2[i]
            rel_loc, rel_vel = loc2, vel2
        else:
            rel_loc, rel_vel = loc1, vel1
        diverged, in_contact, fx, fy, fz = contact_law(
            params,
            flags[s, F_UNIDIR] == 1,
            vint,
            s,
            gap,
            cos_n,
            sin_n,
            rel_loc[0],
            rel_loc[1],
            rel_loc[2],
            rel_vel[0],
            rel_vel[1],
            rel_vel[2],
        )
        if diverged:
            return s
        mode = flags[s, F_IMPLICIT] if flags.shape[1] > F_IMPLICIT else NORMAL_EXPLICIT
        if mode != NORMAL_EXPLICIT:  # friction stays explicit, the normal force does not
            fn = vint[s, V_FN]
            fy -= fn * cos_n
            fz -= fn * sin_n
            if mode == NORMAL_LINEARISED:
                constant = -p[P_KN] * p[P_LIN_GAP]
                fy += constant * p[P_LIN_COS]
                fz += constant * p[P_LIN_SIN]
                in_contact = True
        if in_contact:
            f_local[0] = fx
            f_local[1] = fy
            f_local[2] = fz
            add_generalized_force(rots[s], phis[s, 0], f_local, 1.0, out)
            if two_nodes:
                add_generalized_force(rots[s], phis[s, 1], f_local, -1.0, out)
    return -1


@njit(cache=True, inline="always")
def local_shock_forces(q, v, flags, params, shapes, rest, polars, drive, vint, out):
    """:func:`shock_forces` with the mode shapes already in each shock's
    local frame: ``shapes[s, node]`` = rot Φ (3, n_modes), ``rest[s, node]``
    = rot (coord - origin), ``drive[s, node]`` = the support motion
    (displacement, velocity) in the local frame. Six independent sums over
    the modes per node, the force projected with the same shapes."""
    n = q.shape[0]
    for s in range(flags.shape[0]):
        two_nodes = flags[s, F_TWO_NODES] == 1
        x1 = rest[s, 0, 0] + drive[s, 0, 0]
        y1 = rest[s, 0, 1] + drive[s, 0, 1]
        z1 = rest[s, 0, 2] + drive[s, 0, 2]
        u1, v1, w1 = drive[s, 0, 3], drive[s, 0, 4], drive[s, 0, 5]
        for m in range(n):
            qm, vm = q[m], v[m]
            x1 += shapes[s, 0, 0, m] * qm
            y1 += shapes[s, 0, 1, m] * qm
            z1 += shapes[s, 0, 2, m] * qm
            u1 += shapes[s, 0, 0, m] * vm
            v1 += shapes[s, 0, 1, m] * vm
            w1 += shapes[s, 0, 2, m] * vm
        x2, y2, z2, u2, v2, w2 = 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
        if two_nodes:
            x2 = rest[s, 1, 0] + drive[s, 1, 0]
            y2 = rest[s, 1, 1] + drive[s, 1, 1]
            z2 = rest[s, 1, 2] + drive[s, 1, 2]
            u2, v2, w2 = drive[s, 1, 3], drive[s, 1, 4], drive[s, 1, 5]
            for m in range(n):
                qm, vm = q[m], v[m]
                x2 += shapes[s, 1, 0, m] * qm
                y2 += shapes[s, 1, 1, m] * qm
                z2 += shapes[s, 1, 2, m] * qm
                u2 += shapes[s, 1, 0, m] * vm
                v2 += shapes[s, 1, 1, m] * vm
                w2 += shapes[s, 1, 2, m] * vm
        vint[s, V_LOC1], vint[s, V_LOC1 + 1], vint[s, V_LOC1 + 2] = x1, y1, z1
        vint[s, V_LOC2], vint[s, V_LOC2 + 1], vint[s, V_LOC2 + 2] = x2, y2, z2
        gap, cos_n, sin_n = obstacle_gap(
            flags[s, F_GEOMETRY],
            y1,
            z1,
            y2,
            z2,
            params[s, P_GAP],
            params[s, P_DIST1],
            params[s, P_DIST2],
            params[s, P_SIGN_Y],
            params[s, P_SIGN_Z],
            polars,
            s,
            flags[s, F_NPOLAR],
        )
        if two_nodes:  # relative quantities node 1 - node 2
            x1, y1, z1, u1, v1, w1 = x1 - x2, y1 - y2, z1 - z2, u1 - u2, v1 - v2, w1 - w2
        diverged, in_contact, fx, fy, fz = contact_law(
            params, flags[s, F_UNIDIR] == 1, vint, s, gap, cos_n, sin_n, x1, y1, z1, u1, v1, w1
        )
        if diverged:
            return s
        if in_contact:
            for m in range(n):
                out[m] += (
                    shapes[s, 0, 0, m] * fx + shapes[s, 0, 1, m] * fy + shapes[s, 0, 2, m] * fz
                )
            if two_nodes:
                for m in range(n):
                    out[m] += -(
                        shapes[s, 1, 0, m] * fx + shapes[s, 1, 1, m] * fy + shapes[s, 1, 2, m] * fz
                    )
    return -1
