// The ring frames' drift from the exact rotation-minimizing frame
// (sweep/drift.hpp): the reported bound holds against a reference frame
// carried over 200,000 samples, it is far tighter than what the double
// reflection turns against the minimal rotation (so the enclosure of the
// exact turn does the work), and the sweep's bound includes it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "sweep_support.hpp"

using namespace crspline;
using namespace sweep_test;

namespace {

double drift_angle(const v3& a, const v3& b) { return std::atan2(norm(cross3(a, b)), dot(a, b)); }

/// Ring k's frame normal: profile vertex 0 is the circle's point (r, 0).
v3 drift_ring_normal(const sweep_mesh& m, const catmull_rom<3>& c, std::size_t k) {
    const double* p = m.positions.data() + 3 * k * m.ring_size;
    const v3 d = v3{{p[0], p[1], p[2]}} - c.evaluate(m.t[k]);
    return d / norm(d);
}

/// v carried by the minimal rotation from unit a to unit b (Rodrigues).
v3 drift_minimal_rotation(const v3& a, const v3& b, const v3& v) {
    const v3 k = cross3(a, b);
    const double s = norm(k), c = dot(a, b);
    if (s == 0) return v;
    const v3 u = k / s;
    const double th = std::atan2(s, c);
    return std::cos(th) * v + std::sin(th) * cross3(u, v) + (1 - std::cos(th)) * dot(u, v) * u;
}

}  // namespace

TEST(SweepDrift, BoundsTheExactRotationMinimizingFrame) {
    CRSPLINE_SEEDED(seed, 4242);
    std::mt19937_64 rng(seed);
    int checked = 0, coarse = 0, unproved = 0;
    double worst_ratio = 0, tightest = 0, largest_share = 0;
    for (int trial = 0; trial < 9; ++trial) {
        options<3> o;
        o.closed = trial % 2 == 0;
        o.alpha = trial % 3 == 0 ? 0.5 : (trial % 3 == 1 ? 0.0 : 1.0);
        const catmull_rom<3> c(trial == 0 ? torus_knot(12) : random_points(rng, 5 + std::size_t(trial % 4)), o);
        for (int mode = 0; mode < 3; ++mode) {
            sweep_options so;
            so.profile = sweep_profile::circle(0.1);
            if (mode == 0) so.tolerance = 1e-2;
            if (mode == 1) so.tolerance = 1e-4;
            if (mode == 2) so.tubular_segments = 8 * c.segment_count(), so.radial_segments = 8;  // coarse rings
            const auto m = sweep(c, so);
            const double drift = m.report.frame_drift;
            ASSERT_GT(drift, 0.0) << "trial " << trial << " mode " << mode;
            // The sweep's bound carries the drift times the radius.
            EXPECT_GE(m.report.bound, 0.1 * drift) << "trial " << trial << " mode " << mode;
            if (!std::isfinite(drift)) {  // a step too coarse to enclose: the bound says not proved
                ++unproved;
                continue;
            }
            // The reference: frames.hpp's double reflection on 200,000 samples
            // plus the rings (its own error, fourth order in a step that
            // turns the tangent by ~1e-4 radians, is below 1e-15 per step;
            // its rounding, a few ulps a step, stays below 1e-10 in all),
            // from the first ring's normal, its holonomy spread like the sweep's.
            std::vector<double> ts(m.t.begin(), m.t.end());
            for (int k = 0; k <= 200000; ++k) ts.push_back(c.t_min() + (c.t_max() - c.t_min()) * k / 200000.0);
            std::sort(ts.begin(), ts.end());
            const auto fr = rotation_minimizing_frames(c, std::span<const double>(ts), drift_ring_normal(m, c, 0));
            double actual = 0, turn = 0;
            for (std::size_t k = 0; k < m.rings; ++k) {
                const auto& f = fr[std::size_t(std::lower_bound(ts.begin(), ts.end(), m.t[k]) - ts.begin())];
                actual = std::max(actual, drift_angle(drift_ring_normal(m, c, k), f.normal));
                if (k > 0 && !o.closed) {  // what the rings turn against the minimal rotation, summed
                    const v3 a = c.evaluate(m.t[k - 1], 1), b = c.evaluate(m.t[k], 1);
                    const v3 carried = drift_minimal_rotation(a / norm(a), b / norm(b), drift_ring_normal(m, c, k - 1));
                    turn += drift_angle(carried, drift_ring_normal(m, c, k));
                }
            }
            EXPECT_LE(actual, drift + 1e-10) << "trial " << trial << " mode " << mode << " seed " << seed;
            worst_ratio = std::max(worst_ratio, actual / drift);
            // Open curves: the bound is far below the triangle inequality's
            // sum of the turns against the minimal rotation (no enclosure:
            // what a wrong sign or a missing exact turn would give).
            if (!o.closed && mode < 2) {
                EXPECT_LT(drift, 0.2 * turn) << "trial " << trial << " mode " << mode;
                tightest = std::max(tightest, drift / turn);
            }
            // The drift's share of the bound: what placing the rings keeps
            // for it is a hundredth of the tolerance (more only by splitting).
            if (mode < 2) {
                const double share = m.report.largest_radius * drift * (o.closed ? 2 : 1) / so.tolerance;
                EXPECT_LT(share, 0.01) << "trial " << trial << " mode " << mode;
                largest_share = std::max(largest_share, share);
            }
            coarse += mode == 2;
            ++checked;
        }
    }
    // Only coarse rings may go unproved (at seed 4242: 3 of 9, where the
    // along bound is infinite as well: a step whose speed bound is not
    // positive).
    EXPECT_EQ(checked + unproved, 27);
    EXPECT_GE(coarse, 5);
    EXPECT_EQ(checked - coarse, 18);
    std::printf("frame drift: actual / bound at most %.3g; bound / summed turn at most %.3g; radius x bound / "
                "tolerance at most %.3g (%d sweeps, %d unproved)\n",
                worst_ratio, tightest, largest_share, checked, unproved);
}
