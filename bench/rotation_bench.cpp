// Rotation splines (issue 28), Google Benchmark:
//   rotation/eval/<kind>: batch evaluation of 10^6 samples of a rotation
//       curve (100 random keys), per sample; the goal is at most 4x the
//       time of euclid4/eval below. c2_velocity: rotation and body-frame
//       angular velocity; c2_rates: the body-frame angular velocity alone,
//       as Python's RotationSpline(t, 1) asks for it (SciPy's (t, 1));
//       */scalar: the same samples one
//       evaluate_on() call at a time, the kernels' baseline.
//   rotation/euclid4/eval: crspline's own 4-D Euclidean Catmull-Rom through
//       the same keys as points, batch-evaluated at the same t: the floor.
//   rotation/c2/construct/<keys>: the C2 spline's Newton solve at 10^3 to
//       10^5 keys; linear in the keys (block tridiagonal steps), so time per
//       key (the counter) should stay flat.
//   rotation/pose/eval: a pose curve, 10^6 samples.
//   rotation/fit/mocap/<samples>: keyframe reduction (rotation/fit.hpp) of a
//       120 Hz motion-capture-like stream (sums of sinusoids of the rotation
//       vector, 0.05 degree noise) at 0.5 degrees; per input sample, and the
//       kept keys as a counter. Linear in the samples: the rate should stay flat.
//   */portable: the same batch on the portable lanes (SSE2) where the CPU
//       has the AVX2 clone (batch.hpp), to show what the clone gains.
// Figures go to BENCHMARKS.md with the run that produced them.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <numbers>
#include <random>
#include <span>
#include <vector>

#include <crspline/catmull_rom.hpp>
#include <crspline/rotation/c2.hpp>
#include <crspline/rotation/catmull_rom.hpp>
#include <crspline/rotation/fit.hpp>
#include <crspline/rotation/pose.hpp>

namespace {

using quat = crspline::rotation::quaternion<double>;
namespace rot = crspline::rotation;

constexpr std::size_t samples = 1'000'000;

// n keys, consecutive ones 0.2 to 1.2 rad apart about random axes (seeded).
std::vector<quat> random_keys(std::size_t n, unsigned seed = 28) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g;
    std::uniform_real_distribution<double> a(0.2, 1.2);
    std::vector<quat> k{quat::identity()};
    while (k.size() < n) {
        const rot::vec3<double> axis{{g(rng), g(rng), g(rng)}};
        k.push_back(rot::from_axis_angle(axis, a(rng)) * k.back());
    }
    return k;
}

// Random t over [lo, hi] (the batch takes any order).
std::vector<double> random_t(double lo, double hi, std::size_t n) {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(lo, hi);
    std::vector<double> t(n);
    for (double& x : t) x = u(rng);
    return t;
}

void eval_quaternion(benchmark::State& state, rot::spline_kind kind) {
    const auto keys = random_keys(100);
    rot::rotation_options<double> o;
    o.kind = kind;
    const rot::quaternion_spline<double> c(keys, o);
    const auto t = random_t(c.grid().front(), c.grid().back(), samples);
    std::vector<quat> out(samples);
    for (auto _ : state) {
        c.evaluate(std::span<const double>(t), std::span<quat>(out));
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(samples));
}

// The same batch on the portable lanes (two SSE2 registers per four
// samples), where the CPU would take the AVX2 clone: what the clone gains.
void eval_quaternion_portable(benchmark::State& state, rot::spline_kind kind) {
    const auto keys = random_keys(100);
    rot::rotation_options<double> o;
    o.kind = kind;
    const rot::quaternion_spline<double> c(keys, o);
    const auto t = random_t(c.grid().front(), c.grid().back(), samples);
    std::vector<double> q(4 * samples);
    rot::batch_rows<double> rows;
    rows.q = q.data();
    for (auto _ : state) {
        c.evaluate(std::span<const double>(t), rows, 0, rot::frame::world, rot::detail_batch::isa::portable);
        benchmark::DoNotOptimize(q.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(samples));
}

void eval_c2(benchmark::State& state) {
    const auto keys = random_keys(100);
    std::vector<double> times(keys.size());
    for (std::size_t k = 0; k < times.size(); ++k) times[k] = double(k);
    const rot::c2_rotation_spline<double> c{std::span<const double>(times), std::span<const quat>(keys)};
    const auto t = random_t(times.front(), times.back(), samples);
    std::vector<quat> out(samples);
    for (auto _ : state) {
        c.evaluate(std::span<const double>(t), std::span<quat>(out));
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(samples));
}

rot::c2_rotation_spline<double> c2_curve() {
    const auto keys = random_keys(100);
    std::vector<double> times(keys.size());
    for (std::size_t k = 0; k < times.size(); ++k) times[k] = double(k);
    return rot::c2_rotation_spline<double>{std::span<const double>(times), std::span<const quat>(keys)};
}

// Rotation and body-frame angular velocity (order 1), or the rotation alone
// in the same arrays (order 0, as Python's spline(t) writes it), or with
// rates_only the angular velocity alone (as Python's spline(t, 1), SciPy's
// call, asks for it); on the path the CPU takes, or the portable one.
void eval_c2_rows(benchmark::State& state, int order, bool portable, bool rates_only = false) {
    const auto c = c2_curve();
    const auto t = random_t(c.grid().front(), c.grid().back(), samples);
    std::vector<double> q(4 * samples), w(3 * samples);
    rot::batch_rows<double> rows;
    if (!rates_only) rows.q = q.data();
    if (order >= 1) rows.omega = w.data();
    const auto path = portable ? rot::detail_batch::isa::portable : rot::detail_batch::best_isa();
    for (auto _ : state) {
        c.evaluate(std::span<const double>(t), rows, order, rot::frame::body, false, path);
        benchmark::DoNotOptimize(q.data());
        benchmark::DoNotOptimize(w.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(samples));
}

// The kernels' baseline: one located evaluate_on() per sample.
template <class Curve>
void eval_scalar_loop(benchmark::State& state, const Curve& c) {
    const auto t = random_t(c.grid().front(), c.grid().back(), samples);
    std::vector<quat> out(samples);
    for (auto _ : state) {
        for (std::size_t k = 0; k < samples; ++k) out[k] = c.evaluate_on(c.locate(t[k]), t[k], 0).q;
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(samples));
}
void eval_c2_scalar(benchmark::State& state) { eval_scalar_loop(state, c2_curve()); }
void eval_slerp_scalar(benchmark::State& state) {
    rot::rotation_options<double> o;
    o.kind = rot::spline_kind::piecewise_slerp;
    eval_scalar_loop(state, rot::quaternion_spline<double>(random_keys(100), o));
}

// The floor: the same keys as 4-D points on the uniform grid.
void eval_euclid4(benchmark::State& state) {
    const auto keys = random_keys(100);
    std::vector<crspline::vec<4, double>> pts;
    for (const quat& q : keys) pts.push_back(crspline::vec<4, double>{{q.w, q.x, q.y, q.z}});
    crspline::options<4, double> o;
    o.alpha = 0.0;
    const crspline::catmull_rom<4, double> c(pts, o);
    const auto t = random_t(c.t_min(), c.t_max(), samples);
    std::vector<crspline::vec<4, double>> out(samples);
    for (auto _ : state) {
        c.evaluate(std::span<const double>(t), std::span<crspline::vec<4, double>>(out), 0);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(samples));
}

void construct_c2(benchmark::State& state) {
    const std::size_t n = std::size_t(state.range(0));
    const auto keys = random_keys(n);
    std::vector<double> times(n);
    for (std::size_t k = 0; k < n; ++k) times[k] = double(k);
    for (auto _ : state) {
        const rot::c2_rotation_spline<double> c{std::span<const double>(times), std::span<const quat>(keys)};
        benchmark::DoNotOptimize(c.residual());
    }
    state.counters["ns_per_key"] = benchmark::Counter(double(state.iterations()) * double(n) * 1e-9,
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void eval_pose(benchmark::State& state) {
    const auto keys = random_keys(100);
    std::vector<crspline::vec<3, double>> pts;
    std::mt19937_64 rng(3);
    std::normal_distribution<double> g;
    crspline::vec<3, double> p{};
    for (std::size_t k = 0; k < keys.size(); ++k) {
        p = p + crspline::vec<3, double>{{1 + std::abs(g(rng)), g(rng), g(rng)}};
        pts.push_back(p);
    }
    const rot::pose_curve<double> c{std::span<const crspline::vec<3, double>>(pts), std::span<const quat>(keys)};
    const auto t = random_t(c.grid().front(), c.grid().back(), samples);
    std::vector<rot::pose_sample<double>> out(samples);
    for (auto _ : state) {
        c.evaluate(std::span<const double>(t), std::span<rot::pose_sample<double>>(out));
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(samples));
}

}  // namespace

void fit_mocap(benchmark::State& state) {
    const auto n = std::size_t(state.range(0));
    std::mt19937_64 rng(40);
    std::uniform_real_distribution<double> u(0, 1);
    std::normal_distribution<double> g;
    double amp[9], freq[9], phase[9];
    for (int k = 0; k < 9; ++k) amp[k] = u(rng), freq[k] = u(rng), phase[k] = u(rng);
    const double noise = 0.05 * std::numbers::pi / 180;
    std::vector<double> t(n);
    std::vector<quat> q(n);
    for (std::size_t i = 0; i < n; ++i) {
        t[i] = double(i) / 120;
        rot::vec3<double> r{};
        for (int k = 0; k < 9; ++k)
            r[std::size_t(k / 3)] += 0.8 * amp[k] * std::sin(2 * std::numbers::pi * (0.2 + 1.8 * freq[k]) * t[i] + 6.3 * phase[k]) / 3;
        const rot::vec3<double> e{{g(rng) * noise, g(rng) * noise, g(rng) * noise}};
        q[i] = rot::from_rotation_vector(e) * rot::from_rotation_vector(r);
    }
    std::size_t keys = 0;
    for (auto _ : state) {
        const auto f = rot::fit(t, q, 0.5 * std::numbers::pi / 180);
        keys = f.count();
        benchmark::DoNotOptimize(keys);
    }
    state.counters["keys"] = double(keys);
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(n));
}

BENCHMARK(eval_euclid4)->Name("rotation/euclid4/eval")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(eval_quaternion, catmull_rom, rot::spline_kind::catmull_rom)
    ->Name("rotation/eval/catmull_rom")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(eval_quaternion, slerp, rot::spline_kind::piecewise_slerp)
    ->Name("rotation/eval/slerp")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(eval_quaternion, squad, rot::spline_kind::squad)->Name("rotation/eval/squad")->Unit(benchmark::kMillisecond);
BENCHMARK(eval_c2)->Name("rotation/eval/c2")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(eval_c2_rows, velocity, 1, false)->Name("rotation/eval/c2_velocity")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(eval_c2_rows, rates, 1, false, true)->Name("rotation/eval/c2_rates")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(eval_c2_rows, rates_portable, 1, true, true)
    ->Name("rotation/eval/c2_rates/portable")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(eval_c2_rows, velocity_portable, 1, true)
    ->Name("rotation/eval/c2_velocity/portable")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(eval_c2_rows, rows_portable, 0, true)->Name("rotation/eval/c2/portable")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(eval_quaternion, kochanek_bartels, rot::spline_kind::kochanek_bartels)
    ->Name("rotation/eval/kochanek_bartels")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(eval_quaternion, barry_goldman, rot::spline_kind::barry_goldman)
    ->Name("rotation/eval/barry_goldman")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(eval_quaternion_portable, catmull_rom, rot::spline_kind::catmull_rom)
    ->Name("rotation/eval/catmull_rom/portable")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(eval_quaternion_portable, squad, rot::spline_kind::squad)
    ->Name("rotation/eval/squad/portable")->Unit(benchmark::kMillisecond);
BENCHMARK(eval_c2_scalar)->Name("rotation/eval/c2/scalar")->Unit(benchmark::kMillisecond);
BENCHMARK(eval_slerp_scalar)->Name("rotation/eval/slerp/scalar")->Unit(benchmark::kMillisecond);
BENCHMARK(construct_c2)->Name("rotation/c2/construct")->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond);
BENCHMARK(eval_pose)->Name("rotation/pose/eval")->Unit(benchmark::kMillisecond);

BENCHMARK(fit_mocap)->Name("rotation/fit/mocap")->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
