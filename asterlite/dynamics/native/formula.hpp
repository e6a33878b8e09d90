// Formula load multipliers (asterlite.dynamics.formula): the postfix programs
// run with numpy's semantics and the C library's functions, operation for
// operation as the numba kernels run them (same values to the last bit).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include "layout.hpp"
#include "views.hpp"

namespace asterlite {

// a / b as numpy divides (inf or nan for b == 0)
inline double true_divide(double a, double b) {
    if (b != 0.0) return a / b;
    if (a != a || a == 0.0) return std::numeric_limits<double>::quiet_NaN();
    return std::copysign(INFINITY, a) * std::copysign(1.0, b);
}

// numpy.mod for floats: fmod moved to the sign of the divisor
inline double remainder(double a, double b) {
    if (b == 0.0) return std::numeric_limits<double>::quiet_NaN();
    double r = std::fmod(a, b);
    if (r != 0.0 && ((b < 0.0) != (r < 0.0))) r += b;
    return r;
}

// Python's math.floor/ceil/trunc return integers: numba converts to int64
// and back (what cvttsd2si gives out of range included)
inline double through_int64(double x) {
    return static_cast<double>(static_cast<std::int64_t>(x));
}

inline double unary_function(std::int64_t code, double x) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    switch (code) {
        case SIN: return std::sin(x);
        case COS: return std::cos(x);
        case EXP: return std::exp(x);
        case SQRT: return x >= 0.0 ? std::sqrt(x) : nan;
        case ABS: return std::fabs(x);
        case TAN: return std::tan(x);
        case ASIN: return std::fabs(x) <= 1.0 ? std::asin(x) : nan;
        case ACOS: return std::fabs(x) <= 1.0 ? std::acos(x) : nan;
        case ATAN: return std::atan(x);
        case SINH: return std::sinh(x);
        case COSH: return std::cosh(x);
        case TANH: return std::tanh(x);
        case ASINH: return std::asinh(x);
        case ACOSH: return x >= 1.0 ? std::acosh(x) : nan;
        case ATANH:
            if (std::fabs(x) < 1.0) return std::atanh(x);
            return std::fabs(x) == 1.0 ? std::copysign(INFINITY, x) : nan;
        case LOG: return x > 0.0 ? std::log(x) : (x == 0.0 ? -INFINITY : nan);
        case LOG10: return x > 0.0 ? std::log10(x) : (x == 0.0 ? -INFINITY : nan);
        case FLOOR: return std::fabs(x) < 1.0e300 ? through_int64(std::floor(x)) : x;
        case CEIL: return std::fabs(x) < 1.0e300 ? through_int64(std::ceil(x)) : x;
        case TRUNC: return std::fabs(x) < 1.0e300 ? through_int64(x) : x;
        case DEGREES: return x * (180.0 / M_PI);
        case RADIANS: return x * (M_PI / 180.0);
        default:  // SIGN, numpy's sign of one argument
            if (x > 0.0) return 1.0;
            if (x < 0.0) return -1.0;
            return x;
    }
}

inline double binary_function(std::int64_t code, double a, double b) {
    switch (code) {
        case ATAN2: return std::atan2(a, b);
        case HYPOT: return std::hypot(a, b);
        case MINIMUM: return (a < b || a != a) ? a : b;  // numpy.minimum: nan wins
        case MAXIMUM: return (a > b || a != a) ? a : b;
        case COPYSIGN: return std::copysign(std::fabs(a), b);
        case LESS: return a < b ? 1.0 : 0.0;
        case LESS_EQUAL: return a <= b ? 1.0 : 0.0;
        case GREATER: return a > b ? 1.0 : 0.0;
        case GREATER_EQUAL: return a >= b ? 1.0 : 0.0;
        case EQUAL: return a == b ? 1.0 : 0.0;
        case NOT_EQUAL: return a != b ? 1.0 : 0.0;
        case AND: return (a != 0.0 && b != 0.0) ? 1.0 : 0.0;
        default: return (a != 0.0 || b != 0.0) ? 1.0 : 0.0;  // OR
    }
}

// formula.run_program: the value of row ``row``'s program at time t, every
// operand kept in ``stack`` (what forces.add_external_force runs;
// program_value below keeps the top in a local: the same value)
inline double run_program(const I2& codes, const F2& constants, index row, double t,
                          const F1& stack) {
    index top = -1;
    const index length = codes(row, 0);
    for (index pc = 1; pc < length + 1; ++pc) {
        const std::int64_t code = codes(row, pc);
        if (code == PUSH_TIME) {
            top += 1;
            stack(top) = t;
        } else if (code == PUSH_CONSTANT) {
            top += 1;
            stack(top) = constants(row, pc);
        } else if (code < SIN) {  // arithmetic
            if (code == NEG) {
                stack(top) = -stack(top);
                continue;
            }
            const double b = stack(top);
            top -= 1;
            const double a = stack(top);
            if (code == ADD) {
                stack(top) = a + b;
            } else if (code == SUB) {
                stack(top) = a - b;
            } else if (code == MUL) {
                stack(top) = a * b;
            } else if (code == DIV) {
                stack(top) = true_divide(a, b);
            } else if (code == POW) {
                stack(top) = std::pow(a, b);
            } else if (code == MOD) {
                stack(top) = remainder(a, b);
            } else {  // FLOOR_DIV
                stack(top) = b != 0.0 ? (a - remainder(a, b)) / b : true_divide(a, b);
            }
        } else if (code < ATAN2) {  // functions of one argument
            stack(top) = unary_function(code, stack(top));
        } else if (code == SELECT) {
            const double otherwise = stack(top);
            const double chosen = stack(top - 1);
            top -= 2;
            stack(top) = stack(top) != 0.0 ? chosen : otherwise;
        } else if (code == NOT) {
            stack(top) = stack(top) == 0.0 ? 1.0 : 0.0;
        } else if (code == IDENTITY) {
            // nothing
        } else {  // functions of two arguments, comparisons, logic
            const double b = stack(top);
            top -= 1;
            stack(top) = binary_function(code, stack(top), b);
        }
    }
    return stack(0);
}

// Value of row ``row``'s program at time t (formula.program_value: the top
// of the stack in a local, ``stack`` holds the operands below it).
inline double program_value(const I2& codes, const F2& constants, index row, double t,
                            const F1& stack) {
    index top = -1;
    double x = 0.0;
    const index length = codes(row, 0);
    for (index pc = 1; pc < length + 1; ++pc) {
        const std::int64_t code = codes(row, pc);
        if (code == PUSH_CONSTANT || code == PUSH_TIME) {
            if (top >= 0) stack(top) = x;
            top += 1;
            x = code == PUSH_TIME ? t : constants(row, pc);
        } else if (code == SIN) {
            x = std::sin(x);
        } else if (code == COS) {
            x = std::cos(x);
        } else if (code < SIN) {  // arithmetic
            if (code == NEG) {
                x = -x;
                continue;
            }
            top -= 1;
            const double a = stack(top);
            if (code == MUL) {
                x = a * x;
            } else if (code == ADD) {
                x = a + x;
            } else if (code == SUB) {
                x = a - x;
            } else if (code == DIV) {
                x = true_divide(a, x);
            } else if (code == POW) {
                x = std::pow(a, x);
            } else if (code == MOD) {
                x = remainder(a, x);
            } else {  // FLOOR_DIV
                x = x != 0.0 ? (a - remainder(a, x)) / x : true_divide(a, x);
            }
        } else if (code < ATAN2) {  // the other functions of one argument
            x = unary_function(code, x);
        } else if (code == SELECT) {  // condition, chosen, otherwise (x)
            top -= 2;
            x = stack(top) != 0.0 ? stack(top + 1) : x;
        } else if (code == NOT) {
            x = x == 0.0 ? 1.0 : 0.0;
        } else if (code != IDENTITY) {  // functions of two arguments, comparisons, logic
            top -= 1;
            x = binary_function(code, stack(top), x);
        }
    }
    return x;
}

}  // namespace asterlite
