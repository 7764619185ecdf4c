// Curvature, torsion, Frenet and rotation-minimizing frames: closed forms on
// circles and helices, exact identities, the double-reflection property,
// closing of frames on closed curves, and zero-speed points.
#include "test_support.hpp"

#include <crspline/frames.hpp>

#include <cmath>
#include <limits>
#include <numbers>

namespace {
using namespace crspline;
using crspline::test::random_polygon;
using crspline::test::scale_of;
using P2 = vec<2>;
using P3 = vec<3>;
using crspline::test::eps;
using crspline::test::pi;
using crspline::test::alphas;

template <class T>
std::vector<T> linspace(T a, T b, std::size_t n) {
    std::vector<T> t(n);
    for (std::size_t k = 0; k < n; ++k) t[k] = a + (b - a) * T(k) / T(n - 1);
    t.back() = b;
    return t;
}

template <std::size_t D, class T>
std::vector<T> samples(const catmull_rom<D, T>& c, std::size_t n) {
    return linspace(c.t_min(), c.t_max(), n);
}

std::vector<P2> circle(std::size_t n, double r, P2 centre, double sign = 1) {
    std::vector<P2> p;
    for (std::size_t i = 0; i < n; ++i) {
        const double a = 2 * pi * double(i) / double(n);
        p.push_back(centre + P2{{r * std::cos(a), sign * r * std::sin(a)}});
    }
    return p;
}

std::vector<P3> helix(std::size_t n, double r, double pitch, double turns) {
    std::vector<P3> p;
    for (std::size_t i = 0; i < n; ++i) {
        const double a = 2 * pi * turns * double(i) / double(n - 1);
        p.push_back(P3{{r * std::cos(a), r * std::sin(a), pitch * a}});
    }
    return p;
}

// Largest |curvature * R - 1| over 2001 samples of a closed Catmull-Rom
// curve through n points on a circle of radius R.
double circle_curvature_error(std::size_t n, double alpha) {
    const double r = 2.5;
    catmull_rom<2> c(circle(n, r, P2{{3, -1}}), {.alpha = alpha, .closed = true});
    double worst = 0;
    for (double t : samples(c, 2001)) worst = std::max(worst, std::abs(curvature(c, t) * r - 1));
    return worst;
}

TEST(Curvature, CircleConvergesToOneOverRadius) {
    for (double alpha : alphas) {
        // Equal chords make every alpha the same curve. The cubic through
        // 64 points is an O(h^2) approximation of the circle's curvature:
        // about 0.72% at the knots (where x'' jumps), 0.36% mid-segment;
        // each doubling of the points divides the error by 4.
        const double e64 = circle_curvature_error(64, alpha), e128 = circle_curvature_error(128, alpha),
                     e256 = circle_curvature_error(256, alpha);
        EXPECT_LT(e64, 1e-2);
        EXPECT_LT(e256, 1e-3);
        EXPECT_NEAR(e64 / e128, 4.0, 0.1);
        EXPECT_NEAR(e128 / e256, 4.0, 0.1);
    }
}

TEST(Curvature, FloatCircle) {
    std::vector<vec<2, float>> p;
    for (const auto& x : circle(256, 2.5, P2{{3, -1}})) p.push_back(vec<2, float>{{float(x[0]), float(x[1])}});
    catmull_rom<2, float> c(p, {.closed = true});
    for (float t : samples(c, 501)) {
        // O(h^2) error of 4.5e-4 plus float rounding in x'' (coefficients of
        // size 1e-2 from differences of size-5 coordinates: ~1e-4 relative).
        EXPECT_NEAR(curvature(c, t) * 2.5f, 1.0f, 2e-3f);
        EXPECT_NEAR(signed_curvature(c, t) * 2.5f, 1.0f, 2e-3f);
    }
}

TEST(Curvature, SignedCurvatureFlipsInTheMirror) {
    CRSPLINE_SEEDED(s, 601);
    std::mt19937_64 rng(s);
    std::size_t checked = 0, left = 0;
    for (double alpha : alphas)
        for (int rep = 0; rep < 10; ++rep) {
            auto p = random_polygon<2>(rng, 6, 1.0);
            auto m = p;
            for (auto& x : m) x[1] = -x[1];
            catmull_rom<2> c(p, {.alpha = alpha}), cm(m, {.alpha = alpha});
            for (double t : samples(c, 50)) {
                const double k = signed_curvature(c, t);
                // Negating y is exact, and so is every step after it.
                EXPECT_EQ(signed_curvature(cm, t), -k);
                // Two formulas for one value: relative rounding, plus an
                // absolute eps |x''| / |x'|^2 where the turn nearly vanishes.
                const double speed = norm(c.evaluate(t, 1));
                EXPECT_NEAR(std::abs(k), curvature(c, t),
                            1e-12 * std::abs(k) + 64 * eps * norm(c.evaluate(t, 2)) / (speed * speed));
                left += k > 0;
                ++checked;
            }
        }
    EXPECT_GT(left, checked / 5);  // both signs really occur
    EXPECT_LT(left, checked * 4 / 5);
    // A counterclockwise circle turns left; its mirror image turns right.
    catmull_rom<2> ccw(circle(32, 1, P2{}), {.closed = true}), cw(circle(32, 1, P2{}, -1), {.closed = true});
    EXPECT_GT(signed_curvature(ccw, 0.3), 0.9);
    EXPECT_LT(signed_curvature(cw, 0.3), -0.9);
}

TEST(Curvature, StraightLinesHaveNone) {
    std::size_t checked = 0;
    for (double alpha : alphas) {
        // Along an axis the other coordinates are exactly zero: exactly 0.
        catmull_rom<3> axis({P3{{0, 0, 0}}, P3{{1, 0, 0}}, P3{{3, 0, 0}}, P3{{3.5, 0, 0}}, P3{{6, 0, 0}}},
                            {.alpha = alpha});
        for (double t : samples(axis, 40)) {
            EXPECT_EQ(curvature(axis, t), 0.0);
            EXPECT_EQ(torsion(axis, t), 0.0);
            ++checked;
        }
        // Along a diagonal, x' and x'' are parallel up to rounding: the
        // wedge is a few eps |x'| |x''|, so kappa <= 64 eps |x''| / |x'|^2.
        const P3 dir{{1 / 3.0, 2 / 3.0, -2 / 3.0}};
        catmull_rom<3> diag({0.0 * dir, 1.0 * dir, 3.0 * dir, 3.5 * dir, 6.0 * dir}, {.alpha = alpha});
        for (double t : samples(diag, 40)) {
            const double speed = norm(diag.evaluate(t, 1));
            if (speed < 1e-3) continue;  // a stop on the line: the ratio is unbounded but the rule gives 0
            EXPECT_LE(curvature(diag, t), 64 * eps * norm(diag.evaluate(t, 2)) / (speed * speed));
            ++checked;
        }
    }
    EXPECT_GE(checked, 5u * 40 + 5u * 30);
}

// Derivative magnitudes bound the rounding of a curvature: wedge error
// ~ eps |x'| |x''| and denominator error ~ eps kappa. The bound below uses
// the coefficient sizes (M1, M2 bound |x'|, |x''| before cancellation).
double curvature_tolerance(const catmull_rom<3>& c, double t, double k) {
    const auto& s = c.segment(c.locate(t));
    const double m1 = (max_abs(s.c1) + 2 * max_abs(s.c2) + 3 * max_abs(s.c3)) * s.inv_h;
    const double m2 = (2 * max_abs(s.c2) + 6 * max_abs(s.c3)) * s.inv_h * s.inv_h;
    const double speed = norm(c.evaluate(t, 1));
    return 256 * eps * (m1 * m2 / (speed * speed * speed) + k * m1 / speed);
}

TEST(Curvature, InvariantUnderRigidMotionsAndScalesInversely) {
    CRSPLINE_SEEDED(s, 602);
    std::mt19937_64 rng(s);
    std::normal_distribution<double> g(0.0, 1.0);
    for (double alpha : alphas)
        for (int rep = 0; rep < 8; ++rep) {
            auto p = random_polygon<3>(rng, 6, 1.0);
            // A random rotation (Gram-Schmidt on Gaussian columns) and shift.
            P3 a{{g(rng), g(rng), g(rng)}}, b{{g(rng), g(rng), g(rng)}};
            a = a / norm(a);
            b = b - dot(a, b) * a;
            b = b / norm(b);
            const P3 cc = detail::cross(a, b), shift{{g(rng), g(rng), g(rng)}};
            const double sc = 3.7;
            std::vector<P3> moved, scaled;
            for (const auto& x : p) {
                moved.push_back(x[0] * a + x[1] * b + x[2] * cc + shift);
                scaled.push_back(sc * x);
            }
            catmull_rom<3> c(p, {.alpha = alpha}), cm(moved, {.alpha = alpha}), cs(scaled, {.alpha = alpha});
            for (std::size_t k = 0; k < 40; ++k) {
                // The same point on each curve: same segment, same local u.
                const double u = (double(k) + 0.5) / 40;
                const std::size_t i = k % c.segment_count();
                const double t = c.grid()[i] + u * (c.grid()[i + 1] - c.grid()[i]);
                const double tm = cm.grid()[i] + u * (cm.grid()[i + 1] - cm.grid()[i]);
                const double ts = cs.grid()[i] + u * (cs.grid()[i + 1] - cs.grid()[i]);
                const double kappa = curvature(c, t);
                // Moving the points rounds them (eps of the coordinates); the
                // knots and coefficients follow within a few eps, which the
                // tolerance above covers (times 16 for the rotated sums).
                const double tol = 16 * curvature_tolerance(c, t, kappa);
                EXPECT_NEAR(curvature(cm, tm), kappa, tol);
                EXPECT_NEAR(curvature(cs, ts) * sc, kappa, tol);
                EXPECT_NEAR(std::abs(torsion(cm, tm)), std::abs(torsion(c, t)), 1e-6 * (1 + std::abs(torsion(c, t))));
            }
        }
}

TEST(Torsion, PlanarCurvesHaveNoneAndHelicesHaveTheirHandedness) {
    CRSPLINE_SEEDED(s, 603);
    std::mt19937_64 rng(s);
    for (double alpha : alphas) {
        // In the plane z = 0 every z component is exactly 0: det is exactly 0.
        auto p2 = random_polygon<2>(rng, 7, 1.0);
        std::vector<P3> flat;
        for (const auto& x : p2) flat.push_back(P3{{x[0], x[1], 0}});
        catmull_rom<3> c(flat, {.alpha = alpha});
        for (double t : samples(c, 60)) {
            EXPECT_EQ(torsion(c, t), 0.0);
        }
        // A right-handed helix (radius 2, rise 0.5 per radian) has torsion
        // 0.5 / 4.25 > 0. The interpolant keeps the sign but not the value:
        // torsion needs x''', which a cubic interpolant gets only to O(1)
        // (constant per segment), so this checks the sign. The natural ends
        // have x'' = 0 and so torsion 0 there (the documented limit).
        catmull_rom<3> right(helix(49, 2.0, 0.5, 3.0), {.alpha = alpha});
        catmull_rom<3> left(helix(49, 2.0, -0.5, 3.0), {.alpha = alpha});
        std::size_t positive = 0;
        for (double t : samples(right, 60)) {
            const double tau = torsion(right, t);
            EXPECT_GE(tau, 0.0);
            EXPECT_LT(tau, 1.0);
            positive += tau > 0.01;
            // The mirror image (z -> -z) negates every step exactly.
            EXPECT_EQ(torsion(left, t), -tau);
        }
        EXPECT_GE(positive, 50u);  // all but the two planar end segments
    }
}

template <std::size_t D, class T>
void expect_orthonormal(const frame<D, T>& f, T tol) {
    EXPECT_NEAR(double(norm(f.tangent)), 1.0, double(tol));
    EXPECT_NEAR(double(norm(f.normal)), 1.0, double(tol));
    EXPECT_NEAR(double(dot(f.tangent, f.normal)), 0.0, double(tol));
    if constexpr (D == 3) {
        EXPECT_NEAR(double(norm(f.binormal)), 1.0, double(tol));
        EXPECT_NEAR(double(dot(f.tangent, f.binormal)), 0.0, double(tol));
        EXPECT_NEAR(double(dot(f.normal, f.binormal)), 0.0, double(tol));
        // Right-handed: binormal = tangent x normal.
        EXPECT_LE(double(max_abs(detail::cross(f.tangent, f.normal) - f.binormal)), double(tol));
    }
}

template <std::size_t D, class T>
bool finite(const frame<D, T>& f) {
    for (std::size_t k = 0; k < D; ++k)
        if (!std::isfinite(f.position[k]) || !std::isfinite(f.tangent[k]) || !std::isfinite(f.normal[k]) ||
            !std::isfinite(f.binormal[k]))
            return false;
    return true;
}

TEST(Frames, OrthonormalInDoubleAndFloat) {
    CRSPLINE_SEEDED(s, 604);
    std::mt19937_64 rng(s);
    std::size_t checked = 0;
    for (double alpha : alphas)
        for (bool closed : {false, true}) {
            auto p = random_polygon<3>(rng, 8, 1.0);
            catmull_rom<3> c(p, {.alpha = alpha, .closed = closed});
            const auto t = samples(c, 200);
            // A handful of roundings on unit vectors: 1e-12 is ~4500 eps.
            for (const auto& f : frenet_frames(c, std::span<const double>(t))) expect_orthonormal(f, 1e-12), ++checked;
            for (const auto& f : rotation_minimizing_frames(c, std::span<const double>(t)))
                expect_orthonormal(f, 1e-12), ++checked;
            const auto r = rotation_minimizing_frames(c, std::span<const double>(t));
            for (std::size_t k = 0; k < t.size(); ++k) EXPECT_EQ(r[k].position, c.evaluate(t[k]));
            std::vector<vec<3, float>> pf;
            for (const auto& x : p) pf.push_back(vec<3, float>{{float(x[0]), float(x[1]), float(x[2])}});
            catmull_rom<3, float> cf(pf, {.alpha = alpha, .closed = closed});
            const auto tf = samples(cf, 200);
            for (const auto& f : frenet_frames(cf, std::span<const float>(tf))) expect_orthonormal(f, 1e-5f), ++checked;
            for (const auto& f : rotation_minimizing_frames(cf, std::span<const float>(tf)))
                expect_orthonormal(f, 1e-5f), ++checked;
            auto p2 = random_polygon<2>(rng, 8, 1.0);
            catmull_rom<2> c2(p2, {.alpha = alpha, .closed = closed});
            const auto t2 = samples(c2, 200);
            for (const auto& f : rotation_minimizing_frames(c2, std::span<const double>(t2)))
                expect_orthonormal(f, 1e-12), ++checked;
        }
    EXPECT_EQ(checked, 5u * 2 * 200 * 5);
}

// The rotation about the tangent between consecutive frames: carry frame a
// to b's tangent by the smallest rotation (about a.tangent x b.tangent),
// then the signed angle from the carried normal to b's normal.
double twist(const frame<3, double>& a, const frame<3, double>& b) {
    const P3 axis = detail::cross(a.tangent, b.tangent);
    const double sin_a = norm(axis), cos_a = dot(a.tangent, b.tangent);
    P3 n = a.normal;
    if (sin_a > 0) {
        const P3 k = axis / sin_a;  // Rodrigues
        n = cos_a * n + sin_a * detail::cross(k, n) + (1 - cos_a) * dot(k, n) * k;
    }
    return std::atan2(dot(detail::cross(n, b.normal), b.tangent), dot(n, b.normal));
}

TEST(Frames, RotationMinimizingFramesDoNotTwistButFrenetFramesDo) {
    for (double alpha : alphas) {
        catmull_rom<3> c(helix(33, 2.0, 0.5, 2.0), {.alpha = alpha});
        const auto t = samples(c, 2000);
        const auto rmf = rotation_minimizing_frames(c, std::span<const double>(t));
        const auto fr = frenet_frames(c, std::span<const double>(t));
        double rmf_twist = 0, frenet_twist = 0;
        for (std::size_t k = 0; k + 1 < t.size(); ++k) {
            rmf_twist += std::abs(twist(rmf[k], rmf[k + 1]));
            frenet_twist += std::abs(twist(fr[k], fr[k + 1]));
        }
        // Frenet frames turn with the torsion: about tau * length =
        // 0.5/4.25 * 2 turns * 2 pi * sqrt(4.25) ~ 3 radians in all. The
        // double reflection's per-step twist is O(h^3): far below.
        EXPECT_GT(frenet_twist, 2.0);
        EXPECT_LT(rmf_twist, 1e-4 * frenet_twist);
    }
}

TEST(Frames, DenseFramesAreContinuous) {
    CRSPLINE_SEEDED(s, 605);
    std::mt19937_64 rng(s);
    std::size_t checked = 0;
    for (double alpha : {0.5, 1.0})  // no cusps: the tangent itself is continuous
        for (int rep = 0; rep < 5; ++rep) {
            catmull_rom<3> c(random_polygon<3>(rng, 8, 1.0), {.alpha = alpha});
            const auto t = samples(c, 4000);
            const auto f = rotation_minimizing_frames(c, std::span<const double>(t));
            for (std::size_t k = 0; k + 1 < f.size(); ++k) {
                // An RMF normal moves only as far as the tangent pulls it:
                // dN/ds = -(T' . N) T, so its turn is at most the tangent's.
                const double turn_t = std::acos(std::clamp(dot(f[k].tangent, f[k + 1].tangent), -1.0, 1.0));
                const double turn_n = std::acos(std::clamp(dot(f[k].normal, f[k + 1].normal), -1.0, 1.0));
                EXPECT_LE(turn_n, 1.01 * turn_t + 1e-7) << "sample " << k;
                ++checked;
            }
        }
    EXPECT_EQ(checked, 2u * 5 * 3999);
}

TEST(Frames, ClosedCurvesCloseUp) {
    CRSPLINE_SEEDED(s, 606);
    std::mt19937_64 rng(s);
    std::size_t checked = 0, twisted = 0;
    for (double alpha : alphas)
        for (int rep = 0; rep < 6; ++rep) {
            catmull_rom<3> c(random_polygon<3>(rng, 5 + std::size_t(rep), 1.0), {.alpha = alpha, .closed = true});
            const auto t = samples(c, 300 + 100 * std::size_t(rep));
            const auto f = rotation_minimizing_frames(c, std::span<const double>(t));
            const auto& a = f.front();
            const auto& b = f.back();
            // t_min and t_max are the same point: after the twist is spread,
            // the same frame, up to the rounding of the rotation (1e-9).
            EXPECT_LE(max_abs(a.position - b.position), 0.0);
            EXPECT_LE(max_abs(a.tangent - b.tangent), 1e-9);
            EXPECT_LE(max_abs(a.normal - b.normal), 1e-9);
            EXPECT_LE(max_abs(a.binormal - b.binormal), 1e-9);
            // Without the correction the frames would not close: the
            // same samples on an open copy's frames end elsewhere.
            const std::vector<double> open_t(t.begin(), t.end() - 1);
            const auto g = rotation_minimizing_frames(c, std::span<const double>(open_t));
            twisted += std::abs(twist(g.back(), a)) > 1e-3;
            ++checked;
        }
    EXPECT_GE(twisted, checked / 2);  // the holonomy is generic, not zero
}

TEST(Frames, InitialNormalIsHonouredAndChecked) {
    catmull_rom<3> c(helix(20, 1.0, 0.3, 1.0));
    const auto t = samples(c, 50);
    const P3 wanted{{0, 0, 1}};
    const auto f = rotation_minimizing_frames(c, std::span<const double>(t), wanted);
    const auto expect = detail::perpendicular(wanted, f[0].tangent);
    ASSERT_TRUE(expect.has_value());
    EXPECT_LE(max_abs(f[0].normal - *expect), 1e-15);
    EXPECT_THROW(rotation_minimizing_frames(c, std::span<const double>(t), f[0].tangent), invalid_input);
    EXPECT_THROW(rotation_minimizing_frames(c, std::span<const double>(t), P3{{0, std::nan(""), 0}}), invalid_input);
    const std::vector<double> bad{0.0, c.t_max() * 2};
    EXPECT_THROW(frenet_frames(c, std::span<const double>(bad)), out_of_domain);
    EXPECT_THROW(curvature(c, -1.0), out_of_domain);
    EXPECT_TRUE(rotation_minimizing_frames(c, std::span<const double>()).empty());
    // 2-D: the left normal, or the right one when asked.
    catmull_rom<2> c2(circle(16, 1, P2{}), {.closed = true});
    const auto t2 = samples(c2, 20);
    const auto l = rotation_minimizing_frames(c2, std::span<const double>(t2));
    const auto r = rotation_minimizing_frames(c2, std::span<const double>(t2), P2{{0, -1}});
    for (std::size_t k = 0; k < t2.size(); ++k) {
        EXPECT_EQ(l[k].normal, (P2{{-l[k].tangent[1], l[k].tangent[0]}}));
        EXPECT_EQ(r[k].normal, -l[k].normal);
        EXPECT_EQ(l[k].binormal, P2{});
    }
}

TEST(Frames, ZeroSpeedPointsGiveFiniteFrames) {
    // Uniform knots and P0 = P2: the tangent at P1 is (P2 - P0) / 2 = 0, a
    // cusp (x'' and x''' are not parallel there since P3 is off the line).
    const std::vector<P3> p{{{0, 0, 0}}, {{2, 1, 0}}, {{0, 0, 0}}, {{1, -2, 1}}, {{3, 0, 2}}};
    catmull_rom<3> c(p, {.alpha = 0.0});
    const double t1 = c.grid()[1];
    ASSERT_EQ(norm(c.evaluate(t1, 1)), 0.0);
    EXPECT_EQ(curvature(c, t1), std::numeric_limits<double>::infinity());  // the cusp's limit
    EXPECT_EQ(torsion(c, t1), 0.0);  // planar near a zero-speed point (see frames.hpp)
    EXPECT_GT(curvature(c, t1 + 1e-6), 1e4);  // approaching the cusp: 1 / |t - t1| growth
    // In 2-D the signed limit has the sign of x'' x x'''.
    std::vector<P2> q;
    for (const auto& x : p) q.push_back(P2{{x[0], x[1]}});
    catmull_rom<2> c2(q, {.alpha = 0.0});
    const P2 a = c2.evaluate(t1, 2), b = c2.evaluate(t1, 3);
    EXPECT_EQ(signed_curvature(c2, t1), std::copysign(std::numeric_limits<double>::infinity(), a[0] * b[1] - a[1] * b[0]));
    // Frames at, around and beyond the cusp: finite and orthonormal; the
    // tangent at the cusp is the direction of x'' (the limit from the right).
    std::size_t checked = 0;
    const std::vector<double> t{0.0, 0.5, t1 - 1e-9, t1, t1 + 1e-9, 1.5, 2.0, c.t_max()};
    for (const auto& frames : {frenet_frames(c, std::span<const double>(t)),
                               rotation_minimizing_frames(c, std::span<const double>(t))}) {
        for (const auto& f : frames) {
            EXPECT_TRUE(finite(f));
            expect_orthonormal(f, 1e-12);
            ++checked;
        }
        const P3 x2 = c.evaluate(t1, 2);
        EXPECT_LE(max_abs(frames[3].tangent - x2 / norm(x2)), 1e-15);
    }
    // A constant curve: every derivative vanishes; frames still finite.
    catmull_rom<3> still(std::vector<P3>(4, P3{{1, 2, 3}}));
    const auto ts = samples(still, 5);
    EXPECT_EQ(curvature(still, still.t_min()), 0.0);
    EXPECT_EQ(torsion(still, still.t_min()), 0.0);
    for (const auto& frames : {frenet_frames(still, std::span<const double>(ts)),
                               rotation_minimizing_frames(still, std::span<const double>(ts))})
        for (const auto& f : frames) {
            EXPECT_TRUE(finite(f));
            expect_orthonormal(f, 1e-12);
            ++checked;
        }
    EXPECT_EQ(checked, 2u * 8 + 2u * 5);
}

// Closed forms, independent of the code under test: the twisted cubic
// x(t) = (t, t^2, t^3) on [a, b] as the first segment of a curve. That
// segment is the Hermite cubic with x(a), x(b), the start tangent (given:
// dx(a)) and the tangent at b, which on a uniform grid {a, b, 2b - a} is
// (P2 - P0) / 2h; P2 = P0 + 2h dx(b) makes it dx(b), so the segment is the
// twisted cubic itself. (Two points alone give a straight line whatever the
// end conditions: README.) From x' = (1, 2t, 3t^2), x'' = (0, 2, 6t),
// x''' = (0, 0, 6): x' x x'' = (6t^2, -6t, 2), so
//   kappa = 2 sqrt(9t^4 + 9t^2 + 1) / (1 + 4t^2 + 9t^4)^(3/2),
//   tau = det(x', x'', x''') / |x' x x''|^2 = 3 / (9t^4 + 9t^2 + 1).
TEST(Frames, TwistedCubicCurvatureAndTorsionInClosedForm) {
    const auto x = [](double t) { return P3{{t, t * t, t * t * t}}; };
    const auto dx = [](double t) { return P3{{1, 2 * t, 3 * t * t}}; };
    for (const auto& [a, b] : {std::pair{0.0, 1.0}, std::pair{-1.0, 0.5}, std::pair{-0.25, 0.5}}) {
        const double h = b - a;
        const catmull_rom<3> c(std::vector<P3>{x(a), x(b), x(a) + (2 * h) * dx(b)},
                               {.grid = std::vector<double>{a, b, b + h}, .start = end_condition<3>::tangent(dx(a))});
        for (int j = 0; j < 40; ++j) {  // [a, b): b belongs to the next segment
            const double t = a + h * j / 40.0;
            const double q = 9 * t * t * t * t + 9 * t * t + 1;
            const double kappa = 2 * std::sqrt(q) / std::pow(1 + 4 * t * t + 9 * t * t * t * t, 1.5);
            const double tau = 3 / q;
            // The curve's coefficients carry a few roundings of points and
            // tangents of size 1 to 12; kappa and tau are ratios of products
            // of derivatives: 1e-12 relative is thousands of eps of room for
            // that, and far below any error in a formula, which is O(1).
            EXPECT_NEAR(curvature(c, t), kappa, 1e-12 * kappa) << "t " << t;
            EXPECT_NEAR(torsion(c, t), tau, 1e-12 * tau) << "t " << t;
            // The segment is the cubic itself (coordinates up to 1).
            EXPECT_LE(max_abs(c.evaluate(t) - x(t)), 64 * std::numeric_limits<double>::epsilon()) << "t " << t;
        }
    }
}

}  // namespace
