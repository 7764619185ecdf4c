// crspline for JavaScript: what the bindings share (bindings.cpp,
// bind_segment.cpp): errors that become JavaScript Errors, arrays across the
// boundary, the options as the core's curve description, the report
// builder, and the curve of any dimension behind Spline.
//
// Kept inside the subset of libc++ 13 that Emscripten 3.1.6 ships.
#pragma once

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

namespace crspline_js {

using emscripten::val;
namespace cr = crspline;

// ---------------------------------------------------------------------------
// Errors: the library's message becomes a JavaScript Error.
// ---------------------------------------------------------------------------

[[noreturn]] inline void throw_js(const val& error) {
    error.throw_();
    __builtin_unreachable();
}

// A spec_error's parts as properties of the Error (field, index, component,
// value; null where the core has none), so callers can point at the input.
inline val js_error(const std::string& message, const cr::spec_error* spec) {
    val error = val::global("Error").new_(message);
    if (spec) {
        error.set("field", spec->field());
        error.set("index", spec->index() ? val(double(*spec->index())) : val::null());
        error.set("component", spec->component() ? val(double(*spec->component())) : val::null());
        error.set("value", spec->value());
    }
    return error;
}

// Runs f; a C++ exception becomes a JavaScript Error with the same message.
// The message is copied out of the catch block first, so the C++ exception
// is freed before JavaScript unwinds the stack.
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
    throw_js(js_error(message, spec ? &*spec : nullptr));
}

// ---------------------------------------------------------------------------
// Arrays across the boundary.
// ---------------------------------------------------------------------------

inline val float64_array(const double* data, std::size_t n) {
    // A copy: the view into WASM memory dies with the next allocation.
    return val::global("Float64Array").new_(emscripten::typed_memory_view(n, data));
}
inline val float64_array(const std::vector<double>& v) { return float64_array(v.data(), v.size()); }

template <std::size_t D>
val points_array(const std::vector<cr::vec<D>>& p) {
    return float64_array(p.empty() ? nullptr : p.front().data(), p.size() * D);
}
// The first dim coordinates of each point (a wide curve's padding stays in
// WASM).
template <std::size_t D>
val points_array(std::span<const cr::vec<D>> p, std::size_t dim) {
    if (dim >= D) return float64_array(p.empty() ? nullptr : p.front().data(), p.size() * D);
    std::vector<double> out(p.size() * dim);
    for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t k = 0; k < dim; ++k) out[i * dim + k] = p[i][k];
    return float64_array(out);
}
template <std::size_t D>
val points_array(const std::vector<cr::vec<D>>& p, std::size_t dim) {
    return points_array(std::span<const cr::vec<D>>(p), dim);
}
template <std::size_t D>
val point_array(const cr::vec<D>& p, std::size_t dim) { return float64_array(p.data(), std::min(dim, D)); }

inline bool is_nullish(const val& v) { return v.isUndefined() || v.isNull(); }

// Numbers from a JavaScript array, typed array, or array of arrays (points).
inline std::vector<double> numbers(const val& a, const char* what) {
    if (is_nullish(a)) throw cr::invalid_input(std::string(what) + " is missing");
    const val length = a["length"];
    if (!length.isNumber()) throw cr::invalid_input(std::string(what) + " must be an array of numbers");
    const std::size_t n = length.as<std::size_t>();
    if (n > 0 && !a[0].isNumber() && !is_nullish(a[0]["length"])) {
        // Nested [[x, y], ...]: flatten.
        std::vector<double> out;
        std::size_t first = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const std::vector<double> p = emscripten::convertJSArrayToNumberVector<double>(a[i]);
            if (i == 0) first = p.size();
            if (p.size() != first)
                throw cr::spec_error(what, i, std::nullopt, std::to_string(p.size()),
                                     "point " + std::to_string(i) + " has " + std::to_string(p.size()) +
                                         " coordinates, expected " + std::to_string(first) + " like point 0");
            out.insert(out.end(), p.begin(), p.end());
        }
        return out;
    }
    return emscripten::convertJSArrayToNumberVector<double>(a);
}

// Points of dim coordinates (flat) as vec<D>, D >= dim, zero-padded.
template <std::size_t D>
std::vector<cr::vec<D>> to_points(const std::vector<double>& flat, const char* what, std::size_t dim = D) {
    if (flat.size() % dim != 0)
        throw cr::invalid_input(std::string(what) + " has " + std::to_string(flat.size()) +
                                " coordinates, not a multiple of the dimension " + std::to_string(dim));
    std::vector<cr::vec<D>> p(flat.size() / dim);
    for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t k = 0; k < dim; ++k) p[i][k] = flat[i * dim + k];
    return p;
}

template <std::size_t D>
cr::vec<D> to_point(const val& a, const char* what, std::size_t dim = D) {
    const std::vector<double> v = numbers(a, what);
    if (v.size() != dim)
        throw cr::invalid_input(std::string(what) + " has " + std::to_string(v.size()) + " coordinates, expected " +
                                std::to_string(dim));
    cr::vec<D> p{};
    for (std::size_t k = 0; k < dim; ++k) p[k] = v[k];
    return p;
}

// ---------------------------------------------------------------------------
// Options: { alpha, grid, closed, tension, start, end, strict, kb } and the
// points, as the core's run-time description (crspline/spec.hpp): the core
// validates it once and names the field, index and value when it is wrong.
// ---------------------------------------------------------------------------

inline cr::end_spec end_from(const val& e, const char* which) {
    cr::end_spec r;
    if (is_nullish(e)) return r;
    if (e.isString()) {
        const std::string s = e.as<std::string>();
        return cr::end_from_name(which, s);  // the core's names and words
    }
    r.type = cr::end_spec::kind::tangent;
    r.velocity = numbers(is_nullish(e["tangent"]) ? e : e["tangent"], "tangent");
    return r;
}

inline cr::curve_spec spec_from(std::vector<double> flat, int dimension, const val& o) {
    cr::curve_spec s;
    s.dimension = dimension > 0 ? std::size_t(dimension) : 0;
    s.points = std::move(flat);
    if (is_nullish(o)) return s;
    // An option this reader does not know is an error naming it, never
    // silently dropped (tangents and tangentsIn are read with the points).
    const val keys = val::global("Object").call<val>("keys", o);
    for (std::size_t i = 0, n = keys["length"].as<std::size_t>(); i < n; ++i) {
        const std::string k = keys[i].as<std::string>();
        if (o[k].isUndefined()) continue;  // as if absent (JavaScript's own reading)
        if (k != "alpha" && k != "grid" && k != "closed" && k != "strict" && k != "tension" && k != "start" &&
            k != "end" && k != "kb" && k != "tangents" && k != "tangentsIn")
            cr::detail::spec_fail(k, std::nullopt, std::nullopt, "",
                                  "unknown option '" + k + "' (known: alpha, grid, closed, strict, tension, start, "
                                  "end, kb, tangents, tangentsIn)");
    }
    auto number = [&](const char* key) -> std::optional<double> {
        const val v = o[key];
        if (is_nullish(v)) return std::nullopt;
        if (!v.isNumber())
            cr::detail::spec_fail(key, std::nullopt, std::nullopt, "", std::string(key) + " must be a number");
        return v.as<double>();
    };
    s.alpha = number("alpha");
    if (!is_nullish(o["grid"])) s.grid = numbers(o["grid"], "grid");
    if (!is_nullish(o["closed"])) s.closed = o["closed"].as<bool>();
    if (!is_nullish(o["strict"])) s.strict = o["strict"].as<bool>();
    if (const auto t = number("tension")) s.tension = *t;
    s.start = end_from(o["start"], "start");
    s.end = end_from(o["end"], "end");
    const val kb = o["kb"];
    if (!is_nullish(kb)) {
        // null entries read as NaN: the core ignores the value at the two
        // ends of an open curve and rejects it anywhere else ("kb tension[2]
        // is not finite (nan)"), as the command line rejects null there.
        auto tcb = [&](const char* key) {
            std::vector<double> out;
            const val a = kb[key];
            if (is_nullish(a)) return out;
            const std::size_t n = a["length"].as<std::size_t>();
            for (std::size_t i = 0; i < n; ++i) out.push_back(is_nullish(a[i]) ? std::numeric_limits<double>::quiet_NaN() : a[i].as<double>());
            return out;
        };
        s.kb.tension = tcb("tension");
        s.kb.continuity = tcb("continuity");
        s.kb.bias = tcb("bias");
    }
    return s;
}

// ---------------------------------------------------------------------------
// The analysis report (crspline/report.hpp) as plain JavaScript objects: the
// same snake_case keys and values as `crspline analyze` prints and Python's
// dicts hold (docs/report.md); numbers as numbers, lists as arrays.
// ---------------------------------------------------------------------------

struct js_builder {
    using value = val;
    value object() { return val::object(); }
    value array() { return val::array(); }
    void set(value& o, std::string_view key, value v) { o.set(std::string(key), v); }
    void push(value& a, value v) { a.call<void>("push", v); }
    value number(double x) { return val(x); }
    value integer(std::size_t i) { return val(double(i)); }
    value boolean(bool f) { return val(f); }
    value string(std::string_view s) { return val(std::string(s)); }
    value null() { return val::null(); }
};

// ---------------------------------------------------------------------------
// The curve, any dimension 1-4.
// ---------------------------------------------------------------------------

template <std::size_t D>
struct curve_of {
    cr::catmull_rom<D> curve;
    std::optional<cr::arc_length_table<D>> table;  // built on first use
    double alpha;                                  // NaN when built from a grid
    std::size_t dim;                               // the input's dimension (D, or less when padded)

    const cr::arc_length_table<D>& lengths() {
        if (!table) table.emplace(curve);
        return *table;
    }
};

// Given tangents (options.tangents: dx/dt per point, nested or flat;
// options.tangentsIn where the incoming ones differ): the cubic Hermite curve
// through the points on the grid or alpha's knots (catmull_rom::hermite).
// What would compute tangents (tension, kb, strict, end conditions) is
// rejected rather than ignored.
template <std::size_t D>
curve_of<D> make_hermite_curve(const cr::curve_spec& s, const val& o, double alpha) {
    for (const char* key : {"tension", "kb", "strict", "start", "end"})
        if (!is_nullish(o[key])) throw cr::invalid_input(std::string("given tangents take no '") + key + "'");
    cr::detail::check_alpha_or_grid(s.alpha.has_value(), s.grid.has_value());
    const std::size_t dim = s.dimension;
    const std::vector<cr::vec<D>> p = to_points<D>(s.points, "points", dim);
    const std::vector<cr::vec<D>> out = to_points<D>(numbers(o["tangents"], "tangents"), "tangents", dim);
    const std::vector<cr::vec<D>> in = is_nullish(o["tangentsIn"])
                                           ? out
                                           : to_points<D>(numbers(o["tangentsIn"], "tangentsIn"), "tangentsIn", dim);
    const std::span<const cr::vec<D>> ps(p);
    const std::vector<double> grid = s.grid ? *s.grid : cr::knots(ps, s.alpha.value_or(cr::centripetal), s.closed);
    return curve_of<D>{cr::catmull_rom<D>::hermite(ps, out, in, grid, s.closed), std::nullopt, alpha, dim};
}

// D is the storage dimension: the spec's own (1-4) or the wide 16.
template <std::size_t D>
curve_of<D> make_curve(const cr::curve_spec& s, const val& o) {
    const double alpha = s.grid ? std::nan("") : s.alpha.value_or(cr::centripetal);
    if (!is_nullish(o) && !is_nullish(o["tangents"])) return make_hermite_curve<D>(s, o, alpha);
    return curve_of<D>{cr::make_curve<D>(s), std::nullopt, alpha, s.dimension};
}

}  // namespace crspline_js
