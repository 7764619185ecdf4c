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
        // One number per segment and their sum: no arc-length table (its
        // pieces and copied segments would be held for every segment at
        // once), and the curve is released before the output is built.
        std::vector<double> segments;
        {
            const catmull_rom<D, double> curve = make_curve<D>(spec.curve);
            segments = segment_arc_lengths(curve, spec.accuracy);
        }
        double total = 0;
        for (double len : segments) total += len;
        output_json out;
        out["total"] = total;
        output_json list = output_json::array();
        list.get_ref<output_json::array_t&>().reserve(segments.size());
        for (double len : segments) list.push_back(len);
        segments = {};
        out["segments"] = std::move(list);
        out["accuracy"] = spec.accuracy;
        return out;
    });
}

}  // namespace crspline::cli
