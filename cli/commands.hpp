// crspline command line: the subcommands. Each one takes the parsed input
// document and returns its whole output as JSON, built in memory, so that
// nothing reaches stdout when any step fails.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "json_input.hpp"

namespace crspline::cli {

using output_json = nlohmann::ordered_json;  // keys stay in the order written

struct command {
    std::string_view name;
    std::string_view summary;  ///< one line, for `crspline --help`
    std::string_view details;  ///< the input contract and an example, for `crspline NAME --help`
    output_json (*run)(const document& input);  ///< null for plot and demo (they write figures)
    std::string_view formats;  ///< output formats, the first the default
};

/// Every subcommand, in the order `crspline --help` lists them.
std::span<const command> commands();

output_json run_eval(const document& input);
output_json run_bezier(const document& input);
output_json run_length(const document& input);
output_json run_sample(const document& input);
output_json run_analyze(const document& input);

/// The output of a JSON-producing subcommand in another format: "csv",
/// "tsv", "svg" (a figure of the curve, 2-D) or "svg-path" (bezier).
std::string convert_output(std::string_view command, const std::string& format, const output_json& out,
                           const document& input);

/// The SVG path data of Bezier segments: "M x0 y0 C x1 y1 x2 y2 x3 y3 C ...",
/// every number the shortest text that reads back to the same double.
std::string svg_path_data(const output_json& segments);

/// The output text (one line plus a newline). Throws input_error naming the
/// first value that is not finite (JSON cannot hold NaN or infinity; it
/// happens only when the input's scale overflows double arithmetic).
std::string render(const output_json& out);

}  // namespace crspline::cli
