// crspline command line: the options every subcommand shares, how the input
// is loaded (JSON, CSV/TSV, stdin), and how options override the JSON fields.
//
// The flags are not merged into the JSON: each curve's document points to
// them, and the input contract (json_input.hpp) reads a flag where it reads
// the field it overrides, so that its messages name the flag
// ("--alpha: must be in [0, 1], got 1.5").
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "json_input.hpp"

namespace crspline::cli {

/// Every option, as given (an empty string: not given).
struct cli_options {
    std::string command;
    // Input.
    std::string input = "-";
    std::string input_format;  ///< json | csv | tsv; empty: by extension, else by content
    std::string columns, delimiter;
    std::string curve_column;  ///< CSV: the column whose value names the curve (many curves per file)
    // Output.
    std::string output, format;
    // The curve.
    std::string alpha;
    bool uniform = false, centripetal = false, chordal = false;
    std::string grid, start, end;
    bool closed = false, strict = false;
    std::string tension, kb_tension, kb_continuity, kb_bias;
    // eval, length, sample.
    std::string t, s, derivatives, accuracy, count, spacing, tolerance;
    // Output numbers and eval's normalised parameters (output side).
    std::string precision, u, arc_fraction;
    bool knots = false;
    bool summary = false, no_search = false;  ///< analyze
    std::string aspect, xlim, ylim;           ///< plot: equal | auto; A,B ranges
    std::string pair;                         ///< plot: the two coordinates drawn of a 3-D or higher curve, "I,J" from 1
    bool no_points = false;                   ///< plot: no point markers
    // plot.
    std::string title, size, png, ticks, comb;
    bool comb_on = false, ticks_on = false;
    bool cusps = false, intersections = false, volumes = false, handles = false, all_overlays = false;
};

/// The curves of an input, one document each, with the flags attached.
struct loaded_input {
    std::string name;               ///< the input's name in messages
    std::vector<document> curves;   ///< at least one
    bool many = false;              ///< a many-curve input: one result per curve, in order
    /// A GeoJSON input as read (its curves point into it: document::geojson_pointer);
    /// null for any other input.
    nlohmann::json geojson;
};

/// Reads and parses the input named by the options: its curves, each
/// pointing to the flags that override its fields.
loaded_input load_input(const cli_options& o);

/// The alpha values asked for with --alpha LIST and the presets, in order
/// (plot draws one curve per value); empty when none was given.
std::vector<double> alpha_values(const cli_options& o);

/// The output format: --format, else the extension of -o, else `fallback`.
/// Throws input_error when it is not one of `allowed`.
std::string output_format(const cli_options& o, const std::vector<std::string>& allowed, const std::string& fallback);

/// --precision as a number of significant digits (0: not given, shortest).
int precision_of(const cli_options& o);

/// Writes the bytes to the file (through a temporary file in the same folder
/// and a rename, so that nothing partial is left behind), or to stdout for
/// "" or "-". Throws input_error "PATH: cannot write: <reason>".
void write_output(const std::string& path, const std::string& bytes);

}  // namespace crspline::cli
