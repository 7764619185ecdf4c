// crspline analyze: the analysis report of crspline/report.hpp (per segment
// cusps, loops, distances to the chord and the paper's bound; the curve's
// self-intersections; the Section 5 certificate) as JSON. The schema is the
// core's, written there once: docs/report.md.
#include <crspline/report.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <utility>

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

// The report as JSON text, written as it is built (crspline::report_builder):
// a value is its text, a container's without its closing bracket until it is
// attached. At 10^6 segments the document tree took 9 GB for 1.3 GB of text.
struct text_builder {
    struct value {
        std::string text;
        char close = 0;          // '}' or ']' while a container is open
        std::size_t count = 0;   // members so far
        std::optional<std::string> bad;  // where the first non-finite number is, below this value
    };
    number_format numbers;

    value object() { return {"{", '}'}; }
    value array() { return {"[", ']'}; }
    static void attach(value& parent, value&& v, const std::string& where, std::string_view prefix) {
        if (v.close) v.text += v.close;
        if (!parent.bad && v.bad) parent.bad = where + *v.bad;
        std::string head(parent.count++ ? "," : "");
        head += prefix;
        if (v.text.size() > parent.text.size()) {
            // A long member (the segments): the parent's few bytes go in
            // front of it rather than a copy of it after them.
            v.text.insert(0, parent.text + head);
            parent.text = std::move(v.text);
        } else {
            parent.text += head;
            parent.text += v.text;
        }
    }
    void set(value& o, std::string_view key, value v) {
        std::string prefix = "\"" + std::string(key) + "\":";
        attach(o, std::move(v), "[\"" + std::string(key) + "\"]", prefix);
    }
    void push(value& a, value v) {
        const std::string where = "[" + std::to_string(a.count) + "]";
        attach(a, std::move(v), where, "");
    }
    value number(double x) {
        value v;
        if (!std::isfinite(x)) {
            v.text = "null";
            v.bad = "";
        } else {
            append_json_number(v.text, x, numbers);
        }
        return v;
    }
    value integer(std::size_t i) { return {std::to_string(i)}; }
    value boolean(bool f) { return {f ? "true" : "false"}; }
    value string(std::string_view s) { return {output_json(std::string(s)).dump()}; }
    value null() { return {"null"}; }

    /// The finished text; throws for a non-finite number, by its path as
    /// render() names it (segments[3]["max_chord_distance"]).
    std::string finish(value&& v) {
        if (v.bad) {
            std::string path = *v.bad;
            if (path.rfind("[\"", 0) == 0) {  // the first key without brackets
                const auto end = path.find("\"]");
                path = path.substr(2, end - 2) + path.substr(end + 2);
            }
            output_stream::not_finite(path);
        }
        if (v.close) v.text += v.close;
        return std::move(v.text);
    }
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
// answer does not grow with the curve). The per-segment counts come from the
// analysis itself; the rest from the report of the curve without its
// segments' records.
template <std::size_t D>
output_json summary_of(analysis_report<D, double>&& r) {
    const output_json none = nullptr;
    std::size_t cusps = 0, loops = 0;
    for (const auto& s : r.segments) cusps += s.cusp_u.size(), loops += s.self_intersection.size();
    output_json o;
    o["dimension"] = r.dimension;
    o["segment_count"] = r.segments.size();
    o["cusps"] = cusps;
    o["loops"] = loops;
    r.segments.clear();
    r.segments.shrink_to_fit();
    json_builder b;
    const output_json rest = report(b, r);
    const auto count = [&](const char* key) { return rest[key].is_null() ? none : output_json(rest[key].size()); };
    o["intersections"] = count("intersections");
    o["overlaps"] = count("overlaps");
    o["folds"] = count("folds");
    o["complete"] = rest["complete"];
    o["certificate"] = rest["certificate"];
    return o;
}

}  // namespace

void stream_analyze(const document& input, const output_settings& settings, output_stream& out) {
    const curve_spec spec = parse_analyze(input);
    report_options opt;
    opt.search = flag(input, "search", true);
    const bool summary = flag(input, "summary", false);
    with_dimension(spec.dimension, [&](auto dim) {
        constexpr std::size_t D = decltype(dim)::value;
        analysis_report<D, double> r;
        {
            const catmull_rom<D, double> curve = make_curve<D>(spec);
            // Phases on a terminal for long runs (the core reports no fraction).
            progress shown("crspline analyze");
            if (curve.segment_count() >= 20000) shown.phase(opt.search ? "analysis and intersection search" : "analysis");
            r = make_report(curve, opt, spec.dimension);
        }
        if (summary) {
            out.put(render(summary_of(std::move(r)), settings.numbers));
            return;
        }
        text_builder b{settings.numbers};
        std::string text = b.finish(report(b, r));
        r = {};
        text += '\n';
        if (std::string& buf = out.buffer(); buf.empty()) buf.swap(text);  // no second copy of the text
        else buf += text;
        out.written();
    });
}

output_json run_analyze(const document& input) { return run_streamed(&stream_analyze, input); }

}  // namespace crspline::cli
