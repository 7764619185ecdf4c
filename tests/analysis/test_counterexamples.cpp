// Cusps, loops and folds for every alpha but 1/2: the counterexamples of
// tests/reference/SOURCES.md, and our own for alpha = 0, 0.25, 0.75 and 1
// (the paper's Theorem 1: centripetal is the only parameterization with the
// guarantee). Each loop is checked independently: C(u) = C(v) to rounding,
// and a dense polyline of the segment crosses itself.
#include <crspline/analysis.hpp>

#include "test_support.hpp"

namespace {
using namespace crspline;
using P2 = vec<2>;
using crspline::test::eps;

std::array<P2, 4> pts(P2 a, P2 b, P2 c, P2 d) { return {a, b, c, d}; }

double coefficient_scale(const segment_analysis<2>& a) {
    return norm(a.segment.c1) + norm(a.segment.c2) + norm(a.segment.c3);
}

// The loop [u, v] closes (to rounding) and a 2000-point polyline crosses
// itself between the two parameters.
void expect_real_loop(const segment_analysis<2>& a) {
    ASSERT_EQ(a.self_intersection.size(), 1u);
    const auto [u, v] = a.self_intersection[0];
    EXPECT_LT(u, v);
    EXPECT_LE(norm(a.segment.at(u) - a.segment.at(v)), 64 * eps * coefficient_scale(a));
    const int m = 2000;
    auto orient = [](const P2& p, const P2& q, const P2& r) {
        return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
    };
    bool crossed = false;
    for (int k = 0; k < m && !crossed; ++k)
        for (int j = k + 2; j < m && !crossed; ++j) {
            const P2 a0 = a.segment.at(double(k) / m), a1 = a.segment.at(double(k + 1) / m);
            const P2 b0 = a.segment.at(double(j) / m), b1 = a.segment.at(double(j + 1) / m);
            const double o1 = orient(a0, a1, b0), o2 = orient(a0, a1, b1), o3 = orient(b0, b1, a0), o4 = orient(b0, b1, a1);
            crossed = (o1 > 0) != (o2 > 0) && (o3 > 0) != (o4 > 0) && o1 != 0 && o2 != 0 && o3 != 0 && o4 != 0;
        }
    EXPECT_TRUE(crossed);
    EXPECT_FALSE(a.has_cusp());
}

TEST(Counterexamples, ReadmeUniformExactCusp) {
    // SOURCES.md: uniform (-5,1),(0,0),(1,0),(6,1) has an exact cusp at u = 1/2.
    const auto p = pts(P2{{-5, 1}}, P2{{0, 0}}, P2{{1, 0}}, P2{{6, 1}});
    const auto a = analyze_segment(p, uniform);
    ASSERT_EQ(a.cusp_u.size(), 1u);
    EXPECT_NEAR(a.cusp_u[0], 0.5, 1e-15);
    EXPECT_FALSE(a.has_self_intersection());
    // Theorem 2's premise fails exactly: B1 projects to 1, B2 to 0.
    EXPECT_EQ(a.projection->bezier[0], 1.0);
    EXPECT_EQ(a.projection->bezier[1], 0.0);
    // The same points, centripetal: nothing.
    const auto c = analyze_segment(p, centripetal);
    EXPECT_FALSE(c.has_cusp() || c.has_self_intersection());
}

TEST(Counterexamples, UniformLoopInClosedForm) {
    // Symmetric uniform segment: C(s) = C(t) at s, t = (5 -+ sqrt 5) / 10.
    const auto p = pts(P2{{-12, -6}}, P2{{0, 0}}, P2{{1, 0}}, P2{{1, -6}});
    const auto a = analyze_segment(p, uniform);
    expect_real_loop(a);
    EXPECT_NEAR(a.self_intersection[0][0], (5 - std::sqrt(5.0)) / 10, 1e-14);
    EXPECT_NEAR(a.self_intersection[0][1], (5 + std::sqrt(5.0)) / 10, 1e-14);
}

TEST(Counterexamples, LoopsForEveryAlphaButCentripetal) {
    struct example {
        double alpha;
        std::array<P2, 4> p;
    };
    const example examples[] = {
        {0.0, pts(P2{{-12, -12}}, P2{{5, -3}}, P2{{7, -2}}, P2{{-6, -7}})},  // the oracle's hairpin
        {0.0, pts(P2{{-9, 1}}, P2{{0, 0}}, P2{{1, 0}}, P2{{10, 1}})},        // the oracle's symmetric loop
        {0.25, pts(P2{{-12, -6}}, P2{{0, 0}}, P2{{1, 0}}, P2{{-9, 6}})},
        {0.75, pts(P2{{0.10115089411576582, 0.00071254923638944712}}, P2{{0, 0}}, P2{{1, 0}},
                  P2{{393.75844692613788, -207.01035465505137}})},
        {1.0, pts(P2{{-3, -3}}, P2{{0, 0}}, P2{{20, 0}}, P2{{14, 1}})},
        {1.0, pts(P2{{5, -1}}, P2{{0, 0}}, P2{{1000, 0}}, P2{{996, 5}})},  // the oracle's "chordal small loop"
    };
    std::size_t checked = 0;
    for (const auto& e : examples) {
        SCOPED_TRACE("alpha " + std::to_string(e.alpha) + ", example " + std::to_string(checked));
        const auto a = analyze_segment(e.p, e.alpha);
        expect_real_loop(a);
        // Theorem 1: the projected derivative goes negative somewhere.
        EXPECT_LT(a.projection->derivative_min, 0);
        const auto c = analyze_segment(e.p, centripetal);
        EXPECT_FALSE(c.has_cusp() || c.has_self_intersection());
        EXPECT_GE(c.projection->derivative_min, 0);
        ++checked;
    }
}

// Symmetric segments P0 = (a, b), P3 = (1 - a, b): C'(1/2) is horizontal and
// vanishes where B1 projects to exactly 1. Bisect on a for alpha < 1/2
// (Theorem 3: for alpha >= 1/2 B1 never projects beyond B3).
TEST(Counterexamples, SymmetricCuspsByBisection) {
    std::size_t found = 0;
    for (double alpha : {0.0, 0.25})
        for (double b : {0.01, 0.5, 2.0}) {
            auto family = [&](double a) { return pts(P2{{a, b}}, P2{{0, 0}}, P2{{1, 0}}, P2{{1 - a, b}}); };
            auto f = [&](double a) { return analyze_segment(family(a), alpha).segment.du(0.5, 1)[0]; };
            double lo = -30, hi = -1.5;  // f changes sign in between for both alphas
            ASSERT_LT(f(lo) * f(hi), 0) << "alpha " << alpha << " b " << b;
            while (true) {
                const double mid = lo + (hi - lo) / 2;
                if (!(mid > lo && mid < hi)) break;
                ((f(mid) < 0) == (f(lo) < 0) ? lo : hi) = mid;
            }
            const auto a = analyze_segment(family(lo), alpha);
            ASSERT_EQ(a.cusp_u.size(), 1u) << "alpha " << alpha << " b " << b;
            EXPECT_NEAR(a.cusp_u[0], 0.5, 1e-12);
            EXPECT_FALSE(a.has_self_intersection());
            ++found;
        }
    EXPECT_EQ(found, 6u);
}

// A loop shrinks to a cusp and disappears: move P0 from a loop configuration
// towards one without, bisect on "loop or cusp", and at the boundary the
// detector reports a cusp (zero speed inside the segment) for alpha 0.25,
// 0.75 and 1 (asymmetric cusps, found by their speed).
TEST(Counterexamples, LoopShrinksToACusp) {
    struct example {
        double alpha;
        std::array<P2, 4> p;
        P2 move;   // P0 + move, P3 + move3 has no loop
        P2 move3;
    };
    const example examples[] = {
        // Symmetric: the loop closes at u = 1/2 (a loop can also vanish by
        // sliding out through an end; these paths close it in the middle).
        {0.0, pts(P2{{-9, 1}}, P2{{0, 0}}, P2{{1, 0}}, P2{{10, 1}}), P2{{6, 0}}, P2{{-6, 0}}},
        {0.25, pts(P2{{-12, -6}}, P2{{0, 0}}, P2{{1, 0}}, P2{{-9, 6}}), P2{{0, 12}}, P2{}},
        {0.75, pts(P2{{0.10115089411576582, 0.00071254923638944712}}, P2{{0, 0}}, P2{{1, 0}},
                   P2{{393.75844692613788, -207.01035465505137}}), P2{{0, 0.05}}, P2{}},
        {1.0, pts(P2{{-3, -3}}, P2{{0, 0}}, P2{{20, 0}}, P2{{14, 1}}), P2{{0, 6}}, P2{}},
    };
    std::size_t cusps = 0;
    for (const auto& e : examples) {
        SCOPED_TRACE("alpha " + std::to_string(e.alpha));
        auto at = [&](double lam) {
            auto p = e.p;
            p[0] += lam * e.move;
            p[3] += lam * e.move3;
            return analyze_segment(p, e.alpha);
        };
        auto defect = [&](double lam) {
            const auto a = at(lam);
            return a.has_cusp() || a.has_self_intersection();
        };
        ASSERT_TRUE(defect(0.0));
        ASSERT_FALSE(defect(1.0));
        double lo = 0, hi = 1;
        bool saw_cusp = false;
        while (true) {
            const double mid = lo + (hi - lo) / 2;
            if (!(mid > lo && mid < hi)) break;
            const auto a = at(mid);
            saw_cusp |= a.has_cusp();
            (a.has_cusp() || a.has_self_intersection() ? lo : hi) = mid;
        }
        // At the boundary the loop has closed up: a cusp, reported with its u.
        const auto a = at(lo);
        EXPECT_TRUE(saw_cusp);
        EXPECT_TRUE(a.has_cusp() || (!a.self_intersection.empty() &&
                                     a.self_intersection[0][1] - a.self_intersection[0][0] < 1e-5));
        if (a.has_cusp()) {
            EXPECT_LE(norm(a.segment.du(a.cusp_u[0], 1)), zero_speed_tolerance * eps * coefficient_scale(a));
            ++cusps;
        }
    }
    EXPECT_GE(cusps, 3u);
}

TEST(Counterexamples, CollinearFoldsAreSelfIntersections) {
    // 1-D and collinear 2-D: alpha != 1/2 folds; alpha = 1/2 never does.
    const std::array<vec<1>, 4> q{vec<1>{{-9}}, vec<1>{{0}}, vec<1>{{1}}, vec<1>{{10}}};
    const auto u1 = analyze_segment(q, uniform);
    EXPECT_TRUE(u1.fold);
    EXPECT_TRUE(u1.has_self_intersection());
    EXPECT_EQ(u1.cusp_u.size(), 2u);
    EXPECT_FALSE(analyze_segment(q, centripetal).fold);
    // Chordal folds when the middle chord is long and the neighbours turn back.
    const std::array<vec<1>, 4> r{vec<1>{{0.5}}, vec<1>{{0}}, vec<1>{{10}}, vec<1>{{9.5}}};
    const auto c1 = analyze_segment(r, chordal);
    EXPECT_TRUE(c1.fold);
    EXPECT_EQ(c1.rank, 1u);
    const auto cc = analyze_segment(r, centripetal);
    EXPECT_FALSE(cc.fold || cc.has_cusp());
}

}  // namespace
