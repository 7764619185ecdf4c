// crspline command line: reading an input, and parsing JSON with the path of
// every value known while it is read.
//
// The parser reports a syntax error by file, line and column, a number too
// large for a double by its field ("points[3][1]: expected a finite number,
// got 1e999"), and a duplicate key by its object; the top-level "points" of a
// curve is read flat, without a JSON tree (ten million points in seconds).
// What the fields mean is the input contract's business (json_input.hpp).
#pragma once

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace crspline::cli {

struct cli_options;  // options.hpp: the command line's flags

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
    /// Where each point is, for messages: its 1-based line in a text file
    /// (CSV), or empty when points are named by `path` and their index.
    std::vector<std::size_t> lines;
    std::string path = "points";  ///< JSON path of the points' array ("features[2].geometry.coordinates[0]")
    std::vector<std::string> notes;  ///< what reading them noticed, for stderr (the columns a CSV file gave)
    /// The header's names of the coordinate columns read (CSV with a header
    /// line; empty otherwise), one per coordinate, for axis labels.
    std::vector<std::string> column_names;
    /// Several curves in one text (CSV blocks or a curve-id column): the
    /// first point of each, and its id. Empty: one curve.
    std::vector<std::size_t> curve_starts;
    std::vector<std::string> curve_ids;
    std::size_t size() const noexcept { return dimension == 0 ? 0 : coords.size() / dimension; }
};

/// One curve's input: its JSON fields, and the points when they were read
/// flat (CSV, GeoJSON, SVG path data, or the JSON "points" array read
/// without building a tree). When the input holds many curves, each is a
/// document of its own.
struct document {
    nlohmann::json root = nlohmann::json::object();
    std::optional<point_set> points;  ///< when set, root["points"] is ignored
    /// The command line's flags, which override the JSON fields (null: none).
    const cli_options* flags = nullptr;
    std::string file;        ///< the input's name for messages ("" when not known)
    std::string id;          ///< the curve's name in messages when the input holds many ("" for one)
    nlohmann::json properties;  ///< what the input says about the curve (GeoJSON properties), carried to the output
    nlohmann::json source_id;   ///< the input's own id value (a Feature's or a list item's "id"), null when none
    /// A curve read from GeoJSON: the JSON pointer of its positions in the
    /// input ("/features/1/geometry/coordinates/0"), so that an output can
    /// put the result in the same place (a Polygon's ring stays its ring).
    std::optional<std::string> geojson_pointer;
    bool has_fields = true;  ///< the input can hold JSON fields (false: CSV, GeoJSON, SVG: only flags)
    /// What reading the curve noticed and changed (a closed ring's repeated
    /// first point dropped), for one line each on stderr.
    mutable std::vector<std::string> notes;
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

/// Shortest text that reads back to the same double (for messages).
std::string format_number(double x);

}  // namespace crspline::cli
