// crspline internal: closed intervals of doubles with outward rounding, for
// the proofs of the crossing decision (decision.hpp).
//
// Every operation computes its bounds in the default rounding mode (to
// nearest) and then steps each bound at least one ulp outward (down, up). A
// correctly rounded result is within half an ulp of the exact one, so the
// stepped bounds enclose the exact result: the enclosure is proved without
// changing the rounding mode (which the C++ standard library cannot do
// portably, and which WebAssembly does not have). A fused multiply-add the
// compiler might form is rounded once, which is closer still. Overflow gives
// an infinite bound, never NaN: the callers treat a non-finite interval as
// "nothing proved".
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace crspline::detail {

struct interval {
    double lo = 0, hi = 0;

    static interval point(double x) noexcept { return {x, x}; }
    double mid() const noexcept { return lo + (hi - lo) / 2; }
    double width() const noexcept { return hi - lo; }
    bool finite() const noexcept { return std::isfinite(lo) && std::isfinite(hi); }
    /// Strictly inside other (both bounds), the condition Krawczyk's test needs.
    bool strictly_inside(const interval& o) const noexcept { return lo > o.lo && hi < o.hi; }
    bool contains(double x) const noexcept { return lo <= x && x <= hi; }
};

/// A double above x by one ulp, or two (three just above the subnormals,
/// where |x| eps is rounded to a multiple of the least subnormal): x + (|x| eps + the least
/// subnormal), in round to nearest. Why it is at least one ulp up: for a
/// normal x, |x| eps (a power-of-two scaling, exact or rounded to the
/// nearest subnormal, which rounding cannot take below the ulp of x, itself
/// a double no larger than |x| eps) is at least the gap from x to the next
/// double up; for a zero or subnormal x the least subnormal is that gap; and
/// x plus at least its gap rounds to at least the next double (rounding is
/// monotone). A fused multiply-add rounds once, which keeps every step above.
/// Inline arithmetic rather than std::nextafter, a library call for every
/// bound of every operation. Infinities and overflow go through
/// std::nextafter (up(-inf) is -DBL_MAX, never NaN).
inline double up(double x) noexcept {
    constexpr double e = std::numeric_limits<double>::epsilon(), tiny = std::numeric_limits<double>::denorm_min();
    const double y = x + (std::abs(x) * e + tiny);
    return std::isfinite(y) ? y : std::nextafter(x, std::numeric_limits<double>::infinity());
}
/// A double below x by one to three ulps (up's mirror image).
inline double down(double x) noexcept {
    constexpr double e = std::numeric_limits<double>::epsilon(), tiny = std::numeric_limits<double>::denorm_min();
    const double y = x - (std::abs(x) * e + tiny);
    return std::isfinite(y) ? y : std::nextafter(x, -std::numeric_limits<double>::infinity());
}

inline interval operator+(const interval& a, const interval& b) noexcept { return {down(a.lo + b.lo), up(a.hi + b.hi)}; }
inline interval operator-(const interval& a, const interval& b) noexcept { return {down(a.lo - b.hi), up(a.hi - b.lo)}; }
inline interval operator-(const interval& a) noexcept { return {-a.hi, -a.lo}; }  // exact
inline interval operator*(const interval& a, const interval& b) noexcept {
    const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    // An infinite times a zero bound is NaN: the product is then unbounded.
    for (double x : p)
        if (std::isnan(x)) return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    return {down(std::min({p[0], p[1], p[2], p[3]})), up(std::max({p[0], p[1], p[2], p[3]}))};
}
/// A double times an interval (two products, not four).
inline interval operator*(double c, const interval& b) noexcept {
    const double p = c * b.lo, q = c * b.hi;
    if (std::isnan(p) || std::isnan(q)) return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    return c >= 0 ? interval{down(p), up(q)} : interval{down(q), up(p)};
}
/// The hull of two intervals, and their intersection (empty: lo > hi).
inline interval hull(const interval& a, const interval& b) noexcept { return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)}; }
inline interval intersect(const interval& a, const interval& b) noexcept { return {std::max(a.lo, b.lo), std::min(a.hi, b.hi)}; }

/// a + u (b - a): one de Casteljau step, u in [0, 1].
inline interval lerp(const interval& a, const interval& b, const interval& u) noexcept { return a + u * (b - a); }
inline interval lerp(const interval& a, const interval& b, double u) noexcept { return a + u * (b - a); }

}  // namespace crspline::detail
