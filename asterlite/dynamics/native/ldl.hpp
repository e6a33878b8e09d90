// Sparse LDLᵀ of complex symmetric matrices (asterlite/harmonic/ldl.py's
// _symbolic, _numeric, _solve: T. A. Davis's up-looking algorithm), templated
// over the index types of the arrays (int32 or int64, as numba compiles one
// specialisation per type). Complex arithmetic written out on the real and
// imaginary parts as numba compiles it (CPython's _Py_c_prod and _Py_c_quot),
// not std::complex's operators (__muldc3 and __divdc3 round differently).
#pragma once

#include <patchlevel.h>  // PY_VERSION_HEX: numba's complex arithmetic follows the running Python

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "views.hpp"

namespace asterlite::ldl {

// numpy's complex128 in memory: the real part, then the imaginary part
struct Complex {
    double re, im;
};
static_assert(sizeof(Complex) == 16, "complex128 is two doubles");

using C1 = View1<Complex>;

// the statuses beside numba's returns (a column, or -1): numba raised
// ZeroDivisionError; the arrays are not those of one analysis (numba reads
// out of bounds there; the caller's arrays always are)
constexpr index ZERO_DIVISION = -2;
constexpr index INCONSISTENT = -3;

// From Python 3.14 numba recovers the infinities CPython's products and
// quotients compute as nan+nanj (utils.PYVERSION >= (3, 14))
constexpr bool RECOVER_INFINITIES = PY_VERSION_HEX >= 0x030E0000;

constexpr double NAN_VALUE = std::numeric_limits<double>::quiet_NaN();
constexpr double INF_VALUE = std::numeric_limits<double>::infinity();

inline Complex add(Complex z, Complex w) { return {z.re + w.re, z.im + w.im}; }
inline Complex sub(Complex z, Complex w) { return {z.re - w.re, z.im - w.im}; }

// 1.0 or 0.0 with the sign of x as math.copysign(1.0 if isinf(x) else 0.0, x)
inline double unit_if_infinite(double x) {
    return std::copysign(std::isinf(x) ? 1.0 : 0.0, x);
}
inline double zero_if_nan(double x) { return std::isnan(x) ? std::copysign(0.0, x) : x; }

// z * w: numba's complex_mul (CPython's _Py_c_prod)
inline Complex mul(Complex z, Complex w) {
    double a = z.re, b = z.im, c = w.re, d = w.im;
    const double ac = a * c;
    const double bd = b * d;
    const double ad = a * d;
    const double bc = b * c;
    double real = ac - bd;
    double imag = ad + bc;
    if constexpr (RECOVER_INFINITIES) {
        if (std::isnan(real) && std::isnan(imag)) {
            bool recalc = false;
            if (std::isinf(a) || std::isinf(b)) {  // z is infinite
                a = unit_if_infinite(a);
                b = unit_if_infinite(b);
                c = zero_if_nan(c);
                d = zero_if_nan(d);
                recalc = true;
            }
            if (std::isinf(c) || std::isinf(d)) {  // w is infinite
                c = unit_if_infinite(c);
                d = unit_if_infinite(d);
                a = zero_if_nan(a);
                b = zero_if_nan(b);
                recalc = true;
            }
            if (!recalc &&
                (std::isinf(ac) || std::isinf(bd) || std::isinf(ad) || std::isinf(bc))) {
                a = zero_if_nan(a);
                b = zero_if_nan(b);
                c = zero_if_nan(c);
                d = zero_if_nan(d);
                recalc = true;
            }
            if (recalc) {
                real = INF_VALUE * (a * c - b * d);
                imag = INF_VALUE * (a * d + b * c);
            }
        }
    }
    return {real, imag};
}

// a / b: numba's complex_div (CPython's _Py_c_quot, Smith's algorithm);
// false where numba raises ZeroDivisionError (b an exact zero, either sign)
inline bool divide(Complex a, Complex b, Complex& res) {
    const double areal = a.re, aimag = a.im, breal = b.re, bimag = b.im;
    const double abs_breal = std::fabs(breal);
    const double abs_bimag = std::fabs(bimag);
    if (abs_breal >= abs_bimag) {
        if (abs_breal == 0.0) return false;
        const double ratio = bimag / breal;
        const double denom = breal + bimag * ratio;
        res = {(areal + aimag * ratio) / denom, (aimag - areal * ratio) / denom};
    } else if (abs_bimag >= abs_breal) {
        const double ratio = breal / bimag;
        const double denom = breal * ratio + bimag;
        res = {(areal * ratio + aimag) / denom, (aimag * ratio - areal) / denom};
    } else {  // b.real or b.imag is a NaN
        res = {NAN_VALUE, NAN_VALUE};
    }
    if constexpr (RECOVER_INFINITIES) {
        if (std::isnan(res.re) && std::isnan(res.im)) {
            if ((std::isinf(areal) || std::isinf(aimag)) && std::isfinite(breal) &&
                std::isfinite(bimag)) {
                const double x = unit_if_infinite(areal);
                const double y = unit_if_infinite(aimag);
                res = {INF_VALUE * (x * breal + y * bimag), INF_VALUE * (y * breal - x * bimag)};
            } else if ((std::isinf(abs_breal) || std::isinf(abs_bimag)) &&
                       std::isfinite(areal) && std::isfinite(aimag)) {
                const double x = unit_if_infinite(breal);
                const double y = unit_if_infinite(bimag);
                res = {0.0 * (areal * x + aimag * y), 0.0 * (aimag * x - areal * y)};
            }
        }
    }
    return true;
}

// z == 0.0 for a complex z (both parts compared: -0.0 is a zero, NaN is not)
inline bool is_zero(Complex z) { return z.re == 0.0 && z.im == 0.0; }

// _symbolic: the elimination tree ``parent`` and the column counts ``lnz``
// (n entries each, written) of L from the upper triangle of a CSC pattern
// (``ap``, ``ai``); the fill, or -1 once it exceeds ``limit`` (parent then
// holds only the columns reached, as numba's np.empty does). ``ai`` holds
// rows in [0, n) (the caller checks).
template <class P, class I>
index symbolic(index n, const View1<P>& ap, const View1<I>& ai, std::int64_t limit,
               const I1& parent, const I1& lnz) {
    std::vector<std::int64_t> flag(static_cast<std::size_t>(n));
    for (index k = 0; k < n; ++k) lnz(k) = 0;
    std::int64_t total = 0;
    for (index k = 0; k < n; ++k) {
        if (total > limit) return -1;
        parent(k) = -1;
        flag[k] = k;
        for (index p = ap(k); p < static_cast<index>(ap(k + 1)); ++p) {
            index i = ai(p);
            if (i < k) {
                while (flag[i] != k) {
                    if (parent(i) == -1) parent(i) = k;
                    lnz(i) += 1;
                    total += 1;
                    flag[i] = k;
                    i = parent(i);
                }
            }
        }
    }
    return total;
}

// _numeric: L (CSC ``lp``, ``li``, ``lx``, unit diagonal not stored) and D
// of A = L D Lᵀ from the upper triangle of A (``ap``, ``ai``, ``ax``) and the
// elimination tree ``parent``; -1, or the column whose pivot vanished (or
// ZERO_DIVISION, INCONSISTENT). ``ai`` holds rows in [0, n) and ``lp`` is
// nondecreasing within li's and lx's sizes (the caller checks); a ``parent``
// or ``lp`` not of this pattern's analysis stops at INCONSISTENT before any
// access out of bounds.
template <class P, class I, class LP, class E, class LI>
index numeric(index n, const View1<P>& ap, const View1<I>& ai, const C1& ax, const View1<LP>& lp,
              const View1<E>& parent, const View1<LI>& li, const C1& lx, const C1& d) {
    std::vector<Complex> y(static_cast<std::size_t>(n), Complex{0.0, 0.0});
    std::vector<std::int64_t> flag(static_cast<std::size_t>(n), -1);
    std::vector<std::int64_t> pattern(static_cast<std::size_t>(n));
    std::vector<std::int64_t> lnz(static_cast<std::size_t>(n), 0);
    for (index k = 0; k < n; ++k) {
        y[k] = {0.0, 0.0};
        index top = n;
        flag[k] = k;
        for (index p = ap(k); p < static_cast<index>(ap(k + 1)); ++p) {
            index i = ai(p);
            if (i <= k) {
                y[i] = add(y[i], ax(p));
                index length = 0;
                while (flag[i] != k) {
                    pattern[length] = i;
                    length += 1;
                    flag[i] = k;
                    i = parent(i);
                    // the path from a row of column k climbs the tree to k
                    if (i < 0 || i > k) return INCONSISTENT;
                }
                while (length > 0) {
                    top -= 1;
                    length -= 1;
                    pattern[top] = pattern[length];
                }
            }
        }
        d(k) = y[k];
        y[k] = {0.0, 0.0};
        while (top < n) {
            const index i = pattern[top];
            top += 1;
            const Complex yi = y[i];
            y[i] = {0.0, 0.0};
            const index p2 = static_cast<index>(lp(i)) + lnz[i];
            if (p2 >= static_cast<index>(lp(i + 1))) return INCONSISTENT;  // column i is full
            for (index p = lp(i); p < p2; ++p) {
                const index r = li(p);
                y[r] = sub(y[r], mul(lx(p), yi));
            }
            Complex l_ki;
            if (!divide(yi, d(i), l_ki)) return ZERO_DIVISION;
            d(k) = sub(d(k), mul(l_ki, yi));
            li(p2) = static_cast<LI>(k);
            lx(p2) = l_ki;
            lnz[i] += 1;
        }
        if (is_zero(d(k))) return k;
    }
    return -1;
}

// _solve: x := A⁻¹ x with A = L D Lᵀ, in place; -1, or ZERO_DIVISION (a zero
// of d: numba raises there, x solved up to that row). ``lp`` nondecreasing
// within li's and lx's sizes, ``li`` in [0, n) (the caller checks).
template <class LP, class LI>
index solve(index n, const View1<LP>& lp, const View1<LI>& li, const C1& lx, const C1& d,
            const C1& x) {
    for (index j = 0; j < n; ++j) {
        const Complex xj = x(j);
        for (index p = lp(j); p < static_cast<index>(lp(j + 1)); ++p) {
            const index r = li(p);
            x(r) = sub(x(r), mul(lx(p), xj));
        }
    }
    for (index j = 0; j < n; ++j) {
        if (!divide(x(j), d(j), x(j))) return ZERO_DIVISION;
    }
    for (index j = n - 1; j > -1; --j) {
        Complex s = x(j);
        for (index p = lp(j); p < static_cast<index>(lp(j + 1)); ++p) {
            s = sub(s, mul(lx(p), x(li(p))));
        }
        x(j) = s;
    }
    return -1;
}

}  // namespace asterlite::ldl
