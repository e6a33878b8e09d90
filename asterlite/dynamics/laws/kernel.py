"""The laws of this package in the time loop (general path), compiled.

A localized nonlinearity other than DIS_CHOC is a row of the shock arrays
(``model.build_shocks``) whose ``flags[s, F_LAW]`` holds the code of its
branch below (the ``code`` of its entry in ``connections.RELATIONS``;
relations may share a branch); its law parameters are row ``laws[s]``
(packed as the law's ``prepare_*`` returns them), its internal variables are ``vint[s]``
in the law's own layout (code_aster's VINT1.. order), and column
:data:`V_TIME` of ``vint`` holds the instant of the stored state.

:func:`law_forces` adds the generalized forces of every such row. Laws
that integrate over the step (DIS_VISC, DIS_ECRO_TRAC) take
dt = t - vint[s, V_TIME] and overwrite their state when dt > 0, as
code_aster does with the step of each evaluation (a Runge-Kutta stage
integrates from the previous stage; the schemes restore ``vint`` when a
step is retried). A law that cannot be evaluated (a function outside its
EXCLU domain, a local integration that did not converge) writes NaN into
its force and internal variables: the acceleration becomes non-finite and
the driver names the nonlinearity (:func:`failed_law`).
"""

from __future__ import annotations

import math

import numpy as np

from asterlite.dynamics.contact import (
    F_GEOMETRY,
    F_LAW,
    F_NPOLAR,
    F_TWO_NODES,
    P_COORD1,
    P_COORD2,
    P_DIST1,
    P_DIST2,
    P_DRIVE1,
    P_DRIVE2,
    P_GAP,
    P_ORIGIN,
    P_SIGN_Y,
    P_SIGN_Z,
    obstacle_gap,
)
from asterlite.dynamics.jit import njit
from asterlite.dynamics.laws import (
    anti_sism,
    choc_elas_trac,
    dis_ecro_trac,
    dis_visc,
    flambage,
    rela_effo_depl,
    rk54,
    rotor_fiss,
)

DIS_CHOC, FLAMBAGE, ANTI_SISM, DIS_VISC, DIS_ECRO_TRAC = 0, 1, 2, 3, 4
CHOC_ELAS_TRAC, RELA_EFFO_DEPL, RELA_EFFO_VITE, ROTOR_FISS = 5, 6, 7, 8
V_TIME = 20  # instant of the stored state (after code_aster's 20 archived values)
VINT_WIDTH = 21
# (SCRATCH_ROWS, 14): rk54 work rows, the rates, the kinematics (6 rows), a global vector
W_RATE = rk54.N_WORK
W_KIN = W_RATE + 1
W_VECTOR = W_KIN + 6
SCRATCH_ROWS = W_VECTOR + 3
SCRATCH_COLS = 14


def scratch() -> np.ndarray:
    return np.zeros((SCRATCH_ROWS, SCRATCH_COLS))


@njit(cache=True)
def node_motion(phi, q, v, i):
    """Global displacement and velocity of component row ``i`` of ``phi``."""
    d = 0.0
    w = 0.0
    for m in range(q.shape[0]):
        d += phi[i, m] * q[m]
        w += phi[i, m] * v[m]
    return d, w


@njit(cache=True)
def kinematics(s, q, v, params, rots, phis, two_nodes, out):
    """``out`` rows (9 or more, 6 columns or more): 0/1 local position
    (rest + displacement + support motion, from the origin) of node 1/2,
    2/3 local velocity of node 1/2, 6-8 scratch,
    4/5 local displacement (modal + support motion) minus the origin, as
    code_aster stores it for the axial laws, of node 1/2."""
    for node in range(2):
        for i in range(6):
            out[node, i] = 0.0
            out[2 + node, i] = 0.0
            out[4 + node, i] = 0.0
        if node == 1 and not two_nodes:
            continue
        coord = P_COORD1 if node == 0 else P_COORD2
        drive = P_DRIVE1 if node == 0 else P_DRIVE2
        gx, gu, gv = out[6], out[7], out[8]
        for i in range(3):
            d, w = node_motion(phis[s, node], q, v, i)
            gu[i] = d + params[s, drive + i]
            gx[i] = params[s, coord + i] - params[s, P_ORIGIN + i] + gu[i]
            gu[i] -= params[s, P_ORIGIN + i]  # code_aster's gloloc(u, obstacle origin)
            gv[i] = w + params[s, drive + 3 + i]
        for i in range(3):
            out[node, i] = rots[s, i, 0] * gx[0] + rots[s, i, 1] * gx[1] + rots[s, i, 2] * gx[2]
            out[2 + node, i] = rots[s, i, 0] * gv[0] + rots[s, i, 1] * gv[1] + rots[s, i, 2] * gv[2]
            out[4 + node, i] = rots[s, i, 0] * gu[0] + rots[s, i, 1] * gu[1] + rots[s, i, 2] * gu[2]


@njit(cache=True)
def add_local_force(s, rots, phis, fx, fy, fz, two_nodes, g, out):
    """A local force on node 1 (the opposite on node 2), projected on the
    modes (``g``: scratch for the global force)."""
    for i in range(3):
        g[i] = rots[s, 0, i] * fx + rots[s, 1, i] * fy + rots[s, 2, i] * fz
    for m in range(out.shape[0]):
        f = phis[s, 0, 0, m] * g[0] + phis[s, 0, 1, m] * g[1] + phis[s, 0, 2, m] * g[2]
        if two_nodes:
            f -= phis[s, 1, 0, m] * g[0] + phis[s, 1, 1, m] * g[1] + phis[s, 1, 2, m] * g[2]
        out[m] += f


@njit(cache=True)
def store_locals(vint, s, at1, at2, kin, row):
    for i in range(3):
        vint[s, at1 + i] = kin[row, i]
        vint[s, at2 + i] = kin[row + 1, i]


@njit(cache=True)
def law_forces(t, q, v, flags, params, rots, phis, polars, laws, rphis, vint, work, out):
    """Add the generalized forces of every non-DIS_CHOC row to ``out``."""
    kin = work[W_KIN:]
    g = work[W_VECTOR]
    for s in range(flags.shape[0]):
        code = flags[s, F_LAW]
        if code == DIS_CHOC:
            continue
        law = laws[s]
        if code == RELA_EFFO_DEPL or code == RELA_EFFO_VITE:
            c = int(law[rela_effo_depl.P_COMPONENT])
            shape = phis[s, 0] if c < 3 else rphis[s, 0]
            d, w = node_motion(shape, q, v, c % 3)
            x = d if code == RELA_EFFO_DEPL else w
            f = rela_effo_depl.relation_force(law, x, vint[s])
            for m in range(out.shape[0]):
                out[m] += f * shape[c % 3, m]
            continue
        if code == ROTOR_FISS:  # node 1: the crack's right node, node 2: its left node
            dtx = node_motion(rphis[s, 1], q, v, 0)[0] - node_motion(rphis[s, 0], q, v, 0)[0]
            dty = node_motion(rphis[s, 1], q, v, 1)[0] - node_motion(rphis[s, 0], q, v, 1)[0]
            dtz = node_motion(rphis[s, 1], q, v, 2)[0] - node_motion(rphis[s, 0], q, v, 2)[0]
            mx, my, mz = rotor_fiss.cracked_rotor_moment(law, t, rots[s], dtx, dty, dtz, vint[s])
            for m in range(out.shape[0]):
                out[m] += (
                    (rphis[s, 0, 0, m] - rphis[s, 1, 0, m]) * mx
                    + (rphis[s, 0, 1, m] - rphis[s, 1, 1, m]) * my
                    + (rphis[s, 0, 2, m] - rphis[s, 1, 2, m]) * mz
                )
            continue
        two_nodes = flags[s, F_TWO_NODES] == 1
        kinematics(s, q, v, params, rots, phis, two_nodes, kin)
        if code == FLAMBAGE or code == ANTI_SISM:
            gap, cos_n, sin_n = obstacle_gap(
                flags[s, F_GEOMETRY],
                kin[0, 1],
                kin[0, 2],
                kin[1, 1],
                kin[1, 2],
                params[s, P_GAP],
                params[s, P_DIST1],
                params[s, P_DIST2],
                params[s, P_SIGN_Y],
                params[s, P_SIGN_Z],
                polars,
                s,
                flags[s, F_NPOLAR],
            )
            vy = kin[2, 1] - (kin[3, 1] if two_nodes else 0.0)
            vz = kin[2, 2] - (kin[3, 2] if two_nodes else 0.0)
            vn = vy * cos_n + vz * sin_n
            if code == FLAMBAGE:
                store_locals(vint, s, flambage.V_LOC1, flambage.V_LOC2, kin, 0)
                fn = flambage.buckling_force(law, gap, vn, vint[s], vint[s])
            else:
                store_locals(vint, s, anti_sism.V_LOC1, anti_sism.V_LOC2, kin, 0)
                fn = anti_sism.antiseismic_force(law, gap, vn)
                vint[s, anti_sism.V_FORCE] = fn
                vint[s, anti_sism.V_VN] = vn
            add_local_force(s, rots, phis, 0.0, fn * cos_n, fn * sin_n, two_nodes, g, out)
            continue
        if code == CHOC_ELAS_TRAC:
            store_locals(vint, s, choc_elas_trac.V_LOC1, choc_elas_trac.V_LOC2, kin, 0)
            fx = choc_elas_trac.elastic_shock_force(law, kin[5, 0] - kin[4, 0], vint[s])
            add_local_force(s, rots, phis, fx, 0.0, 0.0, True, g, out)
            continue
        # DIS_VISC, DIS_ECRO_TRAC: integrated over dt from the stored state
        dt = t - vint[s, V_TIME]
        rate = work[W_RATE]
        if code == DIS_VISC:
            if dt > 0.0:
                sigma, converged = dis_visc.zener_force(
                    law, kin[2, 0] - kin[3, 0], dt, vint[s], vint[s], rate, work[: rk54.N_WORK]
                )
                store_locals(vint, s, dis_visc.V_LOC1, dis_visc.V_LOC2, kin, 4)
                vint[s, V_TIME] = t
                if not converged:
                    sigma = math.nan
                    vint[s, dis_visc.V_FORCE] = sigma
            else:
                sigma = vint[s, dis_visc.V_FORCE]
            add_local_force(s, rots, phis, sigma, 0.0, 0.0, True, g, out)
            continue
        if code == DIS_ECRO_TRAC:
            if dt > 0.0:
                relative = kin[7, :3]  # kinematics scratch, free now
                for i in range(3):
                    relative[i] = kin[2, i] - kin[3, i]
                fx, fy, fz, converged = dis_ecro_trac.hardening_force(
                    law, relative, dt, vint[s], vint[s], rate, work[: rk54.N_WORK]
                )
                store_locals(vint, s, dis_ecro_trac.V_LOC1, dis_ecro_trac.V_LOC2, kin, 4)
                vint[s, V_TIME] = t
                if not converged:
                    fx = math.nan
                    vint[s, dis_ecro_trac.V_FORCE] = fx
            else:
                fx = vint[s, dis_ecro_trac.V_FORCE]
                fy = vint[s, dis_ecro_trac.V_FORCE + 1]
                fz = vint[s, dis_ecro_trac.V_FORCE + 2]
            add_local_force(s, rots, phis, fx, fy, fz, True, g, out)
            continue
    return -1


def failed_law(flags, vint) -> int:
    """Index of the first law row whose internal variables hold a NaN, or -1."""
    for s in range(flags.shape[0]):
        if flags[s, F_LAW] != DIS_CHOC and np.any(np.isnan(vint[s])):
            return s
    return -1
