// crspline sample: points evenly spaced in t or in arc length, or the
// vertices of a polyline within a distance tolerance of the curve.
#include <span>
#include <vector>

#include <crspline/arc_length.hpp>
#include <crspline/tessellate.hpp>

#include "commands.hpp"
#include "dispatch.hpp"
#include "json_input.hpp"

namespace crspline::cli {

output_json run_sample(const document& input) {
    const sample_spec spec = parse_sample(input);
    return with_dimension(spec.curve.dimension, [&](auto dim) {
        constexpr std::size_t D = decltype(dim)::value;
        const catmull_rom<D, double> curve = make_curve<D>(spec.curve);
        std::vector<double> t;
        std::vector<vec<D, double>> points;
        output_json out;
        switch (spec.by) {
            case sample_spec::kind::count_t: {
                t.resize(spec.count);
                const double lo = curve.t_min(), hi = curve.t_max();
                for (std::size_t k = 0; k < spec.count; ++k)
                    t[k] = lo + (hi - lo) * (double(k) / double(spec.count - 1));
                t.back() = hi;
                points = curve.evaluate(std::span<const double>(t));
                break;
            }
            case sample_spec::kind::count_arc_length: {
                auto smp = sample_arc_length(curve, spec.count, spec.accuracy);
                t = std::move(smp.t);
                points = std::move(smp.points);
                out["s"] = smp.s;
                break;
            }
            case sample_spec::kind::tolerance: {
                auto line = tessellate(curve, spec.tolerance);
                t = std::move(line.t);
                points = std::move(line.points);
                out["tolerance"] = spec.tolerance;
                break;
            }
        }
        out["t"] = t;
        output_json pts = output_json::array();
        for (const auto& p : points) pts.push_back(coords(p, spec.curve.dimension));
        out["points"] = std::move(pts);
        return out;
    });
}

}  // namespace crspline::cli
