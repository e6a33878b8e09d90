// ROTOR_FISS (asterlite.dynamics.laws.rotor_fiss): a cracked rotor, a
// rotation-dependent stiffness between two nodes.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "formula.hpp"
#include "law_tabulated.hpp"
#include "views.hpp"

namespace asterlite {
namespace rotor_fiss {

constexpr index P_VARIABLE_SPEED = 0;
constexpr double CONSTANT_SPEED = 0.0, ANGLE_TABLE = 1.0, ANGLE_PROGRAM = 2.0;
constexpr index P_ANGLE0 = 1, P_SPEED = 2;
constexpr index P_AT_K = 3, P_AT_DK = 4, P_AT_ANGLE = 5;
constexpr index V_ANGLE = 0, V_MY = 1, V_MZ = 2;
constexpr double TWO_PI = 2.0 * M_PI;
constexpr index STACK_DEPTH = 32;  // formula.STACK_DEPTH

// rotor_fiss.program_value: the formula program packed at start ([n, n codes,
// n constants]) at t, run by the kernels' formula interpreter on fresh arrays
inline double program_value(const F1& params, index start, double t) {
    const index n = tabulated::to_int(params(start));
    std::vector<std::int64_t> code_data(n + 1, 0);
    std::vector<double> constant_data(n + 1, 0.0);
    std::vector<double> stack_data(STACK_DEPTH, 0.0);
    I2 codes;
    codes.data = code_data.data();
    codes.n0 = 1;
    codes.n1 = n + 1;
    F2 constants;
    constants.data = constant_data.data();
    constants.n0 = 1;
    constants.n1 = n + 1;
    F1 stack;
    stack.data = stack_data.data();
    stack.n0 = STACK_DEPTH;
    codes(0, 0) = n;
    for (index i = 0; i < n; ++i) {
        codes(0, 1 + i) = tabulated::to_int(params(start + 1 + i));
        constants(0, 1 + i) = params(start + 1 + n + i);
    }
    return run_program(codes, constants, 0, t, stack);
}

// rotor_fiss.rotor_angle: gamma(t)
inline double rotor_angle(const F1& params, double t) {
    const double source = params(P_VARIABLE_SPEED);
    const index at = tabulated::to_int(params(P_AT_ANGLE));
    if (source == ANGLE_TABLE) return tabulated::value(params, at, t);
    if (source == ANGLE_PROGRAM) return program_value(params, at, t);
    return params(P_ANGLE0) + params(P_SPEED) * t;
}

struct Moment {
    double x, y, z;
};

// rotor_fiss.cracked_rotor_moment: the global moment on node D; dtheta = theta_G
// - theta_D in the global frame
inline Moment cracked_rotor_moment(const F1& params, double t, const F2& rot_axis,
                                   double dtheta_x, double dtheta_y, double dtheta_z,
                                   const F1& state_out) {
    const double gamma = rotor_angle(params, t);
    double cg = std::cos(gamma), sg = std::sin(gamma);
    if (std::fabs(cg) < 1.0e-6) cg = 0.0;  // code_aster's rot3d zeroes such entries
    if (std::fabs(sg) < 1.0e-6) sg = 0.0;
    const double a =
        rot_axis(1, 0) * dtheta_x + rot_axis(1, 1) * dtheta_y + rot_axis(1, 2) * dtheta_z;
    const double b =
        rot_axis(2, 0) * dtheta_x + rot_axis(2, 1) * dtheta_y + rot_axis(2, 2) * dtheta_z;
    const double dy = cg * a + sg * b;  // turning frame: rotation by gamma about x
    const double dz = -sg * a + cg * b;
    double phi = std::atan2(dy, dz);
    if (phi < 0.0) phi += TWO_PI;
    const double k = tabulated::value(params, tabulated::to_int(params(P_AT_K)), phi);
    const double dk = tabulated::value(params, tabulated::to_int(params(P_AT_DK)), phi);
    const double my = k * dy + 0.5 * dk * dz;
    const double mz = k * dz - 0.5 * dk * dy;
    state_out(V_ANGLE) = phi * (180.0 / M_PI);  // math.degrees as numba compiles it
    state_out(V_MY) = my;
    state_out(V_MZ) = mz;
    // back to the axis frame, then to the global frame
    const double ma = cg * my - sg * mz;
    const double mb = sg * my + cg * mz;
    return {rot_axis(1, 0) * ma + rot_axis(2, 0) * mb, rot_axis(1, 1) * ma + rot_axis(2, 1) * mb,
            rot_axis(1, 2) * ma + rot_axis(2, 2) * mb};
}

}  // namespace rotor_fiss
}  // namespace asterlite
