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
#include <utility>
#include <vector>

#include "analysis.hpp"
#include "catmull_rom.hpp"
#include "certify.hpp"
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
};

/// The report of a curve. The certificate runs without its own search (the
/// report's search is the curve's); when it fails and the search ran, its
/// `intersects` says whether that search found a meeting.
template <std::size_t D, class T>
analysis_report<D, T> make_report(const catmull_rom<D, T>& c, const report_options& opt = {},
                                  std::size_t dimension = D) {
    analysis_report<D, T> r;
    r.dimension = std::min(dimension, D);
    r.grid.assign(c.grid().begin(), c.grid().end());
    r.segments = analyze(c);
    if (opt.search) r.search = find_intersections(c, T(opt.tolerance));
    if (opt.certify) {
        certify_options co;
        co.safe_angle = opt.safe_angle;
        co.search_on_failure = false;
        r.certificate = certify_intersection_free(c, co);
        if (!r.certificate->certified && r.search) r.certificate->intersects = r.search->any();
    }
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

    // The search's fields, into an object o (the report's top level, or a
    // search object of its own).
    template <std::size_t D, class T>
    void search_fields(value& o, const intersection_result<D, T>& r, std::span<const T> grid) {
        value list = b.array();
        for (const auto& x : r.intersections) {
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
            b.push(list, std::move(m));
        }
        b.set(o, "intersections", std::move(list));
        // A collinear overlap: one interval per pair of segments, [u0, u1]
        // on the first and the matching [v0, v1] on the second (local).
        value overlaps = b.array();
        for (const auto& x : r.overlaps) {
            value m = b.object();
            b.set(m, "segments", index_pair(x.segments));
            b.set(m, "u", nums(x.u));
            b.set(m, "v", nums(x.v));
            b.push(overlaps, std::move(m));
        }
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

/// The whole report: {dimension, segments, cusp_t, has_cusp,
/// has_self_intersection, intersections, folds, complete, certificate}.
template <report_builder B, std::size_t D, class T>
typename B::value report(B& b, const analysis_report<D, T>& r) {
    detail::report_writer<B> w{b, r.dimension};
    const std::span<const T> grid(r.grid);
    typename B::value o = b.object();
    b.set(o, "dimension", b.integer(r.dimension));
    typename B::value segs = b.array(), cusps = b.array();
    bool cusp = false, loop = false;
    for (const auto& a : r.segments) {
        b.push(segs, w.segment(a, grid[a.index], grid[a.index + 1]));
        for (const T u : a.cusp_u) b.push(cusps, w.num(w.global(u, grid[a.index], grid[a.index + 1])));
        cusp = cusp || a.has_cusp();
        loop = loop || a.has_self_intersection();
    }
    b.set(o, "segments", std::move(segs));
    b.set(o, "cusp_t", std::move(cusps));
    b.set(o, "has_cusp", b.boolean(cusp));
    b.set(o, "has_self_intersection", b.boolean(loop || (r.search && r.search->any())));
    if (r.search) {
        w.search_fields(o, *r.search, grid);
    } else {
        b.set(o, "intersections", b.null());
        b.set(o, "overlaps", b.null());
        b.set(o, "folds", b.null());
        b.set(o, "complete", b.null());
    }
    b.set(o, "certificate", r.certificate ? w.certificate(*r.certificate, grid, false) : b.null());
    return o;
}

}  // namespace crspline
