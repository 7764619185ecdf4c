// Issue 30: eval_sorted_float against its floors, each case timed in turn
// in one process (interleaved), CPU time of the thread, the minimum and the
// median over the repetitions. On a machine shared with other jobs Google
// Benchmark's repetitions average hundreds of iterations each, preemptions
// included; the minimum of single interleaved timings is the measure that
// stays comparable (BENCHMARKS.md, issue 30, float evaluation).
//
//   crspline_float_probe [repetitions=30] [--pages=4k]
//
// Buffers (t and the output) as crspline_bench's: 2 MiB pages, or 4 KiB
// ones with --pages=4k (bench/memory_policy.hpp). Each ratio is printed
// three ways: the fastest floor over the fastest case, the medians, and
// the median of the pairs (each repetition's floor over its case).
//
// Cases, 10^7 points on the benchmark curve (1000 control points, float):
// memset of the output (store_floor_float, the target's floor); reading t
// and writing (t, t, t) with whole-line non-temporal stores (the kernel's
// own traffic; 64-byte stores where the CPU has AVX-512F, else none);
// crspline's sorted evaluation with the kernel the dispatch chose, and with
// the 8-lane AVX2 walk where the CPU has AVX-512F too.
#include <crspline/catmull_rom.hpp>

#include "memory_policy.hpp"
#include "read_stream_floor.hpp"
#include "walk.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <string_view>
#include <vector>

namespace {

double cpu_ms() {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}

#if CRSPLINE_X86_DISPATCH
void read_stream_512(const float* t, float* p, std::size_t n) {
    std::size_t k = crspline_bench::read_write_float_512(t, p, 0, n);
    _mm_sfence();
    for (; k < n; ++k) p[3 * k] = p[3 * k + 1] = p[3 * k + 2] = t[k];
}
#endif

}  // namespace

int main(int argc, char** argv) {
    using F3 = crspline::vec<3, float>;
    int reps = 30;
    for (int i = 1; i < argc; ++i) {
        if (std::string_view(argv[i]) == "--pages=4k") crspline_bench::eval_huge_pages() = false;
        else reps = std::max(1, std::atoi(argv[i]));
    }
    constexpr std::size_t n = 10'000'000;
    const crspline::catmull_rom<3, float> c(crspline_bench::walk<float>(1000));
    crspline_bench::eval_vector<float> t(n);
    for (std::size_t k = 0; k < n; ++k) t[k] = std::min(c.t_max(), c.t_min() + (c.t_max() - c.t_min()) * (float(k) / float(n - 1)));
    t.back() = c.t_max();
    crspline_bench::eval_vector<F3> out(n, F3{});
    struct timed {
        const char* name;
        std::function<void()> run;
        std::vector<double> ms;
    };
    std::vector<timed> cases;
    cases.push_back({"memset (store_floor_float)", [&] { std::memset(static_cast<void*>(out.data()), 0x3f, n * sizeof(F3)); }, {}});
    auto evaluate = [&] { c.evaluate(std::span<const float>(t), std::span<F3>(out), 0); };
#if CRSPLINE_X86_DISPATCH
    const bool wide = crspline::detail::avx512_enabled(), avx2 = crspline::detail::avx2_enabled();
    if (wide) cases.push_back({"read t, stream (t, t, t)", [&] { read_stream_512(t.data(), out.data()->data(), n); }, {}});
    cases.push_back({wide ? "eval_sorted_float, AVX-512" : avx2 ? "eval_sorted_float, AVX2" : "eval_sorted_float, SSE2", evaluate, {}});
    if (wide)
        cases.push_back({"eval_sorted_float, AVX2", [&] {
                             crspline::detail::avx512_enabled() = false;
                             evaluate();
                             crspline::detail::avx512_enabled() = true;
                         }, {}});
#else
    cases.push_back({"eval_sorted_float", evaluate, {}});
#endif
    for (int r = 0; r < reps; ++r)
        for (auto& x : cases) {
            const double a = cpu_ms();
            x.run();
            x.ms.push_back(cpu_ms() - a);
        }
    auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
    };
    const auto& floor = cases[0].ms;
    const double floor_min = *std::min_element(floor.begin(), floor.end()), floor_median = median(floor);
    std::printf("%d repetitions, CPU time, 10^7 points, %s pages (t %.0f%%, output %.0f%% in huge pages); ratios: memset's "
                "time / the case's (throughput of the floor)\n",
                reps, crspline_bench::eval_huge_pages() ? "2 MiB" : "4 KiB", 100 * crspline_bench::huge_page_share(t.data()),
                100 * crspline_bench::huge_page_share(out.data()));
    for (const auto& x : cases) {
        const double lo = *std::min_element(x.ms.begin(), x.ms.end()), mid = median(x.ms);
        std::vector<double> pairs(x.ms.size());
        for (std::size_t r = 0; r < pairs.size(); ++r) pairs[r] = floor[r] / x.ms[r];
        std::printf("%-30s min %7.3f ms (%.3f)   median %7.3f ms (%.3f)   pairs (%.3f)\n", x.name, lo, floor_min / lo, mid,
                    floor_median / mid, median(pairs));
    }
}
