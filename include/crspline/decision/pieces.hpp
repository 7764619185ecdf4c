// crspline: the decision's pieces (decision.hpp, "Proofs"): the curves'
// segments relative to the first point, the monotone pieces they are cut
// into and the store that keeps them small, halving (de Casteljau, with the
// error each level adds), fine pieces in double-doubles (refine) and a frame
// of a pair's own (local), monotonicity and the pieces' boxes.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "../catmull_rom.hpp"
#include "../detail/double_double.hpp"
#include "../detail/interval.hpp"
#include "../error.hpp"
#include "../vec.hpp"
#include "report.hpp"

namespace crspline {
namespace detail {

struct decision_pieces {
    using P = vec<2>;
    static constexpr double eps = std::numeric_limits<double>::epsilon();
    static constexpr int max_depth = 64;

    struct piece {
        std::array<P, 4> b{};   // control points relative to ref (computed)
        std::array<P, 4> lo{};  // fine pieces: b + lo, double-doubles (zero for coarse ones)
        double err = 0;         // |computed - exact| per coordinate, bound (of b + lo)
        double u0 = 0, u1 = 1;
        std::uint32_t curve = 0, segment = 0;
        std::uint8_t start_mult = 1, end_mult = 1;  // control points exactly equal to b[0] / b[3] (incl. it)
        bool fine = false;  // double-double points (refine()), else plain doubles
        int depth = 0;
    };
    using ipoint = std::array<interval, 2>;

    // A curve's segments: Bézier points given, or made by the curve itself
    // when asked (catmull_rom::bezier(i), the same doubles as bezier()),
    // which keeps no copy of them.
    struct source {
        std::span<const std::array<P, 4>> given;
        const catmull_rom<2>* curve = nullptr;
        std::size_t size() const { return curve ? curve->segment_count() : given.size(); }
        std::array<P, 4> operator[](std::size_t s) const { return curve ? curve->bezier(s) : given[s]; }
    };
    std::vector<source> curves;
    std::vector<bool> closed;
    P ref{};
    double M = 0, floor = 0, Mc = 0;  // Mc: the largest absolute coordinate
    // The monotone pieces, in order of curve and segment. A piece that is a
    // whole segment (most are) is kept as its ids alone and rebuilt from the
    // curve when asked (the same doubles as when it was made: its points are
    // the source's minus ref); only pieces cut from a segment keep their
    // points. 12 bytes per segment instead of a 104-byte piece: the
    // report's verdict at 10^6 points stays within issue 26's memory
    // promise.
    struct piece_store {
        struct slot {
            std::uint32_t curve, segment, cut;  // cut: index in `cuts`, or whole
        };
        static constexpr std::uint32_t whole = std::numeric_limits<std::uint32_t>::max();
        const decision_pieces* e = nullptr;
        std::vector<slot> slots;
        std::vector<piece> cuts;
        std::size_t size() const noexcept { return slots.size(); }
        void reserve(std::size_t n) { slots.reserve(n); }
        void push_back(const piece& p) {
            if (p.depth == 0) {
                slots.push_back({p.curve, p.segment, whole});
                return;
            }
            if (cuts.size() >= whole) throw invalid_input("decision: more than 2^32 cut pieces");
            slots.push_back({p.curve, p.segment, std::uint32_t(cuts.size())});
            cuts.push_back(p);
        }
        piece operator[](std::size_t k) const {
            const slot& s = slots[k];
            return s.cut == whole ? e->whole_piece(s.curve, s.segment) : cuts[s.cut];
        }
        std::uint32_t curve(std::size_t k) const noexcept { return slots[k].curve; }
        std::uint32_t segment(std::size_t k) const noexcept { return slots[k].segment; }
        // The parameter range, without rebuilding a whole piece ([0, 1]).
        double u0(std::size_t k) const noexcept { return slots[k].cut == whole ? 0.0 : cuts[slots[k].cut].u0; }
        double u1(std::size_t k) const noexcept { return slots[k].cut == whole ? 1.0 : cuts[slots[k].cut].u1; }
        void resize(std::size_t n) { slots.resize(n); }  // a removed cut piece stays in `cuts`, unused
    };
    piece_store pieces;

    static double norm1(const P& d) noexcept { return std::abs(d[0]) + std::abs(d[1]); }
    // S bounds every coordinate of the frame the pieces are in (M for
    // coarse pieces, relative to ref; local() gives fine ones a frame of
    // their own).
    static double margin(double e, const P& d, double S) noexcept { return (e + 10 * eps * S) * norm1(d); }

    static std::array<piece, 2> split(const piece& p) {
        piece l = p, r = p;
        if (p.fine) {
            // In double-doubles, coordinate by coordinate (the same steps).
            for (std::size_t d = 0; d < 2; ++d) {
                const dd q[4] = {{p.b[0][d], p.lo[0][d]}, {p.b[1][d], p.lo[1][d]}, {p.b[2][d], p.lo[2][d]}, {p.b[3][d], p.lo[3][d]}};
                const dd a0 = midpoint(q[0], q[1]), a1 = midpoint(q[1], q[2]), a2 = midpoint(q[2], q[3]);
                const dd q0 = midpoint(a0, a1), q1 = midpoint(a1, a2), m = midpoint(q0, q1);
                const dd lq[4] = {q[0], a0, q0, m}, rq[4] = {m, q1, a2, q[3]};
                for (std::size_t k = 0; k < 4; ++k) {
                    l.b[k][d] = lq[k].hi, l.lo[k][d] = lq[k].lo;
                    r.b[k][d] = rq[k].hi, r.lo[k][d] = rq[k].lo;
                }
            }
        } else {
            const auto mid = [](const P& x, const P& y) { return (x + y) * 0.5; };
            const auto& q = p.b;
            const P a0 = mid(q[0], q[1]), a1 = mid(q[1], q[2]), a2 = mid(q[2], q[3]);
            const P q0 = mid(a0, a1), q1 = mid(a1, a2), m = mid(q0, q1);
            l.b = {q[0], a0, q0, m};
            r.b = {m, q1, a2, q[3]};
        }
        const double um = p.u0 + (p.u1 - p.u0) / 2;
        l.u1 = um;
        r.u0 = um;
        l.end_mult = 1;
        r.start_mult = 1;
        l.depth = r.depth = p.depth + 1;
        return {l, r};
    }
    // The error a split adds: a coarse midpoint is rounded once per level
    // (three levels, each an average of rounded values: 2 eps M in all); a
    // fine one has the double-double sum's error, at most 4 eps^2 M per
    // midpoint (the magnitudes are convex combinations, within M), three
    // levels: 12 eps^2 M, taken as 16, plus the least normal double for a
    // low part halved into the subnormals.
    void grow(std::array<piece, 2>& h) const {
        for (auto& x : h)
            x.err += x.fine ? 16 * eps * eps * M + std::numeric_limits<double>::min() : 2 * eps * M;
    }

    // Fine pieces. Below the scale where a coarse piece's error (2 eps M a
    // level) would swamp the gaps being decided, a piece is made again from
    // its segment in double-doubles: its control points are the blossom
    // values B(u0,u0,u0), B(u0,u0,u1), B(u0,u1,u1), B(u1,u1,u1) of the
    // segment's Bezier points relative to ref (differences exact as
    // double-doubles), three de Casteljau levels, each step x + t (y - x)
    // within 24 eps^2 M (a difference, a product and a sum, each within
    // 4 eps^2 of magnitudes up to 2M; the inputs' errors carried with
    // weights 1 - t and t): 72 eps^2 M, taken as 128.
    // The end points depend on their own parameter alone (the same value for
    // the two pieces that share them, as the joint argument needs), and are
    // the segment's own points at u = 0 and u = 1.
    void refine(piece& p) const {
        if (p.fine) return;
        const auto& g = curves[p.curve][p.segment];
        const double a = p.u0, b = p.u1;
        for (std::size_t d = 0; d < 2; ++d) {
            dd q[4];
            for (std::size_t k = 0; k < 4; ++k) q[k] = two_sum(g[k][d], -ref[d]);
            const auto blossom = [&](double t1, double t2, double t3) {
                const dd x0 = lerp(q[0], q[1], t1), x1 = lerp(q[1], q[2], t1), x2 = lerp(q[2], q[3], t1);
                const dd y0 = lerp(x0, x1, t2), y1 = lerp(x1, x2, t2);
                return lerp(y0, y1, t3);
            };
            const dd r[4] = {a == 0 ? q[0] : blossom(a, a, a), blossom(a, a, b), blossom(a, b, b),
                             b == 1 ? q[3] : blossom(b, b, b)};
            for (std::size_t k = 0; k < 4; ++k) p.b[k][d] = r[k].hi, p.lo[k][d] = r[k].lo;
        }
        p.err = 128 * eps * eps * M + std::numeric_limits<double>::min();
        p.fine = true;
        // Multiplicities stay as they were: points known equal to an end
        // are equal in exact arithmetic (a zero tangent, at u = 0 or 1,
        // whose blossom values are that end's point exactly).
    }
    // Two pieces in a frame of their own: their points relative to R (a
    // double near them), rounded to doubles. The difference hi - R is
    // exact as s + e (two_sum), and s + (e + lo) rounds twice: within
    // eps S + 2 eps^2 (S + M) of the exact point, S bounding every local
    // coordinate. The margins then scale with the pieces, not with the
    // curve: fine pieces can be told apart at any gap above a few eps of
    // their own size.
    struct framed {
        piece a, b;
        double S;
    };
    framed local(const piece& a, const piece& b) const {
        framed f{a, b, 0};
        const P R = a.b[0];
        double S = 0;
        for (piece* x : {&f.a, &f.b})
            for (std::size_t k = 0; k < 4; ++k)
                for (std::size_t d = 0; d < 2; ++d) {
                    const dd s = two_sum(x->b[k][d], -R[d]);
                    x->b[k][d] = s.hi + (s.lo + x->lo[k][d]);
                    x->lo[k][d] = 0;
                    S = std::max(S, std::abs(x->b[k][d]));
                }
        f.S = S * (1 + 4 * eps) + std::numeric_limits<double>::min();
        for (piece* x : {&f.a, &f.b}) x->err += eps * f.S + 2 * eps * eps * (f.S + M);
        return f;
    }

    // d . B'(u) > 0 on the piece: the hodograph's control points b[k+1] - b[k]
    // all strictly ahead along d, except those known to be exactly zero.
    static bool monotone_in(const piece& p, const P& d, double S) {
        if (!(norm1(d) > 0) || !std::isfinite(norm1(d))) return false;
        const double pad = margin(2 * p.err, d, S);
        const std::size_t k0 = p.start_mult - 1u, k1 = 3u - (p.end_mult - 1u);
        if (k0 >= k1) return false;
        for (std::size_t k = k0; k < k1; ++k)
            if (!(dot(p.b[k + 1], d) - dot(p.b[k], d) > pad)) return false;
        return true;
    }
    static bool is_monotone(const piece& p, double S) {
        const P chord = p.b[3] - p.b[0];
        const P h0 = p.b[std::size_t(p.start_mult)] - p.b[0], h2 = p.b[3] - p.b[3u - p.end_mult];
        const P dirs[] = {chord, h0, h2, h0 / std::max(norm1(h0), 1e-300) + h2 / std::max(norm1(h2), 1e-300)};
        for (const auto& d : dirs)
            if (monotone_in(p, d, S)) return true;
        return false;
    }

    static std::array<P, 2> hull_box(const piece& p) {
        std::array<P, 2> r{p.b[0], p.b[0]};
        for (const auto& x : p.b)
            for (std::size_t k = 0; k < 2; ++k) {
                r[0][k] = std::min(r[0][k], x[k]);
                r[1][k] = std::max(r[1][k], x[k]);
            }
        return r;
    }
    static double extent(const piece& p) {
        const auto b = hull_box(p);
        return std::max(b[1][0] - b[0][0], b[1][1] - b[0][1]);
    }

    // Segment s of curve ci as one piece, from its Bézier points g.
    piece make_piece(const std::array<P, 4>& g, std::size_t ci, std::size_t s) const {
        piece p;
        for (std::size_t k = 0; k < 4; ++k) p.b[k] = g[k] - ref;
        p.err = eps * M;
        p.curve = std::uint32_t(ci);
        p.segment = std::uint32_t(s);
        while (p.start_mult < 3 && g[p.start_mult] == g[0]) ++p.start_mult;
        while (p.end_mult < 3 && g[3u - p.end_mult] == g[3]) ++p.end_mult;
        return p;
    }
    piece whole_piece(std::uint32_t ci, std::uint32_t s) const { return make_piece(curves[ci][s], ci, s); }
};

}  // namespace detail
}  // namespace crspline
