// Bounding boxes: they contain dense samples of the curve, and every face is
// touched (the refined maximum of dense samples meets it, and it is attained
// exactly at an evaluated parameter). Seeded; counts asserted.
#include "test_support.hpp"

#include <crspline/bounds.hpp>

#include <cstdio>

namespace {
using namespace crspline;
using crspline::test::random_polygon;
using crspline::test::alphas;

// How far a sample may stray from a face by rounding alone: evaluations at
// different u round differently, by a few eps of the coordinates' size.
// 1e-12 is ~4500 eps for double; float gets ~80 eps.
template <class T>
T face_slack(T magnitude) {
    return T(std::is_same_v<T, double> ? 1e-12 : 1e-5) * magnitude;
}

// Maximum of sign * s.at(u)[k] on [a, b] by golden-section search (the
// coordinate is a cubic: unimodal on the small brackets used here).
template <std::size_t D, class T>
T refine_max(const cubic_segment<D, T>& s, std::size_t k, T sign, T a, T b) {
    auto f = [&](T u) { return sign * s.at(u)[k]; };
    const T g = T(0.6180339887498949);
    T x1 = b - g * (b - a), x2 = a + g * (b - a);
    T f1 = f(x1), f2 = f(x2);
    for (int it = 0; it < 200 && b - a > 0; ++it) {
        if (f1 < f2) { a = x1; x1 = x2; f1 = f2; x2 = a + g * (b - a); f2 = f(x2); }
        else { b = x2; x2 = x1; f2 = f1; x1 = b - g * (b - a); f1 = f(x1); }
    }
    return std::max({f1, f2, f(a), f(b)});
}

struct face_counts {
    std::size_t curves = 0, faces = 0, samples = 0, interior_faces = 0;
};

// Check bounding_box(c) against 1000 samples per segment; returns what it checked.
template <std::size_t D, class T>
void check_curve(const catmull_rom<D, T>& c, face_counts& n) {
    const box<D, T> b = bounding_box(c);
    const std::size_t nseg = c.segment_count(), per = 1000;
    T magnitude = b.diagonal();
    for (std::size_t k = 0; k < D; ++k) magnitude = std::max({magnitude, std::abs(b.lo[k]), std::abs(b.hi[k])});
    const T slack = face_slack(magnitude);
    // 1. Contains every sample.
    std::vector<std::vector<vec<D, T>>> samples(nseg, std::vector<vec<D, T>>(per));
    for (std::size_t i = 0; i < nseg; ++i)
        for (std::size_t j = 0; j < per; ++j) {
            const T u = T(j) / T(per - 1);
            const vec<D, T> p = samples[i][j] = c.segment(i).at(u);
            for (std::size_t k = 0; k < D; ++k) {
                EXPECT_GE(p[k], b.lo[k] - slack) << "segment " << i << " u " << u << " coordinate " << k;
                EXPECT_LE(p[k], b.hi[k] + slack) << "segment " << i << " u " << u << " coordinate " << k;
            }
            ++n.samples;
        }
    for (const auto& p : c.points()) EXPECT_TRUE(b.contains(p));
    for (std::size_t k = 0; k < D; ++k)
        for (int side = 0; side < 2; ++side) {
            const T sign = side ? T(1) : T(-1);
            const T face = sign * (side ? b.hi[k] : b.lo[k]);
            // 2. Tight: the samples' local maxima, refined between their
            //    neighbours by golden section, reach the face.
            T refined = -std::numeric_limits<T>::infinity();
            for (std::size_t i = 0; i < nseg; ++i)
                for (std::size_t j = 0; j < per; ++j) {
                    const T v = sign * samples[i][j][k];
                    if ((j > 0 && sign * samples[i][j - 1][k] > v) || (j + 1 < per && sign * samples[i][j + 1][k] > v))
                        continue;
                    const T a = j > 0 ? T(j - 1) / T(per - 1) : T(0);
                    const T e = j + 1 < per ? T(j + 1) / T(per - 1) : T(1);
                    refined = std::max({refined, v, refine_max(c.segment(i), k, sign, a, e)});
                }
            EXPECT_NEAR(refined, face, slack) << "coordinate " << k << " side " << side;
            // 3. Attained exactly: at a control point, or at an interior
            //    extremum u of some segment, evaluated with at(u).
            bool attained = false, interior = false;
            for (const auto& p : c.points()) attained |= sign * p[k] == face;
            for (std::size_t i = 0; i < nseg; ++i)
                for (T u : extrema(c.segment(i)))
                    if (sign * c.segment(i).at(u)[k] == face) attained = interior = true;
            EXPECT_TRUE(attained) << "coordinate " << k << " side " << side;
            n.interior_faces += interior && !std::any_of(c.points().begin(), c.points().end(),
                                                        [&](const auto& p) { return sign * p[k] == face; });
            ++n.faces;
        }
    // 4. Each reported extremum is a critical point of some coordinate,
    //    to rounding of the derivative's terms.
    for (std::size_t i = 0; i < nseg; ++i) {
        const auto& s = c.segment(i);
        for (T u : extrema(s)) {
            EXPECT_TRUE(u > 0 && u < 1);
            bool critical = false;
            for (std::size_t k = 0; k < D; ++k) {
                const T size = std::abs(s.c1[k]) + 2 * std::abs(s.c2[k]) + 3 * std::abs(s.c3[k]);
                critical |= std::abs(s.du(u, 1)[k]) <= 16 * std::numeric_limits<T>::epsilon() * size;
            }
            EXPECT_TRUE(critical) << "segment " << i << " u " << u;
        }
    }
    ++n.curves;
}

template <std::size_t D, class T>
face_counts random_curves(std::mt19937_64& rng, int reps) {
    face_counts n;
    for (double alpha : alphas)
        for (bool closed : {false, true})
            for (int rep = 0; rep < reps; ++rep) {
                const auto p = random_polygon<D, T>(rng, 3 + std::size_t(rep) % 6, 2.0, rep % 4 == 3 ? 100.0 : 0.0);
                check_curve(catmull_rom<D, T>(p, {.alpha = alpha, .closed = closed}), n);
            }
    return n;
}

TEST(Bounds, RandomCurvesAreContainedAndTouchEveryFace) {
    CRSPLINE_SEEDED(s, 301);
    std::mt19937_64 rng(s);
    const int reps = 12;
    const std::size_t curves = std::size(alphas) * 2 * reps;
    const face_counts n1 = random_curves<1, double>(rng, reps), n2 = random_curves<2, double>(rng, reps),
                      n3 = random_curves<3, double>(rng, reps), n4 = random_curves<4, double>(rng, reps);
    EXPECT_EQ(n1.curves + n2.curves + n3.curves + n4.curves, 4 * curves);
    EXPECT_EQ(n1.faces + n2.faces + n3.faces + n4.faces, (2 + 4 + 6 + 8) * curves);
    EXPECT_GE(n1.samples + n2.samples + n3.samples + n4.samples, 4 * curves * 3 * 1000);
    // Most random curves bulge past their control points somewhere: the
    // interior extrema are really exercised.
    const std::size_t interior = n1.interior_faces + n2.interior_faces + n3.interior_faces + n4.interior_faces;
    std::printf("[ bounds ] faces attained only at interior extrema: %zu of %zu\n", interior,
                n1.faces + n2.faces + n3.faces + n4.faces);
    EXPECT_GE(interior, curves);
}

TEST(Bounds, FloatCurves) {
    CRSPLINE_SEEDED(s, 302);
    std::mt19937_64 rng(s);
    const face_counts n2 = random_curves<2, float>(rng, 6), n3 = random_curves<3, float>(rng, 6);
    EXPECT_EQ(n2.curves + n3.curves, 2 * std::size(alphas) * 2 * 6);
    EXPECT_EQ(n2.faces + n3.faces, (4 + 6) * std::size(alphas) * 2 * 6);
}

TEST(Bounds, ControlBoxContainsTightBox) {
    CRSPLINE_SEEDED(s, 303);
    std::mt19937_64 rng(s);
    std::size_t checked = 0;
    for (double alpha : alphas)
        for (int rep = 0; rep < 40; ++rep) {
            const auto p = random_polygon<3>(rng, 4 + std::size_t(rep) % 5, 3.0);
            const catmull_rom<3> c(p, {.alpha = alpha, .closed = rep % 2 == 1});
            const box<3> tight = bounding_box(c), loose = control_box(c);
            // The control box holds exact control points; the tight box holds
            // evaluated cubics, within a few eps of the coordinates.
            const double slack = 1e-13 * (loose.diagonal() + max_abs(loose.lo) + max_abs(loose.hi));
            for (std::size_t k = 0; k < 3; ++k) {
                EXPECT_GE(tight.lo[k], loose.lo[k] - slack);
                EXPECT_LE(tight.hi[k], loose.hi[k] + slack);
            }
            for (std::size_t i = 0; i < c.segment_count(); ++i) {
                const box<3> st = bounding_box(c.segment(i)), sl = control_box(c.segment(i));
                for (std::size_t k = 0; k < 3; ++k) {
                    EXPECT_GE(st.lo[k], sl.lo[k] - slack);
                    EXPECT_LE(st.hi[k], sl.hi[k] + slack);
                }
                ++checked;
            }
        }
    EXPECT_GE(checked, 5u * 40 * 4);
}

TEST(Bounds, StraightLineIsTheBoxOfItsEnds) {
    // Collinear, evenly spaced, exactly representable: every segment is the
    // linear interpolant (all tangents equal the chord), so no interior
    // extremum and the box is the box of the two end points exactly.
    std::size_t checked = 0;
    for (double alpha : alphas) {
        std::vector<vec<3>> p;
        for (int i = 0; i < 6; ++i) p.push_back({{1.0 + 0.5 * i, -2.0 - 0.25 * i, 3.0}});
        const catmull_rom<3> c(p, {.alpha = alpha});
        const box<3> b = bounding_box(c);
        EXPECT_EQ(b.lo, (vec<3>{{1.0, -3.25, 3.0}}));
        EXPECT_EQ(b.hi, (vec<3>{{3.5, -2.0, 3.0}}));
        for (const auto& s : c.segments()) {
            EXPECT_TRUE(extrema(s).empty());
            ++checked;
        }
    }
    EXPECT_EQ(checked, 5u * 5);
}

TEST(Bounds, UnevenStraightLineOvershootsOnlyWhenUniform) {
    // Collinear points with uneven steps in 1-D: the uniform curve overshoots
    // between them (its box is wider than the points'), the centripetal and
    // chordal ones do not here. The box follows the curve either way.
    face_counts n;
    const std::vector<vec<1>> p = {{{0.0}}, {{0.1}}, {{1.0}}, {{1.1}}};
    for (double alpha : alphas) {
        const catmull_rom<1> c(p, {.alpha = alpha});
        check_curve(c, n);
        const box<1> b = bounding_box(c);
        if (alpha == 0.0) {
            EXPECT_TRUE(b.lo[0] < 0.0 || b.hi[0] > 1.1) << "[" << b.lo[0] << ", " << b.hi[0] << "]";
        }
    }
    EXPECT_EQ(n.faces, 5u * 2);
}

TEST(Bounds, OneDimensionalCurveFoldsBack) {
    // 0 -> 1 -> 0.25 in 1-D. Uniform: the tangent at the fold is
    // (1 - 0.75) / 2 > 0, so the curve overshoots past 1 and the top face is
    // an interior extremum. Centripetal: the chords 1 and 0.75 weigh the
    // tangent to (sqrt(0.75) - 0.75 / sqrt(0.75)) / ... = 0, no overshoot.
    face_counts n;
    const std::vector<vec<1>> p = {{{0.0}}, {{1.0}}, {{0.25}}};
    for (double alpha : alphas) {
        const catmull_rom<1> c(p, {.alpha = alpha});
        check_curve(c, n);
        const box<1> b = bounding_box(c);
        EXPECT_LE(b.lo[0], 0.0);
        if (alpha == 0.0) {
            EXPECT_GT(b.hi[0], 1.0 + 1e-3);
            EXPECT_FALSE(extrema(c.segment(0)).empty() && extrema(c.segment(1)).empty());
        }
        if (alpha == 0.5) {
            EXPECT_NEAR(b.hi[0], 1.0, 1e-15);
        }
    }
    EXPECT_EQ(n.curves, 5u);
    EXPECT_EQ(n.faces, 5u * 2);
}

TEST(Bounds, ConstantSegmentsAndConstantCurve) {
    // Repeated points give constant segments (h = 0, no motion): they add
    // nothing to the box. A curve of one repeated point is a single point.
    for (double alpha : {0.25, 0.5, 1.0}) {
        const std::vector<vec<2>> p = {{{0.0, 0.0}}, {{0.0, 0.0}}, {{1.0, 2.0}}, {{1.0, 2.0}}, {{3.0, -1.0}}};
        const catmull_rom<2> c(p, {.alpha = alpha});
        EXPECT_EQ(bounding_box(c.segment(0)), box<2>::of(p[0]));
        EXPECT_EQ(bounding_box(c.segment(2)), box<2>::of(p[2]));
        face_counts n;
        check_curve(c, n);
        EXPECT_EQ(n.faces, 4u);
    }
    const vec<2> q{{-1.5, 4.0}};
    for (bool closed : {false, true}) {
        const std::vector<vec<2>> p(4, q);
        const catmull_rom<2> c(p, {.alpha = 0.5, .closed = closed});
        EXPECT_EQ(bounding_box(c), box<2>::of(q));
        EXPECT_EQ(bounding_box(c).diagonal(), 0.0);
        EXPECT_EQ(control_box(c), box<2>::of(q));
    }
}

TEST(Bounds, BoxHelpers) {
    box<2> b = box<2>::of({{1.0, 2.0}});
    b.expand(vec<2>{{-1.0, 5.0}});
    b.expand(box<2>{{{0.0, 0.0}}, {{0.5, 1.0}}});
    EXPECT_EQ(b.lo, (vec<2>{{-1.0, 0.0}}));
    EXPECT_EQ(b.hi, (vec<2>{{1.0, 5.0}}));
    EXPECT_EQ(b.size(), (vec<2>{{2.0, 5.0}}));
    EXPECT_DOUBLE_EQ(b.diagonal(), std::sqrt(29.0));
    EXPECT_TRUE(b.contains({{0.0, 5.0}}));
    EXPECT_FALSE(b.contains({{0.0, 5.5}}));
    EXPECT_FALSE(b.contains({{std::nan(""), 1.0}}));
}

}  // namespace
