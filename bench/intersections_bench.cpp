// crspline benchmarks: the whole-curve intersection search and the
// Section 5 certificate at 10^3 to 10^6 segments, to show how they scale
// (bench/report.py fits the exponent of time against segments).
//
// Inputs: a 2-D Archimedean spiral (chords of about 1, 4 apart between
// turns, starting at radius 10), which is intersection-free and certified,
// so the certificate runs all three rules to the end and the search finds
// nothing (k = 0); a 2-D zigzag, the 3-D random walk of the other cases
// (bench/walk.hpp) and its 2-D projection for find_intersections at 10^5
// points. Each case reports
// items_per_second in segments, and what it found as counters.
#include <crspline/catmull_rom.hpp>
#include <crspline/certify.hpp>
#include <crspline/intersections.hpp>

#include <benchmark/benchmark.h>

#include "walk.hpp"

#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <numbers>
#include <vector>

namespace {

using curve2 = crspline::catmull_rom<2, double>;
using curve3 = crspline::catmull_rom<3, double>;

/// An Archimedean spiral r = 10 + 4 theta / (2 pi) through `points` points
/// about 1 apart.
std::vector<crspline::vec<2, double>> spiral(std::size_t points) {
    std::vector<crspline::vec<2, double>> p(points);
    double theta = 0;
    for (std::size_t i = 0; i < points; ++i) {
        const double r = 10 + 4 * theta / (2 * std::numbers::pi);
        p[i] = {{r * std::cos(theta), r * std::sin(theta)}};
        theta += 1 / r;
    }
    return p;
}

/// A zigzag along x: (i, i mod 2).
std::vector<crspline::vec<2, double>> zigzag(std::size_t points) {
    std::vector<crspline::vec<2, double>> p(points);
    for (std::size_t i = 0; i < points; ++i) p[i] = {{double(i), double(i % 2)}};
    return p;
}

/// The spiral with `segments` segments, built once per size.
const curve2& spiral_curve(std::size_t segments) {
    static std::map<std::size_t, std::unique_ptr<curve2>> cache;
    auto& c = cache[segments];
    if (!c) c = std::make_unique<curve2>(spiral(segments + 1));
    return *c;
}

void certify(benchmark::State& state) {
    const curve2& c = spiral_curve(std::size_t(state.range(0)));
    // An int, not a bool: libbenchmark 1.7.1's DoNotOptimize hands a bool to
    // an asm that may rewrite it (valgrind: "depends on uninitialised
    // value"), and the check below then failed at random.
    int certified = 0;
    for (auto _ : state) {
        const auto cert = crspline::certify_intersection_free(c);
        certified = cert.certified ? 1 : 0;
        benchmark::DoNotOptimize(certified);
    }
    if (!certified) state.SkipWithError("the spiral should be certified");
    state.counters["certified"] = certified;
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(c.segment_count()));
}

template <class Curve>
void run_find(benchmark::State& state, const Curve& c) {
    std::size_t meetings = 0;
    bool complete = true;
    for (auto _ : state) {
        const auto r = crspline::find_intersections(c);
        meetings = r.intersections.size() + r.folds.size();
        complete = r.complete;
        benchmark::DoNotOptimize(meetings);
    }
    state.counters["meetings"] = double(meetings);
    state.counters["complete"] = complete;
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(c.segment_count()));
}

void find_spiral(benchmark::State& state) { run_find(state, spiral_curve(std::size_t(state.range(0)))); }

void find_zigzag(benchmark::State& state) {
    const curve2 c(zigzag(std::size_t(state.range(0)) + 1));
    run_find(state, c);
}

void find_walk(benchmark::State& state) {
    const curve3 c(crspline_bench::walk(std::size_t(state.range(0)) + 1));
    run_find(state, c);
}

/// The walk seen from above (x, y): about one crossing per segment, most of
/// them transversal (issue 26: the case of crspline analyze --summary).
void find_walk2d(benchmark::State& state) {
    const auto w = crspline_bench::walk(std::size_t(state.range(0)) + 1);
    std::vector<crspline::vec<2, double>> p(w.size());
    for (std::size_t i = 0; i < w.size(); ++i) p[i] = {{w[i][0], w[i][1]}};
    const curve2 c(p);
    run_find(state, c);
}

}  // namespace

BENCHMARK(certify)->Name("certify")->Arg(1000)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(find_spiral)
    ->Name("find_intersections")
    ->Arg(1000)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Arg(1'000'000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(find_zigzag)->Name("find_intersections_zigzag")->Arg(100'000)->Unit(benchmark::kMillisecond);
BENCHMARK(find_walk)->Name("find_intersections_walk")->Arg(100'000)->Unit(benchmark::kMillisecond);
BENCHMARK(find_walk2d)->Name("find_intersections_walk2d")->Arg(100'000)->Unit(benchmark::kMillisecond);
