// crspline: the decision's proof of a crossing: Krawczyk's operator for
// F(u, v) = A(u) - B(v) in interval arithmetic with outward rounding
// (detail/interval.hpp), over one segment or two consecutive ones (a
// crossing at a vertex), and the bookkeeping of the crossings proved so far
// (each is reported once, however many piece pairs find it).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

#include "../detail/double_double.hpp"
#include "../detail/interval.hpp"
#include "arguments.hpp"
#include "report.hpp"

namespace crspline {
namespace detail {

struct decision_krawczyk : decision_arguments {
    std::vector<std::size_t> first_piece;  // per curve, and one past the end
    decision out;
    bool record_pairs = true, first_crossing = false;
    // The arguments of each pair of segments, as (key, flags) items that
    // run() merges at the end (a pair decided in several piece pairs has
    // several items).
    std::vector<std::pair<std::array<std::size_t, 4>, unsigned>> pair_flags;
    std::map<std::array<std::size_t, 4>, std::size_t> contact_index;
    std::size_t budget = 0, pair_budget = 0;
    static constexpr std::size_t npos = std::size_t(-1);
    double fine_below = 0;  // pieces no larger are made fine (refine()) before a test
    // Per curve: each segment's rank among the non-point segments, and its
    // neighbours (the next and previous non-point segments sharing its end
    // and start point exactly; npos if none).
    // 32-bit (a piece's ids are): 12 bytes per segment, not 24.
    static constexpr std::uint32_t none32 = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::vector<std::uint32_t>> rank, next_seg, prev_seg;
    std::vector<std::size_t> nonpoint;
    std::vector<std::array<std::array<double, 2>, 2>> crossing_range;  // per crossing: curve ranges (rank + u)
    // The proved crossings by the unit cells of curve coordinates that their
    // ranges cover (cell floor(t), modulo the curve's length when closed),
    // each filed under both its ranges: a crossing that overlaps a new one
    // shares a cell with it, so finding it looks at a few crossings, not all.
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> crossing_cells;
    template <class F>
    void for_each_cell(std::size_t curve, double lo, double hi, F&& f) const {
        const double n = double(nonpoint[curve]);
        for (double c = std::floor(lo); c <= hi; c += 1) {
            const double w = closed[curve] && n > 0 ? c - n * std::floor(c / n) : c;  // >= -1: a range starts at rank - 1 at least
            f((std::uint64_t(curve) << 32) + std::uint64_t(std::int64_t(w) + 2));
        }
    }

    // Interval de Casteljau: the curve and its derivative over u (an
    // interval, or a double: the parameter exactly).
    template <class U>
    static ipoint eval(const std::array<ipoint, 4>& q, const U& u) {
        ipoint r;
        for (std::size_t k = 0; k < 2; ++k) {
            const interval a0 = lerp(q[0][k], q[1][k], u), a1 = lerp(q[1][k], q[2][k], u), a2 = lerp(q[2][k], q[3][k], u);
            r[k] = lerp(lerp(a0, a1, u), lerp(a1, a2, u), u);
        }
        return r;
    }
    static ipoint deriv(const std::array<ipoint, 4>& q, const interval& u) {
        ipoint r;
        const interval three = interval::point(3);
        for (std::size_t k = 0; k < 2; ++k) {
            const interval d0 = q[1][k] - q[0][k], d1 = q[2][k] - q[1][k], d2 = q[3][k] - q[2][k];
            r[k] = three * lerp(lerp(d0, d1, u), lerp(d1, d2, u), u);
        }
        return r;
    }

    // One side of F: a segment f on s in [0, 1], or two consecutive
    // segments f then g on s in [0, 2] (u = s - 1 in g): a crossing at or
    // next to a vertex. The curve is continuous there and its derivative in
    // s jumps at most; the mean value form below needs only that the
    // derivative's enclosure over S holds every one-sided derivative in S
    // (F(x) - F(m) is the integral of the derivative along the segment from
    // m to x, an average of values in that enclosure).
    using dpoint = std::array<dd, 2>;
    struct side {
        std::array<ipoint, 4> f{}, g{};
        std::array<dpoint, 4> fd{}, gd{};  // the same points exactly, as double-doubles
        bool has_g = false;
        // The point at s in double-doubles: within 72 eps^2 M (refine()'s
        // argument, one de Casteljau evaluation). s - 1 is exact for s in
        // [1, 2] (Sterbenz).
        ipoint at_i(double s) const { return has_g && s >= 1 ? eval(g, s - 1) : eval(f, s); }
        dpoint at(double s) const {
            const auto& q = has_g && s >= 1 ? gd : fd;
            const double t = has_g && s >= 1 ? s - 1 : s;
            dpoint r;
            for (std::size_t k = 0; k < 2; ++k) {
                const dd a0 = lerp(q[0][k], q[1][k], t), a1 = lerp(q[1][k], q[2][k], t), a2 = lerp(q[2][k], q[3][k], t);
                r[k] = lerp(lerp(a0, a1, t), lerp(a1, a2, t), t);
            }
            return r;
        }
        ipoint slope(const interval& S) const {
            const bool in_f = S.lo < 1 || !has_g, in_g = has_g && S.hi >= 1;
            ipoint r{};
            if (in_f) r = deriv(f, has_g ? interval{S.lo, std::min(S.hi, 1.0)} : S);
            if (in_g) {
                const ipoint q = deriv(g, interval{std::max(S.lo, 1.0), S.hi} - interval::point(1));
                r = in_f ? ipoint{hull(r[0], q[0]), hull(r[1], q[1])} : q;
            }
            return r;
        }
    };

    // Krawczyk's operator K(X) = m - C F(m) + (I - C J(X)) (X - m) for
    // F(u, v) = A(u) - B(v); K(X) strictly inside X proves exactly one zero
    // in X, with every J in J(X) invertible. X is tightened to K(X) & X.
    // With `precise`, F(m) is evaluated in double-doubles (each side within
    // 72 eps^2 M, the difference within 4 eps^2 (2M) more: e_F =
    // 160 eps^2 M), so its enclosure is a few ulps of |F(m)| wide however
    // large the coordinates: two crossings closer than eps M / (the angle)
    // can be told apart. Else in interval arithmetic (a few eps M wide,
    // cheaper: enough for the crossings of coarse pieces).
    static bool krawczyk(const side& A, const side& B, std::array<interval, 2>& X, double M, bool precise) {
        bool proved = false;
        const double eF = 160 * eps * eps * M + std::numeric_limits<double>::min();
        for (int it = 0; it < 6; ++it) {
            const double m[2] = {X[0].mid(), X[1].mid()};
            ipoint F;
            if (precise) {
                const dpoint fa = A.at(m[0]), fb = B.at(m[1]);
                for (std::size_t k = 0; k < 2; ++k) {
                    const dd d = fa[k] - fb[k];
                    F[k] = interval::point(d.hi) + interval{down(d.lo - eF), up(d.lo + eF)};
                }
            } else {
                const ipoint fa = A.at_i(m[0]), fb = B.at_i(m[1]);
                F = {fa[0] - fb[0], fa[1] - fb[1]};
            }
            const ipoint ja = A.slope(X[0]), jb = B.slope(X[1]);
            const interval J[2][2] = {{ja[0], -jb[0]}, {ja[1], -jb[1]}};
            const double j00 = J[0][0].mid(), j01 = J[0][1].mid(), j10 = J[1][0].mid(), j11 = J[1][1].mid();
            const double det = j00 * j11 - j01 * j10;
            if (!(std::abs(det) > 0) || !std::isfinite(det)) return proved;
            const double C[2][2] = {{j11 / det, -j01 / det}, {-j10 / det, j00 / det}};
            std::array<interval, 2> K;
            for (std::size_t r = 0; r < 2; ++r) {
                interval k = interval::point(m[r]) - (C[r][0] * F[0] + C[r][1] * F[1]);
                for (std::size_t c = 0; c < 2; ++c) {
                    const interval e = interval::point(r == c ? 1.0 : 0.0) -
                                       (C[r][0] * J[0][c] + C[r][1] * J[1][c]);
                    k = k + e * (X[c] - interval::point(m[c]));
                }
                K[r] = k;
            }
            if (!K[0].finite() || !K[1].finite()) return proved;
            if (!proved) {
                if (!(K[0].strictly_inside(X[0]) && K[1].strictly_inside(X[1]))) return false;
                proved = true;
            }
            const std::array<interval, 2> Y{intersect(K[0], X[0]), intersect(K[1], X[1])};
            if (Y[0].lo > Y[0].hi || Y[1].lo > Y[1].hi) return proved;  // cannot happen once proved
            if (Y[0].lo == X[0].lo && Y[0].hi == X[0].hi && Y[1].lo == X[1].lo && Y[1].hi == X[1].hi) break;
            X = Y;
        }
        return proved;
    }

    // The side of piece p for Krawczyk's test, its parameter range in s, the
    // domain of s, and where s = 0 lies along the curve (the rank of its
    // first segment among the curve's non-point segments). With `chain`, a
    // piece at an end of its segment takes the neighbouring segment along.
    struct side_of {
        side sd;
        double s0, s1, dom, base;
        std::size_t f_seg, g_seg;
    };
    side_of make_side(const piece& p, bool chain, bool precise) const {
        const auto wide = [](std::uint32_t x) { return x == none32 ? npos : std::size_t(x); };
        const std::size_t nx = wide(next_seg[p.curve][p.segment]), pv = wide(prev_seg[p.curve][p.segment]);
        const double r = double(rank[p.curve][p.segment]);
        const auto ex = [&](std::size_t s) { return enclosure(p.curve, s); };
        const auto exd = [&](std::size_t s) {
            std::array<dpoint, 4> q{};
            if (!precise) return q;  // not read
            for (std::size_t k = 0; k < 4; ++k)
                for (std::size_t d = 0; d < 2; ++d) q[k][d] = two_sum(curves[p.curve][s][k][d], -ref[d]);
            return q;
        };
        if (chain && p.u1 == 1 && nx != npos)
            return {{ex(p.segment), ex(nx), exd(p.segment), exd(nx), true}, p.u0, p.u1, 2, r, p.segment, nx};
        if (chain && p.u0 == 0 && pv != npos)
            return {{ex(pv), ex(p.segment), exd(pv), exd(p.segment), true}, p.u0 + 1, p.u1 + 1, 2, r - 1, pv, p.segment};
        return {{ex(p.segment), {}, exd(p.segment), {}, false}, p.u0, p.u1, 1, r, p.segment, npos};
    }
    // An enclosure of segment s's control points relative to ref: the
    // exact difference is within half an ulp of the rounded one.
    std::array<ipoint, 4> enclosure(std::size_t curve, std::size_t s) const {
        std::array<ipoint, 4> e;
        for (std::size_t k = 0; k < 4; ++k)
            for (std::size_t d = 0; d < 2; ++d) {
                const double x = curves[curve][s][k][d] - ref[d];
                e[k][d] = {down(x), up(x)};
            }
        return e;
    }
    // Do the curve ranges [x0, x1] and [y0, y1] (curve coordinates: rank +
    // u) overlap, around a closed curve of n non-point segments too?
    static bool overlap(double x0, double x1, double y0, double y1, bool closed_curve, double n) {
        for (const double k : {-n, 0.0, n})
            if ((closed_curve || k == 0) && x0 <= y1 + k && y0 + k <= x1) return true;
        return false;
    }

    bool try_crossing(const piece& a, const piece& b, bool chain) {
        const bool precise = chain || a.fine || b.fine;
        const side_of A = make_side(a, chain, precise), B = make_side(b, chain, precise);
        const bool same = a.curve == b.curve;
        const double n = double(nonpoint[a.curve]);
        // Inflate each range by a quarter of its width, within its domain;
        // on one curve, by less than a third of the gap between them, so
        // that the boxes never hold a point paired with itself (u = v: a
        // zero of F that is no crossing).
        const double ia0 = (A.s1 - A.s0) / 4, ib0 = (B.s1 - B.s0) / 4;
        double cap = std::numeric_limits<double>::infinity();
        if (same) {
            const double x0 = A.base + A.s0, x1 = A.base + A.s1, y0 = B.base + B.s0, y1 = B.base + B.s1;
            double gap = std::numeric_limits<double>::infinity();
            for (const double k : {-n, 0.0, n}) {
                if (!closed[a.curve] && k != 0) continue;
                gap = std::min({gap, std::abs(y0 + k - x1), std::abs(x0 - (y1 + k))});
                if (x0 <= y1 + k && y0 + k <= x1) gap = 0;
            }
            if (!(gap > 0)) return false;
            cap = gap / 3;
        }
        // Krawczyk's box must be wider than the rounding of F over the
        // Jacobian's conditioning: pieces at the floor (a few ulps) can be
        // narrower than that at a shallow crossing, so at the floor
        // (`chain`) wider boxes are tried too, at least 2^-36, 2^-32, 2^-28,
        // 2^-26, 2^-24, 2^-22 and 2^-20 of a segment's parameter range
        // (capped as above): a proof
        // in any box is a proof; a box holding two zeros or a singular
        // Jacobian only fails.
        std::array<interval, 2> X;
        bool proved = false;
        for (const double least : {0.0, 0x1p-36, 0x1p-32, 0x1p-28, 0x1p-26, 0x1p-24, 0x1p-22, 0x1p-20}) {
            if (least > 0 && !chain) break;
            const double ia = std::min(std::max(ia0, least), cap), ib = std::min(std::max(ib0, least), cap);
            if (least > 0 && ia <= ia0 && ib <= ib0) break;  // capped: no wider box to try
            const interval U{std::max(0.0, A.s0 - ia), std::min(A.dom, A.s1 + ia)};
            const interval V{std::max(0.0, B.s0 - ib), std::min(B.dom, B.s1 + ib)};
            if (same && overlap(A.base + U.lo, A.base + U.hi, B.base + V.lo, B.base + V.hi, closed[a.curve], n)) return false;
            X = {U, V};
            if (krawczyk(A.sd, B.sd, X, M, precise)) {
                proved = true;
                break;
            }
        }
        if (!proved) return false;
        // One crossing per zero: a neighbouring pair of pieces may prove the same one.
        const std::array<std::array<double, 2>, 2> g{{{A.base + X[0].lo, A.base + X[0].hi}, {B.base + X[1].lo, B.base + X[1].hi}}};
        bool known = false;
        for_each_cell(a.curve, g[0][0], g[0][1], [&](std::uint64_t cell) {
            const auto it = crossing_cells.find(cell);
            if (known || it == crossing_cells.end()) return;
            for (const std::uint32_t k : it->second) {
                const auto& c = out.crossings[k];
                const auto& h = crossing_range[k];
                for (const int flip : {0, 1}) {
                    const std::size_t p = std::size_t(flip), q = std::size_t(1 - flip);
                    if (c.curve[p] == a.curve && c.curve[q] == b.curve &&
                        overlap(h[p][0], h[p][1], g[0][0], g[0][1], closed[a.curve], double(nonpoint[a.curve])) &&
                        overlap(h[q][0], h[q][1], g[1][0], g[1][1], closed[b.curve], double(nonpoint[b.curve])))
                        known = true;
                }
            }
        });
        if (known) return true;
        // Reported in the segment that holds the middle of the interval
        // (the interval may reach past that segment's end at a vertex).
        auto place = [](const side_of& sd, const interval& x, std::size_t& seg, std::array<double, 2>& u) {
            if (sd.g_seg != npos && x.mid() >= 1) {
                seg = sd.g_seg;
                u = {x.lo - 1, x.hi - 1};
            } else {
                seg = sd.f_seg;
                u = {x.lo, x.hi};
            }
        };
        proved_crossing c;
        c.curve = {a.curve, b.curve};
        place(A, X[0], c.segment[0], c.u[0]);
        place(B, X[1], c.segment[1], c.u[1]);
        c.point = bezier_at(curves[a.curve][c.segment[0]], (c.u[0][0] + c.u[0][1]) / 2);
        const auto k = std::uint32_t(out.crossings.size());
        out.crossings.push_back(c);
        crossing_range.push_back(g);
        for (const std::size_t p : {std::size_t(0), std::size_t(1)})
            for_each_cell(c.curve[p], g[p][0], g[p][1], [&](std::uint64_t cell) { crossing_cells[cell].push_back(k); });
        return true;
    }
};

}  // namespace detail
}  // namespace crspline
