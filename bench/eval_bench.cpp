// crspline benchmarks, evaluation: the machine's memory-write floors, the
// sorted and random batches against Boost (double and float), the
// interleaved kernel-and-floor passes of issue 30, construction, and the
// uniform curve against glm. Part of crspline_bench (see crspline_bench.cpp
// for the conventions; inputs in bench_inputs.hpp).
#include "bench_inputs.hpp"

namespace {

using namespace crspline_bench;
using crspline::vec;

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


}  // namespace

// Registration (in the table's order). Times are wall-clock (the batch cases are memory-bound).
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
