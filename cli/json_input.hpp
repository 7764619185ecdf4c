// crspline command line: the input contract. A curve's JSON fields and the
// command-line flags become one run-time description of the work (dimension
// known only at run time); the flags are read directly, not merged into the
// JSON, so that every message names what the user wrote: the JSON field's
// path or the flag.
//
// The contract checks shapes only (an array where an array belongs, a number
// where a number does, known field names); what the values must be (alpha
// in [0, 1], an increasing grid of the right length, two points at least...)
// is the core's validate() (crspline/spec.hpp), whose spec_error is rendered
// here with the file, the point's line or JSON path, or the flag:
//   points[3][1]: expected a finite number, got "abc"       (shape)
//   --alpha: alpha must be in [0, 1], got 1.5                (the core's words)
// Every problem is an input_error; main() prints it as one line,
// "crspline: <message>", and exits with 2. Reading and parsing the text is
// json_parser.hpp's and csv_input.hpp's.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <crspline/error.hpp>
#include <crspline/spec.hpp>
#include <nlohmann/json.hpp>

#include "json_parser.hpp"

namespace crspline::cli {

/// A curve as the command line describes it: the core's specification
/// (crspline/spec.hpp: points, alpha or grid, ends, tension, Kochanek-Bartels
/// values, strict), which the core validates and builds, plus what only the
/// command line has: given tangents (a Hermite curve), where the points came
/// from, and which fields a flag set, so that the core's messages name the
/// flag the user wrote.
struct curve_spec : crspline::curve_spec {
    /// Given tangents dx/dt per point (flat, like points): the curve is the
    /// cubic Hermite curve through the points with them (catmull_rom::hermite).
    /// Empty: tangents computed. tangents_in empty: incoming = outgoing.
    std::vector<double> tangents_out, tangents_in;
    /// Where the points are, for messages about one of them: the file, and
    /// each point's line (CSV) or the JSON path of their array.
    std::string file;
    std::vector<std::size_t> lines;
    std::string points_path = "points";
    /// The specification's fields set by a flag: {"alpha", "--alpha"}, ...
    std::vector<std::pair<std::string, std::string>> flags;

    const crspline::curve_spec& core() const noexcept { return *this; }
};

/// Where point i (0-based) of the curve is, as a user finds it: "line 7
/// (point 3)" in a text file, "points[2]" in JSON.
std::string point_location(const curve_spec& c, std::size_t i);

/// The core's spec_error about the description rendered for the command
/// line: the core's words after the file, a point's location as the user
/// finds it (line, or JSON path), or the flag that set the field.
/// A JSON value as an error message shows it: a number as format_number
/// writes it, anything else as JSON text cut at 40 characters.
std::string describe_json(const nlohmann::json& v);

/// The path of element i of the array at `path`: "points[3]".
std::string json_index(const std::string& path, std::size_t i);

std::string describe_spec_error(const crspline::spec_error& e, const curve_spec& c);

/// `crspline eval`: the curve, the parameters (t, or arc lengths s) and the
/// derivative orders.
struct eval_spec {
    curve_spec curve;
    std::vector<double> t;
    std::optional<std::vector<double>> s;  ///< arc lengths from the start instead of t
    /// Normalised parameters in [0, 1] instead of t: u, each segment an equal
    /// share (three.js getPoint); arc_fraction, a fraction of the length
    /// (three.js getPointAt).
    std::optional<std::vector<double>> u, arc_fraction;
    bool knots = false;                    ///< the output includes the knot grid
    double accuracy = 1e-12;               ///< relative accuracy of arc lengths
    std::vector<int> derivatives;          ///< distinct, each 0..3, in the order requested
    std::string param_name = "t";         ///< what messages call the parameters given: the JSON field or the flag
};

/// `crspline length`: the curve and the relative accuracy.
struct length_spec {
    curve_spec curve;
    double accuracy = 1e-12;
};

/// `crspline sample`: n points evenly spaced in t or in arc length, or the
/// vertices of a polyline within a distance tolerance of the curve.
struct sample_spec {
    curve_spec curve;
    enum class kind { count_t, count_arc_length, tolerance };
    kind by = kind::count_t;
    std::size_t count = 0;
    double tolerance = 0;
    double accuracy = 1e-12;
};

/// `crspline bezier`: the curve alone.
struct bezier_spec {
    curve_spec curve;
};

/// The fields every subcommand reads to describe a curve.
inline constexpr std::string_view curve_fields[] = {"points", "alpha", "grid", "closed", "start", "end", "tension",
                                                    "kb", "strict", "tangents"};

/// Validates the curve part of a document. `extra_fields` are the other
/// top-level keys the subcommand reads itself; any key in neither list is an
/// error ("unknown field 'foo'"), so typos do not pass silently. `command`
/// names the subcommand in the message for a field another subcommand takes.
curve_spec parse_curve(const document& doc, std::string_view command,
                       std::initializer_list<std::string_view> extra_fields);

eval_spec parse_eval(const document& doc);
length_spec parse_length(const document& doc);
sample_spec parse_sample(const document& doc);
bezier_spec parse_bezier(const document& doc);

/// `crspline analyze` and `crspline plot` read the curve alone.
curve_spec parse_analyze(const document& doc);

}  // namespace crspline::cli
