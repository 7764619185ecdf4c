// crspline bezier: the cubic Bézier control points of every segment,
// written a segment at a time.
#include <algorithm>
#include <string>
#include <vector>

#include "commands.hpp"
#include "dispatch.hpp"
#include "json_input.hpp"
#include "progress.hpp"

namespace crspline::cli {

void stream_bezier(const document& input, const output_settings& settings, output_stream& out) {
    const bezier_spec spec = parse_bezier(input);
    with_dimension(spec.curve.dimension, [&](auto dim) {
        constexpr std::size_t D = decltype(dim)::value;
        const catmull_rom<D, double> curve = make_curve<D>(spec.curve);
        const std::size_t dimension = std::min(spec.curve.dimension, D), n = curve.segment_count();
        const auto grid = curve.grid();
        const number_format& nf = settings.numbers;
        std::string& buf = out.buffer();
        progress shown("crspline bezier");
        const auto tick = [&](std::size_t i) {
            if ((i & 4095) == 0) shown.update(double(i) / double(n));
        };
        const auto where = [](std::size_t i, int k, std::size_t c) {
            return [=] {
                return "segments[" + std::to_string(i) + "][" + std::to_string(k) + "][" + std::to_string(c) + "]";
            };
        };
        if (settings.format == "svg-path") {
            // "M x0 y0 C x1 y1 x2 y2 x3 y3 C ... [Z]": a closed curve ends with
            // Z, so that a stroked outline gets a join at the start, not caps.
            if (dimension != 2)
                throw input_error("--format svg-path: needs 2-D points, got " + std::to_string(spec.curve.dimension) +
                                  "-D (use json or csv)");
            for (std::size_t i = 0; i < n; ++i) {
                tick(i);
                const auto b = curve.bezier(i);
                for (int k = i == 0 ? 0 : 1; k < 4; ++k) {
                    buf += k == 0 ? "M " : k == 1 ? (i == 0 ? " C " : " C ") : " ";
                    out.number(b[k][0], nf, false, where(i, k, 0));
                    buf += ' ';
                    out.number(b[k][1], nf, false, where(i, k, 1));
                }
                out.written();
            }
            if (spec.curve.closed) buf += " Z";
            out.put("\n");
            return;
        }
        if (settings.format == "json") {
            // {"grid": [...], "segments": [[B0, B1, B2, B3], ...]}
            buf += "{\"grid\":[";
            for (std::size_t i = 0; i < grid.size(); ++i) {
                if (i) buf += ',';
                out.number(grid[i], nf, true, [&] { return "grid[" + std::to_string(i) + "]"; });
                out.written();
            }
            buf += "],\"segments\":[";
            for (std::size_t i = 0; i < n; ++i) {
                tick(i);
                const auto b = curve.bezier(i);
                buf += i ? ",[" : "[";
                for (int k = 0; k < 4; ++k) {
                    buf += k ? ",[" : "[";
                    for (std::size_t c = 0; c < dimension; ++c) {
                        if (c) buf += ',';
                        out.number(b[k][c], nf, true, where(i, k, c));
                    }
                    buf += ']';
                }
                buf += ']';
                out.written();
            }
            out.put("]}\n");
            return;
        }
        // CSV / TSV: segment, t0, t1, b0_x, b0_y, ..., b3_y.
        const char sep = settings.format == "tsv" ? '\t' : ',';
        static const char* const axes[] = {"x", "y", "z", "w"};
        buf += "segment";
        buf += sep;
        buf += "t0";
        buf += sep;
        buf += "t1";
        for (int k = 0; k < 4; ++k)
            for (std::size_t c = 0; c < dimension; ++c)
                buf += sep + ("b" + std::to_string(k) + "_") + (c < 4 ? axes[c] : "x" + std::to_string(c + 1));
        buf += '\n';
        for (std::size_t i = 0; i < n; ++i) {
            tick(i);
            const auto b = curve.bezier(i);
            buf += std::to_string(i);
            for (std::size_t g : {i, i + 1}) {
                buf += sep;
                out.number(grid[g], nf, false, [&] { return "grid[" + std::to_string(g) + "]"; });
            }
            for (int k = 0; k < 4; ++k)
                for (std::size_t c = 0; c < dimension; ++c) {
                    buf += sep;
                    out.number(b[k][c], nf, false, where(i, k, c));
                }
            buf += '\n';
            out.written();
        }
    });
}

output_json run_bezier(const document& input) { return run_streamed(&stream_bezier, input); }

}  // namespace crspline::cli
