// crspline fit: the fewest control points whose Catmull-Rom curve stays
// within a tolerance of dense or noisy points, both ways, proved
// (crspline/fit.hpp).
//
//   crspline fit --tolerance T [--mode subset|free] [--alpha A] [--tension X]
//                [--closed] [--start natural|reflect] [--end natural|reflect]
//                [--format json|csv|geojson] [--input-format F] [--columns C]
//                [--delimiter D] [--curve-column C] [-o OUT] [INPUT]
//
// Input: every format and many curves per file as the other commands read
// them (a curve object, a JSON list, GeoJSON, SVG path data, CSV blocks or
// a curve-id column); a curve object's "closed" / "end": "closed" and a
// GeoJSON ring make a closed fit. Output: json (default; the curve file in
// docs/spec.md's words, a list of {"id", "properties", ...curve} for many
// curves, the report in "properties"), csv (the control points; a first
// column "curve" for many curves), geojson (each curve's polyline within
// tolerance / 10 of it, with control_points, deviation, tolerance and mode as
// properties). Bad input exits with status 2 and one line.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <crspline/fit.hpp>
#include <crspline/tessellate.hpp>

#include "collection_input.hpp"
#include "json_parser.hpp"
#include "options.hpp"

namespace crspline::cli {

namespace {

using ojson = nlohmann::ordered_json;

struct fit_settings {
    double tolerance = 0;
    fit_mode mode = fit_mode::subset;
    std::optional<double> alpha;
    std::optional<double> tension;
    bool closed = false;
    std::string start = "natural", end = "natural";
    std::string format;
};

const char* usage =
    "usage: crspline fit --tolerance T [--mode subset|free] [--alpha A] [--tension X] [--closed] "
    "[--start natural|reflect] [--end natural|reflect] [--format json|csv|geojson] [--input-format F] "
    "[--columns C] [--delimiter D] [--curve-column C] [-o OUT] [INPUT]";

[[noreturn]] void fit_usage_error(const std::string& m) { throw input_error(m + " (" + usage + ")"); }

double fit_number_option(const std::string& name, const char* value) {
    if (!value) fit_usage_error(name + " needs a value");
    char* end = nullptr;
    const double v = std::strtod(value, &end);
    if (end == value || *end != '\0') fit_usage_error(name + ": expected a number, got '" + std::string(value) + "'");
    return v;
}

// The points of one curve document, flat, with their dimension.
point_set points_of(const document& d, const std::string& where) {
    if (d.points) return *d.points;
    const auto& root = d.root;
    if (!root.is_object() || !root.contains("points")) throw input_error(where + ": expected a curve with \"points\"");
    const auto& pts = root["points"];
    if (!pts.is_array()) throw input_error(where + "points: expected an array of points");
    point_set ps;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const auto& p = pts[i];
        const std::string at = where + "points[" + std::to_string(i) + "]";
        if (!p.is_array() || p.empty()) throw input_error(at + ": expected a point [x, y, ...]");
        if (ps.dimension == 0) ps.dimension = p.size();
        if (p.size() != ps.dimension)
            throw input_error(at + ": has " + std::to_string(p.size()) + " coordinates, expected " +
                              std::to_string(ps.dimension) + " like points[0]");
        for (std::size_t k = 0; k < p.size(); ++k) {
            if (!p[k].is_number()) throw input_error(at + "[" + std::to_string(k) + "]: expected a finite number");
            ps.coords.push_back(p[k].get<double>());
        }
    }
    return ps;
}

bool closed_of(const document& d, const fit_settings& s) {
    if (s.closed) return true;
    const auto& r = d.root;
    if (!r.is_object()) return false;
    if (r.contains("closed") && r["closed"].is_boolean()) return r["closed"].get<bool>();
    return r.contains("end") && r["end"].is_string() && r["end"].get<std::string>() == "closed";
}

// One curve's fit, as JSON pieces: the curve file object, the control
// points, the polyline for GeoJSON, and the report.
struct fitted {
    ojson curve;                             // the curve file object (docs/spec.md)
    std::vector<std::vector<double>> cps;    // control points
    std::vector<std::vector<double>> line;   // polyline within tolerance / 10
    ojson report;
    bool closed = false;
};

template <std::size_t D>
fitted fit_curve(const point_set& ps, bool closed, const fit_settings& s) {
    std::vector<vec<D>> pts(ps.size());
    for (std::size_t i = 0; i < pts.size(); ++i)
        for (std::size_t k = 0; k < D; ++k) pts[i][k] = ps.coords[i * D + k];
    fit_options<D> o;
    o.tolerance = s.tolerance;
    o.mode = s.mode;
    o.alpha = s.alpha;
    o.closed = closed;
    o.tension = s.tension.value_or(0.0);
    if (s.start == "reflect") o.start = end_condition<D>::reflect();
    if (s.end == "reflect") o.end = end_condition<D>::reflect();
    const fit_result<D> r = fit(std::span<const vec<D>>(pts), o);
    fitted f;
    f.closed = closed;
    ojson points = ojson::array();
    for (const auto& p : r.curve.points()) {
        std::vector<double> c(p.v.begin(), p.v.end());
        points.push_back(c);
        f.cps.push_back(std::move(c));
    }
    f.curve["points"] = std::move(points);
    f.curve["alpha"] = o.alpha.value_or(0.5);
    if (closed) {
        f.curve["closed"] = true;
    } else {
        f.curve["start"] = s.start;
        f.curve["end"] = s.end;
    }
    f.curve["tension"] = o.tension;
    const auto& kb = r.curve.options().kb.tension;
    if (!kb.empty()) {
        ojson t = ojson::array();
        for (double x : kb) t.push_back(x);
        f.curve["kb"] = {{"tension", std::move(t)}};
    }
    f.report = {{"control_points", r.count},
                {"input_points", pts.size()},
                {"deviation", r.deviation},
                {"tolerance", s.tolerance},
                {"mode", s.mode == fit_mode::free ? "free" : "subset"},
                {"tensioned", r.tensioned}};
    if (s.mode == fit_mode::subset) f.report["indices"] = r.indices;
    if (s.format == "geojson") {
        const auto pl = tessellate(r.curve, s.tolerance / 10);
        for (const auto& p : pl.points) f.line.emplace_back(p.v.begin(), p.v.end());
        if (closed && !f.line.empty()) f.line.back() = f.line.front();  // GeoJSON rings repeat the first position exactly
    }
    return f;
}

fitted fit_document(const document& d, const fit_settings& s, const std::string& where) {
    const point_set ps = points_of(d, where);
    const bool closed = closed_of(d, s);
    switch (ps.dimension) {
        case 1: return fit_curve<1>(ps, closed, s);
        case 2: return fit_curve<2>(ps, closed, s);
        case 3: return fit_curve<3>(ps, closed, s);
        case 4: return fit_curve<4>(ps, closed, s);
        default:
            throw input_error(where + "fit takes points of 1 to 4 coordinates, got " + std::to_string(ps.dimension));
    }
}

std::string csv_field(const std::string& v) {
    if (v.find_first_of(",\"\r\n") == std::string::npos) return v;
    std::string q = "\"";
    for (char c : v) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

int run_fit(int argc, char** argv) {
    fit_settings s;
    cli_options o;
    o.command = "fit";
    bool have_tolerance = false;
    std::string input;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const char* next = i + 1 < argc ? argv[i + 1] : nullptr;
        auto value = [&](const std::string& name) -> std::string {
            if (!next) fit_usage_error(name + " needs a value");
            ++i;
            return next;
        };
        if (a == "--help" || a == "-h") {
            std::cout << "crspline fit: the fewest control points whose Catmull-Rom curve stays within a tolerance\n"
                         "of the points, both ways, proved (docs/fit.md).\n"
                      << usage << "\n";
            return 0;
        } else if (a == "--tolerance") {
            s.tolerance = fit_number_option(a, next), ++i, have_tolerance = true;
        } else if (a == "--mode") {
            const std::string m = value(a);
            if (m != "subset" && m != "free") fit_usage_error("--mode: expected subset or free, got '" + m + "'");
            s.mode = m == "free" ? fit_mode::free : fit_mode::subset;
        } else if (a == "--alpha") {
            s.alpha = fit_number_option(a, next), ++i;
        } else if (a == "--tension") {
            s.tension = fit_number_option(a, next), ++i;
        } else if (a == "--closed") {
            s.closed = true;
        } else if (a == "--start" || a == "--end") {
            const std::string e = value(a);
            if (e != "natural" && e != "reflect") fit_usage_error(a + ": expected natural or reflect, got '" + e + "'");
            (a == "--start" ? s.start : s.end) = e;
        } else if (a == "--format") {
            s.format = value(a);
        } else if (a == "--input-format") {
            o.input_format = value(a);
        } else if (a == "--columns") {
            o.columns = value(a);
        } else if (a == "--delimiter") {
            o.delimiter = value(a);
        } else if (a == "--curve-column") {
            o.curve_column = value(a);
        } else if (a == "-o" || a == "--output") {
            o.output = value(a);
        } else if (a.size() > 1 && a[0] == '-' && a != "-") {
            fit_usage_error("unknown option '" + a + "'");
        } else if (input.empty()) {
            input = a;
        } else {
            fit_usage_error("one input only, got '" + input + "' and '" + a + "'");
        }
    }
    if (!have_tolerance) fit_usage_error("--tolerance is required");
    o.input = input.empty() ? "-" : input;
    o.format = s.format;
    s.format = output_format(o, {"json", "csv", "geojson"}, "json");
    const loaded_input in = load_input(o);
    std::vector<fitted> results;
    for (std::size_t i = 0; i < in.curves.size(); ++i) {
        const document& d = in.curves[i];
        const std::string where = in.many ? in.name + ": " + d.id + ": " : in.name + ": ";
        try {
            results.push_back(fit_document(d, s, where));
        } catch (const invalid_input& e) {
            throw input_error(where + e.what());
        }
    }
    std::string out;
    if (s.format == "json") {
        if (!in.many) {
            out = results[0].curve.dump() + "\n";
        } else {
            ojson list = ojson::array();
            for (std::size_t i = 0; i < results.size(); ++i) {
                const document& d = in.curves[i];
                ojson item;
                item["id"] = d.source_id.is_null() ? ojson(d.id) : ojson(d.source_id);
                ojson props = d.properties.is_object() ? ojson(d.properties) : ojson::object();
                for (auto& [k, v] : results[i].report.items()) props["fit_" + k] = v;
                item["properties"] = std::move(props);
                for (auto& [k, v] : results[i].curve.items()) item[k] = v;
                list.push_back(std::move(item));
            }
            out = list.dump() + "\n";
        }
    } else if (s.format == "csv") {
        std::ostringstream csv;
        const std::size_t dim = results[0].cps.empty() ? 0 : results[0].cps[0].size();
        const char* names[] = {"x", "y", "z", "w"};
        if (in.many) csv << "curve,";
        for (std::size_t k = 0; k < dim; ++k) csv << (k ? "," : "") << names[k];
        csv << "\n";
        for (std::size_t i = 0; i < results.size(); ++i)
            for (const auto& p : results[i].cps) {
                if (in.many) csv << csv_field(in.curves[i].id) << ",";
                for (std::size_t k = 0; k < p.size(); ++k) csv << (k ? "," : "") << format_number(p[k]);
                csv << "\n";
            }
        out = csv.str();
    } else {
        ojson fc = {{"type", "FeatureCollection"}, {"features", ojson::array()}};
        for (std::size_t i = 0; i < results.size(); ++i) {
            const document& d = in.curves[i];
            const auto& r = results[i];
            if (!r.line.empty() && r.line[0].size() != 2 && r.line[0].size() != 3)
                throw input_error("--format geojson: needs 2-D or 3-D points, got " +
                                  std::to_string(r.line[0].size()) + "-D (use json or csv)");
            ojson f = {{"type", "Feature"}};
            f["id"] = d.source_id.is_null() ? ojson(in.many ? d.id : "0") : ojson(d.source_id);
            ojson props = d.properties.is_object() ? ojson(d.properties) : ojson::object();
            props["control_points"] = r.report["control_points"];
            props["deviation"] = r.report["deviation"];
            props["tolerance"] = s.tolerance;
            props["mode"] = r.report["mode"];
            f["properties"] = std::move(props);
            ojson coords = r.line;
            if (r.closed) f["geometry"] = {{"type", "Polygon"}, {"coordinates", ojson::array({coords})}};
            else f["geometry"] = {{"type", "LineString"}, {"coordinates", coords}};
            fc["features"].push_back(std::move(f));
        }
        out = fc.dump() + "\n";
    }
    write_output(o.output, out);
    return 0;
}

}  // namespace

int fit_main(int argc, char** argv) {
    try {
        return run_fit(argc, argv);
    } catch (const input_error& e) {
        std::cerr << "crspline: " << e.what() << "\n";
    } catch (const invalid_input& e) {
        std::cerr << "crspline: " << e.what() << "\n";
    } catch (const std::exception& e) {
        std::cerr << "crspline: fit: " << e.what() << "\n";
    }
    return 2;
}

}  // namespace crspline::cli
