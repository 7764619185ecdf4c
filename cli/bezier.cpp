// crspline bezier: the cubic Bézier control points of every segment.
#include <vector>

#include "commands.hpp"
#include "dispatch.hpp"
#include "json_input.hpp"

namespace crspline::cli {

output_json run_bezier(const document& input) {
    const bezier_spec spec = parse_bezier(input);
    return with_dimension(spec.curve.dimension, [&](auto dim) {
        constexpr std::size_t D = decltype(dim)::value;
        const catmull_rom<D, double> curve = make_curve<D>(spec.curve);
        output_json out;
        out["grid"] = std::vector<double>(curve.grid().begin(), curve.grid().end());
        output_json segments = output_json::array();
        for (const auto& b : curve.bezier()) {
            output_json seg = output_json::array();
            for (const auto& p : b) seg.push_back(coords(p, spec.curve.dimension));
            segments.push_back(std::move(seg));
        }
        out["segments"] = std::move(segments);
        return out;
    });
}

}  // namespace crspline::cli
