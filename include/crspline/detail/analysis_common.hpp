// crspline internal: helpers shared by the analysis headers (vector
// polynomials, orthonormal frames of a segment's span, robust angles).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "../segment.hpp"
#include "../vec.hpp"

namespace crspline::detail {

/// Coefficients (ascending) of a(u) . b(u) for vector polynomials a, b.
template <std::size_t D, class T, std::size_t N, std::size_t M>
constexpr std::array<T, N + M - 1> dot_poly(const std::array<vec<D, T>, N>& a,
                                            const std::array<vec<D, T>, M>& b) noexcept {
    std::array<T, N + M - 1> r{};
    for (std::size_t i = 0; i < N; ++i)
        for (std::size_t j = 0; j < M; ++j) r[i + j] += dot(a[i], b[j]);
    return r;
}

/// Vector polynomial sum_k a[k] u^k by Horner.
template <std::size_t D, class T, std::size_t N>
constexpr vec<D, T> horner_vec(const std::array<vec<D, T>, N>& a, T u) noexcept {
    vec<D, T> r{};
    for (std::size_t k = N; k-- > 0;) r = r * u + a[k];
    return r;
}

/// The power-basis coefficients of a segment relative to its origin:
/// {0, c1, c2, c3}.
template <std::size_t D, class T>
constexpr std::array<vec<D, T>, 4> relative_coefficients(const cubic_segment<D, T>& s) noexcept {
    return {vec<D, T>{}, s.c1, s.c2, s.c3};
}

/// Orthonormal basis of span{w[0], w[1], w[2]} by modified Gram-Schmidt with
/// pivoting (largest residual first, orthogonalized twice). A residual of
/// norm <= tol counts as zero; rank is the number of vectors kept.
template <std::size_t D, class T>
struct span_frame {
    std::size_t rank = 0;
    std::array<vec<D, T>, 3> e{};
};

template <std::size_t D, class T>
span_frame<D, T> orthonormal_span(std::array<vec<D, T>, 3> w, T tol) noexcept {
    span_frame<D, T> f;
    std::array<bool, 3> used{};
    for (std::size_t k = 0; k < std::min<std::size_t>(3, D); ++k) {
        std::size_t best = 3;
        T best_n = 0;
        for (std::size_t j = 0; j < 3; ++j)
            if (!used[j]) {
                const T n = norm(w[j]);
                if (best == 3 || n > best_n) { best = j; best_n = n; }
            }
        if (best == 3 || !(best_n > tol)) break;
        used[best] = true;
        const vec<D, T> e = w[best] / best_n;
        f.e[f.rank++] = e;
        for (int pass = 0; pass < 2; ++pass)
            for (std::size_t j = 0; j < 3; ++j)
                if (!used[j]) w[j] -= dot(w[j], e) * e;
    }
    return f;
}

/// Angle between two nonzero vectors in [0, pi], accurate near 0 and pi
/// (Kahan: 2 atan2(|a^ - b^|, |a^ + b^|)).
template <std::size_t D, class T>
T angle_between(const vec<D, T>& a, const vec<D, T>& b) noexcept {
    const vec<D, T> ua = a / norm(a), ub = b / norm(b);
    return T(2) * std::atan2(norm(ua - ub), norm(ua + ub));
}

/// Component of v perpendicular to the unit vector e.
template <std::size_t D, class T>
constexpr vec<D, T> perpendicular_part(const vec<D, T>& v, const vec<D, T>& e) noexcept {
    return v - dot(v, e) * e;
}

/// Distance from x to the closed segment [a, b].
template <std::size_t D, class T>
T distance_to_segment(const vec<D, T>& x, const vec<D, T>& a, const vec<D, T>& b) noexcept {
    const vec<D, T> ab = b - a;
    const T len2 = dot(ab, ab);
    if (!(len2 > 0)) return norm(x - a);
    const T lambda = std::clamp(dot(x - a, ab) / len2, T(0), T(1));
    return norm(x - (a + lambda * ab));
}

}  // namespace crspline::detail
