// crspline command line: the input contract. The JSON fields of a document
// and the command-line flags become one curve description (curve_spec) and
// the work of a subcommand; every problem is reported by the field's JSON
// path or the flag's name. See json_input.hpp.
// The readers of single fields are in json_fields.cpp.
#include "json_input.hpp"

#include <crspline/dispatch.hpp>
#include <crspline/resolution.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

#include "csv_input.hpp"
#include "json_fields.hpp"
#include "options.hpp"

namespace crspline::cli {

using nlohmann::json;

std::string describe_json(const json& v) {
    if (v.is_number()) return format_number(v.get<double>());
    std::string s = v.dump(-1, ' ', false, json::error_handler_t::replace);
    if (s.size() > 40) s = s.substr(0, 37) + "...";
    return s;
}

std::string json_index(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

using namespace json_fields;

std::string point_location(const curve_spec& c, std::size_t i) {
    if (i < c.lines.size()) return "line " + std::to_string(c.lines[i]) + " (point " + std::to_string(i + 1) + ")";
    return json_index(c.points_path, i);
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
    // A Kochanek-Bartels null reaches the core as NaN (parse_kb_values): say
    // where null may stand.
    std::string what = e.what();
    if (e.field().rfind("kb.", 0) == 0 && e.value() == "nan")
        what += " (null is allowed only at the two end vertices of an open curve)";
    // A field a flag set: the flag, then the core's words.
    for (const auto& [field, flag] : c.flags)
        if (field == e.field()) return flag + ": " + what;
    return file + what;
}

namespace {

curve_spec read_curve(const document& doc, std::string_view command, std::initializer_list<std::string_view> extra) {
    const json& root = doc.root;
    const cli_options* f = doc.flags;
    if (!root.is_object()) throw input_error("expected a JSON object {\"points\": ...}, got " + describe_json(root));
    // Unknown fields first: a typo is the likeliest cause of any later error.
    check_fields(root, command, extra);
    curve_spec c;
    c.file = doc.file;
    const auto by_flag = [&c](const char* field, const std::string& flag) { c.flags.emplace_back(field, flag); };

    // points: N lists of the same number of numbers (how many, and their
    // values, are the core's to judge).
    if (doc.points) {
        c.dimension = doc.points->dimension;
        c.points = doc.points->coords;
        c.lines = doc.points->lines;
        c.points_path = doc.points->path;
    } else if (!root.contains("points")) {
        throw input_error("missing field 'points'");
    }
    static const json no_points = json::array();  // flat points were read already
    const json& pts = doc.points ? no_points : array(root["points"], "points", "points");
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const std::string at = json_index("points", i);
        const json& p = array(pts[i], at, "coordinates");
        if (i > 0 && p.size() != c.dimension)
            fail(at, "expected " + std::to_string(c.dimension) + " coordinates like points[0], got " +
                         std::to_string(p.size()));
        c.dimension = p.size();
        for (std::size_t k = 0; k < p.size(); ++k) c.points.push_back(number(p[k], json_index(at, k)));
    }
    // No points at all: no dimension either; any will do for the core to
    // say that two points are needed.
    if (pts.empty() && c.points.empty()) c.dimension = 1;

    // The ends: --closed, --start, --end, else the file's "closed", "start"
    // and "end" (read_ends). A flag for one end leaves the other end as the
    // JSON says (an open curve).
    if (f && f->closed && (!f->start.empty() || !f->end.empty()))
        throw input_error("--closed: a closed curve has no end conditions (--start, --end)");
    // From here on the core judges the values (an end's name too): its
    // spec_error is rendered with the file, the point or the flag.
    try {
        if (f && f->closed) {
            c.closed = true;
        } else {
            read_ends(root, c);
        }
        if (f && (!f->start.empty() || !f->end.empty())) {
            c.closed = false;
            if (!f->start.empty()) {
                by_flag("start", "--start");
                c.start = parse_end(end_value("--start", f->start), "--start", "start");
            }
            if (!f->end.empty()) {
                by_flag("end", "--end");
                c.end = parse_end(end_value("--end", f->end), "--end", "end");
            }
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
        const std::size_t n = c.point_count();

        // alpha or grid (the core: not both; default alpha 0.5). A flag
        // overrides the JSON: --alpha (or a preset) replaces "alpha" and "grid",
        // --grid both.
        const std::optional<double> flag_alpha = f ? alpha_flag(*f) : std::nullopt;
        if (f && !f->grid.empty()) {
            if (any_alpha_flag(*f) && f->command != "plot")
                throw input_error("--grid: give --grid or an alpha (--alpha, --uniform, --centripetal, --chordal), not both");
            c.grid = numbers(number_list("--grid", f->grid), "--grid");
            by_flag("grid", "--grid");
        } else if (flag_alpha) {
            c.alpha = flag_alpha;
            by_flag("alpha", f->alpha.empty() ? "--" + std::string(f->uniform ? "uniform" : f->chordal ? "chordal" : "centripetal") : "--alpha");
        } else {
            if (root.contains("alpha")) c.alpha = number(root["alpha"], "alpha");
            if (root.contains("grid")) c.grid = numbers(root["grid"], "grid");
        }

        // tension: tangents scaled by 1 - tension.
        if (const auto t = field(root, "tension", f, &cli_options::tension, "--tension")) {
            c.tension = number(t->value, t->name);
            if (t->flag) by_flag("tension", t->name);
        }

        // kb: per-vertex Kochanek-Bartels values; a missing array means zeros;
        // --kb-tension and the others replace one array each.
        if (root.contains("kb")) {
            const json& kb = root["kb"];
            if (!kb.is_object())
                fail("kb", "expected {\"tension\": [...], \"continuity\": [...], \"bias\": [...]}, got " + describe_json(kb));
            for (const auto& [key, value] : kb.items()) {
                const std::string path = "kb." + key;
                if (key == "tension") c.kb.tension = parse_kb_values(value, path, n, c.closed);
                else if (key == "continuity") c.kb.continuity = parse_kb_values(value, path, n, c.closed);
                else if (key == "bias") c.kb.bias = parse_kb_values(value, path, n, c.closed);
                else fail("kb", "unknown field '" + key + "' (expected \"tension\", \"continuity\", \"bias\")");
            }
        }
        if (f) {
            const std::tuple<const std::string*, const char*, const char*, std::vector<double>*> kb_flags[] = {
                {&f->kb_tension, "--kb-tension", "kb.tension", &c.kb.tension},
                {&f->kb_continuity, "--kb-continuity", "kb.continuity", &c.kb.continuity},
                {&f->kb_bias, "--kb-bias", "kb.bias", &c.kb.bias}};
            for (const auto& [text, flag, field_name, values] : kb_flags)
                if (!text->empty()) {
                    *values = parse_kb_values(number_list(flag, *text, true), flag, n, c.closed);
                    by_flag(field_name, flag);
                }
        }

        if (f && f->strict) {
            c.strict = true;
        } else if (root.contains("strict")) {
            const json& s = root["strict"];
            if (!s.is_boolean()) fail("strict", "expected true or false, got " + describe_json(s));
            c.strict = s.get<bool>();
        }

        // The values: the core's rules, the core's words.
        crspline::validate(c.core());
    } catch (const crspline::spec_error& e) {
        throw input_error(describe_spec_error(e, c));
    }

    // tangents: [[dx/dt, ...] per point], or {"in": [...], "out": [...]} when
    // incoming and outgoing differ: a cubic Hermite curve with them.
    if (root.contains("tangents")) parse_tangents(root, f, c);
    return c;
}

// "accuracy" / --accuracy: relative accuracy of arc lengths, in (0, 1) and
// not below what doubles resolve; default 1e-12.
double parse_accuracy(const document& doc) {
    const auto a = field(doc.root, "accuracy", doc.flags, &cli_options::accuracy, "--accuracy");
    if (!a) return 1e-12;
    const double x = finite_number(a->value, a->name);
    if (!(x > 0 && x < 1)) fail(a->name, "expected a relative accuracy in (0, 1), got " + describe_json(a->value));
    if (const std::string why = accuracy_floor_problem(x); !why.empty()) fail(a->name, why);
    return x;
}

// The name of a flag when the input has no JSON fields (CSV), of the field
// otherwise, for a message about something missing.
std::string missing(const document& doc, const char* key) {
    return doc.has_fields ? "'" + std::string(key) + "'" : "--" + std::string(key);
}

eval_spec read_eval(const document& doc) {
    const json& root = doc.root;
    const cli_options* f = doc.flags;
    eval_spec e;
    e.curve = read_curve(doc, "eval", {"t", "s", "u", "arc_fraction", "knots", "derivatives", "accuracy"});
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
        if (!root["knots"].is_boolean()) fail("knots", "expected true or false, got " + describe_json(root["knots"]));
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
        const std::string at = json_index(name, i);
        const double x = d[i].is_number() ? d[i].get<double>() : -1.0;
        if (!(x == 0 || x == 1 || x == 2 || x == 3)) fail(at, "expected 0, 1, 2 or 3, got " + describe_json(d[i]));
        const int order = int(x);
        const auto seen = std::find(e.derivatives.begin(), e.derivatives.end(), order);
        if (seen != e.derivatives.end())
            fail(at, "order " + std::to_string(order) + " is already requested by " +
                         json_index(name, std::size_t(seen - e.derivatives.begin())));
        e.derivatives.push_back(order);
    }
    return e;
}

length_spec read_length(const document& doc) {
    length_spec l;
    l.curve = read_curve(doc, "length", {"accuracy"});
    l.accuracy = parse_accuracy(doc);
    return l;
}

sample_spec read_sample(const document& doc) {
    const json& root = doc.root;
    const cli_options* f = doc.flags;
    sample_spec s;
    s.curve = read_curve(doc, "sample", {"count", "spacing", "tolerance", "accuracy"});
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
        if (!(n >= 2 && n <= 1e9 && n == std::floor(n))) fail(count->name, "expected an integer >= 2, got " + describe_json(c));
        s.count = std::size_t(n);
        s.by = sample_spec::kind::count_t;
        if (spacing) {
            const json& sp = spacing->value;
            if (sp == "t") s.by = sample_spec::kind::count_t;
            else if (sp == "arc_length") s.by = sample_spec::kind::count_arc_length;
            else fail(spacing->name, "expected \"t\" or \"arc_length\", got " + describe_json(sp));
        }
    } else {
        if (spacing) fail(spacing->name, std::string("only used with ") + (spacing->flag ? "--count" : "'count'"));
        s.tolerance = finite_number(tolerance->value, tolerance->name);
        if (!(s.tolerance > 0)) fail(tolerance->name, "expected a distance > 0, got " + describe_json(tolerance->value));
        // Below what the coordinates resolve, tessellation would subdivide
        // without end (resolution.hpp): say the smallest meaningful value.
        double largest = 0;
        for (const double x : s.curve.points) largest = std::max(largest, std::abs(x));
        if (const std::string why = tolerance_floor_problem(s.tolerance, largest); !why.empty())
            fail(tolerance->name, why);
        s.by = sample_spec::kind::tolerance;
    }
    return s;
}

// A message about the input's fields starts with the file's name, as a
// message about its values (describe_spec_error) and a list file's do: a
// shape error ("points[1][1]: expected a finite number") or an unknown field
// in curve.json reads "curve.json: points[1][1]: ...". Not for stdin (the
// field's path is the whole address there, as it always was) nor for a
// flag's message, which names the flag, nor for a CSV file, whose only
// fields are flags (its own errors name its lines already).
template <class F>
auto in_file(const document& doc, F&& read) -> decltype(read()) {
    try {
        return read();
    } catch (const input_error& e) {
        const std::string what = e.what();
        if (!doc.has_fields || doc.file.empty() || doc.file == "<stdin>" || what.rfind("--", 0) == 0 ||
            what.rfind(doc.file + ": ", 0) == 0)
            throw;
        throw input_error(doc.file + ": " + what);
    }
}

}  // namespace

curve_spec parse_curve(const document& doc, std::string_view command, std::initializer_list<std::string_view> extra) {
    return in_file(doc, [&] { return read_curve(doc, command, extra); });
}
eval_spec parse_eval(const document& doc) { return in_file(doc, [&] { return read_eval(doc); }); }
length_spec parse_length(const document& doc) { return in_file(doc, [&] { return read_length(doc); }); }
sample_spec parse_sample(const document& doc) { return in_file(doc, [&] { return read_sample(doc); }); }
bezier_spec parse_bezier(const document& doc) {
    return in_file(doc, [&] { return bezier_spec{read_curve(doc, "bezier", {})}; });
}
curve_spec parse_analyze(const document& doc) {
    return in_file(doc, [&] { return read_curve(doc, "analyze", {"summary", "search"}); });
}

}  // namespace crspline::cli
