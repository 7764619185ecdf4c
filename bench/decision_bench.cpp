// crspline benchmarks: the crossing decision (issue 27) at 10^3 to 10^6
// segments, to show how it scales (bench/report.py fits the exponent of
// time against segments; the goal is <= 1.15, as certify's and
// find_intersections' are), and the set form on 10^3 to 10^5 curves of 20
// points each.
//
// Inputs: the certified centripetal Archimedean spiral of
// intersections_bench.cpp (chords about 1, turns 4 apart): `decide` takes
// the fast path there (the paper's certificate; goal: at most 1.5x
// certify), `decide_full` skips it and proves every pair; the same spiral
// with uniform knots (not certifiable: the decision proves it); and a set
// of short centripetal walks on a grid, neighbours overlapping so that some
// pairs cross. Each case reports items_per_second in segments and what it
// decided as counters. `decide_certify` is the baseline of the fast path:
// the paper's certificate alone on the same spiral, in the same run (its
// result held in an int: intersections_bench.cpp's `certify` hands a bool
// to DoNotOptimize, which valgrind sees read uninitialised and which
// sometimes reports "the spiral should be certified" when it is).
// `decide_walk`: a 2-D random walk of unit normal steps, whose crossings
// grow like n log n (about 2 per point at 10^5): the case that was
// quadratic in the crossings.
#include <crspline/catmull_rom.hpp>
#include <crspline/certify.hpp>
#include <crspline/decision.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

namespace {

using curve2 = crspline::catmull_rom<2, double>;
using P = crspline::vec<2, double>;

std::vector<P> decision_spiral(std::size_t points) {
    std::vector<P> p(points);
    double theta = 0;
    for (std::size_t i = 0; i < points; ++i) {
        const double r = 10 + 4 * theta / (2 * std::numbers::pi);
        p[i] = {{r * std::cos(theta), r * std::sin(theta)}};
        theta += 1 / r;
    }
    return p;
}

const curve2& spiral_of(std::size_t segments, double alpha) {
    static std::map<std::pair<std::size_t, double>, std::unique_ptr<curve2>> cache;
    auto& c = cache[{segments, alpha}];
    if (!c) c = std::make_unique<curve2>(decision_spiral(segments + 1), crspline::options<2>{.alpha = alpha});
    return *c;
}

void run_decide(benchmark::State& state, const curve2& c, bool fast_path) {
    crspline::decision d;
    for (auto _ : state) {
        d = crspline::decide(c, {.fast_path = fast_path, .record_pairs = false});
        benchmark::DoNotOptimize(d.result);
    }
    state.counters["simple"] = d.result == crspline::verdict::simple;
    state.counters["fast_path"] = d.fast_path;
    state.counters["pieces"] = double(d.pieces);
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(c.segment_count()));
}

void decide_certify(benchmark::State& state) {
    const curve2& c = spiral_of(std::size_t(state.range(0)), 0.5);
    crspline::certify_options co;
    co.search_on_failure = false;  // as decide's fast path runs it
    int certified = 0;
    for (auto _ : state) {
        certified = crspline::certify_intersection_free(c, co).certified ? 1 : 0;
        benchmark::DoNotOptimize(certified);
    }
    state.counters["certified"] = certified;
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(c.segment_count()));
}

const curve2& walk_of(std::size_t points) {
    static std::map<std::size_t, std::unique_ptr<curve2>> cache;
    auto& c = cache[points];
    if (!c) {
        std::mt19937_64 rng(27);
        std::normal_distribution<double> g(0.0, 1.0);
        std::vector<P> p(points);
        for (std::size_t i = 1; i < points; ++i) p[i] = p[i - 1] + P{{g(rng), g(rng)}};
        c = std::make_unique<curve2>(p, crspline::options<2>{.alpha = 0.5});
    }
    return *c;
}

void decide_walk(benchmark::State& state) {
    const curve2& c = walk_of(std::size_t(state.range(0)));
    crspline::decision d;
    for (auto _ : state) {
        d = crspline::decide(c, {.record_pairs = false});
        benchmark::DoNotOptimize(d.result);
    }
    state.counters["crossings"] = double(d.crossings.size());
    state.counters["touches"] = double(d.touches.size());
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(c.segment_count()));
}

void decide_fast(benchmark::State& state) { run_decide(state, spiral_of(std::size_t(state.range(0)), 0.5), true); }
void decide_full(benchmark::State& state) { run_decide(state, spiral_of(std::size_t(state.range(0)), 0.5), false); }
void decide_uniform(benchmark::State& state) { run_decide(state, spiral_of(std::size_t(state.range(0)), 0.0), true); }

/// `count` centripetal walks of 20 points, each within about 1.5 of its
/// grid cell's centre, cells 2 apart: neighbours sometimes cross.
const std::vector<curve2>& walk_set(std::size_t count) {
    static std::map<std::size_t, std::vector<curve2>> cache;
    auto& s = cache[count];
    if (s.empty()) {
        std::mt19937_64 rng(27);
        std::normal_distribution<double> g(0.0, 0.25);
        const auto side = std::size_t(std::ceil(std::sqrt(double(count))));
        for (std::size_t i = 0; i < count; ++i) {
            std::vector<P> p(20);
            p[0] = {{2.0 * double(i % side), 2.0 * double(i / side)}};
            for (std::size_t k = 1; k < p.size(); ++k) p[k] = p[k - 1] + P{{g(rng), g(rng)}};
            s.emplace_back(p);
        }
    }
    return s;
}

void decide_set(benchmark::State& state) {
    const auto& s = walk_set(std::size_t(state.range(0)));
    crspline::decision d;
    for (auto _ : state) {
        d = crspline::decide(std::span<const curve2>(s), false, {.record_pairs = false});
        benchmark::DoNotOptimize(d.result);
    }
    state.counters["crossings"] = double(d.crossings.size());
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(s.size() * 19));
}

}  // namespace

BENCHMARK(decide_certify)->Name("decide_certify")->Arg(1000)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(decide_walk)->Name("decide_walk")->Arg(1000)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond);
BENCHMARK(decide_fast)->Name("decide")->Arg(1000)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(decide_full)->Name("decide_full")->Arg(1000)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(decide_uniform)
    ->Name("decide_uniform_spiral")
    ->Arg(1000)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Arg(1'000'000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(decide_set)->Name("decide_set")->Arg(1000)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond);
