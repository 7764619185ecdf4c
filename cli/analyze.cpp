// crspline analyze: per segment cusps, loops, distances to the chord and the
// paper's bound; the curve's self-intersections; the Section 5 certificate.
#include <vector>

#include <crspline/analysis.hpp>
#include <crspline/certify.hpp>
#include <crspline/intersections.hpp>

#include "commands.hpp"
#include "dispatch.hpp"
#include "json_input.hpp"

namespace crspline::cli {

output_json run_analyze(const document& input) {
    const curve_spec spec = parse_analyze(input);
    return with_dimension(spec.dimension, [&](auto dim) {
        constexpr std::size_t D = decltype(dim)::value;
        const catmull_rom<D, double> curve = make_curve<D>(spec);
        auto coords = [&](const vec<D, double>& p) { return cli::coords(p, spec.dimension); };

        // 1. Each segment on its own (u local to the segment).
        output_json segments = output_json::array();
        for (const auto& a : analyze(curve)) {
            output_json s;
            s["index"] = a.index;
            s["cusp_u"] = a.cusp_u;
            output_json loops = output_json::array();
            for (const auto& uv : a.self_intersection) loops.push_back({uv[0], uv[1]});
            s["self_intersection"] = std::move(loops);
            s["fold"] = a.fold;
            s["max_chord_distance"] = a.max_chord_distance;
            s["max_chord_line_distance"] = a.max_chord_line_distance;
            s["distance_bound"] = a.bounds ? output_json(a.bounds->eq6) : output_json(nullptr);
            output_json b = output_json::array();
            for (const auto& p : a.bezier) b.push_back(coords(p));
            s["bezier"] = std::move(b);
            segments.push_back(std::move(s));
        }

        // 2. The curve against itself (loops inside a segment have i == j).
        const auto found = find_intersections(curve);
        output_json meets = output_json::array();
        for (const auto& x : found.intersections) {
            output_json m;
            m["segments"] = {x.segments[0], x.segments[1]};
            m["u"] = {x.u[0], x.u[1]};
            m["point"] = coords(x.point);
            // 0 to rounding for a crossing; up to the tolerance for a near
            // miss (in 3-D, closest approaches are what is reported).
            m["distance"] = x.distance;
            meets.push_back(std::move(m));
        }

        // 3. The certificate of Section 5.
        certify_options opt;
        opt.search_on_failure = false;
        const auto cert = certify_intersection_free(curve, opt);
        output_json free;
        free["certified"] = cert.certified;
        free["failed_rule"] = cert.certified ? output_json(nullptr) : output_json(to_string(cert.failed_rule));
        free["detail"] = cert.detail;

        output_json out;
        out["segments"] = std::move(segments);
        out["intersections"] = std::move(meets);
        out["folds"] = found.folds;
        // false: some pair of segments ran out of the search's budget (the
        // list may then miss meetings).
        out["complete"] = found.complete;
        out["intersection_free"] = std::move(free);
        return out;
    });
}

}  // namespace crspline::cli
