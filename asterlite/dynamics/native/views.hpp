// C-ordered views of the numpy arrays the loops receive: a pointer and a
// shape, indexed as numba indexes them (no bounds checks, as there).
#pragma once

#include <cstdint>

namespace asterlite {

using index = std::int64_t;

template <class T>
struct View1 {
    T* data = nullptr;
    index n0 = 0;
    T& operator()(index i) const { return data[i]; }
};

template <class T>
struct View2 {
    T* data = nullptr;
    index n0 = 0, n1 = 0;
    T& operator()(index i, index j) const { return data[i * n1 + j]; }
};

template <class T>
struct View3 {
    T* data = nullptr;
    index n0 = 0, n1 = 0, n2 = 0;
    T& operator()(index i, index j, index k) const { return data[(i * n1 + j) * n2 + k]; }
};

template <class T>
struct View4 {
    T* data = nullptr;
    index n0 = 0, n1 = 0, n2 = 0, n3 = 0;
    T& operator()(index i, index j, index k, index l) const {
        return data[((i * n1 + j) * n2 + k) * n3 + l];
    }
};

using F1 = View1<double>;
using F2 = View2<double>;
using F3 = View3<double>;
using F4 = View4<double>;
using I1 = View1<std::int64_t>;
using I2 = View2<std::int64_t>;

// a[r], as numba's view of a row
inline F1 row(const F2& a, index r) {
    F1 view;
    view.data = a.data + r * a.n1;
    view.n0 = a.n1;
    return view;
}

// a[k], as numba's view of a 2-D slice
inline F2 slice(const F3& a, index k) {
    F2 view;
    view.data = a.data + k * a.n1 * a.n2;
    view.n0 = a.n1;
    view.n1 = a.n2;
    return view;
}

}  // namespace asterlite
