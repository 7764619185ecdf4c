// An up vector through the poles (sweep/rings.hpp): the mesh against an
// independent surface on the frame the sweep promises there. Outside the
// cones within 5 degrees of up the normal is up's projection; where the
// tangent is inside one (its ends found here by bisection on a dense
// sampling, not by the library's root finder) the frame is the
// rotation-minimizing one of frames.hpp carried on a dense grid from the
// projection where the tangent enters, turned by Delta sigma(x), sigma(x) =
// 3 x^2 - 2 x^3, onto the projection (or its opposite, the nearer) where it
// leaves; an open curve ending in a cone keeps the carried frame, a closed
// one turns onto its first ring's normal.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "sweep_support.hpp"

using namespace crspline;
using namespace sweep_test;

namespace {

const v3 pole_up{{0, 0, 1}};
const double pole_sin = std::sin(5 * std::numbers::pi / 180);

double pole_excess(const catmull_rom<3>& c, double t) {  // > 0 outside the cone
    const v3 d = c.evaluate(t, 1);
    return norm(cross3(pole_up, d)) - pole_sin * norm(d);
}

/// The cone's stretches [t_in, t_out] (t_min / t_max where the curve starts
/// or ends in one), from 20,000 samples and bisection.
std::vector<std::array<double, 2>> pole_zones(const catmull_rom<3>& c) {
    std::vector<std::array<double, 2>> zones;
    const int n = 20000;
    const double a = c.t_min(), b = c.t_max();
    double prev_t = a;
    bool inside = pole_excess(c, a) < 0;
    double t_in = a;
    for (int k = 1; k <= n; ++k) {
        const double t = k == n ? b : a + (b - a) * k / n;
        const bool in = pole_excess(c, t) < 0;
        if (in != inside) {
            double lo = prev_t, hi = t;
            for (int it = 0; it < 100; ++it) {
                const double mid = (lo + hi) / 2;
                ((pole_excess(c, mid) < 0) == inside ? lo : hi) = mid;
            }
            const double root = (lo + hi) / 2;
            if (inside) zones.push_back({t_in, root});
            else t_in = root;
            inside = in;
        }
        prev_t = t;
    }
    if (inside) zones.push_back({t_in, b});
    return zones;
}

v3 pole_projection(const v3& e) {
    const v3 p = pole_up - dot(pole_up, e) * e;
    return p / norm(p);
}

}  // namespace

TEST(SweepPoles, UpVectorMeshIsWithinTheToleranceThroughThePoles) {
    CRSPLINE_SEEDED(seed, 5353);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    double worst = 0;
    std::size_t checked = 0, in_zones = 0, zones_crossed = 0;
    for (int trial = 0; trial < 6; ++trial) {
        std::vector<v3> pts;
        options<3> o;
        if (trial < 2) {  // vertical loops drifting sideways: open, then closed
            const int n = trial == 0 ? 16 : 12;
            for (int k = 0; k < n; ++k) {
                const double a = 2 * std::numbers::pi * k / n;
                pts.push_back({{std::sin(a) + (trial == 0 ? 0.3 * a : 0.0), 0.02 * std::sin(3 * a), 1 - std::cos(a)}});
            }
            o.closed = trial == 1;
        } else {  // steep random curves
            for (auto p : random_points(rng, 7)) pts.push_back({{0.3 * p[0], 0.3 * p[1], 2 * p[2]}});
            o.closed = trial % 2 == 1;
        }
        const catmull_rom<3> c(pts, o);
        const auto zones = pole_zones(c);
        sweep_options so;
        const double radius = 0.03 + 0.05 * unit(rng);
        so.profile = sweep_profile::circle(radius);
        so.up = pole_up;
        so.tolerance = trial % 3 == 0 ? 1e-3 : 3e-4;
        const auto m = sweep(c, so);
        ASSERT_TRUE(m.report.proved) << "seed " << seed << ", trial " << trial;
        ASSERT_TRUE(m.report.tolerance_met) << "seed " << seed << ", trial " << trial;
        ASSERT_LE(m.report.bound, so.tolerance * (1 + 1e-12));
        // Samples: ring interval, profile edge, triangle point (as the
        // other surface tests); each zone's reference frame on a dense grid
        // with the samples inside it.
        struct sample {
            std::size_t k, j;
            bool tri0;
            double l, mu, t;
            int zone;
        };
        std::vector<sample> ss;
        const std::size_t n = m.ring_size - 1;
        for (int q = 0; q < 3000; ++q) {
            sample s{};
            s.k = std::size_t(unit(rng) * double(m.rings - 1)), s.j = std::size_t(unit(rng) * double(n));
            s.l = unit(rng), s.mu = unit(rng), s.tri0 = unit(rng) < 0.5;
            s.t = m.t[s.k] + s.l * (m.t[s.k + 1] - m.t[s.k]);
            s.zone = -1;
            for (std::size_t z = 0; z < zones.size(); ++z)
                if (zones[z][0] < s.t && s.t < zones[z][1]) s.zone = int(z);
            ss.push_back(s);
        }
        // The first ring's normal (a closed curve's last zone turns onto it).
        const v3 n0 = (mesh_vertex(m, 0, 0) - c.evaluate(m.t[0])) / (radius * 1.0);
        std::vector<std::vector<std::pair<double, v3>>> zone_normals(zones.size());
        for (std::size_t z = 0; z < zones.size(); ++z) {
            const double a = zones[z][0], b = zones[z][1];
            std::vector<double> ts;
            for (int k = 0; k <= 20000; ++k) ts.push_back(k == 20000 ? b : a + (b - a) * k / 20000.0);
            for (const auto& s : ss)
                if (s.zone == int(z)) ts.push_back(s.t);
            std::sort(ts.begin(), ts.end());
            const v3 ea = c.evaluate(a, 1) / norm(c.evaluate(a, 1));
            // The entry frame: the projection (the sign of the nearest ring's
            // normal), or ring 0's where the curve starts in the cone.
            v3 entry = a == c.t_min() ? n0 : pole_projection(ea);
            if (a > c.t_min()) {
                std::size_t k = 0;
                while (k + 1 < m.rings && m.t[k + 1] <= a + 1e-12) ++k;
                if (dot(entry, mesh_vertex(m, k, 0) - c.evaluate(m.t[k])) < 0) entry = -1.0 * entry;
            }
            const auto fr = rotation_minimizing_frames(c, std::span<const double>(ts), entry);
            const v3 eb = fr.back().tangent, nb = fr.back().normal;
            double delta = 0;
            if (b < c.t_max() || o.closed) {
                const v3 target = b < c.t_max() ? pole_projection(eb) : n0;
                delta = std::atan2(dot(cross3(nb, target), eb), dot(nb, target));
                if (b < c.t_max()) delta -= std::numbers::pi * std::round(delta / std::numbers::pi);  // the nearer of +-
            }
            for (std::size_t k = 0; k < ts.size(); ++k) {
                const double x = (ts[k] - a) / (b - a), psi = delta * x * x * (3 - 2 * x);
                const v3 e = fr[k].tangent, nn = fr[k].normal;
                zone_normals[z].push_back({ts[k], std::cos(psi) * nn + std::sin(psi) * cross3(e, nn)});
            }
            ++zones_crossed;
        }
        for (const auto& s : ss) {
            const double l = s.l, mu = s.mu;
            v3 mp;
            double wj, wj1;
            if (s.tri0) {
                mp = (1 - l) * mu * mesh_vertex(m, s.k, s.j) + (1 - l) * (1 - mu) * mesh_vertex(m, s.k, s.j + 1) +
                     l * mesh_vertex(m, s.k + 1, s.j);
                wj = (1 - l) * mu + l, wj1 = (1 - l) * (1 - mu);
            } else {
                mp = (1 - l) * mesh_vertex(m, s.k, s.j + 1) + l * mu * mesh_vertex(m, s.k + 1, s.j + 1) +
                     l * (1 - mu) * mesh_vertex(m, s.k + 1, s.j);
                wj = l * (1 - mu), wj1 = (1 - l) + l * mu;
            }
            const double a0 = 2 * std::numbers::pi * double(s.j) / double(n), a1 = 2 * std::numbers::pi * double(s.j + 1) / double(n);
            const vec<2> pb{{wj * std::cos(a0) + wj1 * std::cos(a1), wj * std::sin(a0) + wj1 * std::sin(a1)}};
            const vec<2> pc = pb / norm(pb);
            const v3 e = c.evaluate(s.t, 1) / norm(c.evaluate(s.t, 1));
            v3 nn;
            if (s.zone >= 0) {
                const auto& zn = zone_normals[std::size_t(s.zone)];
                const auto it = std::lower_bound(zn.begin(), zn.end(), s.t, [](const auto& p, double t) { return p.first < t; });
                nn = it->second;
                ++in_zones;
            } else {
                nn = pole_projection(e);
                if (dot(nn, mesh_vertex(m, s.k, 0) - c.evaluate(m.t[s.k])) < 0) nn = -1.0 * nn;
            }
            const v3 sp = c.evaluate(s.t) + radius * (pc[0] * nn + pc[1] * cross3(e, nn));
            worst = std::max(worst, norm(sp - mp) / so.tolerance);
            ++checked;
        }
    }
    EXPECT_EQ(checked, 6u * 3000u);
    EXPECT_GE(zones_crossed, 6u) << "seed " << seed;  // the loops cross two cones each, the steep curves some
    EXPECT_GE(in_zones, 300u) << "seed " << seed;
    EXPECT_LE(worst, 1.0) << "seed " << seed;
    EXPECT_GT(worst, 0.1) << "seed " << seed;  // the bound is not wildly loose
    std::printf("up through the poles: largest distance over the tolerance %.3f (%zu samples, %zu in %zu cones)\n", worst,
                checked, in_zones, zones_crossed);
}
