// crspline::geo: what smooth() is asked (smooth_options) and what it answers
// (feature_report, smooth_stats, smooth_result): the one report every front
// end (Python, the command, Dask) renders. See smooth.hpp for the promises.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "../bounds.hpp"
#include "../catmull_rom.hpp"
#include "layer.hpp"

namespace crspline::geo {

/// What happened to a feature.
enum class feature_status : std::uint8_t {
    ok = 0,          ///< smoothed
    empty = 1,       ///< no vertices: nothing to smooth, output empty
    degenerate = 2,  ///< a part with too few distinct points, passed through (others smoothed)
    invalid = 3,     ///< a non-finite coordinate: the feature passed through unchanged
};

/// How a feature's output meets the others and itself.
/// Ordered by what a user must look at first: the larger wins.
enum class verdict : std::uint8_t {
    simple = 0,   ///< meets no other output, and itself only at its joints
    touches = 1,  ///< shares a boundary or a junction with another feature (a coverage), or its input touches one
    nested = 2,   ///< the input's rings nest invalidly (geo/nesting.hpp; the message says which): kept as they are
    crosses = 3,  ///< an input crossing remains: the input segments there are output as they are
};

inline const char* to_string(feature_status s) noexcept {
    switch (s) {
        case feature_status::ok: return "ok";
        case feature_status::empty: return "empty";
        case feature_status::degenerate: return "degenerate";
        case feature_status::invalid: return "invalid";
    }
    return "?";
}
inline const char* to_string(verdict v) noexcept {
    switch (v) {
        case verdict::simple: return "simple";
        case verdict::touches: return "touches";
        case verdict::nested: return "nested";
        case verdict::crosses: return "crosses";
    }
    return "?";
}

/// How to smooth. Every choice has a visible default except the tolerance.
struct smooth_options {
    double alpha = 0.5;                   ///< knot exponent in [0, 1]; centripetal by default
    double tolerance = 0;                 ///< output polyline within this of the curve; > 0, required
    std::optional<double> max_deviation{};  ///< no curve point farther than this from the input polyline
    bool preserve_topology = true;        ///< shared arcs and the crossing proof; false: part by part, unchecked
    /// If given, every curve stays inside this box (proved by its pieces'
    /// control points, raised by tension like the rest): a geographic
    /// layer's frame keeps latitudes within the poles and longitudes within
    /// the antimeridian. Inputs outside it are left as they are there.
    std::optional<box<2>> domain{};
    /// false: measures only (lengths, deviations, verdicts); the output
    /// layer is the input, and the curves are tessellated only where the
    /// proof needs their pieces.
    bool polylines = true;
    /// If set, called now and then from the calling thread with the
    /// fraction of the work done, in [0, 1] (a terminal's progress line).
    std::function<void(double)> progress{};
    /// true: smooth_result::curves holds every arc's final curve (the one
    /// the proof was about), e.g. to hand to decide() (decision.hpp).
    bool keep_curves = false;
    /// If given (issue 40), each arc is first fitted with few control
    /// points, a subset of its vertices (fit.hpp, subset mode: its ends, the
    /// junctions, kept), within this distance of its input both ways
    /// (proved); the proof below then holds for the fitted curves, and
    /// where a pair, a side or the distance is not proved for a segment that
    /// left input vertices out, those vertices come back (then tension, as
    /// in smoothing). `tolerance` stays the output polylines' distance from
    /// the curves.
    std::optional<double> fit{};
};

/// One feature's outcome. Lengths and deviations in the layer's units.
struct feature_report {
    feature_status status = feature_status::ok;
    geo::verdict verdict = geo::verdict::simple;
    double length = 0;         ///< arc length of the smoothed curves (all parts, all rings)
    double max_deviation = 0;  ///< proved bound on the distance of the curves from the input polyline
    std::size_t control_points = 0;  ///< the curves' control points (with fit: the vertices kept), all parts
    std::string message;       ///< why, when the status is not ok; with verdict nested, which ring lies where
};

/// Counts of what smooth() did, for reports and tests.
struct smooth_stats {
    std::size_t arcs = 0;                ///< arcs smoothed (each once)
    std::size_t shared_arcs = 0;         ///< arcs used by more than one part
    std::size_t junctions = 0;
    std::size_t rounds = 0;              ///< proof rounds (1 when nothing needed tension)
    std::size_t tensioned_vertices = 0;  ///< arc vertices left with tension > 0
    std::size_t linear_segments = 0;     ///< segments output as their input segment (tension 1)
    std::size_t pieces = 0;              ///< polyline pieces in the final proof
    std::size_t pairs_checked = 0;       ///< candidate pairs examined in the final proof
    std::size_t input_crossings = 0;     ///< pairs of input segments that cross (left as they are)
    std::size_t input_touches = 0;       ///< pairs of input segments that touch or overlap without crossing
    /// Times a vertex of another arc was found in the region a segment
    /// sweeps between its input chord and its curve (its tension raised
    /// there so that the vertex keeps its side), over every round.
    std::size_t swept_vertices = 0;
    /// With smooth_options::fit: input vertices brought back into fitted
    /// arcs where the proof needed them (over every round).
    std::size_t restored_vertices = 0;
};

/// One arc's final curve (smooth_options::keep_curves): its tensioned
/// Catmull-Rom curve (segments at tension 1 on both ends are their input
/// segments) and the features that use the arc, sorted.
struct arc_curve {
    catmull_rom<2> curve;
    std::vector<std::size_t> features;
};

struct smooth_result {
    layer output;                          ///< same parts, kinds, features and extra_dims; rings closed (first vertex repeated)
    std::vector<feature_report> features;  ///< one per feature of the input
    smooth_stats stats;
    std::vector<arc_curve> curves;         ///< per arc, only with smooth_options::keep_curves
};

}  // namespace crspline::geo
