// crspline for JavaScript: Embind bindings of the public headers.
//
// One class, Spline, holds a curve of dimension 1 to 16 (chosen at run time:
// 1 to 4 as themselves, 5 to 16 as the zero-padded curve of 16, whose first
// coordinates are bit for bit those of the curve's own dimension, see
// crspline/dispatch.hpp; only those coordinates cross back to JavaScript);
// every array crosses the boundary as a flat Float64Array copy (safe across
// memory growth). Names are camelCase here only. A C++ exception never
// escapes as a number: each entry point catches it and throws a JavaScript
// Error carrying the library's message.
//
// Kept inside the subset of libc++ 13 that Emscripten 3.1.6 ships: no
// std::ranges, std::format, constexpr std::vector or std::bit_cast.
//
// What the entry points share (errors, arrays, options, the report builder)
// is in js_values.hpp; one segment's analysis and version() in
// bind_segment.cpp.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <crspline/arc_length.hpp>
#include <crspline/bounds.hpp>
#include <crspline/catmull_rom.hpp>
#include <crspline/dispatch.hpp>
#include <crspline/spec.hpp>
#include <crspline/nearest.hpp>
#include <crspline/tessellate.hpp>
#include <crspline/version.hpp>
#include <crspline/analysis.hpp>
#include <crspline/certify.hpp>
#include <crspline/decision.hpp>
#include <crspline/intersections.hpp>
#include <crspline/report.hpp>
#include <crspline/resolution.hpp>

#include <cmath>
#include <limits>
#include <cstddef>
#include <exception>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "js_values.hpp"

namespace {

using namespace crspline_js;

class Spline {
    using any_curve = std::variant<curve_of<1>, curve_of<2>, curve_of<3>, curve_of<4>, curve_of<cr::wide_dimension>>;
    any_curve c_;

    static any_curve build(const val& points, int dimension, const val& opt) {
        return guarded([&]() -> any_curve {
            const cr::curve_spec s = spec_from(numbers(points, "points"), dimension, opt);
            return cr::with_dimension(
                s.dimension,
                [&](auto d) -> any_curve { return make_curve<decltype(d)::value>(s, opt); },
                [&](std::size_t) { cr::validate(s); });  // throws the core's "dimension must be 1 to 16"
        });
    }

    template <class F>
    decltype(auto) visit(F&& f) const { return std::visit(std::forward<F>(f), c_); }
    template <class F>
    decltype(auto) visit(F&& f) { return std::visit(std::forward<F>(f), c_); }

    // Segments [first, first + n) clipped to [0, nseg); first and n integers.
    static std::pair<std::size_t, std::size_t> range(double first, double n, std::size_t nseg) {
        if (!(first >= 0 && n >= 0 && first == std::floor(first) && n == std::floor(n)))
            throw cr::invalid_input("segment range must be two non-negative integers, got " + cr::detail::num(first) +
                                    ", " + cr::detail::num(n));
        const std::size_t i0 = std::size_t(std::min(first, double(nseg)));
        return {i0, std::size_t(std::min(double(nseg), double(i0) + n))};
    }

    static std::size_t count(double n, double minimum = 2) {
        if (!(n >= minimum && n <= 1e8 && n == std::floor(n)))
            throw cr::invalid_input("count must be an integer in [" + cr::detail::num(minimum) + ", 1e8], got " +
                                    cr::detail::num(n));
        return std::size_t(n);
    }

public:
    Spline(val points, int dimension, val opt) : c_(build(points, dimension, opt)) {}
    Spline(val points, int dimension) : Spline(std::move(points), dimension, val::undefined()) {}

    // --- what the curve is made of ------------------------------------------
    int dimension() const { return visit([](const auto& c) { return int(c.dim); }); }
    double pointCount() const { return visit([](const auto& c) { return double(c.curve.points().size()); }); }
    double segmentCount() const { return visit([](const auto& c) { return double(c.curve.segment_count()); }); }
    bool closed() const { return visit([](const auto& c) { return c.curve.closed(); }); }
    double tMin() const { return visit([](const auto& c) { return c.curve.t_min(); }); }
    double tMax() const { return visit([](const auto& c) { return c.curve.t_max(); }); }
    val points() const {
        return visit([](const auto& c) {
            return points_array(c.curve.points(), c.dim);
        });
    }
    val grid() const {
        return visit([](const auto& c) { return float64_array(c.curve.grid().data(), c.curve.grid().size()); });
    }
    double locate(double t) const { return visit([&](const auto& c) { return double(c.curve.locate(t)); }); }

    // --- evaluation -----------------------------------------------------------
    val evaluate(double t, int order) const {
        return guarded([&] {
            return visit([&](const auto& c) { return point_array(c.curve.evaluate(t, order), c.dim); });
        });
    }
    val evaluate0(double t) const { return evaluate(t, 0); }
    val evaluateMany(val t, int order) const {
        return guarded([&] {
            const std::vector<double> ts = numbers(t, "t");
            return visit([&](const auto& c) { return points_array(c.curve.evaluate(std::span<const double>(ts), order), c.dim); });
        });
    }
    val evaluateMany0(val t) const { return evaluateMany(std::move(t), 0); }

    // --- Bézier form ----------------------------------------------------------
    val bezier(double i) const {
        return guarded([&] {
            return visit([&](const auto& c) {
                if (!(i >= 0 && i < double(c.curve.segment_count()) && i == std::floor(i)))
                    throw cr::invalid_input("segment index " + cr::detail::num(i) + " is outside [0, " +
                                            std::to_string(c.curve.segment_count()) + ")");
                const auto b = c.curve.bezier(std::size_t(i));
                return points_array(std::vector<std::decay_t<decltype(b[0])>>(b.begin(), b.end()), c.dim);
            });
        });
    }
    // Every segment's B0..B3, segment after segment: 4 D numbers per
    // segment. The editor draws a frame from this one call.
    val bezierAll() const {
        return visit([](const auto& c) {
            const std::size_t D = c.dim;
            const std::size_t n = c.curve.segment_count();
            std::vector<double> out(n * 4 * D);
            for (std::size_t i = 0; i < n; ++i) {
                const auto b = c.curve.bezier(i);
                for (std::size_t k = 0; k < 4; ++k)
                    for (std::size_t d = 0; d < D; ++d) out[(i * 4 + k) * D + d] = b[k][d];
            }
            return float64_array(out);
        });
    }

    // --- sampling -------------------------------------------------------------
    val sampleT(double n) const {
        return guarded([&] { return visit([&](const auto& c) { return points_array(cr::sample_t(c.curve, count(n)), c.dim); }); });
    }
    val tessellate(double tolerance) const {
        return guarded([&] {
            return visit([&](const auto& c) {
                if (tolerance > 0) cr::check_distance_tolerance(c.curve, tolerance);  // below it, subdivision never ends
                const auto p = tolerance > 0 ? cr::tessellate(c.curve, tolerance) : cr::tessellate(c.curve);
                val r = val::object();
                r.set("points", points_array(p.points, c.dim));
                r.set("t", float64_array(p.t));
                return r;
            });
        });
    }
    val boundingBox() const {
        return visit([](const auto& c) {
            const auto b = cr::bounding_box(c.curve);
            const std::size_t D = c.dim;
            val r = val::object();
            r.set("lo", float64_array(b.lo.data(), D));
            r.set("hi", float64_array(b.hi.data(), D));
            return r;
        });
    }
    val nearest(val q) const {
        return guarded([&] {
            return visit([&](const auto& c) {
                constexpr std::size_t D = std::decay_t<decltype(c.curve)>::dimension;
                const auto n = cr::nearest(c.curve, to_point<D>(q, "query point", c.dim));
                val r = val::object();
                r.set("t", n.t);
                r.set("distanceSq", n.distance_sq);
                r.set("segment", double(n.segment));
                r.set("point", point_array(n.point, c.dim));
                return r;
            });
        });
    }

    // --- arc length -----------------------------------------------------------
    double arcLength() { return guarded([&] { return visit([](auto& c) { return c.lengths().total(); }); }); }
    double arcLengthAccuracy(double accuracy) const {
        return guarded([&] {
            cr::check_relative_accuracy(accuracy);
            return visit([&](const auto& c) { return cr::arc_length(c.curve, accuracy); });
        });
    }
    double arcLengthBetween(double ta, double tb) const {
        return guarded([&] { return visit([&](const auto& c) { return cr::arc_length(c.curve, ta, tb); }); });
    }
    val knotLengths() {
        return visit([](auto& c) {
            const auto s = c.lengths().knot_lengths();
            return float64_array(s.data(), s.size());
        });
    }
    double sAt(double t) { return guarded([&] { return visit([&](auto& c) { return c.lengths().s_at(t); }); }); }
    double tAtArcLength(double s) { return guarded([&] { return visit([&](auto& c) { return c.lengths().t_at(s); }); }); }
    val sampleArcLength(double n, double accuracy) const {
        return guarded([&] {
            return visit([&](const auto& c) {
                cr::check_relative_accuracy(accuracy);
                const auto smp = cr::sample_arc_length(c.curve, count(n), accuracy > 0 ? accuracy : cr::default_accuracy);
                val r = val::object();
                r.set("t", float64_array(smp.t));
                r.set("s", float64_array(smp.s));
                r.set("points", points_array(smp.points, c.dim));
                return r;
            });
        });
    }
    val sampleArcLength0(double n) const { return sampleArcLength(n, 0); }
    // Points every `spacing` of arc length from the start (ticks): the
    // points flat, then their tangents flat (unit, 0 where undefined).
    val arcLengthTicks(double spacing, double max_ticks) {
        return guarded([&] {
            return visit([&](auto& c) {
                const std::size_t D = c.dim;
                if (!(spacing > 0)) throw cr::invalid_input("tick spacing must be positive, got " + cr::detail::num(spacing));
                const auto& table = c.lengths();
                const double total = table.total();
                const std::size_t n = std::size_t(std::min(std::floor(total / spacing), std::max(0.0, max_ticks - 1))) + 1;
                std::vector<double> s(n);
                for (std::size_t k = 0; k < n; ++k) s[k] = std::min(total, double(k) * spacing);
                std::vector<double> t = table.t_at(std::span<const double>(s));
                for (double& x : t) x = std::clamp(x, c.curve.t_min(), c.curve.t_max());
                const auto pos = c.curve.evaluate(std::span<const double>(t), 0);
                const auto vel = c.curve.evaluate(std::span<const double>(t), 1);
                std::vector<double> out(2 * n * D);
                for (std::size_t k = 0; k < n; ++k) {
                    const double speed = cr::norm(vel[k]);
                    for (std::size_t d = 0; d < D; ++d) {
                        out[k * D + d] = pos[k][d];
                        out[(n + k) * D + d] = speed > 0 ? vel[k][d] / speed : 0.0;
                    }
                }
                return float64_array(out);
            });
        });
    }

    // --- curvature ------------------------------------------------------------
    // Curvature at t (checked), or null where the speed is zero.
    // (frames.hpp's curvature(curve, t) cannot be used here: frames.hpp and
    // analysis.hpp both define detail::perpendicular for the same arguments.)
    val curvature(double t) const {
        return guarded([&] {
            return visit([&](const auto& c) {
                c.curve.evaluate(t);  // the domain check
                const auto& s = c.curve.segment(c.curve.locate(t));
                const auto k = cr::curvature(s, s.local(t));
                return k ? val(*k) : val::null();
            });
        });
    }
    // Curvature comb of a plane curve over segments first .. first + count
    // - 1: per segment per_segment + 1 samples (u = k / per_segment, both
    // ends included), five numbers each: x, y, the unit normal left of
    // travel nx, ny, and the signed curvature (0 where the speed is zero).
    val curvatureComb(double per_segment, double first, double n) const {
        return guarded([&] {
            const auto* c = std::get_if<curve_of<2>>(&c_);
            if (!c) throw cr::invalid_input("the curvature comb needs a plane curve (dimension 2)");
            const std::size_t m = count(per_segment, 1);
            const auto [i0, i1] = range(first, n, c->curve.segment_count());
            std::vector<double> out;
            out.reserve((i1 - i0) * (m + 1) * 5);
            for (std::size_t i = i0; i < i1; ++i) {
                const auto& s = c->curve.segment(i);
                for (std::size_t j = 0; j <= m; ++j) {
                    const double u = double(j) / double(m);
                    const auto d1 = s.du(u, 1), d2 = s.du(u, 2);
                    const double speed = cr::norm(d1);
                    const auto p = s.at(u);
                    double k = 0, nx = 0, ny = 0;
                    if (speed > 0) {
                        nx = -d1[1] / speed;
                        ny = d1[0] / speed;
                        k = (d1[0] * d2[1] - d1[1] * d2[0]) / (speed * speed * speed);
                    }
                    out.insert(out.end(), {p[0], p[1], nx, ny, k});
                }
            }
            return float64_array(out);
        });
    }
    val curvatureComb1(double per_segment) const { return curvatureComb(per_segment, 0, segmentCount()); }

    // --- analysis -------------------------------------------------------------
    // Cusps of segments first .. first + count - 1: (segment, u, t,
    // point...) per cusp, flat. The editor asks only for the segments an
    // edit changed and keeps the rest.
    val cuspsIn(double first, double n) const {
        return guarded([&] {
            return visit([&](const auto& c) {
                const std::size_t D = c.dim;
                const auto [i0, i1] = range(first, n, c.curve.segment_count());
                std::vector<double> out;
                for (std::size_t i = i0; i < i1; ++i) {
                    const auto& s = c.curve.segment(i);
                    for (double u : cr::analyze_segment(s).cusp_u) {
                        const auto p = s.at(u);
                        out.insert(out.end(), {double(i), u, s.t0 + u * s.h});
                        for (std::size_t d = 0; d < D; ++d) out.push_back(p[d]);
                    }
                }
                return float64_array(out);
            });
        });
    }
    val cusps() const { return cuspsIn(0, segmentCount()); }
    // Lengths of segments first .. first + count - 1 (default accuracy).
    val segmentLengths(double first, double n) const {
        return guarded([&] {
            return visit([&](const auto& c) {
                const auto [i0, i1] = range(first, n, c.curve.segment_count());
                std::vector<double> out;
                out.reserve(i1 - i0);
                for (std::size_t i = i0; i < i1; ++i) out.push_back(cr::arc_length(c.curve.segment(i)));
                return float64_array(out);
            });
        });
    }
    // The analysis report (docs/report.md): { verdict, dimension, segments,
    // cusp_t, has_cusp, has_self_intersection, intersections, folds,
    // complete, certificate }. o: { intersections: false } skips the search,
    // tolerance: its tolerance; { decision: false } skips the verdict (null).
    val analyze(val o) const {
        return guarded([&] {
            cr::report_options opt;
            if (!is_nullish(o)) {
                if (!is_nullish(o["intersections"])) opt.search = o["intersections"].as<bool>();
                if (!is_nullish(o["tolerance"])) opt.tolerance = o["tolerance"].as<double>();
                if (!is_nullish(o["decision"])) opt.decide_crossings = o["decision"].as<bool>();
            }
            const std::size_t dim = std::size_t(dimension());
            return visit([&](const auto& c) {
                js_builder b;
                return cr::report(b, cr::make_report(c.curve, opt, dim));
            });
        });
    }
    val analyze0() const { return analyze(val::undefined()); }
    // The report's search object: { intersections, folds, complete, any }.
    val intersections(double tolerance) const {
        return guarded([&] {
            const std::size_t dim = std::size_t(dimension());
            return visit([&](const auto& c) {
                js_builder b;
                return cr::report_search(b, cr::find_intersections(c.curve, tolerance), c.curve.grid(), dim);
            });
        });
    }
    val intersections0() const { return intersections(0); }
    // The report's certificate object. o: { safeAngle, searchOnFailure,
    // tolerance } (the options of certify_intersection_free).
    val certify(val o) const {
        return guarded([&] {
            cr::certify_options opt;
            if (!is_nullish(o)) {
                if (!is_nullish(o["safeAngle"])) opt.safe_angle = o["safeAngle"].as<double>();
                if (!is_nullish(o["searchOnFailure"])) opt.search_on_failure = o["searchOnFailure"].as<bool>();
                if (!is_nullish(o["tolerance"])) opt.tolerance = o["tolerance"].as<double>();
            }
            const std::size_t dim = std::size_t(dimension());
            return visit([&](const auto& c) {
                js_builder b;
                return cr::report_certificate(b, cr::certify_intersection_free(c.curve, opt), c.curve.grid(), dim);
            });
        });
    }
    val certify0() const { return certify(val::undefined()); }
    // The paper's bounding volumes (Figure 5), for the knots the curve was
    // built with (alpha or a grid). boxes: per segment (segment, a..., b..., lambdaMin,
    // lambdaMax, halfWidth); balls: per vertex (vertex, center..., radius).
    val boundingVolumes(std::string kind) const {
        return guarded([&] {
            return visit([&](const auto& c) {
                const std::size_t D = c.dim;
                cr::volume_kind k;
                if (kind == "tightened") k = cr::volume_kind::tightened;
                else if (kind == "local") k = cr::volume_kind::local;
                else throw cr::invalid_input("volume kind must be \"tightened\" or \"local\", got \"" + kind + "\"");
                const auto v = cr::paper_bounding_volumes(c.curve, k);
                std::vector<double> boxes, balls;
                for (const auto& b : v.boxes) {
                    boxes.push_back(double(b.segment));
                    for (std::size_t d = 0; d < D; ++d) boxes.push_back(b.a[d]);
                    for (std::size_t d = 0; d < D; ++d) boxes.push_back(b.b[d]);
                    boxes.insert(boxes.end(), {b.lambda_min, b.lambda_max, b.half_width});
                }
                for (const auto& b : v.balls) {
                    balls.push_back(double(b.vertex));
                    for (std::size_t d = 0; d < D; ++d) balls.push_back(b.center[d]);
                    balls.push_back(b.radius);
                }
                val r = val::object();
                r.set("boxes", float64_array(boxes));
                r.set("boxStride", double(2 * D + 4));
                r.set("balls", float64_array(balls));
                r.set("ballStride", double(D + 2));
                return r;
            });
        });
    }

    // --- the decision (decision.hpp, issue 27) ---------------------------------
    // Plane curves only: the decision is about crossings, which are generic
    // in 2-D (clearance answers in any dimension).
    const cr::catmull_rom<2>& plane(const char* what) const {
        const auto* c = std::get_if<curve_of<2>>(&c_);
        if (!c || c->dim != 2)
            throw cr::invalid_input(std::string(what) + " needs plane curves (dimension 2), got dimension " +
                                    std::to_string(dimension()) + " (clearance works in any dimension)");
        return c->curve;
    }
    static cr::decision_options decision_options_from(const val& o) {
        cr::decision_options opt;
        if (is_nullish(o)) return opt;
        if (!is_nullish(o["fastPath"])) opt.fast_path = o["fastPath"].as<bool>();
        if (!is_nullish(o["recordPairs"])) opt.record_pairs = o["recordPairs"].as<bool>();
        for (const char* key : {"budget", "pairBudget"}) {
            const val v = o[key];
            if (is_nullish(v)) continue;
            const double x = v.isNumber() ? v.as<double>() : std::nan("");
            if (!(x >= 0 && x <= 9007199254740992.0 && x == std::floor(x)))
                throw cr::invalid_input(std::string(key) + " must be a non-negative integer, got " + cr::detail::num(x));
            (std::string(key) == "budget" ? opt.budget : opt.pair_budget) = std::size_t(x);
        }
        return opt;
    }
    // The decision as the report writes it (report_decision's keys:
    // verdict, fast_path, floor, crossings, touches, pairs).
    val decide(val o) const {
        return guarded([&] {
            js_builder b;
            return cr::report_decision(b, cr::decide(plane("the decision"), decision_options_from(o)));
        });
    }
    val decide0() const { return decide(val::undefined()); }
    // Two curves: do they cross each other? (curve 0 is a, 1 is b)
    static val decidePair(const Spline& a, const Spline& b, val o) {
        return guarded([&] {
            js_builder bld;
            return cr::report_decision(bld, cr::decide(a.plane("the decision"), b.plane("the decision"),
                                                       decision_options_from(o)));
        });
    }
    // A set: does any curve cross another? o.self: each curve's own
    // crossings too.
    static val decideSet(val splines, val o) {
        return guarded([&] {
            if (is_nullish(splines) || !splines["length"].isNumber())
                throw cr::invalid_input("decideSet takes an array of curves");
            const std::size_t n = splines["length"].as<std::size_t>();
            std::vector<cr::catmull_rom<2>> curves;
            curves.reserve(n);
            for (std::size_t i = 0; i < n; ++i) {
                const Spline* s = splines[i].as<Spline*>(emscripten::allow_raw_pointers());
                if (!s) throw cr::invalid_input("curve " + std::to_string(i) + " of the set is missing");
                curves.push_back(s->plane(("curve " + std::to_string(i) + " of the set: the decision").c_str()));
            }
            const bool self = !is_nullish(o) && !is_nullish(o["self"]) && o["self"].as<bool>();
            js_builder b;
            return cr::report_decision(b, cr::decide(std::span<const cr::catmull_rom<2>>(curves), self,
                                                     decision_options_from(o)));
        });
    }
    template <std::size_t D>
    static val clearance_object(const cr::clearance_result<D>& r, std::size_t dim) {
        val o = val::object();
        o.set("distance", r.distance);
        o.set("lowerBound", r.lower_bound);
        o.set("curves", val::array(std::vector<double>{double(r.curve[0]), double(r.curve[1])}));
        o.set("segments", val::array(std::vector<double>{double(r.segment[0]), double(r.segment[1])}));
        o.set("u", val::array(std::vector<double>{r.u[0], r.u[1]}));
        val pts = val::array();
        pts.call<void>("push", point_array(r.points[0], dim));
        pts.call<void>("push", point_array(r.points[1], dim));
        o.set("points", pts);
        o.set("exhausted", r.exhausted);
        return o;
    }
    static double clearance_accuracy(double accuracy) {
        if (!(accuracy >= 0) || !std::isfinite(accuracy))
            throw cr::invalid_input("clearance accuracy must be a finite distance >= 0 (0: 1e-10 of the extent), got " +
                                    cr::detail::num(accuracy));
        return accuracy;
    }
    // The least distance between non-adjacent segments, any dimension:
    // {distance, lowerBound, curves, segments, u, points, exhausted}.
    val clearance(double accuracy) const {
        return guarded([&] {
            const double acc = clearance_accuracy(accuracy);
            return visit([&](const auto& c) { return clearance_object(cr::clearance(c.curve, acc), c.dim); });
        });
    }
    val clearance0() const { return clearance(0); }
    // The least distance between two curves of one dimension.
    static val clearancePair(const Spline& a, const Spline& b, double accuracy) {
        return guarded([&] {
            const double acc = clearance_accuracy(accuracy);
            if (a.dimension() != b.dimension())
                throw cr::invalid_input("clearance between curves of dimensions " + std::to_string(a.dimension()) +
                                        " and " + std::to_string(b.dimension()) + ": they must be equal");
            return a.visit([&](const auto& ca) {
                using C = std::decay_t<decltype(ca)>;
                const C& cb = std::get<C>(b.c_);
                return clearance_object(cr::clearance(ca.curve, cb.curve, acc), ca.dim);
            });
        });
    }
};

}  // namespace

EMSCRIPTEN_BINDINGS(crspline) {
    using namespace emscripten;
    class_<Spline>("Spline")
        .constructor<val, int, val>()
        .constructor<val, int>()
        .function("dimension", &Spline::dimension)
        .function("pointCount", &Spline::pointCount)
        .function("segmentCount", &Spline::segmentCount)
        .function("closed", &Spline::closed)
        .function("tMin", &Spline::tMin)
        .function("tMax", &Spline::tMax)
        .function("points", &Spline::points)
        .function("grid", &Spline::grid)
        .function("locate", &Spline::locate)
        .function("evaluate", &Spline::evaluate)
        .function("evaluate", &Spline::evaluate0)
        .function("evaluateMany", &Spline::evaluateMany)
        .function("evaluateMany", &Spline::evaluateMany0)
        .function("bezier", &Spline::bezier)
        .function("bezierAll", &Spline::bezierAll)
        .function("sampleT", &Spline::sampleT)
        .function("tessellate", &Spline::tessellate)
        .function("boundingBox", &Spline::boundingBox)
        .function("nearest", &Spline::nearest)
        .function("arcLength", &Spline::arcLength)
        .function("arcLength", &Spline::arcLengthAccuracy)
        .function("arcLengthBetween", &Spline::arcLengthBetween)
        .function("knotLengths", &Spline::knotLengths)
        .function("sAt", &Spline::sAt)
        .function("tAtArcLength", &Spline::tAtArcLength)
        .function("sampleArcLength", &Spline::sampleArcLength)
        .function("sampleArcLength", &Spline::sampleArcLength0)
        .function("arcLengthTicks", &Spline::arcLengthTicks)
        .function("curvature", &Spline::curvature)
        .function("curvatureComb", &Spline::curvatureComb)
        .function("curvatureComb", &Spline::curvatureComb1)
        .function("cusps", &Spline::cuspsIn)
        .function("cusps", &Spline::cusps)
        .function("segmentLengths", &Spline::segmentLengths)
        .function("analyze", &Spline::analyze)
        .function("analyze", &Spline::analyze0)
        .function("intersections", &Spline::intersections)
        .function("intersections", &Spline::intersections0)
        .function("certify", &Spline::certify)
        .function("certify", &Spline::certify0)
        .function("boundingVolumes", &Spline::boundingVolumes)
        .function("decide", &Spline::decide)
        .function("decide", &Spline::decide0)
        .function("clearance", &Spline::clearance)
        .function("clearance", &Spline::clearance0)
        .class_function("decidePair", &Spline::decidePair)
        .class_function("decideSet", &Spline::decideSet)
        .class_function("clearancePair", &Spline::clearancePair);
}
