// crspline analyze: the analysis report of crspline/report.hpp (per segment
// cusps, loops, distances to the chord and the paper's bound; the curve's
// self-intersections; the Section 5 certificate) as JSON. The schema is the
// core's, written there once: docs/report.md.
#include <crspline/report.hpp>

#include "commands.hpp"
#include "dispatch.hpp"
#include "json_input.hpp"

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

}  // namespace

output_json run_analyze(const document& input) {
    const curve_spec spec = parse_analyze(input);
    return with_dimension(spec.dimension, [&](auto dim) {
        constexpr std::size_t D = decltype(dim)::value;
        const catmull_rom<D, double> curve = make_curve<D>(spec);
        json_builder b;
        return report(b, make_report(curve, {}, spec.dimension));
    });
}

}  // namespace crspline::cli
