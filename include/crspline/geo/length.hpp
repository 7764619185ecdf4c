// crspline::geo internals: the arc length of an arc's curve, a segment with
// a pinned end (tension 1 there) by its own integral.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <vector>

#include "../arc_length.hpp"
#include "../detail/gauss_legendre.hpp"
#include "arcs.hpp"

namespace crspline::geo {

namespace detail {

// Length, to relative accuracy `accuracy`, of the cubic with Bezier points
// b whose speed vanishes at u = 0 (b[1] == b[0]: its first vertex at tension
// 1, the tangent there zero). Then C'(u) = 3 u (p + q u) with p = 2 (b2 -
// b0), q = b3 - 3 b2 + 2 b0, and the length is 3 J, J = int_0^1 u |p + q u|
// du. The factor u is taken out exactly, so what is integrated, u sqrt(Q(u))
// with Q(u) = |p + q u|^2, is analytic but at the two complex roots z of Q:
// known in closed form, they give each piece's Bernstein ellipse (rho) and
// the 16-point Gauss rule's error bound, 64/15 M (w/2) r^-32 / (r^2 - 1) for
// M >= |f| on the ellipse of parameter r < rho (Trefethen, ATAP ch. 19; |f|
// <= T (|p| + |q| T) with T >= |u| there); a piece whose bound exceeds its
// share of accuracy * chord / 3 (the chord |b3 - b0| is at most the length)
// is halved. (arc_length's general path sees such a segment's speed vanish
// at its end and spends tens of microseconds on it; here it takes one or
// two rules.) A speed vanishing at u = 1 is the same with b reversed.
inline double end_pinned_length(const std::array<p2, 4>& b, double accuracy) noexcept {
    const p2 p = 2.0 * (b[2] - b[0]), q = b[3] - 3.0 * b[2] + 2.0 * b[0];
    const double np = norm(p), nq = norm(q), chord = norm(b[3] - b[0]);
    if (nq == 0) return 3 * np / 2;  // |p| int u du
    if (np == 0) return nq;          // 3 |q| int u^2 du
    // The roots of Q: (-(p.q) +- i |p x q|) / |q|^2 (conjugates: one rho).
    const std::complex<double> z(-dot(p, q) / (nq * nq), std::abs(cross2(p, q)) / (nq * nq));
    const double tol = accuracy * chord / 3;
    using gl = crspline::detail::gauss_legendre<16, double>;
    auto f = [&](double u) { return u * norm(p + u * q); };
    auto rule = [&](double a, double c) {
        const double m = (a + c) / 2, h = (c - a) / 2;
        double sum = 0;
        for (int k = 0; k < 8; ++k) sum += gl::w[k] * (f(m - h * gl::x[k]) + f(m + h * gl::x[k]));
        return h * sum;
    };
    double total = 0;
    // Pieces on a stack, left to right; depth bounds the halving where a
    // root sits on the interval (a kink of the speed, p parallel to q).
    struct span_t {
        double a, c;
        int depth;
    };
    span_t stack[64];
    int top = 0;
    stack[top++] = {0.0, 1.0, 0};
    while (top > 0) {
        const span_t sp = stack[--top];
        const double w = sp.c - sp.a, m = (sp.a + sp.c) / 2;
        const std::complex<double> x = (2.0 * z - (sp.a + sp.c)) / w;
        const std::complex<double> r = x + std::sqrt(x - 1.0) * std::sqrt(x + 1.0);
        const double rho = std::min(1e4, std::max(std::abs(r), 1 / std::abs(r)));
        const double rr = 1 + 0.9 * (rho - 1);
        const double T = std::abs(m) + w / 4 * (rr + 1 / rr);
        const double M = T * (np + nq * T);
        const double bound = 64.0 / 15.0 * M * (w / 2) * std::pow(rr, -32.0) / (rr * rr - 1);
        if (bound <= tol * w || sp.depth >= 48 || top + 2 > 64) {
            total += rule(sp.a, sp.c);
            continue;
        }
        // Halve at the root's real part if well inside, else in the middle.
        const double cut = z.real() > sp.a + w / 16 && z.real() < sp.c - w / 16 ? z.real() : m;
        stack[top++] = {cut, sp.c, sp.depth + 1};  // right first: the left is summed first
        stack[top++] = {sp.a, cut, sp.depth + 1};
    }
    return 3 * total;
}

// Arc length of the arc's curve: a linear segment's is its chord's; a
// segment with one end at tension 1 by end_pinned_length; the others' to
// arc_length's default accuracy, sixteen segments at a time (arc_length.hpp's
// batch, the same pieces as arc_length(segment)); summed in segment order.
inline double arc_curve_length(const arc_work& a) {
    if (a.measured) return a.length;  // measured (and released) by proof::run_alone
    const std::size_t segs = a.segments();
    std::vector<double> len(segs, 0.0);
    std::vector<std::size_t> curved;
    curved.reserve(segs);
    for (std::size_t s = 0; s < segs; ++s) {
        bool pinned0 = a.level[s] == linear_level, pinned1 = a.level[a.next(s)] == linear_level;
        if (a.fitted() && !a.linear(s)) {  // an open end's tangent is not zero at level 1 there
            const auto b = segment_bezier(a, s);
            pinned0 = pinned0 && b[1] == b[0];
            pinned1 = pinned1 && b[2] == b[3];
        }
        if (a.linear(s)) {
            len[s] = norm(a.pts[a.next(s)] - a.pts[s]);
        } else if (pinned0 || pinned1) {
            auto b = segment_bezier(a, s);
            if (pinned1) std::swap(b[0], b[3]), std::swap(b[1], b[2]);
            len[s] = end_pinned_length(b, default_accuracy);
        } else {
            curved.push_back(s);
        }
    }
    if (!curved.empty()) {
        const auto segments = a.curve->segments();
        crspline::detail::for_each_segment_length_piece(
            curved.size(), [&](std::size_t k) { return segments[curved[k]]; }, default_accuracy,
            [&](std::size_t k, double, double, double l, const crspline::detail::rule_choice&) { len[curved[k]] += l; });
    }
    double sum = 0;
    for (double l : len) sum += l;
    return sum;
}

}  // namespace detail

}  // namespace crspline::geo
