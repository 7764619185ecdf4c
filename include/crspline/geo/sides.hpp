// crspline::geo internals: the part of the proof that looks at one arc at a
// time: its own tests (loops, cusps, deviation, domain), its raises, and
// containment (issue 39): no vertex of another arc in the region a segment
// sweeps between its input (chord, or the input polyline a fitted segment
// covers) and its curve.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "../analysis.hpp"
#include "../detail/fit_proof.hpp"
#include "arcs.hpp"
#include "hulls.hpp"

namespace crspline::geo {

namespace detail {

// What the proof knows of one arc at a time: the arcs, the options, the
// rounding slack; an arc's own tests (prepare), its raises (tension, or a
// fitted arc's left-out vertices back) and containment (issue 39): a vertex
// of another arc against the region a segment sweeps. proof (proof.hpp)
// adds the pairs and the rounds.
struct proof_base {
    std::vector<arc_work>& arcs;
    const smooth_options& opt;
    double slack;

    proof_base(std::vector<arc_work>& a, const smooth_options& o, double rounding) : arcs(a), opt(o), slack(rounding) {}

    // Rebuilds a dirty arc: curve, polyline, Bézier hulls; flags the
    // segments that fail a test of their own (loop or cusp, deviation,
    // domain) and records the arc's deviation bound.
    void prepare(std::uint32_t i) {
        arc_work& a = arcs[i];
        build_arc_curve(a, opt.alpha);
        a.has_line = false;
        a.pieces = 0;
        if (opt.polylines) ensure_line(i);
        const std::size_t segs = a.segments();
        a.hull.resize(segs);
        a.hull_box.resize(segs);
        a.max_dev = 0;
        for (std::size_t s = 0; s < segs; ++s) {
            auto& b = a.hull[s];
            b = segment_bezier(a, s);
            box<2> bx = box<2>::of(b[0]);
            for (int j = 1; j < 4; ++j) bx.expand(b[j]);
            a.hull_box[s] = bx;
            if (s == 0) a.bounds = bx;
            a.bounds.expand(bx);
            if (a.linear(s)) continue;
            // Loops and cusps inside the segment: exact, unless it plainly advances.
            if (opt.preserve_topology && !advances_along_chord(b, slack)) {
                const auto an = analyze_segment(a.curve->segment(s));
                if (an.has_self_intersection() || an.has_cusp()) a.raise[s] = 1;
            }
            double dev;
            if (a.dropped(s)) {
                // Both ways against the input vertices the segment covers
                // (fit.hpp's proof, rounding included).
                const auto [first, last] = a.span(s);
                const crspline::detail::poly_range<2, double> pr{std::span<const p2>(a.full), first % a.full.size(),
                                                                 last - first + 1};
                const auto proved = crspline::detail::prove_segment(a.curve->segment(s), pr, *opt.fit, slack);
                dev = proved.proved ? proved.worst() : INFINITY;
                if (!proved.proved) a.raise[s] = 1;
            } else {
                dev = segment_deviation(b) + slack;
                if (opt.fit && dev > *opt.fit) a.raise[s] = 1;
            }
            a.max_dev = std::max(a.max_dev, dev);
            if (opt.max_deviation && dev > *opt.max_deviation) a.raise[s] = 1;
            if (opt.domain) {
                bool inside = true;
                for (const p2& q : b) inside = inside && opt.domain->contains(q);
                // The hull leaves the domain: the pieces' own hulls decide.
                if (!inside) ensure_line(i);
                for (std::size_t k = a.first_piece[s]; !inside && k < a.first_piece[s + 1]; ++k) {
                    const piece pc = piece_of(a, i, k, slack);
                    bool in = true;
                    for (const p2& q : pc.q) in = in && opt.domain->contains(q);
                    if (!in) {
                        a.raise[s] = 1;
                        break;
                    }
                }
            }
        }
    }

    // The arc's polyline (tessellated once per curve) and its pieces per segment.
    void ensure_line(std::uint32_t i) {
        arc_work& a = arcs[i];
        if (a.has_line) return;
        tessellate_arc(a, opt.tolerance);
        const std::size_t segs = a.segments();
        a.first_piece.assign(segs + 1, 0);
        for (std::size_t k = a.line.points.size() - 1; k-- > 0;) a.first_piece[a.vseg[k]] = k;
        a.first_piece[segs] = a.line.points.size() - 1;
        a.has_line = true;
        a.pieces = a.line.points.size() - 1;
    }

    void fail(const piece& pc) {
        if (!pc.linear) arcs[pc.arc].raise[pc.seg] = 1;
    }

    // The arc's segments flagged this round: a segment of a fitted arc that
    // left input vertices out gets them back (the curve nearer its input;
    // with `last`, every left-out vertex of the arc comes back); the others
    // get their vertices' tension raised one level (with `last`, to the
    // last resort). True when anything changed.
    bool apply_raises(arc_work& a, bool last) {
        bool failed = false, restore = false;
        for (std::size_t s = 0; s < a.segments(); ++s) {
            if (!a.raise[s]) continue;
            failed = true;
            if (a.dropped(s)) {
                restore = true;
                continue;
            }
            for (std::size_t v : {s, a.next(s)}) {
                const std::uint8_t to = last ? linear_level : std::uint8_t(a.level[v] + 1);
                a.level[v] = std::min(linear_level, std::max(a.level[v], to));
            }
        }
        if (restore) {
            std::vector<p2> pts;
            std::vector<std::uint32_t> src;
            std::vector<std::uint8_t> level;
            for (std::size_t s = 0; s < a.pts.size(); ++s) {
                pts.push_back(a.pts[s]);
                src.push_back(a.src[s]);
                level.push_back(a.level[s]);
                if (s == a.segments() || !a.dropped(s) || !(a.raise[s] || last)) continue;
                const auto [b, e] = a.span(s);
                for (std::size_t k = b + 1; k < e; ++k) {
                    pts.push_back(a.full_at(k));
                    src.push_back(std::uint32_t(k));
                    level.push_back(0);
                    ++restored;
                }
            }
            a.pts = std::move(pts);
            a.src = std::move(src);
            a.level = std::move(level);
            a.raise.assign(a.segments(), 0);
            a.has_line = false;
        }
        return failed;
    }

    // Containment (issue 39). Every input vertex stays on its arc and no
    // new crossing is allowed, so a vertex w of another arc can change side
    // of this arc's ring (or line) only through the region a segment sweeps
    // between its input chord and its curve: the winding number around w
    // of the output ring minus that of the input ring is the sum, over the
    // segments, of the winding numbers around w of the loops "curve, then
    // the input chord back". So where every such loop's winding around
    // every vertex of every other arc is 0, every part keeps its side of
    // every ring: holes stay in their shells, islands stay out, lines stay
    // on their side. Proved here for segment s of arc i and a vertex w not
    // one of its ends: w outside the hull of the segment's Bézier points
    // (which holds the loop), else piece by piece: w farther from each
    // piece's chord than the piece's flatness margin, or outside the
    // piece's own hull (so the loop of pieces has the winding of the polygon
    // of their chords), farther than the slack from the input chord, and
    // the winding of that polygon 0. False: not proved (the caller raises
    // the segment's tension; at tension 1 nothing is swept).
    bool outside_swept(std::uint32_t i, std::size_t s, const p2& w) {
        arc_work& a = arcs[i];
        if (a.linear(s)) return true;
        const p2 p0 = a.pts[s], p3 = a.pts[a.next(s)];
        if (w == p0 || w == p3) return true;
        if (a.dropped(s)) return outside_fitted(i, s, w);
        if (!boxes_meet(a.hull_box[s], box<2>::of(w), slack)) return true;
        if (outside_hull(a.hull[s], w, slack)) return true;
        if (!(point_segment_distance(w, p0, p3) > slack)) return false;
        if (!pieces_clear_of(i, s, w)) return false;
        const std::size_t k0 = a.first_piece[s], k1 = a.first_piece[s + 1];
        return winding_around(std::span<const p2>(a.line.points.data() + k0, k1 - k0 + 1), w) == 0;
    }

    // Each polyline piece of segment s of arc i clear of w: w farther from
    // its chord than its flatness margin, or outside its Bézier hull (then
    // the loop of curve pieces winds around w as the polygon of their chords
    // does).
    bool pieces_clear_of(std::uint32_t i, std::size_t s, const p2& w) {
        ensure_line(i);
        const arc_work& a = arcs[i];
        for (std::size_t k = a.first_piece[s]; k < a.first_piece[s + 1]; ++k) {
            const piece pc = piece_of(a, i, k, slack);
            if (point_segment_distance(w, pc.q[0], pc.q[3]) > pc.e + slack) continue;
            if (!outside_hull(pc.q, w, slack)) return false;
        }
        return true;
    }

    // outside_swept for a fitted segment that leaves input vertices out: its
    // loop is the curve, then the input polyline it covers back (the
    // vertices left out are not on the output, the kept ones are). The same
    // proof with that polyline in place of the chord: w farther than the
    // slack from each of its segments, and the polygon of the curve pieces'
    // chords and the input vertices back winds around w zero times.
    bool outside_fitted(std::uint32_t i, std::size_t s, const p2& w) {
        arc_work& a = arcs[i];
        const auto [first, last] = a.span(s);
        box<2> bx = a.hull_box[s];
        for (std::size_t k = first; k <= last; ++k) bx.expand(a.full_at(k));
        if (!boxes_meet(bx, box<2>::of(w), slack)) return true;
        for (std::size_t k = first; k < last; ++k)
            if (!(point_segment_distance(w, a.full_at(k), a.full_at(k + 1)) > slack)) return false;
        if (!pieces_clear_of(i, s, w)) return false;
        const std::size_t k0 = a.first_piece[s], k1 = a.first_piece[s + 1];
        std::vector<p2>& poly = loop_scratch;
        poly.assign(a.line.points.begin() + std::ptrdiff_t(k0), a.line.points.begin() + std::ptrdiff_t(k1) + 1);
        for (std::size_t k = last - 1; k > first; --k) poly.push_back(a.full_at(k));
        return winding_around(std::span<const p2>(poly), w) == 0;
    }

    // The ends of segment t of arc j against the region segment s of arc i
    // sweeps (and the other way round); a vertex inside raises the
    // segment's tension, as an unproved pair does.
    void prove_sides(std::uint32_t i, std::size_t s, std::uint32_t j, std::size_t t) {
        const auto& ha = arcs[i].hull[s];
        const auto& hb = arcs[j].hull[t];
        if (!arcs[i].linear(s) && !(outside_swept(i, s, hb[0]) && outside_swept(i, s, hb[3]))) {
            arcs[i].raise[s] = 1;
            ++swept;
        }
        if (!arcs[j].linear(t) && !(outside_swept(j, t, ha[0]) && outside_swept(j, t, ha[3]))) {
            arcs[j].raise[t] = 1;
            ++swept;
        }
    }


    std::size_t swept = 0;     // (segment, vertex) pairs found in a swept region, every round
    std::size_t restored = 0;  // input vertices a fitted arc got back, every round
    std::vector<p2> loop_scratch;
};

}  // namespace detail

}  // namespace crspline::geo
