// crspline command line: the subcommands. Each one takes the parsed input
// document and returns its whole output as JSON, built in memory, so that
// nothing reaches stdout when any step fails.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "json_input.hpp"
#include "output_stream.hpp"

namespace crspline::cli {

using output_json = nlohmann::ordered_json;  // keys stay in the order written

/// How a streaming subcommand writes: the format and the numbers' precision.
struct output_settings {
    std::string format = "json";
    number_format numbers;
};

struct command {
    std::string_view name;
    std::string_view summary;  ///< one line, for `crspline --help`
    std::string_view details;  ///< the input contract and an example, for `crspline NAME --help`
    output_json (*run)(const document& input);  ///< null for plot and demo (they write figures)
    std::string_view formats;  ///< output formats, the first the default
    /// Writes the output as it is computed, in any of `formats` but "svg"
    /// (a figure, drawn from run's whole output); null: run only.
    void (*stream)(const document& input, const output_settings& settings, output_stream& out) = nullptr;
};

/// Every subcommand, in the order `crspline --help` lists them.
std::span<const command> commands();

output_json run_eval(const document& input);
output_json run_bezier(const document& input);
output_json run_length(const document& input);
output_json run_sample(const document& input);
output_json run_analyze(const document& input);

/// eval, bezier and sample, written as they are computed (run_eval and the
/// others are these, written to memory and parsed back).
void stream_eval(const document& input, const output_settings& settings, output_stream& out);
void stream_bezier(const document& input, const output_settings& settings, output_stream& out);
void stream_sample(const document& input, const output_settings& settings, output_stream& out);
/// analyze, written as JSON text without a document tree (run_analyze is
/// this, parsed back).
void stream_analyze(const document& input, const output_settings& settings, output_stream& out);

/// A streaming subcommand's JSON output, written to memory and parsed back
/// (run_eval, run_bezier, run_sample and run_analyze are this).
output_json run_streamed(void (*stream)(const document&, const output_settings&, output_stream&),
                         const document& input);

/// The output of a JSON-producing subcommand in another format: "csv",
/// "tsv", "svg" (a figure of the curve, 2-D) or "svg-path" (bezier).
/// Numbers rounded to `numbers.precision` significant digits.
std::string convert_output(std::string_view command, const std::string& format, const output_json& out,
                           const document& input, const number_format& numbers = {});

/// The SVG path data of Bezier segments: "M x0 y0 C x1 y1 x2 y2 x3 y3 C ...",
/// every number the shortest text that reads back to the same double (after
/// rounding to the precision); " Z" at the end of a closed curve.
std::string svg_path_data(const output_json& segments, bool closed = false, const number_format& numbers = {});

/// The output text (one line plus a newline). Throws input_error naming the
/// first value that is not finite (JSON cannot hold NaN or infinity; it
/// happens only when the input's scale overflows double arithmetic).
std::string render(const output_json& out, const number_format& numbers = {});

}  // namespace crspline::cli
