// crspline command line: eval and sample of rotation and pose curve files
// (rotation_input.hpp describes the file). stream_eval and stream_sample
// hand a document with "rotations" to stream_rotation.
#pragma once

#include <string>

#include "commands.hpp"
#include "json_parser.hpp"
#include "rotation_input.hpp"

namespace crspline::cli {

/// `command` is "eval" or "sample".
void stream_rotation(const document& input, const output_settings& settings, output_stream& out,
                     const std::string& command);

}  // namespace crspline::cli
