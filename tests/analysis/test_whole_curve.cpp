// Whole-curve analysis: intersections between segments (2-D exact, 3-D
// closest approaches), the Figure-5 bounding volumes (dense sampling), the
// Section-5 certificate (a search for counterexamples among thousands of
// certified curves) and curvature maxima (Section 6.4).
#include <cstdlib>

#include <crspline/certify.hpp>
#include <crspline/intersections.hpp>

#include "test_support.hpp"

namespace {
using namespace crspline;
using P2 = vec<2>;
using P3 = vec<3>;
using crspline::test::pi;
using test::property_scale;
using test::smooth_polygon;



// Polyline of every segment, m chords each.
template <std::size_t D>
std::vector<std::vector<vec<D>>> polylines(const catmull_rom<D>& c, int m) {
    std::vector<std::vector<vec<D>>> out(c.segment_count());
    for (std::size_t i = 0; i < c.segment_count(); ++i)
        for (int k = 0; k <= m; ++k) out[i].push_back(c.segment(i).at(double(k) / m));
    return out;
}

bool chords_cross(const P2& a, const P2& b, const P2& c, const P2& d) {
    auto orient = [](const P2& p, const P2& q, const P2& r) {
        return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
    };
    const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
    return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

// Polyline crossings between different segments, leaving out the chords at
// a shared joint: (i, j, chord on i, chord on j).
std::vector<std::array<std::size_t, 4>> polyline_crossings(const catmull_rom<2>& c, int m) {
    const auto pl = polylines(c, m);
    const std::size_t n = c.segment_count();
    std::vector<std::array<std::size_t, 4>> out;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
            for (int a = 0; a < m; ++a)
                for (int b = 0; b < m; ++b) {
                    const bool next = j == i + 1, wrap = c.closed() && i == 0 && j == n - 1;
                    if (next && a == m - 1 && b == 0) continue;
                    if (wrap && a == 0 && b == m - 1) continue;
                    if (chords_cross(pl[i][a], pl[i][a + 1], pl[j][b], pl[j][b + 1])) out.push_back({i, j, std::size_t(a), std::size_t(b)});
                }
    return out;
}

TEST(Intersections, FigureEightCrossesOnce) {
    const std::vector<P2> p{P2{{0, 0}}, P2{{4, 4}}, P2{{4, 0}}, P2{{0, 4}}};
    catmull_rom<2> c(p);
    const auto r = find_intersections(c);
    ASSERT_EQ(r.intersections.size(), 1u);
    const auto& x = r.intersections[0];
    EXPECT_EQ(x.segments, (std::array<std::size_t, 2>{0, 2}));
    EXPECT_LE(norm(c.segment(0).at(x.u[0]) - c.segment(2).at(x.u[1])), 1e-13 * 8);
    EXPECT_TRUE(r.complete);
}

// Random 2-D curves: every polyline crossing between segments is reported
// (with parameters within a chord), and every reported crossing closes to
// rounding.
TEST(Intersections, AgreeWithPolylinesOnRandomCurves) {
    CRSPLINE_SEEDED(seed, 4001);
    std::mt19937_64 rng(seed);
    const int m = 64;
    std::size_t curves = 0, reported = 0, crossings = 0;
    const std::size_t count = std::size_t(300 * property_scale());
    for (std::size_t rep = 0; rep < count; ++rep) {
        const double alpha = std::array{0.0, 0.5, 1.0}[rep % 3];
        auto p = crspline::test::random_polygon<2>(rng, 5 + rep % 5, 1.0);
        catmull_rom<2> c(p, {.alpha = alpha, .closed = rep % 4 == 0});
        const double scale = crspline::test::scale_of(p);
        const auto r = find_intersections(c);
        ASSERT_TRUE(r.complete);
        for (const auto& x : r.intersections) {
            const auto& A = c.segment(x.segments[0]);
            const auto& B = c.segment(x.segments[1]);
            EXPECT_LE(norm(A.at(x.u[0]) - B.at(x.u[1])), 1e-11 * scale) << "rep " << rep;
            ++reported;
        }
        for (const auto& [i, j, a, b] : polyline_crossings(c, m)) {
            bool found = false;
            // A crossing through a polygon vertex may be reported on the
            // neighbouring segment (u = 1 instead of v = 0): accept any
            // reported point within two chords of the polyline crossing.
            const auto pl = polylines(c, m);
            const double reach = 2 * (norm(pl[i][a + 1] - pl[i][a]) + norm(pl[j][b + 1] - pl[j][b]));
            for (const auto& x : r.intersections) found |= norm(x.point - pl[i][a]) <= reach;
            for (const auto& x : r.intersections)
                // Within a chord's width of the crossing chords (the polyline
                // is off the curve by its sagitta, so it crosses a little away).
                found |= x.segments[0] == i && x.segments[1] == j && x.u[0] >= double(a - 1) / m &&
                         x.u[0] <= double(a + 2) / m && x.u[1] >= double(b - 1) / m && x.u[1] <= double(b + 2) / m;
            EXPECT_TRUE(found) << "rep " << rep << " segments " << i << ", " << j << " chords " << a << ", " << b;
            ++crossings;
        }
        ++curves;
    }
    std::printf("intersections: %zu curves, %zu reported, %zu polyline crossings\n", curves, reported, crossings);
    EXPECT_EQ(curves, count);
    EXPECT_GT(crossings, count / 10);
}

// Issue 31 point 4: segments joined through zero-length segments (repeated
// points, alpha > 0) are neighbours, meeting at their shared point by
// construction: the straight line 0,0 / 1,0 / 1,0 / 2,0 does not cross
// itself, open or closed, and the certificate's search agrees.
TEST(Intersections, ZeroLengthSegmentsJoinTheirNeighbours) {
    const std::vector<std::vector<P2>> cases{
        {P2{{0, 0}}, P2{{1, 0}}, P2{{1, 0}}, P2{{2, 0}}},                         // the line
        {P2{{0, 0}}, P2{{1, 0}}, P2{{1, 0}}, P2{{1, 0}}, P2{{1, 1}}, P2{{2, 3}}},  // a run of three, a turn
        {P2{{0, 0}}, P2{{1, 0}}, P2{{1, 1}}, P2{{0, 1}}, P2{{0, 0}}},              // closed: repeated across the seam
        {P2{{0, 0}}, P2{{0, 0}}, P2{{1, 0}}, P2{{1, 1}}, P2{{0, 1}}, P2{{0, 0}}},  // closed: both sides of it
    };
    int checked = 0;
    for (std::size_t k = 0; k < cases.size(); ++k)
        for (const double alpha : {0.5, 1.0}) {
            const bool closed = k >= 2;
            const catmull_rom<2> c(cases[k], {.alpha = alpha, .closed = closed});
            const auto r = find_intersections(c);
            EXPECT_TRUE(r.intersections.empty()) << "case " << k << " alpha " << alpha << ": segments "
                                                 << r.intersections[0].segments[0] << " and "
                                                 << r.intersections[0].segments[1];
            EXPECT_TRUE(r.overlaps.empty()) << "case " << k;
            EXPECT_TRUE(r.complete);
            const auto cert = certify_intersection_free(c);
            EXPECT_FALSE(cert.certified);  // coincident points: not certified, but not crossing either
            EXPECT_EQ(cert.failed_rule, certify_rule::coincident_points);
            EXPECT_EQ(cert.intersects, std::optional<bool>(false)) << "case " << k << " alpha " << alpha;
            ++checked;
        }
    EXPECT_EQ(checked, 8);
    // A real crossing away from the repeated point is still found: the
    // figure eight of FigureEightCrossesOnce with its second point doubled.
    const catmull_rom<2> eight({P2{{0, 0}}, P2{{4, 4}}, P2{{4, 4}}, P2{{4, 0}}, P2{{0, 4}}});
    const auto r = find_intersections(eight);
    ASSERT_EQ(r.intersections.size(), 1u);
    EXPECT_EQ(r.intersections[0].segments, (std::array<std::size_t, 2>{0, 3}));
}

// Seeded random polygons with runs of repeated points (alpha > 0, open and
// closed, runs across a closed curve's seam too): the curve is the Hermite
// curve of the same points without the repeats, with the same tangents and
// knots (a zero-length segment only has a knot interval of 0), and its
// self-intersections are that curve's, segment for segment: none at a
// shared point, every real crossing found.
TEST(Intersections, RepeatedPointsAddNoCrossings) {
    CRSPLINE_SEEDED(seed, 3104);
    std::mt19937_64 rng(seed);
    std::size_t curves = 0, zero_segments = 0, crossings = 0;
    const std::size_t count = std::size_t(200 * property_scale());
    for (std::size_t rep = 0; rep < count; ++rep) {
        const double alpha = std::array{0.5, 1.0, 0.25}[rep % 3];
        const bool closed = rep % 3 == 1;
        const auto base = crspline::test::random_polygon<2>(rng, 5 + rep % 6, 1.0);
        // Repeat one or two vertices one to three times; a closed curve
        // sometimes ends where it starts (a zero chord across the seam).
        std::vector<P2> p;
        std::uniform_int_distribution<std::size_t> pick(0, base.size() - 1), times(1, 3);
        const std::size_t r1 = pick(rng), r2 = rep % 2 ? pick(rng) : base.size();
        for (std::size_t i = 0; i < base.size(); ++i) {
            p.push_back(base[i]);
            if (i == r1 || i == r2)
                for (std::size_t t = times(rng); t > 0; --t) p.push_back(base[i]);
        }
        if (closed && rep % 2 == 0) p.push_back(base[0]);
        const catmull_rom<2> c(p, {.alpha = alpha, .closed = closed});
        // The same curve without its zero-length segments.
        std::vector<std::size_t> kept;  // segments of c with a length
        for (std::size_t i = 0; i < c.segment_count(); ++i)
            if (c.grid()[i + 1] > c.grid()[i]) kept.push_back(i);
            else ++zero_segments;
        std::vector<P2> q, out, in;
        std::vector<double> g;
        for (const std::size_t i : kept) {
            q.push_back(c.bezier(i)[0]);
            out.push_back(c.tangents(i)[0]);
            g.push_back(c.grid()[i]);
        }
        in.assign(q.size(), P2{});
        for (std::size_t k = 0; k < kept.size(); ++k) in[(k + 1) % q.size()] = c.tangents(kept[k])[1];
        if (!closed) {
            q.push_back(c.bezier(kept.back())[3]);
            out.push_back(P2{});
            in.push_back(c.tangents(kept.back())[1]);
        }
        g.push_back(c.grid()[kept.back() + 1]);
        const auto h = catmull_rom<2>::hermite(std::span<const P2>(q), std::span<const P2>(out),
                                               std::span<const P2>(in), std::span<const double>(g), closed);
        ASSERT_EQ(h.segment_count(), kept.size());
        const auto rc = find_intersections(c), rh = find_intersections(h);
        ASSERT_TRUE(rc.complete && rh.complete) << "rep " << rep;
        const double scale = crspline::test::scale_of(p);
        ASSERT_EQ(rc.intersections.size(), rh.intersections.size()) << "rep " << rep << " alpha " << alpha;
        for (std::size_t k = 0; k < rc.intersections.size(); ++k) {
            const auto& x = rc.intersections[k];
            const auto& y = rh.intersections[k];
            EXPECT_EQ(kept[y.segments[0]], x.segments[0]) << "rep " << rep;
            EXPECT_EQ(kept[y.segments[1]], x.segments[1]) << "rep " << rep;
            // The same cubics up to the rounding of h times the tangent: the
            // polished meetings agree to the search's own precision.
            EXPECT_LE(norm(x.point - y.point), 1e-9 * scale) << "rep " << rep;
            ++crossings;
        }
        ++curves;
    }
    std::printf("repeated points: %zu curves, %zu zero-length segments, %zu crossings\n", curves, zero_segments,
                crossings);
    EXPECT_EQ(curves, count);
    EXPECT_GE(zero_segments, count);  // at least one repeat per curve
    EXPECT_GT(crossings, count / 20);  // real crossings were there to find
}

TEST(Intersections, ThreeDClosestApproaches) {
    // The figure eight in the plane z = 0, then with one vertex lifted.
    std::vector<P3> p{P3{{0, 0, 0}}, P3{{4, 4, 0}}, P3{{4, 0, 0}}, P3{{0, 4, 0}}};
    EXPECT_EQ(find_intersections(catmull_rom<3>(p)).intersections.size(), 1u);
    p[3][2] = 0.01;
    const catmull_rom<3> lifted(p);
    EXPECT_TRUE(find_intersections(lifted).intersections.empty());  // default: 1e-9 of the scale
    const auto near = find_intersections(lifted, 0.05);
    ASSERT_EQ(near.intersections.size(), 1u);
    EXPECT_GT(near.intersections[0].distance, 0.0);
    EXPECT_LT(near.intersections[0].distance, 0.01);
}

// Figure 5: the curve lies inside its bounding volumes (dense sampling),
// local and tightened, for every alpha where the paper bounds it.
TEST(BoundingVolumes, ContainTheCurve) {
    CRSPLINE_SEEDED(seed, 4002);
    std::mt19937_64 rng(seed);
    std::size_t samples = 0, curves = 0;
    const std::size_t count = std::size_t(400 * property_scale());
    for (std::size_t rep = 0; rep < count; ++rep) {
        const double alpha = std::array{0.0, 0.25, 0.5, 0.75, 1.0}[rep % 5];
        auto p = crspline::test::random_polygon<2>(rng, 6, 3.0);
        const catmull_rom<2> c(p, {.alpha = alpha, .closed = rep % 3 == 0});
        const double slack = 1e-12 * crspline::test::scale_of(p);
        for (auto kind : {volume_kind::tightened, volume_kind::local}) {
            if (kind == volume_kind::local && alpha < 0.5) continue;  // unbounded (Eq. 6 grows like r^(1-2a))
            const auto v = paper_bounding_volumes(c, kind);
            ASSERT_EQ(v.boxes.size(), c.segment_count());
            if (alpha == 0.5 && kind == volume_kind::tightened) {
                // Centripetal needs no balls (Eq. 8 is identically 0).
                EXPECT_TRUE(v.balls.empty());
            }
            for (std::size_t i = 0; i < c.segment_count(); ++i)
                for (int k = 0; k <= 200; ++k) {
                    const P2 x = c.segment(i).at(k / 200.0);
                    EXPECT_TRUE(v.segment_contains(i, x, slack))
                        << "rep " << rep << " alpha " << alpha << " segment " << i << " u " << k / 200.0
                        << (kind == volume_kind::local ? " local" : " tightened");
                    ++samples;
                }
        }
        ++curves;
    }
    std::printf("volumes: %zu curves, %zu samples inside\n", curves, samples);
    EXPECT_EQ(curves, count);
    EXPECT_GE(samples, count * 6 * 201);
}

// The certificate is a guarantee: among thousands of random certified
// centripetal curves (2-D and 3-D, open and closed), none intersects itself
// (exact search and dense polylines).
TEST(Certify, NoCounterexampleAmongCertifiedCurves) {
    CRSPLINE_SEEDED(seed, 4003);
    std::mt19937_64 rng(seed);
    const std::size_t tries = std::size_t(6000 * property_scale());
    std::size_t certified = 0, certified3 = 0;
    std::array<std::size_t, 6> failures{};
    for (std::size_t rep = 0; rep < tries; ++rep) {
        const bool closed = rep % 5 == 0;
        const std::size_t n = 4 + rep % 9;
        const double turn = (0.4 + 0.8 * double(rep % 7) / 6) * 2 * pi / 3;  // up to 160 degrees of turn
        if (rep % 6 == 5) {
            const auto p = smooth_polygon<3>(rng, n, turn, 1.5);
            const catmull_rom<3> c(p, {.closed = closed});
            const auto cert = certify_intersection_free(c, {.search_on_failure = false});
            ++failures[std::size_t(cert.failed_rule)];
            if (!cert.certified) continue;
            ++certified3;
            EXPECT_TRUE(find_intersections(c).intersections.empty()) << "rep " << rep;
            continue;
        }
        const auto p = smooth_polygon<2>(rng, n, turn, 1.5);
        const catmull_rom<2> c(p, {.closed = closed});
        const auto cert = certify_intersection_free(c, {.search_on_failure = false});
        ++failures[std::size_t(cert.failed_rule)];
        if (!cert.certified) continue;
        ++certified;
        const auto r = find_intersections(c);
        EXPECT_FALSE(r.any()) << "rep " << rep << ": certified but intersects";
        EXPECT_TRUE(polyline_crossings(c, 24).empty()) << "rep " << rep << ": certified but the polyline crosses";
    }
    std::printf("certify: %zu tries, %zu certified in 2-D, %zu in 3-D; failures: centripetal %zu, coincident %zu, "
                "angle %zu, boxes %zu, adjacent pair %zu\n",
                tries, certified, certified3, failures[1], failures[2], failures[3], failures[4], failures[5]);
    if (property_scale() >= 1) {
        EXPECT_GE(certified, 2000u);
        EXPECT_GE(certified3, 200u);
    }
    EXPECT_GT(failures[3], 0u);
    EXPECT_GT(failures[4], 0u);
}

TEST(Certify, ReportsTheFailedRuleAndWhetherItIntersects) {
    // Figure eight: its two adjacent pairs each have an end segment, and the
    // exact check proves them apart; the boxes of segments 0 and 2 overlap,
    // and they do cross.
    {
        const catmull_rom<2> c({P2{{0, 0}}, P2{{4, 4}}, P2{{4, 0}}, P2{{0, 4}}});
        const auto cert = certify_intersection_free(c);
        EXPECT_FALSE(cert.certified);
        EXPECT_EQ(cert.failed_rule, certify_rule::overlapping_boxes) << cert.detail;
        EXPECT_EQ(cert.segments, (std::optional<std::array<std::size_t, 2>>({0, 2})));
        ASSERT_TRUE(cert.intersects.has_value());
        EXPECT_TRUE(*cert.intersects);
    }
    // The same eight between two more points: vertex 2 joins two interior
    // segments at 45 degrees, and the angle rule says so.
    {
        const catmull_rom<2> c({P2{{-4, -1}}, P2{{0, 0}}, P2{{4, 4}}, P2{{4, 0}}, P2{{0, 4}}, P2{{-1, 8}}});
        const auto cert = certify_intersection_free(c);
        EXPECT_FALSE(cert.certified);
        EXPECT_EQ(cert.failed_rule, certify_rule::adjacent_angle);
        EXPECT_EQ(cert.vertex, std::optional<std::size_t>(2));
        EXPECT_NEAR(cert.angle, pi / 4, 1e-12);
        EXPECT_EQ(cert.detail, "polygon angle at vertex 2 is 45 degrees, not above 60");
        ASSERT_TRUE(cert.intersects.has_value());
        EXPECT_TRUE(*cert.intersects);
    }
    // A U with right angles whose end turns back towards the start: all
    // angles 90 degrees, boxes apart: certified, and the search is not run.
    {
        const catmull_rom<2> c({P2{{0, 0}}, P2{{10, 0}}, P2{{10, 2}}, P2{{0, 2}}, P2{{0, 1.05}}});
        const auto cert = certify_intersection_free(c);
        EXPECT_TRUE(cert.certified) << cert.detail;
        EXPECT_FALSE(find_intersections(c).any());
    }
    {
        const catmull_rom<2> c({P2{{0, 0}}, P2{{10, 0}}, P2{{14, 4}}, P2{{10, 8}}, P2{{0, 8}}, P2{{-3, 4.5}},
                                P2{{1, 1.2}}});
        const auto cert = certify_intersection_free(c);
        EXPECT_EQ(cert.failed_rule, certify_rule::overlapping_boxes) << cert.detail;
        ASSERT_TRUE(cert.segments.has_value());
        EXPECT_TRUE(cert.intersects.has_value());
    }
    // Not centripetal: chordal knots, or an explicit grid (even the
    // centripetal one: the curve says how it was built, nobody guesses).
    // Tension is not a failure by itself: its segments get Bézier boxes and
    // the exact adjacent-pair check.
    {
        const std::vector<P2> p{P2{{0, 0}}, P2{{4, 1}}, P2{{8, 0}}, P2{{12, 1}}};
        const auto chordal_cert = certify_intersection_free(catmull_rom<2>(p, {.alpha = 1.0}));
        EXPECT_EQ(chordal_cert.failed_rule, certify_rule::not_centripetal);
        EXPECT_EQ(chordal_cert.detail, "the knots are from alpha = 1, not 0.5 (centripetal)");
        const catmull_rom<2> centripetal_curve(p);
        const std::vector<double> g(centripetal_curve.grid().begin(), centripetal_curve.grid().end());
        const auto grid_cert = certify_intersection_free(catmull_rom<2>(p, {.grid = g}));
        EXPECT_EQ(grid_cert.failed_rule, certify_rule::not_centripetal);
        EXPECT_EQ(grid_cert.detail, "the knots were given as an explicit grid, not from alpha = 0.5");
        const auto tense = certify_intersection_free(catmull_rom<2>(p, {.tension = 0.5}));
        EXPECT_TRUE(tense.certified) << tense.detail;
        const auto ok = certify_intersection_free(catmull_rom<2>(p));
        EXPECT_TRUE(ok.certified) << ok.detail;
        EXPECT_FALSE(ok.intersects.has_value());
    }
    // Coincident points.
    EXPECT_EQ(certify_intersection_free(catmull_rom<2>({P2{{0, 0}}, P2{{1, 0}}, P2{{1, 0}}, P2{{2, 1}}})).failed_rule,
              certify_rule::coincident_points);
}

// The angle rule is needed: adjacent centripetal segments do cross at small
// polygon angles (SOURCES.md: crossings up to at least 28.9 degrees); search for one.
TEST(Certify, AdjacentSegmentsCrossAtSmallAngles) {
    CRSPLINE_SEEDED(seed, 4004);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    std::size_t crossings = 0, tries = 0;
    double largest = 0;
    for (; tries < 20000 && crossings < 50; ++tries) {
        const double ang = (5 + 55 * U(rng)) * pi / 180;
        const double a = std::pow(10.0, 2 * U(rng) - 1), b = std::pow(10.0, 2 * U(rng) - 1);
        const double e = std::pow(10.0, 2 * U(rng) - 1), f = 2 * pi * U(rng);
        const P2 p1{{0, 0}}, p0{{-e * std::cos(f), -e * std::sin(f)}};
        const P2 p2{{a, 0}}, p3{{a + b * std::cos(pi - ang), b * std::sin(pi - ang)}};
        const catmull_rom<2> c({p0, p1, p2, p3, P2{{p3[0] + e * std::cos(f), p3[1] + e * std::sin(f)}}});
        const auto r = find_intersections(c);
        for (const auto& x : r.intersections)
            if (x.segments[1] == x.segments[0] + 1) {
                ++crossings;
                const std::size_t k = x.segments[1];  // the shared vertex
                const auto q = c.points();
                largest = std::max(largest, detail::angle_between(q[k - 1] - q[k], q[k + 1] - q[k]));
                const auto cert = certify_intersection_free(c);
                EXPECT_FALSE(cert.certified);
                // Vertex 2 joins two interior segments (the angle rule); 1
                // and 3 an end segment (the exact adjacent-pair check). The
                // first vertex in order that fails is reported.
                EXPECT_TRUE(cert.failed_rule == certify_rule::adjacent_angle ||
                            cert.failed_rule == certify_rule::adjacent_pair)
                    << cert.detail;
                if (k == 2) {
                    EXPECT_EQ(cert.failed_rule, certify_rule::adjacent_angle) << cert.detail;
                }
                EXPECT_TRUE(cert.intersects.value_or(false));
                break;
            }
    }
    std::printf("adjacent crossings: %zu in %zu tries, largest polygon angle %.1f degrees\n", crossings, tries,
                largest * 180 / pi);
    EXPECT_GT(crossings, 0u);
    EXPECT_LT(largest, safe_adjacent_angle);
}

// Section 6.4: centripetal segments tend to peak in curvature at their
// control points; not always. Also: the maxima are exact (dense sampling).
TEST(Curvature, MaximaAtControlPointsMostlyForCentripetal) {
    CRSPLINE_SEEDED(seed, 4005);
    std::mt19937_64 rng(seed);
    std::array<std::size_t, 3> at_points{}, total{};
    std::size_t centripetal_counterexamples = 0;
    const std::size_t count = std::size_t(600 * property_scale());
    for (std::size_t rep = 0; rep < count; ++rep) {
        auto p = crspline::test::random_polygon<2>(rng, 6, 1.5);
        for (std::size_t k = 0; k < 3; ++k) {
            const double alpha = std::array{0.0, 0.5, 1.0}[k];
            const catmull_rom<2> c(p, {.alpha = alpha});
            for (std::size_t i = 1; i + 1 < c.segment_count(); ++i) {
                const auto& s = c.segment(i);
                const auto m = segment_curvature_maxima(s);
                if (!std::isfinite(m.max)) continue;  // a cusp
                double sampled = 0;
                for (int q = 0; q <= 1000; ++q) sampled = std::max(sampled, curvature(s, q / 1000.0).value_or(0.0));
                // No sample beats the reported maximum, which is the
                // curvature at max_u and a local maximum there.
                EXPECT_LE(sampled, m.max * (1 + 1e-9)) << "rep " << rep << " alpha " << alpha;
                EXPECT_NEAR(curvature(s, m.max_u).value_or(0.0), m.max, 1e-12 * m.max);
                for (double du : {-1e-6, 1e-6}) {
                    const double u = std::clamp(m.max_u + du, 0.0, 1.0);
                    EXPECT_LE(curvature(s, u).value_or(0.0), m.max * (1 + 1e-12));
                }
                ++total[k];
                if (m.max_at_control_point()) ++at_points[k];
                else if (alpha == 0.5) ++centripetal_counterexamples;
            }
        }
    }
    std::printf("curvature max at a control point: uniform %zu/%zu, centripetal %zu/%zu, chordal %zu/%zu\n",
                at_points[0], total[0], at_points[1], total[1], at_points[2], total[2]);
    EXPECT_GT(double(at_points[1]) / double(total[1]), double(at_points[0]) / double(total[0]));
    EXPECT_GT(double(at_points[1]) / double(total[1]), 0.5);
    EXPECT_GT(centripetal_counterexamples, 0u);  // "not guaranteed"
}

// Eq. 8 at alpha = 1/2 is r^2 - r^(4 alpha) = 0 for every r: no balls. As
// r * r - pow(r, 2) it was 1 ulp of r^2 for r = d3 / d2 = 0.3924856784...
// (glibc's pow at run time; a compiler folding a constant alpha hides it,
// hence the volatile), a ball of radius 2e-8 d2 at seed 11's rep 282 of
// the test above.
TEST(BoundingVolumes, CentripetalEq8IsExactlyZero) {
    volatile double half = 0.5;
    EXPECT_EQ(paper_eq8(11.876330952848111, 4.6612898111044041 / 11.876330952848111, double(half)), 0.0);
    std::mt19937_64 rng(4007);
    std::uniform_real_distribution<double> e(-6, 6);
    std::size_t nonzero = 0;
    for (int k = 0; k < 100000; ++k)
        if (paper_eq8(1.0, std::pow(10.0, e(rng)), double(half)) != 0.0) ++nonzero;
    EXPECT_EQ(nonzero, 0u);
}

// A near-cusp: the least speed is 1.3e-5 of the coefficients' scale, the
// curvature peaks at 9e10 over a parameter width of about 1e-6, and the
// root of the degree-7 critical-point polynomial (a difference of terms
// 1e16 times larger than itself there) lands 5e-6 from the peak, on its
// flank. segment_curvature_maxima once judged that root no maximum (a
// neighbour 1e-6 away was higher) and reported 1.53 at u = 0: the chordal
// segment of seed 33's rep 537 in the test above.
TEST(Curvature, MaximumOfANearCusp) {
    cubic_segment<2> s;
    s.c1 = P2{{-0.053987305576369202, 2.4460193873924179}};
    s.c2 = P2{{4.5112473509100566, 3.3321881079153002}};
    s.c3 = P2{{-3.3491867699643514, -3.5153753357232311}};
    s.h = s.inv_h = 1;
    const auto m = segment_curvature_maxima(s);
    // The peak by brute force: the densest grid around it, 1e-9 apart.
    double peak = 0, peak_u = 0;
    for (int k = -20000; k <= 20000; ++k) {
        const double u = 0.89195577 + k * 1e-9;
        const double kappa = curvature(s, u).value_or(0.0);
        if (kappa > peak) { peak = kappa; peak_u = u; }
    }
    ASSERT_GT(peak, 1e10);
    // The reported maximum is at least the grid's best, and near it (the
    // peak is 1e-6 wide; the grid is 1e-9 apart).
    EXPECT_GE(m.max, peak);
    EXPECT_NEAR(m.max_u, peak_u, 1e-8);
    EXPECT_EQ(curvature(s, m.max_u).value_or(0.0), m.max);
    for (double du : {-1e-9, 1e-9}) EXPECT_LE(curvature(s, m.max_u + du).value_or(0.0), m.max);
}

}  // namespace
