// crspline command line: reading one field of the input contract (see
// json_fields.hpp); json_input.cpp puts the fields together.
#include "json_fields.hpp"

#include <crspline/dispatch.hpp>
#include <crspline/resolution.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

#include "csv_input.hpp"
#include "options.hpp"

namespace crspline::cli::json_fields {

[[noreturn]] void fail(const std::string& path, const std::string& what) { throw input_error(path + ": " + what); }

// A value of the curve's specification: a number, whatever its value (the
// JSON parser already refuses literals beyond the double range; what the
// value may be is the core's validate()).
double number(const json& v, const std::string& path) {
    if (!v.is_number()) fail(path, "expected a finite number, got " + describe_json(v));
    return v.get<double>();
}

// A value the subcommand reads itself (t, s, accuracy...): a finite number.
double finite_number(const json& v, const std::string& path) {
    const double x = number(v, path);
    if (!std::isfinite(x)) fail(path, "expected a finite number, got " + describe_json(v));
    return x;
}

const json& array(const json& v, const std::string& path, const char* of_what) {
    if (!v.is_array()) fail(path, std::string("expected an array of ") + of_what + ", got " + describe_json(v));
    return v;
}

// An array of numbers, each read by `one` (number or finite_number).
std::vector<double> list_of(const json& v, const std::string& path, double (*one)(const json&, const std::string&)) {
    array(v, path, "numbers");
    std::vector<double> out;
    out.reserve(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) out.push_back(one(v[i], json_index(path, i)));
    return out;
}
std::vector<double> finite_numbers(const json& v, const std::string& path) { return list_of(v, path, finite_number); }
std::vector<double> numbers(const json& v, const std::string& path) { return list_of(v, path, number); }

// Top-level fields the other subcommands take, for a helpful message.
struct foreign_field {
    std::string_view name, command;
};
constexpr foreign_field foreign_fields[] = {{"t", "eval"},       {"s", "eval"},       {"derivatives", "eval"},
                                           {"accuracy", "eval, length or sample"},
                                           {"count", "sample"},  {"spacing", "sample"}, {"tolerance", "sample"}};

void check_fields(const json& root, std::string_view command, std::initializer_list<std::string_view> extra) {
    for (const auto& item : root.items()) {
        const std::string& key = item.key();  // not a structured binding: clang 14 cannot capture those
        const auto known = [&key](std::string_view k) { return k == key; };
        if (std::any_of(std::begin(curve_fields), std::end(curve_fields), known) ||
            std::any_of(extra.begin(), extra.end(), known))
            continue;
        for (const auto& f : foreign_fields)
            if (f.name == key)
                fail(key, "only 'crspline " + std::string(f.command) + "' takes this field, not 'crspline " +
                              std::string(command) + "'");
        throw input_error("unknown field '" + key + "'");
    }
}

// "natural" | "reflect" | [dx/dt, ...] for one end: `which` is the core's
// field ("start" or "end"), `path` what the user wrote (a JSON path or flag).
// The name and the tangent's length and values are the core's to judge.
crspline::end_spec parse_end(const json& v, const std::string& path, const char* which) {
    if (v.is_string()) return end_from_name(which, v.get_ref<const std::string&>());
    if (!v.is_array()) fail(path, "expected \"natural\", \"reflect\" or a tangent [dx/dt, ...], got " + describe_json(v));
    return {crspline::end_spec::kind::tangent, numbers(v, path)};
}

// The ends of the curve file (docs/spec.md, "The curve file"): the table's
// words, "closed": true | false, "start": E and "end": E with E "natural",
// "reflect" or a tangent [dx/dt, ...]; and the compact forms, still read:
// "end": "closed", "end": {"start": E, "end": E}, and a name in "end" with
// neither "start" nor "closed" beside it, for both ends. Two fields that
// say different things are an error naming both.
void read_ends(const json& root, crspline::curve_spec& c) {
    const json* closed = root.contains("closed") ? &root["closed"] : nullptr;
    const json* start = root.contains("start") ? &root["start"] : nullptr;
    const json* end = root.contains("end") ? &root["end"] : nullptr;
    if (closed && !closed->is_boolean()) fail("closed", "expected true or false, got " + describe_json(*closed));
    const bool is_closed = closed && closed->get<bool>();
    if (end && end->is_string() && *end == "closed") {  // the compact closed curve
        if (closed && !is_closed) fail("end", "\"end\": \"closed\" contradicts \"closed\": false");
        if (start) fail("start", "a closed curve (\"end\": \"closed\") has no start condition");
        c.closed = true;
        return;
    }
    if (is_closed) {
        if (start || end)
            fail(start ? "start" : "end", std::string("a closed curve (\"closed\": true) has no ") +
                                              (start ? "start" : "end") + " condition");
        c.closed = true;
        return;
    }
    if (end && end->is_object()) {  // the compact {"start": E, "end": E}
        if (start) fail("start", "given twice: in \"start\" and in \"end\": {\"start\": ...}");
        for (const auto& [key, value] : end->items()) {
            if (key == "start") c.start = parse_end(value, "end.start", "start");
            else if (key == "end") c.end = parse_end(value, "end.end", "end");
            else fail("end", "unknown field '" + key + "' (expected \"start\" and \"end\")");
        }
        return;
    }
    if (end && !end->is_string() && !end->is_array())
        fail("end", "expected \"natural\", \"reflect\", a tangent [dx/dt, ...], \"closed\" or {\"start\": ..., "
                    "\"end\": ...}, got " + describe_json(*end));
    if (start) c.start = parse_end(*start, "start", "start");
    if (end && end->is_string() && !start && !closed) {
        set_ends(c, end->get_ref<const std::string&>());  // the compact name for both ends
        return;
    }
    if (end) c.end = parse_end(*end, "end", "end");
}

// kb.tension / kb.continuity / kb.bias: one number per vertex, the count and
// the values judged by the core. null stands where the library ignores the
// value (the end vertices of an open curve: 0 there); anywhere else it is a
// missing value (NaN, which the core refuses as not finite).
std::vector<double> parse_kb_values(const json& v, const std::string& path, std::size_t n, bool closed) {
    array(v, path, "numbers, one per point");
    std::vector<double> out(v.size(), 0.0);
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (v[i].is_null()) out[i] = !closed && (i == 0 || i + 1 == n) ? 0.0 : std::nan("");
        else out[i] = number(v[i], json_index(path, i));
    }
    return out;
}




// One list of per-point tangents: n rows of `dim` finite numbers, flat.
std::vector<double> tangent_rows(const json& v, const std::string& path, std::size_t n, std::size_t dim) {
    const json& rows = array(v, path, "tangents [dx/dt, ...], one per point");
    if (rows.size() != n)
        fail(path, "expected " + std::to_string(n) + " tangents (one per point), got " + std::to_string(rows.size()));
    std::vector<double> flat;
    flat.reserve(n * dim);
    for (std::size_t i = 0; i < n; ++i) {
        const std::string at = json_index(path, i);
        const json& r = array(rows[i], at, "coordinates");
        if (r.size() != dim)
            fail(at, "expected " + std::to_string(dim) + " coordinates like points[0], got " + std::to_string(r.size()));
        for (std::size_t k = 0; k < dim; ++k) flat.push_back(finite_number(r[k], json_index(at, k)));
    }
    return flat;
}

// "tangents" of the curve description; the curve then has no computed
// tangents, so what computes them (end conditions, tension, kb, strict) is
// rejected rather than silently ignored.
void parse_tangents(const json& root, const cli_options* f, curve_spec& c) {
    for (const char* key : {"tension", "kb", "strict"})
        if (root.contains(key)) fail("tangents", std::string("given tangents take no '") + key + "'");
    if (f) {
        const std::pair<bool, const char*> flags[] = {
            {!f->tension.empty(), "--tension"}, {!f->kb_tension.empty(), "--kb-tension"},
            {!f->kb_continuity.empty(), "--kb-continuity"}, {!f->kb_bias.empty(), "--kb-bias"},
            {f->strict, "--strict"}, {!f->start.empty(), "--start"}, {!f->end.empty(), "--end"}};
        for (const auto& [given, flag] : flags)
            if (given) fail(flag, "given tangents (the input's \"tangents\") take no " + std::string(flag));
    }
    if ((root.contains("end") || root.contains("start")) && !c.closed)
        fail("tangents", "given tangents take no end conditions (only \"closed\": true or \"end\": \"closed\")");
    const std::size_t n = c.point_count();
    const json& t = root["tangents"];
    if (t.is_object()) {
        if (!t.contains("in") || !t.contains("out") || t.size() != 2)
            fail("tangents", "expected {\"in\": [...], \"out\": [...]} or a list of tangents, got " + describe_json(t));
        c.tangents_in = tangent_rows(t["in"], "tangents.in", n, c.dimension);
        c.tangents_out = tangent_rows(t["out"], "tangents.out", n, c.dimension);
    } else {
        c.tangents_out = tangent_rows(t, "tangents", n, c.dimension);
    }
}


// --- flags ---------------------------------------------------------------------------

// A flag's text as the JSON value it stands for: a number when the text is
// one, else the text as a string, so that the field's own validation reports
// it ("--alpha: expected a finite number, got "abc"").
json scalar(const std::string& text) {
    if (const auto x = parse_number(text)) return *x;
    if (text == "true") return true;
    if (text == "false") return false;
    return text;
}

// One end from --start / --end: "natural" | "reflect" | a tangent "dx,dy".
json end_value(const std::string& flag, const std::string& text) {
    if (text == "natural" || text == "reflect") return text;
    try {
        return number_list(flag, text);
    } catch (const input_error&) {
        return text;  // reported by parse_end with the expected forms
    }
}

// The alpha flags of a one-curve command (plot reads its own list).
std::optional<double> alpha_flag(const cli_options& f) {
    if (f.command == "plot") return std::nullopt;
    const int presets = int(f.uniform) + int(f.centripetal) + int(f.chordal) + int(!f.alpha.empty());
    if (presets > 1)
        throw input_error("--alpha: give one of --alpha, --uniform, --centripetal, --chordal (several are for "
                          "'crspline plot')");
    if (presets == 0) return std::nullopt;
    if (f.uniform) return 0.0;
    if (f.centripetal) return 0.5;
    if (f.chordal) return 1.0;
    return number(scalar(f.alpha), "--alpha");  // its range is the core's
}

bool any_alpha_flag(const cli_options& f) { return f.uniform || f.centripetal || f.chordal || !f.alpha.empty(); }

// The value of a field: the flag's when it is given, else the JSON field's.
std::optional<field_value> field(const json& root, const char* key, const cli_options* f,
                                 const std::string cli_options::*flag, const char* flag_name, bool list) {
    if (f && !(f->*flag).empty())
        return field_value{list ? number_list(flag_name, f->*flag) : scalar(f->*flag), flag_name, true};
    if (root.contains(key)) return field_value{root[key], key, false};
    return std::nullopt;
}

// A closed curve whose last point repeats the first (the GeoJSON and SVG
// convention for rings): the repeat is dropped, since a closed curve joins
// its last point to the first by itself; kept, it would be a duplicated
// point with a sharp corner. Returns whether it was dropped.
bool drop_closing_repeat(curve_spec& c) {
    const std::size_t n = c.point_count(), d = c.dimension;
    if (n < 3) return false;
    if (!std::equal(c.points.begin(), c.points.begin() + std::ptrdiff_t(d), c.points.end() - std::ptrdiff_t(d)))
        return false;
    c.points.resize(c.points.size() - d);
    if (!c.lines.empty()) c.lines.pop_back();
    return true;
}


}  // namespace crspline::cli::json_fields
