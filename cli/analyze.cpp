// crspline analyze: the analysis report of crspline/report.hpp (per segment
// cusps, loops, distances to the chord and the paper's bound; the curve's
// self-intersections; the Section 5 certificate) as JSON. The schema is the
// core's, written there once: docs/report.md.
#include <crspline/report.hpp>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
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

// The report's values as JSON text (crspline::report_builder): a value is
// its text, a container's without its closing bracket until it is attached.
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
        if (parent.count++) parent.text += ',';
        parent.text += prefix;
        parent.text += v.text;
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

    /// The finished text of the report's member or item at `where`
    /// (segments[3]); throws for a non-finite number, by its path as
    /// render() names it (segments[3]["max_chord_distance"]).
    static std::string finish(value&& v, const std::string& where) {
        if (v.bad) output_stream::not_finite(where + *v.bad);
        if (v.close) v.text += v.close;
        return std::move(v.text);
    }
};

// The report as JSON text, member by member (crspline::report_sink): each
// segment's record is written as it is analysed and each meeting of the
// search as it is found, kept in a temporary file past 64 KiB until
// its list is written (after has_self_intersection, which needs the whole
// search). At 10^6 segments and 2*10^6 crossings the text is 1.5 GB; the
// whole analysis held until written took 2.7 GB.
struct text_sink {
    output_stream& out;
    std::size_t members = 0, items = 0;
    std::string key;  // the open list's
    struct held_items {
        std::string text;
        std::FILE* file = nullptr;
        std::size_t count = 0;
    } held[2];
    explicit text_sink(output_stream& o) : out(o) {}
    text_sink(const text_sink&) = delete;
    text_sink& operator=(const text_sink&) = delete;
    ~text_sink() {
        for (held_items& h : held)
            if (h.file) std::fclose(h.file);
    }

    void head(std::string_view k) {
        std::string& buf = out.buffer();
        buf += members++ ? ",\"" : "{\"";
        buf += k;
        buf += "\":";
    }
    void member(std::string_view k, text_builder::value v) {
        head(k);
        out.buffer() += text_builder::finish(std::move(v), std::string(k));
        out.written();
    }
    void open(std::string_view k) {
        head(k);
        out.buffer() += '[';
        key = std::string(k);
        items = 0;
    }
    void item(text_builder::value v) {
        std::string& buf = out.buffer();
        if (items) buf += ',';
        buf += text_builder::finish(std::move(v), key + "[" + std::to_string(items++) + "]");
        out.written();
    }
    void close() { out.buffer() += ']'; }
    void hold(int which, text_builder::value v) {
        held_items& h = held[which];
        if (h.count) h.text += ',';
        h.text += text_builder::finish(std::move(v), std::string(which ? "overlaps" : "intersections") + "[" +
                                                         std::to_string(h.count++) + "]");
        if (h.text.size() < (std::size_t(1) << 16)) return;
        if (!h.file && !(h.file = std::tmpfile()))
            throw input_error(std::string("cannot create a temporary file for the search's findings: ") +
                              std::strerror(errno));
        if (std::fwrite(h.text.data(), 1, h.text.size(), h.file) != h.text.size())
            throw input_error(std::string("cannot write the search's findings to a temporary file: ") +
                              std::strerror(errno));
        h.text.clear();
    }
    void release(int which) {
        held_items& h = held[which];
        if (h.file) {
            std::rewind(h.file);
            std::string& buf = out.buffer();
            std::array<char, 1 << 16> chunk;
            for (std::size_t got; (got = std::fread(chunk.data(), 1, chunk.size(), h.file)) > 0;) {
                buf.append(chunk.data(), got);
                out.written();
            }
            if (std::ferror(h.file))
                throw input_error(std::string("cannot read the search's findings back from a temporary file: ") +
                                  std::strerror(errno));
            std::fclose(h.file);
            h.file = nullptr;
        }
        out.put(h.text);
        h.text = std::string();
        items = h.count;
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

}  // namespace

void stream_analyze(const document& input, const output_settings& settings, output_stream& out) {
    const curve_spec spec = parse_analyze(input);
    report_options opt;
    opt.search = flag(input, "search", true);
    const bool summary = flag(input, "summary", false);
    with_dimension(spec.dimension, [&](auto dim) {
        constexpr std::size_t D = decltype(dim)::value;
        const catmull_rom<D, double> curve = make_curve<D>(spec);
        // Phases on a terminal for long runs (the core reports no fraction).
        progress shown("crspline analyze");
        if (curve.segment_count() >= 20000) shown.phase(opt.search ? "analysis and intersection search" : "analysis");
        if (summary) {
            // --summary: the counts instead of the lists; nothing but the
            // counts is kept (crspline::report_summary).
            json_builder b;
            out.put(render(report_summary(b, curve, opt, spec.dimension), settings.numbers));
            return;
        }
        text_builder b{settings.numbers};
        text_sink sink(out);
        write_report(b, sink, curve, opt, spec.dimension);
        out.put("}\n");
    });
}

output_json run_analyze(const document& input) { return run_streamed(&stream_analyze, input); }

}  // namespace crspline::cli
