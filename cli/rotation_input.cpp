// crspline command line: reading rotation and pose curve files (see
// rotation_input.hpp for the format).
#include "rotation_input.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "json_input.hpp"
#include "options.hpp"

namespace crspline::cli {

using nlohmann::json;

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) { throw input_error(path + ": " + what); }

double finite(const json& v, const std::string& path) {
    if (!v.is_number() || !std::isfinite(v.get<double>())) fail(path, "expected a finite number, got " + describe_json(v));
    return v.get<double>();
}

const json& list(const json& v, const std::string& path, const char* of_what) {
    if (!v.is_array()) fail(path, std::string("expected an array of ") + of_what + ", got " + describe_json(v));
    return v;
}

// An array of n finite numbers.
template <std::size_t N>
std::array<double, N> row(const json& v, const std::string& path) {
    if (!v.is_array() || v.size() != N)
        fail(path, "expected an array of " + std::to_string(N) + " numbers, got " + describe_json(v));
    std::array<double, N> r{};
    for (std::size_t k = 0; k < N; ++k) r[k] = finite(v[k], json_index(path, k));
    return r;
}

bool boolean(const json& root, const char* key) {
    if (!root.contains(key)) return false;
    if (!root[key].is_boolean()) fail(key, "expected true or false, got " + describe_json(root[key]));
    return root[key].get<bool>();
}

rotation::frame parse_frame(const json& v, const std::string& path) {
    if (v == "world") return rotation::frame::world;
    if (v == "body") return rotation::frame::body;
    fail(path, "expected \"world\" or \"body\", got " + describe_json(v));
}

// degrees: false (radians) by default.
double angle_unit(const json& obj, const std::string& path) {
    if (!obj.contains("degrees")) return 1.0;
    if (!obj["degrees"].is_boolean()) fail(path + ".degrees", "expected true or false, got " + describe_json(obj["degrees"]));
    return obj["degrees"].get<bool>() ? std::numbers::pi / 180 : 1.0;
}

// The keys from "rotations", with the path of their array for messages.
void read_keys(const json& r, rotation_file& f) {
    using Q = rotation::quaternion<double>;
    if (!r.is_object())
        fail("rotations", "expected an object with one of \"quaternions\", \"rotation_vectors\", \"axis_angle\", "
                          "\"euler\", \"matrices\", got " + describe_json(r));
    static const char* const forms[] = {"quaternions", "rotation_vectors", "axis_angle", "euler", "matrices"};
    std::vector<std::string> found;
    for (const auto& item : r.items()) {
        const std::string& k = item.key();
        if (std::find_if(std::begin(forms), std::end(forms), [&](const char* s) { return k == s; }) != std::end(forms))
            found.push_back(k);
        else if (k != "degrees")
            fail("rotations", "unknown field '" + k + "' (expected one of quaternions, rotation_vectors, axis_angle, "
                              "euler, matrices)");
    }
    if (found.size() != 1)
        fail("rotations", found.empty() ? std::string("expected one of \"quaternions\", \"rotation_vectors\", "
                                                      "\"axis_angle\", \"euler\", \"matrices\"")
                                        : "give one form of rotations, got '" + found[0] + "' and '" + found[1] + "'");
    const std::string form = found[0];
    if (r.contains("degrees") && form != "rotation_vectors" && form != "axis_angle")
        fail("rotations.degrees", "only used with rotation_vectors or axis_angle (euler has its own)");
    const std::string path = "rotations." + form;
    f.keys_path = path;
    if (form == "euler") {
        const json& e = r[form];
        if (!e.is_object()) fail(path, "expected {\"convention\": \"xyz\", \"angles\": [[a, b, c], ...], \"degrees\": "
                                       "false}, got " + describe_json(e));
        for (const auto& item : e.items())
            if (item.key() != "convention" && item.key() != "angles" && item.key() != "degrees")
                fail(path, "unknown field '" + item.key() + "' (expected convention, angles, degrees)");
        if (!e.contains("convention")) fail(path, "missing field 'convention' (e.g. \"xyz\" extrinsic, \"ZYX\" intrinsic)");
        if (!e.contains("angles")) fail(path, "missing field 'angles' (an array of [a, b, c])");
        if (!e["convention"].is_string()) fail(path + ".convention", "expected a string like \"xyz\", got " + describe_json(e["convention"]));
        rotation::euler_convention c;
        try {
            c = rotation::euler_convention::parse(e["convention"].get<std::string>());
        } catch (const crspline::invalid_input& x) {
            fail(path + ".convention", x.what());
        }
        const double unit = angle_unit(e, path);
        const json& a = list(e["angles"], path + ".angles", "[a, b, c] angles");
        f.keys_path = path + ".angles";
        for (std::size_t i = 0; i < a.size(); ++i) {
            std::array<double, 3> x = row<3>(a[i], json_index(path + ".angles", i));
            for (double& v : x) v *= unit;
            f.keys.push_back(rotation::from_euler(c, x));
        }
        return;
    }
    const json& a = list(r[form], path, form == "quaternions" ? "[w, x, y, z] quaternions"
                                        : form == "rotation_vectors" ? "[x, y, z] rotation vectors"
                                        : form == "axis_angle" ? "[ax, ay, az, angle] rows"
                                                               : "3x3 matrices");
    const double unit = angle_unit(r, "rotations");
    for (std::size_t i = 0; i < a.size(); ++i) {
        const std::string p = json_index(path, i);
        if (form == "quaternions") {
            const auto q = row<4>(a[i], p);
            const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            // The file's check, stricter than the native classes (which normalize any
            // nonzero key, as SciPy does): a norm of 0.9 in a file is more likely a
            // wrong field than rounding. Said with the field's path.
            if (!(std::abs(n - 1) <= 1e-6))
                fail(p, "not a unit quaternion (norm " + format_number(n) + ", allowed 1 +- 1e-6; order [w, x, y, z])");
            f.keys.push_back(Q{q[0], q[1], q[2], q[3]});
        } else if (form == "rotation_vectors") {
            const auto v = row<3>(a[i], p);
            f.keys.push_back(rotation::from_rotation_vector(vec<3, double>{{v[0] * unit, v[1] * unit, v[2] * unit}}));
        } else if (form == "axis_angle") {
            const auto v = row<4>(a[i], p);
            if (!(v[0] != 0 || v[1] != 0 || v[2] != 0)) fail(p, "the axis is zero");
            f.keys.push_back(rotation::from_axis_angle(vec<3, double>{{v[0], v[1], v[2]}}, v[3] * unit));
        } else {
            if (!a[i].is_array() || a[i].size() != 3) fail(p, "expected a 3x3 matrix (3 rows of 3 numbers), got " + describe_json(a[i]));
            rotation::matrix3<double> m{};
            for (std::size_t k = 0; k < 3; ++k) m[k] = row<3>(a[i][k], json_index(p, k));
            try {
                f.keys.push_back(rotation::from_matrix(m));
            } catch (const crspline::invalid_input& x) {
                fail(p, x.what());
            }
        }
    }
}

// An end: "natural", "natural_splines", "scipy" or {"angular_velocity": [x, y, z], "frame": "world"}.
void read_end(const json& root, const char* key, rotation_file& f) {
    if (!root.contains(key)) return;
    const json& v = root[key];
    const bool c2 = f.kind == "c2";
    if (f.kind != "catmull_rom" && f.kind != "kochanek_bartels" && !c2)
        fail(key, "only used with kind catmull_rom, kochanek_bartels or c2 (kind is " + f.kind + ")");
    if (f.closed) fail(key, "not used with \"closed\": true");
    const bool start = std::string(key) == "start";
    if (v.is_object()) {
        for (const auto& item : v.items())
            if (item.key() != "angular_velocity" && item.key() != "frame")
                fail(key, "unknown field '" + item.key() + "' (expected angular_velocity, frame)");
        if (!v.contains("angular_velocity")) fail(key, "missing field 'angular_velocity' ([x, y, z], rad per unit t)");
        const auto w = row<3>(v["angular_velocity"], std::string(key) + ".angular_velocity");
        const rotation::frame fr = v.contains("frame") ? parse_frame(v["frame"], std::string(key) + ".frame") : rotation::frame::world;
        const vec<3, double> omega{{w[0], w[1], w[2]}};
        if (c2) (start ? f.start_c2 : f.end_c2) = rotation::c2_end<double>::velocity(omega, fr);
        else (start ? f.start_cr : f.end_cr) = rotation::rotation_end<double>::velocity(omega, fr);
        return;
    }
    if (c2 && v == "scipy") return;
    if (v == "natural") {
        if (c2) (start ? f.start_c2 : f.end_c2) = rotation::c2_end<double>::natural();
        return;
    }
    if (!c2 && v == "natural_splines") {
        (start ? f.start_cr : f.end_cr) = rotation::rotation_end<double>::natural_splines();
        return;
    }
    fail(key, std::string("expected ") + (c2 ? "\"scipy\", \"natural\"" : "\"natural\", \"natural_splines\"") +
                  " or {\"angular_velocity\": [x, y, z], \"frame\": \"world\"}, got " + describe_json(v));
}

// Comma-separated numbers of a flag ("--t 0,0.5,1").
std::vector<double> flag_numbers(const std::string& name, const std::string& text) {
    std::vector<double> out;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        std::size_t used = 0;
        double x = 0;
        try {
            x = std::stod(item, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == 0 || used != item.size() || !std::isfinite(x))
            throw input_error(name + ": expected a list of finite numbers, got \"" + text + "\"");
        out.push_back(x);
    }
    return out;
}

}  // namespace

bool is_rotation_document(const document& doc) {
    return doc.has_fields && doc.root.is_object() && doc.root.contains("rotations");
}

namespace {

rotation_file read_rotation_file(const document& doc, const std::string& command) {
    const json& root = doc.root;
    const cli_options* fl = doc.flags;
    rotation_file f;
    // 0. Flags that describe a point curve have no meaning here: say so.
    if (fl) {
        const std::pair<bool, const char*> unused[] = {
            {!fl->alpha.empty() || fl->uniform || fl->centripetal || fl->chordal, "--alpha"},
            {!fl->grid.empty(), "--grid"}, {!fl->start.empty(), "--start"}, {!fl->end.empty(), "--end"},
            {fl->closed, "--closed"}, {fl->strict, "--strict"}, {!fl->tension.empty(), "--tension"},
            {!fl->s.empty(), "--s"}, {!fl->u.empty(), "--u"}, {!fl->arc_fraction.empty(), "--arc-fraction"},
            {!fl->tolerance.empty(), "--tolerance"}, {fl->knots, "--knots"}};
        for (const auto& [given, name] : unused)
            if (given) throw input_error(std::string(name) + ": not used with a rotation curve file (\"rotations\"); "
                                                             "write the field in the file");
    }
    // 1. Known fields only.
    static const char* const common[] = {"rotations", "points", "kind", "alpha", "grid", "closed", "start", "end",
                                         "tcb", "keep_signs", "strict", "frame", "derivatives", "knots"};
    for (const auto& item : root.items()) {
        const std::string& k = item.key();
        const bool known = std::find_if(std::begin(common), std::end(common), [&](const char* s) { return k == s; }) != std::end(common) ||
                           (command == "eval" && k == "t") || (command == "sample" && (k == "count" || k == "spacing"));
        if (!known)
            fail(k, "unknown field in a rotation curve file for " + command +
                        " (rotations, points, kind, alpha, grid, closed, start, end, tcb, keep_signs, strict, frame, "
                        "derivatives, knots, " + (command == "eval" ? "t)" : "count, spacing)"));
    }
    // 2. The keys, and a pose curve's positions.
    read_keys(root["rotations"], f);
    if (doc.points || root.contains("points")) {
        if (doc.points) {
            const point_set& p = *doc.points;
            if (p.dimension != 3) fail("points", "a pose curve needs 3-D points, got " + std::to_string(p.dimension) + "-D");
            for (std::size_t i = 0; i < p.size(); ++i)
                f.positions.push_back(vec<3, double>{{p.coords[3 * i], p.coords[3 * i + 1], p.coords[3 * i + 2]}});
        } else {
            const json& p = list(root["points"], "points", "[x, y, z] points");
            for (std::size_t i = 0; i < p.size(); ++i) {
                const auto x = row<3>(p[i], json_index("points", i));
                f.positions.push_back(vec<3, double>{{x[0], x[1], x[2]}});
            }
        }
        if (f.positions.size() != f.keys.size())
            fail("points", "a pose curve needs one rotation per point: " + std::to_string(f.positions.size()) +
                               " points, " + std::to_string(f.keys.size()) + " rotations in " + f.keys_path);
        if (f.positions.empty()) fail("points", "expected at least 2 points, got []");
        f.kind = "c2";
    }
    // 3. The class of curve and how it is built.
    if (root.contains("kind")) {
        const json& k = root["kind"];
        static const char* const kinds[] = {"catmull_rom", "kochanek_bartels", "slerp", "barry_goldman", "squad", "c2"};
        const bool ok = k.is_string() && std::find_if(std::begin(kinds), std::end(kinds), [&](const char* s) {
                                             return k.get<std::string>() == s;
                                         }) != std::end(kinds);
        if (!ok)
            fail("kind", "expected one of catmull_rom, kochanek_bartels, slerp, barry_goldman, squad, c2, got " + describe_json(k));
        f.kind = k.get<std::string>();
        if (f.pose() && f.kind != "c2" && f.kind != "catmull_rom")
            fail("kind", "a pose curve takes c2 or catmull_rom, got " + describe_json(k));
    }
    if (root.contains("alpha")) f.alpha = finite(root["alpha"], "alpha");
    if (root.contains("grid")) {
        const json& g = list(root["grid"], "grid", "numbers");
        std::vector<double> grid;
        for (std::size_t i = 0; i < g.size(); ++i) grid.push_back(finite(g[i], json_index("grid", i)));
        f.grid = std::move(grid);
    }
    if (f.alpha && f.grid) fail("grid", "give 'alpha' or 'grid', not both");
    f.closed = boolean(root, "closed");
    f.keep_signs = boolean(root, "keep_signs");
    f.strict = boolean(root, "strict");
    f.knots = boolean(root, "knots");
    if (f.pose() && (root.contains("keep_signs") || root.contains("strict")))
        fail(root.contains("keep_signs") ? "keep_signs" : "strict", "not used with a pose curve");
    if (f.pose() && (root.contains("start") || root.contains("end")))
        fail(root.contains("start") ? "start" : "end", "not used with a pose curve (its ends are natural)");
    read_end(root, "start", f);
    read_end(root, "end", f);
    if (root.contains("tcb")) {
        if (f.kind != "kochanek_bartels") fail("tcb", "only used with kind kochanek_bartels (kind is " + f.kind + ")");
        const json& v = list(root["tcb"], "tcb", "[tension, continuity, bias] values");
        if (!v.empty() && v[0].is_number()) {
            const auto x = row<3>(v, "tcb");
            f.tcb.push_back({x[0], x[1], x[2]});
        } else {
            for (std::size_t i = 0; i < v.size(); ++i) {
                const auto x = row<3>(v[i], json_index("tcb", i));
                f.tcb.push_back({x[0], x[1], x[2]});
            }
        }
    }
    if (root.contains("frame")) f.out_frame = parse_frame(root["frame"], "frame");
    // 4. What the command reads: derivatives, t or count and spacing.
    const int top = f.pose() ? 1 : 2;
    std::optional<std::pair<json, std::string>> d;
    if (fl && !fl->derivatives.empty()) {
        json arr = json::array();
        for (const double x : flag_numbers("--derivatives", fl->derivatives)) arr.push_back(x);
        d.emplace(arr, "--derivatives");
    } else if (root.contains("derivatives")) {
        d.emplace(root["derivatives"], "derivatives");
    }
    if (d) {
        const json& v = list(d->first, d->second, "derivative orders");
        if (v.empty()) fail(d->second, "expected at least one order, got []");
        f.derivatives.clear();
        for (std::size_t i = 0; i < v.size(); ++i) {
            const double x = v[i].is_number() ? v[i].get<double>() : -1.0;
            if (!(x == 0 || x == 1 || (x == 2 && top == 2)))
                fail(json_index(d->second, i), std::string(top == 2 ? "expected 0, 1 or 2" : "expected 0 or 1 (a pose curve gives position and "
                                                                                       "orientation, velocity and angular velocity)") +
                                           ", got " + describe_json(v[i]));
            if (std::find(f.derivatives.begin(), f.derivatives.end(), int(x)) != f.derivatives.end())
                fail(json_index(d->second, i), "order " + std::to_string(int(x)) + " is asked twice");
            f.derivatives.push_back(int(x));
        }
    }
    if (command == "eval") {
        if (fl && !fl->t.empty()) {
            f.t = flag_numbers("--t", fl->t);
            f.t_name = "--t";
        } else {
            if (!root.contains("t")) fail("t", "missing (the parameter values to evaluate at)");
            const json& v = list(root["t"], "t", "numbers");
            for (std::size_t i = 0; i < v.size(); ++i) f.t.push_back(finite(v[i], json_index("t", i)));
        }
    } else {
        json c;
        std::string cname = "count";
        if (fl && !fl->count.empty()) {
            const auto xs = flag_numbers("--count", fl->count);
            c = xs.size() == 1 ? json(xs[0]) : json(fl->count);
            cname = "--count";
        } else if (root.contains("count")) {
            c = root["count"];
        } else {
            fail("count", "missing (the number of samples)");
        }
        const double n = c.is_number() ? c.get<double>() : -1.0;
        if (!(n >= 2 && n <= 1e9 && n == std::floor(n))) fail(cname, "expected an integer >= 2, got " + describe_json(c));
        f.count = std::size_t(n);
        std::string sname = "spacing";
        json s;
        if (fl && !fl->spacing.empty()) {
            s = fl->spacing;
            sname = "--spacing";
        } else if (root.contains("spacing")) {
            s = root["spacing"];
        }
        if (!s.is_null()) {
            const bool ok = s == "t" || s == "angle" || (f.pose() && s == "arc_length");
            if (!ok) fail(sname, std::string("expected \"t\", \"angle\"") + (f.pose() ? " or \"arc_length\"" : "") + ", got " + describe_json(s));
            f.spacing = s.get<std::string>();
        }
    }
    return f;
}

}  // namespace

rotation_file parse_rotation_file(const document& doc, const std::string& command) {
    try {
        return read_rotation_file(doc, command);
    } catch (const input_error& e) {
        const std::string what = e.what();
        if (doc.file.empty() || doc.file == "<stdin>" || what.rfind("--", 0) == 0) throw;
        throw input_error(doc.file + ": " + what);
    }
}

}  // namespace crspline::cli
