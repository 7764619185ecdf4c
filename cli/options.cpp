// crspline command line: loading the input and merging the options into it.
// See options.hpp.
#include "options.hpp"

#include <cerrno>
#include <cmath>
#include <tuple>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "collection_input.hpp"
#include "csv_input.hpp"
#include "output_stream.hpp"

namespace crspline::cli {

using nlohmann::json;

namespace {

std::string extension_of(const std::string& path) {
    const std::string ext = std::filesystem::path(path).extension().string();
    std::string lower;
    for (char c : ext) lower += char(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    return lower;
}

}  // namespace

std::vector<double> alpha_values(const cli_options& o) {
    std::vector<double> a;
    if (o.uniform) a.push_back(0.0);
    if (o.centripetal) a.push_back(0.5);
    if (o.chordal) a.push_back(1.0);
    if (!o.alpha.empty()) {
        const json list = number_list("--alpha", o.alpha);
        for (std::size_t i = 0; i < list.size(); ++i) {
            const double x = list[i].get<double>();
            const std::string at = list.size() > 1 ? "--alpha[" + std::to_string(i) + "]" : "--alpha";
            try {
                check_alpha(x);  // the core's rule and words
            } catch (const spec_error& e) {
                throw input_error(at + ": " + e.what());
            }
            a.push_back(x);
        }
    }
    return a;
}

loaded_input load_input(const cli_options& o) {
    loaded_input li;
    const input_text in = read_input(o.input);
    li.name = in.name;

    // 0. Nothing but blanks: the same words for an empty file and an empty
    //    stdin, whatever the format would have been.
    if (in.text.find_first_not_of(" \t\r\n") == std::string::npos)
        throw input_error(in.name + ": the input is empty (a curve needs at least 2 points, got 0)");

    // 1. The format: --input-format, the extension, or the first character.
    std::string fmt = o.input_format;
    if (fmt.empty()) {
        const std::string ext = o.input == "-" ? "" : extension_of(o.input);
        if (ext == ".json" || ext == ".geojson") fmt = "json";
        else if (ext == ".svg") fmt = "svg";
        else if (ext == ".csv" || ext == ".txt" || ext == ".dat") fmt = "csv";
        else if (ext == ".tsv" || ext == ".tab") fmt = "tsv";
        else {
            const std::size_t first = in.text.find_first_not_of(" \t\r\n");
            const bool json_like = first == std::string::npos || in.text[first] == '{' || in.text[first] == '[';
            fmt = json_like ? "json" : looks_like_svg(in.text) ? "svg" : "csv";
        }
    } else if (fmt != "json" && fmt != "csv" && fmt != "tsv" && fmt != "svg") {
        throw input_error("--input-format: expected json, csv, tsv or svg, got '" + fmt + "'");
    }
    if (!o.curve_column.empty() && fmt != "csv" && fmt != "tsv")
        throw input_error("--curve-column: only for CSV input, and " + in.name + " is read as " + fmt);

    // 2. Parse.
    if (fmt == "json") {
        if (!o.columns.empty()) throw input_error("--columns: only for CSV input, and " + in.name + " is read as JSON");
        if (!o.delimiter.empty())
            throw input_error("--delimiter: only for CSV input, and " + in.name + " is read as JSON");
        document parsed = parse_json_document(in);
        if (auto many = json_curves(parsed, in)) {
            li.curves = std::move(*many);
            li.many = true;
            if (li.curves.front().geojson_pointer) li.geojson = std::move(parsed.root);
        } else {
            li.curves.push_back(std::move(parsed));
        }
    } else if (fmt == "svg") {
        if (!o.columns.empty()) throw input_error("--columns: only for CSV input, and " + in.name + " is read as SVG");
        li.curves = svg_curves(in);
        li.many = true;
    } else {
        csv_options c;
        if (!o.delimiter.empty()) c.delimiter = parse_delimiter(o.delimiter);
        else if (fmt == "tsv") c.delimiter = '\t';
        if (!o.columns.empty()) {
            std::string name;
            for (char ch : o.columns + ",") {
                if (ch != ',') {
                    name += ch;
                    continue;
                }
                while (!name.empty() && name.back() == ' ') name.pop_back();
                while (!name.empty() && name.front() == ' ') name.erase(0, 1);
                if (name.empty()) throw input_error("--columns: expected names or numbers separated by commas, got '" + o.columns + "'");
                c.columns.push_back(name);
                name.clear();
            }
        }
        c.curve_column = o.curve_column;
        point_set all = parse_csv(in, c);
        std::vector<std::string> notes = std::move(all.notes);
        if (all.curve_starts.size() <= 1 && o.curve_column.empty()) {
            document d;
            d.points = std::move(all);
            d.has_fields = false;
            d.notes = std::move(notes);
            li.curves.push_back(std::move(d));
        } else {
            // One curve per block of lines (blank-line separated) or per
            // value of the curve-id column, in the order they come.
            li.many = true;
            const std::size_t dim = all.dimension;
            for (std::size_t k = 0; k < all.curve_starts.size(); ++k) {
                const std::size_t b = all.curve_starts[k];
                const std::size_t e = k + 1 < all.curve_starts.size() ? all.curve_starts[k + 1] : all.size();
                document d;
                point_set p;
                p.dimension = dim;
                p.coords.assign(all.coords.begin() + std::ptrdiff_t(b * dim), all.coords.begin() + std::ptrdiff_t(e * dim));
                p.lines.assign(all.lines.begin() + std::ptrdiff_t(b), all.lines.begin() + std::ptrdiff_t(e));
                d.id = !all.curve_ids[k].empty() ? all.curve_ids[k]
                                                 : "block " + std::to_string(k + 1) + " (line " +
                                                       std::to_string(all.lines[b]) + ")";
                p.name = "points";
                p.column_names = all.column_names;
                d.points = std::move(p);
                d.has_fields = false;
                li.curves.push_back(std::move(d));
            }
            if (!li.curves.empty()) li.curves.front().notes = std::move(notes);
        }
    }

    // 3. The flags override the JSON fields: the contract reads them itself.
    for (document& d : li.curves) {
        d.flags = &o;
        d.file = li.many ? std::string() : in.name;  // many: messages start with the file and the curve's id
    }
    return li;
}

std::string output_format(const cli_options& o, const std::vector<std::string>& allowed, const std::string& fallback) {
    std::string fmt = o.format, list;
    for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
    if (fmt.empty() && !o.output.empty() && o.output != "-") {
        const std::string ext = extension_of(o.output);
        if (ext.empty()) return fallback;
        fmt = ext.substr(1);
        if (std::find(allowed.begin(), allowed.end(), fmt) == allowed.end())
            throw input_error("--output: cannot tell the format from the extension '" + ext + "' of " + o.output +
                              " ('crspline " + o.command + "' writes " + list + "; choose one with --format)");
        return fmt;
    }
    if (fmt.empty()) return fallback;
    if (std::find(allowed.begin(), allowed.end(), fmt) == allowed.end())
        throw input_error("--format: expected one of " + list + " for 'crspline " + o.command + "', got '" + fmt + "'");
    return fmt;
}

int precision_of(const cli_options& o) {
    if (o.precision.empty()) return 0;
    const auto x = parse_number(o.precision);
    if (!x || !(*x >= 1 && *x <= 17) || *x != std::floor(*x))
        throw input_error("--precision: expected a whole number of significant digits from 1 to 17, got '" +
                          o.precision + "'");
    return int(*x);
}

void write_output(const std::string& path, const std::string& bytes) {
    output_stream out(path);
    out.put(bytes);
    out.commit();
}

}  // namespace crspline::cli
