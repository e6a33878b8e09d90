// DIS_CHOC shock and friction forces (asterlite.dynamics.contact, R5.06.03):
// the gap of each obstacle geometry, the penalised normal force, the
// incremental Coulomb friction, in the global frame (shock_forces) and in
// each shock's local frame (local_shock_forces).
#pragma once

#include <cmath>

#include "layout.hpp"
#include "python_math.hpp"
#include "views.hpp"

namespace asterlite {

struct Shocks {
    I2 flags;    // (n_shocks, >= 4): contact.F_*
    F2 params;   // (n_shocks, 35): contact.P_*
    F3 rots;     // (n_shocks, 3, 3): global -> local
    F4 phis;     // (n_shocks, 2, 3, n_modes): mode shapes at the nodes, global frame
    F3 polars;   // (n_shocks, n_polar, 2): DISCRET facets
    // the relations of laws/ (laws.hpp): packed law parameters (n_shocks, width; width 0
    // without laws), rotation shapes (n_shocks, 2, 3, n_modes or 0), the laws' scratch
    F2 laws;
    F4 rphis;
    F2 law_scratch;
};

struct Gap {
    double gap, cos_n, sin_n;
};

// Fortran SIGN(1, x)
inline double sign_of(double x) { return x >= 0.0 ? 1.0 : -1.0; }

inline Gap discrete_gap(double y, double z, const F3& polars, index s, index npolar) {
    const double r = std::sqrt(y * y + z * z);
    double theta = r != 0.0 ? std::atan2(z, y) : 0.0;
    if (theta < 0.0) theta += 2.0 * M_PI;
    for (index i = 0; i < npolar - 1; ++i) {
        const double t1 = polars(s, i, 0), t2 = polars(s, i + 1, 0);
        if (t1 <= theta && theta <= t2) {
            const double ya = polars(s, i, 1) * std::cos(t1), za = polars(s, i, 1) * std::sin(t1);
            const double yb = polars(s, i + 1, 1) * std::cos(t2);
            const double zb = polars(s, i + 1, 1) * std::sin(t2);
            const double dy = yb - ya, dz = zb - za;
            const double length = std::sqrt(dy * dy + dz * dz);
            double cos_n = -1.0, sin_n = 0.0;
            if (length != 0.0) {
                cos_n = -dz / length;  // inward normal of a counter-clockwise polygon
                sin_n = dy / length;
            }
            return {(y - ya) * cos_n + (z - za) * sin_n, cos_n, sin_n};
        }
    }
    return {1.0e300, -1.0, 0.0};  // outside the described sectors: no contact
}

// contact.obstacle_gap: d_N (< 0 in contact) and the normal (cos_n, sin_n)
inline Gap obstacle_gap(std::int64_t geometry, double y1, double z1, double y2, double z2,
                        double gap0, double dist1, double dist2, double sign_y, double sign_z,
                        const F3& polars, index s, index npolar) {
    if (geometry == CERCLE) {
        const double r = std::sqrt(y1 * y1 + z1 * z1);
        if (r != 0.0) return {gap0 - r, -y1 / r, -z1 / r};
        return {gap0 - r, -1.0, 0.0};
    }
    if (geometry == PLAN_Y) return {gap0 - std::fabs(y1), -sign_of(y1), 0.0};
    if (geometry == PLAN_Z) return {gap0 - std::fabs(z1), 0.0, -sign_of(z1)};
    if (geometry == BI_PLAN_Y) return {(y2 - y1) * sign_y - dist1 - dist2, -sign_y, 0.0};
    if (geometry == BI_PLAN_Z) return {(z2 - z1) * sign_z - dist1 - dist2, 0.0, -sign_z};
    if (geometry == BI_CERCLE) {
        const double dy = y1 - y2, dz = z1 - z2;
        const double r = std::sqrt(dy * dy + dz * dz);
        if (r != 0.0) return {r - dist1 - dist2, dy / r, dz / r};
        return {-dist1 - dist2, -1.0, 0.0};
    }
    if (geometry == BI_CERC_INT) {
        const double dy = y1 - y2, dz = z1 - z2;
        const double r = std::sqrt(dy * dy + dz * dz);
        if (r > 0.0) return {dist2 - dist1 - r, -dy / r, -dz / r};
        return {dist2 - dist1 - r, -1.0, 0.0};
    }
    return discrete_gap(y1, z1, polars, s, npolar);
}

inline double normal_force(double gap, double normal_velocity, double k_n, double c_n) {
    if (gap > 0.0) return 0.0;
    const double fn = -k_n * gap - c_n * normal_velocity;
    return fn > 0.0 ? fn : 0.0;
}

inline void slip_force(double fn, double mu_dyn, double vt1, double vt2, double vnorm,
                       bool unidir, double& ft1, double& ft2) {
    ft1 = -mu_dyn * fn * vt1 / vnorm;
    ft2 = unidir ? 0.0 : -mu_dyn * fn * vt2 / vnorm;
}

inline void start_stick_reference(const F2& vint, index s, double ft1, double ft2, double rx,
                                  double ry, double rz) {
    vint(s, V_FT_REF) = ft1;
    vint(s, V_FT_REF + 1) = ft2;
    vint(s, V_X_REF) = rx;
    vint(s, V_X_REF + 1) = ry;
    vint(s, V_X_REF + 2) = rz;
}

// contact.friction_force: the incremental tangential force with Coulomb cap
inline void friction_force(double fn, double rx, double ry, double rz, double vx, double vy,
                           double vz, double cos_n, double sin_n, double mu_dyn, double mu_stat,
                           double k_t, double c_t, bool unidir, const F2& vint, index s,
                           double& ft1, double& ft2, double& vt1, double& vt2) {
    vt1 = -sin_n * vy + cos_n * vz;
    vt2 = vx;
    const double vnorm = unidir ? std::fabs(vt1) : std::sqrt(vt1 * vt1 + vt2 * vt2);
    const bool same_direction = vt1 * vint(s, V_VT_OLD) + vt2 * vint(s, V_VT_OLD + 1) >= 0.0;
    const bool sliding = same_direction && vint(s, V_STICK) == 0.0 && vnorm > SLIP_VELOCITY_FLOOR;
    if (sliding) {
        slip_force(fn, mu_dyn, vt1, vt2, vnorm, unidir, ft1, ft2);
        start_stick_reference(vint, s, ft1, ft2, rx, ry, rz);
    } else {
        const double dx1 =
            -(ry - vint(s, V_X_REF + 1)) * sin_n + (rz - vint(s, V_X_REF + 2)) * cos_n;
        const double dx2 = rx - vint(s, V_X_REF);
        vint(s, V_STICK) = 1.0;
        ft1 = vint(s, V_FT_REF) - k_t * dx1 - c_t * vt1;
        ft2 = unidir ? 0.0 : vint(s, V_FT_REF + 1) - k_t * dx2 - c_t * vt2;
        if (std::sqrt(ft1 * ft1 + ft2 * ft2) > mu_stat * fn) {
            vint(s, V_STICK) = 0.0;
            if (vnorm <= EPS) {
                ft1 = 0.0;
                ft2 = 0.0;
            } else {
                slip_force(fn, mu_dyn, vt1, vt2, vnorm, unidir, ft1, ft2);
            }
            start_stick_reference(vint, s, ft1, ft2, rx, ry, rz);
        }
    }
    vint(s, V_VT_OLD) = vt1;
    vint(s, V_VT_OLD + 1) = vt2;
}

struct LocalForce {
    bool diverged, in_contact;
    double fx, fy, fz;
};

// contact.contact_law: the DIS_CHOC law of shock s from its relative local
// kinematics; the local force on node 1 (node 2 takes the opposite)
inline LocalForce contact_law(const F2& params, bool unidir, const F2& vint, index s, double gap,
                              double cos_n, double sin_n, double rx, double ry, double rz,
                              double vx, double vy, double vz) {
    double fn = 0.0, ft1 = 0.0, ft2 = 0.0, vn = 0.0, vt1 = 0.0, vt2 = 0.0;
    double fx = 0.0, fy = 0.0, fz = 0.0;
    const bool in_contact = gap <= 0.0;
    if (in_contact) {
        vn = vy * cos_n + vz * sin_n;
        fn = normal_force(gap, vn, params(s, P_KN), params(s, P_CN));
        fy = fn * cos_n;
        fz = fn * sin_n;
        if (std::fabs(params(s, P_MU_STAT)) > EPS || std::fabs(params(s, P_MU_DYN)) > EPS) {
            if (py_max(vx, vy, vz) > VELOCITY_DIVERGENCE) return {true, in_contact, fx, fy, fz};
            friction_force(fn, rx, ry, rz, vx, vy, vz, cos_n, sin_n, params(s, P_MU_DYN),
                           params(s, P_MU_STAT), params(s, P_KT), params(s, P_CT), unidir, vint,
                           s, ft1, ft2, vt1, vt2);
            fx += ft2;
            fy += -ft1 * sin_n;
            fz += ft1 * cos_n;
        }
    } else {  // out of contact: the friction memory starts again from here
        vint(s, V_STICK) = 0.0;
        for (index i = 0; i < 2; ++i) {
            vint(s, V_FT_REF + i) = 0.0;
            vint(s, V_VT_OLD + i) = 0.0;
        }
        vint(s, V_X_REF) = rx;
        vint(s, V_X_REF + 1) = ry;
        vint(s, V_X_REF + 2) = rz;
    }
    vint(s, V_FN) = fn;
    vint(s, V_FT1) = ft1;
    vint(s, V_FT2) = ft2;
    vint(s, V_VN) = vn;
    vint(s, V_VT1) = vt1;
    vint(s, V_VT2) = vt2;
    return {false, in_contact, fx, fy, fz};
}

inline void rotate_in_place(const F3& rots, index s, double* x) {
    const double a = rots(s, 0, 0) * x[0] + rots(s, 0, 1) * x[1] + rots(s, 0, 2) * x[2];
    const double b = rots(s, 1, 0) * x[0] + rots(s, 1, 1) * x[1] + rots(s, 1, 2) * x[2];
    const double c = rots(s, 2, 0) * x[0] + rots(s, 2, 1) * x[1] + rots(s, 2, 2) * x[2];
    x[0] = a;
    x[1] = b;
    x[2] = c;
}

// contact.local_state: a node's local position (from the obstacle's origin,
// support motion added) and velocity; phis(s, node) is (3, n_modes)
inline void local_state(const Shocks& shk, index s, index node, index coord, index drive,
                        const F1& q, const F1& v, double* loc, double* vel) {
    for (index i = 0; i < 3; ++i) {
        double xg = shk.params(s, coord + i) - shk.params(s, P_ORIGIN + i) + shk.params(s, drive + i);
        double vg = shk.params(s, drive + 3 + i);
        for (index m = 0; m < q.n0; ++m) {
            xg += shk.phis(s, node, i, m) * q(m);
            vg += shk.phis(s, node, i, m) * v(m);
        }
        loc[i] = xg;
        vel[i] = vg;
    }
    rotate_in_place(shk.rots, s, loc);
    rotate_in_place(shk.rots, s, vel);
}

// contact.add_generalized_force: out += coef Phi^T (rot^T f_local)
inline void add_generalized_force(const F3& rots, const F4& phis, index s, index node,
                                  const double* f, double coef, const F1& out) {
    const double g0 = rots(s, 0, 0) * f[0] + rots(s, 1, 0) * f[1] + rots(s, 2, 0) * f[2];
    const double g1 = rots(s, 0, 1) * f[0] + rots(s, 1, 1) * f[1] + rots(s, 2, 1) * f[2];
    const double g2 = rots(s, 0, 2) * f[0] + rots(s, 1, 2) * f[1] + rots(s, 2, 2) * f[2];
    for (index m = 0; m < out.n0; ++m) {
        out(m) += coef * (phis(s, node, 0, m) * g0 + phis(s, node, 1, m) * g1 + phis(s, node, 2, m) * g2);
    }
}

// contact.shock_forces: every DIS_CHOC shock's generalized force added to
// out, mode shapes in the global frame; ``work`` (5, 3) scratch as there.
// Returns the first diverging shock or -1. With the implicit treatment
// (flags[s, F_IMPLICIT], implicit_shocks.hpp) the normal force of a shock is
// left out, or replaced by the constant term of its linearisation.
inline index shock_forces(const F1& q, const F1& v, const Shocks& shk, const F2& vint,
                          const F2& work, const F1& out) {
    double* loc1 = &work(0, 0);
    double* vel1 = &work(1, 0);
    double* loc2 = &work(2, 0);
    double* vel2 = &work(3, 0);
    double* f_local = &work(4, 0);
    const I2& flags = shk.flags;
    const F2& params = shk.params;
    for (index s = 0; s < flags.n0; ++s) {
        if (flags.n1 > F_LAW && flags(s, F_LAW) != 0) continue;  // another relation
        const bool two_nodes = flags(s, F_TWO_NODES) == 1;
        local_state(shk, s, 0, P_COORD1, P_DRIVE1, q, v, loc1, vel1);
        if (two_nodes) {
            local_state(shk, s, 1, P_COORD2, P_DRIVE2, q, v, loc2, vel2);
        } else {
            for (index i = 0; i < 3; ++i) {
                loc2[i] = 0.0;
                vel2[i] = 0.0;
            }
        }
        for (index i = 0; i < 3; ++i) {
            vint(s, V_LOC1 + i) = loc1[i];
            vint(s, V_LOC2 + i) = loc2[i];
        }
        const Gap g = obstacle_gap(flags(s, F_GEOMETRY), loc1[1], loc1[2], loc2[1], loc2[2],
                                   params(s, P_GAP), params(s, P_DIST1), params(s, P_DIST2),
                                   params(s, P_SIGN_Y), params(s, P_SIGN_Z), shk.polars, s,
                                   flags(s, F_NPOLAR));
        const double* rel_loc = loc1;
        const double* rel_vel = vel1;
        if (two_nodes) {  // relative quantities node 1 - node 2
            for (index i = 0; i < 3; ++i) {
                loc2[i] = loc1[i] - loc2[i];
                vel2[i] = vel1[i] - vel2[i];
            }
            rel_loc = loc2;
            rel_vel = vel2;
        }
        LocalForce lf = contact_law(params, flags(s, F_UNIDIR) == 1, vint, s, g.gap, g.cos_n,
                                    g.sin_n, rel_loc[0], rel_loc[1], rel_loc[2], rel_vel[0],
                                    rel_vel[1], rel_vel[2]);
        if (lf.diverged) return s;
        double fy = lf.fy, fz = lf.fz;
        bool in_contact = lf.in_contact;
        const std::int64_t mode =
            flags.n1 > F_IMPLICIT ? flags(s, F_IMPLICIT) : std::int64_t{NORMAL_EXPLICIT};
        if (mode != NORMAL_EXPLICIT) {  // friction stays explicit, the normal force does not
            const double fn = vint(s, V_FN);
            fy -= fn * g.cos_n;
            fz -= fn * g.sin_n;
            if (mode == NORMAL_LINEARISED) {
                const double constant = -params(s, P_KN) * params(s, P_LIN_GAP);
                fy += constant * params(s, P_LIN_COS);
                fz += constant * params(s, P_LIN_SIN);
                in_contact = true;
            }
        }
        if (in_contact) {
            f_local[0] = lf.fx;
            f_local[1] = fy;
            f_local[2] = fz;
            add_generalized_force(shk.rots, shk.phis, s, 0, f_local, 1.0, out);
            if (two_nodes) add_generalized_force(shk.rots, shk.phis, s, 1, f_local, -1.0, out);
        }
    }
    return -1;
}

// x += sum_m ax[m] q[m] and u += sum_m ax[m] v[m] (likewise y, v with ay and
// z, w with az), each sum in the order of m: the displacement and velocity
// sums of one row go in the two lanes of a vector (GCC's vector extension),
// each lane doing exactly the scalar operations, in half the instructions
inline void sum_pairs(const double* ax, const double* ay, const double* az, const double* q,
                      const double* v, index n, double& x, double& y, double& z, double& u,
                      double& vv, double& w) {
    typedef double pair __attribute__((vector_size(16)));
    pair xu = {x, u}, yv = {y, vv}, zw = {z, w};
    for (index m = 0; m < n; ++m) {
        const pair qv = {q[m], v[m]};
        xu += ax[m] * qv;
        yv += ay[m] * qv;
        zw += az[m] * qv;
    }
    x = xu[0];
    u = xu[1];
    y = yv[0];
    vv = yv[1];
    z = zw[0];
    w = zw[1];
}

// contact.local_shock_forces: the same forces with the mode shapes already in
// each shock's local frame (shapes, rest) and the support motion in ``drive``
inline index local_shock_forces(const F1& q, const F1& v, const Shocks& shk, const F4& shapes,
                                const F3& rest, const F3& drive, const F2& vint, const F1& out) {
    const index n = q.n0;
    const I2& flags = shk.flags;
    const F2& params = shk.params;
    for (index s = 0; s < flags.n0; ++s) {
        const bool two_nodes = flags(s, F_TWO_NODES) == 1;
        double x1 = rest(s, 0, 0) + drive(s, 0, 0);
        double y1 = rest(s, 0, 1) + drive(s, 0, 1);
        double z1 = rest(s, 0, 2) + drive(s, 0, 2);
        double u1 = drive(s, 0, 3), v1 = drive(s, 0, 4), w1 = drive(s, 0, 5);
        // the rows of rot Phi at node 1 (and 2), read through plain pointers
        const double* ax1 = &shapes(s, 0, 0, 0);
        const double* ay1 = &shapes(s, 0, 1, 0);
        const double* az1 = &shapes(s, 0, 2, 0);
        sum_pairs(ax1, ay1, az1, q.data, v.data, n, x1, y1, z1, u1, v1, w1);
        double x2 = 0.0, y2 = 0.0, z2 = 0.0, u2 = 0.0, v2 = 0.0, w2 = 0.0;
        if (two_nodes) {
            x2 = rest(s, 1, 0) + drive(s, 1, 0);
            y2 = rest(s, 1, 1) + drive(s, 1, 1);
            z2 = rest(s, 1, 2) + drive(s, 1, 2);
            u2 = drive(s, 1, 3);
            v2 = drive(s, 1, 4);
            w2 = drive(s, 1, 5);
            const double* ax2 = &shapes(s, 1, 0, 0);
            const double* ay2 = &shapes(s, 1, 1, 0);
            const double* az2 = &shapes(s, 1, 2, 0);
            sum_pairs(ax2, ay2, az2, q.data, v.data, n, x2, y2, z2, u2, v2, w2);
        }
        vint(s, V_LOC1) = x1;
        vint(s, V_LOC1 + 1) = y1;
        vint(s, V_LOC1 + 2) = z1;
        vint(s, V_LOC2) = x2;
        vint(s, V_LOC2 + 1) = y2;
        vint(s, V_LOC2 + 2) = z2;
        const Gap g = obstacle_gap(flags(s, F_GEOMETRY), y1, z1, y2, z2, params(s, P_GAP),
                                   params(s, P_DIST1), params(s, P_DIST2), params(s, P_SIGN_Y),
                                   params(s, P_SIGN_Z), shk.polars, s, flags(s, F_NPOLAR));
        if (two_nodes) {
            x1 = x1 - x2;
            y1 = y1 - y2;
            z1 = z1 - z2;
            u1 = u1 - u2;
            v1 = v1 - v2;
            w1 = w1 - w2;
        }
        const LocalForce lf = contact_law(params, flags(s, F_UNIDIR) == 1, vint, s, g.gap,
                                          g.cos_n, g.sin_n, x1, y1, z1, u1, v1, w1);
        if (lf.diverged) return s;
        if (lf.in_contact) {
            const double fx = lf.fx, fy = lf.fy, fz = lf.fz;
            double* force = out.data;
            for (index m = 0; m < n; ++m) force[m] += ax1[m] * fx + ay1[m] * fy + az1[m] * fz;
            if (two_nodes) {
                const double* bx = &shapes(s, 1, 0, 0);
                const double* by = &shapes(s, 1, 1, 0);
                const double* bz = &shapes(s, 1, 2, 0);
                for (index m = 0; m < n; ++m) force[m] += -(bx[m] * fx + by[m] * fy + bz[m] * fz);
            }
        }
    }
    return -1;
}

}  // namespace asterlite
