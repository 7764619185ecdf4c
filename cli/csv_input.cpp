// crspline command line: CSV / TSV points and option number lists. See
// csv_input.hpp. Hand-written for speed (std::from_chars, one pass, no
// allocation per line): ten million points load in a few seconds.
#include "csv_input.hpp"

#include <crspline/dispatch.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string_view>

namespace crspline::cli {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t'; }

std::string_view trim(std::string_view s) {
    while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
    while (!s.empty() && (is_blank(s.back()) || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

std::string_view unquote(std::string_view s) {
    if (s.size() >= 2 && s.front() == '"' && s.back() == '"') return s.substr(1, s.size() - 2);
    return s;
}

// A field as it appears in a message: quoted, shortened when long.
std::string shown(std::string_view s) {
    if (s.empty()) return "an empty field";
    std::string t(s.substr(0, std::min<std::size_t>(s.size(), 40)));
    if (s.size() > 40) t += "...";
    return "\"" + t + "\"";
}

struct csv_field {
    std::size_t begin = 0;  // byte offset in the line
    std::string_view text;  // trimmed
};

// Splits a line into fields (trimmed); blanks as delimiter means runs of
// spaces and tabs, ignoring leading and trailing ones.
void split(std::string_view line, char delimiter, std::vector<csv_field>& out) {
    out.clear();
    if (delimiter == ' ') {
        std::size_t i = 0;
        while (true) {
            while (i < line.size() && (is_blank(line[i]) || line[i] == '\r')) ++i;
            if (i >= line.size()) return;
            const std::size_t b = i;
            while (i < line.size() && !is_blank(line[i]) && line[i] != '\r') ++i;
            out.push_back({b, line.substr(b, i - b)});
        }
    }
    std::size_t b = 0;
    while (true) {
        const std::size_t e = line.find(delimiter, b);
        const std::string_view raw = line.substr(b, e == std::string_view::npos ? std::string_view::npos : e - b);
        std::size_t lead = 0;
        while (lead < raw.size() && is_blank(raw[lead])) ++lead;
        out.push_back({b + lead, trim(raw)});
        if (e == std::string_view::npos) return;
        b = e + 1;
    }
}

std::string where(const input_text& in, std::size_t line, std::size_t column) {
    return in.name + ": line " + std::to_string(line) + ", column " + std::to_string(column) + ": ";
}


// A name a coordinate column goes by: x, y, z, w (with a suffix like x1 or
// x_m), longitude, latitude and the like.
bool coordinate_name(std::string name) {
    for (char& ch : name) ch = char(ch >= 'A' && ch <= 'Z' ? ch - 'A' + 'a' : ch);
    static const char* const known[] = {"lon", "lng", "long", "longitude", "lat", "latitude", "alt", "altitude",
                                        "elevation", "ele", "height", "depth", "easting", "northing"};
    for (const char* k : known)
        if (name == k) return true;
    return !name.empty() && std::strchr("xyzw", name[0]) &&
           (name.size() == 1 || (name[1] >= '0' && name[1] <= '9') || name[1] == '_' || name[1] == ' ');
}

// More than two columns read as coordinates by default: a pandas-style
// ",x,y" file (an index column) or a "t,x,y" track would silently become a
// 3-D curve with a wrong length. A first column that is unnamed, named like
// an index, a time or a parameter, or that counts 0, 1, 2, ... (or from 1)
// is an error asking for --columns; other columns that are not named like
// coordinates are read, and a note on stderr names them.
void check_columns(const input_text& in, point_set& out, const std::vector<std::string>& header,
                   std::size_t first_line) {
    const std::size_t d = out.dimension, n = out.size();
    std::string names;
    for (std::size_t k = 0; k < d; ++k)
        names += (k ? ", " : "") + (header.empty() ? "column " + std::to_string(k + 1)
                                                   : header[k].empty() ? std::string("(unnamed)") : header[k]);
    std::string first = header.empty() ? std::string() : header[0];
    for (char& ch : first) ch = char(ch >= 'A' && ch <= 'Z' ? ch - 'A' + 'a' : ch);
    static const char* const not_coordinates[] = {"", "index", "idx", "id", "i", "n", "no", "row", "t", "time",
                                                  "date", "datetime", "timestamp", "year", "s", "u", "frame",
                                                  "unnamed: 0", "step"};
    bool counts = n >= 3;
    for (std::size_t i = 0; i < n && counts; ++i)
        counts = out.coords[i * d] == out.coords[0] + double(i) && (out.coords[0] == 0 || out.coords[0] == 1);
    const bool named_like_index =
        !header.empty() && std::any_of(std::begin(not_coordinates), std::end(not_coordinates),
                                       [&](const char* k) { return first == k; });
    if (named_like_index || counts) {
        const std::string why = named_like_index
                                    ? (header[0].empty() ? "the first column has no name (an index column?)"
                                                         : "the first column, '" + header[0] +
                                                               "', looks like an index or a parameter, not a coordinate")
                                    : "the first column counts " + format_number(out.coords[0]) + ", " +
                                          format_number(out.coords[0] + 1) + ", " + format_number(out.coords[0] + 2) +
                                          ", ... like an index";
        const std::string example = header.size() >= 3 && !header[1].empty() && !header[2].empty()
                                        ? header[1] + "," + header[2]
                                        : "2,3";
        throw input_error(in.name + ": line " + std::to_string(first_line) + ": " + std::to_string(d) +
                          " numeric columns (" + names + ") would make a " + std::to_string(d) + "-D curve, but " +
                          why + "; choose the coordinates with --columns (e.g. --columns " + example + ")");
    }
    const bool all_coordinates =
        !header.empty() && std::all_of(header.begin(), header.end(), [](const std::string& h) { return coordinate_name(h); });
    if (!all_coordinates)
        out.notes.push_back(in.name + ": " + std::to_string(d) + " columns read as a " + std::to_string(d) +
                            "-D curve (" + names + "); choose others with --columns");
}

}  // namespace

std::optional<double> parse_number(std::string_view s) {
    s = unquote(s);
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    if (s.empty() || s.front() == '+') return std::nullopt;
    double x = 0;
    const auto r = std::from_chars(s.data(), s.data() + s.size(), x);
    if (r.ptr != s.data() + s.size()) return std::nullopt;
    if (r.ec == std::errc::result_out_of_range) {
        // Underflow reads as the nearest double (0 or subnormal); overflow is infinite.
        x = std::strtod(std::string(s).c_str(), nullptr);
    } else if (r.ec != std::errc()) {
        return std::nullopt;
    }
    return x;
}

char parse_delimiter(const std::string& text) {
    if (text == "," || text == ";" || text == "|" || text == ":") return text[0];
    if (text == "tab" || text == "\\t" || text == "\t") return '\t';
    if (text == "space" || text == " " || text == "blank") return ' ';
    throw input_error("--delimiter: expected ',', ';', '|', ':', 'tab' or 'space', got '" + text + "'");
}

point_set parse_csv(const input_text& in, const csv_options& opt) {
    point_set out;
    out.name = in.name;
    const std::string_view text = in.text;
    std::vector<csv_field> fields;
    fields.reserve(8);
    std::optional<char> delimiter = opt.delimiter;
    std::vector<std::size_t> chosen;  // indices of the columns to read
    std::size_t nfields = 0, first_line = 0, line_no = 0;
    std::vector<std::string> header_names;  // empty: no header
    std::optional<std::size_t> id_column;  // the curve-id column's index
    bool blank_after_points = false;
    std::vector<std::string> seen_ids;
    for (std::size_t pos = 0; pos < text.size();) {
        const std::size_t nl = text.find('\n', pos);
        const std::size_t end = nl == std::string_view::npos ? text.size() : nl;
        std::string_view line = text.substr(pos, end - pos);
        pos = end + 1;
        ++line_no;
        // Blank lines and comments.
        std::size_t lead = 0;
        while (lead < line.size() && (is_blank(line[lead]) || line[lead] == '\r')) ++lead;
        if (lead == line.size()) {
            blank_after_points = !out.lines.empty();  // a blank line between points separates curves
            continue;
        }
        if (line[lead] == '#') continue;

        if (first_line == 0) {
            // The first line fixes the delimiter, the field count, the header
            // and the chosen columns.
            first_line = line_no;
            if (!delimiter) {
                delimiter = line.find('\t') != std::string_view::npos   ? '\t'
                            : line.find(',') != std::string_view::npos  ? ','
                            : line.find(';') != std::string_view::npos  ? ';'
                            : trim(line).find(' ') != std::string_view::npos ? ' '
                                                                            : ',';
            }
            split(line, *delimiter, fields);
            nfields = fields.size();
            const bool header = std::none_of(fields.begin(), fields.end(),
                                             [](const csv_field& f) { return parse_number(f.text).has_value(); });
            if (!opt.curve_column.empty()) {
                const std::string& c = opt.curve_column;
                const bool numeric = std::all_of(c.begin(), c.end(), [](char ch) { return ch >= '0' && ch <= '9'; });
                if (numeric) {
                    const std::size_t k = std::size_t(std::strtoull(c.c_str(), nullptr, 10));
                    if (k < 1 || k > nfields)
                        throw input_error("--curve-column: column " + c + " does not exist: line " +
                                          std::to_string(line_no) + " of " + in.name + " has " +
                                          std::to_string(nfields) + " fields (columns are numbered from 1)");
                    id_column = k - 1;
                } else {
                    const auto it = std::find_if(fields.begin(), fields.end(),
                                                 [&](const csv_field& f) { return unquote(f.text) == c; });
                    if (!header || it == fields.end())
                        throw input_error("--curve-column: no column named '" + c + "' in the header of " + in.name);
                    id_column = std::size_t(it - fields.begin());
                }
            }
            if (opt.columns.empty() && id_column) {
                for (std::size_t k = 0; k < nfields; ++k)
                    if (k != *id_column) chosen.push_back(k);
                if (chosen.size() > max_runtime_dimension)
                    throw input_error(where(in, line_no, 1) + "expected 1 to " + std::to_string(max_runtime_dimension) +
                                      " coordinate columns, got " + std::to_string(chosen.size()) +
                                      " (choose some with --columns)");
            } else if (opt.columns.empty()) {
                if (nfields > max_runtime_dimension)
                    throw input_error(where(in, line_no, fields[max_runtime_dimension].begin + 1) +
                                      "expected 1 to " + std::to_string(max_runtime_dimension) + " columns, got " +
                                      std::to_string(nfields) + " (choose some with --columns)");
                for (std::size_t k = 0; k < nfields; ++k) chosen.push_back(k);
            } else {
                if (opt.columns.size() > max_runtime_dimension)
                    throw input_error("--columns: expected 1 to " + std::to_string(max_runtime_dimension) +
                                      " columns, got " + std::to_string(opt.columns.size()));
                for (const std::string& c : opt.columns) {
                    const bool numeric = !c.empty() && std::all_of(c.begin(), c.end(), [](char ch) { return ch >= '0' && ch <= '9'; });
                    if (numeric) {
                        const std::size_t k = std::size_t(std::strtoull(c.c_str(), nullptr, 10));
                        if (k < 1 || k > nfields)
                            throw input_error("--columns: column " + c + " does not exist: line " + std::to_string(line_no) +
                                              " of " + in.name + " has " + std::to_string(nfields) +
                                              " fields (columns are numbered from 1)");
                        chosen.push_back(k - 1);
                        continue;
                    }
                    if (!header)
                        throw input_error("--columns: '" + c + "' is not a column number, and " + in.name +
                                          " has no header line to name columns");
                    const auto it = std::find_if(fields.begin(), fields.end(),
                                                 [&](const csv_field& f) { return unquote(f.text) == c; });
                    if (it == fields.end()) {
                        std::string names;
                        for (const csv_field& f : fields) names += (names.empty() ? "" : ", ") + std::string(unquote(f.text));
                        throw input_error("--columns: no column named '" + c + "' in the header of " + in.name +
                                          " (columns: " + names + ")");
                    }
                    chosen.push_back(std::size_t(it - fields.begin()));
                }
            }
            out.dimension = chosen.size();
            if (header) {
                for (const csv_field& f : fields) header_names.emplace_back(unquote(f.text));
                for (const std::size_t k : chosen) out.column_names.push_back(header_names[k]);
                continue;
            }
        } else {
            split(line, *delimiter, fields);
        }
        if (fields.size() != nfields) {
            const std::size_t column = fields.size() > nfields ? fields[nfields].begin + 1 : trim(line).size() + 1;
            throw input_error(where(in, line_no, column) + "expected " + std::to_string(nfields) + " field" +
                              (nfields == 1 ? "" : "s") + " like line " + std::to_string(first_line) + ", got " +
                              std::to_string(fields.size()));
        }
        // Curves: a change of the id column's value, or a blank line
        // between points.
        if (id_column) {
            const std::string id(unquote(fields[*id_column].text));
            if (out.curve_ids.empty() || id != out.curve_ids.back()) {
                if (std::find(seen_ids.begin(), seen_ids.end(), id) != seen_ids.end())
                    throw input_error(where(in, line_no, fields[*id_column].begin + 1) + "curve '" + id +
                                      "' again after other curves (the rows of a curve must be consecutive)");
                seen_ids.push_back(id);
                out.curve_starts.push_back(out.size());
                out.curve_ids.push_back(id);
            }
        } else if (out.lines.empty() || blank_after_points) {
            out.curve_starts.push_back(out.size());
            out.curve_ids.emplace_back();
        }
        blank_after_points = false;
        for (const std::size_t k : chosen) {
            const auto x = parse_number(fields[k].text);
            if (!x || !std::isfinite(*x))
                throw input_error(where(in, line_no, fields[k].begin + 1) + "expected a finite number, got " +
                                  shown(fields[k].text));
            out.coords.push_back(*x);
        }
        out.lines.push_back(line_no);
    }
    if (opt.columns.empty() && !id_column && nfields > 2 && out.size() > 0) check_columns(in, out, header_names, first_line);
    return out;
}

nlohmann::json number_list(const std::string& option, const std::string& text, bool allow_null, bool allow_files) {
    using nlohmann::json;
    // 1. A list written on the command line.
    {
        json list = json::array();
        bool ok = !trim(text).empty();
        std::vector<csv_field> fields;
        split(text, text.find(',') != std::string::npos ? ',' : ' ', fields);
        for (const csv_field& f : fields) {
            if (allow_null && f.text == "null") {
                list.push_back(nullptr);
                continue;
            }
            const auto x = parse_number(f.text);
            if (!x) {
                ok = false;
                break;
            }
            list.push_back(*x);
        }
        if (ok) return list;
    }
    // 2. A file: a JSON array, or numbers separated by commas, blanks or lines.
    if (!allow_files) throw input_error(option + ": expected a list of numbers like 0,1,2.5, got '" + text + "'");
    input_text in;
    try {
        if (text.empty() || text == "-") throw input_error("-: not a file name");
        in = read_input(text);
    } catch (const input_error& e) {
        const std::string why = e.what();
        throw input_error(option + ": '" + text + "' is neither a list of numbers (like 0,1,2.5) nor a readable file (" +
                          why.substr(why.find(": ") + 2) + ")");
    }
    const std::size_t first = in.text.find_first_not_of(" \t\r\n");
    if (first != std::string::npos && in.text[first] == '[') return parse_json(in);
    json list = json::array();
    std::vector<csv_field> fields;
    std::size_t line_no = 0;
    for (std::size_t pos = 0; pos < in.text.size();) {
        const std::size_t nl = in.text.find('\n', pos);
        const std::size_t end = nl == std::string::npos ? in.text.size() : nl;
        const std::string_view line = std::string_view(in.text).substr(pos, end - pos);
        pos = end + 1;
        ++line_no;
        if (trim(line).empty() || trim(line).front() == '#') continue;
        split(line, line.find(',') != std::string_view::npos ? ',' : ' ', fields);
        for (const csv_field& f : fields) {
            if (allow_null && f.text == "null") {
                list.push_back(nullptr);
                continue;
            }
            const auto x = parse_number(f.text);
            if (!x || !std::isfinite(*x))
                throw input_error(where(in, line_no, f.begin + 1) + "expected a finite number, got " + shown(f.text));
            list.push_back(*x);
        }
    }
    return list;
}

}  // namespace crspline::cli
