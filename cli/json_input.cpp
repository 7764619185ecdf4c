// crspline command line: the input contract. The JSON fields of a document
// and the command-line flags become one curve description (curve_spec) and
// the work of a subcommand; every problem is reported by the field's JSON
// path or the flag's name. See json_input.hpp.
#include "json_input.hpp"

#include <crspline/dispatch.hpp>
#include <crspline/resolution.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

#include "csv_input.hpp"
#include "options.hpp"

namespace crspline::cli {

using nlohmann::json;
namespace {

// The offending value as it appears in JSON, shortened when long.
std::string describe(const json& v) {
    if (v.is_number()) return format_number(v.get<double>());
    std::string s = v.dump(-1, ' ', false, json::error_handler_t::replace);
    if (s.size() > 40) s = s.substr(0, 37) + "...";
    return s;
}

std::string index(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

[[noreturn]] void fail(const std::string& path, const std::string& what) { throw input_error(path + ": " + what); }

double finite_number(const json& v, const std::string& path) {
    if (!v.is_number()) fail(path, "expected a finite number, got " + describe(v));
    const double x = v.get<double>();
    if (!std::isfinite(x)) fail(path, "expected a finite number, got " + describe(v));
    return x;
}

const json& array(const json& v, const std::string& path, const char* of_what) {
    if (!v.is_array()) fail(path, std::string("expected an array of ") + of_what + ", got " + describe(v));
    return v;
}

std::vector<double> finite_numbers(const json& v, const std::string& path) {
    array(v, path, "numbers");
    std::vector<double> out;
    out.reserve(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) out.push_back(finite_number(v[i], index(path, i)));
    return out;
}

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

// "natural" | "reflect" | [dx/dt, ...] for one end of the object form.
end_spec parse_end(const json& v, const std::string& path, std::size_t dim) {
    const std::string expected = "expected \"natural\", \"reflect\" or a tangent [dx/dt, ...], got ";
    end_spec e;
    if (v.is_string()) {
        const auto& s = v.get_ref<const std::string&>();
        if (s == "natural") e.type = end_spec::kind::natural;
        else if (s == "reflect") e.type = end_spec::kind::reflect;
        else fail(path, expected + describe(v));
        return e;
    }
    if (!v.is_array()) fail(path, expected + describe(v));
    if (v.size() != dim)
        fail(path, "expected a tangent of " + std::to_string(dim) + " coordinates like the points, got " +
                       std::to_string(v.size()));
    e.type = end_spec::kind::tangent;
    e.velocity = finite_numbers(v, path);
    return e;
}

// kb.tension / kb.continuity / kb.bias: one finite value per vertex; null
// only where the library ignores the value (the end vertices of an open curve).
std::vector<double> parse_kb_values(const json& v, const std::string& path, std::size_t n, bool closed) {
    array(v, path, "numbers, one per point");
    if (v.size() != n)
        fail(path, "expected " + std::to_string(n) + " values (one per point), got " + std::to_string(v.size()));
    std::vector<double> out(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        if (v[i].is_null() && !closed && (i == 0 || i + 1 == n)) continue;  // ignored end vertex
        if (v[i].is_null())
            fail(index(path, i), "expected a finite number, got null (null is allowed only at the two end "
                                 "vertices of an open curve)");
        out[i] = finite_number(v[i], index(path, i));
    }
    return out;
}

}  // namespace

// --- the contract ------------------------------------------------------------------

namespace {

// One list of per-point tangents: n rows of `dim` finite numbers, flat.
std::vector<double> tangent_rows(const json& v, const std::string& path, std::size_t n, std::size_t dim) {
    const json& rows = array(v, path, "tangents [dx/dt, ...], one per point");
    if (rows.size() != n)
        fail(path, "expected " + std::to_string(n) + " tangents (one per point), got " + std::to_string(rows.size()));
    std::vector<double> flat;
    flat.reserve(n * dim);
    for (std::size_t i = 0; i < n; ++i) {
        const std::string at = index(path, i);
        const json& r = array(rows[i], at, "coordinates");
        if (r.size() != dim)
            fail(at, "expected " + std::to_string(dim) + " coordinates like points[0], got " + std::to_string(r.size()));
        for (std::size_t k = 0; k < dim; ++k) flat.push_back(finite_number(r[k], index(at, k)));
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
    if (root.contains("end") && !c.closed)
        fail("tangents", "given tangents take no end conditions (only \"end\": \"closed\")");
    const std::size_t n = c.point_count();
    const json& t = root["tangents"];
    if (t.is_object()) {
        if (!t.contains("in") || !t.contains("out") || t.size() != 2)
            fail("tangents", "expected {\"in\": [...], \"out\": [...]} or a list of tangents, got " + describe(t));
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
    const double a = finite_number(scalar(f.alpha), "--alpha");
    if (!(a >= 0 && a <= 1)) fail("--alpha", "must be in [0, 1], got " + format_number(a));
    return a;
}

bool any_alpha_flag(const cli_options& f) { return f.uniform || f.centripetal || f.chordal || !f.alpha.empty(); }

// The value of a field: the flag's when it is given, else the JSON field's.
// `name` is what messages call it.
struct field_value {
    json value;
    std::string name;
    bool flag = false;
};
std::optional<field_value> field(const json& root, const char* key, const cli_options* f,
                                 const std::string cli_options::*flag, const char* flag_name, bool list = false) {
    if (f && !(f->*flag).empty())
        return field_value{list ? number_list(flag_name, f->*flag) : scalar(f->*flag), flag_name, true};
    if (root.contains(key)) return field_value{root[key], key, false};
    return std::nullopt;
}

// The grid: N increasing finite values (N + 1 when closed).
std::vector<double> parse_grid(const json& v, const std::string& name, std::size_t n, bool closed) {
    std::vector<double> g = finite_numbers(v, name);
    const std::size_t expected = closed ? n + 1 : n;
    if (g.size() != expected)
        fail(name, "expected " + std::to_string(expected) + " values (" +
                       (closed ? "one per point plus one to close the curve" : "one per point") + "), got " +
                       std::to_string(g.size()));
    for (std::size_t i = 1; i < g.size(); ++i)
        if (!(g[i] > g[i - 1]))
            fail(index(name, i), "must be greater than grid[" + std::to_string(i - 1) + "] = " +
                                     format_number(g[i - 1]) + ", got " + format_number(g[i]));
    return g;
}

// A closed curve whose last point repeats the first (the GeoJSON and SVG
// convention for rings): the repeat is dropped, since a closed curve joins
// its last point to the first by itself; kept, it would be a duplicated
// point with a sharp corner. Returns whether it was dropped.
bool drop_closing_repeat(curve_spec& c) {
    const std::size_t n = c.point_count(), d = c.dimension;
    if (n < 3) return false;
    if (!std::equal(c.coords.begin(), c.coords.begin() + std::ptrdiff_t(d), c.coords.end() - std::ptrdiff_t(d)))
        return false;
    c.coords.resize(c.coords.size() - d);
    if (!c.lines.empty()) c.lines.pop_back();
    return true;
}

}  // namespace

std::string point_location(const curve_spec& c, std::size_t i) {
    if (i < c.lines.size()) return "line " + std::to_string(c.lines[i]) + " (point " + std::to_string(i + 1) + ")";
    return index(c.points_path, i);
}

std::string describe_spec_error(const crspline::spec_error& e, const curve_spec& c) {
    const std::string file = c.file.empty() ? std::string() : c.file + ": ";
    if (e.field() == "points" && e.index() && *e.index() < c.point_count()) {
        const std::size_t i = *e.index(), n = c.point_count(), j = (i + 1) % n;
        const std::string what = e.what();
        // The core's words (the same in every front end), after where the
        // points are as the user finds them; the core counts from 0.
        if (what.find("coincident") != std::string::npos)
            return file + point_location(c, i) + " and " + point_location(c, j) + ": " + what +
                   (c.lines.empty() ? "" : " (counted from 0)");
        return file + point_location(c, i) + ": " + what;
    }
    return file + e.what();
}

curve_spec parse_curve(const document& doc, std::string_view command, std::initializer_list<std::string_view> extra) {
    const json& root = doc.root;
    const cli_options* f = doc.flags;
    if (!root.is_object()) throw input_error("expected a JSON object {\"points\": ...}, got " + describe(root));
    // Unknown fields first: a typo is the likeliest cause of any later error.
    check_fields(root, command, extra);
    curve_spec c;
    c.file = doc.file;

    // points: N x D finite numbers, D in 1..16 and the same for every point.
    std::string points_name = "points";
    if (doc.points) {
        c.dimension = doc.points->dimension;
        c.coords = doc.points->coords;
        c.lines = doc.points->lines;
        c.points_path = doc.points->path;
        points_name = doc.points->name;
    } else if (!root.contains("points")) {
        throw input_error("missing field 'points'");
    }
    static const json no_points = json::array();  // flat points were validated when read
    const json& pts = doc.points ? no_points : array(root["points"], "points", "points");
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const std::string at = index("points", i);
        const json& p = array(pts[i], at, "coordinates");
        if (i == 0 && (p.empty() || p.size() > max_runtime_dimension))
            fail(at, "expected 1 to " + std::to_string(max_runtime_dimension) + " coordinates, got " +
                         std::to_string(p.size()));
        if (i > 0 && p.size() != c.dimension)
            fail(at, "expected " + std::to_string(c.dimension) + " coordinates like points[0], got " +
                         std::to_string(p.size()));
        c.dimension = p.size();
        for (std::size_t k = 0; k < p.size(); ++k) c.coords.push_back(finite_number(p[k], index(at, k)));
    }
    if (c.point_count() == 0) fail(points_name, "a curve needs at least 2 points, got 0");

    // end: --closed, --start, --end, else "end": "natural" | "reflect" |
    // "closed" | {"start": E, "end": E}. A flag for one end leaves the other
    // end as the JSON says (an open curve).
    if (f && f->closed && (!f->start.empty() || !f->end.empty()))
        throw input_error("--closed: a closed curve has no end conditions (--start, --end)");
    if (f && f->closed) {
        c.closed = true;
    } else if (root.contains("end")) {
        const json& e = root["end"];
        const std::string expected =
            "expected \"natural\", \"reflect\", \"closed\" or {\"start\": ..., \"end\": ...}, got ";
        if (e.is_string()) {
            const auto& s = e.get_ref<const std::string&>();
            if (s == "closed") c.closed = true;
            else if (s == "natural") c.start.type = c.end.type = end_spec::kind::natural;
            else if (s == "reflect") c.start.type = c.end.type = end_spec::kind::reflect;
            else fail("end", expected + describe(e));
        } else if (e.is_object()) {
            for (const auto& [key, value] : e.items()) {
                if (key == "start") c.start = parse_end(value, "end.start", c.dimension);
                else if (key == "end") c.end = parse_end(value, "end.end", c.dimension);
                else fail("end", "unknown field '" + key + "' (expected \"start\" and \"end\")");
            }
        } else {
            fail("end", expected + describe(e));
        }
    }
    if (f && (!f->start.empty() || !f->end.empty())) {
        c.closed = false;
        if (!f->start.empty()) c.start = parse_end(end_value("--start", f->start), "--start", c.dimension);
        if (!f->end.empty()) c.end = parse_end(end_value("--end", f->end), "--end", c.dimension);
    }
    // A repeated first point is dropped where the closing comes from the
    // command line (--closed on a CSV or JSON file); the JSON curve file's
    // own "end": "closed" is taken as written (three.js and d3 keep such a
    // point, and the reference tests compare with them).
    if (c.closed && f && f->closed && c.point_count() > 0) {
        const std::string last = point_location(c, c.point_count() - 1);
        if (drop_closing_repeat(c))
            doc.notes.push_back((c.file.empty() ? std::string() : c.file + ": ") + last +
                                ": repeats the first point; a closed curve joins its last point to the first by "
                                "itself, so the repeat is dropped");
    }
    const std::size_t n = c.point_count(), needed = 2;  // closed too: a loop of two segments
    if (n < needed)
        fail(points_name, std::string(c.closed ? "a closed curve" : "a curve") + " needs at least " +
                              std::to_string(needed) + " points, got " + std::to_string(n));

    // alpha or grid (not both); default alpha 0.5. A flag overrides the
    // JSON: --alpha (or a preset) replaces "alpha" and "grid", --grid both.
    const std::optional<double> flag_alpha = f ? alpha_flag(*f) : std::nullopt;
    if (f && !f->grid.empty()) {
        if (any_alpha_flag(*f) && f->command != "plot")
            throw input_error("--grid: give --grid or an alpha (--alpha, --uniform, --centripetal, --chordal), not both");
        c.grid = parse_grid(number_list("--grid", f->grid), "--grid", n, c.closed);
    } else if (flag_alpha) {
        c.alpha = flag_alpha;
    } else {
        if (root.contains("alpha") && root.contains("grid")) fail("grid", "give alpha or grid, not both");
        if (root.contains("alpha")) {
            const double a = finite_number(root["alpha"], "alpha");
            if (!(a >= 0 && a <= 1)) fail("alpha", "must be in [0, 1], got " + format_number(a));
            c.alpha = a;
        }
        if (root.contains("grid")) c.grid = parse_grid(root["grid"], "grid", n, c.closed);
    }

    // tension: tangents scaled by 1 - tension.
    if (const auto t = field(root, "tension", f, &cli_options::tension, "--tension")) {
        c.tension = finite_number(t->value, t->name);
        if (!(c.tension >= 0 && c.tension <= 1)) fail(t->name, "must be in [0, 1], got " + format_number(c.tension));
    }

    // kb: per-vertex Kochanek-Bartels values; a missing array means zeros;
    // --kb-tension and the others replace one array each.
    if (root.contains("kb")) {
        const json& kb = root["kb"];
        if (!kb.is_object())
            fail("kb", "expected {\"tension\": [...], \"continuity\": [...], \"bias\": [...]}, got " + describe(kb));
        for (const auto& [key, value] : kb.items()) {
            const std::string path = "kb." + key;
            if (key == "tension") c.kb_tension = parse_kb_values(value, path, n, c.closed);
            else if (key == "continuity") c.kb_continuity = parse_kb_values(value, path, n, c.closed);
            else if (key == "bias") c.kb_bias = parse_kb_values(value, path, n, c.closed);
            else fail("kb", "unknown field '" + key + "' (expected \"tension\", \"continuity\", \"bias\")");
        }
    }
    if (f) {
        const std::tuple<const std::string*, const char*, std::vector<double>*> kb_flags[] = {
            {&f->kb_tension, "--kb-tension", &c.kb_tension},
            {&f->kb_continuity, "--kb-continuity", &c.kb_continuity},
            {&f->kb_bias, "--kb-bias", &c.kb_bias}};
        for (const auto& [text, flag, values] : kb_flags)
            if (!text->empty()) *values = parse_kb_values(number_list(flag, *text, true), flag, n, c.closed);
    }

    if (f && f->strict) {
        c.strict = true;
    } else if (root.contains("strict")) {
        const json& s = root["strict"];
        if (!s.is_boolean()) fail("strict", "expected true or false, got " + describe(s));
        c.strict = s.get<bool>();
    }

    // tangents: [[dx/dt, ...] per point], or {"in": [...], "out": [...]} when
    // incoming and outgoing differ: a cubic Hermite curve with them.
    if (root.contains("tangents")) parse_tangents(root, f, c);
    return c;
}

namespace {

// "accuracy" / --accuracy: relative accuracy of arc lengths, in (0, 1) and
// not below what doubles resolve; default 1e-12.
double parse_accuracy(const document& doc) {
    const auto a = field(doc.root, "accuracy", doc.flags, &cli_options::accuracy, "--accuracy");
    if (!a) return 1e-12;
    const double x = finite_number(a->value, a->name);
    if (!(x > 0 && x < 1)) fail(a->name, "expected a relative accuracy in (0, 1), got " + describe(a->value));
    if (const std::string why = accuracy_floor_problem(x); !why.empty()) fail(a->name, why);
    return x;
}

// The name of a flag when the input has no JSON fields (CSV), of the field
// otherwise, for a message about something missing.
std::string missing(const document& doc, const char* key) {
    return doc.has_fields ? "'" + std::string(key) + "'" : "--" + std::string(key);
}

}  // namespace

eval_spec parse_eval(const document& doc) {
    const json& root = doc.root;
    const cli_options* f = doc.flags;
    eval_spec e;
    e.curve = parse_curve(doc, "eval", {"t", "s", "u", "arc_fraction", "knots", "derivatives", "accuracy"});
    // Where to evaluate: exactly one of t, s, u, arc_fraction. A flag
    // replaces every field: --t 0,1 on a document with "s" evaluates at t.
    struct kind {
        const char* key;
        const std::string cli_options::*flag;
        const char* flag_name;
    };
    static constexpr kind kinds[] = {{"t", &cli_options::t, "--t"},
                                     {"s", &cli_options::s, "--s"},
                                     {"u", &cli_options::u, "--u"},
                                     {"arc_fraction", &cli_options::arc_fraction, "--arc-fraction"}};
    std::vector<std::pair<std::string, field_value>> given;  // key, value
    for (const kind& k : kinds)
        if (f && !(f->*k.flag).empty()) given.emplace_back(k.key, field_value{number_list(k.flag_name, f->*k.flag), k.flag_name, true});
    if (given.empty())
        for (const kind& k : kinds)
            if (root.contains(k.key)) given.emplace_back(k.key, field_value{root[k.key], k.key, false});
    if (given.size() > 1) {
        const bool flags = given[0].second.flag;
        const bool t_and_s = given.size() == 2 && given[0].first == "t" && given[1].first == "s";
        if (t_and_s)
            throw input_error(flags ? "--s: give --t (parameter values) or --s (arc lengths), not both"
                                    : "give 't' (parameter values) or 's' (arc lengths), not both");
        throw input_error(flags ? given[1].second.name + ": give one of --t, --s, --u, --arc-fraction, got " +
                                      given[0].second.name + " and " + given[1].second.name
                                : "give one of 't', 's', 'u', 'arc_fraction', got '" + given[0].first + "' and '" +
                                      given[1].first + "'");
    }
    if (given.empty()) {
        const bool fields = doc.has_fields;
        throw input_error(std::string(fields ? "missing field " : "missing option ") + missing(doc, "t") +
                          " (the parameter values to evaluate at) or " + missing(doc, "s") + " (arc lengths)");
    }
    const std::string& key = given[0].first;
    const field_value& param = given[0].second;
    e.param_name = param.name;
    if (key == "s" || key == "arc_fraction") {
        (key == "s" ? e.s : e.arc_fraction) = finite_numbers(param.value, param.name);
        e.accuracy = parse_accuracy(doc);
    } else {
        if (const auto a = field(root, "accuracy", f, &cli_options::accuracy, "--accuracy"))
            fail(a->name, std::string("only used with ") +
                              (key == "t" ? (a->flag ? "--s" : "'s'") : (a->flag ? "--s or --arc-fraction" : "'s' or 'arc_fraction'")) +
                              " (arc lengths)");
        (key == "u" ? e.u.emplace() : e.t) = finite_numbers(param.value, param.name);
    }
    if (f && f->knots) e.knots = true;
    else if (root.contains("knots")) {
        if (!root["knots"].is_boolean()) fail("knots", "expected true or false, got " + describe(root["knots"]));
        e.knots = root["knots"].get<bool>();
    }
    const auto d_field = field(root, "derivatives", f, &cli_options::derivatives, "--derivatives", true);
    if (!d_field) {
        e.derivatives = {0};
        return e;
    }
    const std::string& name = d_field->name;
    const json& d = array(d_field->value, name, "derivative orders");
    if (d.empty()) fail(name, "expected at least one order (0, 1, 2 or 3), got []");
    for (std::size_t i = 0; i < d.size(); ++i) {
        const std::string at = index(name, i);
        const double x = d[i].is_number() ? d[i].get<double>() : -1.0;
        if (!(x == 0 || x == 1 || x == 2 || x == 3)) fail(at, "expected 0, 1, 2 or 3, got " + describe(d[i]));
        const int order = int(x);
        const auto seen = std::find(e.derivatives.begin(), e.derivatives.end(), order);
        if (seen != e.derivatives.end())
            fail(at, "order " + std::to_string(order) + " is already requested by " +
                         index(name, std::size_t(seen - e.derivatives.begin())));
        e.derivatives.push_back(order);
    }
    return e;
}

bezier_spec parse_bezier(const document& doc) { return {parse_curve(doc, "bezier", {})}; }

curve_spec parse_analyze(const document& doc) { return parse_curve(doc, "analyze", {"summary", "search"}); }

length_spec parse_length(const document& doc) {
    length_spec l;
    l.curve = parse_curve(doc, "length", {"accuracy"});
    l.accuracy = parse_accuracy(doc);
    return l;
}

sample_spec parse_sample(const document& doc) {
    const json& root = doc.root;
    const cli_options* f = doc.flags;
    sample_spec s;
    s.curve = parse_curve(doc, "sample", {"count", "spacing", "tolerance", "accuracy"});
    s.accuracy = parse_accuracy(doc);
    const bool flag_count = f && !f->count.empty(), flag_tolerance = f && !f->tolerance.empty();
    if (flag_count && flag_tolerance)
        throw input_error("--tolerance: give --count (number of points) or --tolerance (largest distance to the "
                          "curve), not both");
    // A flag replaces the JSON's choice: --count on a document with
    // "tolerance" samples by count.
    const auto count = flag_count ? std::optional<field_value>(field_value{scalar(f->count), "--count", true})
                       : flag_tolerance || !root.contains("count") ? std::nullopt
                                                                   : std::optional<field_value>(field_value{root["count"], "count", false});
    const auto tolerance = flag_tolerance ? std::optional<field_value>(field_value{scalar(f->tolerance), "--tolerance", true})
                           : flag_count || !root.contains("tolerance") ? std::nullopt
                                                                       : std::optional<field_value>(field_value{root["tolerance"], "tolerance", false});
    if (bool(count) == bool(tolerance))
        throw input_error(doc.has_fields ? "give 'count' (number of points) or 'tolerance' (largest distance to the "
                                           "curve), exactly one of them"
                                         : "give --count (number of points) or --tolerance (largest distance to the "
                                           "curve), exactly one of them");
    const auto spacing = flag_tolerance ? (f->spacing.empty() ? std::nullopt : std::optional<field_value>(field_value{f->spacing, "--spacing", true}))
                                        : field(root, "spacing", f, &cli_options::spacing, "--spacing");
    if (count) {
        const json& c = count->value;
        const double n = c.is_number() ? c.get<double>() : -1.0;
        if (!(n >= 2 && n <= 1e9 && n == std::floor(n))) fail(count->name, "expected an integer >= 2, got " + describe(c));
        s.count = std::size_t(n);
        s.by = sample_spec::kind::count_t;
        if (spacing) {
            const json& sp = spacing->value;
            if (sp == "t") s.by = sample_spec::kind::count_t;
            else if (sp == "arc_length") s.by = sample_spec::kind::count_arc_length;
            else fail(spacing->name, "expected \"t\" or \"arc_length\", got " + describe(sp));
        }
    } else {
        if (spacing) fail(spacing->name, std::string("only used with ") + (spacing->flag ? "--count" : "'count'"));
        s.tolerance = finite_number(tolerance->value, tolerance->name);
        if (!(s.tolerance > 0)) fail(tolerance->name, "expected a distance > 0, got " + describe(tolerance->value));
        // Below what the coordinates resolve, tessellation would subdivide
        // without end (resolution.hpp): say the smallest meaningful value.
        double largest = 0;
        for (const double x : s.curve.coords) largest = std::max(largest, std::abs(x));
        if (const std::string why = tolerance_floor_problem(s.tolerance, largest); !why.empty())
            fail(tolerance->name, why);
        s.by = sample_spec::kind::tolerance;
    }
    return s;
}

}  // namespace crspline::cli
