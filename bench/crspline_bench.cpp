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
//
// The cases live in eval_bench.cpp (floors, evaluation, construction,
// uniform) and length_bench.cpp (arc length, tessellation, nearest, three.js
// equivalents), their shared inputs in bench_inputs.hpp; here the context of
// the report and main().
#include "bench_inputs.hpp"

#include <cstdio>
#include <fstream>
#include <string>
#include <string_view>

using crspline_bench::points;

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
