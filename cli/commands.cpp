// crspline command line: the table of subcommands, their help texts, and the
// rendering of their output.
#include "commands.hpp"

#include <cmath>
#include <string>

#include "json_input.hpp"

namespace crspline::cli {

namespace {

// The part of the contract every subcommand shares.
#define CRSPLINE_CLI_CURVE_FIELDS                                                                   \
    "Input: one JSON object, read from the file 'input', or from stdin when it is '-' or absent;\n"  \
    "or CSV/TSV points (one point per line, see 'Points from CSV'). The options below override\n"  \
    "the JSON fields; with CSV input they are the only way to set them.\n"                        \
    "  \"points\": [[x, y, ...], ...]   required; 1 to 16 coordinates, the same for every point\n" \
    "  \"alpha\": 0.5                   knot exponent in [0, 1] (0 uniform, 0.5 centripetal,\n"    \
    "                                 1 chordal); default 0.5\n"                                   \
    "  \"grid\": [t0, t1, ...]          explicit knots instead of alpha (one per point, one more\n" \
    "                                 for a closed curve)\n"                                       \
    "  \"end\": \"natural\"               or \"reflect\", \"closed\", or per end\n"                \
    "                                 {\"start\": E, \"end\": E}, E = \"natural\" | \"reflect\" |\n" \
    "                                 [dx/dt, ...]; default \"natural\"\n"                          \
    "  \"tension\": 0                   in [0, 1]: computed tangents scaled by 1 - tension\n"       \
    "  \"kb\": {\"tension\": [...], \"continuity\": [...], \"bias\": [...]}\n"                      \
    "                                 Kochanek-Bartels, one value per point (null allowed at\n"    \
    "                                 the two ends of an open curve); a missing array = zeros\n"   \
    "  \"strict\": false                reject coincident consecutive points\n"                     \
    "  \"tangents\": [[dx/dt, ...], ...] given tangents, one per point (or {\"in\": [...],\n"      \
    "                                 \"out\": [...]} when they differ): a cubic Hermite curve;\n"  \
    "                                 not with \"tension\", \"kb\", \"strict\" or end conditions\n"

#define CRSPLINE_CLI_CSV_AND_ERRORS                                                                 \
    "Points from CSV: one point per line, 1 to 16 numbers; '#' lines skipped; a first line\n"       \
    "without numbers is a header; delimiter , ; tab or blanks (detected, or --delimiter);\n"      \
    "--columns x,y (header names) or --columns 2,3 (numbered from 1) chooses columns. The\n"      \
    "format comes from --input-format, else the extension (.json, .geojson, .csv, .tsv, .svg),\n" \
    "else the first character ('{' or '[' is JSON, '<' or 'M' SVG).\n"                             \
    "Many curves: a JSON list of curve objects, GeoJSON, SVG path data, CSV with blank lines\n"  \
    "between curves or --curve-column; one result per curve: [{\"id\", \"properties\", \"result\"}].\n" \
    "\n"                                                                                           \
    "Output: stdout, or -o FILE (written whole or not at all); the format from --format, else\n"  \
    "the extension of FILE.\n"                                                                    \
    "\n"                                                                                           \
    "Errors: exit status 2 and one line on stderr naming the file, line and column (or the\n"     \
    "field or option, and the index) and what was expected."

constexpr std::string_view eval_details =
    CRSPLINE_CLI_CURVE_FIELDS
    "One of:\n"
    "  \"t\": [...]                     the curve's parameter, in [grid[0], grid[last]] (the\n"
    "                                 knots: 0, 1, 2, ... only for alpha 0)\n"
    "  \"u\": [...]                     in [0, 1] over the whole curve, each segment an equal\n"
    "                                 share (three.js getPoint); the output adds \"t_of_u\"\n"
    "  \"arc_fraction\": [...]          in [0, 1], a fraction of the arc length (three.js\n"
    "                                 getPointAt); the output adds \"t_of_arc_fraction\"\n"
    "  \"s\": [...]                     arc lengths from the start in [0, length]; the output\n"
    "                                 adds \"t_of_s\"; \"accuracy\": 1e-12 (relative), also\n"
    "                                 for arc_fraction\n"
    "  \"derivatives\": [0]             orders to evaluate, each 0..3, no repeats\n"
    "  \"knots\": false                 true: the output starts with the knot \"grid\"\n"
    "\n"
    "Output: {\"values\": {\"0\": [[x, y], ...], \"1\": ...}}, one key per requested order\n"
    "(d^k x / dt^k), in the order requested.\n"
    "\n"
    "Example:\n"
    "  echo '{\"points\": [[0, 0], [1, 1], [2, 0]], \"u\": [0, 0.25, 0.5, 1]}' | crspline eval\n"
    "  {\"t_of_u\":[0.0,0.5946035575013605,1.189207115002721,2.378414230005442],\"values\":\n"
    "   {\"0\":[[0.0,0.0],[0.5,0.6875],[1.0,1.0],[2.0,0.0]]}}\n"
    "\n"
    "More examples:\n"
    "  crspline eval --t 0,0.5,1 --derivatives 0,1 --format csv points.csv\n"
    "  crspline eval --arc-fraction 0,0.5,1 --precision 6 --format csv points.csv\n"
    "  crspline eval --centripetal --s 0,1,2 -o out.csv curve.json\n"
    "\n" CRSPLINE_CLI_CSV_AND_ERRORS;

constexpr std::string_view bezier_details =
    CRSPLINE_CLI_CURVE_FIELDS
    "\n"
    "Output: {\"grid\": [...], \"segments\": [[B0, B1, B2, B3], ...]}: the cubic Bezier control\n"
    "points of segment i, from points[i] to the next point, on [grid[i], grid[i+1]].\n"
    "\n"
    "Example:\n"
    "  echo '{\"points\": [[0, 0], [1, 1], [2, 0]], \"alpha\": 0}' | crspline bezier\n"
    "  {\"grid\":[0.0,1.0,2.0],\"segments\":[[[0.0,0.0],[0.3333333333333333,0.5],\n"
    "   [0.6666666666666667,1.0],[1.0,1.0]],[[1.0,1.0],[1.3333333333333333,1.0],\n"
    "   [1.6666666666666667,0.5],[2.0,0.0]]]}\n"
    "\n"
    "More examples:\n"
    "  crspline bezier --format svg-path points.csv        the SVG path d string\n"
    "  crspline bezier --chordal --closed -o curve.svg points.csv\n"
    "\n" CRSPLINE_CLI_CSV_AND_ERRORS;

constexpr std::string_view length_details =
    CRSPLINE_CLI_CURVE_FIELDS
    "  \"accuracy\": 1e-12              relative accuracy of the lengths, in (0, 1)\n"
    "\n"
    "Output: {\"total\": L, \"segments\": [L0, L1, ...], \"accuracy\": a}: arc lengths by adaptive\n"
    "Gauss-Legendre quadrature, each within a * length of the exact value.\n"
    "\n"
    "Example:\n"
    "  echo '{\"points\": [[0, 0], [3, 4], [6, 0]]}' | crspline length\n"
    "\n"
    "  crspline length --columns x,y --uniform track.csv\n"
    "\n" CRSPLINE_CLI_CSV_AND_ERRORS;

constexpr std::string_view sample_details =
    CRSPLINE_CLI_CURVE_FIELDS
    "  \"count\": n                     n >= 2 points from the start to the end, evenly spaced\n"
    "  \"spacing\": \"t\"                 in the parameter, or \"arc_length\"\n"
    "  \"tolerance\": d                 instead of count: polyline vertices such that the\n"
    "                                 polyline is within distance d of the curve, few vertices\n"
    "  \"accuracy\": 1e-12              relative accuracy of arc lengths (spacing arc_length)\n"
    "\n"
    "Output: {\"t\": [...], \"points\": [[x, y], ...]} plus \"s\" (arc lengths) for\n"
    "arc-length spacing and \"tolerance\" for a tolerance.\n"
    "\n"
    "Examples:\n"
    "  echo '{\"points\": [[0, 0], [1, 1], [2, 0]], \"count\": 5, \"spacing\": \"arc_length\"}' \\\n"
    "    | crspline sample\n"
    "  echo '{\"points\": [[0, 0], [1, 1], [2, 0]], \"tolerance\": 0.001}' | crspline sample\n"
    "\n"
    "  crspline sample --count 100 --spacing arc_length --format csv points.csv\n"
    "\n" CRSPLINE_CLI_CSV_AND_ERRORS;

constexpr std::string_view analyze_details =
    "Input: the curve, as for 'crspline bezier' (JSON fields or CSV points plus options).\n"
    "\n"
    "Output (JSON): the analysis report, the same keys and values as Python's\n"
    "CatmullRom.analyze() and the web module's Spline.analyze() (docs/report.md):\n"
    "  {\"dimension\": d, \"segments\": [{\"index\": i, \"bezier\": [B0, B1, B2, B3], \"cusp_u\": [...],\n"
    "                 \"cusp_t\": [...], \"self_intersection_u\": [[u, v], ...], \"fold\": false,\n"
    "                 \"max_chord_distance\": d, \"max_chord_line_distance\": d,\n"
    "                 \"distance_bound\": b, \"bounds\": {...}, ...}, ...],\n"
    "   \"cusp_t\": [...], \"has_cusp\": false, \"has_self_intersection\": false,\n"
    "   \"intersections\": [{\"segments\": [i, j], \"u\": [u_i, u_j], \"t\": [t_i, t_j],\n"
    "                      \"point\": [x, y], \"distance\": 0}, ...],\n"
    "   \"overlaps\": [{\"segments\": [i, j], \"u\": [u0, u1], \"v\": [v0, v1]}, ...],\n"
    "   \"folds\": [...], \"complete\": true,\n"
    "   \"certificate\": {\"certified\": true, \"failed_rule\": null, \"detail\": \"\", ...}}\n"
    "u is local to its segment, in [0, 1]; t global. max_chord_distance: to the closed chord\n"
    "segment from points[i] to the next point; max_chord_line_distance: to its line;\n"
    "distance_bound: the paper's Eq. 6 (two-sided form) for interior segments of a plain curve,\n"
    "else null. intersections: crossings between segments, and loops inside one (i == j);\n"
    "complete: false if the search ran out of its work budget. certified: the paper's\n"
    "Section 5 rules prove there is no self-intersection (centripetal curves only).\n"
    "overlaps: stretches where two segments run together (collinear overlaps), one interval\n"
    "[u0, u1] on segment i and [v0, v1] on segment j per pair instead of a point per crossing.\n"
    "--summary (\"summary\": true): counts instead of lists: {\"dimension\", \"segment_count\",\n"
    "\"cusps\", \"loops\", \"intersections\", \"overlaps\", \"folds\", \"complete\", \"certificate\"}.\n"
    "--no-intersections (\"search\": false): no search; its fields are null.\n"
    "\n"
    "Example:\n"
    "  crspline analyze --uniform points.csv\n"
    "  crspline analyze --summary --no-intersections track.csv\n"
    "  echo '{\"points\": [[0, 0], [1, 1], [1.1, 1], [2, 0]], \"alpha\": 0}' | crspline analyze\n"
    "\n" CRSPLINE_CLI_CSV_AND_ERRORS;

constexpr std::string_view plot_details =
    "Input: the curve, as for 'crspline bezier' (JSON fields or CSV points plus options).\n"
    "\n"
    "Draws the points, the control polygon and one curve per alpha (--alpha 0,0.5,1 or the\n"
    "presets together: uniform, centripetal and chordal in distinct colours, with a legend),\n"
    "each segment an exact cubic Bezier, on axes scaled to the data, with a title. Overlays:\n"
    "  --cusps            cusps (zero speed inside a segment), marked x\n"
    "  --intersections    self-intersections, marked o\n"
    "  --volumes          the paper's bounding volumes (Eq. 6 boxes, Eq. 8 balls)\n"
    "  --comb [SCALE]     curvature comb (teeth of length SCALE * curvature; auto by default)\n"
    "  --handles          Bezier handles B0-B1 and B2-B3\n"
    "  --ticks [STEP]     arc-length ticks every STEP (auto by default)\n"
    "  --all              all of them\n"
    "Output: SVG, or PNG with --format png or -o FILE.png; --png FILE writes a PNG as well.\n"
    "\n"
    "Examples:\n"
    "  crspline plot --alpha 0,0.5,1 --cusps --intersections -o figure.svg --png figure.png pts.csv\n"
    "  crspline plot --centripetal --volumes --comb --title 'Centripetal' curve.json -o c.png\n"
    "\n" CRSPLINE_CLI_CSV_AND_ERRORS;

constexpr std::string_view demo_details =
    "The paper's comparison on an embedded control polygon (the README figure's): the uniform\n"
    "curve loops, the chordal one overshoots, the centripetal one does neither. Writes\n"
    "DIR/demo.svg and DIR/demo.png (DIR from -o, default the current folder) and prints a\n"
    "table per parameterization: arc length, cusps, self-intersections, maximum distance to\n"
    "the control polygon, certified intersection-free or not.\n"
    "\n"
    "Example:\n"
    "  crspline demo -o figures\n";

#undef CRSPLINE_CLI_CURVE_FIELDS
#undef CRSPLINE_CLI_CSV_AND_ERRORS

constexpr command all_commands[] = {
    {"eval", "Positions and derivatives at parameter values t", eval_details, &run_eval, "json csv tsv svg",
     &stream_eval},
    {"bezier", "Cubic Bezier control points of every segment", bezier_details, &run_bezier,
     "json csv tsv svg svg-path", &stream_bezier},
    {"length", "Arc length of the curve and of each segment", length_details, &run_length, "json csv tsv"},
    {"sample", "Points evenly spaced in t or arc length, or within a tolerance", sample_details, &run_sample,
     "json csv tsv svg svg-path geojson", &stream_sample},
    {"analyze", "Cusps, self-intersections, distances to the polygon, certificate", analyze_details, &run_analyze,
     "json", &stream_analyze},
    {"plot", "A figure of the curve(s) with overlays, as SVG or PNG", plot_details, nullptr, "svg png"},
    {"demo", "Uniform vs centripetal vs chordal: the paper's figure and a table", demo_details, nullptr, ""},
};

// First non-finite number in the output, with its path; empty when none.
std::string first_non_finite(const output_json& v, const std::string& path) {
    if (v.is_number_float()) return std::isfinite(v.get<double>()) ? std::string() : path;
    if (v.is_array()) {
        for (std::size_t i = 0; i < v.size(); ++i)
            if (auto p = first_non_finite(v[i], path + "[" + std::to_string(i) + "]"); !p.empty()) return p;
    } else if (v.is_object()) {
        for (const auto& [key, value] : v.items())
            if (auto p = first_non_finite(value, path.empty() ? key : path + "[\"" + key + "\"]"); !p.empty())
                return p;
    }
    return {};
}

}  // namespace

std::span<const command> commands() { return all_commands; }

output_json run_streamed(void (*stream)(const document&, const output_settings&, output_stream&),
                         const document& input) {
    output_stream text = output_stream::in_memory();
    stream(input, {}, text);
    return output_json::parse(std::move(text).take());
}

std::string render(const output_json& out, const number_format& numbers) {
    if (const std::string bad = first_non_finite(out, ""); !bad.empty())
        throw input_error(bad + ": the result is not finite (the input's coordinates or knot intervals are "
                                "too extreme for double arithmetic)");
    if (numbers.precision == 0) return out.dump() + "\n";
    // --precision: every float rounded to that many significant digits, then
    // written as the shortest text that reads back to the rounded value.
    output_json rounded = out;
    const auto round_all = [&](auto& self, output_json& v) -> void {
        if (v.is_number_float()) v = round_to_precision(v.get<double>(), numbers.precision);
        else if (v.is_structured())
            for (auto& x : v) self(self, x);
    };
    round_all(round_all, rounded);
    return rounded.dump() + "\n";
}

}  // namespace crspline::cli
