// Sweeps: the seam, the proved tolerance against an independent sampling
// of the surface, frame continuity, roll keys, the up vector, given counts
// and the self-intersection report.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "sweep_support.hpp"

using namespace crspline;
using namespace sweep_test;

namespace {

double angle_between(const v3& a, const v3& b) { return std::atan2(norm(cross3(a, b)), dot(a, b)); }

v3 vertex(const sweep_mesh& m, std::size_t k, std::size_t j) { return mesh_vertex(m, k, j); }
v3 normal_at(const sweep_mesh& m, std::size_t k, std::size_t j) {
    const double* p = m.normals.data() + 3 * (k * m.ring_size + j);
    return {{p[0], p[1], p[2]}};
}

}  // namespace

// The closing ring, as computed, meets the first to rounding; without the
// spread holonomy it does not (the seam three.js has). 64 eps of the
// coordinates: the frame carried once around by double reflection and
// turned back by the measured angle loses a few ulps a ring in direction,
// not in position (the knot's radius is 3).
TEST(Sweep, ClosedCurvesCloseWithoutASeam) {
    CRSPLINE_SEEDED(seed, 41);
    std::mt19937_64 rng(seed);
    int checked = 0;
    for (int trial = 0; trial < 6; ++trial) {
        options<3> o;
        o.closed = true;
        const catmull_rom<3> c(trial == 0 ? torus_knot(12) : random_points(rng, 7), o);
        sweep_options so;
        so.profile = sweep_profile::circle(1e-3);
        so.tolerance = 1e-3;
        // Half the smallest radius of curvature: a tube that does not fold.
        so.profile.radius = 0.5 * sweep(c, so).report.min_radius_of_curvature;
        const auto m = sweep(c, so);
        EXPECT_FALSE(m.report.local_fold) << "trial " << trial;
        EXPECT_LE(m.report.seam_gap, 1e-9) << "trial " << trial;
        EXPECT_LE(m.report.seam_normal_gap, 1e-9) << "trial " << trial;
        // The stored closing ring is the first bit for bit, texture u too.
        const std::size_t last = m.rings - 1;
        for (std::size_t j = 0; j < m.ring_size; ++j) {
            EXPECT_EQ(vertex(m, last, j), vertex(m, 0, j));
            EXPECT_EQ(normal_at(m, last, j), normal_at(m, 0, j));
            EXPECT_EQ(m.uvs[2 * (last * m.ring_size + j)], m.uvs[2 * j]);
        }
        EXPECT_EQ(m.uvs[2 * (last * m.ring_size) + 1], 1.0);
        // Across the seam the normals turn no more than between other rings.
        double step = 0;
        for (std::size_t k = 0; k + 1 < m.rings; ++k) step = std::max(step, angle_between(normal_at(m, k, 0), normal_at(m, k + 1, 0)));
        EXPECT_LE(angle_between(normal_at(m, m.rings - 2, 0), normal_at(m, 0, 0)), step * 1.000001);
        // Without the fix: a seam as wide as the holonomy says.
        so.spread_holonomy = false;
        const auto bad = sweep(c, so);
        EXPECT_GT(bad.report.seam_gap, so.profile.radius * 0.5 * std::abs(m.report.holonomy)) << "trial " << trial;
        ++checked;
    }
    EXPECT_EQ(checked, 6);
}

// The mesh within the tolerance of the swept surface, checked at random
// points of random triangles against the surface built independently: the
// rotation-minimizing frame of frames.hpp on a dense grid (its own holonomy
// spreading), the roll from the rotation spline's evaluate(), the scale from
// a 1-D Catmull-Rom curve, the profile's point projected radially onto the
// circle. Each triangle point and its surface point share parameters (the
// correspondence the proof uses).
TEST(Sweep, MeshIsWithinTheToleranceOfAnIndependentSurface) {
    CRSPLINE_SEEDED(seed, 4141);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    std::size_t points_checked = 0;
    double worst = 0;
    for (int trial = 0; trial < 8; ++trial) {
        options<3> o;
        o.closed = trial % 2 == 0;
        const catmull_rom<3> c(trial == 0 ? torus_knot(10) : random_points(rng, 6), o);
        const arc_length_table<3> table(c);
        const double L = table.total();
        sweep_options so;
        const double radius = 0.05 + 0.1 * unit(rng);
        so.profile = sweep_profile::circle(radius);
        so.tolerance = trial < 4 ? 2e-3 : 3e-4;
        std::vector<double> roll_w;
        if (trial % 3 != 2) {
            for (std::size_t k = 0; k < c.points().size(); ++k) so.roll.push_back(3 * (unit(rng) - 0.5));
            roll_w.assign(c.grid().begin(), c.grid().begin() + std::ptrdiff_t(so.roll.size()));
        }
        so.scale_s = {0.2 * L, 0.5 * L, 0.8 * L};
        so.scale = {1.0, 0.5 + unit(rng), 1.2};
        const auto m = sweep(c, so);
        ASSERT_TRUE(m.report.tolerance_met);
        ASSERT_LE(m.report.bound, so.tolerance * (1 + 1e-12));
        const reference_roll roll(roll_w, so.roll,
                                  o.closed ? std::optional<double>(c.t_max() - c.t_min()) : std::nullopt);
        std::vector<vec<1>> sk;
        for (double v : so.scale) sk.push_back({{v}});
        options<1> so1;
        so1.grid = so.scale_s;
        if (o.closed) so1.grid->push_back(so.scale_s.front() + L), so1.closed = true;  // the scale closes up too
        const catmull_rom<1> scale(sk, so1);
        // Sample points: ring interval, lambda, triangle, split.
        struct sample { std::size_t k, j; int tri; double lambda, mu; double t; };
        std::vector<sample> ss;
        for (int q = 0; q < 3000; ++q) {
            sample s{};
            s.k = std::size_t(unit(rng) * double(m.rings - 1));
            s.j = std::size_t(unit(rng) * double(m.ring_size - 1));
            s.tri = unit(rng) < 0.5 ? 0 : 1;
            s.lambda = unit(rng), s.mu = unit(rng);
            s.t = m.t[s.k] + s.lambda * (m.t[s.k + 1] - m.t[s.k]);
            ss.push_back(s);
        }
        std::vector<double> ts;
        for (const auto& s : ss) ts.push_back(s.t);
        for (int k = 0; k <= 20000; ++k) ts.push_back(k == 20000 ? c.t_max() : c.t_min() + (c.t_max() - c.t_min()) * k / 20000.0);
        std::sort(ts.begin(), ts.end());
        const auto fr = rotation_minimizing_frames(c, std::span<const double>(ts));
        const std::size_t n = m.ring_size - 1;
        for (const auto& s : ss) {
            const auto it = std::lower_bound(ts.begin(), ts.end(), s.t);
            const auto& f = fr[std::size_t(it - ts.begin())];
            // Triangle corners (k, j), (k, j + 1), (k + 1, j), (k + 1, j + 1) and weights.
            const double l = s.lambda, mu = s.mu;
            v3 mp;
            double wj, wj1;  // weights of profile vertices j and j + 1
            if (s.tri == 0) {  // (k, j), (k, j + 1), (k + 1, j): w_c = lambda
                mp = (1 - l) * mu * vertex(m, s.k, s.j) + (1 - l) * (1 - mu) * vertex(m, s.k, s.j + 1) + l * vertex(m, s.k + 1, s.j);
                wj = (1 - l) * mu + l, wj1 = (1 - l) * (1 - mu);
            } else {  // (k, j + 1), (k + 1, j + 1), (k + 1, j): w_b = 1 - lambda
                mp = (1 - l) * vertex(m, s.k, s.j + 1) + l * mu * vertex(m, s.k + 1, s.j + 1) + l * (1 - mu) * vertex(m, s.k + 1, s.j);
                wj = l * (1 - mu), wj1 = (1 - l) + l * mu;
            }
            const double a0 = 2 * std::numbers::pi * double(s.j) / double(n), a1 = 2 * std::numbers::pi * double(s.j + 1) / double(n);
            const vec<2> pb{{wj * std::cos(a0) + wj1 * std::cos(a1), wj * std::sin(a0) + wj1 * std::sin(a1)}};
            const vec<2> pc = pb / norm(pb);
            const double psi = roll(s.t);
            const v3 nn = std::cos(psi) * f.normal + std::sin(psi) * cross3(f.tangent, f.normal);
            const v3 bb = cross3(f.tangent, nn);
            double sv = table.s_at(s.t);
            if (o.closed) sv = sv < so.scale_s.front() ? sv + L : sv;
            else sv = std::clamp(sv, so.scale_s.front(), so.scale_s.back());
            const double r = scale.evaluate(sv)[0];
            const v3 sp = c.evaluate(s.t) + r * radius * (pc[0] * nn + pc[1] * bb);
            worst = std::max(worst, norm(sp - mp) / so.tolerance);
            ++points_checked;
        }
    }
    EXPECT_LE(worst, 1.0);
    EXPECT_GT(worst, 0.2);  // the bound is not wildly loose: 0.52 at seed 4141 (0.90 with the bound divided by 4)
    EXPECT_EQ(points_checked, 8u * 3000u);
    std::printf("largest distance over the tolerance: %.3f\n", worst);
}

// Adjacent rings' frames turn by at most what the curve and the roll allow
// (the curve's tangent turn plus the spread holonomy's share): no flips.
TEST(Sweep, FramesAreContinuous) {
    CRSPLINE_SEEDED(seed, 414);
    std::mt19937_64 rng(seed);
    for (int trial = 0; trial < 5; ++trial) {
        options<3> o;
        o.closed = trial % 2 == 1;
        const catmull_rom<3> c(random_points(rng, 8), o);
        sweep_options so;
        so.profile = sweep_profile::circle(0.05);
        so.tolerance = 1e-3;
        const auto m = sweep(c, so);
        const double twist = std::abs(m.report.holonomy) / (c.t_max() - c.t_min());
        for (std::size_t k = 0; k + 1 < m.rings; ++k) {
            const v3 e0 = c.evaluate(m.t[k], 1), e1 = c.evaluate(m.t[k + 1], 1);
            const double allowed = angle_between(e0, e1) + twist * (m.t[k + 1] - m.t[k]) + 1e-9;
            // The normal of profile vertex 0 is the frame's normal direction (turned by the surface's tilt
            // where the speed changes): compare the frames through ring positions instead.
            const v3 n0 = vertex(m, k, 0) - c.evaluate(m.t[k]), n1 = vertex(m, k + 1, 0) - c.evaluate(m.t[k + 1]);
            EXPECT_LE(angle_between(n0, n1), allowed) << "trial " << trial << " ring " << k;
        }
    }
}

// Roll keys at knots and at arc lengths are hit exactly: the ring at a key
// is the roll-free ring turned by the key's angle about the tangent.
TEST(Sweep, RollKeysAreHitExactly) {
    CRSPLINE_SEEDED(seed, 1441);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> a(-1.4, 1.4);
    int keys_checked = 0;
    for (int trial = 0; trial < 4; ++trial) {
        const catmull_rom<3> c(random_points(rng, 6));
        sweep_options plain;
        plain.profile = sweep_profile::circle(0.1);
        plain.tolerance = 1e-3;
        plain.tubular_segments = 0;
        const auto m0 = sweep(c, plain);
        sweep_options rolled = plain;
        const bool at_s = trial % 2 == 1;
        std::vector<double> where;
        if (at_s) {
            rolled.roll_at = roll_position::arc_length;
            for (double f : {0.0, 0.3, 0.55, 1.0}) rolled.roll_s.push_back(f * m0.report.length);
            where = rolled.roll_s;
        } else {
            where.assign(c.grid().begin(), c.grid().end());
        }
        for (std::size_t k = 0; k < where.size(); ++k) rolled.roll.push_back(k == 0 ? a(rng) : rolled.roll.back() + a(rng) * 2);
        const auto m1 = sweep(c, rolled);
        for (std::size_t q = 0; q < where.size(); ++q) {
            const auto& ring_w = at_s ? m1.s : m1.t;
            const auto it = std::min_element(ring_w.begin(), ring_w.end(), [&](double x, double y) { return std::abs(x - where[q]) < std::abs(y - where[q]); });
            ASSERT_LE(std::abs(*it - where[q]), 1e-9 * m0.report.length) << "a ring at key " << q;
            const std::size_t k1 = std::size_t(it - ring_w.begin());
            // The roll-free frame at that t: a sweep of the same curve, ring by ring, is what m0 has at
            // the knots; at arc-length keys, compare with the rotation-minimizing frame itself.
            const double t = m1.t[k1];
            const v3 e = c.evaluate(t, 1) / norm(c.evaluate(t, 1));
            std::vector<double> ts(m1.t.begin(), m1.t.begin() + std::ptrdiff_t(k1 + 1));
            const auto fr = rotation_minimizing_frames(c, std::span<const double>(ts));
            const v3 n1 = (vertex(m1, k1, 0) - c.evaluate(t)) / 0.1;
            const double got = std::atan2(dot(cross3(fr.back().normal, n1), e), dot(fr.back().normal, n1));
            EXPECT_NEAR(std::remainder(got - rolled.roll[q], 2 * std::numbers::pi), 0.0, 1e-9) << "trial " << trial << " key " << q;
            ++keys_checked;
        }
    }
    EXPECT_EQ(keys_checked, 2 * 6 + 2 * 4);
}

// The roll read as angles from the rotation spline's control rotations
// is the rotation spline's own curve.
TEST(Sweep, RollIsTheRotationSplinesCurve) {
    const std::vector<double> w{0, 1, 2.5, 3, 5}, th{0.3, -1.0, 1.5, 2.9, 0.2};
    const auto f = detail::roll_function(w, th, std::nullopt);
    const reference_roll ref(w, th, std::nullopt);
    double worst = 0;
    for (int k = 0; k <= 1000; ++k) {
        const double x = 5.0 * k / 1000;
        worst = std::max(worst, std::abs(std::remainder(f.value(x) - ref(x), 2 * std::numbers::pi)));
    }
    EXPECT_LE(worst, 1e-12);
}

// With an up vector the normal is the up vector's projection (or its
// opposite after passing vertical) wherever the tangent is more than 5
// degrees from vertical; through a vertical loop it never flips, and the
// bound is proved through the poles too (test_poles.cpp checks it).
TEST(Sweep, UpVectorKeepsNormalsUprightAndNeverFlips) {
    std::vector<v3> loop;
    for (int k = 0; k < 16; ++k) {  // a loop in the vertical x-z plane, drifting sideways by less than 1 degree
        const double a = 2 * std::numbers::pi * k / 16.0;
        loop.push_back({{std::sin(a) + 0.3 * a, 0.001 * a, 1 - std::cos(a)}});
    }
    const catmull_rom<3> c(loop);
    sweep_options so;
    so.profile = sweep_profile::circle(0.05);
    so.up = v3{{0, 0, 1}};
    so.tolerance = 1e-3;
    const auto m = sweep(c, so);
    EXPECT_TRUE(m.report.proved);
    EXPECT_TRUE(m.report.tolerance_met);
    const v3 up{{0, 0, 1}};
    int upright = 0;
    double biggest_step = 0;
    for (std::size_t k = 0; k < m.rings; ++k) {
        const v3 e = c.evaluate(m.t[k], 1) / norm(c.evaluate(m.t[k], 1));
        const v3 n = (vertex(m, k, 0) - c.evaluate(m.t[k])) / 0.05;
        if (norm(cross3(e, up)) > std::sin(5 * std::numbers::pi / 180)) {
            const v3 p = (up - dot(up, e) * e) / norm(up - dot(up, e) * e);
            EXPECT_NEAR(norm(cross3(n, p)), 0.0, 1e-9) << "ring " << k;
            ++upright;
        }
        if (k > 0) {
            const v3 n0 = (vertex(m, k - 1, 0) - c.evaluate(m.t[k - 1])) / 0.05;
            biggest_step = std::max(biggest_step, angle_between(n0, n));
        }
    }
    EXPECT_GT(upright, int(m.rings) / 2);
    EXPECT_LT(biggest_step, 0.3);
    // The normal turns in all about as much as the rotation-minimizing
    // frame's (the loop is nearly planar, so the up vector's projection is
    // nearly that frame's normal): a half turn at each vertical pass (a
    // flip, even an eased one) would add pi twice.
    auto total_turn = [&](const sweep_mesh& mm) {
        double sum = 0;
        for (std::size_t k = 0; k + 1 < mm.rings; ++k)
            sum += angle_between(vertex(mm, k, 0) - c.evaluate(mm.t[k]), vertex(mm, k + 1, 0) - c.evaluate(mm.t[k + 1]));
        return sum;
    };
    sweep_options rmf = so;
    rmf.up.reset();
    const double turn_rmf = total_turn(sweep(c, rmf)), turn_up = total_turn(m);
    EXPECT_LT(turn_up, turn_rmf + 1.0) << turn_up << " vs " << turn_rmf;
}

// With an up vector whose poles the curve keeps clear of (every tangent
// more than 5 degrees from it), the frame is the up vector's projection
// everywhere, and the bound is proved for it (sweep/sampling.hpp): the mesh
// against an independent surface on that frame, sampled as the test above
// samples the rotation-minimizing one. Seeded curves nearly level (a road:
// random points in x, y and a tenth of it in z) and a steep helix, its
// tangent 8 degrees from vertical (the up frame turns about it 7 times
// faster than the rotation-minimizing one). The bound's up terms are not
// what this sampling can catch missing: measured while writing it, with
// radii 0.5 to 1 the helix took 379 rings with them and 212 without, and
// both meshes sampled within the tolerance (the along-curve share of the
// bound is loose there); what fails it is a frame other than the
// projection, or a bound that does not hold.
TEST(Sweep, UpVectorMeshIsWithinTheToleranceOfItsSurface) {
    CRSPLINE_SEEDED(seed, 5151);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    const v3 up{{0, 0, 1}};
    double worst = 0;
    std::size_t checked = 0;
    for (int trial = 0; trial < 6; ++trial) {
        std::vector<v3> pts;
        if (trial == 0) {
            for (int k = 0; k < 12; ++k) pts.push_back({{std::cos(k * 0.7), std::sin(k * 0.7), 0.7 * std::tan(82 * std::numbers::pi / 180) * k}});
        } else {
            for (auto p : random_points(rng, 7)) pts.push_back({{p[0], p[1], 0.1 * p[2]}});
        }
        options<3> o;
        o.closed = trial % 2 == 1;
        const catmull_rom<3> c(pts, o);
        // Keep only curves clear of the poles (nearly level ones are; a
        // random one may still turn steeply at a tight corner): the test
        // is of the bound, which the report says it proves.
        bool clear = true;
        for (int k = 0; k <= 4000; ++k) {
            const v3 d = c.evaluate(c.t_min() + (c.t_max() - c.t_min()) * k / 4000.0, 1);
            clear &= norm(cross3(d, up)) > std::sin(6 * std::numbers::pi / 180) * norm(d);
        }
        if (!clear) continue;
        sweep_options so;
        const double radius = 0.05 + 0.1 * unit(rng);
        so.profile = sweep_profile::circle(radius);
        so.up = up;
        so.tolerance = trial < 3 ? 2e-3 : 3e-4;
        const auto m = sweep(c, so);
        ASSERT_TRUE(m.report.proved) << "seed " << seed << ", trial " << trial;
        ASSERT_TRUE(m.report.tolerance_met) << "seed " << seed << ", trial " << trial;
        ASSERT_LE(m.report.bound, so.tolerance * (1 + 1e-12));
        const std::size_t n = m.ring_size - 1;
        for (int q = 0; q < 3000; ++q) {
            const std::size_t k = std::size_t(unit(rng) * double(m.rings - 1)), j = std::size_t(unit(rng) * double(n));
            const double l = unit(rng), mu = unit(rng);
            const bool tri0 = unit(rng) < 0.5;
            v3 mp;
            double wj, wj1;
            if (tri0) {
                mp = (1 - l) * mu * vertex(m, k, j) + (1 - l) * (1 - mu) * vertex(m, k, j + 1) + l * vertex(m, k + 1, j);
                wj = (1 - l) * mu + l, wj1 = (1 - l) * (1 - mu);
            } else {
                mp = (1 - l) * vertex(m, k, j + 1) + l * mu * vertex(m, k + 1, j + 1) + l * (1 - mu) * vertex(m, k + 1, j);
                wj = l * (1 - mu), wj1 = (1 - l) + l * mu;
            }
            const double t = m.t[k] + l * (m.t[k + 1] - m.t[k]);
            const double a0 = 2 * std::numbers::pi * double(j) / double(n), a1 = 2 * std::numbers::pi * double(j + 1) / double(n);
            const vec<2> pb{{wj * std::cos(a0) + wj1 * std::cos(a1), wj * std::sin(a0) + wj1 * std::sin(a1)}};
            const vec<2> pc = pb / norm(pb);
            // The independent frame: the up vector's projection, its sign
            // that of ring k's normal (vertex 0 of a circle lies on it).
            const v3 e = c.evaluate(t, 1) / norm(c.evaluate(t, 1));
            v3 nn = (up - dot(up, e) * e) / norm(up - dot(up, e) * e);
            if (dot(nn, vertex(m, k, 0) - c.evaluate(m.t[k])) < 0) nn = -1.0 * nn;
            const v3 sp = c.evaluate(t) + radius * (pc[0] * nn + pc[1] * cross3(e, nn));
            worst = std::max(worst, norm(sp - mp) / so.tolerance);
            ++checked;
        }
    }
    EXPECT_GE(checked, 3u * 3000u) << "seed " << seed;  // the helix and at least two random roads
    EXPECT_LE(worst, 1.0) << "seed " << seed;
    EXPECT_GT(worst, 0.1) << "seed " << seed;  // the bound is not wildly loose
    std::printf("up frame: largest distance over the tolerance %.3f (%zu samples)\n", worst, checked);
}

// Given counts: three.js' layout of (tubular + 1) x (radial + 1) vertices.
TEST(Sweep, GivenCountsGiveThreeJsCounts) {
    options<3> o;
    o.closed = true;
    const catmull_rom<3> c(torus_knot(10), o);
    sweep_options so;
    so.profile = sweep_profile::circle(0.2);
    so.tubular_segments = 64;
    so.radial_segments = 8;
    const auto m = sweep(c, so);
    EXPECT_EQ(m.rings, 65u);
    EXPECT_EQ(m.ring_size, 9u);
    EXPECT_EQ(m.positions.size(), 3u * 65u * 9u);
    EXPECT_EQ(m.indices.size(), 6u * 64u * 8u);
    EXPECT_GT(m.report.bound, 0.0);
    EXPECT_TRUE(std::isfinite(m.report.bound));
    for (std::size_t k = 0; k < m.rings; ++k) EXPECT_NEAR(m.s[k], m.report.length * double(k) / 64.0, 1e-9);
}

// Self-intersection: a thick tube on a knot meets itself, a thin one not;
// a radius above the radius of curvature folds. The radius of curvature is
// bounded from below between the rings too: against 20,000 samples of the
// curvature of seeded curves, the report's minimum is at most the sampled
// one and not far below it (the bound is not wildly loose).
TEST(Sweep, ReportSaysWhenTheTubeMeetsItself) {
    CRSPLINE_SEEDED(seed, 4343);
    std::mt19937_64 rng(seed);
    auto sampled_min_radius = [](const catmull_rom<3>& c) {
        double best = std::numeric_limits<double>::infinity();
        for (int k = 0; k <= 20000; ++k) {
            const double t = c.t_min() + (c.t_max() - c.t_min()) * k / 20000.0;
            const v3 d1 = c.evaluate(t, 1), d2 = c.evaluate(t, 2);
            const double sp = norm(d1), kappa = norm(cross3(d1, d2)) / (sp * sp * sp);
            if (kappa > 0) best = std::min(best, 1 / kappa);
        }
        return best;
    };
    double loosest = 1;
    for (int trial = 0; trial < 6; ++trial) {
        options<3> oo;
        oo.closed = trial % 2 == 0;
        const catmull_rom<3> cc(random_points(rng, 7), oo);
        sweep_options s1;
        s1.profile = sweep_profile::circle(0.01);
        s1.tolerance = trial < 3 ? 1e-3 : 1e-2;
        const auto m = sweep(cc, s1);
        const double sampled = sampled_min_radius(cc);
        EXPECT_LE(m.report.min_radius_of_curvature, sampled * (1 + 1e-9)) << "seed " << seed << " trial " << trial;
        EXPECT_GT(m.report.min_radius_of_curvature, 0.8 * sampled) << "seed " << seed << " trial " << trial;
        loosest = std::min(loosest, m.report.min_radius_of_curvature / sampled);
        // A radius just above the sampled minimum folds; well below the bound, not.
        s1.profile = sweep_profile::circle(1.01 * sampled);
        EXPECT_TRUE(sweep(cc, s1).report.local_fold) << "seed " << seed << " trial " << trial;
        s1.profile = sweep_profile::circle(0.5 * m.report.min_radius_of_curvature);
        EXPECT_FALSE(sweep(cc, s1).report.local_fold) << "seed " << seed << " trial " << trial;
    }
    std::printf("radius of curvature: bound / sampled minimum at least %.3f\n", loosest);
    options<3> o;
    o.closed = true;
    const catmull_rom<3> c(torus_knot(12), o);
    sweep_options so;
    so.profile = sweep_profile::circle(0.1);
    const auto thin = sweep(c, so);
    EXPECT_FALSE(thin.report.self_intersects);
    EXPECT_GT(thin.report.clearance, 0.2);
    so.profile = sweep_profile::circle(0.8);
    const auto thick = sweep(c, so);
    EXPECT_TRUE(thick.report.far_contact);
    EXPECT_TRUE(thick.report.self_intersects);
    so.profile = sweep_profile::circle(1.01 * sampled_min_radius(c));
    EXPECT_TRUE(sweep(c, so).report.local_fold);
}

// Polyline and curve profiles: vertex counts and outward normals.
TEST(Sweep, ProfilesOfEveryKind) {
    const catmull_rom<3> c(std::vector<v3>{{{0, 0, 0}}, {{1, 0.2, 0}}, {{2, 0, 0.3}}, {{3, 0.1, 0}}});
    sweep_options so;
    so.profile = sweep_profile::polyline({{{-0.1, 0}}, {{0.1, 0}}}, false);  // a ribbon
    const auto ribbon = sweep(c, so);
    EXPECT_EQ(ribbon.ring_size, 2u);
    so.profile = sweep_profile::polyline({{{-0.1, -0.1}}, {{0.1, -0.1}}, {{0.1, 0.1}}, {{-0.1, 0.1}}}, true);
    const auto box = sweep(c, so);
    EXPECT_EQ(box.ring_size, 5u);
    so.profile = sweep_profile::curve({{{0.1, 0}}, {{0, 0.05}}, {{-0.1, 0}}, {{0, -0.05}}}, true);
    const auto oval = sweep(c, so);
    EXPECT_GT(oval.ring_size, 8u);
    // Outward: each normal points away from the centre line.
    for (const auto* m : {&box, &oval})
        for (std::size_t k = 0; k < m->rings; ++k)
            for (std::size_t j = 0; j < m->ring_size; ++j)
                EXPECT_GT(dot(normal_at(*m, k, j), vertex(*m, k, j) - c.evaluate(m->t[k])), 0.0);
}
