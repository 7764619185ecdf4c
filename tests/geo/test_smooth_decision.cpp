// GIS smoothing against the rest of the library: the lengths smooth()
// reports are arc_length()'s lengths of the curves it proved (including its
// own integral for segments pinned at one end by tension 1), and the
// verdicts of its crossing proof are those of decide() (decision.hpp) on
// the same curves. Seeded; counts asserted.
#include "test_support.hpp"

#include <crspline/arc_length.hpp>
#include <crspline/decision.hpp>
#include <crspline/geo/smooth.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <set>
#include <vector>

namespace {
using namespace crspline;
using geo::part_kind;
using P = vec<2>;

// n seeded random walks of 10-50 vertices (steps 0.5-1.5, turns within
// +-60 degrees: some cross themselves), one per `spacing` cell of a grid:
// with spacing 100 no two walks meet; with spacing 8 neighbours overlap.
geo::layer walks(std::mt19937_64& rng, std::size_t n, double spacing) {
    std::uniform_real_distribution<double> u(0, 1);
    geo::layer l;
    const std::size_t side = std::size_t(std::ceil(std::sqrt(double(n))));
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t m = 10 + std::size_t(rng() % 41);
        std::vector<double> xy;
        double h = u(rng) * 2 * std::numbers::pi, x = spacing * double(i % side), y = spacing * double(i / side);
        for (std::size_t k = 0; k < m; ++k) {
            xy.insert(xy.end(), {x, y});
            h += (2 * u(rng) - 1) * std::numbers::pi / 3;
            const double st = 0.5 + u(rng);
            x += st * std::cos(h);
            y += st * std::sin(h);
        }
        l.add_part(i, part_kind::line, xy);
    }
    return l;
}

// The segment from p0 to p1 with tangent m at one end and zero at the other.
cubic_segment<2> pinned_segment(const P& p0, const P& p1, const P& m, bool zero_at_end) {
    const P zero{};
    return zero_at_end ? cubic_segment<2>::hermite(p0, p1, m, zero, 0.0, 1.0)
                       : cubic_segment<2>::hermite(p0, p1, zero, m, 0.0, 1.0);
}

}  // namespace

// end_pinned_length (the integral with the vanishing factor taken out)
// against arc_length's general path at 1e-14, on seeded segments, a third
// of them nearly straight (q ~ 0) and a third with p nearly parallel to q
// (the speed's roots near the real axis).
TEST(GeoLength, EndPinnedLengthAgreesWithArcLength) {
    CRSPLINE_SEEDED(seed, 2911);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    double worst = 0;
    std::size_t checked = 0;
    for (int it = 0; it < 3000; ++it) {
        const P p0{{u(rng), u(rng)}}, p1{{u(rng), u(rng)}};
        P m{{3 * u(rng), 3 * u(rng)}};
        if (it % 3 == 0) m = (2.0 + 0.01 * u(rng)) * (p1 - p0);  // q = b3 - 3 b2 + 2 b0 nearly 0
        if (it % 3 == 1) m = (3.0 * (1 + u(rng))) * (p1 - p0);   // p parallel to q
        const bool zero_at_end = it % 2 == 1;
        const auto seg = pinned_segment(p0, p1, m, zero_at_end);
        // Bezier points with the zero tangent at b[0] (reversed when it is at the end).
        std::array<P, 4> b = zero_at_end ? std::array<P, 4>{p1, p1, p0 + m / 3.0, p0}
                                         : std::array<P, 4>{p0, p0, p1 - m / 3.0, p1};
        const double ref = arc_length(seg, 1e-14);
        const double got = geo::detail::end_pinned_length(b, default_accuracy);
        ASSERT_GT(ref, 0);
        const double rel = std::abs(got - ref) / ref;
        worst = std::max(worst, rel);
        // default_accuracy (1e-12 relative) promised by both, plus the
        // reference's own 1e-14.
        EXPECT_LE(rel, 2e-12) << "it " << it << " got " << got << " ref " << ref;
        ++checked;
    }
    EXPECT_EQ(checked, 3000u);
    std::printf("end_pinned_length: worst relative difference %.3g over %zu segments\n", worst, checked);
}

// Every feature's reported length is arc_length() of its arc's final curve
// (one arc per walk here: the walks do not meet), though smooth() takes
// linear segments by their chords and pinned ones by its own integral.
TEST(GeoLength, ReportedLengthsAreArcLengthsOfTheProvedCurves) {
    CRSPLINE_SEEDED(seed, 2912);
    std::mt19937_64 rng(seed);
    const geo::layer l = walks(rng, 150, 100.0);
    geo::smooth_options opt;
    opt.tolerance = 0.01;
    opt.keep_curves = true;
    const auto r = geo::smooth(l, opt);
    ASSERT_EQ(r.curves.size(), l.feature_count);
    std::size_t pinned = 0, linear = 0;
    for (std::size_t i = 0; i < r.curves.size(); ++i) {
        const auto& c = r.curves[i].curve;
        ASSERT_EQ(r.curves[i].features, std::vector<std::size_t>{i});
        for (std::size_t s = 0; s < c.segment_count(); ++s) {
            const auto b = c.bezier(s);
            const bool z0 = b[1] == b[0], z1 = b[2] == b[3];
            pinned += z0 != z1;
            linear += z0 && z1;
        }
        const double ref = arc_length(c, 1e-13);
        // Each segment to 1e-12 relative (default_accuracy), summed.
        EXPECT_NEAR(r.features[i].length, ref, 2e-12 * ref) << "feature " << i;
    }
    // Not vacuous: the crossings make tension 1 (linear segments) and its neighbours pinned.
    EXPECT_GT(r.stats.input_crossings, 0u);
    EXPECT_GT(linear, 0u);
    EXPECT_GT(pinned, 10u);
}

// The proof's verdicts are decide()'s on the same curves: a walk that the
// proof says crosses (an input crossing kept as the input segments) is in a
// crossing decide() proves, and no other walk is in one; walks it calls
// simple are simple to decide() too (no contact). Dense layers, so that
// neighbours' free curves would meet and the proof adds tension between
// walks, and sparse ones.
TEST(GeoDecision, ProofVerdictsAreDecideVerdicts) {
    CRSPLINE_SEEDED(seed, 2913);
    std::mt19937_64 rng(seed);
    std::size_t crossing_features = 0, simple_features = 0, decided_crossings = 0, tensioned = 0, layers = 0;
    for (double spacing : {100.0, 12.0, 8.0}) {
        for (int rep = 0; rep < 2; ++rep) {
            const geo::layer l = walks(rng, 40, spacing);
            geo::smooth_options opt;
            opt.tolerance = 0.01;
            opt.keep_curves = true;
            const auto r = geo::smooth(l, opt);
            tensioned += r.stats.tensioned_vertices;
            // The arcs: one per walk unless walks share a vertex (they do not: random doubles).
            ASSERT_EQ(r.curves.size(), l.feature_count);
            std::vector<catmull_rom<2>> curves;
            for (const auto& a : r.curves) curves.push_back(a.curve);
            const decision d = decide(std::span<const catmull_rom<2>>(curves), true);
            std::set<std::size_t> in_crossing;
            for (const auto& c : d.crossings) in_crossing.insert({c.curve[0], c.curve[1]});
            decided_crossings += d.crossings.size();
            for (std::size_t f = 0; f < l.feature_count; ++f) {
                const auto v = r.features[f].verdict;
                EXPECT_NE(v, geo::verdict::touches) << "spacing " << spacing << " feature " << f;
                EXPECT_EQ(v == geo::verdict::crosses, in_crossing.count(f) == 1)
                    << "spacing " << spacing << " rep " << rep << " feature " << f;
                crossing_features += v == geo::verdict::crosses;
                simple_features += v == geo::verdict::simple;
            }
            // No contact anywhere: the proof's "simple" is decide()'s.
            EXPECT_TRUE(d.touches.empty()) << "spacing " << spacing << ": " << d.touches.size() << " contacts";
            EXPECT_EQ(d.result == verdict::crosses, r.stats.input_crossings > 0);
            ++layers;
        }
    }
    std::printf("proof vs decide: %zu crossing and %zu simple features agreed, %zu proved crossings, %zu tensioned vertices\n",
                crossing_features, simple_features, decided_crossings, tensioned);
    EXPECT_EQ(layers, 6u);
    EXPECT_GT(crossing_features, 10u);
    EXPECT_GT(simple_features, 10u);
    EXPECT_GE(decided_crossings, crossing_features / 2);
    EXPECT_GT(tensioned, 0u);
}
