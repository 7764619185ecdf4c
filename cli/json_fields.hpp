// crspline command line: reading one field of the input contract (json_input.cpp
// puts them together): numbers and lists of numbers named by their JSON path,
// the ends, Kochanek-Bartels values and tangents of a curve, and the flags
// that stand for fields. Every problem is an input_error naming the field's
// JSON path or the flag.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <crspline/spec.hpp>
#include <nlohmann/json.hpp>

#include "json_input.hpp"
#include "options.hpp"

namespace crspline::cli::json_fields {

using nlohmann::json;

[[noreturn]] void fail(const std::string& path, const std::string& what);
/// A number of the curve's specification, whatever its value (the core's validate() judges it).
double number(const json& v, const std::string& path);
/// A value the subcommand reads itself (t, s, accuracy...): a finite number.
double finite_number(const json& v, const std::string& path);
const json& array(const json& v, const std::string& path, const char* of_what);
std::vector<double> finite_numbers(const json& v, const std::string& path);
std::vector<double> numbers(const json& v, const std::string& path);
/// Unknown top-level fields, with a hint when another subcommand takes them.
void check_fields(const json& root, std::string_view command, std::initializer_list<std::string_view> extra);
crspline::end_spec parse_end(const json& v, const std::string& path, const char* which);
/// The ends of the curve file (docs/spec.md, "The curve file").
void read_ends(const json& root, crspline::curve_spec& c);
std::vector<double> parse_kb_values(const json& v, const std::string& path, std::size_t n, bool closed);
/// "tangents": a cubic Hermite curve with them.
void parse_tangents(const json& root, const cli_options* f, curve_spec& c);
/// A flag's text as the JSON value it stands for.
json scalar(const std::string& text);
/// One end from --start / --end.
json end_value(const std::string& flag, const std::string& text);
/// The alpha flags of a one-curve command.
std::optional<double> alpha_flag(const cli_options& f);
bool any_alpha_flag(const cli_options& f);

/// The value of a field: the flag's when it is given, else the JSON field's.
/// `name` is what messages call it.
struct field_value {
    json value;
    std::string name;
    bool flag = false;
};
std::optional<field_value> field(const json& root, const char* key, const cli_options* f,
                                 const std::string cli_options::*flag, const char* flag_name, bool list = false);
/// Drops a closed curve's last point when it repeats the first; returns whether it did.
bool drop_closing_repeat(curve_spec& c);

}  // namespace crspline::cli::json_fields
