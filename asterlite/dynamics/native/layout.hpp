// The positions the kernels share with the Python side, as numbers. Each is
// defined in Python (asterlite.dynamics.kernel, .contact, asterlite.lang.numeric);
// the extension reports these (layout()) and tests/test_native_loops.py
// checks them against the Python ones.
#pragma once

#include <cfloat>
#include <cmath>

namespace asterlite {

// kernel.py: status codes, clock[] and counters[] slots, archive info columns
enum Status : int {
    STATUS_DONE = 0,
    STATUS_NOT_FINITE = 1,
    STATUS_SHOCK_DIVERGED = 2,
    STATUS_STEP_UNDERFLOW = 3,
    STATUS_REJECTED = 4,
    STATUS_SWITCH_NOT_LOCATED = 5,
    STATUS_FULL = 10,
    STATUS_LOADS = 11,
    STATUS_PAUSE = 12,
    // not a kernel status: numba's step raised ZeroDivisionError there (its
    // error model is Python's: a float division by zero raises); a loop
    // returns it at once and its binding raises the same (loop_status)
    STATUS_ZERO_DIVISION = 100,
};
enum ClockSlot : int { C_TIME, C_STEP, C_STEP0, C_END, C_NEWDT, C_MIN_STEP, C_MAX_STEP, C_ORIGIN };
enum CounterSlot : int {
    K_STEP, K_ARCHIVED, K_INSTANT, K_FORCE, K_IRREGULAR, K_REJECTED, K_ADAPTIVE, K_SHOCK,
    K_PAUSE_AT, K_GRID,
};
enum InfoColumn : int { INFO_STEP, INFO_REJECTED };
constexpr double GRID_TOLERANCE = 1.0e-6;

// contact.py: obstacle geometries, parameter and flag columns, internal variables
enum GeometryCode : int { PLAN_Y, PLAN_Z, CERCLE, DISCRET, BI_PLAN_Y, BI_PLAN_Z, BI_CERCLE, BI_CERC_INT };
enum ParamColumn : int {
    P_GAP, P_DIST1, P_DIST2, P_KN, P_CN, P_KT, P_CT, P_MU_DYN, P_MU_STAT, P_SIGN_Y, P_SIGN_Z,
    P_ORIGIN = 11, P_COORD1 = 14, P_COORD2 = 17, P_DRIVE1 = 20, P_DRIVE2 = 26,
    P_LIN_GAP = 32, P_LIN_COS = 33, P_LIN_SIN = 34,  // the implicit treatment's linearisation
};
enum FlagColumn : int { F_GEOMETRY, F_TWO_NODES, F_UNIDIR, F_NPOLAR, F_LAW, F_IMPLICIT };
// flags[s, F_IMPLICIT]: how the normal force enters (implicit_shocks.py)
enum NormalMode : int { NORMAL_EXPLICIT, NORMAL_LINEARISED, NORMAL_LEFT_OUT };
enum VintColumn : int {
    V_FN = 0, V_FT1 = 1, V_FT2 = 2, V_LOC1 = 3, V_LOC2 = 6, V_VN = 9, V_VT1 = 10, V_VT2 = 11,
    V_STICK = 12, V_FT_REF = 13, V_X_REF = 15, V_VT_OLD = 18,
};
constexpr double SLIP_VELOCITY_FLOOR = 1.0e-6;
constexpr double EPS = DBL_EPSILON;
inline const double VELOCITY_DIVERGENCE = 0.5 * std::sqrt(DBL_MAX);

// asterlite.lang.numeric: the operation codes of formula programs
enum OpCode : int {
    PUSH_CONSTANT = 0, PUSH_TIME = 1,
    ADD = 2, SUB, MUL, DIV, POW, MOD, FLOOR_DIV, NEG,
    SIN = 10, COS, TAN, ASIN, ACOS, ATAN, SINH, COSH, TANH,
    ASINH = 19, ACOSH, ATANH, EXP, LOG, LOG10, SQRT, ABS,
    FLOOR = 27, CEIL, TRUNC, DEGREES, RADIANS, SIGN,
    ATAN2 = 33, HYPOT, MINIMUM, MAXIMUM, COPYSIGN,
    LESS = 38, LESS_EQUAL, GREATER, GREATER_EQUAL, EQUAL, NOT_EQUAL,
    AND = 44, OR, NOT, SELECT, IDENTITY,
};

}  // namespace asterlite
