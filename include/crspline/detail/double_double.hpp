// crspline internal: double-double numbers (an unevaluated sum hi + lo of
// two doubles, about 106 bits), for the crossing decision's pieces below
// the scale where plain doubles' rounding would swamp them (decision.hpp).
//
// two_sum and two_prod are error-free: a + b == s + e and a * b == p + e
// exactly (Knuth; the product's error by a fused multiply-add where the
// target has one, else by Dekker's splitting). The compound
// operations are the accurate double-double sum of Bailey's QD library and
// a double-double times a double; each is within a few eps^2 |result| of
// the exact result (eps = 2^-52), which the caller's error bounds take as
// 4 eps^2 times a bound of the magnitudes involved.
#pragma once

#include <cmath>

namespace crspline::detail {

struct dd {
    double hi = 0, lo = 0;
};

inline dd two_sum(double a, double b) noexcept {
    const double s = a + b, bb = s - a;
    return {s, (a - (s - bb)) + (b - bb)};
}
inline dd fast_two_sum(double a, double b) noexcept {  // |a| >= |b| (or a == 0)
    const double s = a + b;
    return {s, b - (s - a)};
}
// Dekker's splitting (no fused multiply-add needed): a == hi + lo with
// hi holding the top 26 bits, exact for |a| < 2^996.
inline dd split26(double a) noexcept {
    const double c = 134217729.0 * a;  // 2^27 + 1
    const double hi = c - (c - a);
    return {hi, a - hi};
}
inline dd two_prod(double a, double b) noexcept {
    const double p = a * b;
#ifdef FP_FAST_FMA
    return {p, std::fma(a, b, -p)};  // one instruction where the target has it
#else
    // Without a hardware fused multiply-add (the x86-64 baseline, WebAssembly)
    // std::fma is a library call; Dekker's product is exact in plain
    // arithmetic, which the compiler cannot contract into fused operations
    // on such a target. Huge operands (whose split would overflow) take the
    // library call.
    if (!(std::abs(a) < 0x1p995 && std::abs(b) < 0x1p995)) return {p, std::fma(a, b, -p)};
    const dd x = split26(a), y = split26(b);
    return {p, ((x.hi * y.hi - p) + x.hi * y.lo + x.lo * y.hi) + x.lo * y.lo};
#endif
}
inline dd operator+(const dd& a, const dd& b) noexcept {
    dd s = two_sum(a.hi, b.hi);
    const dd t = two_sum(a.lo, b.lo);
    s.lo += t.hi;
    s = fast_two_sum(s.hi, s.lo);
    s.lo += t.lo;
    return fast_two_sum(s.hi, s.lo);
}
inline dd operator-(const dd& a) noexcept { return {-a.hi, -a.lo}; }
inline dd operator-(const dd& a, const dd& b) noexcept { return a + (-b); }
inline dd operator*(const dd& a, double t) noexcept {
    dd p = two_prod(a.hi, t);
    p.lo += a.lo * t;
    return fast_two_sum(p.hi, p.lo);
}
/// (a + b) / 2: the sum's error, halved exactly.
inline dd midpoint(const dd& a, const dd& b) noexcept {
    const dd s = a + b;
    return {s.hi * 0.5, s.lo * 0.5};
}
/// a + t (b - a), a de Casteljau step.
inline dd lerp(const dd& a, const dd& b, double t) noexcept { return a + (b - a) * t; }

}  // namespace crspline::detail
