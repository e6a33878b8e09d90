// The adaptive embedded Runge-Kutta 5(4) (Cash-Karp) of the rate-form laws
// (asterlite.dynamics.laws.rk54, code_aster's rk5adp): DIS_VISC's and
// DIS_ECRO_TRAC's rates over a step, the relative velocity held constant.
#pragma once

#include <cmath>

#include "law_discrete_hardening.hpp"
#include "law_zener.hpp"
#include "python_math.hpp"
#include "views.hpp"

namespace asterlite {
namespace rk54 {

enum System : int { ZENER = 1, HARDENING = 2 };

// the Cash-Karp tableau, each constant the double Python computes (the same
// correctly rounded operations on the same literals)
constexpr double A21 = 0.2;
constexpr double A31 = 3.0 / 40.0, A32 = 9.0 / 40.0;
constexpr double A41 = 0.3, A42 = -0.9, A43 = 1.2;
constexpr double A51 = -11.0 / 54.0, A52 = 2.5, A53 = -70.0 / 27.0, A54 = 35.0 / 27.0;
constexpr double A61 = 1631.0 / 55296.0, A62 = 175.0 / 512.0, A63 = 575.0 / 13824.0;
constexpr double A64 = 44275.0 / 110592.0, A65 = 253.0 / 4096.0;
constexpr double B1 = 37.0 / 378.0, B3 = 250.0 / 621.0, B4 = 125.0 / 594.0;
constexpr double B6 = 512.0 / 1771.0;
constexpr double E1 = B1 - 2825.0 / 27648.0;
constexpr double E3 = B3 - 18575.0 / 48384.0;
constexpr double E4 = B4 - 13525.0 / 55296.0;
constexpr double E5 = -277.0 / 14336.0;
constexpr double E6 = B6 - 0.25;

constexpr double GROW_POWER = -0.20, SHRINK_POWER = -0.25;
constexpr double SAFETY = 0.90, FORCED_CUT = 0.30, MAX_GROWTH = 5.0;
// (MAX_GROWTH / SAFETY) ** (1.0 / GROW_POWER) as Python computed it
constexpr double GROWTH_THRESHOLD = 0x1.8c4568d7ea3e3p-13;
constexpr double TINY_SCALE = 1.0e-8;
constexpr double END_PRECISION = 1.0e-8;
constexpr double HUGE_ERROR = 1.0e8;
constexpr double SMALLEST_STEP = 1.0e-10;
constexpr index N_WORK = 9;

// rk54.rates: the system's rates at y
inline bool rates(int system, const F1& model, const F1& y, const F1& rate, const F1& dy) {
    if (system == ZENER) return zener::zener_rates(model, y, rate(0), dy);
    return discrete_hardening::hardening_rates(model, y, rate, dy);
}

// rk54.stage: out = y + h (a ka + b kb + c kc + d kd + e ke), zero weights included
inline void stage(const F1& y, double h, index n, const F1& out, const F1& ka, double a,
                  const F1& kb, double b, const F1& kc, double c, const F1& kd, double d,
                  const F1& ke, double e) {
    for (index i = 0; i < n; ++i) {
        out(i) = y(i) + h * (a * ka(i) + b * kb(i) + c * kc(i) + d * kd(i) + e * ke(i));
    }
}

// rk54.cash_karp_step: one embedded step from y, work row 7 the 5th-order
// solution, row 8 the error; false when the rates ask for a smaller step
inline bool cash_karp_step(int system, const F1& model, const F1& y, const F1& rate, double h,
                           index n, const F2& work) {
    const F1 k1 = row(work, 0), k2 = row(work, 1), k3 = row(work, 2), k4 = row(work, 3);
    const F1 k5 = row(work, 4), k6 = row(work, 5);
    const F1 ys = row(work, 6), y5 = row(work, 7), err = row(work, 8);
    if (!rates(system, model, y, rate, k1)) return false;
    stage(y, h, n, ys, k1, A21, k1, 0.0, k1, 0.0, k1, 0.0, k1, 0.0);
    if (!rates(system, model, ys, rate, k2)) return false;
    stage(y, h, n, ys, k1, A31, k2, A32, k1, 0.0, k1, 0.0, k1, 0.0);
    if (!rates(system, model, ys, rate, k3)) return false;
    stage(y, h, n, ys, k1, A41, k2, A42, k3, A43, k1, 0.0, k1, 0.0);
    if (!rates(system, model, ys, rate, k4)) return false;
    stage(y, h, n, ys, k1, A51, k2, A52, k3, A53, k4, A54, k1, 0.0);
    if (!rates(system, model, ys, rate, k5)) return false;
    stage(y, h, n, ys, k1, A61, k2, A62, k3, A63, k4, A64, k5, A65);
    if (!rates(system, model, ys, rate, k6)) return false;
    for (index i = 0; i < n; ++i) {
        y5(i) = y(i) + h * (B1 * k1(i) + B3 * k3(i) + B4 * k4(i) + B6 * k6(i));
        err(i) = h * (E1 * k1(i) + E3 * k3(i) + E4 * k4(i) + E5 * k5(i) + E6 * k6(i));
    }
    return true;
}

// rk54.adaptive_integrate: the system from y_in over dt into y_out (may be
// y_in); false when a sub-step failed max_attempts times in a row or sub-steps
// shrink below 1e-10 dt (y_out then holds the state reached so far)
inline bool adaptive_integrate(int system, const F1& model, const F1& y_in, const F1& rate,
                               double dt, index max_attempts, double tolerance, const F1& scales,
                               const F1& y_out, const F2& work) {
    const index n = y_out.n0;
    for (index i = 0; i < n; ++i) y_out(i) = y_in(i);
    if (dt <= 0.0) return true;
    double t = 0.0, h = dt;
    index attempts = 0;
    while (true) {
        if (attempts > max_attempts || h < SMALLEST_STEP * dt) return false;
        attempts += 1;
        if (!cash_karp_step(system, model, y_out, rate, h, n, work)) {
            h *= FORCED_CUT;
            continue;
        }
        double error = 0.0;
        bool blown = false;
        for (index i = 0; i < n; ++i) {
            double scale;
            if (scales.n0 == n) {
                scale = scales(i);
            } else {
                scale = std::fabs(y_out(i)) > TINY_SCALE ? std::fabs(y_out(i)) : 1.0;
            }
            const double e = std::fabs(work(8, i) / scale);
            if (e > HUGE_ERROR && std::log10(e) > 100.0) blown = true;
            error += e * e;
        }
        if (blown) {
            h *= FORCED_CUT;
            continue;
        }
        error = std::sqrt(error) / tolerance;
        if (error > 1.0) {
            h = py_max(0.1 * h, SAFETY * h * std::pow(error, SHRINK_POWER));
            continue;
        }
        for (index i = 0; i < n; ++i) y_out(i) = work(7, i);
        if (std::fabs(t + h - dt) <= END_PRECISION) return true;  // rk5adp: the end
        t += h;
        attempts = 0;
        h = error > GROWTH_THRESHOLD ? SAFETY * h * std::pow(error, GROW_POWER) : MAX_GROWTH * h;
        if (t + h > dt) h = dt - t;
    }
}

}  // namespace rk54
}  // namespace asterlite
