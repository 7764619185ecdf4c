// crspline eval: positions and derivatives at given parameter values,
// written as they are computed (a chunk of parameters at a time).
#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include <crspline/arc_length.hpp>

#include "commands.hpp"
#include "dispatch.hpp"
#include "json_input.hpp"
#include "rotation_commands.hpp"
#include "progress.hpp"

namespace crspline::cli {

namespace {

constexpr std::size_t chunk = 4096;  // parameters evaluated per call

const char* const axis_names[] = {"x", "y", "z", "w"};

std::string axis_name(std::size_t k) { return k < 4 ? axis_names[k] : "x" + std::to_string(k + 1); }

}  // namespace

void stream_eval(const document& input, const output_settings& settings, output_stream& out) {
    if (is_rotation_document(input)) return stream_rotation(input, settings, out, "eval");  // issue 28
    const eval_spec spec = parse_eval(input);
    with_dimension(spec.curve.dimension, [&](auto dim) {
        constexpr std::size_t D = decltype(dim)::value;
        const catmull_rom<D, double> curve = make_curve<D>(spec.curve);
        const std::size_t dimension = std::min(spec.curve.dimension, D);
        const double lo = curve.t_min(), hi = curve.t_max();

        // 0. The parameters as given (t, s, u or arc_fraction), and t of them.
        const std::string given = spec.s ? "s" : spec.u ? "u" : spec.arc_fraction ? "arc_fraction" : "t";
        const std::vector<double>& param = spec.s ? *spec.s : spec.u ? *spec.u : spec.arc_fraction ? *spec.arc_fraction : spec.t;
        std::vector<double> t_of;
        const auto outside = [&](std::size_t i, double a, double b) {
            throw input_error(spec.param_name + "[" + std::to_string(i) + "]: " + given + " = " + format_number(param[i]) +
                              " is outside " + (given == "s" ? "the arc-length range " : "") + "[" + format_number(a) +
                              ", " + format_number(b) + "]");
        };
        if (spec.u || spec.arc_fraction) {
            for (std::size_t i = 0; i < param.size(); ++i)
                if (!(param[i] >= 0 && param[i] <= 1)) outside(i, 0, 1);
        }
        if (spec.s || spec.arc_fraction) {
            // Arc lengths: each s in [0, length] (or a fraction of it), then t of s.
            const arc_length_table<D, double> table(curve, spec.accuracy);
            std::vector<double> s = param;
            if (spec.arc_fraction)
                for (double& x : s) x = x == 1 ? table.total() : x * table.total();
            else  // the core's rule: within end_slack() of an end is that end
                for (std::size_t i = 0; i < s.size(); ++i)
                    if (!table.in_range(s[i])) outside(i, 0, table.total());
            t_of = table.t_at(std::span<const double>(s));
        } else if (spec.u) {
            // three.js getPoint(u): every segment an equal share of [0, 1].
            const std::span<const double> grid = curve.grid();
            const std::size_t n = curve.segment_count();
            t_of.resize(param.size());
            for (std::size_t i = 0; i < param.size(); ++i) {
                const double x = param[i] * double(n);
                const std::size_t seg = std::min(std::size_t(x), n - 1);
                const double w = x - double(seg);
                t_of[i] = param[i] == 1 ? hi : grid[seg] + w * (grid[seg + 1] - grid[seg]);
            }
        }
        const std::vector<double>& t = given == "t" ? spec.t : t_of;

        // 1. Every t inside the domain, reported by its index in the input.
        for (std::size_t i = 0; i < spec.t.size(); ++i)
            if (!(spec.t[i] >= lo && spec.t[i] <= hi))
                throw input_error(spec.param_name + "[" + std::to_string(i) + "]: t = " + format_number(spec.t[i]) +
                                  " is outside the domain [" + format_number(lo) + ", " + format_number(hi) + "]");

        // 2. The output, a chunk of parameters at a time.
        const number_format& nf = settings.numbers;
        progress shown("crspline eval");
        const double work = double(t.size()) * double(spec.derivatives.size()) + 1;
        std::vector<vec<D, double>> values(chunk);
        const auto evaluate = [&](std::size_t b, std::size_t m, int order) {
            curve.evaluate(std::span<const double>(t).subspan(b, m), std::span<vec<D, double>>(values).first(m), order);
        };
        if (settings.format == "json") {
            // {"grid": [...] (with "knots"), "t_of_s": [...] (or t_of_u, ...), "values": {"0": [[x, y], ...], ...}}
            std::string& buf = out.buffer();
            const auto list = [&](const std::string& key, std::span<const double> xs, bool comma) {
                if (comma) buf += ',';
                out.json_list(key, xs, nf);
            };
            buf += '{';
            if (spec.knots) list("grid", curve.grid(), false);
            if (given != "t") list("t_of_" + given, t_of, spec.knots);
            buf += (spec.knots || given != "t") ? ",\"values\":{" : "\"values\":{";
            for (std::size_t o = 0; o < spec.derivatives.size(); ++o) {
                const int order = spec.derivatives[o];
                buf += (o ? ",\"" : "\"") + std::to_string(order) + "\":[";
                for (std::size_t b = 0; b < t.size(); b += chunk) {
                    const std::size_t m = std::min(chunk, t.size() - b);
                    shown.update((double(o) * double(t.size()) + double(b)) / work);
                    evaluate(b, m, order);
                    for (std::size_t i = 0; i < m; ++i) {
                        buf += (b + i) ? ",[" : "[";
                        for (std::size_t k = 0; k < dimension; ++k) {
                            if (k) buf += ',';
                            out.number(values[i][k], nf, true, [&] {
                                return "values[\"" + std::to_string(order) + "\"][" + std::to_string(b + i) + "][" +
                                       std::to_string(k) + "]";
                            });
                        }
                        buf += ']';
                        out.written();
                    }
                }
                buf += ']';
            }
            out.put("}}\n");
            return;
        }
        // CSV / TSV: one row per parameter: [s|u|arc_fraction,] t, x, y, ..., d1x, d1y, ...
        const char sep = settings.format == "tsv" ? '\t' : ',';
        std::string& buf = out.buffer();
        if (given != "t") buf += given + sep;
        buf += 't';
        for (const int order : spec.derivatives)
            for (std::size_t k = 0; k < dimension; ++k)
                buf += sep + (order == 0 ? "" : "d" + std::to_string(order)) + axis_name(k);
        buf += '\n';
        std::vector<std::vector<vec<D, double>>> rows(spec.derivatives.size());
        for (std::size_t b = 0; b < t.size(); b += chunk) {
            const std::size_t m = std::min(chunk, t.size() - b);
            shown.update(double(b) / double(t.size()));
            for (std::size_t o = 0; o < spec.derivatives.size(); ++o) {
                evaluate(b, m, spec.derivatives[o]);
                rows[o].assign(values.begin(), values.begin() + std::ptrdiff_t(m));
            }
            for (std::size_t i = 0; i < m; ++i) {
                const auto where = [&] { return "row " + std::to_string(b + i + 1); };
                if (given != "t") {
                    out.number(param[b + i], nf, false, where);
                    buf += sep;
                }
                out.number(t[b + i], nf, false, where);
                for (std::size_t o = 0; o < rows.size(); ++o)
                    for (std::size_t k = 0; k < dimension; ++k) {
                        buf += sep;
                        out.number(rows[o][i][k], nf, false, [&] {
                            return "values[\"" + std::to_string(spec.derivatives[o]) + "\"][" +
                                   std::to_string(b + i) + "][" + std::to_string(k) + "]";
                        });
                    }
                buf += '\n';
                out.written();
            }
        }
    });
}

output_json run_eval(const document& input) { return run_streamed(&stream_eval, input); }

}  // namespace crspline::cli
