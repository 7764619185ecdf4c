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
        const arc_length_table<D, double> table(curve, spec.accuracy);
        output_json out;
        out["total"] = table.total();
        std::vector<double> segments(curve.segment_count());
        for (std::size_t i = 0; i < segments.size(); ++i) segments[i] = table.segment_length(i);
        out["segments"] = segments;
        out["accuracy"] = spec.accuracy;
        return out;
    });
}

}  // namespace crspline::cli
