// Shared helpers for crspline's C++ tests: seeded generators that report
// their seed, random control polygons, and scale-aware comparisons.
#pragma once

#include <gtest/gtest.h>

#include <crspline/crspline.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace crspline::test {

/// Constants many test files use; each file names them with a
/// using-declaration (allowed more than once in one translation unit, as a
/// unity build makes one of a folder's files).
inline constexpr double eps = std::numeric_limits<double>::epsilon();
inline constexpr double pi = std::numbers::pi;
inline constexpr double alphas[] = {0.0, 0.25, 0.5, 0.75, 1.0};

/// Seed for a property test: CRSPLINE_SEED from the environment, or the
/// given default. Reported through SCOPED_TRACE on every failure.
inline std::uint64_t seed(std::uint64_t fallback) {
    if (const char* s = std::getenv("CRSPLINE_SEED")) return std::strtoull(s, nullptr, 10);
    return fallback;
}

#define CRSPLINE_SEEDED(var, fallback)                     \
    const std::uint64_t var = ::crspline::test::seed(fallback); \
    SCOPED_TRACE("seed " + std::to_string(var) + " (rerun with CRSPLINE_SEED=" + std::to_string(var) + ")")

/// Random control polygon: a walk with uneven steps (lengths spread over
/// `decades` orders of magnitude) and random turns, so parameterizations
/// really differ.
template <std::size_t D, class T = double>
std::vector<vec<D, T>> random_polygon(std::mt19937_64& rng, std::size_t n, double decades = 2.0,
                                      double offset = 0.0) {
    std::normal_distribution<double> g(0.0, 1.0);
    std::uniform_real_distribution<double> e(-decades / 2, decades / 2);
    std::vector<vec<D, T>> p(n);
    vec<D, double> x{};
    for (std::size_t k = 0; k < D; ++k) x[k] = offset + g(rng);
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t k = 0; k < D; ++k) p[i][k] = T(x[k]);
        vec<D, double> step;
        for (std::size_t k = 0; k < D; ++k) step[k] = g(rng);
        const double len = std::pow(10.0, e(rng));
        const double nn = norm(step);
        for (std::size_t k = 0; k < D; ++k) x[k] += nn > 0 ? step[k] / nn * len : len;
    }
    return p;
}

/// Bounding-box diagonal of a point set: the length scale of a curve.
template <std::size_t D, class T>
T scale_of(const std::vector<vec<D, T>>& p) {
    vec<D, T> lo = p.front(), hi = p.front();
    for (const auto& q : p)
        for (std::size_t k = 0; k < D; ++k) { lo[k] = std::min(lo[k], q[k]); hi[k] = std::max(hi[k], q[k]); }
    return norm(hi - lo);
}

template <std::size_t D, class T>
T distance(const vec<D, T>& a, const vec<D, T>& b) { return norm(a - b); }

// CRSPLINE_PROPERTY_SCALE (default 1: the full run) multiplies the random
// case counts. Below 1 the minimum-count checks are off, and the run says so
// on stderr: a reduced run must never pass for a full one.
inline double property_scale() {
    const char* s = std::getenv("CRSPLINE_PROPERTY_SCALE");
    if (!s) return 1.0;
    char* end = nullptr;
    const double x = std::strtod(s, &end);
    if (end == s || *end != '\0' || !(x > 0) || !std::isfinite(x))
        throw std::invalid_argument(std::string("CRSPLINE_PROPERTY_SCALE: expected a number > 0, got '") + s + "'");
    static const bool said = x < 1 && std::fprintf(stderr,
        "note: CRSPLINE_PROPERTY_SCALE=%s: a REDUCED run, the minimum-count checks are off\n", s) > 0;
    (void)said;
    return std::max(0.01, x);
}

// A polygon whose turn at every vertex is at most max_turn (so polygon angles
// are at least pi - max_turn), with step lengths over `decades`.
template <std::size_t D>
std::vector<vec<D>> smooth_polygon(std::mt19937_64& rng, std::size_t n, double max_turn, double decades) {
    std::uniform_real_distribution<double> U(0.0, 1.0);
    std::normal_distribution<double> G(0.0, 1.0);
    std::vector<vec<D>> p(n);
    vec<D> dir{};
    for (std::size_t k = 0; k < D; ++k) dir[k] = G(rng);
    dir = dir / norm(dir);
    for (std::size_t i = 1; i < n; ++i) {
        // Rotate dir by a random angle <= max_turn in a random plane.
        vec<D> r{};
        for (std::size_t k = 0; k < D; ++k) r[k] = G(rng);
        r = r - dot(r, dir) * dir;
        if (norm(r) > 0) r = r / norm(r);
        const double t = max_turn * (2 * U(rng) - 1);
        dir = std::cos(t) * dir + std::sin(t) * r;
        p[i] = p[i - 1] + std::pow(10.0, decades * (U(rng) - 0.5)) * dir;
    }
    return p;
}

}  // namespace crspline::test
