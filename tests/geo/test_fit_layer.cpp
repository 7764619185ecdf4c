// Issue 40 (GIS): smooth_options::fit fits each arc with a subset of its
// vertices within a proved distance of its input, and the smoothing's
// proof holds for the fitted curves (no new crossing, every part on its
// side); where it fails, left-out vertices come back. Seeded; counts
// asserted.
#include "test_support.hpp"

#include <crspline/geo/smooth.hpp>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace {
using namespace crspline;
using geo::part_kind;
using geo::ring_role;
using P = vec<2>;

// Noisy wavy rings around the origin, `gap` apart, n vertices each.
geo::layer nested_rings(std::mt19937_64& rng, int rings, double gap, double noise, int n) {
    std::normal_distribution<double> g(0, noise);
    geo::layer l;
    for (int r = 0; r < rings; ++r) {
        std::vector<double> xy;
        for (int k = 0; k < n; ++k) {
            const double a = 2 * std::numbers::pi * k / n, rad = 10 + r * gap + 0.5 * std::sin(7 * a);
            xy.insert(xy.end(), {rad * std::cos(a) + g(rng), rad * std::sin(a) + g(rng)});
        }
        l.add_part(std::size_t(r), part_kind::ring, xy, {}, ring_role::outer);
    }
    return l;
}

double distance_to_part(const geo::layer& l, std::size_t p, const P& x, bool ring) {
    double best = INFINITY;
    const std::size_t v0 = l.part_offsets[p], v1 = l.part_offsets[p + 1];
    for (std::size_t v = v0; v < v1; ++v) {
        const std::size_t w = v + 1 < v1 ? v + 1 : (ring ? v0 : v);
        const P a{{l.xy[2 * v], l.xy[2 * v + 1]}}, b{{l.xy[2 * w], l.xy[2 * w + 1]}};
        best = std::min(best, geo::detail::point_segment_distance(x, a, b));
    }
    return best;
}

TEST(GeoFit, RingsAreFittedProvedAndKeepTheirNesting) {
    CRSPLINE_SEEDED(seed, 40);
    std::mt19937_64 rng(seed);
    std::size_t restored = 0, compared = 0, kept = 0, input = 0;
    for (const double gap : {0.6, 0.3, 0.15}) {
        const geo::layer l = nested_rings(rng, 4, gap, 0.03, 400);
        geo::smooth_options opt;
        opt.tolerance = 0.01;
        opt.fit = 0.1;
        const auto r = geo::smooth(l, opt);
        ASSERT_EQ(r.stats.input_crossings, 0u) << "gap " << gap << ": the noisy inputs cross: not this test's case";
        restored += r.stats.restored_vertices;
        for (std::size_t f = 0; f < 4; ++f) {
            const auto& rep = r.features[f];
            EXPECT_EQ(rep.verdict, geo::verdict::simple);
            EXPECT_GT(rep.max_deviation, 0);
            EXPECT_LE(rep.max_deviation, 0.1);
            kept += rep.control_points;
            input += 400;
            // Independently: every output vertex (on the curve) within the
            // proved deviation of the input ring, and every input vertex
            // within it plus the polylines' tolerance of the output.
            const std::size_t o0 = r.output.part_offsets[f], o1 = r.output.part_offsets[f + 1];
            for (std::size_t v = o0; v < o1; ++v)
                EXPECT_LE(distance_to_part(l, f, P{{r.output.xy[2 * v], r.output.xy[2 * v + 1]}}, true),
                          rep.max_deviation * (1 + 1e-12));
            for (std::size_t v = l.part_offsets[f]; v < l.part_offsets[f + 1]; ++v)
                EXPECT_LE(distance_to_part(r.output, f, P{{l.xy[2 * v], l.xy[2 * v + 1]}}, true),
                          rep.max_deviation + opt.tolerance);
        }
        // Nesting: every output vertex of ring k + 1 outside ring k.
        for (std::size_t k = 0; k + 1 < 4; ++k)
            for (std::size_t v = r.output.part_offsets[k + 1]; v < r.output.part_offsets[k + 2]; ++v) {
                ++compared;
                EXPECT_EQ(geo::detail::point_in_ring(r.output.xy, r.output.part_offsets[k], r.output.part_offsets[k + 1],
                                                     r.output.xy[2 * v], r.output.xy[2 * v + 1]),
                          0)
                    << "gap " << gap << " ring " << k + 1 << " vertex " << v;
            }
    }
    EXPECT_GT(compared, 1000u);
    EXPECT_LT(kept, input / 2) << "the fit kept " << kept << " of " << input << " vertices";
    // At a gap of 0.15 (1.5 tolerances) the fitted rings would meet: the
    // proof brought vertices back (a proof that never fails checks nothing).
    EXPECT_GT(restored, 0u);
}

TEST(GeoFit, SharedBordersAreFittedOnce) {
    // Two squares sharing a wavy, noisy border: the border is one arc, so
    // both outputs hold the same fitted polyline there.
    CRSPLINE_SEEDED(seed, 41);
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g(0, 0.02);
    std::vector<P> border;
    for (int k = 0; k <= 200; ++k) border.push_back(P{{5 + 0.3 * std::sin(k * 0.1) + g(rng), 10.0 * k / 200}});
    std::vector<double> left{0, 0}, right;
    for (const P& p : border) left.insert(left.end(), {p[0], p[1]});
    left.insert(left.end(), {0, 10});
    for (auto it = border.rbegin(); it != border.rend(); ++it) right.insert(right.end(), {(*it)[0], (*it)[1]});
    right.insert(right.end(), {10, 0, 10, 10});
    geo::layer l;
    l.add_part(0, part_kind::ring, left, {}, ring_role::outer);
    l.add_part(1, part_kind::ring, right, {}, ring_role::outer);
    geo::smooth_options opt;
    opt.tolerance = 0.005;
    opt.fit = 0.05;
    const auto r = geo::smooth(l, opt);
    EXPECT_EQ(r.stats.shared_arcs, 1u);
    // The output vertices strictly inside the strip 0 < y < 10 and near x = 5
    // are the border's: the same set in both rings.
    auto border_vertices = [&](std::size_t p) {
        std::vector<std::array<double, 2>> v;
        for (std::size_t k = r.output.part_offsets[p]; k < r.output.part_offsets[p + 1]; ++k) {
            const double x = r.output.xy[2 * k], y = r.output.xy[2 * k + 1];
            if (y > 0 && y < 10 && std::abs(x - 5) < 1) v.push_back({x, y});
        }
        std::sort(v.begin(), v.end());
        return v;
    };
    const auto a = border_vertices(0), b = border_vertices(1);
    EXPECT_GT(a.size(), 10u);
    EXPECT_EQ(a, b);
    EXPECT_LT(r.features[0].control_points, 100u);  // of 203 input vertices
}

TEST(GeoFit, BadFitDistancesAreRefused) {
    geo::layer l;
    l.add_part(0, part_kind::line, std::vector<double>{1e12, 0, 1.000001e12, 1, 1.000002e12, 0});
    auto message = [&](double fit) {
        geo::smooth_options opt;
        opt.tolerance = 1;
        opt.fit = fit;
        try {
            geo::smooth(l, opt);
        } catch (const invalid_input& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message(-1), "fit must be a positive finite distance, got -1");
    EXPECT_EQ(message(NAN), "fit must be a positive finite distance, got nan");
    EXPECT_EQ(message(1e-6).rfind("fit 1e-06 is at or below the rounding floor 0.0568", 0), 0u) << message(1e-6);
}

}  // namespace
