// Where construction time goes at 10^6 points: user-mode time (the
// arithmetic) against kernel time and page faults (first touch of the
// arrays), per construction, from getrusage over 30 constructions after 3
// warm-up ones. Same walk as crspline_bench; Boost is given a copy of the
// points as in construct/boost. Printed by bench/run_bench.sh.
// Built twice: as is (large arrays advised for transparent huge pages, see
// include/crspline/detail/storage.hpp) and with CRSPLINE_NO_HUGE_PAGES
// (crspline_construct_rusage_4k, which prints only its crspline row), so
// one run shows what the huge pages change.
#include <crspline/catmull_rom.hpp>

#include <boost/math/interpolators/catmull_rom.hpp>

#include <sys/resource.h>

#include "memory_policy.hpp"
#include "walk.hpp"

#include <array>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace {
double seconds(const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); }
}  // namespace

int main() {
    using v3 = crspline::vec<3, double>;
    using bp = std::array<double, 3>;
    const std::size_t n = 1'000'000;
    const std::vector<v3> p = crspline_bench::walk(n);
    std::vector<bp> b(n);
    for (std::size_t i = 0; i < n; ++i) b[i] = {p[i][0], p[i][1], p[i][2]};
    volatile double sink = 0;
#ifdef CRSPLINE_NO_HUGE_PAGES
    const int libs = 1;
    const char* name = "crspline, 4 KiB pages (CRSPLINE_NO_HUGE_PAGES)";
#else
    const int libs = 2;
    const char* name = "crspline";
    std::string thp = "unknown";
    std::getline(std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled"), thp);
    std::printf("Transparent huge pages on this machine: %s\n\n", thp.c_str());
    std::printf("| construct, 10^6 points | user ms | kernel ms | user + kernel ms | page faults |\n"
                "|---|---:|---:|---:|---:|\n");
#endif
    // The memory policy of construct/* in crspline_bench (memory_policy.hpp),
    // so that the two harnesses measure the same thing.
    crspline_bench::fresh_memory();
    for (int lib = 0; lib < libs; ++lib) {
        auto once = [&] {
            if (lib == 0) sink = crspline::catmull_rom<3>(p).t_max();
            else sink = boost::math::catmull_rom<bp>(std::vector<bp>(b), false, 0.5).max_parameter();
        };
        for (int w = 0; w < 3; ++w) once();
        const int reps = 30;
        rusage a{}, z{};
        getrusage(RUSAGE_SELF, &a);
        for (int r = 0; r < reps; ++r) once();
        getrusage(RUSAGE_SELF, &z);
        const double user = 1e3 * (seconds(z.ru_utime) - seconds(a.ru_utime)) / reps;
        const double kernel = 1e3 * (seconds(z.ru_stime) - seconds(a.ru_stime)) / reps;
        std::printf("| %s | %.1f | %.1f | %.1f | %.0f |\n", lib == 0 ? name : "boost", user, kernel, user + kernel,
                    double(z.ru_minflt - a.ru_minflt) / reps);
    }
    return 0;
}
