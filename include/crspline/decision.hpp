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

// The parts, one job each (include/crspline/decision/):
//   report.hpp     the verdict, crossings, contacts, options; report_decision
//   pieces.hpp     monotone pieces, halving, fine pieces, frames
//   arguments.hpp  separation, joints, transversality, along-contacts
//   krawczyk.hpp   Krawczyk's test and the proved crossings' bookkeeping
//   engine.hpp     the pairs, the floor, the contacts: the decision itself
//   clearance.hpp  the least distance between non-adjacent parts
// This header is the public entry: decide() and everything above.

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
#include "decision/clearance.hpp"
#include "decision/engine.hpp"
#include "decision/report.hpp"

namespace crspline {

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

}  // namespace crspline
