// crspline command line: reading the input and turning the JSON contract into
// a run-time description of the work (dimension known only at run time).
//
// Every problem with the input is reported as an input_error whose message
// names the field, the index and the offending value, e.g.
//   points[3][1]: expected a finite number, got "abc"
// main() prints it as one line, "crspline: <message>", and exits with 2.
#pragma once

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace crspline::cli {

/// Bad input or usage: the message is the whole line after "crspline: ".
class input_error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The raw text of one input and the name used in messages.
struct input_text {
    std::string name;  ///< the file name as given, or "<stdin>"
    std::string text;
};

/// Reads the file named on the command line; "-" or "" reads stdin.
/// Throws input_error "NAME: cannot open: <reason>" and the like.
input_text read_input(const std::string& path);

/// Points stored flat: point i is coords[i * dimension .. (i + 1) * dimension).
/// Every coordinate is finite and every point has the same dimension 1..16.
struct point_set {
    std::size_t dimension = 0;
    std::vector<double> coords;
    std::string name = "points";  ///< what messages call them: "points", or the CSV file's name
    std::size_t size() const noexcept { return dimension == 0 ? 0 : coords.size() / dimension; }
};

/// A parsed input: the JSON fields, and the points when they were read flat
/// (a CSV file, or the JSON "points" array read without building a tree).
struct document {
    nlohmann::json root = nlohmann::json::object();
    std::optional<point_set> points;  ///< when set, root["points"] is ignored
};

/// Parses JSON text. Syntax errors become "NAME: line L, column C: <what>"
/// (column counted in bytes, the offending character's own position);
/// numbers too large for a double become "FIELD: expected a finite number,
/// got 1e999"; duplicate keys in an object are rejected.
nlohmann::json parse_json(const input_text& in);

/// Like parse_json, but a well-formed "points" array at the top level (arrays
/// of 1 to 16 numbers, all the same length) is read into document::points
/// without building a JSON tree for it: ten million points load in seconds.
/// Anything else in "points" falls back to the tree, so that validation
/// reports it exactly as parse_json's tree would.
document parse_json_document(const input_text& in);

/// One end of an open curve.
struct end_spec {
    enum class kind { natural, reflect, tangent };
    kind type = kind::natural;
    std::vector<double> velocity;  ///< dx/dt, one value per dimension, for kind::tangent
};

/// Everything needed to build a curve, in run-time form.
struct curve_spec {
    std::size_t dimension = 0;        ///< 1..16
    std::vector<double> coords;       ///< the points, flat (point_set layout)
    std::size_t point_count() const noexcept { return dimension == 0 ? 0 : coords.size() / dimension; }
    std::optional<double> alpha;      ///< none with a grid; default 0.5 otherwise
    std::optional<std::vector<double>> grid;
    bool closed = false;
    end_spec start, end;
    double tension = 0;
    std::vector<double> kb_tension, kb_continuity, kb_bias;  ///< empty = zeros
    bool strict = false;
    /// Given tangents dx/dt per point (flat, like coords): the curve is the
    /// cubic Hermite curve through the points with them (catmull_rom::hermite).
    /// Empty: tangents computed. tangents_in empty: incoming = outgoing.
    std::vector<double> tangents_out, tangents_in;
};

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
inline constexpr std::string_view curve_fields[] = {"points", "alpha", "grid", "end", "tension", "kb", "strict",
                                                    "tangents"};

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


/// Shortest text that reads back to the same double (for messages).
std::string format_number(double x);

}  // namespace crspline::cli
