// crspline: the paper's closed forms for a Catmull-Rom segment (Yuksel,
// Schaefer and Keyser 2011): with r = d1 / d2 and alpha the knot exponent,
// the Eq. 6 and Eq. 8 factors and the bounds of one segment (paper_bounds),
// which analysis.hpp reports beside what it measures.
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

#include "detail/analysis_common.hpp"
#include "parameterization.hpp"
#include "segment.hpp"
#include "vec.hpp"

namespace crspline {


/// Eq. 5: distance of B1 to the chord line, d2 r^(1-a) |sin theta| / (3 (1 + r^a)),
/// theta the polygon angle at P1 (between P0 - P1 and P2 - P1).
template <class T>
T paper_eq5(T d2, T r, T theta, double alpha) noexcept {
    const T a = T(alpha);
    return d2 * std::pow(r, 1 - a) * std::abs(std::sin(theta)) / (3 * (1 + std::pow(r, a)));
}

/// Eq. 6 for one side: d2 r^(1-a) / (4 (1 + r^a)). The paper prints only the
/// side r = d1/d2; the bound on the whole segment needs the larger of the two
/// sides (paper_eq6_two_sided).
template <class T>
T paper_eq6(T d2, T r, double alpha) noexcept {
    const T a = T(alpha);
    return d2 * std::pow(r, 1 - a) / (4 * (1 + std::pow(r, a)));
}

/// Eq. 6 corrected: max over r in {d1/d2, d3/d2}.
template <class T>
T paper_eq6_two_sided(T d1, T d2, T d3, double alpha) noexcept {
    return std::max(paper_eq6(d2, d1 / d2, alpha), paper_eq6(d2, d3 / d2, alpha));
}

/// Eq. 8: how far B1 can lie behind B0 (beyond the chord's end),
/// d2 sqrt(r^2 - r^(4a)) / (3 r^a (1 + r^a)) where r^2 > r^(4a), else 0 (B1
/// cannot project behind B0: Eq. 7 has no solution). r^2 - r^(4a) is
/// computed as r^2 (1 - r^(4a - 2)): at alpha = 1/2 that is exactly 0, as it
/// is in exact arithmetic, where r * r - pow(r, 2) is 1 ulp of r^2 for some r.
template <class T>
T paper_eq8(T d2, T r, double alpha) noexcept {
    const T a = T(alpha);
    const T v = r * r * (1 - std::pow(r, 4 * a - 2));
    if (!(v > 0)) return T(0);
    return d2 * std::sqrt(v) / (3 * std::pow(r, a) * (1 + std::pow(r, a)));
}

/// sup over r > 0 of paper_eq6(1, r, alpha): the "local" Eq. 6 factor (the
/// bound from the edge length alone, Figure 5 top row). Infinite for alpha <
/// 1/2; 1/4 for 1/2 and 1; 1/8 at alpha = 2/3 (the paper's minimum).
inline double local_eq6_factor(double alpha) noexcept {
    if (alpha < 0.5) return std::numeric_limits<double>::infinity();
    if (alpha == 0.5 || alpha == 1.0) return 0.25;  // limits r -> infinity and r -> 0
    // d/dr log f = 0  <=>  r^a = (1 - a) / (2a - 1)
    const double ra = (1 - alpha) / (2 * alpha - 1);
    const double r = std::pow(ra, 1 / alpha);
    return std::max(0.25 * std::pow(r, 1 - alpha) / (1 + ra), 0.0);
}

/// sup over r > 0 of paper_eq8(1, r, alpha): the local Eq. 8 factor. Zero at
/// alpha = 1/2, 1/3 for alpha = 1, infinite for alpha < 1/2. Found by a
/// golden-section search in log r (the function is unimodal there).
inline double local_eq8_factor(double alpha) noexcept {
    if (alpha < 0.5) return std::numeric_limits<double>::infinity();
    if (alpha == 0.5) return 0.0;
    if (alpha == 1.0) return 1.0 / 3.0;  // the limit r -> 0
    auto f = [&](double x) { return paper_eq8(1.0, std::exp(x), alpha); };
    double lo = -60, hi = 0;  // r <= 1 is where r^2 > r^(4a) for a > 1/2
    const double g = (std::sqrt(5.0) - 1) / 2;
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = f(x1), f2 = f(x2);
    for (int it = 0; it < 200; ++it) {
        if (f1 < f2) { lo = x1; x1 = x2; f1 = f2; x2 = lo + g * (hi - lo); f2 = f(x2); }
        else { hi = x2; x2 = x1; f2 = f1; x1 = hi - g * (hi - lo); f1 = f(x1); }
    }
    // Near r -> 0 the supremum may be the limit 0 < r: compare with the edge.
    return std::max({f1, f2, f(-60.0)});
}

/// The paper's per-segment quantities from the four control points P0..P3
/// and the knot intervals h0 = t1 - t0, h1 = t2 - t1, h2 = t3 - t2. Written
/// for general knots; with h = d^alpha they are exactly the printed formulas
/// (Eq. 5, Eq. 6, Eq. 8) with r = d1/d2 at P1 and r = d3/d2 at P2.
template <class T = double>
struct paper_bounds {
    T d1 = 0, d2 = 0, d3 = 0;          ///< polygon edge lengths |P1-P0|, |P2-P1|, |P3-P2|
    T theta1 = 0, theta2 = 0;          ///< polygon angles at P1 (P0-P1, P2-P1) and at P2 (P1-P2, P3-P2)
    T h1 = 0, h2 = 0;                  ///< Eq. 5: distances of B1, B2 to the chord line
    T eq6_one_sided = 0;               ///< Eq. 6 as printed (r = d1/d2 only): NOT a bound in general
    T eq6 = 0;                         ///< Eq. 6 two-sided (corrected): bounds the distance to the chord line
    T eq8_start = 0, eq8_end = 0;      ///< Eq. 8 at P1 (r = d1/d2) and at P2 (r = d3/d2)
};

/// Paper bounds from points and knot intervals; nullopt when an edge or a
/// knot interval is zero (the formulas divide by them).
template <std::size_t D, class T>
std::optional<paper_bounds<T>> segment_paper_bounds(const std::array<vec<D, T>, 4>& p,
                                                    const std::array<T, 3>& h) noexcept {
    paper_bounds<T> b;
    const vec<D, T> e0 = p[1] - p[0], e1 = p[2] - p[1], e2 = p[3] - p[2];
    b.d1 = norm(e0);
    b.d2 = norm(e1);
    b.d3 = norm(e2);
    if (!(b.d1 > 0 && b.d2 > 0 && b.d3 > 0 && h[0] > 0 && h[1] > 0 && h[2] > 0)) return std::nullopt;
    b.theta1 = detail::angle_between(vec<D, T>(-e0), e1);
    b.theta2 = detail::angle_between(vec<D, T>(-e1), e2);
    // B1 - P1 = [h1^2 (P1 - P0) + h0^2 (P2 - P1)] / [3 h0 (h0 + h1)]: its part
    // perpendicular to the chord is h1^2 d1 sin(theta1) / [3 h0 (h0 + h1)].
    const T k1 = h[1] * h[1] * b.d1 / (3 * h[0] * (h[0] + h[1]));  // |B1 - P1| part from P1 - P0
    const T k2 = h[1] * h[1] * b.d3 / (3 * h[2] * (h[1] + h[2]));
    b.h1 = k1 * std::sin(b.theta1);
    b.h2 = k2 * std::sin(b.theta2);
    // Eq. 6: 3/4 of the largest height with |sin| <= 1.
    b.eq6_one_sided = T(0.75) * k1;
    b.eq6 = T(0.75) * std::max(k1, k2);
    // Eq. 8: B1 projects behind P1 iff cos(theta1) > c* = h0^2 d2 / (h1^2 d1)
    // (Eq. 7 in general knots); |B1 - P1| is largest at cos(theta1) = c*:
    // k1 sqrt(1 - c*^2).
    const T c1s = h[0] * h[0] * b.d2 / (h[1] * h[1] * b.d1);
    const T c2s = h[2] * h[2] * b.d2 / (h[1] * h[1] * b.d3);
    // For alpha = 1/2, c* = 1 exactly (Eq. 8 is identically 0); its rounding
    // (a few ulps) must not turn into a radius of sqrt(ulp).
    const T one = 1 - T(16) * std::numeric_limits<T>::epsilon();
    b.eq8_start = c1s < one ? k1 * std::sqrt((1 - c1s) * (1 + c1s)) : T(0);
    b.eq8_end = c2s < one ? k2 * std::sqrt((1 - c2s) * (1 + c2s)) : T(0);
    return b;
}

}  // namespace crspline
