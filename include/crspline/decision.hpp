// crspline: a proved decision on crossings (issue 27). Does a plane curve
// cross itself, do two curves cross, do any curves of a set cross?
//
// The answer is one of three verdicts, each a statement about the piecewise
// cubic Bézier curve whose control points are the doubles
// catmull_rom::bezier(i) returns (B0 and B3 are the stored points exactly;
// B1 and B2 are rounded once from the tangents):
//
//   simple   proved: no two points of the curve (of two curves) coincide,
//            except consecutive segments at their shared point. Every pair
//            of pieces that could meet was shown apart by one of the
//            arguments in decision_argument, each evaluated with its
//            rounding error bounded (see "Proofs" below).
//   crosses  at least one crossing is proved: for each, parameter intervals
//            (u in segment[0], v in segment[1]) that contain exactly one
//            point where the two pieces meet, and meet transversally
//            (Krawczyk's test on F(u, v) = A(u) - B(v) in interval
//            arithmetic). Other pairs may be undecided (listed as touches).
//   touches  nothing crosses that could be proved, and some pieces come
//            within the floor delta (decision::floor) of each other without
//            either a proof that they are apart or a proof that they cross:
//            a tangency, a cusp, a fold, two vertices at one point that do
//            not cross, or a contact closer than double precision can
//            resolve. Each is reported with where and how close.
//
// The paper's certificate (certify.hpp) is the fast path: when it certifies
// a curve, the verdict is `simple` with the argument paper_rule and nothing
// else is computed.
//
// Proofs. The curve is taken relative to its first point (the difference
// enclosed exactly, so 1e8 offsets cost nothing). Each segment is cut into
// pieces that are monotone in some direction d (d . B'(u) > 0 on the piece,
// checked on the hodograph's control points): a monotone piece never meets
// itself. Pieces whose boxes meet are found with a box tree. A pair of
// pieces is then
//   * apart by separation: a separating axis (the two coordinate axes and
//     the normals of both chords) puts their convex hulls strictly apart;
//   * apart at a joint: consecutive pieces share their end point J exactly,
//     and a direction d puts every other control point of the first strictly
//     behind J and of the second strictly ahead of it (control points that
//     are exactly J, as at a zero tangent, are allowed: a piece's other
//     points carry positive weight away from its end);
//   * crossing: Krawczyk's operator of F over a parameter box lies strictly
//     inside the box, which proves one zero there and every Jacobian in the
//     box invertible (a transversal crossing); at the floor the box may
//     span a vertex into the neighbouring segment (a crossing at a vertex);
//   * a contact when both run along each other within their rounding
//     margins (flat, parallel, overlapping: a fold or a tangency);
//   * else split in halves (de Casteljau), down to the floor.
// Rounding: coarse pieces (plain doubles, relative to the first point)
// carry an error bound (the initial difference, plus 2 eps M per level of
// halving, where M bounds every coordinate relative to the first point);
// every projection is compared with a margin covering that bound and the
// rounding of the projection itself (|x . n| rounding <= 2 eps S |n|_1,
// taken as 10 eps S |n|_1, S bounding the coordinates: M here). Such
// margins do not shrink with the pieces, so below 2^-30 M a pair is made
// fine (refine()): each piece is made again from its segment as
// double-doubles (the blossom of the segment's exact Bezier points over
// its parameter range, within 128 eps^2 M, and halved in double-doubles
// from then on, 16 eps^2 M a level), and the pair is tested in a frame of
// its own (local(): points relative to a double near them, rounded once):
// margins of a few eps of the pieces' own size. Krawczyk's test runs in
// interval arithmetic with outward rounding (detail/interval.hpp) from an
// exact enclosure of the control points; for fine pieces and at the
// floor, F(m) itself is evaluated in double-doubles, so its enclosure is
// a few ulps of |F(m)| wide and crossings closer together than eps M over
// their angle are told apart.
//
// The floor: delta = 4 eps Mc, Mc the largest absolute coordinate (4 to 8
// ulps of it: about 8.9e-16 of a curve reaching out to its own size from
// the origin, and below the spacing of the coordinates themselves far from
// it). Two pieces, each no larger than delta, neither separated nor proved
// to cross, are a contact: they are within 2 sqrt(2) delta plus their
// margins of each other. Fine pieces are separated at any gap above a few
// eps of their own size (a gap g between arcs of curvature k: pieces of
// length about sqrt(8 g / k) separate, far above delta), so only exact
// contacts (tangencies, cusps, a vertex visited twice) and contacts within
// a few ulps reach the floor. Pieces running along each other within their
// margins (along()) are a contact when those margins are within delta,
// w = 2 (err) + 16 eps S <= delta (distance within 3 w); wider, they are
// halved until their frame is small enough. At the floor (and before an
// along-contact) a crossing is tried with Krawczyk's test in boxes wider
// than the pieces too (try_crossing): a shallow crossing needs a box wider
// than the rounding of F over the Jacobian's conditioning.
// A work budget (decision_options::budget, pair_budget) bounds the
// time anyway; a pair that exhausts it is reported as a contact with
// budget_exhausted set.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <initializer_list>
#include <map>
#include <optional>
#include <queue>
#include <span>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "catmull_rom.hpp"
#include "certify.hpp"
#include "detail/box_tree.hpp"
#include "detail/double_double.hpp"
#include "detail/interval.hpp"
#include "segment.hpp"
#include "vec.hpp"

namespace crspline {

enum class verdict { simple, crosses, touches };

inline const char* to_string(verdict v) noexcept {
    switch (v) {
        case verdict::simple: return "simple";
        case verdict::crosses: return "crosses";
        case verdict::touches: return "touches";
    }
    return "unknown";
}

/// The arguments that decide a pair of segments, as bit flags (a pair cut
/// into pieces may need several).
enum decision_argument : unsigned {
    paper_rule = 1,   ///< the paper's certificate (Section 5) certified the whole curve
    separation = 2,   ///< a separating axis between convex hulls, with rounding margins
    joint = 4,        ///< consecutive pieces meet only at their shared point (half-space test)
    monotone = 8,     ///< a piece is monotone in a direction: it does not meet itself
    crossing = 16,    ///< Krawczyk's test proved a transversal crossing
    unresolved = 32,  ///< a contact within the floor (or the budget ran out)
};

/// "separation+joint" for the flags set in `arguments`.
inline std::string argument_names(unsigned arguments) {
    static constexpr std::pair<unsigned, const char*> names[] = {{paper_rule, "paper_rule"}, {separation, "separation"},
                                                                 {joint, "joint"},           {monotone, "monotone"},
                                                                 {crossing, "crossing"},     {unresolved, "unresolved"}};
    std::string s;
    for (const auto& [bit, name] : names)
        if (arguments & bit) s += (s.empty() ? "" : "+") + std::string(name);
    return s;
}

/// A proved crossing: the two pieces meet exactly once, transversally, at
/// local parameters u in [u[0][0], u[0][1]] of segment[0] of curve[0] and
/// [u[1][0], u[1][1]] of segment[1] of curve[1]. At a vertex an interval
/// may reach past its segment's end (below 0 or above 1): that part lies in
/// the neighbouring segment (u - 1, or u + 1, there).
struct proved_crossing {
    std::array<std::size_t, 2> curve{};
    std::array<std::size_t, 2> segment{};
    std::array<std::array<double, 2>, 2> u{};
    vec<2> point{};  ///< the curve at the middle of the first interval (rounded)
};

/// Two pieces within the floor that could not be proved apart or crossing.
struct contact {
    std::array<std::size_t, 2> curve{};
    std::array<std::size_t, 2> segment{};  ///< equal for a contact inside one segment (cusp, fold)
    std::array<double, 2> u{};             ///< local parameters where it was found
    double distance = 0;                   ///< |A(u0) - B(u1)| there (rounded)
    std::size_t pieces = 0;                ///< unresolved piece pairs merged into this contact
    bool budget_exhausted = false;         ///< the work budget ran out (distance may exceed the floor)
};

/// Which arguments decided a pair of segments (i <= j; i == j: within one segment).
struct decided_pair {
    std::array<std::size_t, 2> curve{};
    std::array<std::size_t, 2> segment{};
    unsigned arguments = 0;
};

struct decision_options {
    bool fast_path = true;             ///< try the paper's certificate first (single curves)
    std::size_t budget = 0;            ///< visits in all before every remaining pair is a contact (0: 2^24 or 256 per piece, the larger)
    std::size_t pair_budget = 1u << 17;  ///< visits for one pair of pieces (an overlap or a near tangency)
    bool record_pairs = true;          ///< fill decision::pairs
    bool first_crossing = false;       ///< stop at the first proved crossing: the same verdict, the lists partial (and in the box tree's order)
};

struct decision {
    crspline::verdict result = verdict::simple;
    bool fast_path = false;                  ///< decided by the paper's certificate alone
    std::vector<proved_crossing> crossings;  ///< in order of (curve, segment) pairs
    std::vector<contact> touches;
    std::vector<decided_pair> pairs;         ///< every pair of segments examined (not with fast_path)
    double floor = 0;                        ///< delta: the contact floor (see the header comment)
    std::size_t pieces = 0;                  ///< monotone pieces the curves were cut into
    std::size_t visits = 0;                  ///< pairs of pieces examined
    std::size_t candidate_pairs = 0;         ///< pairs of pieces whose boxes met
};

/// A piecewise cubic Bézier curve in the plane: segment i runs from
/// segments[i][0] to segments[i][3]; consecutive segments share that point
/// exactly (segments[i][3] == segments[i + 1][0], and back to the first when
/// closed) -- the decision checks it.
struct bezier_path {
    std::span<const std::array<vec<2>, 4>> segments;
    bool closed = false;
};

namespace detail {

struct decision_engine {
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
        const decision_engine* e = nullptr;
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

    static bool separated_on(const piece& a, const piece& b, const P& n, double S) {
        if (!(norm1(n) > 0) || !std::isfinite(norm1(n))) return false;
        double a0 = dot(a.b[0], n), a1 = a0, b0 = dot(b.b[0], n), b1 = b0;
        for (std::size_t k = 1; k < 4; ++k) {
            a0 = std::min(a0, dot(a.b[k], n));
            a1 = std::max(a1, dot(a.b[k], n));
            b0 = std::min(b0, dot(b.b[k], n));
            b1 = std::max(b1, dot(b.b[k], n));
        }
        const double pad = margin(a.err + b.err, n, S);
        return a1 + pad < b0 || b1 + pad < a0;
    }
    static bool separated(const piece& a, const piece& b, double S) {
        const P ca = a.b[3] - a.b[0], cb = b.b[3] - b.b[0];
        const P axes[] = {P{{1, 0}}, P{{0, 1}}, P{{-ca[1], ca[0]}}, P{{-cb[1], cb[0]}}};
        for (const auto& n : axes)
            if (separated_on(a, b, n, S)) return true;
        return false;
    }

    // a ends where b starts (J, the same double): do they meet only there?
    static bool apart_at_joint(const piece& a, const piece& b, double S) {
        const P J = a.b[3];
        const P da = J - a.b[3u - a.end_mult], db = b.b[b.start_mult] - J;
        const P dirs[] = {da, db, da / std::max(norm1(da), 1e-300) + db / std::max(norm1(db), 1e-300)};
        for (const auto& d : dirs) {
            if (!(norm1(d) > 0) || !std::isfinite(norm1(d))) continue;
            const double pad = margin(2 * (a.err + b.err), d, S), j = dot(J, d);
            bool ok = true;
            for (std::size_t k = 0; k + a.end_mult < 4 && ok; ++k) ok = dot(a.b[k], d) < j - pad;
            for (std::size_t k = b.start_mult; k < 4 && ok; ++k) ok = dot(b.b[k], d) > j + pad;
            if (ok) return true;
        }
        return false;
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

    // Worth Krawczyk's test? Only where every tangent of a crosses every
    // tangent of b with one sign: the cross products of their hodographs'
    // control vectors (zero ones left out) all strictly positive or all
    // strictly negative. Elsewhere some Jacobian of F over the pieces may be
    // singular, and then the test cannot succeed (its success proves every
    // Jacobian in the box invertible): the pair is split instead, and its
    // halves' hodographs are tighter. A filter on where to try, rounded
    // plainly: it decides nothing, and a crossing it passes over is proved
    // on smaller pieces (or at the floor, where the test is always tried).
    static bool transversal(const piece& a, const piece& b) {
        // The chords meet (end points on both sides of the other's chord line, or on it).
        const P ca = a.b[3] - a.b[0], cb = b.b[3] - b.b[0];
        if (cross2(ca, b.b[0] - a.b[0]) * cross2(ca, b.b[3] - a.b[0]) > 0) return false;
        if (cross2(cb, a.b[0] - b.b[0]) * cross2(cb, a.b[3] - b.b[0]) > 0) return false;
        int pos = 0, neg = 0;
        for (std::size_t i = 0; i < 3; ++i) {
            const P ha = a.b[i + 1] - a.b[i];
            if (ha[0] == 0 && ha[1] == 0) continue;
            for (std::size_t j = 0; j < 3; ++j) {
                const P hb = b.b[j + 1] - b.b[j];
                if (hb[0] == 0 && hb[1] == 0) continue;
                const double x = cross2(ha, hb);
                pos += x > 0, neg += x < 0;
                if (!(x > 0 || x < 0) || (pos && neg)) return false;
            }
        }
        return true;
    }

    // Do two pieces run along each other within their rounding margins?
    // Both flat (their control points within w of their chord lines, w =
    // 2 (their error bounds) + 16 eps M), their chords parallel to within w
    // over their length, each one's end points within w of the other's
    // chord line, the chords' projections overlapping. Such pieces are
    // within a few w of each other all along (an overlap, as in a fold, or
    // a tangency at the margins' scale); no separating axis can ever be
    // proved for them and their halves repeat the same: a contact at once,
    // instead of 2^32 pieces down to the floor.
    static double along_width(const piece& a, const piece& b, double S) { return 2 * (a.err + b.err) + 16 * eps * S; }
    static bool along(const piece& a, const piece& b, double S) {
        const P ca = a.b[3] - a.b[0], cb = b.b[3] - b.b[0];
        const double la = norm(ca), lb = norm(cb), w = along_width(a, b, S);
        if (!(la > w) || !(lb > w)) return false;
        auto off = [](const P& x, const P& o, const P& c, double l) { return std::abs(cross2(x - o, c)) / l; };
        for (std::size_t k = 1; k < 3; ++k)
            if (off(a.b[k], a.b[0], ca, la) > w || off(b.b[k], b.b[0], cb, lb) > w) return false;
        if (std::abs(cross2(ca, cb)) > w * std::max(la, lb)) return false;
        if (off(b.b[0], a.b[0], ca, la) > w || off(b.b[3], a.b[0], ca, la) > w) return false;
        const double p0 = dot(b.b[0] - a.b[0], ca) / la, p1 = dot(b.b[3] - a.b[0], ca) / la;
        return std::max(p0, p1) > 0 && std::min(p0, p1) < la;
    }
    static double cross2(const P& x, const P& y) noexcept { return x[0] * y[1] - x[1] * y[0]; }

    // A contact's distance and where: the closest of nine samples of b to
    // the polyline through nine samples of a (rounded, in the pieces' own
    // frame, so the rounding is a few eps of their size; the pieces are
    // small or flat, so this is their distance to within the floor).
    void add_contact(const piece& a0, const piece& b0, bool exhausted) {
        const framed f = local(a0, b0);
        const piece &a = f.a, &b = f.b;
        double ua = (a.u0 + a.u1) / 2, ub = (b.u0 + b.u1) / 2, dist = std::numeric_limits<double>::infinity();
        constexpr int n = 8;
        std::array<P, n + 1> sa, sb;
        for (int k = 0; k <= n; ++k) {
            sa[std::size_t(k)] = bezier_at(a.b, double(k) / n);
            sb[std::size_t(k)] = bezier_at(b.b, double(k) / n);
        }
        for (int l = 0; l <= n; ++l)
            for (int k = 0; k < n; ++k) {
                const P e = sa[std::size_t(k) + 1] - sa[std::size_t(k)], x = sb[std::size_t(l)] - sa[std::size_t(k)];
                const double ee = dot(e, e), w = ee > 0 ? std::clamp(dot(x, e) / ee, 0.0, 1.0) : 0.0;
                const double dd = norm(x - w * e);
                if (dd < dist) {
                    dist = dd;
                    ua = a.u0 + (a.u1 - a.u0) * (k + w) / n;
                    ub = b.u0 + (b.u1 - b.u0) * l / n;
                }
            }
        const std::array<std::size_t, 4> key{a.curve, a.segment, b.curve, b.segment};
        const auto it = contact_index.find(key);
        if (it != contact_index.end()) {
            contact& c = out.touches[it->second];
            ++c.pieces;
            c.budget_exhausted = c.budget_exhausted || exhausted;
            if (dist < c.distance) {
                c.distance = dist;
                c.u = {ua, ub};
            }
            return;
        }
        contact c;
        c.curve = {a.curve, b.curve};
        c.segment = {a.segment, b.segment};
        c.u = {ua, ub};
        c.distance = dist;
        c.pieces = 1;
        c.budget_exhausted = exhausted;
        contact_index.emplace(key, out.touches.size());
        out.touches.push_back(c);
    }

    void flag(const piece& a, const piece& b, unsigned f) {
        std::array<std::size_t, 4> key{a.curve, a.segment, b.curve, b.segment};
        if (std::pair(key[2], key[3]) < std::pair(key[0], key[1])) key = {key[2], key[3], key[0], key[1]};
        if (record_pairs) pair_flags.push_back({key, f});
    }

    struct task {
        piece a, b;
        bool corner;
    };
    std::vector<task> pair_stack;
    std::vector<piece> cut_stack;

    // One pair of pieces; `corner`: a ends exactly where b starts.
    void decide_pair(const piece& a0, const piece& b0, bool corner) {
        auto& stack = pair_stack;  // reused: one allocation for every pair
        stack.assign(1, {a0, b0, corner});
        unsigned f = 0;
        std::size_t visits = 0;
        while (!stack.empty()) {
            task t = stack.back();
            stack.pop_back();
            if (out.visits >= budget || visits++ >= pair_budget) {
                add_contact(t.a, t.b, true);
                f |= unresolved;
                continue;
            }
            ++out.visits;
            const bool fine = t.a.fine || t.b.fine;
            if (fine && !(t.a.fine && t.b.fine)) {  // a fine cut piece against a coarse one: both fine
                refine(t.a);
                refine(t.b);
            }
            // The tests see the pieces in their own frame when fine (margins
            // of a few eps of their size), else as they are (margins of a
            // few eps M).
            std::optional<framed> fr;
            const piece *A = &t.a, *B = &t.b;
            double S = M;
            if (fine) {
                fr = local(t.a, t.b);
                A = &fr->a, B = &fr->b, S = fr->S;
            }
            if (separated(*A, *B, S)) { f |= separation; continue; }
            if (!fine && std::max(extent(t.a), extent(t.b)) <= fine_below) {  // again, in the fine frame
                refine(t.a);
                refine(t.b);
                stack.push_back(t);
                continue;
            }
            if (t.corner && apart_at_joint(*A, *B, S)) { f |= joint; continue; }
            if (!t.corner && (t.a.depth + t.b.depth > 0 || t.a.segment != t.b.segment || t.a.curve != t.b.curve) &&
                transversal(*A, *B) && try_crossing(t.a, t.b, false)) {
                f |= crossing;
                continue;
            }
            if (!t.corner && along(*A, *B, S)) {  // an overlap or a tangency along a stretch
                if (!fine) {  // again in the fine frame, whose margins are the pieces' own
                    refine(t.a);
                    refine(t.b);
                    stack.push_back(t);
                    continue;
                }
                // Within the floor all along: a contact, unless a (shallow)
                // crossing is proved in a box around them (pieces shorter
                // than the margins over the angle look along). Wider: halved
                // below, until their frame is small enough.
                if (along_width(*A, *B, S) <= floor) {
                    if (try_crossing(t.a, t.b, true)) {
                        f |= crossing;
                        continue;
                    }
                    add_contact(t.a, t.b, false);
                    f |= unresolved;
                    continue;
                }
            }
            const double ea = extent(t.a), eb = extent(t.b);
            const bool can_a = t.a.depth < max_depth, can_b = t.b.depth < max_depth;
            if (std::max(ea, eb) <= floor || (!can_a && !can_b)) {  // a contact, unless it crosses at a vertex
                if (!t.corner && try_crossing(t.a, t.b, true)) {
                    f |= crossing;
                    continue;
                }
                add_contact(t.a, t.b, false);
                f |= unresolved;
                continue;
            }
            if ((ea >= eb && can_a) || !can_b) {
                auto h = split(t.a);
                grow(h);
                stack.push_back({h[0], t.b, false});
                stack.push_back({h[1], t.b, t.corner});
            } else {
                auto h = split(t.b);
                grow(h);
                stack.push_back({t.a, h[0], t.corner});
                stack.push_back({t.a, h[1], false});
            }
        }
        flag(a0, b0, f);
    }

    // Cut one segment into monotone pieces, in order.
    void cut(const piece& s) {
        auto& stack = cut_stack;
        stack.assign(1, s);
        while (!stack.empty()) {
            piece p = stack.back();
            stack.pop_back();
            if (!p.fine && extent(p) <= fine_below) refine(p);
            const bool mono = p.fine ? [&] {
                const framed fr = local(p, p);
                return is_monotone(fr.a, fr.S);
            }() : is_monotone(p, M);
            if (mono) {
                pieces.push_back(p);
                continue;
            }
            if (p.depth >= max_depth || extent(p) <= floor) {
                // A cusp or a fold: the piece may meet itself; a contact within one segment.
                add_contact(p, p, false);
                flag(p, p, unresolved);
                pieces.push_back(p);
                continue;
            }
            auto h = split(p);
            grow(h);
            stack.push_back(h[1]);
            stack.push_back(h[0]);
        }
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

    void build() {
        pieces.e = this;
        // 1. The reference point and the bound M (the enclosures of the
        // relative control points are made when Krawczyk's test needs them).
        for (const auto& c : curves)
            if (c.size() > 0) { ref = c[0][0]; break; }
        std::size_t segments = 0;
        for (const auto& c : curves) {
            segments += c.size();
            for (std::size_t s = 0; s < c.size(); ++s)
                for (const auto& x : c[s]) {
                    M = std::max({M, std::abs(x[0] - ref[0]), std::abs(x[1] - ref[1])});
                    Mc = std::max({Mc, std::abs(x[0]), std::abs(x[1])});
                }
        }
        pieces.reserve(segments + segments / 64 + 16);  // most segments are one monotone piece
        M = std::nextafter(M * (1 + 1e-12), std::numeric_limits<double>::infinity());
        for (std::size_t ci = 0; ci < curves.size(); ++ci) {
            const auto& c = curves[ci];
            const std::size_t n = c.size();
            auto point_seg = [&](std::size_t s) {
                const auto g = c[s];
                return g[0] == g[1] && g[1] == g[2] && g[2] == g[3];
            };
            if (n >= none32) throw invalid_input("decision: curve " + std::to_string(ci) + " has 2^32 segments or more");
            std::vector<std::uint32_t> order;
            rank.emplace_back(n, none32);
            next_seg.emplace_back(n, none32);
            prev_seg.emplace_back(n, none32);
            for (std::size_t s = 0; s < n; ++s)
                if (!point_seg(s)) {
                    rank[ci][s] = std::uint32_t(order.size());
                    order.push_back(std::uint32_t(s));
                }
            nonpoint.push_back(order.size());
            for (std::size_t k = 0; k < order.size(); ++k) {
                const bool last = k + 1 == order.size();
                if (last && !closed[ci]) continue;
                const std::uint32_t s = order[k], t = order[last ? 0 : k + 1];
                if (s != t && c[s][3] == c[t][0]) {
                    next_seg[ci][s] = t;
                    prev_seg[ci][t] = s;
                }
            }
        }
        // The floor: 4 eps of the largest coordinate (4 to 8 of its ulps,
        // never below the least normal double); pieces are made fine below
        // 2^-30 M (coarse errors, 2 eps M a level, stay below 2^-20 of a
        // piece's size above that).
        floor = std::max(4 * eps * Mc, std::numeric_limits<double>::min());
        out.floor = floor;
        fine_below = std::ldexp(M, -30);
        // 2. Monotone pieces of every segment that is not a single point.
        for (std::size_t ci = 0; ci < curves.size(); ++ci) {
            first_piece.push_back(pieces.size());
            for (std::size_t s = 0; s < curves[ci].size(); ++s) {
                const auto& g = curves[ci][s];
                if (g[0] == g[1] && g[1] == g[2] && g[2] == g[3]) continue;
                const piece p = make_piece(g, ci, s);
                cut(p);
                flag(p, p, monotone);
            }
            // A closed curve of two pieces would have them adjacent at both ends.
            if (closed[ci] && pieces.size() - first_piece.back() == 2) {
                std::vector<piece> halves;
                for (std::size_t k = first_piece.back(); k < pieces.size(); ++k) {
                    auto h = split(pieces[k]);
                    grow(h);
                    halves.push_back(h[0]);
                    halves.push_back(h[1]);
                }
                pieces.resize(first_piece.back());
                for (const auto& h : halves) pieces.push_back(h);
            }
        }
        first_piece.push_back(pieces.size());
        out.pieces = pieces.size();
        if (budget == 0) budget = std::max<std::size_t>(std::size_t(1) << 24, 256 * pieces.size());
    }

    // Is the pair (p, q), p < q, consecutive? Returns 1 when p ends where q
    // starts, 2 when q ends where p starts (across a closed curve's seam).
    int adjacency(std::size_t p, std::size_t q) const {
        // The index tests first: a piece that is a whole segment is rebuilt
        // from the curve when read, and most candidate pairs are neither.
        const std::uint32_t c = pieces.curve(p);
        if (pieces.curve(q) != c) return 0;
        if (q == p + 1 && shares_end(p, q)) return 1;
        if (closed[c] && p == first_piece[c] && q + 1 == first_piece[c + 1] && shares_end(q, p)) return 2;
        return 0;
    }
    // Does piece x end exactly where piece y starts (one curve)? Pieces of
    // one segment that meet share B(u) exactly, whatever their points'
    // rounding (coarse or fine); pieces of two segments share a point when
    // the segments' end and start are the same double.
    bool shares_end(std::size_t x, std::size_t y) const {
        const std::uint32_t sx = pieces.segment(x), sy = pieces.segment(y);
        if (sx == sy) return pieces.u1(x) == pieces.u0(y);
        if (!(pieces.u1(x) == 1 && pieces.u0(y) == 0)) return false;
        const auto& c = curves[pieces.curve(x)];
        if (c.curve) {  // B0 and B3 are the curve's points (catmull_rom::bezier)
            const auto pts = c.curve->points();
            return pts[(std::size_t(sx) + 1) % pts.size()] == pts[sy];
        }
        return c.given[sx][3] == c.given[sy][0];
    }

    void run(bool self, bool between) {
        build();
        // 3. Candidate pairs: the pairs of pieces whose boxes (grown by each
        // piece's error and the rounding of the growth) meet. The tree holds
        // runs of `chunk` consecutive pieces under their merged box (a
        // quarter of the memory of a tree of pieces, for the report's
        // verdict at 10^6 points); the pieces of two runs that meet, and of
        // one run, are matched box against box: the same pairs as a tree of
        // the pieces would give.
        if (pieces.size() > std::numeric_limits<std::uint32_t>::max())
            throw invalid_input("decision: more than 2^32 pieces");
        constexpr std::size_t chunk = 4;
        const auto piece_box = [&](std::size_t k) {
            const auto hb = hull_box(pieces[k]);
            const double g = pieces[k].err + 8 * eps * M;
            return box<2, double>{hb[0] - P{{g, g}}, hb[1] + P{{g, g}}};
        };
        const std::size_t runs = (pieces.size() + chunk - 1) / chunk;
        const auto run_of = [&](std::size_t r, std::array<box<2, double>, chunk>& bx) {
            const std::size_t k0 = r * chunk, k1 = std::min(pieces.size(), k0 + chunk);
            for (std::size_t k = k0; k < k1; ++k) bx[k - k0] = piece_box(k);
            return std::array<std::size_t, 2>{k0, k1};
        };
        const box_tree<2, double> tree = [&] {
            std::vector<box<2, double>> boxes(runs);  // the tree keeps its own copy
            std::array<box<2, double>, chunk> bx;
            for (std::size_t r = 0; r < runs; ++r) {
                const auto [k0, k1] = run_of(r, bx);
                boxes[r] = bx[0];
                for (std::size_t k = k0 + 1; k < k1; ++k) boxes[r] = merge(boxes[r], bx[k - k0]);
            }
            return box_tree<2, double>(boxes);
        }();
        const auto for_each_candidate = [&](auto&& f) {
            std::array<box<2, double>, chunk> bx, by;
            for (std::size_t r = 0; r < runs; ++r) {
                const auto [k0, k1] = run_of(r, bx);
                for (std::size_t k = k0; k < k1; ++k)
                    for (std::size_t l = k + 1; l < k1; ++l)
                        if (boxes_meet(bx[k - k0], bx[l - k0], 0.0)) f(std::uint32_t(k), std::uint32_t(l));
            }
            tree.for_each_meeting_pair(0.0, [&](std::uint32_t r, std::uint32_t q) {  // r < q: its pieces come first
                const auto [k0, k1] = run_of(r, bx);
                const auto [l0, l1] = run_of(q, by);
                for (std::size_t k = k0; k < k1; ++k)
                    for (std::size_t l = l0; l < l1; ++l)
                        if (boxes_meet(bx[k - k0], by[l - l0], 0.0)) f(std::uint32_t(k), std::uint32_t(l));
            });
        };
        const auto wanted = [&](std::uint32_t i, std::uint32_t j) {
            const bool same = pieces.curve(i) == pieces.curve(j);
            return (same && self) || (!same && between);
        };
        const auto decide_candidate = [&](std::uint32_t i, std::uint32_t j) {
            const int adj = self ? adjacency(i, j) : 0;
            if (adj == 1) decide_pair(pieces[i], pieces[j], true);
            else if (adj == 2) decide_pair(pieces[j], pieces[i], true);
            else decide_pair(pieces[i], pieces[j], false);
        };
        if (first_crossing) {
            // 4'. The verdict only: each pair as it is met, none
            // after the first proved crossing, and no list of them held
            // (the report's verdict at 10^6 points).
            for_each_candidate([&](std::uint32_t i, std::uint32_t j) {
                if (!out.crossings.empty() || !wanted(i, j)) return;
                ++out.candidate_pairs;
                decide_candidate(i, j);
            });
        } else {
            std::vector<std::array<std::uint32_t, 2>> cand;
            for_each_candidate([&](std::uint32_t i, std::uint32_t j) {
                if (wanted(i, j)) cand.push_back({i, j});
            });
            // In order of (i, j), whatever the tree's order: counted out by i
            // (linear), each run sorted by j.
            {
                std::vector<std::size_t> start(pieces.size() + 1, 0);
                for (const auto& c : cand) ++start[c[0] + 1];
                for (std::size_t k = 0; k < pieces.size(); ++k) start[k + 1] += start[k];
                std::vector<std::array<std::uint32_t, 2>> by_i(cand.size());
                std::vector<std::size_t> next(start.begin(), start.end() - 1);
                for (const auto& c : cand) by_i[next[c[0]]++] = c;
                for (std::size_t k = 0; k < pieces.size(); ++k)
                    std::sort(by_i.begin() + std::ptrdiff_t(start[k]), by_i.begin() + std::ptrdiff_t(start[k + 1]));
                cand.swap(by_i);
            }
            out.candidate_pairs = cand.size();
            // 4. Every candidate pair.
            for (const auto& [i, j] : cand) decide_candidate(i, j);
        }
        // 5. The verdict.
        std::sort(out.crossings.begin(), out.crossings.end(), [](const proved_crossing& x, const proved_crossing& y) {
            return std::tie(x.curve, x.segment, x.u[0][0]) < std::tie(y.curve, y.segment, y.u[0][0]);
        });
        out.result = !out.crossings.empty() ? verdict::crosses : !out.touches.empty() ? verdict::touches : verdict::simple;
        std::sort(pair_flags.begin(), pair_flags.end());
        for (std::size_t k = 0; k < pair_flags.size();) {
            const auto& key = pair_flags[k].first;
            unsigned f = 0;
            for (; k < pair_flags.size() && pair_flags[k].first == key; ++k) f |= pair_flags[k].second;
            out.pairs.push_back({{key[0], key[2]}, {key[1], key[3]}, f});
        }
    }
};

inline void check_path(const bezier_path& c, std::size_t ci) {
    const auto& s = c.segments;
    for (std::size_t i = 0; i < s.size(); ++i) {
        for (std::size_t k = 0; k < 4; ++k)
            if (!std::isfinite(s[i][k][0]) || !std::isfinite(s[i][k][1]))
                throw invalid_input("decision: curve " + std::to_string(ci) + " segment " + std::to_string(i) +
                                    " Bezier point " + std::to_string(k) + " is not finite");
        const bool last = i + 1 == s.size();
        if ((!last || c.closed) && !(s[i][3] == s[last ? 0 : i + 1][0]))
            throw invalid_input("decision: curve " + std::to_string(ci) + " segment " + std::to_string(i) +
                                " does not end where segment " + std::to_string(last ? 0 : i + 1) + " starts");
    }
}

inline decision run_engine(decision_engine& e, bool self, bool between, const decision_options& opt);

inline decision decide_paths(std::span<const bezier_path> curves, bool self, bool between, const decision_options& opt) {
    decision_engine e;
    for (std::size_t ci = 0; ci < curves.size(); ++ci) {
        check_path(curves[ci], ci);
        e.curves.push_back({curves[ci].segments, nullptr});
        e.closed.push_back(curves[ci].closed);
    }
    return run_engine(e, self, between, opt);
}

// The same for curves whose Bézier points the engine asks for one segment at
// a time (valid by construction: finite, consecutive segments sharing their
// end points exactly).
inline decision decide_curves(std::span<const catmull_rom<2>* const> curves, bool self, bool between,
                              const decision_options& opt) {
    decision_engine e;
    for (std::size_t ci = 0; ci < curves.size(); ++ci) {
        const catmull_rom<2>* c = curves[ci];
        // Finite points, but B1 and B2 may overflow (huge coordinates): refused as for a Bézier path.
        for (std::size_t i = 0; i < c->segment_count(); ++i) {
            const auto b = c->bezier(i);
            for (std::size_t k = 0; k < 4; ++k)
                if (!std::isfinite(b[k][0]) || !std::isfinite(b[k][1]))
                    throw invalid_input("decision: curve " + std::to_string(ci) + " segment " + std::to_string(i) +
                                        " Bezier point " + std::to_string(k) + " is not finite");
        }
        e.curves.push_back({{}, c});
        e.closed.push_back(c->closed());
    }
    return run_engine(e, self, between, opt);
}

inline decision run_engine(decision_engine& e, bool self, bool between, const decision_options& opt) {
    e.budget = opt.budget;
    e.pair_budget = opt.pair_budget;
    e.record_pairs = opt.record_pairs;
    e.first_crossing = opt.first_crossing;
    e.run(self, between);
    return std::move(e.out);
}

}  // namespace detail

/// The decision for one piecewise Bézier curve (does it cross itself?).
inline decision decide(const bezier_path& c, const decision_options& opt = {}) {
    return detail::decide_paths(std::span<const bezier_path>(&c, 1), true, false, opt);
}

/// The decision for one curve: does it cross itself? 2-D only. The paper's
/// certificate first (opt.fast_path), then the proofs of the header comment.
inline decision decide(const catmull_rom<2>& c, const decision_options& opt = {}) {
    if (opt.fast_path) {
        certify_options co;
        co.search_on_failure = false;
        if (certify_intersection_free(c, co).certified) {
            decision d;
            d.result = verdict::simple;
            d.fast_path = true;
            if (opt.record_pairs) d.pairs.push_back({{0, 0}, {0, c.segment_count() - 1}, paper_rule});
            return d;
        }
    }
    const catmull_rom<2>* p[1] = {&c};
    return detail::decide_curves(p, true, false, opt);
}

/// Do two curves cross each other? (Each one's own crossings are not
/// looked for: decide(a) and decide(b) answer that.) curve[0] of each
/// crossing is 0 for a, 1 for b.
inline decision decide(const catmull_rom<2>& a, const catmull_rom<2>& b, const decision_options& opt = {}) {
    const catmull_rom<2>* p[2] = {&a, &b};
    return detail::decide_curves(p, false, true, opt);
}

/// Do any two curves of a set cross each other? Every pair of pieces whose
/// boxes meet is found through one box tree over all the curves' pieces.
/// With `self`, each curve's own crossings are decided too (no fast path).
inline decision decide(std::span<const catmull_rom<2>> curves, bool self = false, const decision_options& opt = {}) {
    std::vector<const catmull_rom<2>*> p(curves.size());
    for (std::size_t i = 0; i < curves.size(); ++i) p[i] = &curves[i];
    return detail::decide_curves(p, self, true, opt);
}


/// The decision as a report value, made by a report_builder B (report.hpp):
///
///     {"verdict": "simple" | "crosses" | "touches", "fast_path": bool,
///      "floor": number,
///      "crossings": [{"curves": [i, j], "segments": [a, b],
///                     "u": [[lo, hi], [lo, hi]], "point": [x, y]}],
///      "touches": [{"curves", "segments", "u": [u, v], "distance",
///                   "budget_exhausted"}],
///      "pairs": [{"curves", "segments", "arguments": ["separation", ...]}]}
///
/// Every front end's decide() returns this object (its keys written here
/// once: docs/report.md, "The decision object"); the whole-curve report
/// carries only its verdict, as "verdict" at its top (report.hpp).
template <class B>
typename B::value report_decision(B& b, const decision& d) {
    auto idx2 = [&](const std::array<std::size_t, 2>& a) {
        auto v = b.array();
        for (const std::size_t i : a) b.push(v, b.integer(i));
        return v;
    };
    auto nums = [&](std::initializer_list<double> xs) {
        auto v = b.array();
        for (const double x : xs) b.push(v, b.number(x));
        return v;
    };
    auto o = b.object();
    b.set(o, "verdict", b.string(to_string(d.result)));
    b.set(o, "fast_path", b.boolean(d.fast_path));
    b.set(o, "floor", b.number(d.floor));
    auto crossings = b.array();
    for (const auto& c : d.crossings) {
        auto x = b.object();
        b.set(x, "curves", idx2(c.curve));
        b.set(x, "segments", idx2(c.segment));
        auto u = b.array();
        b.push(u, nums({c.u[0][0], c.u[0][1]}));
        b.push(u, nums({c.u[1][0], c.u[1][1]}));
        b.set(x, "u", std::move(u));
        b.set(x, "point", nums({c.point[0], c.point[1]}));
        b.push(crossings, std::move(x));
    }
    b.set(o, "crossings", std::move(crossings));
    auto touches = b.array();
    for (const auto& t : d.touches) {
        auto x = b.object();
        b.set(x, "curves", idx2(t.curve));
        b.set(x, "segments", idx2(t.segment));
        b.set(x, "u", nums({t.u[0], t.u[1]}));
        b.set(x, "distance", b.number(t.distance));
        b.set(x, "budget_exhausted", b.boolean(t.budget_exhausted));
        b.push(touches, std::move(x));
    }
    b.set(o, "touches", std::move(touches));
    auto pairs = b.array();
    for (const auto& p : d.pairs) {
        auto x = b.object();
        b.set(x, "curves", idx2(p.curve));
        b.set(x, "segments", idx2(p.segment));
        auto names = b.array();
        for (unsigned bit = 1; bit <= unresolved; bit <<= 1)
            if (p.arguments & bit) b.push(names, b.string(argument_names(bit)));
        b.set(x, "arguments", std::move(names));
        b.push(pairs, std::move(x));
    }
    b.set(o, "pairs", std::move(pairs));
    return o;
}


// ---------------------------------------------------------------------------
// Clearance: the least distance between non-adjacent parts
// ---------------------------------------------------------------------------

/// Where the least distance is attained: local parameter u of segment[k] of
/// curve[k], the two points, and a lower bound: the true least distance lies
/// in [lower_bound, distance], and distance - lower_bound <= the accuracy
/// asked for (unless `exhausted`).
template <std::size_t D>
struct clearance_result {
    double distance = std::numeric_limits<double>::infinity();  ///< infinity: no pair to measure
    double lower_bound = std::numeric_limits<double>::infinity();
    std::array<std::size_t, 2> curve{};
    std::array<std::size_t, 2> segment{};
    std::array<double, 2> u{};
    std::array<vec<D>, 2> points{};
    bool exhausted = false;  ///< the work budget ran out before the accuracy was reached
};

namespace detail {

// Branch and bound over pairs of Bézier pieces, in any dimension. Lower
// bound of a pair: the larger of the gap between the control points' boxes
// and the gap of their projections on the line through the two pieces'
// control-point centroids (the convex hulls contain the pieces). Upper
// bound: the distance between the pieces' end points, which lie on the
// curves. Pairs are taken in order of their lower bound; the search stops
// when the best lower bound reaches the distance found less the accuracy.
// Floating point throughout (the bounds are rounded to a few ulps of the
// coordinates, which the accuracy must exceed).
template <std::size_t D>
clearance_result<D> clearance_among(const std::vector<std::vector<std::array<vec<D>, 4>>>& curves,
                                    const std::vector<std::array<std::size_t, 4>>& segment_pairs, double accuracy,
                                    std::size_t budget) {
    using V = vec<D>;
    struct piece {
        std::array<V, 4> b;
        double u0, u1;
        std::size_t curve, segment;
    };
    struct item {
        double lower;
        piece a, b;
        bool operator<(const item& o) const noexcept { return lower > o.lower; }  // min-heap
    };
    clearance_result<D> best;
    auto lower = [](const piece& a, const piece& b) {
        double gap = 0;
        V ca{}, cb{};
        for (std::size_t k = 0; k < D; ++k) {
            double alo = a.b[0][k], ahi = alo, blo = b.b[0][k], bhi = blo;
            for (const auto& x : a.b) { alo = std::min(alo, x[k]); ahi = std::max(ahi, x[k]); }
            for (const auto& x : b.b) { blo = std::min(blo, x[k]); bhi = std::max(bhi, x[k]); }
            const double g = std::max(blo - ahi, alo - bhi);
            if (g > 0) gap += g * g;
        }
        for (std::size_t q = 0; q < 4; ++q) { ca += a.b[q] / 4.0; cb += b.b[q] / 4.0; }
        double lb = std::sqrt(gap);
        const V d = cb - ca;
        const double L = norm(d);
        if (L > 0) {
            const V n = d / L;
            double amax = -std::numeric_limits<double>::infinity(), bmin = -amax;
            for (const auto& x : a.b) amax = std::max(amax, dot(x, n));
            for (const auto& x : b.b) bmin = std::min(bmin, dot(x, n));
            lb = std::max(lb, bmin - amax);
        }
        return std::max(lb, 0.0);
    };
    auto upper = [&](const piece& a, const piece& b) {
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) {
                const V& x = a.b[i ? 3 : 0];
                const V& y = b.b[j ? 3 : 0];
                const double dd = norm(x - y);
                if (dd < best.distance) {
                    best.distance = dd;
                    best.curve = {a.curve, b.curve};
                    best.segment = {a.segment, b.segment};
                    best.u = {i ? a.u1 : a.u0, j ? b.u1 : b.u0};
                    best.points = {x, y};
                }
            }
    };
    auto split = [](const piece& p) {
        const auto& q = p.b;
        const V a0 = lerp(q[0], q[1], 0.5), a1 = lerp(q[1], q[2], 0.5), a2 = lerp(q[2], q[3], 0.5);
        const V q0 = lerp(a0, a1, 0.5), q1 = lerp(a1, a2, 0.5), m = lerp(q0, q1, 0.5);
        const double um = (p.u0 + p.u1) / 2;
        return std::array<piece, 2>{piece{{q[0], a0, q0, m}, p.u0, um, p.curve, p.segment},
                                    piece{{m, q1, a2, q[3]}, um, p.u1, p.curve, p.segment}};
    };
    auto extent = [](const piece& p) { return norm(p.b[3] - p.b[0]) + norm(p.b[1] - p.b[0]) + norm(p.b[2] - p.b[3]); };
    std::priority_queue<item> heap;
    for (const auto& sp : segment_pairs) {
        const piece a{curves[sp[0]][sp[1]], 0, 1, sp[0], sp[1]}, b{curves[sp[2]][sp[3]], 0, 1, sp[2], sp[3]};
        upper(a, b);
        heap.push({lower(a, b), a, b});
    }
    std::size_t visits = 0;
    while (!heap.empty()) {
        const item it = heap.top();
        if (it.lower >= best.distance - accuracy) break;
        heap.pop();
        if (++visits > budget) {
            best.exhausted = true;
            best.lower_bound = it.lower;
            return best;
        }
        const bool split_a = extent(it.a) >= extent(it.b);
        const auto h = split(split_a ? it.a : it.b);
        for (const auto& c : h) {
            const piece& a = split_a ? c : it.a;
            const piece& b = split_a ? it.b : c;
            upper(a, b);
            const double lb = lower(a, b);
            if (lb < best.distance - accuracy) heap.push({lb, a, b});
        }
    }
    best.lower_bound = heap.empty() ? best.distance : std::min(best.distance, heap.top().lower);
    // Points relative to nothing: the curves were given as they are.
    return best;
}

// The segment pairs that can hold the least distance: the pairs whose
// boxes come within `reach` (found with the box tree), without
// neighbours in one curve (consecutive segments, through zero-length
// ones, and across a closed curve's seam) when `self`.
template <std::size_t D>
std::vector<std::array<std::size_t, 4>> clearance_pairs(const std::vector<std::vector<std::array<vec<D>, 4>>>& curves,
                                                        const std::vector<bool>& closed, bool self, bool between) {
    std::vector<box<D, double>> boxes;
    std::vector<std::array<std::size_t, 2>> id;
    std::vector<std::vector<std::size_t>> rank(curves.size());  // order among non-point segments
    std::vector<std::size_t> count(curves.size());
    for (std::size_t c = 0; c < curves.size(); ++c) {
        for (std::size_t s = 0; s < curves[c].size(); ++s) {
            const auto& g = curves[c][s];
            rank[c].push_back(count[c]);
            if (g[0] == g[1] && g[1] == g[2] && g[2] == g[3]) continue;  // a point
            ++count[c];
            box<D, double> bx{g[0], g[0]};
            for (const auto& x : g)
                for (std::size_t k = 0; k < D; ++k) {
                    bx.lo[k] = std::min(bx.lo[k], x[k]);
                    bx.hi[k] = std::max(bx.hi[k], x[k]);
                }
            boxes.push_back(bx);
            id.push_back({c, s});
        }
    }
    auto neighbours = [&](std::size_t c, std::size_t s, std::size_t t) {
        const std::size_t a = rank[c][s], b = rank[c][t], n = count[c];
        const std::size_t d = a > b ? a - b : b - a;
        return d <= 1 || (closed[c] && d + 1 == n);
    };
    // Reach: from the largest box, widened until a pair is found. Once the
    // pairs within `reach` hold one at distance found <= reach, every pair
    // closer than that has boxes within reach: they are all there.
    double reach = 0, whole = 0;
    box<D, double> all{};
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        all = i ? merge(all, boxes[i]) : boxes[i];
        for (std::size_t k = 0; k < D; ++k) reach = std::max(reach, boxes[i].hi[k] - boxes[i].lo[k]);
    }
    for (std::size_t k = 0; k < D && !boxes.empty(); ++k) whole += all.hi[k] - all.lo[k];
    reach = std::max(reach, std::numeric_limits<double>::min());
    const box_tree<D, double> tree(boxes);
    while (true) {
        std::vector<std::array<std::size_t, 4>> pairs;
        double found = std::numeric_limits<double>::infinity();
        tree.for_each_meeting_pair(reach, [&](std::uint32_t i, std::uint32_t j) {
            const auto a = id[i], b = id[j];
            const bool same = a[0] == b[0];
            if (same ? (!self || neighbours(a[0], a[1], b[1])) : !between) return;
            pairs.push_back({a[0], a[1], b[0], b[1]});
            for (const std::size_t p : {std::size_t(0), std::size_t(3)})
                for (const std::size_t q : {std::size_t(0), std::size_t(3)})
                    found = std::min(found, norm(curves[a[0]][a[1]][p] - curves[b[0]][b[1]][q]));
        });
        if (found <= reach || reach > whole) return pairs;  // all there, or every pair was looked at
        reach = std::isfinite(found) ? found : 4 * reach;
    }
}

template <std::size_t D>
std::vector<std::array<vec<D>, 4>> relative_bezier(const catmull_rom<D>& c, const vec<D>& ref) {
    auto b = c.bezier();
    for (auto& s : b)
        for (auto& x : s) x = x - ref;
    return b;
}

template <std::size_t D>
clearance_result<D> clearance_of(std::vector<std::vector<std::array<vec<D>, 4>>> curves, const std::vector<bool>& closed,
                                 const vec<D>& ref, bool self, bool between, double accuracy, std::size_t budget) {
    double size = 0;
    for (const auto& c : curves)
        for (const auto& s : c)
            for (const auto& x : s) size = std::max(size, max_abs(x));
    if (!(accuracy > 0)) accuracy = 1e-10 * size;
    const auto pairs = clearance_pairs<D>(curves, closed, self, between);
    auto r = clearance_among<D>(curves, pairs, accuracy, budget);
    for (auto& x : r.points) x = x + ref;
    return r;
}

}  // namespace detail

/// The least distance between non-adjacent segments of a curve (segments
/// that are not consecutive, through zero-length segments and across a
/// closed curve's seam), any dimension, to within `accuracy` (0: 1e-10 of
/// the curve's extent from its first point). Crossings inside a segment or
/// between neighbours are decide()'s business, not measured here. A tube of
/// radius r around a 3-D curve has no self-contact between non-adjacent
/// segments when the clearance exceeds 2 r (and, near the joints, when the
/// curvature stays below 1 / r).
template <std::size_t D>
clearance_result<D> clearance(const catmull_rom<D>& c, double accuracy = 0, std::size_t budget = 1u << 22) {
    const vec<D> ref = c.points()[0];
    return detail::clearance_of<D>({detail::relative_bezier(c, ref)}, {c.closed()}, ref, true, false, accuracy, budget);
}

/// The least distance between two curves (curve 0 is a, 1 is b).
template <std::size_t D>
clearance_result<D> clearance(const catmull_rom<D>& a, const catmull_rom<D>& b, double accuracy = 0,
                              std::size_t budget = 1u << 22) {
    const vec<D> ref = a.points()[0];
    return detail::clearance_of<D>({detail::relative_bezier(a, ref), detail::relative_bezier(b, ref)},
                                   {a.closed(), b.closed()}, ref, false, true, accuracy, budget);
}

}  // namespace crspline
