// crspline smooth: a GeoJSON layer smoothed with its topology kept
// (crspline/geo/smooth.hpp), written back as GeoJSON with the measures as
// properties.
//
//   crspline smooth --tolerance 50 [--alpha 0.5] [--max-deviation M]
//                   [--topology preserve|none] [-o OUT.geojson] [IN.geojson]
//
// GeoJSON is WGS 84 longitude/latitude (RFC 7946), so distances are in
// metres: the core works in the conservative equirectangular frame that
// crspline.geo uses (x = R cos(phi0) lambda, y = R phi, R = a^2 / b; frame
// distances are never below true ones), input vertices come back bit for
// bit, and lengths are geodesic on the WGS 84 ellipsoid (GeographicLib's
// inverse problem per segment, accurate to rounding). Each feature gets the properties
// crspline_length_m (of the output polylines), crspline_curve_length_m (the
// curves' arc length in the frame's metres), crspline_max_deviation_m, crspline_verdict and
// crspline_status; the collection gets "crspline": {units, stats}. Bad input
// exits with status 2 and one line naming the feature and field.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include <GeographicLib/Geodesic.hpp>
#include <nlohmann/json.hpp>

#include <crspline/geo/smooth.hpp>

#include "progress.hpp"

namespace crspline::cli {

namespace {

using json = nlohmann::json;

struct smooth_error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

constexpr double wgs84_a = 6378137.0, wgs84_f = 1 / 298.257223563;
constexpr double wgs84_b = wgs84_a * (1 - wgs84_f);
constexpr double r_max = wgs84_a * wgs84_a / wgs84_b;

// Geodesic distance on WGS 84 (GeographicLib: Karney's algorithm, accurate
// to rounding for every pair of points, antipodal ones included).
double geodesic(double lon1, double lat1, double lon2, double lat2) {
    double s12 = 0;
    GeographicLib::Geodesic::WGS84().Inverse(lat1, lon1, lat2, lon2, s12);
    return s12;
}

struct recipe {
    std::string type;                // LineString, MultiLineString, Polygon, MultiPolygon, or "" (pass through)
    std::vector<std::size_t> rings;  // rings per polygon
    std::size_t first_part = 0, parts = 0;
    bool has_z = false;
};

// Positions of a GeoJSON line or ring into the layer.
void add_positions(geo::layer& l, std::size_t feature, geo::part_kind kind, const json& coords,
                   const std::string& where, bool& has_z, geo::ring_role role = geo::ring_role::none) {
    if (!coords.is_array()) throw smooth_error(where + ": expected an array of positions");
    std::vector<double> xy, z;
    for (std::size_t i = 0; i < coords.size(); ++i) {
        const json& p = coords[i];
        if (!p.is_array() || p.size() < 2 || !p[0].is_number() || !p[1].is_number())
            throw smooth_error(where + "[" + std::to_string(i) + "]: expected a position [x, y] or [x, y, z]");
        xy.push_back(p[0].get<double>());
        xy.push_back(p[1].get<double>());
        const bool zi = p.size() > 2 && p[2].is_number();
        has_z = has_z || zi;
        z.push_back(zi ? p[2].get<double>() : 0.0);
    }
    l.add_part(feature, kind, xy, z, role);
}

recipe add_geometry(geo::layer& l, std::size_t feature, const json& g, const std::string& where) {
    recipe r;
    r.first_part = l.part_count();
    if (g.is_null()) return r;
    if (!g.is_object() || !g.contains("type") || !g["type"].is_string())
        throw smooth_error(where + ": expected a GeoJSON geometry {\"type\": ..., \"coordinates\": ...}");
    const std::string type = g["type"].get<std::string>();
    if (type != "LineString" && type != "MultiLineString" && type != "Polygon" && type != "MultiPolygon")
        return r;  // passed through unchanged (Point, GeometryCollection, ...)
    if (!g.contains("coordinates") || !g["coordinates"].is_array())
        throw smooth_error(where + ".coordinates: expected an array");
    const json& c = g["coordinates"];
    const std::string wc = where + ".coordinates";
    r.type = type;
    if (type == "LineString") {
        add_positions(l, feature, geo::part_kind::line, c, wc, r.has_z);
    } else if (type == "MultiLineString") {
        for (std::size_t i = 0; i < c.size(); ++i)
            add_positions(l, feature, geo::part_kind::line, c[i], wc + "[" + std::to_string(i) + "]", r.has_z);
    } else {
        const bool multi = type == "MultiPolygon";
        const std::size_t np = multi ? c.size() : 1;
        for (std::size_t k = 0; k < np; ++k) {
            const json& poly = multi ? c[k] : c;
            const std::string wp = multi ? wc + "[" + std::to_string(k) + "]" : wc;
            if (!poly.is_array()) throw smooth_error(wp + ": expected an array of rings");
            for (std::size_t i = 0; i < poly.size(); ++i)
                add_positions(l, feature, geo::part_kind::ring, poly[i], wp + "[" + std::to_string(i) + "]", r.has_z,
                              i == 0 ? geo::ring_role::outer : geo::ring_role::inner);
            r.rings.push_back(poly.size());
        }
    }
    r.parts = l.part_count() - r.first_part;
    return r;
}

void usage_error(const std::string& m) { throw smooth_error(m + " (usage: crspline smooth --tolerance METRES "
                                                                "[--alpha A] [--max-deviation METRES] [--fit METRES] "
                                                                "[--topology preserve|none] [-o OUT] [IN])"); }

double number_option(const std::string& name, const char* value) {
    if (!value) usage_error(name + " needs a value");
    char* end = nullptr;
    const double v = std::strtod(value, &end);
    if (end == value || *end != '\0') usage_error(name + ": expected a number, got '" + std::string(value) + "'");
    return v;
}

int run(int argc, char** argv) {
    geo::smooth_options opt;
    bool have_tolerance = false;
    std::string in_path, out_path;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const char* next = i + 1 < argc ? argv[i + 1] : nullptr;
        if (a == "--tolerance") opt.tolerance = number_option(a, next), have_tolerance = true, ++i;
        else if (a == "--alpha") opt.alpha = number_option(a, next), ++i;
        else if (a == "--max-deviation") opt.max_deviation = number_option(a, next), ++i;
        else if (a == "--fit") opt.fit = number_option(a, next), ++i;
        else if (a == "--topology") {
            if (!next || (std::strcmp(next, "preserve") != 0 && std::strcmp(next, "none") != 0))
                usage_error("--topology must be 'preserve' or 'none'");
            opt.preserve_topology = std::strcmp(next, "preserve") == 0;
            ++i;
        } else if (a == "-o" || a == "--output") {
            if (!next) usage_error(a + " needs a file name");
            out_path = next;
            ++i;
        } else if (a == "-h" || a == "--help") {
            std::cout << "crspline smooth: smooth a GeoJSON layer (WGS 84; distances in metres), keeping shared\n"
                         "borders shared, every vertex, and no new crossings (see docs/geo.md).\n"
                         "  --tolerance M       output polylines within M metres of the curves (required)\n"
                         "  --alpha A           knot exponent, default 0.5 (centripetal)\n"
                         "  --max-deviation M   no curve point farther than M metres from the input\n"
                         "  --topology T        preserve (default) or none (each part alone, unchecked)\n"
                         "  --fit M             fit each arc with few control points (a subset of its vertices)\n"
                         "                      within M metres of the input, proved both ways (docs/fit.md);\n"
                         "                      --tolerance defaults to M/10 then\n"
                         "  -o FILE             output GeoJSON (default: standard output)\n"
                         "GeoJSON only: convert a GeoPackage or Shapefile with ogr2ogr -f GeoJSON, or use\n"
                         "crspline.geo.smooth on a GeoPandas frame (docs/geo.md).\n";
            return 0;
        } else if (!a.empty() && a[0] == '-' && a != "-") {
            usage_error("unknown option " + a);
        } else if (in_path.empty()) {
            in_path = a;
        } else {
            usage_error("more than one input file");
        }
    }
    if (opt.fit && !have_tolerance && *opt.fit > 0 && std::isfinite(*opt.fit)) {
        opt.tolerance = *opt.fit / 10;  // the polylines near the fitted curves
        have_tolerance = true;
    }
    if (!have_tolerance) usage_error("--tolerance is required");
    // Read.
    json root;
    {
        const std::string name = in_path.empty() || in_path == "-" ? "<stdin>" : in_path;
        std::ifstream file;
        if (!in_path.empty() && in_path != "-") {
            file.open(in_path);
            if (!file) throw smooth_error(name + ": cannot open");
        }
        std::istream& is = file.is_open() ? static_cast<std::istream&>(file) : std::cin;
        try {
            root = json::parse(is);
        } catch (const json::parse_error& e) {
            throw smooth_error(name + ": not JSON: " + e.what());
        }
    }
    // Features: a FeatureCollection, one Feature, or one geometry.
    std::vector<json*> geometries;
    std::vector<json*> features;
    if (root.is_object() && root.value("type", "") == "FeatureCollection") {
        if (!root.contains("features") || !root["features"].is_array())
            throw smooth_error("features: expected an array");
        for (auto& f : root["features"]) {
            if (!f.is_object() || f.value("type", "") != "Feature")
                throw smooth_error("features[" + std::to_string(features.size()) + "]: expected a GeoJSON Feature");
            features.push_back(&f);
            geometries.push_back(f.contains("geometry") ? &f["geometry"] : nullptr);
        }
    } else if (root.is_object() && root.value("type", "") == "Feature") {
        features.push_back(&root);
        geometries.push_back(root.contains("geometry") ? &root["geometry"] : nullptr);
    } else {
        geometries.push_back(&root);
    }
    geo::layer layer;
    layer.extra_dims = 1;  // Z, carried when present
    std::vector<recipe> recipes;
    static const json null_json;
    for (std::size_t i = 0; i < geometries.size(); ++i) {
        const std::string where = features.empty() ? "geometry" : "features[" + std::to_string(i) + "].geometry";
        recipes.push_back(add_geometry(layer, i, geometries[i] ? *geometries[i] : null_json, where));
    }
    layer.feature_count = geometries.size();
    // Lines and rings across the antimeridian (a step of more than 180
    // degrees between neighbours) are unwrapped: longitudes continuous along
    // the part, back into [-180, 180] on output. A ring round a pole (its
    // steps add up to a turn) is left as it is. As crspline.geo's _unwrap.
    std::vector<double> lon_of(layer.vertex_count());
    for (std::size_t v = 0; v < layer.vertex_count(); ++v) lon_of[v] = layer.xy[2 * v];
    for (std::size_t p = 0; p < layer.part_count(); ++p) {
        const std::size_t a = layer.part_offsets[p], b = layer.part_offsets[p + 1];
        std::vector<double> shift(b - a, 0.0);
        bool moved = false;
        for (std::size_t v = a + 1; v < b; ++v) {
            const double step = layer.xy[2 * v] - layer.xy[2 * v - 2];
            shift[v - a] = shift[v - a - 1] + (step > 180 ? -360.0 : step < -180 ? 360.0 : 0.0);
            moved = moved || shift[v - a] != 0;
        }
        if (!moved) continue;
        if (layer.part_kinds[p] == geo::part_kind::ring &&
            !(std::abs(layer.xy[2 * a] - (layer.xy[2 * (b - 1)] + shift[b - 1 - a])) <= 180))
            continue;
        for (std::size_t v = a; v < b; ++v) lon_of[v] = layer.xy[2 * v] + shift[v - a];
    }
    // The frame (as crspline.geo's: the same arithmetic, so the same numbers):
    // the domain holds the unwrapped input, the clip box the input as given.
    double phi0 = 90, lat_min = 90, lat_max = -90, lon_min = -180, lon_max = 180;
    double clip_lon_min = -180, clip_lon_max = 180;
    for (std::size_t v = 0; v < layer.vertex_count(); ++v) {
        const double lon = lon_of[v], lat = layer.xy[2 * v + 1];
        if (!std::isfinite(lat) || !std::isfinite(lon)) continue;
        lat_min = std::min(lat_min, lat);
        lat_max = std::max(lat_max, lat);
        lon_min = std::min(lon_min, lon);
        lon_max = std::max(lon_max, lon);
        clip_lon_min = std::min(clip_lon_min, layer.xy[2 * v]);
        clip_lon_max = std::max(clip_lon_max, layer.xy[2 * v]);
        phi0 = std::min(phi0, std::abs(lat));
    }
    const bool wrapped = lon_min < clip_lon_min || lon_max > clip_lon_max;
    if (lat_min <= 0 && lat_max >= 0) phi0 = 0;
    if (layer.vertex_count() == 0) phi0 = 0;
    const double k = r_max * std::numbers::pi / 180;
    const double sx = k * std::cos(phi0 * (std::numbers::pi / 180.0)), sy = k;
    geo::layer framed = layer;
    std::unordered_map<std::string, std::size_t> original;  // frame point bits -> layer vertex
    auto key = [](double x, double y) {
        std::string s(16, '\0');
        std::memcpy(s.data(), &x, 8);
        std::memcpy(s.data() + 8, &y, 8);
        return s;
    };
    for (std::size_t v = 0; v < layer.vertex_count(); ++v) {
        framed.xy[2 * v] = lon_of[v] * sx;
        framed.xy[2 * v + 1] *= sy;
        original.emplace(key(framed.xy[2 * v], framed.xy[2 * v + 1]), v);
    }
    opt.domain = box<2>{vec<2>{{std::min(-180.0, lon_min) * sx, std::min(-90.0, lat_min) * sy}},
                        vec<2>{{std::max(180.0, lon_max) * sx, std::max(90.0, lat_max) * sy}}};
    // Progress on a terminal for large layers (stderr, only when it is a TTY).
    progress shown("crspline smooth");
    opt.progress = [&shown](double fraction) { shown.update(fraction); };
    const geo::smooth_result res = geo::smooth(framed, opt);
    // Back to longitude and latitude: input vertices exactly, the others through the frame.
    const geo::layer& o = res.output;
    std::vector<double> lonlat(o.xy.size());
    for (std::size_t v = 0; v < o.vertex_count(); ++v) {
        const double x = o.xy[2 * v], y = o.xy[2 * v + 1];
        const auto it = original.find(key(x, y));
        if (it != original.end()) {
            lonlat[2 * v] = layer.xy[2 * it->second];
            lonlat[2 * v + 1] = layer.xy[2 * it->second + 1];
        } else {
            double lon = x / sx;
            if (wrapped) lon = lon > clip_lon_max ? lon - 360 : lon < clip_lon_min ? lon + 360 : lon;
            lonlat[2 * v] = std::clamp(lon, clip_lon_min, clip_lon_max);
            lonlat[2 * v + 1] = std::clamp(y / sy, std::min(-90.0, lat_min), std::max(90.0, lat_max));
        }
    }
    // Write: geometries replaced, measures as properties.
    std::vector<double> length(layer.feature_count, 0.0);
    auto part_json = [&](std::size_t p, bool has_z) {
        json a = json::array();
        for (std::size_t v = o.part_offsets[p]; v < o.part_offsets[p + 1]; ++v) {
            if (v > o.part_offsets[p])
                length[o.part_features[p]] += geodesic(lonlat[2 * v - 2], lonlat[2 * v - 1], lonlat[2 * v], lonlat[2 * v + 1]);
            json pos = json::array({lonlat[2 * v], lonlat[2 * v + 1]});
            if (has_z) pos.push_back(o.extra[v]);
            a.push_back(std::move(pos));
        }
        return a;
    };
    for (std::size_t i = 0; i < geometries.size(); ++i) {
        const recipe& r = recipes[i];
        const auto& rep = res.features[i];
        if (r.type.empty() || rep.status == geo::feature_status::invalid) continue;
        json coords = json::array();
        std::size_t p = r.first_part;
        if (r.type == "LineString") {
            coords = part_json(p, r.has_z);
        } else if (r.type == "MultiLineString") {
            for (; p < r.first_part + r.parts; ++p) coords.push_back(part_json(p, r.has_z));
        } else {
            for (std::size_t rings : r.rings) {
                json poly = json::array();
                for (std::size_t q = 0; q < rings; ++q, ++p) poly.push_back(part_json(p, r.has_z));
                if (r.type == "Polygon") coords = std::move(poly);
                else coords.push_back(std::move(poly));
            }
        }
        (*geometries[i])["coordinates"] = std::move(coords);
    }
    for (std::size_t i = 0; i < features.size(); ++i) {
        json& f = *features[i];
        if (!f.contains("properties") || !f["properties"].is_object()) f["properties"] = json::object();
        const auto& rep = res.features[i];
        std::string status = geo::to_string(rep.status);
        if (recipes[i].type.empty() && geometries[i] && !geometries[i]->is_null())
            status = "invalid: unsupported geometry type " + geometries[i]->value("type", std::string("?")) +
                     ": passed through unchanged";
        else if (!rep.message.empty() && rep.status != geo::feature_status::empty)
            status += ": " + rep.message;
        f["properties"]["crspline_length_m"] = length[i];
        // The curves' own arc length, in the frame's metres (an upper bound
        // of the true one), as crspline.geo's curve_length.
        f["properties"]["crspline_curve_length_m"] =
            rep.status == geo::feature_status::invalid ? 0.0 : rep.length;
        f["properties"]["crspline_max_deviation_m"] = rep.max_deviation;
        f["properties"]["crspline_verdict"] = geo::to_string(rep.verdict);
        f["properties"]["crspline_status"] = status;
        if (opt.fit) f["properties"]["crspline_control_points"] = rep.control_points;
    }
    if (root.is_object()) {
        root["crspline"] = {{"units", "metre (lengths geodesic on WGS 84; tolerance and deviations bound true metres)"},
                            {"arcs", res.stats.arcs},
                            {"shared_arcs", res.stats.shared_arcs},
                            {"rounds", res.stats.rounds},
                            {"tensioned_vertices", res.stats.tensioned_vertices},
                            {"input_crossings", res.stats.input_crossings},
                            {"swept_vertices", res.stats.swept_vertices}};
    }
    const std::string text = root.dump();
    if (out_path.empty() || out_path == "-") {
        std::cout << text << "\n";
    } else {
        std::ofstream out(out_path);
        if (!out) throw smooth_error(out_path + ": cannot write");
        out << text << "\n";
    }
    return 0;
}

}  // namespace

/// `crspline smooth ...`: argv[0] is "smooth". Returns the exit status; bad
/// input is one line on stderr and status 2.
int smooth_main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::cerr << "crspline smooth: " << e.what() << "\n";
        return 2;
    }
}

}  // namespace crspline::cli
