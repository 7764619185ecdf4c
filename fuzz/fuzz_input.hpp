// The fuzz entry point shared by the libFuzzer target and the corpus replay.
#pragma once

#include <cstddef>
#include <cstdint>

/// Feeds one input to the crspline parsers and the JSON contract. The first
/// byte picks the path (JSON document for each subcommand, CSV with or
/// without chosen columns, option number lists); the rest is the text.
/// Expected errors (input_error, the library's invalid_input and
/// out_of_domain) are caught; anything else escapes and is a finding.
int crspline_fuzz_one(const std::uint8_t* data, std::size_t size);
