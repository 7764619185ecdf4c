// crspline for JavaScript: sweeps and strokes (issue 41, crspline/sweep.hpp
// and crspline/stroke.hpp), bound with Embind beside bindings.cpp
// (web/build.sh links every web/src/*.cpp into one module).
//
// The curve crosses the boundary as what the package's curve object shows:
// its points, knots (grid), closedness and every segment's Bezier control
// points. Here it is rebuilt as the cubic Hermite curve with those points,
// knots and end tangents (3 (B1 - B0) / h and 3 (B3 - B2) / h per segment),
// which is the same piecewise cubic up to rounding, whatever built it
// (alpha, tension, Kochanek-Bartels, given tangents). The sweep and stroke
// options arrive normalized by js/index.js (camelCase there, snake_case in
// the core); the core validates them and names the field: its spec_error's
// field, index and value become properties of the JavaScript Error, as in
// bindings.cpp.
//
// Kept inside the subset of libc++ 13 that Emscripten 3.1.6 ships.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <crspline/catmull_rom.hpp>
#include <crspline/error.hpp>
// nearest.hpp first: decision/clearance.hpp (through sweep.hpp) uses the box
// tree without including it (reported to the lead; harmless once fixed).
#include <crspline/nearest.hpp>
#include <crspline/stroke.hpp>
#include <crspline/sweep.hpp>

#include <cstdint>
#include <exception>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace {

using emscripten::val;
namespace cr = crspline;

template <class F>
auto guarded(F&& f) -> decltype(f()) {
    std::string message;
    std::optional<cr::spec_error> spec;
    try {
        return f();
    } catch (const cr::spec_error& e) {
        message = e.what();
        spec.emplace(e);
    } catch (const std::exception& e) {
        message = e.what();
    } catch (...) {
        message = "crspline: unknown error";
    }
    val error = val::global("Error").new_(message);
    if (spec) {
        error.set("field", spec->field());
        error.set("index", spec->index() ? val(double(*spec->index())) : val::null());
        error.set("component", spec->component() ? val(double(*spec->component())) : val::null());
        error.set("value", spec->value());
    }
    error.throw_();
    __builtin_unreachable();
}

bool nullish(const val& v) { return v.isUndefined() || v.isNull(); }

std::vector<double> numbers(const val& a, const char* what) {
    if (nullish(a)) return {};
    if (!a["length"].isNumber())
        throw cr::spec_error(what, std::nullopt, std::nullopt, "", std::string(what) + ": must be an array of numbers");
    return emscripten::convertJSArrayToNumberVector<double>(a);
}

double number(const val& o, const char* key, double fallback) {
    const val v = o[key];
    if (nullish(v)) return fallback;
    if (!v.isNumber()) throw cr::spec_error(key, std::nullopt, std::nullopt, "", std::string(key) + ": must be a number");
    return v.as<double>();
}

bool flag(const val& o, const char* key, bool fallback) {
    const val v = o[key];
    if (nullish(v)) return fallback;
    if (!v.isTrue() && !v.isFalse())
        throw cr::spec_error(key, std::nullopt, std::nullopt, "", std::string(key) + ": must be true or false");
    return v.as<bool>();
}

std::size_t count(const val& o, const char* key, const char* field) {
    const double n = number(o, key, 0);
    if (!(n >= 0 && n <= 1e8 && n == std::floor(n)))
        throw cr::spec_error(field, std::nullopt, std::nullopt, cr::detail::num(n),
                             std::string(field) + ": must be a whole number >= 1 (0 or absent: from the tolerance), got " +
                                 cr::detail::num(n));
    return std::size_t(n);
}

// The curve of dimension D from its points, knots and Bezier control points.
template <std::size_t D>
cr::catmull_rom<D> hermite_of(const val& points, const val& grid, const val& bezier, bool closed, int dimension) {
    if (dimension != int(D)) {
        const char* op = D == 3 ? "sweep" : "stroke";
        throw cr::spec_error("curve", std::nullopt, std::nullopt, std::to_string(dimension),
                             std::string("curve: ") + op + " needs a " + std::to_string(D) + "-D curve, got a " +
                                 std::to_string(dimension) + "-D one");
    }
    const std::vector<double> p = numbers(points, "points"), g = numbers(grid, "grid"), b = numbers(bezier, "bezier");
    const std::size_t n = p.size() / D, nseg = closed ? n : n - 1;
    if (n < 2 || g.size() != nseg + 1 || b.size() != nseg * 4 * D)
        throw cr::invalid_input("curve: its points, knots and Bezier form do not agree");
    std::vector<cr::vec<D>> pts(n), out(n), in(n);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k < D; ++k) pts[i][k] = p[i * D + k];
    for (std::size_t i = 0; i < nseg; ++i) {
        const double h = g[i + 1] - g[i];
        const std::size_t j = (i + 1) % n;
        for (std::size_t k = 0; k < D; ++k) {
            const double b0 = b[(i * 4 + 0) * D + k], b1 = b[(i * 4 + 1) * D + k];
            const double b2 = b[(i * 4 + 2) * D + k], b3 = b[(i * 4 + 3) * D + k];
            // A segment of zero knot interval is a point: no tangent.
            out[i][k] = h > 0 ? 3 * (b1 - b0) / h : 0;
            in[j][k] = h > 0 ? 3 * (b3 - b2) / h : 0;
        }
    }
    if (!closed) {
        in[0] = out[0];
        out[n - 1] = in[n - 1];
    }
    return cr::catmull_rom<D>::hermite(std::span<const cr::vec<D>>(pts), std::span<const cr::vec<D>>(out),
                                       std::span<const cr::vec<D>>(in), std::span<const double>(g), closed);
}

val float64_array(const std::vector<double>& v) {
    return val::global("Float64Array").new_(emscripten::typed_memory_view(v.size(), v.data()));  // a copy
}

// What WebGL takes: one conversion here, one copy across.
val float32_array(const std::vector<double>& v) {
    const std::vector<float> f(v.begin(), v.end());
    return val::global("Float32Array").new_(emscripten::typed_memory_view(f.size(), f.data()));
}

std::vector<cr::vec<2>> profile_points(const val& o) {
    const std::vector<double> f = numbers(o["profilePoints"], "profile");
    if (f.size() % 2 != 0)
        throw cr::spec_error("profile", std::nullopt, std::nullopt, std::to_string(f.size()),
                             "profile: " + std::to_string(f.size()) + " coordinates, not 2 per point");
    std::vector<cr::vec<2>> p(f.size() / 2);
    for (std::size_t i = 0; i < p.size(); ++i) p[i] = {{f[2 * i], f[2 * i + 1]}};
    return p;
}

val report_object(const cr::sweep_report& r) {
    val o = val::object();
    o.set("tolerance", r.tolerance);
    o.set("bound", r.bound);
    o.set("toleranceMet", r.tolerance_met);
    o.set("proved", r.proved);
    o.set("holonomy", r.holonomy);
    o.set("frameDrift", r.frame_drift);
    o.set("length", r.length);
    o.set("largestRadius", r.largest_radius);
    o.set("clearance", r.clearance);
    o.set("minRadiusOfCurvature", r.min_radius_of_curvature);
    o.set("farContact", r.far_contact);
    o.set("localFold", r.local_fold);
    o.set("selfIntersects", r.self_intersects);
    o.set("seamGap", r.seam_gap);
    o.set("seamNormalGap", r.seam_normal_gap);
    return o;
}

val sweepCurve(val points, val grid, val bezier, bool closed, int dimension, val o) {
    return guarded([&] {
        const cr::catmull_rom<3> c = hermite_of<3>(points, grid, bezier, closed, dimension);
        cr::sweep_options opt;
        const std::string kind = nullish(o["profileKind"]) ? "circle" : o["profileKind"].as<std::string>();
        if (kind == "circle") opt.profile = cr::sweep_profile::circle(number(o, "radius", 1));
        else if (kind == "polyline") opt.profile = cr::sweep_profile::polyline(profile_points(o), flag(o, "profileClosed", false));
        else if (kind == "curve")
            opt.profile = cr::sweep_profile::curve(profile_points(o), flag(o, "profileClosed", true), number(o, "profileAlpha", 0.5));
        else
            throw cr::spec_error("profile", std::nullopt, std::nullopt, kind,
                                 "profile: must be a circle (radius), a polyline or a curve, got '" + kind + "'");
        opt.roll = numbers(o["roll"], "roll");
        const std::string at = nullish(o["rollAt"]) ? "knots" : o["rollAt"].as<std::string>();
        if (at == "arcLength") opt.roll_at = cr::roll_position::arc_length;
        else if (at != "knots")
            throw cr::spec_error("rollAt", std::nullopt, std::nullopt, at, "rollAt: must be 'knots' or 'arcLength', got '" + at + "'");
        opt.roll_s = numbers(o["rollS"], "rollS");
        opt.scale = numbers(o["scale"], "scale");
        opt.scale_s = numbers(o["scaleS"], "scaleS");
        if (!nullish(o["up"])) {
            const std::vector<double> u = numbers(o["up"], "up");
            if (u.size() != 3)
                throw cr::spec_error("up", std::nullopt, std::nullopt, std::to_string(u.size()),
                                     "up: needs 3 coordinates, got " + std::to_string(u.size()));
            opt.up = cr::vec<3>{{u[0], u[1], u[2]}};
        }
        opt.tolerance = number(o, "tolerance", 0);
        opt.tubular_segments = count(o, "tubularSegments", "tubularSegments");
        opt.radial_segments = count(o, "radialSegments", "radialSegments");
        opt.spread_holonomy = flag(o, "spreadHolonomy", true);
        opt.clearance = flag(o, "clearance", true);
        const cr::sweep_mesh m = cr::sweep(c, opt);
        val r = val::object();
        r.set("positions", float32_array(m.positions));
        r.set("normals", float32_array(m.normals));
        r.set("uvs", float32_array(m.uvs));
        r.set("indices", val::global("Uint32Array").new_(emscripten::typed_memory_view(m.indices.size(), m.indices.data())));
        r.set("rings", double(m.rings));
        r.set("ringSize", double(m.ring_size));
        r.set("t", float64_array(m.t));
        r.set("s", float64_array(m.s));
        r.set("report", report_object(m.report));
        return r;
    });
}

val strokeCurve(val points, val grid, val bezier, bool closed, int dimension, double width, val o) {
    return guarded([&] {
        const cr::catmull_rom<2> c = hermite_of<2>(points, grid, bezier, closed, dimension);
        cr::stroke_options opt;
        const std::string join = nullish(o["join"]) ? "round" : o["join"].as<std::string>();
        if (join == "round") opt.join = cr::stroke_join::round;
        else if (join == "miter") opt.join = cr::stroke_join::miter;
        else if (join == "bevel") opt.join = cr::stroke_join::bevel;
        else throw cr::spec_error("join", std::nullopt, std::nullopt, join, "join: must be 'round', 'miter' or 'bevel', got '" + join + "'");
        const std::string cap = nullish(o["cap"]) ? "butt" : o["cap"].as<std::string>();
        if (cap == "butt") opt.cap = cr::stroke_cap::butt;
        else if (cap == "round") opt.cap = cr::stroke_cap::round;
        else if (cap == "square") opt.cap = cr::stroke_cap::square;
        else throw cr::spec_error("cap", std::nullopt, std::nullopt, cap, "cap: must be 'butt', 'round' or 'square', got '" + cap + "'");
        opt.miter_limit = number(o, "miterLimit", 4);
        opt.tolerance = number(o, "tolerance", 0);
        const cr::stroke_result s = cr::stroke(c, width, opt);
        auto ring = [](const std::vector<cr::vec<2>>& r) {
            std::vector<double> f(r.size() * 2);
            for (std::size_t i = 0; i < r.size(); ++i) f[2 * i] = r[i][0], f[2 * i + 1] = r[i][1];
            return float64_array(f);
        };
        val polygons = val::array();
        for (const auto& p : s.polygons) {
            val rings = val::array();
            rings.call<void>("push", ring(p.exterior));
            for (const auto& h : p.holes) rings.call<void>("push", ring(h));
            polygons.call<void>("push", rings);
        }
        val r = val::object();
        r.set("polygons", polygons);
        r.set("tolerance", s.tolerance);
        r.set("tessellationVertices", double(s.tessellation_vertices));
        return r;
    });
}

}  // namespace

EMSCRIPTEN_BINDINGS(crspline_sweep) {
    emscripten::function("sweepCurve", &sweepCurve);
    emscripten::function("strokeCurve", &strokeCurve);
}
