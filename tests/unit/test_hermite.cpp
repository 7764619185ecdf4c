// Cubic Hermite curves from given tangents (catmull_rom::hermite), and closed
// curves through two points. Expected values come from closed forms.
#include "test_support.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace {
using namespace crspline;
using P2 = vec<2>;
using P3 = vec<3>;
using crspline::test::eps;

template <class E, class F>
std::string error_of(F&& f) {
    try {
        f();
    } catch (const E& e) {
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "wrong exception type: " << e.what();
        return {};
    }
    ADD_FAILURE() << "no exception";
    return {};
}

// x(t) = a + b t + c t^2 + d t^3 per coordinate, and its derivatives.
struct cubic3 {
    P3 a, b, c, d;
    P3 at(double t) const { return a + t * b + (t * t) * c + (t * t * t) * d; }
    P3 dt(double t) const { return b + (2 * t) * c + (3 * t * t) * d; }
    P3 dt2(double t) const { return 2.0 * c + (6 * t) * d; }
};

TEST(Hermite, ReproducesACubicFromItsExactTangents) {
    // A Hermite curve whose points and tangents are those of one cubic
    // polynomial is that polynomial, on any grid: positions and the first
    // two derivatives match the closed form everywhere.
    CRSPLINE_SEEDED(s, 31);
    std::mt19937_64 rng(s);
    std::normal_distribution<double> g(0, 1);
    std::uniform_real_distribution<double> step(0.1, 3.0);
    int checked = 0;
    for (int rep = 0; rep < 20; ++rep) {
        cubic3 f;
        for (std::size_t k = 0; k < 3; ++k) f.a[k] = g(rng), f.b[k] = g(rng), f.c[k] = g(rng), f.d[k] = g(rng);
        const std::size_t n = 2 + std::size_t(rep % 6);
        std::vector<double> grid{g(rng)};
        for (std::size_t i = 1; i < n; ++i) grid.push_back(grid.back() + step(rng));
        std::vector<P3> p, v;
        for (double t : grid) p.push_back(f.at(t)), v.push_back(f.dt(t));
        const auto c = catmull_rom<3>::hermite(p, v, grid);
        ASSERT_EQ(c.segment_count(), n - 1);
        double scale = 0;
        for (double t : grid) scale = std::max({scale, max_abs(f.at(t)), max_abs(f.dt(t)), max_abs(f.dt2(t))});
        // The polynomial's own values are computed with a few roundings of
        // terms of size `scale` (times |t|^3 <= ~30^3 for t): 1e-12 relative.
        const double tol = 1e-12 * std::max(scale, 1.0) * std::pow(1 + std::abs(grid.back()), 3);
        for (int k = 0; k <= 40; ++k) {
            // (k = 40 is the end itself: front + (back - front) can round past it.)
            const double t = k == 40 ? grid.back() : grid.front() + (grid.back() - grid.front()) * k / 40;
            EXPECT_LE(max_abs(c.evaluate(t) - f.at(t)), tol) << "t = " << t;
            EXPECT_LE(max_abs(c.evaluate(t, 1) - f.dt(t)), tol) << "t = " << t;
            EXPECT_LE(max_abs(c.evaluate(t, 2) - f.dt2(t)), tol) << "t = " << t;
            ++checked;
        }
    }
    EXPECT_EQ(checked, 20 * 41);
}

TEST(Hermite, IncomingAndOutgoingTangentsMayDiffer) {
    // Vertex 1 of [(0,0), (1,0), (2,0)] on grid 0, 1, 2 gets incoming (1, 1)
    // and outgoing (1, -1): the segments' end derivatives are those vectors.
    const std::vector<P2> p{P2{{0, 0}}, P2{{1, 0}}, P2{{2, 0}}};
    const std::vector<P2> out{P2{{1, 0}}, P2{{1, -1}}, P2{{9, 9}}};  // the last one is not used (open)
    const std::vector<P2> in{P2{{7, 7}}, P2{{1, 1}}, P2{{1, 0}}};    // the first one is not used (open)
    const std::vector<double> grid{0, 1, 2};
    const auto c = catmull_rom<2>::hermite(p, out, in, grid);
    const auto t0 = c.tangents(0), t1 = c.tangents(1);
    EXPECT_EQ(t0[0], (P2{{1, 0}}));
    EXPECT_EQ(t0[1], (P2{{1, 1}}));
    EXPECT_EQ(t1[0], (P2{{1, -1}}));
    EXPECT_EQ(t1[1], (P2{{1, 0}}));
    // The knot belongs to the segment on its right: dx/dt there is the outgoing one.
    EXPECT_LE(max_abs(c.evaluate(1.0, 1) - P2{{1, -1}}), 4 * eps);
    // Segment 0 is the Hermite cubic with m0 = (1, 0), m1 = (1, 1) on [0, 1]:
    // y(u) = (u^3 - u^2) * 1, so y(1/2) = -1/8; x(u) = u.
    EXPECT_LE(max_abs(c.evaluate(0.5) - P2{{0.5, -0.125}}), 4 * eps);
    // The unused entries must not matter, not even when not finite.
    std::vector<P2> out2 = out, in2 = in;
    out2[2] = P2{{NAN, 0}}, in2[0] = P2{{INFINITY, 0}};
    const auto c2 = catmull_rom<2>::hermite(p, out2, in2, grid);
    for (double t : {0.0, 0.3, 1.0, 1.7, 2.0}) EXPECT_EQ(c2.evaluate(t), c.evaluate(t));
}

TEST(Hermite, CatmullRomTangentsGiveTheCatmullRomCurve) {
    // Feeding a curve's own knots and tangents back gives the same curve,
    // bit for bit (open and closed, Kochanek-Bartels with split tangents).
    CRSPLINE_SEEDED(s, 32);
    std::mt19937_64 rng(s);
    int checked = 0;
    for (bool closed : {false, true}) {
        for (int rep = 0; rep < 10; ++rep) {
            const auto p = crspline::test::random_polygon<3>(rng, 3 + rep);
            options<3> opt{.alpha = 0.5, .closed = closed};
            if (rep % 2) {
                opt.kb.tension.assign(p.size(), 0.2);
                opt.kb.continuity.assign(p.size(), -0.4);
                opt.kb.bias.assign(p.size(), 0.3);
            }
            const catmull_rom<3> c(p, opt);
            const std::size_t n = p.size();
            std::vector<P3> out(n), in(n);
            for (std::size_t i = 0; i < c.segment_count(); ++i) {
                const auto tv = c.tangents(i);
                out[i] = tv[0];
                in[(i + 1) % n] = tv[1];
            }
            const auto h = catmull_rom<3>::hermite(p, out, in, c.grid(), closed);
            for (std::size_t i = 0; i < c.segment_count(); ++i) {
                // Bit for bit where the stored knots' difference is the
                // interval; where the running sum rounded it, tangents() are
                // the vertex tangents times h / d, and the Hermite segment's
                // d (h/d m) is h m within a few roundings of its coefficients.
                const double d = c.grid()[i + 1] - c.grid()[i];
                for (int k = 0; k <= 8; ++k) {
                    const double t = c.grid()[i] + d * k / 8;
                    const std::size_t j = c.locate(t);  // i, or the next segment for k = 8
                    const bool exact = c.grid()[j + 1] - c.grid()[j] == c.intervals()[j];
                    const auto& sg = c.segment(j);
                    const double size = max_abs(sg.origin) + max_abs(sg.c1) + max_abs(sg.c2) + max_abs(sg.c3);
                    if (exact) {
                        ASSERT_EQ(h.evaluate(t), c.evaluate(t)) << "closed " << closed << ", rep " << rep << ", t " << t;
                        ASSERT_EQ(h.evaluate(t, 1), c.evaluate(t, 1));
                    } else {
                        ASSERT_LE(norm(h.evaluate(t) - c.evaluate(t)), 16 * eps * size) << "t " << t;
                        ASSERT_LE(norm(h.evaluate(t, 1) - c.evaluate(t, 1)), 16 * eps * size * sg.inv_h) << "t " << t;
                    }
                    ++checked;
                }
            }
        }
    }
    EXPECT_GT(checked, 0);
}

TEST(Hermite, Errors) {
    const std::vector<P2> p{P2{{0, 0}}, P2{{1, 0}}, P2{{2, 1}}};
    const std::vector<P2> v{P2{{1, 0}}, P2{{1, 0}}, P2{{1, 0}}};
    const std::vector<double> grid{0, 1, 2};
    EXPECT_EQ(error_of<invalid_input>([&] { catmull_rom<2>::hermite(std::span(p).first(1), std::span(v).first(1), std::span(grid).first(1)); }),
              "a curve needs at least 2 points, got 1");
    EXPECT_EQ(error_of<invalid_input>([&] { catmull_rom<2>::hermite(p, std::span(v).first(2), grid); }),
              "outgoing tangents: got 2, expected one per point (3)");
    std::vector<P2> bad = v;
    bad[1][1] = NAN;
    EXPECT_EQ(error_of<invalid_input>([&] { catmull_rom<2>::hermite(p, v, bad, grid); }),
              "incoming tangent 1, coordinate 1 is not finite (nan)");
    EXPECT_EQ(error_of<invalid_input>([&] { catmull_rom<2>::hermite(p, bad, v, grid); }),
              "outgoing tangent 1, coordinate 1 is not finite (nan)");
    const std::vector<double> flat{0, 1, 1};
    EXPECT_EQ(error_of<invalid_input>([&] { catmull_rom<2>::hermite(p, v, flat); }),
              "grid must be strictly increasing: grid[2] = 1 is not greater than grid[1] = 1");
    EXPECT_EQ(error_of<invalid_input>([&] { catmull_rom<2>::hermite(p, v, grid, true); }),
              "grid has 3 values, expected 4 (one per point plus one: a closed curve repeats the first knot)");
    std::vector<P2> q = p;
    q[2][0] = INFINITY;
    EXPECT_EQ(error_of<invalid_input>([&] { catmull_rom<2>::hermite(q, v, grid); }),
              "point 2, coordinate 0 is not finite (inf)");
}

TEST(ClosedTwoPoints, UniformIsSymmetricWithZeroTangents) {
    // Closed through (0,0), (1,1), uniform: each vertex's neighbours are both
    // the other vertex, so its tangent is 0 and each segment is the Hermite
    // cubic with zero tangents, P0 + (3u^2 - 2u^3)(P1 - P0). The splines
    // package gives evaluate(1.5) = (0.5, 0.5) (tests/reference probes).
    const std::vector<P2> p{P2{{0, 0}}, P2{{1, 1}}};
    const catmull_rom<2> c(p, {.alpha = uniform, .closed = true});
    ASSERT_EQ(c.segment_count(), 2u);
    EXPECT_EQ(std::vector<double>(c.grid().begin(), c.grid().end()), (std::vector<double>{0, 1, 2}));
    EXPECT_LE(max_abs(c.evaluate(1.5) - P2{{0.5, 0.5}}), 4 * eps);
    EXPECT_LE(max_abs(c.evaluate(0.5) - P2{{0.5, 0.5}}), 4 * eps);
    const double u = 0.25, w = 3 * u * u - 2 * u * u * u;
    EXPECT_LE(max_abs(c.evaluate(0.25) - P2{{w, w}}), 4 * eps);
    EXPECT_LE(max_abs(c.evaluate(1.25) - P2{{1 - w, 1 - w}}), 4 * eps);
    EXPECT_EQ(c.evaluate(2.0), (P2{{0, 0}}));
    for (double t : {0.0, 1.0}) EXPECT_LE(max_abs(c.evaluate(t, 1)), 4 * eps);
    // Centripetal: both chords have the same length, so the same curve.
    const catmull_rom<2> cc(p, {.alpha = centripetal, .closed = true});
    for (double t : {0.3, 0.9})
        EXPECT_LE(max_abs(cc.evaluate(t * cc.t_max()) - c.evaluate(t * c.t_max())), 8 * eps);
}

TEST(ClosedTwoPoints, UnevenGridTangentsFollowTheFormula) {
    // Grid 0, 1, 3: at vertex 0 the interval before is h0 = 2 (the closing
    // segment), after h1 = 1; at vertex 1, h0 = 1, h1 = 2. The tangent
    // [h1^2 (P_i - P_prev) + h0^2 (P_next - P_i)] / [h0 h1 (h0 + h1)] with
    // P_prev = P_next = the other point gives (P1 - P0) / 2 at both vertices.
    const std::vector<P2> p{P2{{0, 0}}, P2{{2, 4}}};
    const catmull_rom<2> c(p, {.grid = std::vector<double>{0, 1, 3}, .closed = true});
    EXPECT_LE(max_abs(c.evaluate(0.0, 1) - P2{{1, 2}}), 8 * eps);
    EXPECT_LE(max_abs(c.evaluate(1.0, 1) - P2{{1, 2}}), 8 * eps);
    EXPECT_LE(max_abs(c.evaluate(3.0, 1) - P2{{1, 2}}), 8 * eps);  // back at vertex 0: C1 across the seam
    EXPECT_EQ(c.evaluate(3.0), (P2{{0, 0}}));
}

TEST(ClosedTwoPoints, OnePointIsStillAnError) {
    const std::vector<P2> one{P2{{0, 0}}};
    EXPECT_EQ(error_of<invalid_input>([&] { catmull_rom<2> c(one, {.closed = true}); }),
              "a closed curve needs at least 2 points, got 1");
}

}  // namespace

TEST(Hermite, GivenTangentsAreNeverTakenForCatmullRom) {
    // The Catmull-Rom tangents of this centripetal polygon, given back
    // through hermite(), draw the same curve; but the analysis must not read
    // the curve as Catmull-Rom (it cannot know where given tangents came
    // from): rule 1 fails naming the given tangents, and no segment gets the
    // paper's bounds, which hold only for tangents computed by Eq. 2.
    const std::vector<P2> pts{{0, 0}, {1, 0}, {2, 1}, {3, 3}, {5, 3}};
    const catmull_rom<2> cr(pts);
    std::vector<P2> tan(pts.size());
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) tan[i] = cr.tangents(i)[0];
    tan.back() = cr.tangents(pts.size() - 2)[1];
    const auto h = catmull_rom<2>::hermite(pts, tan, cr.grid());
    EXPECT_TRUE(h.given_tangents());
    EXPECT_FALSE(cr.given_tangents());
    const auto cert = certify_intersection_free(h);
    EXPECT_FALSE(cert.certified);
    EXPECT_EQ(cert.failed_rule, certify_rule::not_centripetal);
    EXPECT_NE(cert.detail.find("tangents were given"), std::string::npos) << cert.detail;
    EXPECT_TRUE(certify_intersection_free(cr).certified);
    for (const auto& a : analyze(h)) EXPECT_FALSE(a.bounds.has_value());
}
