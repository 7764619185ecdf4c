// The benchmarks' input: one definition for crspline_bench, the callgrind
// driver and the construction rusage probe, so that all three measure the
// same curve.
#pragma once

#include <crspline/vec.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace crspline_bench {

inline constexpr std::uint64_t seed = 20240601;

/// A 3-D random walk with uneven steps: unit directions, step lengths
/// log-normal (exp of a standard normal, so consecutive chords differ by
/// factors up to ~50). Seeded: the same curve on every run.
template <class T = double>
std::vector<crspline::vec<3, T>> walk(std::size_t n, std::uint64_t s = seed) {
    std::mt19937_64 rng(s);
    std::normal_distribution<double> g(0.0, 1.0);
    std::vector<crspline::vec<3, T>> p(n);
    crspline::vec<3, double> x{};
    for (std::size_t i = 0; i < n; ++i) {
        p[i] = {{T(x[0]), T(x[1]), T(x[2])}};
        crspline::vec<3, double> d{{g(rng), g(rng), g(rng)}};
        x += (std::exp(g(rng)) / crspline::norm(d)) * d;
    }
    return p;
}

}  // namespace crspline_bench
