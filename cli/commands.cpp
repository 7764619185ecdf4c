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
    "Input: one JSON object, read from the file 'input', or from stdin when it is '-' or absent.\n" \
    "  \"points\": [[x, y, ...], ...]   required; 1 to 4 coordinates, the same for every point\n"  \
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
    "  \"strict\": false                reject coincident consecutive points\n"

constexpr std::string_view eval_details =
    CRSPLINE_CLI_CURVE_FIELDS
    "  \"t\": [...]                     parameter values in [grid[0], grid[last]], or\n"
    "  \"s\": [...]                     arc lengths from the start in [0, length]; the output\n"
    "                                 then also has \"t_of_s\"; \"accuracy\": 1e-12 (relative)\n"
    "  \"derivatives\": [0]             orders to evaluate, each 0..3, no repeats\n"
    "\n"
    "Output: {\"grid\": [...], \"values\": {\"0\": [[x, y], ...], \"1\": ...}}, one key per\n"
    "requested order (d^k x / dt^k), in the order requested.\n"
    "\n"
    "Example:\n"
    "  echo '{\"points\": [[0, 0], [1, 1], [2, 0]], \"alpha\": 0, \"t\": [0, 0.5, 2],\n"
    "         \"derivatives\": [0, 1]}' | crspline eval\n"
    "  {\"grid\":[0.0,1.0,2.0],\"values\":{\"0\":[[0.0,0.0],[0.5,0.6875],[2.0,0.0]],\n"
    "   \"1\":[[1.0,1.5],[1.0,1.125],[1.0,-1.5]]}}\n"
    "\n"
    "Errors: exit status 2 and one line on stderr naming the field, index and value.";

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
    "Errors: exit status 2 and one line on stderr naming the field, index and value.";

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
    "Errors: exit status 2 and one line on stderr naming the field, index and value.";

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
    "Errors: exit status 2 and one line on stderr naming the field, index and value.";

#undef CRSPLINE_CLI_CURVE_FIELDS

constexpr command all_commands[] = {
    {"eval", "Positions and derivatives at parameter values t", eval_details, &run_eval},
    {"bezier", "Cubic Bezier control points of every segment", bezier_details, &run_bezier},
    {"length", "Arc length of the curve and of each segment", length_details, &run_length},
    {"sample", "Points evenly spaced in t or arc length, or within a tolerance", sample_details, &run_sample},
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

std::string render(const output_json& out) {
    if (const std::string bad = first_non_finite(out, ""); !bad.empty())
        throw input_error(bad + ": the result is not finite (the input's coordinates or knot intervals are "
                                "too extreme for double arithmetic)");
    return out.dump() + "\n";
}

}  // namespace crspline::cli
