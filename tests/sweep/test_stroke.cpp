// Strokes: simple rings, areas of known regions, holes where the stroke
// overlaps itself, joins and caps. (Validity against Shapely and areas
// against its buffer: tests/python/test_sweep.py.)
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <crspline/stroke.hpp>

#include "test_support.hpp"

using namespace crspline;
using p2 = vec<2>;

namespace {

double area_of(const stroke_result& r) {
    double a = 0;
    for (const auto& p : r.polygons) {
        a += detail::ring_area(p.exterior);
        for (const auto& h : p.holes) a += detail::ring_area(h);
    }
    return a;
}

bool proper_crossing(const p2& a, const p2& b, const p2& c, const p2& d) {
    const double o1 = detail::orient(a, b, c), o2 = detail::orient(a, b, d), o3 = detail::orient(c, d, a),
                 o4 = detail::orient(c, d, b);
    return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

/// No two edges of all the rings cross (brute force).
std::size_t crossings(const stroke_result& r) {
    std::vector<std::array<p2, 2>> e;
    auto add = [&](const std::vector<p2>& ring) {
        for (std::size_t i = 0; i < ring.size(); ++i) e.push_back({ring[i], ring[(i + 1) % ring.size()]});
    };
    for (const auto& p : r.polygons) {
        add(p.exterior);
        for (const auto& h : p.holes) add(h);
    }
    std::size_t n = 0;
    for (std::size_t i = 0; i < e.size(); ++i)
        for (std::size_t j = i + 1; j < e.size(); ++j)
            if (proper_crossing(e[i][0], e[i][1], e[j][0], e[j][1])) ++n;
    return n;
}

}  // namespace

// A straight stroke: a rectangle (butt), plus a disc (round caps), plus two
// squares (square caps). Tolerance x perimeter bounds the area error (the
// round caps' inscribed arcs lose at most that).
TEST(Stroke, StraightStrokeAreas) {
    const catmull_rom<2> c(std::vector<p2>{{{0, 0}}, {{1, 0}}, {{2, 0}}, {{4, 0}}});
    const double w = 0.5, d = w / 2;
    stroke_options o;
    o.tolerance = 1e-4;
    o.cap = stroke_cap::butt;
    auto r = stroke(c, w, o);
    ASSERT_EQ(r.polygons.size(), 1u);
    EXPECT_NEAR(area_of(r), 4 * w, 1e-12);
    o.cap = stroke_cap::round;
    r = stroke(c, w, o);
    EXPECT_NEAR(area_of(r), 4 * w + std::numbers::pi * d * d, 1e-4 * (8 + 2 * std::numbers::pi * d));
    o.cap = stroke_cap::square;
    r = stroke(c, w, o);
    EXPECT_NEAR(area_of(r), 4 * w + 2 * w * d, 1e-12);
}

// A path that retraces itself: the stroke is the band around it, whichever
// way it runs. Before, the outline's edges came twice over (there and back,
// or both sides of a U-turn) and the nonzero rule left collinear overlaps
// uncut: the open out-and-back gave no polygon at all, the closed one a
// sliver of area 0.013. Open, uniform (a cusp at the turn: a round join):
// the segment [0, 3] at half width 0.1 with round ends, area 0.6 + pi 0.01,
// within the tolerance times the perimeter; the same along a diagonal
// (length 3 |(1, 0.7)|); closed, centripetal (the curve turns smoothly
// where it reverses, as the open one, so the same region).
TEST(Stroke, RetracedPathIsItsBand) {
    const double w = 0.2, d = w / 2, tol = 1e-4;
    stroke_options o;
    o.tolerance = tol;
    o.join = stroke_join::round;
    o.cap = stroke_cap::round;
    options<2> uniform;
    uniform.alpha = 0.0;
    const double slack = tol * (2 * 3 + 2 * std::numbers::pi * d) * 2;
    std::size_t checked = 0;
    for (const p2 step : {p2{{1, 0}}, p2{{1, 0.7}}}) {
        std::vector<p2> there_and_back;
        for (int k : {0, 1, 2, 3, 2, 1, 0}) there_and_back.push_back(double(k) * step);
        const double len = 3 * norm(step);
        const auto r = stroke(catmull_rom<2>(there_and_back, uniform), w, o);
        ASSERT_EQ(r.polygons.size(), 1u) << "step " << step[1];
        EXPECT_EQ(r.polygons[0].holes.size(), 0u);
        EXPECT_NEAR(area_of(r), len * w + std::numbers::pi * d * d, slack * norm(step)) << "step " << step[1];
        EXPECT_EQ(crossings(r), 0u);
        options<2> ring;
        ring.closed = true;
        const std::vector<p2> out{there_and_back.begin(), there_and_back.begin() + 4};
        const auto rc = stroke(catmull_rom<2>(out, ring), w, o);
        ASSERT_EQ(rc.polygons.size(), 1u) << "closed, step " << step[1];
        EXPECT_NEAR(area_of(rc), len * w + std::numbers::pi * d * d, slack * norm(step)) << "closed, step " << step[1];
        checked += 2;
    }
    EXPECT_EQ(checked, 4u);
}

// A closed circle-like curve: an annulus, one polygon with one hole, its
// area pi ((R + d)^2 - (R - d)^2) = 4 pi R d within the tolerance times the
// perimeter (plus the curve's own distance from the circle, measured).
TEST(Stroke, ClosedCurveGivesAnAnnulus) {
    std::vector<p2> pts;
    for (int k = 0; k < 64; ++k) pts.push_back({{std::cos(2 * std::numbers::pi * k / 64), std::sin(2 * std::numbers::pi * k / 64)}});
    options<2> oc;
    oc.closed = true;
    const catmull_rom<2> c(pts, oc);
    stroke_options o;
    o.tolerance = 1e-4;
    const auto r = stroke(c, 0.2, o);
    ASSERT_EQ(r.polygons.size(), 1u);
    ASSERT_EQ(r.polygons[0].holes.size(), 1u);
    EXPECT_GT(detail::ring_area(r.polygons[0].exterior), 0);
    EXPECT_LT(detail::ring_area(r.polygons[0].holes[0]), 0);
    double dev = 0;  // the Catmull-Rom curve's distance from the unit circle
    for (int k = 0; k <= 6400; ++k) dev = std::max(dev, std::abs(norm(c.evaluate(c.t_max() * k / 6400.0)) - 1));
    EXPECT_NEAR(area_of(r), 4 * std::numbers::pi * 0.1, (1e-4 + dev) * 4 * std::numbers::pi);
    EXPECT_EQ(crossings(r), 0u);
}

// A curve that crosses itself with a wide stroke: the union, with a hole
// where the loop encloses free space, rings that never cross.
TEST(Stroke, SelfOverlapIsTheUnion) {
    const catmull_rom<2> c(std::vector<p2>{{{0, 0}}, {{4, 0}}, {{4, 3}}, {{2, 4}}, {{0, 3}}, {{2, -1}}});
    const auto r = stroke(c, 0.4);
    ASSERT_GE(r.polygons.size(), 1u);
    std::size_t holes = 0;
    for (const auto& p : r.polygons) holes += p.holes.size();
    EXPECT_GE(holes, 1u);
    EXPECT_EQ(crossings(r), 0u);
}

// Random curves and widths: rings never cross, outer rings counterclockwise,
// holes clockwise.
TEST(Stroke, RandomStrokesAreSimple) {
    CRSPLINE_SEEDED(seed, 2041);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 10);
    int checked = 0;
    for (int trial = 0; trial < 40; ++trial) {
        std::vector<p2> pts;
        const int n = 3 + trial % 8;
        for (int k = 0; k < n; ++k) pts.push_back({{u(rng), u(rng)}});
        options<2> oc;
        oc.closed = trial % 3 == 0;
        const catmull_rom<2> c(pts, oc);
        stroke_options o;
        o.join = stroke_join(trial % 3);
        o.cap = stroke_cap((trial / 3) % 3);
        const auto r = stroke(c, 0.1 + u(rng) / 5, o);
        EXPECT_EQ(crossings(r), 0u) << "trial " << trial;
        for (const auto& p : r.polygons) {
            EXPECT_GT(detail::ring_area(p.exterior), 0) << "trial " << trial;
            for (const auto& h : p.holes) EXPECT_LT(detail::ring_area(h), 0) << "trial " << trial;
        }
        ++checked;
    }
    EXPECT_EQ(checked, 40);
}

// Joins at a corner (coincident points make a uniform curve's corner): a
// mitre reaches the corner's offset, a bevel cuts it, round lies between.
TEST(Stroke, JoinsAtACorner) {
    options<2> oc;
    oc.alpha = 0.0;
    oc.tension = 1.0;  // tension 1: zero tangents, straight segments with corners at the points
    const catmull_rom<2> c(std::vector<p2>{{{0, 0}}, {{2, 0}}, {{2, 2}}}, oc);
    stroke_options o;
    o.tolerance = 1e-5;
    std::array<double, 3> a{};
    for (int j = 0; j < 3; ++j) {
        o.join = stroke_join(j);
        a[std::size_t(j)] = area_of(stroke(c, 0.5, o));
    }
    const double d = 0.25;
    // mitre - bevel is the triangle beyond the bevel: d^2 / 2 for a right angle;
    // round - bevel is the circular segment: d^2 (pi / 4 - 1 / 2).
    EXPECT_NEAR(a[1] - a[2], d * d / 2, 1e-4);
    EXPECT_NEAR(a[0] - a[2], d * d * (std::numbers::pi / 4 - 0.5), 1e-4);
    o.join = stroke_join::miter;
    o.miter_limit = 1.2;  // sqrt(2) > 1.2: a bevel
    EXPECT_NEAR(area_of(stroke(c, 0.5, o)), a[2], 1e-9);
}
