// crspline command line: points from CSV / TSV text, and number lists given
// to options ("0,1,2.5" or a file).
//
// CSV rules: one point per line; blank lines and lines starting with '#' are
// skipped; the first line is a header when none of its fields is a number;
// the delimiter is ',' ';' tab or blanks, detected from the first line unless
// given; fields may be quoted ("1.5"); 1 to 16 columns, or the columns chosen
// by name (needs the header) or by 1-based index. Every line has the same
// number of fields as the first one. Errors name the file, line and column:
//   data.csv: line 7, column 9: expected a finite number, got "abc"
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "json_parser.hpp"

namespace crspline::cli {

struct csv_options {
    std::optional<char> delimiter;     ///< nullopt: detect; ' ' means runs of blanks
    std::vector<std::string> columns;  ///< names or 1-based indices; empty: every column
    std::string curve_column;          ///< name or 1-based index of a curve-id column; empty: none
};

/// The points of a CSV text (validated: finite, 1 to 16 coordinates each).
point_set parse_csv(const input_text& in, const csv_options& opt);

/// "," ";" "|" "tab" "\t" "space" (blanks) -> the delimiter; throws
/// input_error "--delimiter: ..." for anything else.
char parse_delimiter(const std::string& text);

/// Parses one number as the CSV reader does (whole text, optional '+',
/// finite). nullopt when it is not one.
std::optional<double> parse_number(std::string_view text);

/// A list of numbers for an option, from "1,2.5,-3" or from a file (a JSON
/// array, or numbers separated by commas, blanks or line breaks, with '#'
/// comment lines). `option` names the option in messages. "null" is kept as
/// null when allow_null. Returned as a JSON array so that the contract's own
/// validation checks it like the JSON field (non-finite values included).
/// Without allow_files, text that is not a list is an error (the fuzzer).
nlohmann::json number_list(const std::string& option, const std::string& text, bool allow_null = false,
                           bool allow_files = true);

}  // namespace crspline::cli
