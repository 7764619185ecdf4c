// crspline benchmarks: the cost of a dimension known only at run time
// (issue 14, "any dimension at run time").
//
// The front ends (CLI, Python, WebAssembly) turn the input's dimension into
// a compile-time one with crspline::with_dimension (crspline/dispatch.hpp):
// 1..4 get a curve of exactly that dimension, 5..16 the one zero-padded
// catmull_rom<16>. Each case runs one operation two ways on the same curve:
//
//   dimension/<op>/native/<d>   catmull_rom<d> used directly (the fixed-D
//                               kernels a C++ user gets);
//   dimension/<op>/runtime/<d>  the front ends' path: a curve built from a
//                               crspline::curve_spec by with_dimension into a
//                               std::variant of the storage types (what the
//                               Python module holds), each call dispatched
//                               with std::visit, results cut back to d
//                               coordinates where the storage is wider;
//   dimension/<op>/pad8/<d>     the same with 5..8 padded to catmull_rom<8>
//                               instead of 16: a cheaper mapping, measured
//                               only (with_dimension does not use it).
//
// d = 2, 3 show that 2-D and 3-D stay on the fast path (the runtime case
// builds the very same catmull_rom<2>/<3>, so only the dispatch is added);
// d = 5, 7 measure the padding to 16. bench/report.py prints the ratios.
//
// Operations, per item:
//   construct      make_curve from the specification, per control point;
//   eval_scalar    one evaluate(t) per point (runtime: one std::visit per
//                  run of 10^5 points, as the CLI dispatches once per
//                  command; wide points cut to d coordinates), per point;
//   eval_batch     evaluate(span t, span out) over 10^5 sorted t (runtime:
//                  one visit per batch, then the first d coordinates copied
//                  out of the 16-wide points, as the front ends do), per point;
//   arc_length     arc_length(curve, 1e-12), per segment;
//   analyze        analyze(curve) (cusps, loops, chord distances, Bezier
//                  points), per segment;
//   intersections  find_intersections(curve) (the CLI's analyze runs it),
//                  per segment.
// Input: a seeded random walk of 1000 points with log-normal steps (as
// bench/walk.hpp, in d dimensions), centripetal knots. Every runtime case
// but construct and intersections reports vs_native, the largest difference
// from the native result, and fails unless it is 0 (dispatch.hpp promises
// the same numbers bit for bit).
#include <crspline/analysis.hpp>
#include <crspline/arc_length.hpp>
#include <crspline/catmull_rom.hpp>
#include <crspline/dispatch.hpp>
#include <crspline/intersections.hpp>
#include <crspline/spec.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <random>
#include <span>
#include <type_traits>
#include <variant>
#include <vector>

namespace {

using crspline::catmull_rom;
using crspline::vec;

constexpr std::size_t points_n = 1000;
constexpr std::size_t eval_n = 100'000;

/// The specification of a d-dimensional random walk of points_n points:
/// unit directions, log-normal step lengths, seeded.
const crspline::curve_spec& spec(std::size_t d) {
    static std::map<std::size_t, crspline::curve_spec> cache;
    auto& s = cache[d];
    if (s.dimension == 0) {
        std::mt19937_64 rng(20240601 + d);
        std::normal_distribution<double> g(0.0, 1.0);
        std::vector<double> x(d, 0.0), dir(d);
        s.dimension = d;
        for (std::size_t i = 0; i < points_n; ++i) {
            s.points.insert(s.points.end(), x.begin(), x.end());
            double n2 = 0;
            for (auto& v : dir) v = g(rng), n2 += v * v;
            const double step = std::exp(g(rng)) / std::sqrt(n2);
            for (std::size_t k = 0; k < d; ++k) x[k] += step * dir[k];
        }
        s.alpha = 0.5;
    }
    return s;
}

template <std::size_t D>
const catmull_rom<D, double>& native(std::size_t d) {
    static std::map<std::size_t, catmull_rom<D, double>> cache;
    auto it = cache.find(d);
    if (it == cache.end()) it = cache.emplace(d, crspline::make_curve<D>(spec(d))).first;
    return it->second;
}

/// What a front end holds: one of the storage types of with_dimension.
using runtime_curve = std::variant<catmull_rom<1, double>, catmull_rom<2, double>, catmull_rom<3, double>,
                                   catmull_rom<4, double>, catmull_rom<crspline::wide_dimension, double>>;

/// A mapping not taken (measured to see what it would save): 5..8 padded to 8.
using pad8_curve = std::variant<catmull_rom<8, double>>;

template <class V>
V make_runtime(const crspline::curve_spec& s) {
    if constexpr (std::is_same_v<V, pad8_curve>)
        return crspline::make_curve<8>(s);
    else
        return crspline::with_dimension(
            s.dimension, [&](auto dim) -> V { return crspline::make_curve<decltype(dim)::value>(s); },
            [](std::size_t) {});
}

template <class V = runtime_curve>
const V& runtime(std::size_t d) {
    static std::map<std::size_t, V> cache;
    auto it = cache.find(d);
    if (it == cache.end()) it = cache.emplace(d, make_runtime<V>(spec(d))).first;
    return it->second;
}

/// eval_n sorted parameters across the curve's domain.
const std::vector<double>& params(std::size_t d) {
    static std::map<std::size_t, std::vector<double>> cache;
    auto& t = cache[d];
    if (t.empty()) {
        const auto g = std::visit([](const auto& c) { return std::vector<double>(c.grid().begin(), c.grid().end()); },
                                  runtime<runtime_curve>(d));
        t.resize(eval_n);
        for (std::size_t k = 0; k < eval_n; ++k) t[k] = g.front() + (g.back() - g.front()) * double(k) / double(eval_n - 1);
    }
    return t;
}

/// Records vs_native and fails the case unless it is 0: dispatch.hpp promises
/// the padded curve's numbers bit for bit.
void check_native(benchmark::State& state, double diff) {
    state.counters["vs_native"] = diff;
    if (diff != 0) state.SkipWithError("the run-time path differs from catmull_rom<d> (vs_native != 0)");
}

double max_diff(std::span<const double> a, std::span<const double> b) {
    double m = 0;
    for (std::size_t k = 0; k < a.size(); ++k) m = std::max(m, std::abs(a[k] - b[k]));
    return m;
}

/// The native batch result, flat (n * d), the reference of vs_native.
template <std::size_t D>
std::vector<double> native_positions() {
    const auto& t = params(D);
    std::vector<vec<D, double>> out(t.size());
    native<D>(D).evaluate(std::span<const double>(t), std::span<vec<D, double>>(out));
    std::vector<double> flat;
    for (const auto& p : out) flat.insert(flat.end(), p.v.begin(), p.v.end());
    return flat;
}

/// The scalar loop, one instantiation per storage type, shared by the native
/// and the runtime cases (not inlined, so both run the same machine code and
/// differ only by the dispatch around it).
template <std::size_t S>
[[gnu::noinline]] void scalar_points(const catmull_rom<S, double>& c, std::span<const double> t,
                                     std::span<vec<S, double>> out) {
    for (std::size_t k = 0; k < t.size(); ++k) out[k] = c.evaluate(t[k]);
}

/// The same for a wide curve: each point cut to its first d coordinates.
template <std::size_t S>
[[gnu::noinline]] void scalar_cut(const catmull_rom<S, double>& c, std::span<const double> t, std::size_t d,
                                  std::span<double> flat) {
    for (std::size_t k = 0; k < t.size(); ++k) {
        const vec<S, double> p = c.evaluate(t[k]);
        std::copy_n(p.v.begin(), d, flat.begin() + std::ptrdiff_t(k * d));
    }
}

// ---------------------------------------------------------------------------
// Native cases: catmull_rom<D> directly.

template <std::size_t D>
void construct_native(benchmark::State& state) {
    const auto& s = spec(D);
    for (auto _ : state) {
        auto c = crspline::make_curve<D>(s);
        benchmark::DoNotOptimize(c);
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * points_n));
}

template <std::size_t D>
void eval_scalar_native(benchmark::State& state) {
    const auto& c = native<D>(D);
    const auto& t = params(D);
    std::vector<vec<D, double>> out(t.size());
    for (auto _ : state) {
        scalar_points<D>(c, std::span<const double>(t), std::span<vec<D, double>>(out));
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * t.size()));
}

template <std::size_t D>
void eval_batch_native(benchmark::State& state) {
    const auto& c = native<D>(D);
    const auto& t = params(D);
    std::vector<vec<D, double>> out(t.size());
    for (auto _ : state) {
        c.evaluate(std::span<const double>(t), std::span<vec<D, double>>(out));
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * t.size()));
}

template <std::size_t D>
void arc_length_native(benchmark::State& state) {
    const auto& c = native<D>(D);
    for (auto _ : state) benchmark::DoNotOptimize(crspline::arc_length(c, 1e-12));
    state.SetItemsProcessed(std::int64_t(state.iterations() * c.segment_count()));
}

template <std::size_t D>
void analyze_native(benchmark::State& state) {
    const auto& c = native<D>(D);
    for (auto _ : state) {
        auto a = crspline::analyze(c);
        benchmark::DoNotOptimize(a.data());
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * c.segment_count()));
}

template <std::size_t D>
void intersections_native(benchmark::State& state) {
    const auto& c = native<D>(D);
    std::size_t found = 0;
    for (auto _ : state) {
        const auto r = crspline::find_intersections(c);
        found = r.intersections.size() + r.folds.size();
        benchmark::DoNotOptimize(found);
    }
    state.counters["meetings"] = double(found);
    state.SetItemsProcessed(std::int64_t(state.iterations() * c.segment_count()));
}

// ---------------------------------------------------------------------------
// Runtime cases: the front ends' variant, dimension state.range(0).

/// The native result for dimension d, by a switch over the dimensions run.
template <class F>
auto native_for(std::size_t d, F f) {
    switch (d) {
        case 2: return f(native<2>(2));
        case 3: return f(native<3>(3));
        case 5: return f(native<5>(5));
        default: return f(native<7>(7));
    }
}

template <class V>
void construct_runtime(benchmark::State& state) {
    const auto& s = spec(std::size_t(state.range(0)));
    for (auto _ : state) {
        auto c = make_runtime<V>(s);
        benchmark::DoNotOptimize(c);
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * points_n));
}

/// The flat n * d output of the front ends' batch path (evaluate into the
/// storage points, then the first d coordinates where the storage is wider).
template <class V>
void runtime_batch(const V& rc, std::size_t d, std::span<const double> t, std::vector<double>& flat) {
    std::visit(
        [&](const auto& c) {
            using point = typename std::decay_t<decltype(c)>::point;
            constexpr std::size_t S = std::tuple_size_v<decltype(point{}.v)>;
            if constexpr (S <= crspline::max_exact_dimension) {  // S == d: the output array is the points
                c.evaluate(t, std::span<point>(reinterpret_cast<point*>(flat.data()), t.size()));
            } else {
                static std::vector<point> wide;
                wide.resize(t.size());
                c.evaluate(t, std::span<point>(wide));
                for (std::size_t k = 0; k < t.size(); ++k)
                    std::copy_n(wide[k].v.begin(), d, flat.begin() + std::ptrdiff_t(k * d));
            }
        },
        rc);
}

template <class V>
void eval_scalar_runtime(benchmark::State& state) {
    const std::size_t d = std::size_t(state.range(0));
    const auto& rc = runtime<V>(d);
    const auto& t = params(d);
    std::vector<double> flat(t.size() * d);
    for (auto _ : state) {
        // One dispatch per run of points (as the CLI: one per command), then
        // one evaluate(t) per point, stored as the input's d coordinates.
        std::visit(
            [&](const auto& c) {
                using point = typename std::decay_t<decltype(c)>::point;
                constexpr std::size_t S = std::tuple_size_v<decltype(point{}.v)>;
                if constexpr (S <= crspline::max_exact_dimension)  // S == d
                    scalar_points<S>(c, std::span<const double>(t),
                                     std::span<point>(reinterpret_cast<point*>(flat.data()), t.size()));
                else
                    scalar_cut<S>(c, std::span<const double>(t), d, std::span<double>(flat));
            },
            rc);
        benchmark::DoNotOptimize(flat.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * t.size()));
    const auto ref = native_for(d, [&](const auto& c) {
        std::vector<double> r;
        for (double x : t) {
            const auto p = c.evaluate(x);
            r.insert(r.end(), p.v.begin(), p.v.end());
        }
        return r;
    });
    check_native(state, max_diff(flat, ref));
}

template <class V>
void eval_batch_runtime(benchmark::State& state) {
    const std::size_t d = std::size_t(state.range(0));
    const auto& rc = runtime<V>(d);
    const auto& t = params(d);
    std::vector<double> flat(t.size() * d);
    for (auto _ : state) {
        runtime_batch(rc, d, std::span<const double>(t), flat);
        benchmark::DoNotOptimize(flat.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * t.size()));
    const auto ref = d == 2 ? native_positions<2>() : d == 3 ? native_positions<3>() : d == 5 ? native_positions<5>() : native_positions<7>();
    check_native(state, max_diff(flat, ref));
}

template <class V>
void arc_length_runtime(benchmark::State& state) {
    const std::size_t d = std::size_t(state.range(0));
    const auto& rc = runtime<V>(d);
    double L = 0;
    for (auto _ : state) {
        L = std::visit([](const auto& c) { return crspline::arc_length(c, 1e-12); }, rc);
        benchmark::DoNotOptimize(L);
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * (points_n - 1)));
    const double ref = native_for(d, [](const auto& c) { return crspline::arc_length(c, 1e-12); });
    check_native(state, std::abs(L - ref) / ref);  // relative
}

template <class V>
void analyze_runtime(benchmark::State& state) {
    const std::size_t d = std::size_t(state.range(0));
    const auto& rc = runtime<V>(d);
    double cusps = 0;
    for (auto _ : state) {
        std::visit(
            [&](const auto& c) {
                auto a = crspline::analyze(c);
                benchmark::DoNotOptimize(a.data());
                cusps = double(std::count_if(a.begin(), a.end(), [](const auto& s) { return s.has_cusp(); }));
            },
            rc);
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * (points_n - 1)));
    // vs_native: the largest difference in max_chord_distance per segment.
    const auto mine = std::visit(
        [](const auto& c) {
            std::vector<double> r;
            for (const auto& a : crspline::analyze(c)) r.push_back(a.max_chord_distance);
            return r;
        },
        rc);
    const auto ref = native_for(d, [](const auto& c) {
        std::vector<double> r;
        for (const auto& a : crspline::analyze(c)) r.push_back(a.max_chord_distance);
        return r;
    });
    check_native(state, max_diff(mine, ref));
    state.counters["cusps"] = cusps;
}

template <class V>
void intersections_runtime(benchmark::State& state) {
    const std::size_t d = std::size_t(state.range(0));
    const auto& rc = runtime<V>(d);
    std::size_t found = 0;
    for (auto _ : state) {
        found = std::visit(
            [](const auto& c) {
                const auto r = crspline::find_intersections(c);
                return r.intersections.size() + r.folds.size();
            },
            rc);
        benchmark::DoNotOptimize(found);
    }
    state.counters["meetings"] = double(found);
    state.SetItemsProcessed(std::int64_t(state.iterations() * (points_n - 1)));
}

#define CRSPLINE_DIMENSION_CASES(op, unit)                                                                   \
    BENCHMARK(op##_native<2>)->Name("dimension/" #op "/native/2")->Unit(unit);                                \
    BENCHMARK(op##_native<3>)->Name("dimension/" #op "/native/3")->Unit(unit);                                \
    BENCHMARK(op##_native<5>)->Name("dimension/" #op "/native/5")->Unit(unit);                                \
    BENCHMARK(op##_native<7>)->Name("dimension/" #op "/native/7")->Unit(unit);                                \
    BENCHMARK(op##_runtime<runtime_curve>)->Name("dimension/" #op "/runtime")->Arg(2)->Arg(3)->Arg(5)->Arg(7)->Unit(unit); \
    BENCHMARK(op##_runtime<pad8_curve>)->Name("dimension/" #op "/pad8")->Arg(5)->Arg(7)->Unit(unit)

CRSPLINE_DIMENSION_CASES(construct, benchmark::kMicrosecond);
CRSPLINE_DIMENSION_CASES(eval_scalar, benchmark::kMillisecond);
CRSPLINE_DIMENSION_CASES(eval_batch, benchmark::kMillisecond);
CRSPLINE_DIMENSION_CASES(arc_length, benchmark::kMillisecond);
CRSPLINE_DIMENSION_CASES(analyze, benchmark::kMillisecond);
CRSPLINE_DIMENSION_CASES(intersections, benchmark::kMillisecond);

}  // namespace
