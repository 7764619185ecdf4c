// crspline command line: the subcommands. Each one takes the parsed input
// document and returns its whole output as JSON, built in memory, so that
// nothing reaches stdout when any step fails.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace crspline::cli {

using output_json = nlohmann::ordered_json;  // keys stay in the order written

struct command {
    std::string_view name;
    std::string_view summary;  ///< one line, for `crspline --help`
    std::string_view details;  ///< the input contract and an example, for `crspline NAME --help`
    output_json (*run)(const nlohmann::json& input);
};

/// Every subcommand, in the order `crspline --help` lists them.
std::span<const command> commands();

output_json run_eval(const nlohmann::json& input);
output_json run_bezier(const nlohmann::json& input);
output_json run_length(const nlohmann::json& input);
output_json run_sample(const nlohmann::json& input);

/// The output text (one line plus a newline). Throws input_error naming the
/// first value that is not finite (JSON cannot hold NaN or infinity; it
/// happens only when the input's scale overflows double arithmetic).
std::string render(const output_json& out);

}  // namespace crspline::cli
