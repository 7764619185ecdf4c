// crspline: the analysis report, one schema for every front end.
//
// What `crspline analyze` prints, what Python's CatmullRom.analyze() returns
// and what the WebAssembly module's Spline.analyze() returns are the same
// tree: the same keys (snake_case), the same values. The tree is written
// here, once; a front end only says how to make its own values (a JSON
// node, a Python object, a JavaScript value) through a report_builder:
//
//     struct my_builder {
//         using value = ...;                 // the front end's value type
//         value object();                    // {}
//         value array();                     // []
//         void set(value& object, std::string_view key, value v);
//         void push(value& array, value v);
//         value number(double);              // finite or not: the report's doubles
//         value integer(std::size_t);        // indices and counts
//         value boolean(bool);
//         value string(std::string_view);
//         value null();
//     };
//
// The schema, field by field, with an example: docs/report.md. Parameters:
// u is local to its segment in [0, 1], t the curve's global parameter
// (t = t_i + u (t_(i+1) - t_i), exactly t_(i+1) at u = 1). Points are written
// with `dimension` coordinates: a curve stored wider than its input (the
// zero-padded wide curve of dispatch.hpp) reports only the input's own.
#pragma once

#include <algorithm>
#include <array>
#include <concepts>
#include <cstddef>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "analysis.hpp"
#include "catmull_rom.hpp"
#include "certify.hpp"
#include "decision.hpp"
#include "intersections.hpp"
#include "vec.hpp"

namespace crspline {

/// How a front end makes the values of a report (see the top of this file).
template <class B>
concept report_builder = requires(B& b, typename B::value& v, std::string_view s, double x, std::size_t n,
                                  bool f) {
    { b.object() } -> std::same_as<typename B::value>;
    { b.array() } -> std::same_as<typename B::value>;
    b.set(v, s, b.null());
    b.push(v, b.null());
    { b.number(x) } -> std::same_as<typename B::value>;
    { b.integer(n) } -> std::same_as<typename B::value>;
    { b.boolean(f) } -> std::same_as<typename B::value>;
    { b.string(s) } -> std::same_as<typename B::value>;
    { b.null() } -> std::same_as<typename B::value>;
};

/// What a whole-curve report runs.
struct report_options {
    bool search = true;        ///< find_intersections (the report's intersections, folds, complete)
    double tolerance = 0;      ///< for that search (0: default_intersection_tolerance of the curve's size)
    bool certify = true;       ///< certify_intersection_free (the report's certificate)
    double safe_angle = safe_adjacent_angle;  ///< the certificate's rule 2 threshold (radians)
    bool decide_crossings = true;  ///< the proved decision's verdict (decision.hpp; plane curves, else null)
};

/// Everything `analyze` reports about a curve: the per-segment analysis, the
/// whole-curve search and the Section 5 certificate, with the knots and the
/// number of coordinates to write.
template <std::size_t D, class T = double>
struct analysis_report {
    std::size_t dimension = D;  ///< coordinates written per point (<= D)
    std::vector<T> grid;        ///< the curve's knots
    std::vector<segment_analysis<D, T>> segments;
    std::optional<intersection_result<D, T>> search;  ///< nullopt when not asked for
    std::optional<crspline::certificate<D, T>> certificate;  ///< nullopt when not asked for
    std::optional<crspline::verdict> verdict;  ///< decide()'s verdict; nullopt when not asked for or not a plane curve
};

/// The report's "verdict": decision.hpp's proved answer to "does the curve
/// cross itself?" for a plane curve (a float curve is decided as built: its
/// Bézier points convert to double exactly), nullopt for other dimensions
/// or when not asked for. The paper's certificate first; the decision stops
/// at the first proved crossing (the same verdict as the whole decision,
/// whose lists the report does not carry: crspline.decide and the demo give
/// them).
template <std::size_t D, class T>
std::optional<verdict> verdict_for_report(const catmull_rom<D, T>& c, const report_options& opt) {
    if constexpr (D == 2) {
        if (!opt.decide_crossings) return std::nullopt;
        decision_options o;
        o.record_pairs = false;
        o.first_crossing = true;
        if constexpr (std::is_same_v<T, double>) {
            return decide(c, o).result;
        } else {
            std::vector<std::array<vec<2>, 4>> b;
            for (const auto& s : c.bezier()) {
                std::array<vec<2>, 4> x{};
                for (std::size_t k = 0; k < 4; ++k) x[k] = {{double(s[k][0]), double(s[k][1])}};
                b.push_back(x);
            }
            return decide(bezier_path{b, c.closed()}, o).result;
        }
    } else {
        (void)c, (void)opt;
        return std::nullopt;
    }
}

/// The report's certificate (nullopt when not asked for): it runs without a
/// search of its own (the report's search is the curve's); when it fails
/// and the search ran, its `intersects` is `searched_any`, whether that
/// search found a meeting.
template <std::size_t D, class T>
std::optional<certificate<D, T>> certify_for_report(const catmull_rom<D, T>& c, const report_options& opt,
                                                    std::optional<bool> searched_any) {
    if (!opt.certify) return std::nullopt;
    certify_options co;
    co.safe_angle = opt.safe_angle;
    co.search_on_failure = false;
    certificate<D, T> cert = certify_intersection_free(c, co);
    if (!cert.certified && searched_any) cert.intersects = *searched_any;
    return cert;
}

/// The report of a curve, held whole (write_report writes it as it is
/// computed instead).
template <std::size_t D, class T>
analysis_report<D, T> make_report(const catmull_rom<D, T>& c, const report_options& opt = {},
                                  std::size_t dimension = D) {
    analysis_report<D, T> r;
    r.dimension = std::min(dimension, D);
    r.verdict = verdict_for_report(c, opt);
    r.grid.assign(c.grid().begin(), c.grid().end());
    r.segments = analyze(c);
    if (opt.search) r.search = find_intersections(c, T(opt.tolerance));
    r.certificate = certify_for_report(c, opt, r.search ? std::optional<bool>(r.search->any()) : std::nullopt);
    return r;
}

namespace detail {

// The report's values, made by a builder B. Every key of the schema is
// written in this namespace and nowhere else.
template <report_builder B>
struct report_writer {
    using value = typename B::value;
    B& b;
    std::size_t dimension;

    template <class T>
    value num(T x) { return b.number(double(x)); }
    template <class T, std::size_t N>
    value nums(const std::array<T, N>& a) {
        value v = b.array();
        for (const T& x : a) b.push(v, num(x));
        return v;
    }
    template <class T>
    value nums(std::span<const T> a) {
        value v = b.array();
        for (const T& x : a) b.push(v, num(x));
        return v;
    }
    value index(std::size_t i) { return b.integer(i); }
    value indices(std::span<const std::size_t> a) {
        value v = b.array();
        for (std::size_t i : a) b.push(v, index(i));
        return v;
    }
    value index_pair(const std::array<std::size_t, 2>& a) { return indices(std::span<const std::size_t>(a)); }
    template <std::size_t D, class T>
    value point(const vec<D, T>& p) {
        value v = b.array();
        for (std::size_t k = 0; k < std::min(dimension, D); ++k) b.push(v, num(p[k]));
        return v;
    }
    template <class T>
    static T global(T u, T t0, T t1) { return u == T(1) ? t1 : t0 + u * (t1 - t0); }

    template <class T>
    value projection(const chord_projection<T>& p) {
        value q = b.object();
        b.set(q, "bezier", nums(p.bezier));
        b.set(q, "theorem2", b.boolean(p.theorem2));
        b.set(q, "derivative_min", num(p.derivative_min));
        b.set(q, "derivative_min_u", num(p.derivative_min_u));
        b.set(q, "range", nums(p.range));
        return q;
    }

    template <class T>
    value bounds(const paper_bounds<T>& p) {
        value q = b.object();
        b.set(q, "d1", num(p.d1));
        b.set(q, "d2", num(p.d2));
        b.set(q, "d3", num(p.d3));
        b.set(q, "theta1", num(p.theta1));
        b.set(q, "theta2", num(p.theta2));
        b.set(q, "h1", num(p.h1));
        b.set(q, "h2", num(p.h2));
        b.set(q, "eq6_one_sided", num(p.eq6_one_sided));
        b.set(q, "eq6", num(p.eq6));
        b.set(q, "eq8_start", num(p.eq8_start));
        b.set(q, "eq8_end", num(p.eq8_end));
        return q;
    }

    // One segment on the knot interval [t0, t1].
    template <std::size_t D, class T>
    value segment(const segment_analysis<D, T>& a, T t0, T t1) {
        value s = b.object();
        b.set(s, "index", index(a.index));
        b.set(s, "rank", index(a.rank));
        value bez = b.array();
        for (const auto& p : a.bezier) b.push(bez, point(p));
        b.set(s, "bezier", std::move(bez));
        b.set(s, "zero_speed_u", nums(std::span<const T>(a.zero_speed_u)));
        b.set(s, "cusp_u", nums(std::span<const T>(a.cusp_u)));
        value ct = b.array();
        for (const T u : a.cusp_u) b.push(ct, num(global(u, t0, t1)));
        b.set(s, "cusp_t", std::move(ct));
        value lu = b.array(), lt = b.array();
        for (const auto& uv : a.self_intersection) {
            b.push(lu, nums(uv));
            b.push(lt, nums(std::array<T, 2>{global(uv[0], t0, t1), global(uv[1], t0, t1)}));
        }
        b.set(s, "self_intersection_u", std::move(lu));
        b.set(s, "self_intersection_t", std::move(lt));
        b.set(s, "fold", b.boolean(a.fold));
        b.set(s, "has_cusp", b.boolean(a.has_cusp()));
        b.set(s, "has_self_intersection", b.boolean(a.has_self_intersection()));
        b.set(s, "projection", a.projection ? projection(*a.projection) : b.null());
        b.set(s, "bezier_height", nums(a.bezier_height));
        b.set(s, "bezier_bound", num(a.bezier_bound));
        b.set(s, "max_chord_line_distance", num(a.max_chord_line_distance));
        b.set(s, "max_chord_line_distance_u", num(a.max_chord_line_distance_u));
        b.set(s, "max_chord_distance", num(a.max_chord_distance));
        b.set(s, "max_chord_distance_u", num(a.max_chord_distance_u));
        b.set(s, "overshoot", nums(a.overshoot));
        b.set(s, "distance_bound", a.bounds ? num(a.bounds->eq6) : b.null());
        b.set(s, "bounds", a.bounds ? bounds(*a.bounds) : b.null());
        return s;
    }

    template <std::size_t D, class T>
    value intersection(const curve_intersection<D, T>& x, std::span<const T> grid) {
        value m = b.object();
        b.set(m, "segments", index_pair(x.segments));
        b.set(m, "u", nums(x.u));
        std::array<T, 2> t{};
        for (std::size_t j = 0; j < 2; ++j) t[j] = global(x.u[j], grid[x.segments[j]], grid[x.segments[j] + 1]);
        b.set(m, "t", nums(t));
        b.set(m, "point", point(x.point));
        // 0 to rounding for a crossing; up to the search's tolerance for
        // a near miss (in 3-D, closest approaches are what is reported).
        b.set(m, "distance", num(x.distance));
        return m;
    }

    // A collinear overlap: one interval per pair of segments, [u0, u1] on
    // the first and the matching [v0, v1] on the second (local).
    template <std::size_t D, class T>
    value overlap(const curve_overlap<D, T>& x) {
        value m = b.object();
        b.set(m, "segments", index_pair(x.segments));
        b.set(m, "u", nums(x.u));
        b.set(m, "v", nums(x.v));
        return m;
    }

    // The search's fields, into an object o (the report's top level, or a
    // search object of its own).
    template <std::size_t D, class T>
    void search_fields(value& o, const intersection_result<D, T>& r, std::span<const T> grid) {
        value list = b.array();
        for (const auto& x : r.intersections) b.push(list, intersection(x, grid));
        b.set(o, "intersections", std::move(list));
        value overlaps = b.array();
        for (const auto& x : r.overlaps) b.push(overlaps, overlap(x));
        b.set(o, "overlaps", std::move(overlaps));
        b.set(o, "folds", indices(std::span<const std::size_t>(r.folds)));
        // false: some pair of segments ran out of the search's work budget
        // (the list may then miss meetings).
        b.set(o, "complete", b.boolean(r.complete));
    }

    template <std::size_t D, class T>
    value search(const intersection_result<D, T>& r, std::span<const T> grid) {
        value o = b.object();
        search_fields(o, r, grid);
        b.set(o, "any", b.boolean(r.any()));
        return o;
    }

    template <std::size_t D, class T>
    value certificate(const crspline::certificate<D, T>& c, std::span<const T> grid, bool with_search) {
        value o = b.object();
        b.set(o, "certified", b.boolean(c.certified));
        b.set(o, "failed_rule", c.certified ? b.null() : b.string(to_string(c.failed_rule)));
        b.set(o, "detail", b.string(c.detail));
        b.set(o, "vertex", c.vertex ? index(*c.vertex) : b.null());
        b.set(o, "segment", c.segment ? index(*c.segment) : b.null());
        b.set(o, "segments", c.segments ? index_pair(*c.segments) : b.null());
        b.set(o, "angle", c.failed_rule == certify_rule::adjacent_angle ? num(c.angle) : b.null());
        b.set(o, "intersects", c.intersects ? b.boolean(*c.intersects) : b.null());
        b.set(o, "search", with_search && c.intersects ? search(c.search, grid) : b.null());
        return o;
    }
};

}  // namespace detail

/// One segment's analysis on the knot interval [t0, t1] (cusp_t and
/// self_intersection_t are in those units).
template <report_builder B, std::size_t D, class T>
typename B::value report_segment(B& b, const segment_analysis<D, T>& a, T t0, T t1, std::size_t dimension = D) {
    return detail::report_writer<B>{b, dimension}.segment(a, t0, t1);
}

/// The whole-curve search, as its own object: {intersections, folds,
/// complete, any}.
template <report_builder B, std::size_t D, class T>
typename B::value report_search(B& b, const intersection_result<D, T>& r, std::span<const T> grid,
                                std::size_t dimension = D) {
    return detail::report_writer<B>{b, dimension}.search(r, grid);
}

/// The certificate, with its own search (null when it did not search).
template <report_builder B, std::size_t D, class T>
typename B::value report_certificate(B& b, const certificate<D, T>& c, std::span<const T> grid,
                                     std::size_t dimension = D) {
    return detail::report_writer<B>{b, dimension}.certificate(c, grid, true);
}

/// Where a report goes as it is written (write_report, and report() through
/// a sink that builds the tree): the members of the top-level object, in
/// the schema's order, each whole or, for a list that grows with the curve,
/// item by item:
///
///     sink.member(key, value);   // a member, whole
///     sink.open(key);            // a list member: its items follow
///     sink.item(value);          // the next item of the open list
///     sink.close();              // the end of the open list
///     sink.hold(which, value);   // an item of a list written later
///                                // (which: 0 intersections, 1 overlaps)
///     sink.release(which);       // the items held, into the open list
///
/// The search finds its meetings before `has_self_intersection`, which
/// comes first in the schema, is known: they are held until then (a sink
/// that writes text keeps them on disk, not in memory).
template <class S, class B>
concept report_sink = report_builder<B> && requires(S& s, std::string_view key, typename B::value v, int which) {
    s.member(key, std::move(v));
    s.open(key);
    s.item(std::move(v));
    s.close();
    s.hold(which, std::move(v));
    s.release(which);
};

namespace detail {

// A sink that builds the report's tree with the builder (report()).
template <report_builder B>
struct tree_sink {
    using value = typename B::value;
    B& b;
    value o = b.object();
    std::string_view key{};
    value list = b.array();
    std::vector<value> held[2];
    void member(std::string_view k, value v) { b.set(o, k, std::move(v)); }
    void open(std::string_view k) { key = k, list = b.array(); }
    void item(value v) { b.push(list, std::move(v)); }
    void close() { b.set(o, key, std::move(list)); }
    void hold(int which, value v) { held[which].push_back(std::move(v)); }
    void release(int which) {
        for (value& v : held[which]) b.push(list, std::move(v));
        held[which].clear();
    }
};

// The report's members, in the schema's order, into the sink. Where the
// parts come from is the caller's: each_segment(f) calls f with every
// segment's analysis in order; search(visitor) runs the search through
// the visitor (as visit_intersections does) and returns its `complete`,
// or nullopt when the search is not run; certify(any) returns the
// certificate (nullopt: none), `any` saying whether the search found a
// meeting (nullopt when it did not run).
template <report_builder B, class Sink, std::size_t D, class T, class Segments, class Search, class Certify>
void write_members(B& b, Sink& sink, std::optional<crspline::verdict> verdict, std::size_t dimension,
                   std::span<const T> grid, Segments&& each_segment, Search&& search, Certify&& certify) {
    report_writer<B> w{b, dimension};
    sink.member("verdict", verdict ? b.string(to_string(*verdict)) : b.null());
    sink.member("dimension", b.integer(dimension));
    std::vector<T> cusp_t;
    bool loop = false;
    sink.open("segments");
    each_segment([&](const segment_analysis<D, T>& a) {
        const T t0 = grid[a.index], t1 = grid[a.index + 1];
        sink.item(w.segment(a, t0, t1));
        for (const T u : a.cusp_u) cusp_t.push_back(w.global(u, t0, t1));
        loop = loop || a.has_self_intersection();
    });
    sink.close();
    sink.member("cusp_t", w.nums(std::span<const T>(cusp_t)));
    sink.member("has_cusp", b.boolean(!cusp_t.empty()));
    // The search, its meetings held until has_self_intersection is written.
    struct holder {
        report_writer<B>& w;
        Sink& sink;
        std::span<const T> grid;
        std::vector<std::size_t> folds{};
        bool any = false;
        void operator()(const curve_intersection<D, T>& x) { sink.hold(0, w.intersection(x, grid)), any = true; }
        void operator()(const curve_overlap<D, T>& x) { sink.hold(1, w.overlap(x)), any = true; }
        void fold(std::size_t i) { folds.push_back(i), any = true; }
    } found{w, sink, grid};
    const std::optional<bool> complete = search(found);
    // A loop or fold inside a segment is known without the search; anything
    // else needs it: unknown (null) when it did not run, like the search's
    // own fields below.
    sink.member("has_self_intersection",
                loop ? b.boolean(true) : complete ? b.boolean(found.any) : b.null());
    if (complete) {
        sink.open("intersections");
        sink.release(0);
        sink.close();
        sink.open("overlaps");
        sink.release(1);
        sink.close();
        sink.member("folds", w.indices(std::span<const std::size_t>(found.folds)));
        // false: some pair of segments ran out of the search's work budget
        // (the list may then miss meetings).
        sink.member("complete", b.boolean(*complete));
    } else {
        for (const char* key : {"intersections", "overlaps", "folds", "complete"}) sink.member(key, b.null());
    }
    const auto cert = certify(complete ? std::optional<bool>(found.any) : std::nullopt);
    sink.member("certificate", cert ? w.certificate(*cert, grid, false) : b.null());
}

}  // namespace detail

/// The whole report: {verdict, dimension, segments, cusp_t, has_cusp,
/// has_self_intersection, intersections, overlaps, folds, complete,
/// certificate}.
template <report_builder B, std::size_t D, class T>
typename B::value report(B& b, const analysis_report<D, T>& r) {
    detail::tree_sink<B> sink{b};
    detail::write_members<B, detail::tree_sink<B>, D, T>(
        b, sink, r.verdict, r.dimension, std::span<const T>(r.grid),
        [&](auto&& f) {
            for (const auto& a : r.segments) f(a);
        },
        [&](auto& visit) -> std::optional<bool> {
            if (!r.search) return std::nullopt;
            for (const auto& x : r.search->intersections) visit(x);
            for (const auto& x : r.search->overlaps) visit(x);
            for (const std::size_t i : r.search->folds) visit.fold(i);
            return r.search->complete;
        },
        [&](std::optional<bool>) { return r.certificate; });
    return std::move(sink.o);
}

/// The report of a curve written as it is computed, for a curve too large
/// to hold its whole analysis (crspline analyze at 10^6 points): each
/// segment's record goes to the sink as it is analysed and each meeting as
/// the search finds it; what is held is what the whole-curve parts need
/// (the search's boxes and candidate pairs, the certificate's state, the
/// cusps' t). The same members and values as report(b, make_report(c, opt,
/// dimension)).
template <report_builder B, class Sink, std::size_t D, class T>
    requires report_sink<Sink, B>
void write_report(B& b, Sink& sink, const catmull_rom<D, T>& c, const report_options& opt = {},
                  std::size_t dimension = D) {
    const std::vector<T> grid(c.grid().begin(), c.grid().end());
    detail::write_members<B, Sink, D, T>(
        b, sink, verdict_for_report(c, opt), std::min(dimension, D), std::span<const T>(grid),
        [&](auto&& f) {
            for (std::size_t i = 0; i < c.segment_count(); ++i) f(analyze(c, i));
        },
        [&](auto& visit) -> std::optional<bool> {
            if (!opt.search) return std::nullopt;
            return visit_intersections(c, T(opt.tolerance), visit);
        },
        [&](std::optional<bool> any) { return certify_for_report(c, opt, any); });
}

/// The report's counts instead of its lists, for a curve of any size:
/// {verdict, dimension, segment_count, cusps, loops, intersections,
/// overlaps, folds, complete, certificate}, the search's counts null when
/// it is not run. Nothing but counts is kept.
template <report_builder B, std::size_t D, class T>
typename B::value report_summary(B& b, const catmull_rom<D, T>& c, const report_options& opt = {},
                                 std::size_t dimension = D) {
    const std::optional<crspline::verdict> verdict = verdict_for_report(c, opt);
    std::size_t cusps = 0, loops = 0;
    for (std::size_t i = 0; i < c.segment_count(); ++i) {
        const auto a = analyze(c, i);
        cusps += a.cusp_u.size(), loops += a.self_intersection.size();
    }
    struct counter {
        std::size_t intersections = 0, overlaps = 0, folds = 0;
        void operator()(const curve_intersection<D, T>&) { ++intersections; }
        void operator()(const curve_overlap<D, T>&) { ++overlaps; }
        void fold(std::size_t) { ++folds; }
    } count;
    const bool searched = opt.search;
    const bool complete = searched && visit_intersections(c, T(opt.tolerance), count);
    const auto counted = [&](std::size_t k) { return searched ? b.integer(k) : b.null(); };
    const std::vector<T> grid(c.grid().begin(), c.grid().end());
    const auto cert = certify_for_report(
        c, opt, searched ? std::optional<bool>(count.intersections + count.overlaps + count.folds > 0) : std::nullopt);
    detail::report_writer<B> w{b, std::min(dimension, D)};
    typename B::value o = b.object();
    b.set(o, "verdict", verdict ? b.string(to_string(*verdict)) : b.null());
    b.set(o, "dimension", b.integer(std::min(dimension, D)));
    b.set(o, "segment_count", b.integer(c.segment_count()));
    b.set(o, "cusps", b.integer(cusps));
    b.set(o, "loops", b.integer(loops));
    b.set(o, "intersections", counted(count.intersections));
    b.set(o, "overlaps", counted(count.overlaps));
    b.set(o, "folds", counted(count.folds));
    b.set(o, "complete", searched ? b.boolean(complete) : b.null());
    b.set(o, "certificate", cert ? w.certificate(*cert, std::span<const T>(grid), false) : b.null());
    return o;
}

}  // namespace crspline
