// crspline sweep and crspline stroke (issue 41): a tube along a 3-D curve as
// a mesh file, and the stroke of a 2-D curve as polygons.
//
//   crspline sweep [IN] -o tube.obj|tube.gltf|tube.ply [--radius R] [--tolerance T]
//                  [--tubular-segments N --radial-segments M] [--profile X,Y,X,Y,... [--profile-open]]
//                  [--roll A,B,...] [--roll-s S,S,...] [--scale F,F,... --scale-s S,S,...]
//                  [--up X,Y,Z] [--seam]  (plus the curve options: --alpha, --closed, ...)
//   crspline stroke [IN] --width W [--join round|miter|bevel] [--miter-limit L]
//                   [--cap butt|round|square] [--tolerance T] [--format geojson|svg] [-o OUT]
//
// The input is read as every subcommand reads curves (JSON, CSV, GeoJSON,
// SVG path data; many curves in one input give one mesh or one polygon
// feature each). sweep writes the mesh (every curve's, one after the other)
// in the format of -o's extension or --format, and its report as JSON on
// stdout when the mesh goes to a file. glTF is glTF 2.0 JSON with the buffer
// embedded as base64 (float32 positions, normals, texture coordinates;
// uint32 indices). stroke writes GeoJSON (a FeatureCollection, one
// MultiPolygon Feature per curve, rings closed, exteriors counterclockwise
// as RFC 7946 asks) or an SVG figure. Bad input: one line on stderr, exit 2.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <crspline/stroke.hpp>
#include <crspline/sweep.hpp>

#include "csv_input.hpp"
#include "dispatch.hpp"
#include "json_input.hpp"
#include "options.hpp"
#include "output_stream.hpp"

namespace crspline::cli {

namespace {

using ojson = nlohmann::ordered_json;

// A comma-separated list of numbers given to a flag; the message names the flag.
std::vector<double> number_list(const std::string& text, const std::string& flag) {
    std::vector<double> out;
    if (text.empty()) return out;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        const auto v = parse_number(item);
        if (!v) throw input_error(flag + ": '" + item + "' is not a number");
        out.push_back(*v);
    }
    return out;
}

std::optional<double> one_number(const std::string& text, const std::string& flag) {
    if (text.empty()) return std::nullopt;
    const auto v = parse_number(text);
    if (!v) throw input_error(flag + ": '" + text + "' is not a number");
    return *v;
}

std::size_t count_of(const std::string& text, const std::string& flag) {
    if (text.empty()) return 0;
    const auto v = parse_number(text);
    if (!v || !(*v >= 1) || *v != std::floor(*v) || *v > 1e8)
        throw input_error(flag + ": must be a whole number from 1, got '" + text + "'");
    return std::size_t(*v);
}

// The curve options every subcommand takes (read by the curve's document).
void add_curve_options(CLI::App& app, cli_options& o) {
    app.add_option("input", o.input, "Input file (JSON, CSV, GeoJSON, SVG); '-' or absent reads stdin");
    app.add_option("--input-format", o.input_format, "json, csv, tsv or svg (default: by extension, else by content)");
    app.add_option("--columns", o.columns, "CSV columns to read");
    app.add_option("--alpha", o.alpha, "Knot exponent in [0, 1] (default 0.5, centripetal)");
    app.add_flag("--closed", o.closed, "A closed curve");
    app.add_option("--tension", o.tension, "Tension in [0, 1]");
    app.add_option("-o,--output", o.output, "Output file (default: stdout)");
    app.add_option("--format", o.format, "Output format (default: by extension of -o)");
}

template <class Body>
int guarded(const char* name, Body&& body) {
    try {
        return body();
    } catch (const CLI::ParseError& e) {
        std::cerr << "crspline " << name << ": " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "crspline " << name << ": " << e.what() << "\n";
        return 2;
    }
}

std::string base64(const std::vector<std::uint8_t>& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t a = bytes[i], b = i + 1 < bytes.size() ? bytes[i + 1] : 0,
                            c = i + 2 < bytes.size() ? bytes[i + 2] : 0;
        const std::uint32_t v = (a << 16) | (b << 8) | c;
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? table[v & 63] : '=';
    }
    return out;
}

template <class T>
void append_bytes(std::vector<std::uint8_t>& out, const T& v) {
    const auto* p = reinterpret_cast<const std::uint8_t*>(&v);
    out.insert(out.end(), p, p + sizeof(T));
}

// Every curve's mesh, one after the other.
struct merged_mesh {
    std::vector<double> positions, normals, uvs;
    std::vector<std::uint32_t> indices;
};

void merge(merged_mesh& m, const sweep_mesh& s) {
    const auto base = std::uint32_t(m.positions.size() / 3);
    m.positions.insert(m.positions.end(), s.positions.begin(), s.positions.end());
    m.normals.insert(m.normals.end(), s.normals.begin(), s.normals.end());
    m.uvs.insert(m.uvs.end(), s.uvs.begin(), s.uvs.end());
    for (auto i : s.indices) m.indices.push_back(base + i);
}

std::string write_obj(const merged_mesh& m) {
    std::string out = "# crspline sweep\n";
    char line[160];
    for (std::size_t k = 0; k < m.positions.size() / 3; ++k) {
        std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", m.positions[3 * k], m.positions[3 * k + 1], m.positions[3 * k + 2]);
        out += line;
    }
    for (std::size_t k = 0; k < m.normals.size() / 3; ++k) {
        std::snprintf(line, sizeof line, "vn %.9g %.9g %.9g\n", m.normals[3 * k], m.normals[3 * k + 1], m.normals[3 * k + 2]);
        out += line;
    }
    for (std::size_t k = 0; k < m.uvs.size() / 2; ++k) {
        std::snprintf(line, sizeof line, "vt %.9g %.9g\n", m.uvs[2 * k], m.uvs[2 * k + 1]);
        out += line;
    }
    for (std::size_t f = 0; f < m.indices.size() / 3; ++f) {
        const auto a = m.indices[3 * f] + 1, b = m.indices[3 * f + 1] + 1, c = m.indices[3 * f + 2] + 1;
        std::snprintf(line, sizeof line, "f %u/%u/%u %u/%u/%u %u/%u/%u\n", a, a, a, b, b, b, c, c, c);
        out += line;
    }
    return out;
}

std::string write_ply(const merged_mesh& m) {
    const std::size_t nv = m.positions.size() / 3, nf = m.indices.size() / 3;
    std::string out = "ply\nformat ascii 1.0\ncomment crspline sweep\nelement vertex " + std::to_string(nv) +
                      "\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\n"
                      "property float nz\nproperty float s\nproperty float t\nelement face " +
                      std::to_string(nf) + "\nproperty list uchar uint vertex_indices\nend_header\n";
    char line[240];
    for (std::size_t k = 0; k < nv; ++k) {
        std::snprintf(line, sizeof line, "%.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g\n", m.positions[3 * k],
                      m.positions[3 * k + 1], m.positions[3 * k + 2], m.normals[3 * k], m.normals[3 * k + 1],
                      m.normals[3 * k + 2], m.uvs[2 * k], m.uvs[2 * k + 1]);
        out += line;
    }
    for (std::size_t f = 0; f < nf; ++f) {
        std::snprintf(line, sizeof line, "3 %u %u %u\n", m.indices[3 * f], m.indices[3 * f + 1], m.indices[3 * f + 2]);
        out += line;
    }
    return out;
}

// glTF 2.0: one buffer (base64 data URI) with four views, one mesh, one node.
std::string write_gltf(const merged_mesh& m) {
    const std::size_t nv = m.positions.size() / 3;
    std::vector<std::uint8_t> buf;
    std::array<float, 3> lo{}, hi{};
    lo.fill(std::numeric_limits<float>::infinity());
    hi.fill(-std::numeric_limits<float>::infinity());
    for (std::size_t k = 0; k < 3 * nv; ++k) {
        const float v = float(m.positions[k]);
        lo[k % 3] = std::min(lo[k % 3], v), hi[k % 3] = std::max(hi[k % 3], v);
        append_bytes(buf, v);
    }
    const std::size_t normals_at = buf.size();
    for (double v : m.normals) append_bytes(buf, float(v));
    const std::size_t uvs_at = buf.size();
    // glTF's texture v runs downwards: 1 - v.
    for (std::size_t k = 0; k < m.uvs.size(); ++k) append_bytes(buf, float(k % 2 ? 1 - m.uvs[k] : m.uvs[k]));
    const std::size_t indices_at = buf.size();
    for (auto i : m.indices) append_bytes(buf, i);
    ojson g;
    g["asset"] = {{"version", "2.0"}, {"generator", "crspline sweep"}};
    g["scene"] = 0;
    g["scenes"] = ojson::array({{{"nodes", {0}}}});
    g["nodes"] = ojson::array({{{"mesh", 0}}});
    g["meshes"] = ojson::array({{{"primitives", ojson::array({{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}},
                                                             {"indices", 3},
                                                             {"mode", 4}}})}}});
    g["buffers"] = ojson::array({{{"byteLength", buf.size()},
                                 {"uri", "data:application/octet-stream;base64," + base64(buf)}}});
    g["bufferViews"] = ojson::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", normals_at}, {"target", 34962}},
                                    {{"buffer", 0}, {"byteOffset", normals_at}, {"byteLength", uvs_at - normals_at}, {"target", 34962}},
                                    {{"buffer", 0}, {"byteOffset", uvs_at}, {"byteLength", indices_at - uvs_at}, {"target", 34962}},
                                    {{"buffer", 0}, {"byteOffset", indices_at}, {"byteLength", buf.size() - indices_at}, {"target", 34963}}});
    g["accessors"] = ojson::array(
        {{{"bufferView", 0}, {"componentType", 5126}, {"count", nv}, {"type", "VEC3"}, {"min", lo}, {"max", hi}},
         {{"bufferView", 1}, {"componentType", 5126}, {"count", nv}, {"type", "VEC3"}},
         {{"bufferView", 2}, {"componentType", 5126}, {"count", nv}, {"type", "VEC2"}},
         {{"bufferView", 3}, {"componentType", 5125}, {"count", m.indices.size()}, {"type", "SCALAR"}}});
    return g.dump() + "\n";
}

ojson report_json(const sweep_report& r, const std::string& id) {
    auto num = [](double v) -> ojson { return std::isfinite(v) ? ojson(v) : ojson(nullptr); };
    ojson j;
    if (!id.empty()) j["id"] = id;
    j["tolerance"] = num(r.tolerance);
    j["bound"] = num(r.bound);
    j["tolerance_met"] = r.tolerance_met;
    j["proved"] = r.proved;
    j["holonomy"] = r.holonomy;
    j["frame_drift"] = num(r.frame_drift);
    j["length"] = r.length;
    j["largest_radius"] = r.largest_radius;
    j["clearance"] = num(r.clearance);
    j["min_radius_of_curvature"] = num(r.min_radius_of_curvature);
    j["far_contact"] = r.far_contact;
    j["local_fold"] = r.local_fold;
    j["self_intersects"] = r.self_intersects;
    return j;
}

// CLI11's parse: --help prints and ends the command (exit 0); other errors
// become one line.
bool parsed(CLI::App& app, int argc, char** argv, int& code) {
    try {
        app.parse(argc, argv);
        return true;
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) {
            code = app.exit(e);
            return false;
        }
        throw input_error(e.what());
    }
}

std::string extension_format(const cli_options& o, const std::vector<std::string>& allowed, const std::string& fallback) {
    return output_format(o, allowed, fallback);
}

int run_sweep(int argc, char** argv) {
    CLI::App app{"crspline sweep: a profile swept along a 3-D curve, as a mesh (OBJ, glTF, PLY)"};
    cli_options o;
    o.command = "sweep";
    add_curve_options(app, o);
    std::string radius, tolerance, tubular, radial, profile, roll, roll_s, scale, scale_s, up;
    bool profile_open = false, seam = false;
    app.add_option("--radius", radius, "Radius of the circular profile (default 1)");
    app.add_option("--tolerance", tolerance, "Largest distance of the mesh to the swept surface (default 1e-3 of the size)");
    app.add_option("--tubular-segments", tubular, "Pieces along the curve, equal in arc length (three.js' tubularSegments)");
    app.add_option("--radial-segments", radial, "Pieces around the circle (three.js' radialSegments)");
    app.add_option("--profile", profile, "A polygon profile X,Y,X,Y,... in the (normal, binormal) plane");
    app.add_flag("--profile-open", profile_open, "The profile is an open polyline (a ribbon)");
    app.add_option("--roll", roll, "Roll angles in radians, one per point (or at --roll-s arc lengths)");
    app.add_option("--roll-s", roll_s, "Arc lengths of the roll angles");
    app.add_option("--scale", scale, "Scale factors of the profile at the --scale-s arc lengths");
    app.add_option("--scale-s", scale_s, "Arc lengths of the scale factors");
    app.add_option("--up", up, "Up vector X,Y,Z the normal follows");
    app.add_flag("--seam", seam, "Leave a closed curve's holonomy unspread (the seam other libraries have)");
    int code = 0;
    if (!parsed(app, argc, argv, code)) return code;
    const std::string format = extension_format(o, {"obj", "gltf", "ply"}, "obj");
    sweep_options so;
    if (const auto r = one_number(radius, "--radius")) so.profile = sweep_profile::circle(*r);
    if (!profile.empty()) {
        const auto v = number_list(profile, "--profile");
        if (v.size() % 2) throw input_error("--profile: expected X,Y pairs, got " + std::to_string(v.size()) + " numbers");
        std::vector<vec<2>> pts;
        for (std::size_t k = 0; k + 1 < v.size(); k += 2) pts.push_back({{v[k], v[k + 1]}});
        so.profile = sweep_profile::polyline(pts, !profile_open);
    }
    so.tolerance = one_number(tolerance, "--tolerance").value_or(0.0);
    if (!tolerance.empty() && !(so.tolerance > 0)) throw input_error("--tolerance: must be positive, got " + tolerance);
    so.tubular_segments = count_of(tubular, "--tubular-segments");
    so.radial_segments = count_of(radial, "--radial-segments");
    so.roll = number_list(roll, "--roll");
    so.roll_s = number_list(roll_s, "--roll-s");
    if (!so.roll_s.empty()) so.roll_at = roll_position::arc_length;
    so.scale = number_list(scale, "--scale");
    so.scale_s = number_list(scale_s, "--scale-s");
    if (!up.empty()) {
        const auto v = number_list(up, "--up");
        if (v.size() != 3) throw input_error("--up: expected X,Y,Z, got " + std::to_string(v.size()) + " numbers");
        so.up = vec<3>{{v[0], v[1], v[2]}};
    }
    so.spread_holonomy = !seam;
    const loaded_input in = load_input(o);
    merged_mesh all;
    ojson reports = ojson::array();
    for (const auto& doc : in.curves) {
        const curve_spec spec = parse_curve(doc, "sweep", {});
        if (spec.dimension != 3)
            throw input_error((doc.id.empty() ? std::string() : doc.id + ": ") + "curve: sweep needs a 3-D curve, got a " +
                              std::to_string(spec.dimension) + "-D one");
        const catmull_rom<3> c = make_curve<3>(spec);
        sweep_mesh m;
        try {
            m = sweep(c, so);
        } catch (const spec_error& e) {
            // The core names the field; the command line names the flag.
            const std::string f = e.field() == "radius" ? "--radius" : e.field() == "tolerance" ? "--tolerance" :
                                  e.field() == "curve" ? "curve" : "--" + e.field();
            std::string what = e.what();
            if (what.rfind(e.field(), 0) == 0) what = f + what.substr(e.field().size());
            throw input_error(what);
        }
        merge(all, m);
        reports.push_back(report_json(m.report, doc.id));
    }
    const std::string bytes = format == "gltf" ? write_gltf(all) : format == "ply" ? write_ply(all) : write_obj(all);
    write_output(o.output, bytes);
    if (!o.output.empty() && o.output != "-") std::cout << ojson({{"reports", reports}}).dump() << "\n";
    return 0;
}

std::string svg_of(const std::vector<stroke_result>& results) {
    double lo_x = std::numeric_limits<double>::infinity(), lo_y = lo_x, hi_x = -lo_x, hi_y = -lo_x;
    for (const auto& r : results)
        for (const auto& p : r.polygons)
            for (const auto& q : p.exterior) lo_x = std::min(lo_x, q[0]), hi_x = std::max(hi_x, q[0]), lo_y = std::min(lo_y, q[1]), hi_y = std::max(hi_y, q[1]);
    if (!std::isfinite(lo_x)) lo_x = lo_y = 0, hi_x = hi_y = 1;
    const double pad = 0.02 * std::max(hi_x - lo_x, hi_y - lo_y) + 1e-12;
    char head[400];
    // y up in the curve's plane, down in SVG: the figure flips it.
    std::snprintf(head, sizeof head,
                  "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"%.9g %.9g %.9g %.9g\">\n<g transform=\"scale(1,-1)\">\n",
                  lo_x - pad, -(hi_y + pad), hi_x - lo_x + 2 * pad, hi_y - lo_y + 2 * pad);
    std::string out = head;
    char pt[80];
    for (const auto& r : results) {
        out += "<path fill=\"black\" fill-rule=\"nonzero\" d=\"";
        auto ring = [&](const std::vector<vec<2>>& ring_points) {
            for (std::size_t k = 0; k < ring_points.size(); ++k) {
                std::snprintf(pt, sizeof pt, "%s%.9g %.9g ", k ? "L" : "M", ring_points[k][0], ring_points[k][1]);
                out += pt;
            }
            out += "Z ";
        };
        for (const auto& p : r.polygons) {
            ring(p.exterior);
            for (const auto& h : p.holes) ring(h);
        }
        out += "\"/>\n";
    }
    out += "</g>\n</svg>\n";
    return out;
}

ojson geojson_of(const std::vector<stroke_result>& results, const loaded_input& in) {
    ojson features = ojson::array();
    for (std::size_t i = 0; i < results.size(); ++i) {
        ojson polys = ojson::array();
        for (const auto& p : results[i].polygons) {
            ojson rings = ojson::array();
            auto ring = [](const std::vector<vec<2>>& r) {
                ojson a = ojson::array();
                for (const auto& q : r) a.push_back({q[0], q[1]});
                if (!r.empty()) a.push_back({r.front()[0], r.front()[1]});  // closed, as GeoJSON asks
                return a;
            };
            rings.push_back(ring(p.exterior));
            for (const auto& h : p.holes) rings.push_back(ring(h));
            polys.push_back(rings);
        }
        ojson f = {{"type", "Feature"},
                  {"properties", {{"crspline_tolerance", results[i].tolerance}}},
                  {"geometry", {{"type", "MultiPolygon"}, {"coordinates", polys}}}};
        const auto& doc = in.curves[i];
        if (doc.properties.is_object())
            for (const auto& [k, v] : doc.properties.items()) f["properties"][k] = v;
        if (!doc.source_id.is_null()) f["id"] = doc.source_id;
        features.push_back(f);
    }
    return {{"type", "FeatureCollection"}, {"features", features}};
}

int run_stroke(int argc, char** argv) {
    CLI::App app{"crspline stroke: the outline of a 2-D curve stroked at a width, as polygons (GeoJSON, SVG)"};
    cli_options o;
    o.command = "stroke";
    add_curve_options(app, o);
    std::string width, join = "round", cap = "butt", miter_limit, tolerance;
    app.add_option("--width", width, "Stroke width (required)");
    app.add_option("--join", join, "Join at the curve's corners: round, miter or bevel (default round)");
    app.add_option("--miter-limit", miter_limit, "Miter length over width above which a miter becomes a bevel (default 4)");
    app.add_option("--cap", cap, "Cap at the ends: butt, round or square (default butt)");
    app.add_option("--tolerance", tolerance, "Largest distance to the true stroke (default 1e-3 of the size)");
    int code = 0;
    if (!parsed(app, argc, argv, code)) return code;
    const std::string format = extension_format(o, {"geojson", "svg"}, "geojson");
    if (width.empty()) throw input_error("--width: required");
    const auto w = one_number(width, "--width");
    if (!(*w > 0) || !std::isfinite(*w)) throw input_error("--width: must be positive and finite, got " + width);
    stroke_options so;
    if (join == "round") so.join = stroke_join::round;
    else if (join == "miter") so.join = stroke_join::miter;
    else if (join == "bevel") so.join = stroke_join::bevel;
    else throw input_error("--join: must be round, miter or bevel, got '" + join + "'");
    if (cap == "butt") so.cap = stroke_cap::butt;
    else if (cap == "round") so.cap = stroke_cap::round;
    else if (cap == "square") so.cap = stroke_cap::square;
    else throw input_error("--cap: must be butt, round or square, got '" + cap + "'");
    so.miter_limit = one_number(miter_limit, "--miter-limit").value_or(4.0);
    if (!(so.miter_limit >= 1)) throw input_error("--miter-limit: must be at least 1, got " + miter_limit);
    so.tolerance = one_number(tolerance, "--tolerance").value_or(0.0);
    if (!tolerance.empty() && !(so.tolerance > 0)) throw input_error("--tolerance: must be positive, got " + tolerance);
    const loaded_input in = load_input(o);
    std::vector<stroke_result> results;
    for (const auto& doc : in.curves) {
        const curve_spec spec = parse_curve(doc, "stroke", {});
        if (spec.dimension != 2)
            throw input_error((doc.id.empty() ? std::string() : doc.id + ": ") + "curve: stroke needs a 2-D curve, got a " +
                              std::to_string(spec.dimension) + "-D one");
        results.push_back(stroke(make_curve<2>(spec), *w, so));
    }
    write_output(o.output, format == "svg" ? svg_of(results) : geojson_of(results, in).dump() + "\n");
    return 0;
}

}  // namespace

int sweep_main(int argc, char** argv) {
    return guarded("sweep", [&] { return run_sweep(argc, argv); });
}

int stroke_main(int argc, char** argv) {
    return guarded("stroke", [&] { return run_stroke(argc, argv); });
}

}  // namespace crspline::cli
