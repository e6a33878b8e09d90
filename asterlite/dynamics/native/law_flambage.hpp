// FLAMBAGE (asterlite.dynamics.laws.flambage): a shock on a support that
// buckles, code_aster 17's functions of the crushing or code_aster 15's scalar law.
#pragma once

#include "law_tabulated.hpp"
#include "python_math.hpp"
#include "views.hpp"

namespace asterlite {
namespace flambage {

constexpr index P_DAMPING_IN_CRITERION = 0;
constexpr index P_AT_FX = 1, P_AT_RIGI = 2, P_AT_AMOR = 3;
constexpr index P_SCALAR = 4;
constexpr index HEADER = 5;
constexpr index S_KNORM = HEADER, S_CNORM = HEADER + 1, S_FLIM = HEADER + 2;
constexpr index S_FPOST = HEADER + 3, S_ENFO = HEADER + 4, S_DEFT0 = HEADER + 5;
constexpr index S_COUNT = HEADER + 6, S_POINTS = HEADER + 7;

constexpr index V_FN = 0, V_LOC1 = 1, V_LOC2 = 4, V_VN = 7, V_DEFPLA = 8, V_RIGI = 9;
constexpr index V_DEFMAX = 10, V_AMOR = 11;

struct ScalarLaw {
    double fn, defpla, rigi, amor;
};

// flambage._scalar_law: (force, crushing, stiffness, damping) at the penetration u >= 0
inline ScalarLaw scalar_law(const F1& params, double u, double vn, bool included, double defpla,
                            double rigi, double umax, double amor) {
    const double knorm = params(S_KNORM), cnorm = params(S_CNORM);
    const double flim = params(S_FLIM), fpost = params(S_FPOST);
    const double enfo = params(S_ENFO), deft0 = params(S_DEFT0);
    const double damping = included ? amor : 0.0;
    double fn = 0.0;
    if (defpla <= 0.0) {  // not buckled yet
        const double c0 = included ? cnorm : 0.0;
        if (u < (flim + c0 * vn) / knorm) {
            fn = py_max(knorm * u - c0 * vn, 0.0);
        } else {  // buckling starts
            fn = flim;
            defpla = 1.0e-20;
        }
        return {fn, defpla, knorm, cnorm};
    }
    if (u < defpla) return {0.0, defpla, rigi, amor};  // inside the gap the crushing opened
    const index n = tabulated::to_int(params(S_COUNT));
    const F1 crush = tabulated::part(params, S_POINTS, S_POINTS + n);
    const F1 total = tabulated::part(params, S_POINTS + n, S_POINTS + 2 * n);
    const F1 damps = tabulated::part(params, S_POINTS + 2 * n, S_POINTS + 3 * n);
    if (vn > 0.0 || u <= umax) {  // unloading, or reloading below the largest penetration
        fn = -rigi * (defpla - u) - damping * vn;
        if (included) {
            const double ramp = flim + ((fpost - flim) / enfo) * (u - deft0);
            if (u < deft0 && fn >= flim) {
                fn = flim;
            } else if (fn >= ramp && u < total(0)) {
                fn = ramp;
            } else if (fn >= fpost && u >= total(0)) {
                fn = fpost;
            }
            fn = py_max(fn, 0.0);
        }
        return {fn, defpla, rigi, amor};
    }
    if (u < deft0) {  // on the plateau: the crushing follows
        fn = flim;
        defpla = u - flim / rigi;
    }
    if (deft0 <= u && u < total(0)) {  // the drop to the post-buckling force
        fn = flim + ((fpost - flim) / enfo) * (u - deft0);
        rigi = fn / (u - defpla);
        defpla = crush(0);
        amor = cnorm + ((damps(0) - cnorm) / enfo) * (u - deft0);
    }
    if (u >= total(0) && n < 2) {
        fn = fpost;
        rigi = fpost / (total(0) - crush(0));
        defpla = u - fpost / rigi;
        amor = damps(0);
    } else {
        for (index j = 0; j < n - 1; ++j) {
            if (total(j) <= u && u < total(j + 1)) {
                const double alpha = (u - total(j)) / (total(j + 1) - total(j));
                fn = fpost;
                defpla = crush(j) + alpha * (crush(j + 1) - crush(j));
                amor = damps(j) + alpha * (damps(j + 1) - damps(j));
                rigi = fpost / (u - defpla);
            }
        }
        if (u > total(n - 1)) {  // beyond the last point: its branch continued
            fn = fpost;
            rigi = fpost / (total(n - 1) - crush(n - 1));
            defpla = u - fpost / rigi;
            amor = damps(n - 1);
        }
    }
    return {fn, defpla, rigi, amor};
}

// flambage.scalar_buckling_force: buckling_force with code_aster 15's scalar law
inline double scalar_buckling_force(const F1& params, double gap, double vn, const F1& state_in,
                                    const F1& state_out) {
    const bool included = params(P_DAMPING_IN_CRITERION) != 0.0;
    double defpla = state_in(V_DEFPLA);
    double rigi = state_in(V_RIGI);
    double umax = state_in(V_DEFMAX);
    double amor = state_in(V_AMOR);
    double fn = 0.0;
    if (gap <= 0.0) {
        const double u = -gap;
        const ScalarLaw law = scalar_law(params, u, vn, included, defpla, rigi, umax, amor);
        fn = law.fn;
        defpla = law.defpla;
        rigi = law.rigi;
        amor = law.amor;
        if (defpla < 0.0) defpla = 0.0;
        if (u > umax) umax = u;
        if (!included) {
            fn -= amor * vn;
            if (fn < 0.0 || u < defpla) fn = 0.0;
        }
    } else {
        vn = 0.0;
    }
    state_out(V_FN) = fn;
    state_out(V_VN) = vn;
    state_out(V_DEFPLA) = defpla;
    state_out(V_DEFMAX) = umax;
    state_out(V_RIGI) = rigi;
    state_out(V_AMOR) = amor;
    return fn;
}

// flambage.buckling_force: the normal force magnitude F >= 0; the memory from
// state_in into state_out (the same array allowed); NaN outside an EXCLU domain
inline double buckling_force(const F1& params, double gap, double vn, const F1& state_in,
                             const F1& state_out) {
    if (params(P_SCALAR) == 1.0) return scalar_buckling_force(params, gap, vn, state_in, state_out);
    double defpla = state_in(V_DEFPLA);
    double umax = state_in(V_DEFMAX);
    double rigi = state_in(V_RIGI);
    double amor = state_in(V_AMOR);
    double fn = 0.0;
    if (gap <= 0.0) {
        if (-gap > umax) umax = -gap;
        const double crit = tabulated::value(params, tabulated::to_int(params(P_AT_FX)), umax);
        rigi = tabulated::value(params, tabulated::to_int(params(P_AT_RIGI)), umax);
        amor = tabulated::value(params, tabulated::to_int(params(P_AT_AMOR)), umax);
        const bool included = params(P_DAMPING_IN_CRITERION) != 0.0;
        fn = -rigi * (gap + defpla) - (included ? amor * vn : 0.0);
        if (fn >= crit) {
            fn = crit;
            defpla = -gap - crit / rigi;  // crushing follows, the force stays on the threshold
        }
        if (defpla < 0.0) defpla = 0.0;
        if (!included) fn -= amor * vn;
        if (fn < 0.0 || -gap < defpla) fn = 0.0;  // only pushes, not across the opened gap
    } else {
        vn = 0.0;
    }
    state_out(V_FN) = fn;
    state_out(V_VN) = vn;
    state_out(V_DEFPLA) = defpla;
    state_out(V_DEFMAX) = umax;
    state_out(V_RIGI) = rigi;
    state_out(V_AMOR) = amor;
    return fn;
}

}  // namespace flambage
}  // namespace asterlite
