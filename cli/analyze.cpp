// crspline analyze: the analysis report of crspline/report.hpp (per segment
// cusps, loops, distances to the chord and the paper's bound; the curve's
// self-intersections; the Section 5 certificate) as JSON. The schema is the
// core's, written there once: docs/report.md.
#include <crspline/report.hpp>

#include "commands.hpp"
#include "dispatch.hpp"
#include "json_input.hpp"
#include "options.hpp"
#include "progress.hpp"

namespace crspline::cli {

namespace {

// The report's values as JSON nodes (crspline::report_builder).
struct json_builder {
    using value = output_json;
    value object() { return output_json::object(); }
    value array() { return output_json::array(); }
    void set(value& o, std::string_view key, value v) { o[std::string(key)] = std::move(v); }
    void push(value& a, value v) { a.push_back(std::move(v)); }
    value number(double x) { return x; }
    value integer(std::size_t i) { return i; }
    value boolean(bool f) { return f; }
    value string(std::string_view s) { return std::string(s); }
    value null() { return nullptr; }
};

// "summary" and "search": true or false (--summary, --no-intersections).
// The flags win over the fields (--summary sets "summary", --no-intersections
// clears "search").
bool flag(const document& input, const char* key, bool fallback) {
    if (input.flags && std::string_view(key) == "summary" && input.flags->summary) return true;
    if (input.flags && std::string_view(key) == "search" && input.flags->no_search) return false;
    if (!input.root.contains(key)) return fallback;
    const auto& v = input.root[key];
    if (!v.is_boolean()) throw input_error(std::string(key) + ": expected true or false, got " + v.dump());
    return v.get<bool>();
}

// --summary: the report's counts instead of its lists (the size of the
// answer does not grow with the curve).
output_json summary_of(const output_json& r) {
    const output_json none = nullptr;
    std::size_t loops = 0;
    for (const auto& s : r["segments"]) loops += s["self_intersection_u"].size();
    const auto count = [&](const char* key) { return r[key].is_null() ? none : output_json(r[key].size()); };
    output_json o;
    o["dimension"] = r["dimension"];
    o["segment_count"] = r["segments"].size();
    o["cusps"] = r["cusp_t"].size();
    o["loops"] = loops;
    o["intersections"] = count("intersections");
    o["overlaps"] = count("overlaps");
    o["folds"] = count("folds");
    o["complete"] = r["complete"];
    o["certificate"] = r["certificate"];
    return o;
}

}  // namespace

output_json run_analyze(const document& input) {
    const curve_spec spec = parse_analyze(input);
    report_options opt;
    opt.search = flag(input, "search", true);
    const bool summary = flag(input, "summary", false);
    return with_dimension(spec.dimension, [&](auto dim) {
        constexpr std::size_t D = decltype(dim)::value;
        const catmull_rom<D, double> curve = make_curve<D>(spec);
        // Phases on a terminal for long runs (the core reports no fraction).
        progress shown("crspline analyze");
        if (curve.segment_count() >= 20000) shown.phase(opt.search ? "analysis and intersection search" : "analysis");
        json_builder b;
        output_json r = report(b, make_report(curve, opt, spec.dimension));
        return summary ? summary_of(r) : r;
    });
}

}  // namespace crspline::cli
