// The energy balance of a generalized transient (asterlite.dynamics.energy):
// powers and energies at the end of every accepted step, integrated with the
// trapezoidal rule, a row per archived instant; the relations of laws/ give
// TRAV_NL (their forces on a copy of their states, as energy.py does).
#pragma once

#include "contact.hpp"
#include "laws.hpp"
#include "loads.hpp"
#include "model.hpp"
#include "python_math.hpp"
#include "views.hpp"

namespace asterlite {
namespace energy {

enum Column : int {
    C_INST, C_ENER_CIN, C_ENER_POT, C_ENER_CHOC, C_TRAV_EXT, C_DISS_AMOR, C_DISS_CHOC,
    C_DISS_FROT, C_TRAV_NL, C_RESIDU,
};
enum Slot : int {
    A_ON, A_STAGGERED, A_DIAGONAL, A_EXT, A_AMOR, A_DCHOC, A_WFROT, A_NL, A_P_EXT, A_P_AMOR,
    A_P_NL, A_E_CIN, A_E_POT, A_E_N, A_E_TAN, A_E0, A_E_TAN0,
};
enum LocalColumn : int { L_GAP, L_VN, L_FN, L_DCHOC, L_FROT, L_DRIVE };
enum VectorRow : int { R_VELOCITY, R_EXTERNAL, R_LAW };

// layouts.Balance
struct Balance {
    F1 acc;
    F3 matrices;  // M, K, C
    F2 vectors;   // synchronous velocity, external force, law force
    F2 vint_copy;
    F2 work;      // (5, 3)
    F2 rows;      // archived rows (C_* columns)
    F3 local;     // (2, n_shocks, L_*): the previous and the last state
    bool active() const { return acc.data != nullptr && acc(A_ON) == 1.0; }
};

inline void copy_rows(const F2& source, const F2& target) {
    for (index i = 0; i < source.n0; ++i) {
        for (index j = 0; j < source.n1; ++j) target(i, j) = source(i, j);
    }
}

// x^T A y (the diagonal of A only when diagonal)
inline double quadratic(const F2& a, const F1& x, const F1& y, bool diagonal) {
    const index n = x.n0;
    double s = 0.0;
    if (diagonal) {
        for (index i = 0; i < n; ++i) s += x(i) * a(i, i) * y(i);
    } else {
        for (index i = 0; i < n; ++i) {
            double row = 0.0;
            for (index j = 0; j < n; ++j) row += a(i, j) * y(j);
            s += x(i) * row;
        }
    }
    return s;
}

// energy.shock_powers: each DIS_CHOC row's contact quantities at (q, v) into
// local (L_* columns); returns the stored (normal, tangential) energies
inline void shock_powers(const F1& q, const F1& v, const F2& vint, const Shocks& shk,
                         const F2& copy, const F2& work, const F2& local, double& e_n,
                         double& e_tan) {
    double* loc1 = &work(0, 0);
    double* vel1 = &work(1, 0);
    double* loc2 = &work(2, 0);
    double* vel2 = &work(3, 0);
    const I2& flags = shk.flags;
    const F2& params = shk.params;
    e_n = 0.0;
    e_tan = 0.0;
    for (index s = 0; s < flags.n0; ++s) {
        for (index j = 0; j < local.n1; ++j) local(s, j) = 0.0;
        if (flags(s, F_LAW) != 0) {
            local(s, L_GAP) = 1.0;
            continue;  // a relation of laws/: TRAV_NL
        }
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
        const Gap g = obstacle_gap(flags(s, F_GEOMETRY), loc1[1], loc1[2], loc2[1], loc2[2],
                                   params(s, P_GAP), params(s, P_DIST1), params(s, P_DIST2),
                                   params(s, P_SIGN_Y), params(s, P_SIGN_Z), shk.polars, s,
                                   flags(s, F_NPOLAR));
        double rx = loc1[0], ry = loc1[1], rz = loc1[2];
        double vx = vel1[0], vy = vel1[1], vz = vel1[2];
        if (two_nodes) {
            rx = rx - loc2[0];
            ry = ry - loc2[1];
            rz = rz - loc2[2];
            vx = vx - vel2[0];
            vy = vy - vel2[1];
            vz = vz - vel2[2];
        }
        local(s, L_GAP) = g.gap;
        local(s, L_VN) = vy * g.cos_n + vz * g.sin_n;
        if (g.gap > 0.0) continue;  // no force, nothing stored
        for (index j = 0; j < copy.n1; ++j) copy(s, j) = vint(s, j);
        const bool unidir = flags(s, F_UNIDIR) == 1;
        const LocalForce lf = contact_law(params, unidir, copy, s, g.gap, g.cos_n, g.sin_n, rx,
                                          ry, rz, vx, vy, vz);
        const double fn = copy(s, V_FN), vn = copy(s, V_VN);
        const double ft1 = copy(s, V_FT1), ft2 = copy(s, V_FT2);
        const double vt1 = copy(s, V_VT1), vt2 = copy(s, V_VT2);
        const double k_n = params(s, P_KN);
        const double penetration = -g.gap;
        e_n += 0.5 * k_n * penetration * penetration;
        local(s, L_FN) = fn;
        local(s, L_DCHOC) = (k_n * penetration - fn) * vn;
        local(s, L_FROT) = ft1 * vt1 + ft2 * vt2;
        const double k_t = params(s, P_KT);
        const bool friction =
            std::fabs(params(s, P_MU_STAT)) > EPS || std::fabs(params(s, P_MU_DYN)) > EPS;
        if (k_t > 0.0 && friction) {
            double el1 = ft1, el2 = ft2;
            if (copy(s, V_STICK) == 1.0) {  // stick: the spring holds F_T + C_T v_T
                el1 += params(s, P_CT) * vt1;
                if (!unidir) el2 += params(s, P_CT) * vt2;
            }
            e_tan += 0.5 * (el1 * el1 + el2 * el2) / k_t;
        }
        // the support motion seen by the contact, local frame
        double w1 = 0.0, w2 = 0.0, w3 = 0.0;
        for (index i = 0; i < 3; ++i) {
            double gi = params(s, P_DRIVE1 + 3 + i);
            if (two_nodes) gi -= params(s, P_DRIVE2 + 3 + i);
            w1 += shk.rots(s, 0, i) * gi;
            w2 += shk.rots(s, 1, i) * gi;
            w3 += shk.rots(s, 2, i) * gi;
        }
        local(s, L_DRIVE) = lf.fx * w1 + lf.fy * w2 + lf.fz * w3;
    }
}

// energy.contact_integrals: the integrals over a step of each shock's normal
// dissipation, friction and support powers
inline void contact_integrals(const F2& before, const F2& after, const F2& params, double dt,
                              double& d_choc, double& w_frot, double& w_drive) {
    d_choc = 0.0;
    w_frot = 0.0;
    w_drive = 0.0;
    for (index s = 0; s < before.n0; ++s) {
        const double g0 = before(s, L_GAP), g1 = after(s, L_GAP);
        if (g0 > 0.0 && g1 > 0.0) continue;
        if (g0 <= 0.0 && g1 <= 0.0) {
            const double h = 0.5 * dt;
            d_choc += h * (before(s, L_DCHOC) + after(s, L_DCHOC));
            w_frot += h * (before(s, L_FROT) + after(s, L_FROT));
            w_drive += h * (before(s, L_DRIVE) + after(s, L_DRIVE));
            continue;
        }
        const F2& inside = g1 <= 0.0 ? after : before;  // the end in contact
        double theta = (g1 <= 0.0 ? g1 : g0) / (g1 - g0);
        if (g0 <= 0.0) theta = -theta;
        const double vn = before(s, L_VN) + (after(s, L_VN) - before(s, L_VN)) *
                                                (g0 != g1 ? g0 / (g0 - g1) : 0.0);
        const double fn_cross = py_max(-params(s, P_CN) * vn, 0.0);
        const double scale = inside(s, L_FN) > 0.0 ? fn_cross / inside(s, L_FN) : 0.0;
        const double h = 0.5 * theta * dt;
        d_choc += h * (fn_cross * std::fabs(vn) + inside(s, L_DCHOC));
        w_frot += h * (1.0 + scale) * inside(s, L_FROT);
        w_drive += h * (1.0 + scale) * inside(s, L_DRIVE);
    }
}

// energy.evaluate: powers and energies at (t, q, v); dt the step that led to
// it (0 at the start)
inline void evaluate(const Balance& e, double t, const F1& q, const F1& v, const F1& a, double dt,
                     const F2& vint, const Model& model) {
    const F1& acc = e.acc;
    const index n = q.n0;
    const bool diagonal = acc(A_DIAGONAL) == 1.0;
    const F1 w = row(e.vectors, R_VELOCITY);
    const double half = acc(A_STAGGERED) == 1.0 ? 0.5 * dt : 0.0;
    for (index i = 0; i < n; ++i) w(i) = v(i) + half * a(i);
    acc(A_E_CIN) = 0.5 * quadratic(slice(e.matrices, 0), w, w, diagonal);
    acc(A_E_POT) = 0.5 * quadratic(slice(e.matrices, 1), q, q, diagonal);
    acc(A_P_AMOR) = quadratic(slice(e.matrices, 2), w, w, diagonal);
    const F1 f = row(e.vectors, R_EXTERNAL);
    for (index i = 0; i < f.n0; ++i) f(i) = 0.0;
    add_external_force(t, model.loads, f);
    double p_ext = 0.0;
    for (index i = 0; i < n; ++i) p_ext += f(i) * w(i);
    acc(A_P_EXT) = p_ext;
    support_motion(t, model.sup, model.shk.params);
    double e_n, e_tan;
    shock_powers(q, w, vint, model.shk, e.vint_copy, e.work, slice(e.local, 1), e_n, e_tan);
    acc(A_E_N) = e_n;
    acc(A_E_TAN) = e_tan;
    double p_nl = 0.0;
    if (model.shk.laws.n1 > 0) {  // relations of laws/, on a copy of their states
        copy_rows(vint, e.vint_copy);
        const F1 g = row(e.vectors, R_LAW);
        for (index i = 0; i < g.n0; ++i) g(i) = 0.0;
        law_forces(t, q, w, model.shk, e.vint_copy, g);
        for (index i = 0; i < n; ++i) p_nl += g(i) * w(i);
    }
    acc(A_P_NL) = p_nl;
}

inline void record(const Balance& e, index row, double t) {
    const F1& acc = e.acc;
    const F2& out = e.rows;
    const double e_choc = acc(A_E_N) + acc(A_E_TAN);
    const double diss_frot = -acc(A_WFROT) - (acc(A_E_TAN) - acc(A_E_TAN0));
    out(row, C_INST) = t;
    out(row, C_ENER_CIN) = acc(A_E_CIN);
    out(row, C_ENER_POT) = acc(A_E_POT);
    out(row, C_ENER_CHOC) = e_choc;
    out(row, C_TRAV_EXT) = acc(A_EXT);
    out(row, C_DISS_AMOR) = acc(A_AMOR);
    out(row, C_DISS_CHOC) = acc(A_DCHOC);
    out(row, C_DISS_FROT) = diss_frot;
    out(row, C_TRAV_NL) = acc(A_NL);
    out(row, C_RESIDU) = acc(A_E_CIN) + acc(A_E_POT) + e_choc - acc(A_E0) - acc(A_EXT) +
                         acc(A_AMOR) + acc(A_DCHOC) + diss_frot - acc(A_NL);
}

// energy.start: the balance at the initial state (row 0)
inline void start(const Balance& e, double t, const F1& q, const F1& v, const F1& a,
                  const F2& vint, const Model& model) {
    for (index k = A_EXT; k < A_NL + 1; ++k) e.acc(k) = 0.0;
    evaluate(e, t, q, v, a, 0.0, vint, model);
    copy_rows(slice(e.local, 1), slice(e.local, 0));
    e.acc(A_E0) = e.acc(A_E_CIN) + e.acc(A_E_POT) + e.acc(A_E_N) + e.acc(A_E_TAN);
    e.acc(A_E_TAN0) = e.acc(A_E_TAN);
    record(e, 0, t);
}

// energy.accumulate: after an accepted step of length dt ending at t
inline void accumulate(const Balance& e, double t, double dt, const F1& q, const F1& v,
                       const F1& a, const F2& vint, const Model& model) {
    const F1& acc = e.acc;
    const double p_ext = acc(A_P_EXT), p_amor = acc(A_P_AMOR), p_nl = acc(A_P_NL);
    evaluate(e, t, q, v, a, dt, vint, model);
    double d_choc, w_frot, w_drive;
    contact_integrals(slice(e.local, 0), slice(e.local, 1), model.shk.params, dt, d_choc, w_frot,
                      w_drive);
    copy_rows(slice(e.local, 1), slice(e.local, 0));
    const double h = 0.5 * dt;
    acc(A_EXT) += h * (p_ext + acc(A_P_EXT)) - w_drive;
    acc(A_AMOR) += h * (p_amor + acc(A_P_AMOR));
    acc(A_DCHOC) += d_choc;
    acc(A_WFROT) += w_frot;
    acc(A_NL) += h * (p_nl + acc(A_P_NL));
}

// energy.after_step: the hook of the loops after an accepted step
inline void after_step(const Balance& e, std::int64_t archived_before, std::int64_t archived_after,
                       double t, double dt, const F1& q, const F1& v, const F1& a, const F2& vint,
                       const Model& model) {
    accumulate(e, t, dt, q, v, a, vint, model);
    if (archived_after > archived_before) record(e, archived_after - 1, t);
}

}  // namespace energy
}  // namespace asterlite
