// crspline command line: the outputs of eval, bezier, sample and length as
// CSV / TSV, as an SVG figure of the curve, or as SVG path data.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <string>
#include <vector>

#include "commands.hpp"
#include "json_input.hpp"

namespace crspline::cli {

namespace {

std::size_t dimension_of(const output_json& points) {
    return points.empty() ? 0 : points[0].size();
}

class table {
public:
    table(char sep, const number_format& nf) : sep_(sep), nf_(nf) {}
    void header(const std::vector<std::string>& names) {
        for (std::size_t i = 0; i < names.size(); ++i) text_ += (i ? std::string(1, sep_) : "") + names[i];
        text_ += '\n';
    }
    void cell(double x) {
        if (!first_) text_ += sep_;
        first_ = false;
        append_number(text_, x, nf_);
    }
    void cell(const std::string& s) {
        if (!first_) text_ += sep_;
        first_ = false;
        text_ += s;
    }
    void end_row() {
        text_ += '\n';
        first_ = true;
    }
    std::string text() && { return std::move(text_); }

private:
    char sep_;
    number_format nf_;
    bool first_ = true;
    std::string text_;
};

std::string to_table(std::string_view command, char sep, const output_json& out, const number_format& nf) {
    table t(sep, nf);
    if (command == "length") {
        t.header({"segment", "length"});
        for (std::size_t i = 0; i < out["segments"].size(); ++i) {
            t.cell(std::to_string(i));
            t.cell(out["segments"][i].get<double>());
            t.end_row();
        }
        t.cell("total");
        t.cell(out["total"].get<double>());
        t.end_row();
    }
    return std::move(t).text();
}

// A standalone SVG of the curve (exact cubic segments), its control polygon
// and the points the command computed, in data coordinates under one
// transform that flips y, so that a reader gets the numbers back exactly.
std::string to_svg(std::string_view command, const output_json& out, const document& input, const number_format& nf) {
    // The curve of the input (its curve fields only: bezier takes no others).
    document curve_only = input;
    for (const char* key : {"t", "s", "u", "arc_fraction", "knots", "derivatives", "accuracy", "count", "spacing", "tolerance"})
        curve_only.root.erase(key);
    const bool closed = parse_bezier(curve_only).curve.closed;
    const output_json bez = command == "bezier" ? out : run_bezier(curve_only);
    const output_json& segments = bez["segments"];
    const std::size_t dim = dimension_of(segments[0]);
    if (dim != 2)
        throw input_error("--format svg: needs 2-D points, got " + std::to_string(dim) + "-D (use json or csv)");
    output_json marks = output_json::array();
    if (command == "eval" && out["values"].contains("0")) marks = out["values"]["0"];
    if (command == "sample") marks = out["points"];

    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    auto add = [&](const output_json& p) {
        const double x = p[0].get<double>(), y = p[1].get<double>();
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    };
    for (const auto& s : segments)
        for (const auto& p : s) add(p);
    for (const auto& p : marks) add(p);
    const double width = 800, height = 600, margin = 30;
    const double dx = x1 - x0 > 0 ? x1 - x0 : 1, dy = y1 - y0 > 0 ? y1 - y0 : 1;
    const double scale = std::min((width - 2 * margin) / dx, (height - 2 * margin) / dy);
    const double tx = width / 2 - scale * (x0 + x1) / 2, ty = height / 2 + scale * (y0 + y1) / 2;

    std::string s = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    s += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\" height=\"600\" viewBox=\"0 0 800 600\">\n";
    s += "  <title>crspline " + std::string(command) + "</title>\n";
    s += "  <rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    s += "  <g transform=\"matrix(";
    for (double v : {scale, 0.0, 0.0, -scale, tx, ty}) {
        append_number(s, v, {});
        s += ' ';
    }
    s.back() = ')';
    s += "\" fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
    s += "    <polyline id=\"control-polygon\" stroke=\"#999999\" stroke-width=\"1\" stroke-dasharray=\"4 3\" "
         "vector-effect=\"non-scaling-stroke\" points=\"";
    for (std::size_t i = 0; i < segments.size(); ++i) {
        for (const std::size_t k : {std::size_t(0), std::size_t(3)}) {
            if (k == 3 && i + 1 < segments.size()) continue;
            append_number(s, segments[i][k][0].get<double>(), nf);
            s += ',';
            append_number(s, segments[i][k][1].get<double>(), nf);
            s += ' ';
        }
    }
    s.back() = '"';
    s += "/>\n";
    s += "    <path id=\"curve\" stroke=\"#1f77b4\" stroke-width=\"2\" vector-effect=\"non-scaling-stroke\" d=\"" +
         svg_path_data(segments, closed, nf) + "\"/>\n";
    if (!marks.empty()) {
        s += "    <g id=\"points\" fill=\"#d62728\" stroke=\"none\">\n";
        for (const auto& p : marks) {
            s += "      <circle cx=\"";
            append_number(s, p[0].get<double>(), nf);
            s += "\" cy=\"";
            append_number(s, p[1].get<double>(), nf);
            s += "\" r=\"";
            append_number(s, 3 / scale, {});
            s += "\"/>\n";
        }
        s += "    </g>\n";
    }
    s += "  </g>\n</svg>\n";
    return s;
}

}  // namespace

std::string svg_path_data(const output_json& segments, bool closed, const number_format& nf) {
    std::string d;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const auto& b = segments[i];
        if (i == 0) {
            d += "M ";
            append_number(d, b[0][0].get<double>(), nf);
            d += ' ';
            append_number(d, b[0][1].get<double>(), nf);
        }
        d += " C";
        for (int k = 1; k < 4; ++k) {
            d += ' ';
            append_number(d, b[k][0].get<double>(), nf);
            d += ' ';
            append_number(d, b[k][1].get<double>(), nf);
        }
    }
    if (closed && !segments.empty()) d += " Z";
    return d;
}

std::string convert_output(std::string_view command, const std::string& format, const output_json& out,
                           const document& input, const number_format& nf) {
    if (format == "svg") return to_svg(command, out, input, nf);
    if (format == "csv" || format == "tsv") {
        if (command == "length") return to_table(command, format == "csv" ? ',' : '\t', out, nf);
    }
    // eval, bezier, sample: their own writer, to memory.
    const output_settings settings{format, nf};
    output_stream text = output_stream::in_memory();
    if (command == "eval") stream_eval(input, settings, text);
    else if (command == "bezier") stream_bezier(input, settings, text);
    else if (command == "sample") stream_sample(input, settings, text);
    else return render(out, nf);
    return std::move(text).take();
}

}  // namespace crspline::cli
