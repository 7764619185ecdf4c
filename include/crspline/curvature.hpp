// crspline: curvature of a Catmull-Rom segment along u, and where its
// maxima lie (Yuksel, Schaefer and Keyser 2011, Section 6.4), exactly from
// the roots of the derivative of curvature squared.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

#include "catmull_rom.hpp"
#include "detail/analysis_common.hpp"
#include "detail/polynomial.hpp"
#include "segment.hpp"
#include "vec.hpp"

namespace crspline {

/// Curvature |C' ^ C''| / |C'|^3 at local u (the same in u and t units);
/// nullopt where the speed is zero.
template <std::size_t D, class T>
std::optional<T> curvature(const cubic_segment<D, T>& s, T u) noexcept {
    const vec<D, T> d1 = s.du(u, 1), d2 = s.du(u, 2);
    const T sp = norm(d1);
    if (!(sp > 0)) return std::nullopt;
    // |d1 ^ d2|^2 as a sum of squared 2x2 minors (no cancellation).
    T w2 = 0;
    for (std::size_t i = 0; i < D; ++i)
        for (std::size_t j = i + 1; j < D; ++j) {
            const T m = d1[i] * d2[j] - d1[j] * d2[i];
            w2 += m * m;
        }
    return std::sqrt(w2) / (sp * sp * sp);
}

/// Where the curvature of a segment peaks.
template <class T = double>
struct curvature_maxima {
    T start = 0, end = 0;            ///< curvature at u = 0 and u = 1 (infinity at zero speed)
    std::vector<T> interior_u;       ///< interior local maxima, 0 < u < 1
    std::vector<T> interior_value;
    T max = 0, max_u = 0;            ///< the largest over [0, 1]
    /// The segment's largest curvature is at one of its ends, i.e. at a
    /// control point (Section 6.4's observation for centripetal curves).
    bool max_at_control_point() const noexcept { return max_u == 0 || max_u == 1; }
};

/// Curvature maxima of a segment: kappa^2 = N / S^3 with N = |C' ^ C''|^2
/// (degree 4, the sum of squared 2x2 minors) and S = |C'|^2 (degree 4); the
/// critical points are the roots of N' S - 3 N S' (degree 7).
template <std::size_t D, class T>
curvature_maxima<T> segment_curvature_maxima(const cubic_segment<D, T>& s) {
    curvature_maxima<T> m;
    const T inf = std::numeric_limits<T>::infinity();
    auto kappa = [&](T u) { return curvature(s, u).value_or(inf); };
    m.start = kappa(T(0));
    m.end = kappa(T(1));
    const std::array<vec<D, T>, 3> d1{s.c1, T(2) * s.c2, T(3) * s.c3};
    const std::array<vec<D, T>, 2> d2{T(2) * s.c2, T(6) * s.c3};
    std::array<T, 5> N{};
    for (std::size_t i = 0; i < D; ++i)
        for (std::size_t j = i + 1; j < D; ++j) {
            const std::array<T, 3> a{d1[0][i], d1[1][i], d1[2][i]}, b{d1[0][j], d1[1][j], d1[2][j]};
            const std::array<T, 2> da{d2[0][i], d2[1][i]}, db{d2[0][j], d2[1][j]};
            const auto p = detail::multiply(a, db), q = detail::multiply(b, da);
            std::array<T, 3> minor{};
            for (std::size_t k = 0; k < 3; ++k) minor[k] = p[k] - q[k];
            const auto sq = detail::multiply(minor, minor);
            for (std::size_t k = 0; k < 5; ++k) N[k] += sq[k];
        }
    const auto S = detail::dot_poly(d1, d1);
    const auto a = detail::multiply(detail::derivative(N), S), b = detail::multiply(N, detail::derivative(S));
    std::array<T, 8> crit{};
    for (std::size_t k = 0; k < 8; ++k) crit[k] = a[k] - T(3) * b[k];
    m.max = m.start;
    m.max_u = 0;
    if (m.end > m.max) { m.max = m.end; m.max_u = 1; }
    // The critical points, with the ends: kappa is monotone between
    // consecutive ones.
    detail::root_list<T, 10> cp;
    cp.push_back(T(0));
    for (T u : detail::real_roots(crit, T(0), T(1)))
        if (u > cp.back() && u < 1) cp.push_back(u);
    cp.push_back(T(1));
    for (std::size_t j = 1; j + 1 < cp.size(); ++j) {
        // A local maximum: above kappa halfway to the critical points on
        // either side (where it is monotone in exact arithmetic). Not
        // compared at a fixed small step: near a near-cusp (speed 1e-5 of
        // the coefficients' scale) the peak is narrower (1e-6, with kappa
        // 1e11) than the rounding of crit's roots there (crit is a
        // difference of terms 1e16 times larger than itself), so the root can
        // sit on the peak's flank, below a neighbour 1e-6 away.
        const T lo = cp[j - 1], hi = cp[j + 1], u = cp[j];
        const T k = kappa(u);
        if (!(k >= kappa(lo + (u - lo) / 2) && k >= kappa(u + (hi - u) / 2))) continue;
        // The maximum over (lo, hi), where kappa rises then falls: golden
        // section, to adjacent doubles (the root alone can miss the peak by
        // several widths).
        const T g = T(0.38196601125010515);  // (3 - sqrt 5) / 2
        T ga = lo, gb = hi, x1 = ga + g * (gb - ga), x2 = gb - g * (gb - ga), f1 = kappa(x1), f2 = kappa(x2);
        T best = k, best_u = u;
        auto keep = [&](T x, T f) {
            if (f > best) { best = f; best_u = x; }
        };
        for (int it = 0; it < 200 && x1 < x2; ++it) {
            keep(x1, f1);
            keep(x2, f2);
            if (f1 < f2) {
                ga = x1; x1 = x2; f1 = f2; x2 = gb - g * (gb - ga); f2 = kappa(x2);
            } else {
                gb = x2; x2 = x1; f2 = f1; x1 = ga + g * (gb - ga); f1 = kappa(x1);
            }
        }
        keep(x1, f1);
        keep(x2, f2);
        if (!m.interior_u.empty() && best_u == m.interior_u.back()) continue;  // one peak from two roots
        m.interior_u.push_back(best_u);
        m.interior_value.push_back(best);
        if (best > m.max) { m.max = best; m.max_u = best_u; }
    }
    return m;
}

}  // namespace crspline
