// crspline for JavaScript: fit (issue 40, crspline/fit.hpp), bound with
// Embind beside bindings.cpp (web/build.sh links every web/src/*.cpp into
// one module).
//
// fitPoints(flat, dimension, options) returns the fitted control points
// (flat Float64Array), the per-vertex Kochanek-Bartels tension where the fit
// raised it (null otherwise) and the report; the npm package (js/index.js)
// builds its curve object from them with the same options the core used, so
// the curve is the core's one. Dimensions 1 to 4 (the editor and three.js
// need 2 and 3). A C++ exception becomes a JavaScript Error with the core's
// message, as in bindings.cpp.
//
// Kept inside the subset of libc++ 13 that Emscripten 3.1.6 ships.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <crspline/fit.hpp>

#include <cmath>
#include <exception>
#include <span>
#include <string>
#include <vector>

namespace {

using emscripten::val;
namespace cr = crspline;

template <class F>
auto guarded(F&& f) -> decltype(f()) {
    std::string message;
    try {
        return f();
    } catch (const std::exception& e) {
        message = e.what();
    } catch (...) {
        message = "crspline: unknown error";
    }
    val::global("Error").new_(message).throw_();
    __builtin_unreachable();
}

bool nullish(const val& v) { return v.isUndefined() || v.isNull(); }

val float64_array(const double* p, std::size_t n) {
    return val::global("Float64Array").new_(emscripten::typed_memory_view(n, p));  // a copy
}

// Every option name fit knows; any other is an error naming it.
void known_options(const val& o) {
    if (nullish(o)) return;
    const val keys = val::global("Object").call<val>("keys", o);
    for (std::size_t i = 0, n = keys["length"].as<std::size_t>(); i < n; ++i) {
        const std::string k = keys[i].as<std::string>();
        if (o[k].isUndefined()) continue;
        if (k != "tolerance" && k != "mode" && k != "alpha" && k != "closed" && k != "tension" && k != "start" &&
            k != "end")
            throw cr::invalid_input("fit: unknown option '" + k +
                                    "' (known: tolerance, mode, alpha, closed, tension, start, end)");
    }
}

double number_option(const val& o, const char* key, double fallback) {
    const val v = o[key];
    if (nullish(v)) return fallback;
    if (!v.isNumber()) throw cr::invalid_input(std::string("fit: ") + key + " must be a number");
    return v.as<double>();
}

std::string string_option(const val& o, const char* key, const char* fallback) {
    const val v = o[key];
    if (nullish(v)) return fallback;
    if (!v.isString()) throw cr::invalid_input(std::string("fit: ") + key + " must be a string");
    return v.as<std::string>();
}

template <std::size_t D>
val fit_in(const std::vector<double>& flat, const val& o) {
    const std::size_t n = flat.size() / D;
    std::vector<cr::vec<D>> pts(n);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k < D; ++k) pts[i][k] = flat[i * D + k];
    cr::fit_options<D> opt;
    opt.tolerance = number_option(o, "tolerance", std::nan(""));
    if (std::isnan(opt.tolerance) && nullish(o["tolerance"]))
        throw cr::invalid_input("fit: tolerance is missing (a positive distance in the points' units)");
    const std::string mode = string_option(o, "mode", "subset");
    if (mode != "subset" && mode != "free") throw cr::invalid_input("fit: mode must be 'subset' or 'free', got '" + mode + "'");
    opt.mode = mode == "free" ? cr::fit_mode::free : cr::fit_mode::subset;
    opt.alpha = number_option(o, "alpha", 0.5);
    const val closed = o["closed"];
    if (!nullish(closed) && !closed.isTrue() && !closed.isFalse()) throw cr::invalid_input("fit: closed must be true or false");
    opt.closed = !nullish(closed) && closed.as<bool>();
    opt.tension = number_option(o, "tension", 0);
    for (const char* key : {"start", "end"}) {
        const std::string e = string_option(o, key, "natural");
        if (e != "natural" && e != "reflect")
            throw cr::invalid_input(std::string("fit: the ") + key + " end must be 'natural' or 'reflect', got '" + e + "'");
        auto& end = std::string(key) == "start" ? opt.start : opt.end;
        if (e == "reflect") end = cr::end_condition<D>::reflect();
    }
    const cr::fit_result<D> r = cr::fit(std::span<const cr::vec<D>>(pts), opt);
    const auto cp = r.curve.points();
    val out = val::object();
    out.set("points", float64_array(cp.empty() ? nullptr : cp.front().data(), cp.size() * D));
    out.set("dimension", val(int(D)));
    const auto& kb = r.curve.options().kb.tension;
    if (kb.empty()) {
        out.set("kbTension", val::null());
    } else {
        const std::vector<double> t(kb.begin(), kb.end());
        out.set("kbTension", float64_array(t.data(), t.size()));
    }
    out.set("deviation", val(double(r.deviation)));
    out.set("curveToInput", val(double(r.curve_to_input)));
    out.set("inputToCurve", val(double(r.input_to_curve)));
    out.set("count", val(double(r.count)));
    out.set("tensioned", val(double(r.tensioned)));
    out.set("roundingFloor", val(double(r.rounding_floor)));
    if (opt.mode == cr::fit_mode::subset) {
        const std::vector<double> idx(r.indices.begin(), r.indices.end());
        out.set("indices", float64_array(idx.data(), idx.size()));
    } else {
        out.set("indices", val::null());
    }
    out.set("alpha", val(*opt.alpha));
    out.set("closed", val(opt.closed));
    out.set("tension", val(double(opt.tension)));
    return out;
}

val fitPoints(val points, int dimension, val options) {
    return guarded([&] {
        if (nullish(points) || !points["length"].isNumber()) throw cr::invalid_input("fit: points must be an array of numbers");
        const std::vector<double> flat = emscripten::convertJSArrayToNumberVector<double>(points);
        if (dimension < 1 || dimension > 4)
            throw cr::invalid_input("fit: points of dimension " + std::to_string(dimension) +
                                    " (the npm package fits dimensions 1 to 4)");
        if (flat.size() % std::size_t(dimension) != 0)
            throw cr::invalid_input("fit: " + std::to_string(flat.size()) + " coordinates are not a multiple of the dimension " +
                                    std::to_string(dimension));
        known_options(options);
        const val o = nullish(options) ? val::object() : options;
        switch (dimension) {
            case 1: return fit_in<1>(flat, o);
            case 2: return fit_in<2>(flat, o);
            case 3: return fit_in<3>(flat, o);
            default: return fit_in<4>(flat, o);
        }
    });
}

}  // namespace

EMSCRIPTEN_BINDINGS(crspline_fit) {
    emscripten::function("fitPoints", &fitPoints);
}
