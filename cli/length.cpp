// crspline length: the arc length of the whole curve and of each segment.
#include <vector>

#include <crspline/arc_length.hpp>

#include "commands.hpp"
#include "dispatch.hpp"
#include "json_input.hpp"

namespace crspline::cli {

output_json run_length(const document& input) {
    const length_spec spec = parse_length(input);
    return with_dimension(spec.curve.dimension, [&](auto dim) {
        constexpr std::size_t D = decltype(dim)::value;
        const catmull_rom<D, double> curve = make_curve<D>(spec.curve);
        // One number per segment and their sum: no arc-length table (its
        // pieces and copied segments would be held for every segment at
        // once); each segment's quadrature work is released as it goes.
        std::vector<double> segments(curve.segment_count());
        double total = 0;
        for (std::size_t i = 0; i < segments.size(); ++i) {
            segments[i] = arc_length(curve.segment(i), spec.accuracy);
            total += segments[i];
        }
        output_json out;
        out["total"] = total;
        out["segments"] = segments;
        out["accuracy"] = spec.accuracy;
        return out;
    });
}

}  // namespace crspline::cli
