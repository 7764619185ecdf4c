// crspline command line: the options every subcommand shares, how the input
// is loaded (JSON, CSV/TSV, stdin), and how options override the JSON fields.
//
// Options become JSON fields of the input document (--alpha 0.5 is
// "alpha": 0.5, --start reflect is "end": {"start": "reflect", ...}) and go
// through the contract's one validation; a message about such a field names
// the option instead ("--alpha: must be in [0, 1], got 1.5").
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
    bool no_points = false;                   ///< plot: no point markers
    // plot.
    std::string title, size, png, ticks, comb;
    bool comb_on = false, ticks_on = false;
    bool cusps = false, intersections = false, volumes = false, handles = false, all_overlays = false;
};

/// A loaded input with the options merged in, and the fields the options set
/// (field, option) for renaming messages.
struct loaded_input {
    document doc;
    bool from_json = true;
    std::vector<std::pair<std::string, std::string>> option_fields;
};

/// Reads and parses the input named by the options, then merges the curve
/// and subcommand options into it. `alpha_list` (plot) leaves alpha out.
loaded_input load_input(const cli_options& o, bool alpha_list = false);

/// The alpha values asked for with --alpha LIST and the presets, in order
/// (plot draws one curve per value); empty when none was given.
std::vector<double> alpha_values(const cli_options& o);

/// A message about a field the options set, rewritten to name the option.
std::string rename_fields(const std::string& message, const loaded_input& in);

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
