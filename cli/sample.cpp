// crspline sample: points evenly spaced in t or in arc length, or the
// vertices of a polyline within a distance tolerance of the curve; as JSON,
// CSV/TSV, SVG path data ("M x y L x y ...") or a GeoJSON LineString.
#include <algorithm>
#include <span>
#include <string>
#include <vector>

#include <crspline/arc_length.hpp>
#include <crspline/tessellate.hpp>

#include "commands.hpp"
#include "dispatch.hpp"
#include "json_input.hpp"
#include "rotation_commands.hpp"

namespace crspline::cli {

void stream_sample(const document& input, const output_settings& settings, output_stream& out) {
    if (is_rotation_document(input)) return stream_rotation(input, settings, out, "sample");  // issue 28
    const sample_spec spec = parse_sample(input);
    with_dimension(spec.curve.dimension, [&](auto dim) {
        constexpr std::size_t D = decltype(dim)::value;
        const catmull_rom<D, double> curve = make_curve<D>(spec.curve);
        const std::size_t dimension = std::min(spec.curve.dimension, D);
        const std::string& format = settings.format;
        if (format == "svg-path" && dimension != 2)
            throw input_error("--format svg-path: needs 2-D points, got " + std::to_string(spec.curve.dimension) +
                              "-D (use json or csv)");
        if (format == "geojson" && dimension != 2 && dimension != 3)
            throw input_error("--format geojson: needs 2-D or 3-D points, got " + std::to_string(spec.curve.dimension) +
                              "-D (use json or csv)");

        // 1. The samples.
        std::vector<double> t, s;
        std::vector<vec<D, double>> points;
        switch (spec.by) {
            case sample_spec::kind::count_t: {
                t.resize(spec.count);
                const double lo = curve.t_min(), hi = curve.t_max();
                for (std::size_t k = 0; k < spec.count; ++k)
                    t[k] = lo + (hi - lo) * (double(k) / double(spec.count - 1));
                t.back() = hi;
                points = curve.evaluate(std::span<const double>(t));
                break;
            }
            case sample_spec::kind::count_arc_length: {
                auto smp = sample_arc_length(curve, spec.count, spec.accuracy);
                t = std::move(smp.t);
                points = std::move(smp.points);
                s = std::move(smp.s);
                break;
            }
            case sample_spec::kind::tolerance: {
                auto line = tessellate(curve, spec.tolerance);
                t = std::move(line.t);
                points = std::move(line.points);
                break;
            }
        }
        const bool with_s = spec.by == sample_spec::kind::count_arc_length;
        const bool with_tolerance = spec.by == sample_spec::kind::tolerance;

        // 2. The output.
        const number_format& nf = settings.numbers;
        std::string& buf = out.buffer();
        const auto coord = [&](std::size_t i, std::size_t k, bool json) {
            out.number(points[i][k], nf, json,
                       [&] { return "points[" + std::to_string(i) + "][" + std::to_string(k) + "]"; });
        };
        const auto list = [&](const char* key, const std::vector<double>& xs) {
            out.json_list(key, xs, nf);
            buf += ',';
        };
        const auto point_list = [&] {
            buf += '[';
            for (std::size_t i = 0; i < points.size(); ++i) {
                buf += i ? ",[" : "[";
                for (std::size_t k = 0; k < dimension; ++k) {
                    if (k) buf += ',';
                    coord(i, k, true);
                }
                buf += ']';
                out.written();
            }
            buf += ']';
        };
        if (format == "json") {
            // {"s": [...] | "tolerance": d, "t": [...], "points": [[x, y], ...]}
            buf += '{';
            if (with_s) list("s", s);
            if (with_tolerance) {
                buf += "\"tolerance\":";
                out.number(spec.tolerance, {}, true, [] { return std::string("tolerance"); });
                buf += ',';
            }
            list("t", t);
            buf += "\"points\":";
            point_list();
            out.put("}\n");
        } else if (format == "geojson") {
            // One Feature: the polyline as a LineString, how it was sampled
            // in its properties (t per vertex is in the JSON output).
            buf += "{\"type\":\"Feature\",\"properties\":{";
            if (with_tolerance) {
                buf += "\"tolerance\":";
                out.number(spec.tolerance, {}, true, [] { return std::string("tolerance"); });
            } else {
                buf += "\"count\":" + std::to_string(spec.count) + ",\"spacing\":\"" + (with_s ? "arc_length" : "t") + "\"";
            }
            buf += spec.curve.closed ? ",\"closed\":true" : ",\"closed\":false";
            buf += "},\"geometry\":{\"type\":\"LineString\",\"coordinates\":";
            point_list();
            out.put("}}\n");
        } else if (format == "svg-path") {
            // "M x0 y0 L x1 y1 ...", " Z" for a closed curve (its last sample
            // is its first point: Z closes with a join instead of caps).
            const std::size_t last = spec.curve.closed && points.size() > 1 ? points.size() - 1 : points.size();
            for (std::size_t i = 0; i < last; ++i) {
                buf += i == 0 ? "M " : " L ";
                coord(i, 0, false);
                buf += ' ';
                coord(i, 1, false);
                out.written();
            }
            if (spec.curve.closed) buf += " Z";
            out.put("\n");
        } else {
            // CSV / TSV: t, [s,] x, y, ...
            const char sep = format == "tsv" ? '\t' : ',';
            static const char* const axes[] = {"x", "y", "z", "w"};
            buf += with_s ? std::string("t") + sep + "s" : std::string("t");
            for (std::size_t k = 0; k < dimension; ++k) buf += sep + (k < 4 ? std::string(axes[k]) : "x" + std::to_string(k + 1));
            buf += '\n';
            for (std::size_t i = 0; i < points.size(); ++i) {
                out.number(t[i], nf, false, [&] { return "t[" + std::to_string(i) + "]"; });
                if (with_s) {
                    buf += sep;
                    out.number(s[i], nf, false, [&] { return "s[" + std::to_string(i) + "]"; });
                }
                for (std::size_t k = 0; k < dimension; ++k) {
                    buf += sep;
                    coord(i, k, false);
                }
                buf += '\n';
                out.written();
            }
        }
    });
}

output_json run_sample(const document& input) { return run_streamed(&stream_sample, input); }

}  // namespace crspline::cli
