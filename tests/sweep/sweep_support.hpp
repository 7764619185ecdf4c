// Helpers of the sweep tests: random curves and an independent reference
// surface (frames from frames.hpp on a dense grid, the roll from the
// rotation spline's own evaluate(), the scale from a 1-D curve).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <random>
#include <vector>

#include <crspline/arc_length.hpp>
#include <crspline/frames.hpp>
#include <crspline/rotation/catmull_rom.hpp>
#include <crspline/sweep.hpp>

#include "test_support.hpp"

namespace sweep_test {

using crspline::vec;
using v3 = vec<3>;

inline v3 cross3(const v3& a, const v3& b) {
    return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

/// A (p, q) torus knot through n points.
inline std::vector<v3> torus_knot(std::size_t n, int p = 2, int q = 3) {
    std::vector<v3> pts;
    for (std::size_t k = 0; k < n; ++k) {
        const double a = 2 * std::numbers::pi * double(k) / double(n);
        pts.push_back({{(2 + std::cos(q * a)) * std::cos(p * a), (2 + std::cos(q * a)) * std::sin(p * a), std::sin(q * a)}});
    }
    return pts;
}

/// Random points in a unit-ish box, far enough apart.
inline std::vector<v3> random_points(std::mt19937_64& rng, std::size_t n) {
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<v3> pts;
    while (pts.size() < n) {
        const v3 p{{u(rng), u(rng), u(rng)}};
        if (!pts.empty() && crspline::norm(p - pts.back()) < 0.3) continue;
        pts.push_back(p);
    }
    return pts;
}

/// Vertex j of ring k of a sweep's mesh.
inline v3 mesh_vertex(const crspline::sweep_mesh& m, std::size_t k, std::size_t j) {
    const double* p = m.positions.data() + 3 * (k * m.ring_size + j);
    return {{p[0], p[1], p[2]}};
}

/// The roll by the rotation spline itself, at w.
struct reference_roll {
    std::optional<crspline::rotation::quaternion_spline<double>> spline;
    double lo = 0, hi = 0;
    bool periodic = false;
    reference_roll(const std::vector<double>& w, const std::vector<double>& theta, std::optional<double> period) {
        if (theta.size() < 2) return;
        std::vector<crspline::rotation::quaternion<double>> keys;
        for (double a : theta) keys.push_back({std::cos(a / 2), 0, 0, std::sin(a / 2)});
        crspline::rotation::rotation_options<double> opt;
        std::vector<double> g = w;
        if (period) g.push_back(w.front() + *period);
        opt.grid = g;
        opt.closed = period.has_value();
        spline.emplace(std::span<const crspline::rotation::quaternion<double>>(keys), opt);
        lo = g.front(), hi = g.back(), periodic = opt.closed;
    }
    double operator()(double w) const {
        if (!spline) return 0;
        if (periodic) {
            w = std::fmod(w - lo, hi - lo);
            if (w < 0) w += hi - lo;
            w += lo;
        }
        w = std::clamp(w, lo, hi);
        const auto q = (*spline)(w);
        return 2 * std::atan2(q.z, q.w);
    }
};

}  // namespace sweep_test
