// crspline command line: inputs that hold many curves. See collection_input.hpp.
#include "collection_input.hpp"

#include <crspline/dispatch.hpp>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>
#include <utility>

#include "json_input.hpp"

namespace crspline::cli {

using nlohmann::json;

namespace {


[[noreturn]] void fail(const input_text& in, const std::string& path, const std::string& what) {
    throw input_error(in.name + ": " + path + ": " + what);
}

std::string shown(const json& v) {
    std::string s = v.dump(-1, ' ', false, json::error_handler_t::replace);
    return s.size() > 40 ? s.substr(0, 37) + "..." : s;
}

// A curve of the collection: its points read flat from JSON positions.
document curve_from_positions(const input_text& in, const json& positions, const std::string& path,
                              const std::string& pointer, std::string id, const json& feature_id,
                              const json& properties, bool ring) {
    if (!positions.is_array()) fail(in, path, "expected an array of positions [x, y, ...], got " + shown(positions));
    point_set p;
    p.name = path;
    p.path = path;
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const json& q = positions[i];
        const std::string at = json_index(path, i);
        if (!q.is_array() || q.empty() || q.size() > max_runtime_dimension)
            fail(in, at, "expected a position of 1 to " + std::to_string(max_runtime_dimension) + " numbers, got " +
                             shown(q));
        if (i == 0) p.dimension = q.size();
        if (q.size() != p.dimension)
            fail(in, at, "expected " + std::to_string(p.dimension) + " coordinates like " + json_index(path, 0) + ", got " +
                             std::to_string(q.size()));
        for (std::size_t k = 0; k < q.size(); ++k) {
            if (!q[k].is_number() || !std::isfinite(q[k].get<double>()))
                fail(in, json_index(at, k), "expected a finite number, got " + shown(q[k]));
            p.coords.push_back(q[k].get<double>());
        }
    }
    // A GeoJSON ring repeats its first position by definition (RFC 7946,
    // 3.1.6); the closed curve joins its ends by itself.
    const std::size_t d = p.dimension, n = p.size();
    if (ring && n >= 3 && std::equal(p.coords.begin(), p.coords.begin() + std::ptrdiff_t(d), p.coords.end() - std::ptrdiff_t(d)))
        p.coords.resize(p.coords.size() - d);
    document doc;
    doc.points = std::move(p);
    doc.id = std::move(id);
    doc.source_id = feature_id;
    doc.properties = properties;
    doc.geojson_pointer = pointer;
    doc.has_fields = false;
    if (ring) doc.root["end"] = "closed";
    return doc;
}

// The curves of one GeoJSON geometry at `path`, named `id` (with " ring k"
// or " part k" when it has several).
void geometry_curves(const input_text& in, const json& g, const std::string& path, const std::string& pointer,
                     const std::string& id, const json& feature_id, const json& properties,
                     std::vector<document>& out) {
    if (!g.is_object() || !g.contains("type") || !g["type"].is_string())
        fail(in, path, "expected a GeoJSON geometry {\"type\": ..., \"coordinates\": ...}, got " + shown(g));
    const std::string type = g["type"].get<std::string>();
    if (type == "GeometryCollection") {
        const json& gs = g.contains("geometries") ? g["geometries"] : json();
        if (!gs.is_array()) fail(in, path + ".geometries", "expected an array of geometries, got " + shown(gs));
        for (std::size_t i = 0; i < gs.size(); ++i)
            geometry_curves(in, gs[i], json_index(path + ".geometries", i), pointer + "/geometries/" + std::to_string(i),
                            id + " geometry " + std::to_string(i), feature_id, properties, out);
        return;
    }
    const std::string cpath = path + ".coordinates", cptr = pointer + "/coordinates";
    const auto item = [](const std::string& p, std::size_t i) { return p + "/" + std::to_string(i); };
    const json& c = g.contains("coordinates") ? g["coordinates"] : json();
    const auto list = [&](const json& v, const std::string& at) -> const json& {
        if (!v.is_array()) fail(in, at, "expected an array, got " + shown(v));
        return v;
    };
    const auto part = [](const std::string& base, const char* what, std::size_t k, std::size_t count) {
        return count == 1 ? base : base + " " + what + " " + std::to_string(k);
    };
    if (type == "LineString") {
        out.push_back(curve_from_positions(in, c, cpath, cptr, id, feature_id, properties, false));
    } else if (type == "MultiLineString") {
        for (std::size_t i = 0; i < list(c, cpath).size(); ++i)
            out.push_back(curve_from_positions(in, c[i], json_index(cpath, i), item(cptr, i), part(id, "part", i, c.size()),
                                               feature_id, properties, false));
    } else if (type == "Polygon") {
        for (std::size_t r = 0; r < list(c, cpath).size(); ++r)
            out.push_back(curve_from_positions(in, c[r], json_index(cpath, r), item(cptr, r), part(id, "ring", r, c.size()),
                                               feature_id, properties, true));
    } else if (type == "MultiPolygon") {
        for (std::size_t p = 0; p < list(c, cpath).size(); ++p) {
            const std::string ppath = json_index(cpath, p);
            const json& rings = list(c[p], ppath);
            for (std::size_t r = 0; r < rings.size(); ++r)
                out.push_back(curve_from_positions(in, rings[r], json_index(ppath, r), item(item(cptr, p), r),
                                                   part(part(id, "polygon", p, c.size()), "ring", r, rings.size()),
                                                   feature_id, properties, true));
        }
    } else if (type == "Point" || type == "MultiPoint") {
        fail(in, path, "a " + type + " is not a curve (expected LineString, Polygon or their Multi* forms)");
    } else {
        fail(in, path + ".type", "expected a GeoJSON geometry type (LineString, MultiLineString, Polygon, "
                                 "MultiPolygon, GeometryCollection), got " + shown(g["type"]));
    }
}

// A Feature's id for messages: its "id", else its path.
std::string feature_id(const json& f, const std::string& path) {
    if (f.is_object() && f.contains("id")) {
        const json& id = f["id"];
        return id.is_string() ? id.get<std::string>() : shown(id);
    }
    return path;
}

void feature_curves(const input_text& in, const json& f, const std::string& path, const std::string& pointer,
                    std::vector<document>& out) {
    if (!f.is_object() || f.value("type", json()) != "Feature")
        fail(in, path, "expected a GeoJSON Feature, got " + shown(f));
    const json& props = f.contains("properties") ? f["properties"] : json();
    if (!f.contains("geometry") || f["geometry"].is_null()) fail(in, path + ".geometry", "a Feature without a geometry is not a curve");
    const json fid = f.contains("id") ? f["id"] : json();
    geometry_curves(in, f["geometry"], path + ".geometry", pointer + "/geometry", feature_id(f, path), fid, props, out);
}

bool is_geojson(const json& root) {
    if (!root.is_object() || !root.contains("type") || !root["type"].is_string()) return false;
    const std::string t = root["type"].get<std::string>();
    for (const char* k : {"FeatureCollection", "Feature", "GeometryCollection", "LineString", "MultiLineString",
                          "Polygon", "MultiPolygon", "Point", "MultiPoint"})
        if (t == k) return true;
    return false;
}

}  // namespace

std::optional<std::vector<document>> json_curves(const document& parsed, const input_text& in) {
    const json& root = parsed.root;
    std::vector<document> out;
    if (root.is_array()) {
        // A list of curve objects: each is the one-curve contract, plus an
        // optional "id" and "properties" carried to the output.
        for (std::size_t i = 0; i < root.size(); ++i) {
            const std::string path = json_index("", i);
            if (!root[i].is_object())
                fail(in, path, "expected a curve object {\"points\": ...}, got " + shown(root[i]));
            document d;
            d.root = root[i];
            d.id = path;
            if (d.root.contains("id")) {
                const json& id = d.root["id"];
                if (!id.is_string() && !id.is_number())
                    fail(in, path + ".id", "expected a string or a number, got " + shown(id));
                d.id = id.is_string() ? id.get<std::string>() : shown(id);
                d.source_id = id;
                d.root.erase("id");
            }
            if (d.root.contains("properties")) {
                d.properties = d.root["properties"];
                d.root.erase("properties");
            }
            out.push_back(std::move(d));
        }
        if (out.empty()) throw input_error(in.name + ": an empty list holds no curve");
        return out;
    }
    if (!is_geojson(root)) return std::nullopt;
    const std::string type = root["type"].get<std::string>();
    if (type == "FeatureCollection") {
        const json& fs = root.contains("features") ? root["features"] : json();
        if (!fs.is_array()) fail(in, "features", "expected an array of Features, got " + shown(fs));
        for (std::size_t i = 0; i < fs.size(); ++i)
            feature_curves(in, fs[i], json_index("features", i), "/features/" + std::to_string(i), out);
    } else if (type == "Feature") {
        feature_curves(in, root, "feature", "", out);
    } else {
        geometry_curves(in, root, "geometry", "", "geometry", json(), json(), out);
    }
    if (out.empty()) throw input_error(in.name + ": the GeoJSON holds no curve");
    return out;
}

// --- SVG path data -----------------------------------------------------------------------

bool looks_like_svg(const std::string& text) {
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    if (first == std::string::npos) return false;
    return text[first] == '<' || text[first] == 'M' || text[first] == 'm';
}

namespace {

struct svg_reader {
    const input_text& in;
    std::string_view d;      // the path data
    std::size_t offset = 0;  // of d in the text, for line numbers
    std::size_t pos = 0;

    std::size_t line_at(std::size_t p) const {
        std::size_t line = 1;
        for (std::size_t i = 0; i < offset + p && i < in.text.size(); ++i) line += in.text[i] == '\n';
        return line;
    }
    [[noreturn]] void fail_here(const std::string& what) const {
        throw input_error(in.name + ": line " + std::to_string(line_at(pos)) + ": path data: " + what);
    }
    void skip() {
        while (pos < d.size() && (std::isspace(static_cast<unsigned char>(d[pos])) || d[pos] == ',')) ++pos;
    }
    bool number_next() {
        skip();
        return pos < d.size() && (std::isdigit(static_cast<unsigned char>(d[pos])) || d[pos] == '-' || d[pos] == '+' || d[pos] == '.');
    }
    double number() {
        skip();
        const char* b = d.data() + pos;
        char* e = nullptr;
        const std::string tmp(b, std::min<std::size_t>(64, d.size() - pos));
        const double x = std::strtod(tmp.c_str(), &e);
        if (e == tmp.c_str() || !std::isfinite(x)) fail_here("expected a finite number");
        pos += std::size_t(e - tmp.c_str());
        return x;
    }
    double flag() {  // arc flags may be written without separators: "a1 1 0 01 10 10"
        skip();
        if (pos < d.size() && (d[pos] == '0' || d[pos] == '1')) return double(d[pos++] - '0');
        fail_here("expected an arc flag 0 or 1");
    }
};

}  // namespace

std::vector<document> svg_curves(const input_text& in) {
    // 1. The path data: every d="..." of a <path> element, or the whole text.
    std::vector<std::pair<std::size_t, std::string_view>> datas;  // (offset, data)
    std::vector<std::string> names;
    const std::string_view text = in.text;
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    if (first != std::string_view::npos && text[first] == '<') {
        for (std::size_t p = text.find("<path"); p != std::string_view::npos; p = text.find("<path", p + 5)) {
            const std::size_t end = text.find('>', p);
            const std::string_view el = text.substr(p, end == std::string_view::npos ? std::string_view::npos : end - p);
            const auto attr = [&](std::string_view name) -> std::optional<std::pair<std::size_t, std::string_view>> {
                for (std::size_t a = el.find(name); a != std::string_view::npos; a = el.find(name, a + 1)) {
                    if (a == 0 || !std::isspace(static_cast<unsigned char>(el[a - 1]))) continue;
                    std::size_t q = a + name.size();
                    while (q < el.size() && std::isspace(static_cast<unsigned char>(el[q]))) ++q;
                    if (q >= el.size() || el[q] != '=') continue;
                    ++q;
                    while (q < el.size() && std::isspace(static_cast<unsigned char>(el[q]))) ++q;
                    if (q >= el.size() || (el[q] != '"' && el[q] != '\'')) continue;
                    const std::size_t close = el.find(el[q], q + 1);
                    if (close == std::string_view::npos) continue;
                    return std::make_pair(p + q + 1, el.substr(q + 1, close - q - 1));
                }
                return std::nullopt;
            };
            const auto dv = attr("d");
            if (!dv) continue;
            datas.push_back(*dv);
            const auto idv = attr("id");
            names.push_back(idv ? std::string(idv->second) : "path " + std::to_string(datas.size()));
        }
        if (datas.empty()) throw input_error(in.name + ": no <path d=\"...\"> element, so no curve");
    } else {
        datas.emplace_back(0, text);
        names.push_back("path");
    }

    // 2. Each subpath: the end points of its commands.
    std::vector<document> out;
    for (std::size_t k = 0; k < datas.size(); ++k) {
        svg_reader r{in, datas[k].second, datas[k].first};
        struct subpath {
            std::vector<double> coords;
            std::vector<std::size_t> lines;
            bool closed = false;
        };
        std::vector<subpath> subs;
        double x = 0, y = 0, sx = 0, sy = 0;
        char cmd = 0;
        const auto add = [&](double nx, double ny) {
            x = nx, y = ny;
            subs.back().coords.push_back(x);
            subs.back().coords.push_back(y);
            subs.back().lines.push_back(r.line_at(r.pos));
        };
        r.skip();
        while (r.pos < r.d.size()) {
            const char c = r.d[r.pos];
            if (std::isalpha(static_cast<unsigned char>(c))) {
                cmd = c;
                ++r.pos;
            } else if (cmd == 0) {
                r.fail_here(std::string("expected a command (M, L, C, ...), got '") + c + "'");
            } else if (cmd == 'M') {
                cmd = 'L';  // further pairs after M are lines
            } else if (cmd == 'm') {
                cmd = 'l';
            }
            const bool rel = std::islower(static_cast<unsigned char>(cmd));
            const double bx = rel ? x : 0, by = rel ? y : 0;
            switch (std::toupper(static_cast<unsigned char>(cmd))) {
                case 'M': {
                    const double nx = bx + r.number(), ny = by + r.number();
                    subs.emplace_back();
                    add(nx, ny);
                    sx = x, sy = y;
                    break;
                }
                case 'Z':
                    if (subs.empty()) r.fail_here("Z before any M");
                    subs.back().closed = true;
                    x = sx, y = sy;
                    cmd = 0;
                    break;
                default: {
                    if (subs.empty()) r.fail_here("a drawing command before any M");
                    if (subs.back().closed) {  // drawing on after Z starts a new subpath at the start point
                        subs.emplace_back();
                        add(sx, sy);
                    }
                    const char u = char(std::toupper(static_cast<unsigned char>(cmd)));
                    if (u == 'L' || u == 'T') {
                        const double nx = bx + r.number(), ny = by + r.number();
                        add(nx, ny);
                    } else if (u == 'H') {
                        add(bx + r.number(), y);
                    } else if (u == 'V') {
                        add(x, (rel ? y : 0) + r.number());
                    } else if (u == 'C') {
                        for (int i = 0; i < 4; ++i) r.number();
                        const double nx = bx + r.number(), ny = by + r.number();
                        add(nx, ny);
                    } else if (u == 'S' || u == 'Q') {
                        r.number(), r.number();
                        const double nx = bx + r.number(), ny = by + r.number();
                        add(nx, ny);
                    } else if (u == 'A') {
                        r.number(), r.number(), r.number(), r.flag(), r.flag();
                        const double nx = bx + r.number(), ny = by + r.number();
                        add(nx, ny);
                    } else {
                        r.fail_here(std::string("unknown command '") + cmd + "'");
                    }
                }
            }
            r.skip();
            if (cmd != 0 && !r.number_next() && r.pos < r.d.size() && !std::isalpha(static_cast<unsigned char>(r.d[r.pos])))
                r.fail_here(std::string("unexpected '") + r.d[r.pos] + "'");
        }
        for (std::size_t s = 0; s < subs.size(); ++s) {
            subpath& sp = subs[s];
            // Z returns to the start: a last point on the start is the repeat.
            const std::size_t n = sp.coords.size() / 2;
            if (sp.closed && n >= 3 && sp.coords[0] == sp.coords[2 * n - 2] && sp.coords[1] == sp.coords[2 * n - 1]) {
                sp.coords.resize(sp.coords.size() - 2);
                sp.lines.pop_back();
            }
            document doc;
            point_set p;
            p.dimension = 2;
            p.coords = std::move(sp.coords);
            p.lines = std::move(sp.lines);
            doc.id = names[k] + (subs.size() > 1 ? " subpath " + std::to_string(s + 1) : "");
            p.name = "points";
            doc.points = std::move(p);
            doc.has_fields = false;
            if (sp.closed) doc.root["end"] = "closed";
            out.push_back(std::move(doc));
        }
    }
    if (out.empty()) throw input_error(in.name + ": the path data holds no curve");
    return out;
}

}  // namespace crspline::cli
