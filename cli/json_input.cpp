// crspline command line: input reading, JSON parsing with positions, and
// validation of the JSON contract. See json_input.hpp.
#include "json_input.hpp"

#include <crspline/dispatch.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <iterator>
#include <utility>

namespace crspline::cli {

using nlohmann::json;

// --- reading -------------------------------------------------------------------

input_text read_input(const std::string& path) {
    input_text in;
    if (path.empty() || path == "-") {
        // stdin: read everything, bytes as they are.
        in.name = "<stdin>";
        std::array<char, 1 << 16> buf;
        std::size_t got;
        while ((got = std::fread(buf.data(), 1, buf.size(), stdin)) > 0) in.text.append(buf.data(), got);
        if (std::ferror(stdin)) throw input_error(in.name + ": cannot read: " + std::strerror(errno));
        return in;
    }
    in.name = path;
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) throw input_error(path + ": cannot open: " + std::strerror(errno));
    std::array<char, 1 << 16> buf;
    std::size_t got;
    while ((got = std::fread(buf.data(), 1, buf.size(), f)) > 0) in.text.append(buf.data(), got);
    const bool failed = std::ferror(f) != 0;
    const int err = errno;  // a directory opens but fails to read (EISDIR)
    std::fclose(f);
    if (failed) throw input_error(path + ": cannot read: " + std::strerror(err));
    return in;
}

// --- parsing -------------------------------------------------------------------

namespace {

// Builds the document like nlohmann's own DOM parser, but knows at every
// moment the path of the value being read ("points[3][1]"), so that a number
// too large for a double is reported by its field, and rejects duplicate keys
// (nlohmann would silently keep the last one).
class path_tracking_parser final : public nlohmann::json_sax<json> {
public:
    explicit path_tracking_parser(const input_text& in, bool fast_points = false)
        : in_(in), fast_enabled_(fast_points) {}

    json root;
    std::string error;            // set when parsing stopped
    std::optional<point_set> flat;  // the top-level "points", read flat

    bool null() override { return leave_fast() && add(json(nullptr)); }
    bool boolean(bool v) override { return leave_fast() && add(json(v)); }
    bool number_integer(number_integer_t v) override { return number(double(v)) || add(json(v)); }
    bool number_unsigned(number_unsigned_t v) override { return number(double(v)) || add(json(v)); }
    bool number_float(number_float_t v, const string_t&) override { return number(v) || add(json(v)); }
    bool string(string_t& v) override { return leave_fast() && add(json(std::move(v))); }
    bool binary(binary_t& v) override { return leave_fast() && add(json::binary(std::move(v))); }

    bool start_object(std::size_t) override { return leave_fast() && open(json::object()); }
    bool key(string_t& k) override {
        frame& f = stack_.back();
        if (f.value->contains(k)) {
            error = prefix(path_of_parent()) + "duplicate field '" + k + "'";
            return false;
        }
        f.key = k;
        // The top-level "points": read flat if it turns out well-formed.
        if (fast_enabled_ && stack_.size() == 1 && k == "points") fast_ = fast::armed;
        return true;
    }
    bool end_object() override { return leave_fast() && close(); }
    bool start_array(std::size_t) override {
        if (fast_ == fast::armed) {
            fast_ = fast::on;
            fast_depth_ = 1;
            flat.emplace();
            place(json::array());  // a placeholder: "points" is present
            return true;
        }
        if (fast_ == fast::on && fast_depth_ == 1) {
            fast_depth_ = 2;
            fast_count_ = 0;
            return true;
        }
        return leave_fast() && open(json::array());
    }
    bool end_array() override {
        if (fast_ == fast::on) {
            if (fast_depth_ == 1) {  // the end of "points": all of it was well-formed
                fast_ = fast::off;
                return true;
            }
            const bool first = fast_points_ == 0;
            if (fast_count_ > 0 && (first || fast_count_ == flat->dimension)) {
                if (first) flat->dimension = fast_count_;
                ++fast_points_;
                fast_depth_ = 1;
                return true;
            }
            fallback();
        }
        return close();
    }

    bool parse_error(std::size_t position, const std::string& last_token,
                     const nlohmann::detail::exception& ex) override {
        if (ex.id == 406) {
            // "number overflow parsing '1e999'": a literal beyond the double range.
            const std::string at = fast_ != fast::on ? path_of_next()
                                   : fast_depth_ == 1 ? "points[" + std::to_string(fast_points_) + "]"
                                   : "points[" + std::to_string(fast_points_) + "][" + std::to_string(fast_count_) + "]";
            error = prefix(at) + "expected a finite number, got " + last_token;
            return false;
        }
        error = in_.name + ": " + line_column(position) + ": " + strip_prefix(ex.what());
        return false;
    }

private:
    struct frame {
        json* value;
        std::string key;  // objects: the key of the value being read
    };
    const input_text& in_;
    std::vector<frame> stack_;

    // Fast path: armed after the top-level key "points", on inside its array
    // (depth 1: between points, depth 2: inside one point).
    enum class fast { off, armed, on };
    bool fast_enabled_ = false;
    fast fast_ = fast::off;
    int fast_depth_ = 0;
    std::size_t fast_count_ = 0;   // coordinates read in the current point
    std::size_t fast_points_ = 0;  // points completed

    // A number on the fast path; false when it is not (the caller adds it).
    bool number(double v) {
        if (fast_ == fast::on && fast_depth_ == 2 && fast_count_ < max_runtime_dimension) {
            flat->coords.push_back(v);
            ++fast_count_;
            return true;
        }
        leave_fast();
        return false;
    }

    // Anything but a number inside a point ends the fast path.
    bool leave_fast() {
        if (fast_ == fast::armed) fast_ = fast::off;  // "points" is not an array
        if (fast_ == fast::on) fallback();
        return true;
    }

    // Rebuilds the tree for what the fast path has read so far, so that the
    // rest of "points" goes into the tree and validation sees all of it.
    void fallback() {
        const std::size_t d = flat->dimension;
        json outer = json::array();
        for (std::size_t i = 0; i < fast_points_; ++i) {
            json p = json::array();
            for (std::size_t k = 0; k < d; ++k) p.push_back(flat->coords[i * d + k]);
            outer.push_back(std::move(p));
        }
        json* o = &(root["points"] = std::move(outer));
        stack_.push_back({o, {}});
        if (fast_depth_ == 2) {
            json p = json::array();
            for (std::size_t k = fast_points_ * d; k < flat->coords.size(); ++k) p.push_back(flat->coords[k]);
            o->push_back(std::move(p));
            stack_.push_back({&o->back(), {}});
        }
        flat.reset();
        fast_ = fast::off;
    }

    // The value just read goes into the innermost container, or is the root.
    json* place(json&& v) {
        if (stack_.empty()) {
            root = std::move(v);
            return &root;
        }
        frame& f = stack_.back();
        if (f.value->is_array()) {
            f.value->push_back(std::move(v));
            return &f.value->back();
        }
        return &((*f.value)[f.key] = std::move(v));
    }
    bool add(json&& v) {
        place(std::move(v));
        return true;
    }
    bool open(json&& container) {
        json* p = place(std::move(container));
        stack_.push_back({p, {}});
        return true;
    }
    bool close() {
        stack_.pop_back();
        return true;
    }

    // Path of the value being read now ("points[3][1]"), or of the innermost
    // container itself. A container below the innermost one was the last
    // value added to its parent, at index size - 1.
    std::string path(bool include_next) const {
        std::string p;
        const std::size_t n = stack_.size(), upto = include_next ? n : (n == 0 ? 0 : n - 1);
        for (std::size_t i = 0; i < upto; ++i) {
            const frame& f = stack_[i];
            if (f.value->is_array()) p += "[" + std::to_string(i + 1 == n ? f.value->size() : f.value->size() - 1) + "]";
            else p += (p.empty() ? "" : ".") + f.key;
        }
        return p;
    }
    std::string path_of_next() const { return path(true); }
    std::string path_of_parent() const { return path(false); }
    std::string prefix(const std::string& path) const { return (path.empty() ? in_.name : path) + ": "; }

    // nlohmann counts the end of input as one character read; the offending
    // character is the last one read, at byte index position - 1.
    std::string line_column(std::size_t position) const {
        const std::size_t at = std::min(position == 0 ? 0 : position - 1, in_.text.size());
        const std::size_t line = 1 + std::size_t(std::count(in_.text.begin(), in_.text.begin() + std::ptrdiff_t(at), '\n'));
        const std::size_t nl = at == 0 ? std::string::npos : in_.text.rfind('\n', at - 1);
        const std::size_t column = nl == std::string::npos ? at + 1 : at - nl;
        return "line " + std::to_string(line) + ", column " + std::to_string(column);
    }

    // "[json.exception.parse_error.101] parse error at line 2, column 11: syntax
    // error ..." -> "syntax error ...": the position is given by ourselves.
    static std::string strip_prefix(std::string msg) {
        if (const auto c = msg.find("column "); c != std::string::npos)
            if (const auto colon = msg.find(": ", c); colon != std::string::npos) return msg.substr(colon + 2);
        if (const auto b = msg.find("] "); b != std::string::npos) return msg.substr(b + 2);
        return msg;
    }
};

}  // namespace

json parse_json(const input_text& in) {
    path_tracking_parser p(in);
    const bool ok = json::sax_parse(in.text, &p);
    if (!ok) throw input_error(p.error.empty() ? in.name + ": not valid JSON" : p.error);
    return std::move(p.root);
}

document parse_json_document(const input_text& in) {
    path_tracking_parser p(in, true);
    const bool ok = json::sax_parse(in.text, &p);
    if (!ok) throw input_error(p.error.empty() ? in.name + ": not valid JSON" : p.error);
    document d;
    d.root = std::move(p.root);
    if (d.root.is_object()) d.points = std::move(p.flat);
    return d;
}

// --- validation helpers ----------------------------------------------------------

std::string format_number(double x) {
    if (std::isnan(x)) return "nan";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    std::array<char, 64> buf;
    const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), x);
    return std::string(buf.data(), r.ptr);
}

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
void parse_tangents(const json& root, curve_spec& c) {
    for (const char* key : {"tension", "kb", "strict"})
        if (root.contains(key)) fail("tangents", std::string("given tangents take no '") + key + "'");
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

}  // namespace

curve_spec parse_curve(const document& doc, std::string_view command, std::initializer_list<std::string_view> extra) {
    const json& root = doc.root;
    if (!root.is_object()) throw input_error("expected a JSON object {\"points\": ...}, got " + describe(root));
    // Unknown fields first: a typo is the likeliest cause of any later error.
    check_fields(root, command, extra);
    curve_spec c;

    // points: N x D finite numbers, D in 1..4 and the same for every point.
    std::string points_name = "points";
    if (doc.points) {
        c.dimension = doc.points->dimension;
        c.coords = doc.points->coords;
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

    // end: "natural" | "reflect" | "closed" | {"start": E, "end": E}.
    if (root.contains("end")) {
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
    const std::size_t n = c.point_count(), needed = 2;  // closed too: a loop of two segments
    if (n < needed)
        fail(points_name, std::string(c.closed ? "a closed curve" : "a curve") + " needs at least " +
                           std::to_string(needed) + " points, got " + std::to_string(n));

    // alpha or grid (not both); default alpha 0.5.
    if (root.contains("alpha") && root.contains("grid")) fail("grid", "give alpha or grid, not both");
    if (root.contains("alpha")) {
        const double a = finite_number(root["alpha"], "alpha");
        if (!(a >= 0 && a <= 1)) fail("alpha", "must be in [0, 1], got " + format_number(a));
        c.alpha = a;
    }
    if (root.contains("grid")) {
        std::vector<double> g = finite_numbers(root["grid"], "grid");
        const std::size_t expected = c.closed ? n + 1 : n;
        if (g.size() != expected)
            fail("grid", "expected " + std::to_string(expected) + " values (" +
                             (c.closed ? "one per point plus one to close the curve" : "one per point") +
                             "), got " + std::to_string(g.size()));
        for (std::size_t i = 1; i < g.size(); ++i)
            if (!(g[i] > g[i - 1]))
                fail(index("grid", i), "must be greater than grid[" + std::to_string(i - 1) + "] = " +
                                           format_number(g[i - 1]) + ", got " + format_number(g[i]));
        c.grid = std::move(g);
    }

    // tension: tangents scaled by 1 - tension.
    if (root.contains("tension")) {
        c.tension = finite_number(root["tension"], "tension");
        if (!(c.tension >= 0 && c.tension <= 1)) fail("tension", "must be in [0, 1], got " + format_number(c.tension));
    }

    // kb: per-vertex Kochanek-Bartels values; a missing array means zeros.
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

    if (root.contains("strict")) {
        const json& s = root["strict"];
        if (!s.is_boolean()) fail("strict", "expected true or false, got " + describe(s));
        c.strict = s.get<bool>();
    }

    // tangents: [[dx/dt, ...] per point], or {"in": [...], "out": [...]} when
    // incoming and outgoing differ: a cubic Hermite curve with them.
    if (root.contains("tangents")) parse_tangents(root, c);
    return c;
}

// "accuracy": relative accuracy of arc lengths, in (0, 1); default 1e-12.
double parse_accuracy(const json& root) {
    if (!root.contains("accuracy")) return 1e-12;
    const double a = finite_number(root["accuracy"], "accuracy");
    if (!(a > 0 && a < 1)) fail("accuracy", "expected a relative accuracy in (0, 1), got " + describe(root["accuracy"]));
    return a;
}

eval_spec parse_eval(const document& doc) {
    const json& root = doc.root;
    eval_spec e;
    e.curve = parse_curve(doc, "eval", {"t", "s", "u", "arc_fraction", "knots", "derivatives", "accuracy"});
    // Where to evaluate: exactly one of t, s, u, arc_fraction.
    std::vector<std::string> given;
    for (const char* key : {"t", "s", "u", "arc_fraction"})
        if (root.contains(key)) given.emplace_back(key);
    if (given.size() > 1)
        throw input_error(root.contains("u") || root.contains("arc_fraction")
                              ? "give one of 't', 's', 'u', 'arc_fraction', got '" + given[0] + "' and '" + given[1] + "'"
                              : std::string("give 't' (parameter values) or 's' (arc lengths), not both"));
    if (root.contains("s") || root.contains("arc_fraction")) {
        (root.contains("s") ? e.s : e.arc_fraction) =
            finite_numbers(root.contains("s") ? root["s"] : root["arc_fraction"], root.contains("s") ? "s" : "arc_fraction");
        e.accuracy = parse_accuracy(root);
    } else if (root.contains("u")) {
        if (root.contains("accuracy")) fail("accuracy", "only used with 's' or 'arc_fraction' (arc lengths)");
        e.u = finite_numbers(root["u"], "u");
    } else if (!root.contains("t")) {
        throw input_error("missing field 't' (the parameter values to evaluate at) or 's' (arc lengths)");
    } else {
        if (root.contains("accuracy")) fail("accuracy", "only used with 's' (arc lengths)");
        e.t = finite_numbers(root["t"], "t");
    }
    if (root.contains("knots")) {
        if (!root["knots"].is_boolean()) fail("knots", "expected true or false, got " + describe(root["knots"]));
        e.knots = root["knots"].get<bool>();
    }
    if (!root.contains("derivatives")) {
        e.derivatives = {0};
        return e;
    }
    const json& d = array(root["derivatives"], "derivatives", "derivative orders");
    if (d.empty()) fail("derivatives", "expected at least one order (0, 1, 2 or 3), got []");
    for (std::size_t i = 0; i < d.size(); ++i) {
        const std::string at = index("derivatives", i);
        const double x = d[i].is_number() ? d[i].get<double>() : -1.0;
        if (!(x == 0 || x == 1 || x == 2 || x == 3)) fail(at, "expected 0, 1, 2 or 3, got " + describe(d[i]));
        const int order = int(x);
        const auto seen = std::find(e.derivatives.begin(), e.derivatives.end(), order);
        if (seen != e.derivatives.end())
            fail(at, "order " + std::to_string(order) + " is already requested by " +
                         index("derivatives", std::size_t(seen - e.derivatives.begin())));
        e.derivatives.push_back(order);
    }
    return e;
}

bezier_spec parse_bezier(const document& doc) { return {parse_curve(doc, "bezier", {})}; }

curve_spec parse_analyze(const document& doc) { return parse_curve(doc, "analyze", {"summary", "search"}); }

length_spec parse_length(const document& doc) {
    const json& root = doc.root;
    length_spec l;
    l.curve = parse_curve(doc, "length", {"accuracy"});
    l.accuracy = parse_accuracy(root);
    return l;
}

sample_spec parse_sample(const document& doc) {
    const json& root = doc.root;
    sample_spec s;
    s.curve = parse_curve(doc, "sample", {"count", "spacing", "tolerance", "accuracy"});
    s.accuracy = parse_accuracy(root);
    const bool by_count = root.contains("count"), by_tolerance = root.contains("tolerance");
    if (by_count == by_tolerance)
        throw input_error("give 'count' (number of points) or 'tolerance' (largest distance to the curve), "
                          "exactly one of them");
    if (by_count) {
        const json& c = root["count"];
        const double n = c.is_number() ? c.get<double>() : -1.0;
        if (!(n >= 2 && n <= 1e9 && n == std::floor(n))) fail("count", "expected an integer >= 2, got " + describe(c));
        s.count = std::size_t(n);
        s.by = sample_spec::kind::count_t;
        if (root.contains("spacing")) {
            const json& sp = root["spacing"];
            if (sp == "t") s.by = sample_spec::kind::count_t;
            else if (sp == "arc_length") s.by = sample_spec::kind::count_arc_length;
            else fail("spacing", "expected \"t\" or \"arc_length\", got " + describe(sp));
        }
    } else {
        if (root.contains("spacing")) fail("spacing", "only used with 'count'");
        s.tolerance = finite_number(root["tolerance"], "tolerance");
        if (!(s.tolerance > 0)) fail("tolerance", "expected a distance > 0, got " + describe(root["tolerance"]));
        s.by = sample_spec::kind::tolerance;
    }
    return s;
}

}  // namespace crspline::cli
