// crspline benchmarks: side by side with the peers (Boost.Math catmull_rom,
// glm::catmullRom) and with the machine's memory-write limit.
//
// Case names are stable across versions (see BENCHMARKS.md). Unless a case
// says otherwise: 3-D double points, 1000 control points from a seeded random
// walk with uneven steps, centripetal knots. Every case reports
// items_per_second (points, queries or control points) and, where the
// result is approximate, its accuracy as a counter beside the time, measured
// outside the timed loop against an independent computation.
//
// bench/report.py turns the JSON of a run with repetitions into the table of
// medians and ratios; bench/run_bench.sh is the whole `./run bench`.
#include <crspline/arc_length.hpp>
#include <crspline/catmull_rom.hpp>
#include <crspline/nearest.hpp>
#include <crspline/tessellate.hpp>

#include <benchmark/benchmark.h>

#include "memory_policy.hpp"
#include "read_stream_floor.hpp"
#include "walk.hpp"

#include <boost/math/interpolators/catmull_rom.hpp>

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/glm.hpp>
#include <glm/gtx/spline.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <string>
#include <string_view>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace {

using crspline::vec;
using v3 = vec<3, double>;
using curve3 = crspline::catmull_rom<3, double>;
using boost_point = std::array<double, 3>;
using boost_curve = boost::math::catmull_rom<boost_point>;

constexpr std::size_t big = 10'000'000;  // points per batch in the eval cases
constexpr std::size_t control_points = 1000;
constexpr std::uint64_t seed = crspline_bench::seed;

// ---------------------------------------------------------------------------
// Inputs, built once on first use (function-local statics: a filtered run
// builds only what it needs).

using crspline_bench::walk;  // bench/walk.hpp

std::vector<boost_point> to_boost(std::span<const v3> p) {
    std::vector<boost_point> b(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) b[i] = {p[i][0], p[i][1], p[i][2]};
    return b;
}

const std::vector<v3>& points() { static const auto p = walk(control_points); return p; }
const curve3& curve() { static const curve3 c(points()); return c; }
const boost_curve& bcurve() { static const boost_curve b(to_boost(points()), false, 0.5); return b; }

/// n evenly spaced increasing t over [a, b], the last exactly b.
template <class T, class V = std::vector<T>>
V linspace(T a, T b, std::size_t n) {
    V t(n);
    for (std::size_t k = 0; k < n; ++k) t[k] = std::min(b, a + (b - a) * (T(k) / T(n - 1)));
    t.back() = b;
    return t;
}
template <class T, class V = std::vector<T>>
V uniform_random(T a, T b, std::size_t n) {
    std::mt19937_64 rng(seed + 1);
    std::uniform_real_distribution<T> U(a, b);
    V t(n);
    for (auto& x : t) x = std::min(b, U(rng));
    return t;
}
// The batches' parameters and outputs are eval_vectors: 2 MiB pages
// (bench/memory_policy.hpp says why; --pages=4k for 4 KiB ones).
using crspline_bench::eval_vector;
const eval_vector<double>& t_sorted() {
    static const auto t = linspace<double, eval_vector<double>>(curve().t_min(), curve().t_max(), big);
    return t;
}
const eval_vector<double>& t_random() {
    static const auto t = uniform_random<double, eval_vector<double>>(curve().t_min(), curve().t_max(), big);
    return t;
}

// Boost's parameter is the raw knot value, the same cumulative chord^alpha
// as crspline's grid (to rounding): clamp into its own domain.
double boost_t(double t) { return std::min(t, bcurve().max_parameter()); }

/// The output buffer, reused across iterations and cases (its pages are
/// already mapped: no case pays page faults; see store_floor/fresh), one
/// per point type: the floors and the kernels of a type share it.
template <class P>
eval_vector<P>& output(std::size_t n) {
    static eval_vector<P> out;
    if (out.size() != n) out.assign(n, P{});
    return out;
}

template <class P, class Q>
double max_diff(const P& a, const Q& b) {
    double m = 0;
    for (std::size_t d = 0; d < 3; ++d) m = std::max(m, std::abs(double(a[d]) - double(b[d])));
    return m;
}

/// crspline and Boost agree on interior segments (Boost closes the ends
/// with wrapped neighbours, crspline with natural end conditions): the
/// largest coordinate difference over 10^5 interior samples, relative to the
/// bounding-box diagonal. Printed beside eval_sorted: both compute the same
/// curve.
double agreement_with_boost() {
    const auto& c = curve();
    const auto g = c.grid();
    const auto t = linspace(g[1], g[g.size() - 2], 100000);
    double m = 0;
    for (double x : t) {
        const auto b = bcurve()(boost_t(x));
        m = std::max(m, max_diff(c.evaluate(x), b));
    }
    v3 lo = points()[0], hi = lo;
    for (const auto& p : points())
        for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], p[d]), hi[d] = std::max(hi[d], p[d]);
    return m / crspline::norm(hi - lo);
}

// ---------------------------------------------------------------------------
// store_floor: the machine's memory-write limit for 10^7 points (240 MB).

/// A plain store loop: std::fill of the output with a constant point. GCC
/// makes it one 16-byte and one 8-byte store per point (movups + movsd).
void fill_pass(eval_vector<v3>& out) { std::fill(out.begin(), out.end(), v3{{1.0, 2.0, 3.0}}); }
void store_floor(benchmark::State& state) {
    auto& out = output<v3>(big);
    for (auto _ : state) {
        fill_pass(out);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * big));
    state.SetBytesProcessed(std::int64_t(state.iterations() * big * sizeof(v3)));
}

/// memset of the same bytes (glibc 2.36 uses `rep stosb` for large sizes:
/// full-line writes without reading the lines first). A nonzero byte: this
/// is the floor the targets use. Zero bytes are special-cased by this machine
/// (store_floor/memset_zero runs 2.5x faster than any other write of the same
/// size), so they are reported apart and not taken as the floor.
template <class P>
void memset_pass(eval_vector<P>& out, int byte) { std::memset(static_cast<void*>(out.data()), byte, out.size() * sizeof(P)); }
void store_floor_memset(benchmark::State& state, int byte) {
    auto& out = output<v3>(big);
    for (auto _ : state) {
        memset_pass(out, byte);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * big));
    state.SetBytesProcessed(std::int64_t(state.iterations() * big * sizeof(v3)));
}

/// Non-temporal stores (movntpd, SSE2): the write bypasses the caches and
/// skips the read-for-ownership of each line, so only the written bytes cross
/// the memory bus. The portable fallback is the plain loop.
void store_floor_stream(benchmark::State& state) {
    auto& out = output<v3>(big);
    for (auto _ : state) {
        double* p = out.data()->data();
        const std::size_t n = out.size() * 3;
#if defined(__SSE2__)
        std::size_t k = 0;
        if (reinterpret_cast<std::uintptr_t>(p) % 16 != 0) p[k++] = 1.0;
        const __m128d x = _mm_set_pd(2.0, 1.0);
        for (; k + 2 <= n; k += 2) _mm_stream_pd(p + k, x);
        for (; k < n; ++k) p[k] = 1.0;
        _mm_sfence();
#else
        std::fill(p, p + n, 1.0);
#endif
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * big));
    state.SetBytesProcessed(std::int64_t(state.iterations() * big * sizeof(v3)));
}

/// The memory traffic of any evaluation of 10^7 t: read the 8-byte t and
/// write a 24-byte point for each, (t, t, t), with non-temporal stores (the
/// fastest write found above). store_floor counts only the write; this floor
/// counts the 8 bytes of input per point that eval_sorted must also read.
void read_write_pass(const eval_vector<double>& t, eval_vector<v3>& out) {
    double* p = out.data()->data();
    const std::size_t n = t.size();
    std::size_t k = 0;
#if defined(__SSE2__)
    for (; k < n && reinterpret_cast<std::uintptr_t>(p + 3 * k) % 16 != 0; ++k) p[3 * k] = p[3 * k + 1] = p[3 * k + 2] = t[k];
    for (; k + 2 <= n; k += 2) {
        const __m128d a = _mm_loadu_pd(t.data() + k);         // t0 t1
        _mm_stream_pd(p + 3 * k, _mm_unpacklo_pd(a, a));      // t0 t0
        _mm_stream_pd(p + 3 * k + 2, a);                      // t0 t1
        _mm_stream_pd(p + 3 * k + 4, _mm_unpackhi_pd(a, a));  // t1 t1
    }
    _mm_sfence();
#endif
    for (; k < n; ++k) p[3 * k] = p[3 * k + 1] = p[3 * k + 2] = t[k];
}
void store_floor_read_write(benchmark::State& state) {
    auto& out = output<v3>(big);
    const auto& t = t_sorted();
    for (auto _ : state) {
        read_write_pass(t, out);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * big));
    state.SetBytesProcessed(std::int64_t(state.iterations() * big * (sizeof(v3) + sizeof(double))));
}

/// A fresh buffer each time: allocation, page faults and memset. Shows what
/// the reused buffer of every other case saves.
void store_floor_fresh(benchmark::State& state) {
    for (auto _ : state) {
        std::vector<v3> out(big);  // value-initialized: zeroed
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * big));
}

/// The float target's floor: memset of the 10^7 12-byte points (as
/// store_floor/memset: full-line writes that skip the read of each line,
/// the same bytes the float kernel writes with non-temporal stores). It
/// reads nothing; eval_sorted_float must also read its 4-byte t
/// (store_floor_float/read_write below has both).
template <class T>
void store_floor_float(benchmark::State& state) {
    auto& out = output<vec<3, T>>(big);
    for (auto _ : state) {
        memset_pass(out, 0x3f);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * big));
}

// ---------------------------------------------------------------------------
// Evaluation.

/// crspline's batch evaluation of t (position or first derivative) into
/// the shared output buffer.
void crspline_batch(benchmark::State& state, std::span<const double> t, int order) {
    const auto& c = curve();
    auto& out = output<v3>(big);
    for (auto _ : state) {
        c.evaluate(std::span<const double>(t), std::span<v3>(out), order);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * big));
}

/// Boost, one call per point (it has no batch evaluation): f(curve, t).
template <class F>
void boost_loop(benchmark::State& state, std::span<const double> t, F f) {
    const auto& b = bcurve();
    auto& out = output<boost_point>(big);
    for (auto _ : state) {
        for (std::size_t k = 0; k < big; ++k) out[k] = f(b, boost_t(t[k]));
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * big));
}

const auto boost_position = [](const boost_curve& b, double t) { return b(t); };

void eval_sorted_crspline(benchmark::State& state) {
    crspline_batch(state, t_sorted(), 0);
    static const double agree = agreement_with_boost();
    state.counters["vs_boost_rel"] = agree;
}
void eval_sorted_boost(benchmark::State& state) { boost_loop(state, t_sorted(), boost_position); }
void eval_random_crspline(benchmark::State& state) { crspline_batch(state, t_random(), 0); }
void eval_random_boost(benchmark::State& state) { boost_loop(state, t_random(), boost_position); }

/// Derivative checks, printed beside deriv_sorted (on 10^4 interior t):
/// each library's dx/dt against a central difference of its own positions,
/// max |d - fd| / max |fd|. Boost's prime() fails this off straight lines;
/// on a straight line with uneven spacing it is run too (prime_line_err).
struct deriv_errors { double crspline, boost, boost_line; };
deriv_errors derivative_errors() {
    const auto& c = curve();
    const auto g = c.grid();
    const auto t = linspace(g[1] + 1e-3, g[g.size() - 2] - 1e-3, 10000);
    auto check = [&](auto&& pos, auto&& der, const std::vector<double>& ts) {
        double err = 0, scale = 0;
        for (double x : ts) {
            const double h = 1e-6;
            const auto a = pos(x + h), b = pos(x - h), d = der(x);
            for (int k = 0; k < 3; ++k) {
                const double fd = (a[k] - b[k]) / (2 * h);
                err = std::max(err, std::abs(d[k] - fd));
                scale = std::max(scale, std::abs(fd));
            }
        }
        return err / scale;
    };
    deriv_errors e{};
    e.crspline = check([&](double x) { return c.evaluate(x); }, [&](double x) { return c.evaluate(x, 1); }, t);
    const auto& b = bcurve();
    e.boost = check([&](double x) { return b(x); }, [&](double x) { return b.prime(x); }, t);
    // A straight line, uneven spacing.
    std::vector<boost_point> line;
    for (int i = 0; i < 20; ++i) {
        const double s = i * i * 0.37 + i;
        line.push_back({s, 2 * s, -s});
    }
    const boost_curve bl(std::move(line), false, 0.5);
    std::vector<double> tl = linspace(bl.parameter_at_point(1) + 1e-3, bl.parameter_at_point(17) - 1e-3, 1000);
    e.boost_line = check([&](double x) { return bl(x); }, [&](double x) { return bl.prime(x); }, tl);
    return e;
}

void deriv_sorted_crspline(benchmark::State& state) {
    crspline_batch(state, t_sorted(), 1);
    static const deriv_errors e = derivative_errors();
    state.counters["fd_rel_err"] = e.crspline;
}

void deriv_sorted_boost(benchmark::State& state) {
    boost_loop(state, t_sorted(), [](const boost_curve& b, double t) { return b.prime(t); });
    static const deriv_errors e = derivative_errors();
    state.counters["fd_rel_err"] = e.boost;
    state.counters["line_fd_rel_err"] = e.boost_line;
}

// Float variants: the same curve and parameters in single precision.
const std::vector<vec<3, float>>& points_f() { static const auto p = walk<float>(control_points); return p; }
const crspline::catmull_rom<3, float>& curve_f() { static const crspline::catmull_rom<3, float> c(points_f()); return c; }

const eval_vector<float>& t_sorted_f() {
    static const auto t = linspace<float, eval_vector<float>>(curve_f().t_min(), curve_f().t_max(), big);
    return t;
}

void eval_sorted_float_crspline(benchmark::State& state) {
    const auto& c = curve_f();
    const auto& t = t_sorted_f();
    auto& out = output<vec<3, float>>(big);
    for (auto _ : state) {
        c.evaluate(std::span<const float>(t), std::span<vec<3, float>>(out), 0);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * big));
}

/// The float evaluation's own memory traffic (issue 30), beside
/// store_floor_float (the target's floor, which only writes): read
/// eval_sorted_float's 10^7 t (4 bytes each) and write each as a 12-byte
/// point (t, t, t), coordinates interleaved, into the same reused buffer,
/// with non-temporal stores of whole cache lines as the kernel's: 64-byte
/// stores where the CPU has AVX-512F (the kernel's own width there; 16 t,
/// 3 permutes, 3 stores), else 16-byte SSE2 ones (4 t, 3 shuffles, 3
/// stores; on the EPYC these reach less than the kernel). What the kernel
/// can reach at best; reported, not a target (read_stream_floor.hpp).
void read_write_float_pass(const eval_vector<float>& t, eval_vector<vec<3, float>>& out) {
    float* p = out.data()->data();
    const std::size_t n = t.size();
    std::size_t k = 0;
#if defined(__SSE2__)
#if CRSPLINE_X86_DISPATCH
    if (crspline::detail::avx512_enabled()) k = crspline_bench::read_write_float_512(t.data(), p, k, n);
#endif
    for (; k < n && reinterpret_cast<std::uintptr_t>(p + 3 * k) % 16 != 0; ++k) p[3 * k] = p[3 * k + 1] = p[3 * k + 2] = t[k];
    for (; k + 4 <= n; k += 4) {
        const __m128 a = _mm_loadu_ps(t.data() + k);               // t0 t1 t2 t3
        _mm_stream_ps(p + 3 * k, _mm_shuffle_ps(a, a, 0x40));      // t0 t0 t0 t1
        _mm_stream_ps(p + 3 * k + 4, _mm_shuffle_ps(a, a, 0xA5));  // t1 t1 t2 t2
        _mm_stream_ps(p + 3 * k + 8, _mm_shuffle_ps(a, a, 0xFE));  // t2 t3 t3 t3
    }
    _mm_sfence();
#endif
    for (; k < n; ++k) p[3 * k] = p[3 * k + 1] = p[3 * k + 2] = t[k];
}
void store_floor_float_read_write(benchmark::State& state) {
    auto& out = output<vec<3, float>>(big);
    const auto& t = t_sorted_f();
    for (auto _ : state) {
        read_write_float_pass(t, out);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * big));
    state.SetBytesProcessed(std::int64_t(state.iterations() * big * (sizeof(vec<3, float>) + sizeof(float))));
}

void eval_sorted_float_boost(benchmark::State& state) {
    using P = std::array<float, 3>;
    static const boost::math::catmull_rom<P> b = [] {
        std::vector<P> p;
        for (const auto& x : points_f()) p.push_back({x[0], x[1], x[2]});
        return boost::math::catmull_rom<P>(std::move(p), false, 0.5f);
    }();
    static const auto t = linspace(0.0f, b.max_parameter(), big);
    auto& out = output<P>(big);
    for (auto _ : state) {
        for (std::size_t k = 0; k < big; ++k) out[k] = b(t[k]);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * big));
}

// ---------------------------------------------------------------------------
// Issue 30: the memory-bound targets measured interleaved. A kernel and its
// floors, each one whole pass over the 10^7 points, are timed in turn
// inside every iteration (thread CPU time, as crspline_float_probe), the
// order reversed every other iteration, on the same buffers as the
// separate cases (the shared output and t, 2 MiB pages). Each ratio is
// taken pass by pass, the floor's time over the kernel's beside it, then
// the median over the repetition's pairs: the machine's memory bandwidth
// moves by up to 40% from one minute to the next, and the separate cases,
// seconds to minutes apart, measured that as much as the kernel. These
// ratios are the targets' (bench/report.py); the separate cases stay for
// the time per point. Counters: vs_<floor>, the floor's time over the
// kernel's (the kernel's share of the floor's throughput), median of the
// pairs; vs_<floor>_min, the fastest floor pass over the fastest kernel
// pass; <pass>_ms, the median pass; huge_pages, the share of the output
// in 2 MiB pages.

double thread_cpu_ms() {
#if defined(CLOCK_THREAD_CPUTIME_ID)
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
#else
    return 1e3 * double(std::clock()) / CLOCKS_PER_SEC;
#endif
}

struct pass {
    std::string name;
    std::function<void()> run;
};

double median_of(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t h = v.size() / 2;
    return v.size() % 2 ? v[h] : 0.5 * (v[h - 1] + v[h]);
}

/// passes: the floors, then the kernel (last).
void interleaved(benchmark::State& state, const std::vector<pass>& passes, const void* output) {
    const std::size_t m = passes.size(), kernel = m - 1;
    std::vector<std::vector<double>> ms(m);
    bool reverse = false;
    for (auto _ : state) {
        for (std::size_t j = 0; j < m; ++j) {
            const std::size_t i = reverse ? m - 1 - j : j;
            const double a = thread_cpu_ms();
            passes[i].run();
            benchmark::ClobberMemory();
            ms[i].push_back(thread_cpu_ms() - a);
        }
        reverse = !reverse;
    }
    for (std::size_t i = 0; i < m; ++i) {
        state.counters[passes[i].name + "_ms"] = median_of(ms[i]);
        if (i == kernel) continue;
        std::vector<double> pairs(ms[i].size());
        for (std::size_t r = 0; r < pairs.size(); ++r) pairs[r] = ms[i][r] / ms[kernel][r];
        state.counters["vs_" + passes[i].name] = median_of(pairs);
        state.counters["vs_" + passes[i].name + "_min"] = *std::min_element(ms[i].begin(), ms[i].end()) /
                                                           *std::min_element(ms[kernel].begin(), ms[kernel].end());
    }
    state.counters["huge_pages"] = crspline_bench::huge_page_share(output);
    state.SetItemsProcessed(std::int64_t(state.iterations() * big));
}

/// eval_sorted against store_floor/memset (the target's floor), the plain
/// store loop (store_floor) and read-and-stream (store_floor/read_write).
void eval_sorted_interleaved(benchmark::State& state) {
    const auto& c = curve();
    const auto& t = t_sorted();
    auto& out = output<v3>(big);
    interleaved(state,
                {{"memset", [&] { memset_pass(out, 0x3f); }},
                 {"store_floor", [&] { fill_pass(out); }},
                 {"read_write", [&] { read_write_pass(t, out); }},
                 {"kernel", [&] { c.evaluate(std::span<const double>(t), std::span<v3>(out), 0); }}},
                out.data());
}

/// eval_sorted_float against store_floor_float (memset, the target's
/// floor) and store_floor_float/read_write.
void eval_sorted_float_interleaved(benchmark::State& state) {
    const auto& c = curve_f();
    const auto& t = t_sorted_f();
    auto& out = output<vec<3, float>>(big);
    interleaved(state,
                {{"memset", [&] { memset_pass(out, 0x3f); }},
                 {"read_write", [&] { read_write_float_pass(t, out); }},
                 {"kernel", [&] { c.evaluate(std::span<const float>(t), std::span<vec<3, float>>(out), 0); }}},
                out.data());
}

// ---------------------------------------------------------------------------
// Construction, per control point. Boost takes its points by rvalue: the
// copy into its container is timed, as crspline's constructor copies too.

// Memory: bench/memory_policy.hpp's policy (every block of 4 MiB or more
// fresh from the kernel), set at the start of main() for the whole run, the
// same as crspline_construct_rusage's.
void construct_crspline(benchmark::State& state) {
    const std::size_t n = std::size_t(state.range(0));
    const auto p = walk(n);
    for (auto _ : state) {
        curve3 c(p);
        benchmark::DoNotOptimize(c.grid().data());
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * n));
}

void construct_boost(benchmark::State& state) {
    const std::size_t n = std::size_t(state.range(0));
    const auto p = to_boost(walk(n));
    for (auto _ : state) {
        std::vector<boost_point> copy(p);
        boost_curve b(std::move(copy), false, 0.5);
        benchmark::DoNotOptimize(&b);
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * n));
}

// ---------------------------------------------------------------------------
// Uniform Catmull-Rom: glm evaluates one segment from its four points;
// crspline evaluates the uniform (alpha = 0) curve through the same points.
// Both: 10^7 sorted t over the 999 segments.

void uniform_segment_crspline(benchmark::State& state) {
    static const curve3 c = [] {
        crspline::options<3> o;
        o.alpha = 0.0;
        return curve3(points(), o);
    }();
    static const auto t = linspace(c.t_min(), c.t_max(), big);
    auto& out = output<v3>(big);
    for (auto _ : state) {
        c.evaluate(std::span<const double>(t), std::span<v3>(out), 0);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * big));
}

void uniform_segment_glm(benchmark::State& state) {
    static const std::vector<glm::dvec3> p = [] {
        std::vector<glm::dvec3> q;
        for (const auto& x : points()) q.emplace_back(x[0], x[1], x[2]);
        return q;
    }();
    const std::size_t nseg = p.size() - 1;
    static const auto t = linspace(0.0, double(nseg), big);
    auto& out = output<glm::dvec3>(big);
    for (auto _ : state) {
        for (std::size_t k = 0; k < big; ++k) {
            const std::size_t i = std::min(std::size_t(t[k]), nseg - 1);
            const double s = t[k] - double(i);
            // Ends: the missing neighbour repeats the end point.
            out[k] = glm::catmullRom(p[i > 0 ? i - 1 : 0], p[i], p[i + 1], p[std::min(i + 2, nseg)], s);
        }
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * big));
}

// ---------------------------------------------------------------------------
// Arc length. The reference: composite 8-point Gauss-Legendre in long double
// on 1024 equal pieces per segment (and 2048 to show it has converged: the
// uneven walk has tight turns where 64 pieces still leave 1.5e-11); it is
// independent of crspline's adaptive cuts.

long double ref_length(const crspline::cubic_segment<3, double>& s, long double a, long double b, int pieces) {
    static const long double x[4] = {0.18343464249564980494L, 0.52553240991632898582L, 0.79666647741362673959L,
                                     0.96028985649753623168L};
    static const long double w[4] = {0.36268378337836198297L, 0.31370664587788728734L, 0.22238103445337447054L,
                                     0.10122853629037625915L};
    auto speed = [&](long double u) {
        long double q = 0;
        for (int d = 0; d < 3; ++d) {
            const long double v = s.c1[d] + u * (2.0L * s.c2[d] + 3.0L * u * s.c3[d]);
            q += v * v;
        }
        return std::sqrt(q);
    };
    long double sum = 0;
    const long double h = (b - a) / pieces;
    for (int p = 0; p < pieces; ++p) {
        const long double m = a + (p + 0.5L) * h, r = h / 2;
        for (int i = 0; i < 4; ++i) sum += w[i] * r * (speed(m - r * x[i]) + speed(m + r * x[i]));
    }
    return sum;
}

/// Cumulative reference length at each knot.
const std::vector<long double>& ref_knot_lengths() {
    static const std::vector<long double> s = [] {
        std::vector<long double> r{0.0L};
        for (const auto& seg : curve().segments()) r.push_back(r.back() + ref_length(seg, 0, 1, 1024));
        return r;
    }();
    return s;
}

void arc_length(benchmark::State& state) {
    const auto& c = curve();
    double L = 0;
    for (auto _ : state) {
        L = crspline::arc_length(c, 1e-12);
        benchmark::DoNotOptimize(L);
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * c.segment_count()));  // per segment
    long double ref2048 = 0;
    for (const auto& seg : c.segments()) ref2048 += ref_length(seg, 0, 1, 2048);
    const long double ref = ref_knot_lengths().back();
    state.counters["rel_err"] = double(std::abs((long double)L - ref) / ref);
    state.counters["ref_converged"] = double(std::abs(ref2048 - ref) / ref);
}

void t_at_arc_length(benchmark::State& state) {
    const auto& c = curve();
    static const crspline::arc_length_table<3> table(c, 1e-12);
    const std::size_t n = 1'000'000;
    static const auto s = linspace(0.0, table.total(), n);
    static std::vector<double> t(n);
    for (auto _ : state) {
        table.t_at(std::span<const double>(s), std::span<double>(t));
        benchmark::DoNotOptimize(t.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * n));
    // Accuracy: every 997th query, |s_ref(t) - s| / total with the reference
    // integrator from the segment's start.
    double err = 0;
    const auto& ref = ref_knot_lengths();
    for (std::size_t k = 0; k < n; k += 997) {
        const std::size_t i = c.locate(t[k]);
        const auto& seg = c.segment(i);
        const long double u = std::clamp<long double>(((long double)t[k] - seg.t0) / seg.h, 0, 1);
        const long double sr = ref[i] + ref_length(seg, 0, u, 1024);
        err = std::max(err, double(std::abs(sr - (long double)s[k])));
    }
    state.counters["rel_err"] = err / table.total();
}

// Issue 16: arc length on a 20,000-point walk against one plain 16-point
// Gauss-Legendre rule per segment on the same segments, both errors
// against a long-double reference (16 points on 256 panels per segment).
const curve3& walk20k() { static const curve3 c(walk(20'000)); return c; }

long double walk20k_reference() {
    static const long double ref = [] {
        using G = crspline::detail::gauss_legendre<16, long double>;
        long double sum = 0;
        for (const auto& s : walk20k().segments())
            for (int p = 0; p < 256; ++p) {
                const long double m = (p + 0.5L) / 256, r = 0.5L / 256;
                for (int i = 0; i < 8; ++i)
                    for (long double u : {m - r * G::x[i], m + r * G::x[i]}) {
                        long double q = 0;
                        for (int d = 0; d < 3; ++d) {
                            const long double v = s.c1[d] + u * (2.0L * s.c2[d] + 3.0L * u * s.c3[d]);
                            q += v * v;
                        }
                        sum += G::w[i] * r * std::sqrt(q);
                    }
            }
        return sum;
    }();
    return ref;
}

void arc_length_walk(benchmark::State& state) {
    const auto& c = walk20k();
    double L = 0;
    for (auto _ : state) {
        L = crspline::arc_length(c, 1e-12);
        benchmark::DoNotOptimize(L);
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * c.segment_count()));  // per segment
    const long double ref = walk20k_reference();
    state.counters["rel_err"] = double(std::abs((long double)L - ref) / ref);
    // Quadrature nodes per segment, over the pieces arc_length integrates.
    const auto segments = c.segments();
    double nodes = 0;
    crspline::detail::for_each_segment_length_piece(
        c.segment_count(), [&](std::size_t i) { return segments[i]; }, 1e-12,
        [&](std::size_t, double, double, double, const crspline::detail::rule_choice& rc) { nodes += rc.n; });
    state.counters["nodes_per_segment"] = nodes / double(c.segment_count());
}

void arc_length_walk_gl16(benchmark::State& state) {
    const auto& c = walk20k();
    double L = 0;
    for (auto _ : state) {
        L = 0;
        for (const auto& s : c.segments()) L += crspline::detail::gauss_length_n<16>(s, 0.0, 1.0);
        benchmark::DoNotOptimize(L);
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * c.segment_count()));
    const long double ref = walk20k_reference();
    state.counters["rel_err"] = double(std::abs((long double)L - ref) / ref);
}

// Tessellation of the same walk at tol 1e-3 and 1e-5 (steps are ~1): per
// output vertex, with the vertex count over the asymptotic optimum
// integral sqrt(kappa / (8 tol)) ds (computed here by a 16-point rule on 64
// panels per segment); the baseline is a sorted batch evaluation of as
// many points.
double tessellation_optimum(const curve3& c, double tol) {
    using G = crspline::detail::gauss_legendre<16, double>;
    double sum = 0;
    for (const auto& s : c.segments())
        for (int p = 0; p < 64; ++p) {
            const double m = (p + 0.5) / 64, r = 0.5 / 64;
            for (int i = 0; i < 8; ++i)
                for (double u : {m - r * G::x[i], m + r * G::x[i]}) {
                    const v3 d1 = s.du(u, 1), d2 = s.du(u, 2);
                    const double v2 = crspline::dot(d1, d1);
                    const double cross2 = std::max(0.0, v2 * crspline::dot(d2, d2) - std::pow(crspline::dot(d1, d2), 2));
                    // sqrt(kappa) |C'| du with kappa = |C' x C''| / |C'|^3
                    if (v2 > 0) sum += G::w[i] * r * std::sqrt(std::sqrt(cross2) / (v2 * std::sqrt(v2))) * std::sqrt(v2);
                }
        }
    return sum / std::sqrt(8 * tol);
}

void tessellate_walk(benchmark::State& state) {
    const auto& c = walk20k();
    const double tol = state.range(0) == 3 ? 1e-3 : 1e-5;
    crspline::polyline<3, double> pl;
    for (auto _ : state) {
        pl = crspline::tessellate(c, tol);
        benchmark::DoNotOptimize(pl.points.data());
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * pl.points.size()));  // per vertex
    state.counters["vertices"] = double(pl.points.size());
    state.counters["over_optimum"] = double(pl.points.size() - 1) / tessellation_optimum(c, tol);
}

void tessellate_walk_eval(benchmark::State& state) {
    const auto& c = walk20k();
    const double tol = state.range(0) == 3 ? 1e-3 : 1e-5;
    static std::size_t n3 = 0, n5 = 0;
    std::size_t& n = tol == 1e-3 ? n3 : n5;
    if (n == 0) n = crspline::tessellate(c, tol).points.size();
    const auto t = linspace(c.t_min(), c.t_max(), n);
    std::vector<v3> out(n);
    for (auto _ : state) {
        c.evaluate(std::span<const double>(t), std::span<v3>(out), 0);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * n));
}

// Tessellation at an absolute tolerance of 1e-6 (the walk's steps are ~1).
// Accuracy: the largest distance from 15 curve points inside every piece to
// its chord, over the tolerance (must be <= 1).
void tessellate(benchmark::State& state) {
    const auto& c = curve();
    const double tol = 1e-6;
    crspline::polyline<3, double> pl;
    for (auto _ : state) {
        pl = crspline::tessellate(c, tol);
        benchmark::DoNotOptimize(pl.points.data());
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * c.segment_count()));  // per segment
    double worst = 0;
    for (std::size_t k = 0; k + 1 < pl.t.size(); ++k) {
        const v3 a = pl.points[k], b = pl.points[k + 1], ab = b - a;
        const double ab2 = crspline::dot(ab, ab);
        for (int j = 1; j < 16; ++j) {
            const v3 x = c.evaluate(pl.t[k] + (pl.t[k + 1] - pl.t[k]) * (j / 16.0));
            const double w = ab2 > 0 ? std::clamp(crspline::dot(x - a, ab) / ab2, 0.0, 1.0) : 0.0;
            worst = std::max(worst, crspline::norm(x - (a + w * ab)));
        }
    }
    state.counters["vertices"] = double(pl.points.size());
    state.counters["err_over_tol"] = worst / tol;
}

// ---------------------------------------------------------------------------
// Nearest point: nearest_index on curves of 10^3 .. 10^6 segments (the same
// walk generator), 10^5 queries within about one step of a random curve
// point. The `nearest` case of the table is 10^6 segments. Accuracy: the
// index must equal the global O(N) search (checked on 10 queries).

struct nearest_setup {
    std::vector<v3> p;
    curve3 c;
    crspline::nearest_index<3> index;
    std::vector<v3> q;
    double mismatch = 0;
    explicit nearest_setup(std::size_t nseg) : p(walk(nseg + 1, seed + nseg)), c(p), index(c), q(100000) {
        std::mt19937_64 rng(seed + 2);
        std::uniform_real_distribution<double> U(c.t_min(), c.t_max());
        std::normal_distribution<double> g(0.0, 1.0);
        for (auto& x : q) x = c.evaluate(U(rng)) + v3{{g(rng), g(rng), g(rng)}};
        for (std::size_t j = 0; j < 10; ++j)
            mismatch = std::max(mismatch, std::abs(index.nearest(q[j]).distance_sq - crspline::nearest(c, q[j]).distance_sq));
    }
};

void nearest(benchmark::State& state) {
    const std::size_t nseg = std::size_t(state.range(0));
    // One setup per size, kept across repetitions (the index refers to its curve).
    static std::map<std::size_t, std::unique_ptr<nearest_setup>> cache;
    auto& slot = cache[nseg];
    if (!slot) slot = std::make_unique<nearest_setup>(nseg);
    const nearest_setup& S = *slot;
    std::size_t nodes = 0, solved = 0, queries = 0;
    for (auto _ : state) {
        for (const auto& x : S.q) {
            const auto r = S.index.search(x);
            nodes += r.nodes_visited;
            solved += r.segments_solved;
            benchmark::DoNotOptimize(r.result.distance_sq);
        }
        queries += S.q.size();
    }
    state.SetItemsProcessed(std::int64_t(queries));
    state.counters["nodes_per_query"] = double(nodes) / double(queries);
    state.counters["solved_per_query"] = double(solved) / double(queries);
    state.counters["vs_global_abs"] = S.mismatch;
}

// ---------------------------------------------------------------------------
// Native equivalents of three.js CatmullRomCurve3 (timed by bench/js):
// getPoint(u) for 10^6 increasing u is a sorted batch evaluation; getPointAt
// (by arc length) is evaluate_at_arc_length on a prebuilt table.

void threejs_getPoint_crspline(benchmark::State& state) {
    const auto& c = curve();
    const std::size_t n = 1'000'000;
    static const auto t = linspace(c.t_min(), c.t_max(), n);
    auto& out = output<v3>(n);
    for (auto _ : state) {
        c.evaluate(std::span<const double>(t), std::span<v3>(out), 0);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * n));
}

void threejs_getPointAt_crspline(benchmark::State& state) {
    const auto& c = curve();
    static const crspline::arc_length_table<3> table(c, 1e-12);
    const std::size_t n = 1'000'000;
    static const auto s = linspace(0.0, table.total(), n);
    for (auto _ : state) {
        auto out = crspline::evaluate_at_arc_length(c, table, std::span<const double>(s));
        benchmark::DoNotOptimize(out.data());
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * n));
}

}  // namespace

// Registration. Times are wall-clock (the batch cases are memory-bound).
BENCHMARK(store_floor)->Name("store_floor")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(store_floor_memset, nonzero, 0x3f)->Name("store_floor/memset")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(store_floor_memset, zero, 0)->Name("store_floor/memset_zero")->Unit(benchmark::kMillisecond);
BENCHMARK(store_floor_stream)->Name("store_floor/stream")->Unit(benchmark::kMillisecond);
BENCHMARK(store_floor_read_write)->Name("store_floor/read_write")->Unit(benchmark::kMillisecond);
BENCHMARK(store_floor_fresh)->Name("store_floor/fresh")->Unit(benchmark::kMillisecond);
BENCHMARK(eval_sorted_crspline)->Name("eval_sorted/crspline")->Unit(benchmark::kMillisecond);
BENCHMARK(eval_sorted_boost)->Name("eval_sorted/boost")->Unit(benchmark::kMillisecond);
BENCHMARK(eval_sorted_interleaved)->Name("eval_sorted/interleaved")->Unit(benchmark::kMillisecond);
BENCHMARK(eval_random_crspline)->Name("eval_random/crspline")->Unit(benchmark::kMillisecond);
BENCHMARK(eval_random_boost)->Name("eval_random/boost")->Unit(benchmark::kMillisecond);
BENCHMARK(deriv_sorted_crspline)->Name("deriv_sorted/crspline")->Unit(benchmark::kMillisecond);
BENCHMARK(deriv_sorted_boost)->Name("deriv_sorted/boost")->Unit(benchmark::kMillisecond);
BENCHMARK(store_floor_float<float>)->Name("store_floor_float")->Unit(benchmark::kMillisecond);
BENCHMARK(store_floor_float_read_write)->Name("store_floor_float/read_write")->Unit(benchmark::kMillisecond);
BENCHMARK(eval_sorted_float_crspline)->Name("eval_sorted_float/crspline")->Unit(benchmark::kMillisecond);
BENCHMARK(eval_sorted_float_boost)->Name("eval_sorted_float/boost")->Unit(benchmark::kMillisecond);
BENCHMARK(eval_sorted_float_interleaved)->Name("eval_sorted_float/interleaved")->Unit(benchmark::kMillisecond);
BENCHMARK(construct_crspline)->Name("construct/crspline")->Arg(1000)->Arg(1'000'000)->Unit(benchmark::kMicrosecond);
BENCHMARK(construct_boost)->Name("construct/boost")->Arg(1000)->Arg(1'000'000)->Unit(benchmark::kMicrosecond);
BENCHMARK(uniform_segment_crspline)->Name("uniform_segment/crspline")->Unit(benchmark::kMillisecond);
BENCHMARK(uniform_segment_glm)->Name("uniform_segment/glm")->Unit(benchmark::kMillisecond);
BENCHMARK(arc_length)->Name("arc_length")->Unit(benchmark::kMicrosecond);
BENCHMARK(arc_length_walk)->Name("arc_length_walk20k/crspline")->Unit(benchmark::kMillisecond);
BENCHMARK(arc_length_walk_gl16)->Name("arc_length_walk20k/gl16")->Unit(benchmark::kMillisecond);
BENCHMARK(tessellate_walk)->Name("tessellate_walk20k/crspline")->Arg(3)->Arg(5)->Unit(benchmark::kMillisecond);
BENCHMARK(tessellate_walk_eval)->Name("tessellate_walk20k/eval")->Arg(3)->Arg(5)->Unit(benchmark::kMillisecond);
BENCHMARK(t_at_arc_length)->Name("t_at_arc_length")->Unit(benchmark::kMillisecond);
BENCHMARK(tessellate)->Name("tessellate")->Unit(benchmark::kMillisecond);
BENCHMARK(nearest)->Name("nearest")->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(nearest)->Name("nearest_scaling")->Arg(1000)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond);
BENCHMARK(threejs_getPoint_crspline)->Name("threejs_getPoint/crspline")->Unit(benchmark::kMillisecond);
BENCHMARK(threejs_getPointAt_crspline)->Name("threejs_getPointAt/crspline")->Unit(benchmark::kMillisecond);

namespace crspline_bench {
/// The processor's name (/proc/cpuinfo's "model name", with its family,
/// model and stepping: a VM may call an EPYC only "AMD EPYC").
std::string cpu_model() {
    std::ifstream f("/proc/cpuinfo");
    std::string line, name = "unknown", family, model, stepping;
    auto value = [](const std::string& l) {
        const auto k = l.find(':');
        return k == std::string::npos ? std::string() : l.substr(std::min(l.size(), k + 2));
    };
    while (std::getline(f, line)) {
        if (line.rfind("model name", 0) == 0) name = value(line);
        else if (line.rfind("cpu family", 0) == 0) family = value(line);
        else if (line.rfind("model", 0) == 0 && model.empty()) model = value(line);
        else if (line.rfind("stepping", 0) == 0) stepping = value(line);
        else if (line.empty() && name != "unknown") break;
    }
    if (!family.empty()) name += " (family " + family + ", model " + model + ", stepping " + stepping + ")";
    return name;
}
/// Which kernels the dispatch chose on this CPU.
std::string kernels() {
#if CRSPLINE_X86_DISPATCH
    const bool avx2 = crspline::detail::avx2_enabled(), avx512 = crspline::detail::avx512_enabled();
    return std::string("evaluation double: ") + (avx2 && avx512 ? "AVX-512 (sorted), AVX2 (unsorted)" : avx2 ? "AVX2" : "SSE2") +
           "; evaluation float: " + (avx2 && avx512 ? "AVX-512" : avx2 ? "AVX2" : "SSE2") +
           "; arc length rules and first pass: " + (avx2 ? "AVX2" : "SSE2") +
           "; tessellation cut: " + (avx2 && avx512 ? "AVX-512 (2 x 8 lanes)" : avx2 ? "AVX2 (2 x 4 lanes)" : "one segment at a time") +
           "; construction: SSE2";
#else
    return "portable (no x86 dispatch)";
#endif
}
}  // namespace crspline_bench

// --dump-points=FILE writes the 1000-point walk as JSON (for the three.js
// script, so both languages time the same curve) and exits.
int main(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        const std::string_view a = argv[i];
        if (a.starts_with("--dump-points=")) {
            std::FILE* f = std::fopen(std::string(a.substr(14)).c_str(), "w");
            if (!f) return 1;
            std::fputc('[', f);
            for (std::size_t k = 0; k < points().size(); ++k)
                std::fprintf(f, "%s[%.17g,%.17g,%.17g]", k ? "," : "", points()[k][0], points()[k][1], points()[k][2]);
            std::fputs("]\n", f);
            return std::fclose(f) == 0 ? 0 : 1;
        }
    }
    // --pages=4k: the evaluation cases' buffers in 4 KiB pages instead of
    // 2 MiB ones (bench/memory_policy.hpp). --no-avx512, --no-avx2: the
    // kernels a CPU without AVX-512F (or without AVX2) would run, on this
    // one (the report's second line names them). Taken out before Google
    // Benchmark reads the arguments.
    for (int i = 1; i < argc; ++i) {
        const std::string_view a = argv[i];
        if (a == "--pages=4k") {
            crspline_bench::eval_huge_pages() = false;
#if CRSPLINE_X86_DISPATCH
        } else if (a == "--no-avx512") {
            crspline::detail::avx512_enabled() = false;
        } else if (a == "--no-avx2") {
            crspline::detail::avx512_enabled() = crspline::detail::avx2_enabled() = false;
#endif
        } else {
            continue;
        }
        for (int j = i; j + 1 < argc; ++j) argv[j] = argv[j + 1];
        argv[--argc] = nullptr;
        --i;
    }
    crspline_bench::fresh_memory();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    // The processor and the kernels that ran, for the report (issue 30): a
    // number means little without them.
    benchmark::AddCustomContext("cpu_model", crspline_bench::cpu_model());
    benchmark::AddCustomContext("kernels", crspline_bench::kernels());
    benchmark::AddCustomContext("eval_pages", crspline_bench::eval_huge_pages() ? "2 MiB (MADV_HUGEPAGE)" : "4 KiB (MADV_NOHUGEPAGE)");
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
