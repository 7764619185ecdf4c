// crspline: fixed-dimension vector value type used inside the library.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

namespace crspline {

/// A point or vector in D dimensions with scalar type T. An aggregate, so
/// `vec<2>{{1.0, 2.0}}` works and it is trivially copyable.
template <std::size_t D, class T = double>
struct vec {
    static_assert(D >= 1, "crspline: dimension must be at least 1");
    static_assert(std::is_floating_point_v<T>, "crspline: scalar must be float or double");
    using value_type = T;
    static constexpr std::size_t dimension = D;

    std::array<T, D> v{};

    constexpr T& operator[](std::size_t i) noexcept { return v[i]; }
    constexpr const T& operator[](std::size_t i) const noexcept { return v[i]; }
    constexpr T* data() noexcept { return v.data(); }
    constexpr const T* data() const noexcept { return v.data(); }
    static constexpr std::size_t size() noexcept { return D; }

    constexpr vec& operator+=(const vec& o) noexcept { for (std::size_t i = 0; i < D; ++i) v[i] += o.v[i]; return *this; }
    constexpr vec& operator-=(const vec& o) noexcept { for (std::size_t i = 0; i < D; ++i) v[i] -= o.v[i]; return *this; }
    constexpr vec& operator*=(T s) noexcept { for (std::size_t i = 0; i < D; ++i) v[i] *= s; return *this; }
    constexpr vec& operator/=(T s) noexcept { for (std::size_t i = 0; i < D; ++i) v[i] /= s; return *this; }

    friend constexpr vec operator+(vec a, const vec& b) noexcept { return a += b; }
    friend constexpr vec operator-(vec a, const vec& b) noexcept { return a -= b; }
    friend constexpr vec operator-(vec a) noexcept { for (auto& x : a.v) x = -x; return a; }
    friend constexpr vec operator*(vec a, T s) noexcept { return a *= s; }
    friend constexpr vec operator*(T s, vec a) noexcept { return a *= s; }
    friend constexpr vec operator/(vec a, T s) noexcept { return a /= s; }
    friend constexpr bool operator==(const vec&, const vec&) = default;
};

template <std::size_t D, class T>
constexpr T dot(const vec<D, T>& a, const vec<D, T>& b) noexcept {
    T s = 0;
    for (std::size_t i = 0; i < D; ++i) s += a[i] * b[i];
    return s;
}

/// Largest absolute component (the infinity norm).
template <std::size_t D, class T>
constexpr T max_abs(const vec<D, T>& a) noexcept {
    // |x| by std::abs at run time (a mask, no branch on the sign, which
    // random data mispredicts half the time); std::abs is constexpr only
    // from C++23.
    T m = 0;
    for (std::size_t i = 0; i < D; ++i)
        m = std::max(m, std::is_constant_evaluated() ? (a[i] < 0 ? -a[i] : a[i]) : std::abs(a[i]));
    return m;
}

namespace detail {
/// Whether norm() takes the plain formula sqrt(a . a) for a vector whose
/// largest absolute component is m: while the squares neither overflow nor
/// lose digits to subnormals (for double: about 1e-138 < m < 1e153).
/// fill_intervals() makes the same choice, so it must ask here.
template <std::size_t D, class T>
[[gnu::always_inline]] inline bool plain_norm_range(T m) noexcept {
    const T lo = std::sqrt(std::numeric_limits<T>::min()) / std::numeric_limits<T>::epsilon();
    const T hi = std::sqrt(std::numeric_limits<T>::max() / T(D));
    return m > lo && m < hi;
}

/// norm() when the squares would overflow or lose digits: rescaled by m.
template <std::size_t D, class T>
[[gnu::noinline, gnu::cold]] T norm_rescaled(const vec<D, T>& a, T m) noexcept {
    T s = 0;
    for (std::size_t i = 0; i < D; ++i) { const T x = a[i] / m; s += x * x; }
    return m * std::sqrt(s);
}
}  // namespace detail

/// Euclidean norm. sqrt(a . a) as NumPy computes it (so knots agree with
/// the `splines` package bit for bit in the common case), rescaled only when
/// the squares would overflow or underflow. The common case is small enough
/// to inline (arc-length integrands call it millions of times).
template <std::size_t D, class T>
[[gnu::always_inline]] inline T norm(const vec<D, T>& a) noexcept {
    if constexpr (D == 1) {
        return std::abs(a[0]);
    } else {
        const T m = max_abs(a);
        if (detail::plain_norm_range<D>(m)) [[likely]] return std::sqrt(dot(a, a));
        if (m == 0 || !std::isfinite(m)) return m;
        return detail::norm_rescaled(a, m);
    }
}

/// Linear interpolation written as in the paper's pyramid:
/// (b - t) / (b - a) * p + (t - a) / (b - a) * q.
template <std::size_t D, class T>
constexpr vec<D, T> lerp(const vec<D, T>& p, const vec<D, T>& q, T w) noexcept {
    return (T(1) - w) * p + w * q;
}

}  // namespace crspline
