// crspline: axis-aligned bounding boxes of a segment and of a curve.
//
// The tight box of a cubic is attained at u = 0, u = 1 or where one
// coordinate's derivative c1 + 2 c2 u + 3 c3 u^2 vanishes inside (0, 1)
// (kurbo's `extrema` and `bounding_box`, in any dimension). The control box
// (the box of the Bézier points) is cheaper and always contains it.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "catmull_rom.hpp"
#include "detail/polynomial.hpp"
#include "segment.hpp"
#include "vec.hpp"

namespace crspline {

/// An axis-aligned box [lo, hi] (lo <= hi in every coordinate).
template <std::size_t D, class T = double>
struct box {
    using point = vec<D, T>;
    point lo{}, hi{};

    /// The box holding one point.
    static box of(const point& p) noexcept { return {p, p}; }

    point size() const noexcept { return hi - lo; }
    /// Length of the diagonal: the length scale crspline uses for tolerances.
    T diagonal() const noexcept { return norm(hi - lo); }
    bool contains(const point& p) const noexcept {
        for (std::size_t k = 0; k < D; ++k)
            if (!(p[k] >= lo[k] && p[k] <= hi[k])) return false;
        return true;
    }
    /// Grow to hold p, or another box.
    void expand(const point& p) noexcept {
        for (std::size_t k = 0; k < D; ++k) {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
    }
    void expand(const box& b) noexcept {
        expand(b.lo);
        expand(b.hi);
    }
    friend bool operator==(const box&, const box&) = default;
};

/// Local parameters u in (0, 1), sorted and each once, where some coordinate
/// of the segment has a critical point that it crosses (a root of that
/// coordinate's derivative with a sign change, or an exact zero). At most 2 D.
template <std::size_t D, class T>
std::vector<T> extrema(const cubic_segment<D, T>& s) {
    std::vector<T> u;
    for (std::size_t k = 0; k < D; ++k) {
        // d/du of coordinate k, ascending: c1 + 2 c2 u + 3 c3 u^2.
        const std::array<T, 3> dk{s.c1[k], T(2) * s.c2[k], T(3) * s.c3[k]};
        for (T r : detail::real_roots(dk, T(0), T(1)))
            if (r > T(0) && r < T(1)) u.push_back(r);
    }
    std::sort(u.begin(), u.end());
    u.erase(std::unique(u.begin(), u.end()), u.end());
    return u;
}

namespace detail {
// Tight box of segment s whose end point is `end` (the curve passes the
// exact next control point there, the cubic at u = 1 only within rounding).
template <std::size_t D, class T>
crspline::box<D, T> tight_box_to(const cubic_segment<D, T>& s, const vec<D, T>& end) {
    crspline::box<D, T> b = crspline::box<D, T>::of(s.origin);
    b.expand(end);
    for (T u : crspline::extrema(s)) b.expand(s.at(u));
    return b;
}
}  // namespace detail

/// Tight axis-aligned box of a segment over u in [0, 1]: every face is
/// touched by the segment, at u = 0, u = 1 or an interior extremum, each
/// evaluated with at(u). Exact up to the root of the derivative (found to
/// full precision, where the coordinate is flat to first order).
template <std::size_t D, class T>
box<D, T> bounding_box(const cubic_segment<D, T>& s) {
    return detail::tight_box_to(s, s.at(T(1)));
}

/// Tight axis-aligned box of the whole curve: the control points and every
/// segment's interior extrema.
template <std::size_t D, class T>
box<D, T> bounding_box(const catmull_rom<D, T>& c) {
    const auto p = c.points();
    box<D, T> b = box<D, T>::of(p[0]);
    for (std::size_t i = 0; i < c.segment_count(); ++i)
        b.expand(detail::tight_box_to(c.segment(i), p[(i + 1) % p.size()]));
    return b;
}

/// Box of the Bézier control points of a segment: cheap, and by the convex
/// hull property it contains the segment (up to the rounding of the points).
template <std::size_t D, class T>
box<D, T> control_box(const cubic_segment<D, T>& s) {
    const auto b = to_bezier(s);
    box<D, T> r = box<D, T>::of(b[0]);
    for (const auto& q : b) r.expand(q);
    return r;
}

/// Box of all the curve's Bézier control points (catmull_rom::bezier): it
/// contains the curve.
template <std::size_t D, class T>
box<D, T> control_box(const catmull_rom<D, T>& c) {
    box<D, T> r = box<D, T>::of(c.points()[0]);
    for (std::size_t i = 0; i < c.segment_count(); ++i)
        for (const auto& q : c.bezier(i)) r.expand(q);
    return r;
}

}  // namespace crspline
