// crspline: the decision's engine: the pieces cut from every segment, the
// pairs whose boxes meet (a box tree), each pair decided by the arguments
// (arguments.hpp), Krawczyk's test (krawczyk.hpp) or halving down to the
// floor, the contacts, and the arguments of each pair of segments merged
// into the decision (decision.hpp's decide() calls it).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "../catmull_rom.hpp"
#include "../certify.hpp"
#include "../detail/box_tree.hpp"
#include "../error.hpp"
#include "krawczyk.hpp"
#include "report.hpp"

namespace crspline {
namespace detail {

struct decision_engine : decision_krawczyk {

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
}  // namespace crspline
