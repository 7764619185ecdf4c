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

// A number when the text is one, else the text as a string, so that the
// contract's validation reports it ("expected a finite number, got "abc"").
json scalar(const std::string& text) {
    if (const auto x = parse_number(text)) return *x;
    if (text == "true") return true;
    if (text == "false") return false;
    return text;
}

// One end: "natural" | "reflect" | a tangent "dx,dy".
json end_value(const std::string& option, const std::string& text) {
    if (text == "natural" || text == "reflect") return text;
    try {
        return number_list(option, text);
    } catch (const input_error&) {
        return text;  // reported by the contract with the expected forms
    }
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
            if (!(x >= 0 && x <= 1)) throw input_error(at + ": must be in [0, 1], got " + format_number(x));
            a.push_back(x);
        }
    }
    return a;
}

loaded_input load_input(const cli_options& o, bool alpha_list) {
    loaded_input li;
    const input_text in = read_input(o.input);

    // 1. The format: --input-format, the extension, or the first character.
    std::string fmt = o.input_format;
    if (fmt.empty()) {
        const std::string ext = o.input == "-" ? "" : extension_of(o.input);
        if (ext == ".json") fmt = "json";
        else if (ext == ".csv" || ext == ".txt" || ext == ".dat") fmt = "csv";
        else if (ext == ".tsv" || ext == ".tab") fmt = "tsv";
        else {
            const std::size_t first = in.text.find_first_not_of(" \t\r\n");
            const bool json_like = first == std::string::npos || in.text[first] == '{' || in.text[first] == '[';
            fmt = json_like ? "json" : "csv";
        }
    } else if (fmt != "json" && fmt != "csv" && fmt != "tsv") {
        throw input_error("--input-format: expected json, csv or tsv, got '" + fmt + "'");
    }

    // 2. Parse.
    if (fmt == "json") {
        if (!o.columns.empty()) throw input_error("--columns: only for CSV input, and " + in.name + " is read as JSON");
        if (!o.delimiter.empty())
            throw input_error("--delimiter: only for CSV input, and " + in.name + " is read as JSON");
        li.doc = parse_json_document(in);
    } else {
        li.from_json = false;
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
        li.doc.points = parse_csv(in, c);
    }

    // 3. Options override (or complement) the JSON fields.
    json& r = li.doc.root;
    if (!r.is_object()) return li;  // reported by the contract
    auto set = [&](const std::string& field, const std::string& option, json value) {
        r[field] = std::move(value);
        li.option_fields.emplace_back(field, option);
    };
    if (!alpha_list) {
        const int presets = int(o.uniform) + int(o.centripetal) + int(o.chordal) + int(!o.alpha.empty());
        if (presets > 1)
            throw input_error("--alpha: give one of --alpha, --uniform, --centripetal, --chordal (several are for "
                              "'crspline plot')");
        if (presets == 1) {
            r.erase("grid");
            set("alpha", "--alpha", o.uniform ? json(0.0) : o.centripetal ? json(0.5) : o.chordal ? json(1.0) : scalar(o.alpha));
        }
    }
    if (!o.grid.empty()) {
        if (!o.alpha.empty() || o.uniform || o.centripetal || o.chordal)
            throw input_error("--grid: give --grid or an alpha (--alpha, --uniform, --centripetal, --chordal), not both");
        r.erase("alpha");
        set("grid", "--grid", number_list("--grid", o.grid));
    }
    if (o.closed) {
        if (!o.start.empty() || !o.end.empty())
            throw input_error("--closed: a closed curve has no end conditions (--start, --end)");
        set("end", "--closed", "closed");
    }
    if (!o.start.empty() || !o.end.empty()) {
        json e = json::object();
        if (r.contains("end") && r["end"].is_object()) e = r["end"];
        else if (r.contains("end") && (r["end"] == "natural" || r["end"] == "reflect")) e = {{"start", r["end"]}, {"end", r["end"]}};
        if (!o.start.empty()) {
            e["start"] = end_value("--start", o.start);
            li.option_fields.emplace_back("end.start", "--start");
        }
        if (!o.end.empty()) {
            e["end"] = end_value("--end", o.end);
            li.option_fields.emplace_back("end.end", "--end");
        }
        r["end"] = std::move(e);
    }
    if (!o.tension.empty()) set("tension", "--tension", scalar(o.tension));
    const std::pair<const std::string*, const char*> kb[] = {
        {&o.kb_tension, "tension"}, {&o.kb_continuity, "continuity"}, {&o.kb_bias, "bias"}};
    for (const auto& [text, key] : kb) {
        if (text->empty()) continue;
        const std::string option = std::string("--kb-") + key;
        if (!r.contains("kb") || !r["kb"].is_object()) r["kb"] = json::object();
        r["kb"][key] = number_list(option, *text, true);
        li.option_fields.emplace_back(std::string("kb.") + key, option);
    }
    if (o.strict) set("strict", "--strict", true);
    if (!o.t.empty()) {
        r.erase("s"), r.erase("u"), r.erase("arc_fraction");
        set("t", "--t", number_list("--t", o.t));
    }
    if (!o.s.empty()) {
        r.erase("t"), r.erase("u"), r.erase("arc_fraction");
        set("s", "--s", number_list("--s", o.s));
    }
    if (!o.derivatives.empty()) set("derivatives", "--derivatives", number_list("--derivatives", o.derivatives));
    if (!o.accuracy.empty()) set("accuracy", "--accuracy", scalar(o.accuracy));
    if (!o.count.empty()) {
        r.erase("tolerance");
        set("count", "--count", scalar(o.count));
    }
    if (!o.tolerance.empty()) {
        r.erase("count");
        r.erase("spacing");
        set("tolerance", "--tolerance", scalar(o.tolerance));
    }
    if (!o.spacing.empty()) set("spacing", "--spacing", o.spacing);
    // eval's normalised parameters and the knot grid (output side).
    for (const auto& [text, field, option] : {std::tuple{&o.u, "u", "--u"}, {&o.arc_fraction, "arc_fraction", "--arc-fraction"}}) {
        if (text->empty()) continue;
        for (const char* other : {"t", "s", "u", "arc_fraction"})
            if (std::string(other) != field) r.erase(other);
        set(field, option, number_list(option, *text));
    }
    if (o.knots) set("knots", "--knots", true);
    if (o.summary) set("summary", "--summary", true);
    if (o.no_search) set("search", "--no-intersections", false);
    return li;
}

std::string rename_fields(const std::string& message, const loaded_input& in) {
    for (const auto& [field, option] : in.option_fields) {
        if (message.rfind(field, 0) == 0 && message.size() > field.size() &&
            (message[field.size()] == ':' || message[field.size()] == '['))
            return option + message.substr(field.size());
    }
    if (!in.from_json && message.rfind("missing field '", 0) == 0) {
        // CSV input has no fields besides the points: name the options.
        std::string m = message;
        for (std::size_t p; (p = m.find("field '")) != std::string::npos;) {
            const std::size_t q = m.find('\'', p + 7);
            m = m.substr(0, p) + "option --" + m.substr(p + 7, q - p - 7) + m.substr(q + 1);
        }
        for (std::size_t p; (p = m.find(" or '")) != std::string::npos;) {
            const std::size_t q = m.find('\'', p + 5);
            m = m.substr(0, p) + " or --" + m.substr(p + 5, q - p - 5) + m.substr(q + 1);
        }
        return m;
    }
    return message;
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
