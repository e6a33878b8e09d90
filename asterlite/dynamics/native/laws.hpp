// The relations of laws/ in the time loop (asterlite.dynamics.laws.kernel):
// the generalized forces of every row of the shocks whose F_LAW is not DIS_CHOC,
// each law's module in its own header (law_<module>.hpp), operation for
// operation as numba compiles them.
#pragma once

#include <cstdint>
#include <limits>

#include "contact.hpp"
#include "law_anti_sism.hpp"
#include "law_choc_elas_trac.hpp"
#include "law_dis_ecro_trac.hpp"
#include "law_dis_visc.hpp"
#include "law_flambage.hpp"
#include "law_rela_effo_depl.hpp"
#include "law_rk54.hpp"
#include "law_rotor_fiss.hpp"
#include "law_tabulated.hpp"
#include "views.hpp"

namespace asterlite {
namespace laws {

// the branch of each relation (laws.kernel)
enum Code : std::int64_t {
    DIS_CHOC, FLAMBAGE, ANTI_SISM, DIS_VISC, DIS_ECRO_TRAC,
    CHOC_ELAS_TRAC, RELA_EFFO_DEPL, RELA_EFFO_VITE, ROTOR_FISS,
};
constexpr std::int64_t LAST_CODE = ROTOR_FISS;
constexpr index V_TIME = 20;  // instant of the stored state (after code_aster's 20 values)
constexpr index VINT_WIDTH = 21;
// (SCRATCH_ROWS, SCRATCH_COLS) scratch: rk54 work rows, the rates, the kinematics
// (6 rows, and 3 more of its scratch overlapping the global vector's), a global vector
constexpr index N_WORK = rk54::N_WORK;
constexpr index W_RATE = N_WORK, W_KIN = W_RATE + 1, W_VECTOR = W_KIN + 6;
constexpr index SCRATCH_ROWS = W_VECTOR + 3, SCRATCH_COLS = 14;

// a[start:] and a[:stop] of a 2-D array, as numba's views of row ranges
inline F2 rows_from(const F2& a, index start) {
    F2 view;
    view.data = a.data + start * a.n1;
    view.n0 = a.n0 - start;
    view.n1 = a.n1;
    return view;
}
inline F2 rows_to(const F2& a, index stop) {
    F2 view;
    view.data = a.data;
    view.n0 = stop;
    view.n1 = a.n1;
    return view;
}

// phis[s, node] of a (n_shocks, 2, 3, n_modes) array: a (3, n_modes) view
inline F2 shape_of(const F4& phis, index s, index node) {
    F2 view;
    view.data = &phis(s, node, 0, 0);
    view.n0 = phis.n2;
    view.n1 = phis.n3;
    return view;
}

struct Motion {
    double d, w;
};

// kernel.node_motion: the global displacement and velocity of row i of phi
inline Motion node_motion(const F2& phi, const F1& q, const F1& v, index i) {
    double d = 0.0;
    double w = 0.0;
    for (index m = 0; m < q.n0; ++m) {
        d += phi(i, m) * q(m);
        w += phi(i, m) * v(m);
    }
    return {d, w};
}

// kernel.kinematics: out rows 0/1 the local positions of node 1/2 (from the
// origin), 2/3 their local velocities, 4/5 their local displacements (support
// motion included) minus the origin, 6-8 scratch
inline void kinematics(index s, const F1& q, const F1& v, const F2& params, const F3& rots,
                       const F4& phis, bool two_nodes, const F2& out) {
    for (index node = 0; node < 2; ++node) {
        for (index i = 0; i < 6; ++i) {
            out(node, i) = 0.0;
            out(2 + node, i) = 0.0;
            out(4 + node, i) = 0.0;
        }
        if (node == 1 && !two_nodes) continue;
        const index coord = node == 0 ? P_COORD1 : P_COORD2;
        const index drive = node == 0 ? P_DRIVE1 : P_DRIVE2;
        const F1 gx = row(out, 6), gu = row(out, 7), gv = row(out, 8);
        const F2 phi = shape_of(phis, s, node);
        for (index i = 0; i < 3; ++i) {
            const Motion motion = node_motion(phi, q, v, i);
            gu(i) = motion.d + params(s, drive + i);
            gx(i) = params(s, coord + i) - params(s, P_ORIGIN + i) + gu(i);
            gu(i) -= params(s, P_ORIGIN + i);  // code_aster's gloloc(u, obstacle origin)
            gv(i) = motion.w + params(s, drive + 3 + i);
        }
        for (index i = 0; i < 3; ++i) {
            out(node, i) = rots(s, i, 0) * gx(0) + rots(s, i, 1) * gx(1) + rots(s, i, 2) * gx(2);
            out(2 + node, i) =
                rots(s, i, 0) * gv(0) + rots(s, i, 1) * gv(1) + rots(s, i, 2) * gv(2);
            out(4 + node, i) =
                rots(s, i, 0) * gu(0) + rots(s, i, 1) * gu(1) + rots(s, i, 2) * gu(2);
        }
    }
}

// kernel.add_local_force: a local force on node 1 (the opposite on node 2)
// projected on the modes (g: scratch for the global force)
inline void add_local_force(index s, const F3& rots, const F4& phis, double fx, double fy,
                            double fz, bool two_nodes, const F1& g, const F1& out) {
    for (index i = 0; i < 3; ++i) {
        g(i) = rots(s, 0, i) * fx + rots(s, 1, i) * fy + rots(s, 2, i) * fz;
    }
    for (index m = 0; m < out.n0; ++m) {
        double f = phis(s, 0, 0, m) * g(0) + phis(s, 0, 1, m) * g(1) + phis(s, 0, 2, m) * g(2);
        if (two_nodes) {
            f -= phis(s, 1, 0, m) * g(0) + phis(s, 1, 1, m) * g(1) + phis(s, 1, 2, m) * g(2);
        }
        out(m) += f;
    }
}

// kernel.store_locals: rows row and row + 1 of kin into vint[s] at at1 and at2
inline void store_locals(const F2& vint, index s, index at1, index at2, const F2& kin,
                         index row_) {
    for (index i = 0; i < 3; ++i) {
        vint(s, at1 + i) = kin(row_, i);
        vint(s, at2 + i) = kin(row_ + 1, i);
    }
}

// Python's c % 3 on an integer (the sign of the divisor)
inline index py_mod(index a, index b) {
    const index r = a % b;
    return (r != 0 && ((r < 0) != (b < 0))) ? r + b : r;
}

}  // namespace laws

// laws.kernel.law_forces: add the generalized forces of every non-DIS_CHOC row to out
// (shk.law_scratch: its work); -1
inline index law_forces(double t, const F1& q, const F1& v, const Shocks& shk, const F2& vint,
                        const F1& out) {
    using namespace laws;
    const I2& flags = shk.flags;
    const F2& params = shk.params;
    const F3& rots = shk.rots;
    const F4& phis = shk.phis;
    const F4& rphis = shk.rphis;
    const F2& work = shk.law_scratch;
    const F2 kin = rows_from(work, W_KIN);
    const F1 g = row(work, W_VECTOR);
    for (index s = 0; s < flags.n0; ++s) {
        const std::int64_t code = flags(s, F_LAW);
        if (code == DIS_CHOC) continue;
        const F1 law = row(shk.laws, s);
        const F1 state = row(vint, s);
        if (code == RELA_EFFO_DEPL || code == RELA_EFFO_VITE) {
            const index c = tabulated::to_int(law(rela_effo_depl::P_COMPONENT));
            const F2 shape = c < 3 ? shape_of(phis, s, 0) : shape_of(rphis, s, 0);
            const index component = py_mod(c, 3);
            const Motion motion = node_motion(shape, q, v, component);
            const double x = code == RELA_EFFO_DEPL ? motion.d : motion.w;
            const double f = rela_effo_depl::relation_force(law, x, state);
            for (index m = 0; m < out.n0; ++m) out(m) += f * shape(component, m);
            continue;
        }
        if (code == ROTOR_FISS) {  // node 1: the crack's right node, node 2: its left node
            const F2 right = shape_of(rphis, s, 1), left = shape_of(rphis, s, 0);
            const double dtx = node_motion(right, q, v, 0).d - node_motion(left, q, v, 0).d;
            const double dty = node_motion(right, q, v, 1).d - node_motion(left, q, v, 1).d;
            const double dtz = node_motion(right, q, v, 2).d - node_motion(left, q, v, 2).d;
            const rotor_fiss::Moment moment =
                rotor_fiss::cracked_rotor_moment(law, t, slice(rots, s), dtx, dty, dtz, state);
            for (index m = 0; m < out.n0; ++m) {
                out(m) += (rphis(s, 0, 0, m) - rphis(s, 1, 0, m)) * moment.x +
                          (rphis(s, 0, 1, m) - rphis(s, 1, 1, m)) * moment.y +
                          (rphis(s, 0, 2, m) - rphis(s, 1, 2, m)) * moment.z;
            }
            continue;
        }
        const bool two_nodes = flags(s, F_TWO_NODES) == 1;
        kinematics(s, q, v, params, rots, phis, two_nodes, kin);
        if (code == FLAMBAGE || code == ANTI_SISM) {
            const Gap gap = obstacle_gap(flags(s, F_GEOMETRY), kin(0, 1), kin(0, 2), kin(1, 1),
                                         kin(1, 2), params(s, P_GAP), params(s, P_DIST1),
                                         params(s, P_DIST2), params(s, P_SIGN_Y),
                                         params(s, P_SIGN_Z), shk.polars, s, flags(s, F_NPOLAR));
            const double vy = kin(2, 1) - (two_nodes ? kin(3, 1) : 0.0);
            const double vz = kin(2, 2) - (two_nodes ? kin(3, 2) : 0.0);
            const double vn = vy * gap.cos_n + vz * gap.sin_n;
            double fn;
            if (code == FLAMBAGE) {
                store_locals(vint, s, flambage::V_LOC1, flambage::V_LOC2, kin, 0);
                fn = flambage::buckling_force(law, gap.gap, vn, state, state);
            } else {
                store_locals(vint, s, anti_sism::V_LOC1, anti_sism::V_LOC2, kin, 0);
                fn = anti_sism::antiseismic_force(law, gap.gap, vn);
                vint(s, anti_sism::V_FORCE) = fn;
                vint(s, anti_sism::V_VN) = vn;
            }
            add_local_force(s, rots, phis, 0.0, fn * gap.cos_n, fn * gap.sin_n, two_nodes, g, out);
            continue;
        }
        if (code == CHOC_ELAS_TRAC) {
            store_locals(vint, s, choc_elas_trac::V_LOC1, choc_elas_trac::V_LOC2, kin, 0);
            const double fx =
                choc_elas_trac::elastic_shock_force(law, kin(5, 0) - kin(4, 0), state);
            add_local_force(s, rots, phis, fx, 0.0, 0.0, true, g, out);
            continue;
        }
        // DIS_VISC, DIS_ECRO_TRAC: integrated over dt from the stored state
        const double dt = t - vint(s, V_TIME);
        const F1 rate = row(work, W_RATE);
        if (code == DIS_VISC) {
            double sigma;
            if (dt > 0.0) {
                const dis_visc::Force force = dis_visc::zener_force(
                    law, kin(2, 0) - kin(3, 0), dt, state, state, rate, rows_to(work, N_WORK));
                sigma = force.sigma;
                store_locals(vint, s, dis_visc::V_LOC1, dis_visc::V_LOC2, kin, 4);
                vint(s, V_TIME) = t;
                if (!force.converged) {
                    sigma = std::numeric_limits<double>::quiet_NaN();
                    vint(s, dis_visc::V_FORCE) = sigma;
                }
            } else {
                sigma = vint(s, dis_visc::V_FORCE);
            }
            add_local_force(s, rots, phis, sigma, 0.0, 0.0, true, g, out);
            continue;
        }
        if (code == DIS_ECRO_TRAC) {
            double fx, fy, fz;
            if (dt > 0.0) {
                F1 relative = row(kin, 7);  // kinematics scratch, free now
                relative.n0 = 3;
                for (index i = 0; i < 3; ++i) relative(i) = kin(2, i) - kin(3, i);
                const dis_ecro_trac::Force force = dis_ecro_trac::hardening_force(
                    law, relative, dt, state, state, rate, rows_to(work, N_WORK));
                fx = force.fx;
                fy = force.fy;
                fz = force.fz;
                store_locals(vint, s, dis_ecro_trac::V_LOC1, dis_ecro_trac::V_LOC2, kin, 4);
                vint(s, V_TIME) = t;
                if (!force.converged) {
                    fx = std::numeric_limits<double>::quiet_NaN();
                    vint(s, dis_ecro_trac::V_FORCE) = fx;
                }
            } else {
                fx = vint(s, dis_ecro_trac::V_FORCE);
                fy = vint(s, dis_ecro_trac::V_FORCE + 1);
                fz = vint(s, dis_ecro_trac::V_FORCE + 2);
            }
            add_local_force(s, rots, phis, fx, fy, fz, true, g, out);
            continue;
        }
    }
    return -1;
}

}  // namespace asterlite
