// How the benchmarks get their memory (issue 30). First (fresh_memory) one
// policy for Google Benchmark's construct/* cases and for
// crspline_construct_rusage, so that the two measure the same thing; then
// (eval_allocator, below) the pages of the memory-bound evaluation cases.
//
// glibc's malloc serves a large block (128 KiB or more at start) by mmap and
// raises that threshold, up to 32 MiB, each time such a block is freed. So
// whether Boost's arrays (its 24 MB copy of the points and its 8 MB of
// knots at 10^6 points) come as fresh pages from the kernel, which faults
// and zeroes them, or as freed memory reused from the heap depended on what
// the process had allocated and freed before: the two harnesses disagreed
// (on the AMD EPYC, Google Benchmark had crspline at 1.13x Boost's time,
// getrusage at 0.77x) because their histories differed. crspline's large
// arrays are mappings of their own (detail/storage.hpp), fresh every time.
//
// fresh_memory() fixes the threshold at 4 MiB (crspline's own threshold for
// a mapping, detail/storage.hpp): every block that large is mapped when
// allocated and unmapped when freed, for both libraries, in both harnesses,
// whatever ran before, and every smaller one comes from the heap. Both
// programs set it first thing, so no case's numbers depend on the order
// the cases run in. That is what a program pays that
// builds one large curve, and the measure the construct targets use: the
// kernel's cost of the bytes a curve keeps (crspline 68 per point, Boost 32:
// the tangents and 1/h that make evaluation 10x faster) is part of it.
// Below 4 MiB (the 10^3-point case) blocks come from the heap, reused.
#pragma once

#if defined(__GLIBC__)
#include <malloc.h>
#endif
#if defined(__linux__)
#include <sys/mman.h>
#endif

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <new>
#include <string>
#include <vector>

namespace crspline_bench {

inline void fresh_memory() {
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 4 << 20);
    mallopt(M_TRIM_THRESHOLD, 8 << 20);
#endif
}

}  // namespace crspline_bench

// ---------------------------------------------------------------------------
// The memory-bound evaluation cases' buffers (issue 30): 2 MiB pages.
//
// eval_sorted, eval_sorted_float and their floors (memset, the plain store
// loop, read-and-stream) write 120-240 MB and read 40-80 MB of t. Where
// those bytes sit decides the floor more than the kernel: on the AMD EPYC
// VM (THP "madvise", so a plain std::vector gets 4 KiB pages) memset of the
// float output took 2.7-3.1 ms on 2 MiB pages and 2.9 to 4.0 ms on 4 KiB
// pages, from one allocation to the next (wherever the pages came from),
// and the float kernel 3.1-3.9 and 3.2-4.4 ms: the ratio the target reads
// moved from 0.80 to 1.26 on 4 KiB pages for the same code, and stayed
// within 0.80-0.87 on 2 MiB pages. So every such buffer (the inputs t and the
// shared outputs) comes from eval_allocator: its own mapping, 2 MiB
// aligned, advised MADV_HUGEPAGE, the pages touched when the vector fills
// it. That is the floor at its fastest (memset's best case, the strict
// one) and the same for every case and every run; huge_page_share() says
// how much of a buffer the kernel did back with huge pages (the report
// prints it: with THP "never" it is 0 and the ratios are 4 KiB-page ones).
// --pages=4k (crspline_bench, crspline_float_probe) advises
// MADV_NOHUGEPAGE instead, to measure the other side.

namespace crspline_bench {

/// true: 2 MiB pages (the default); false: 4 KiB pages (--pages=4k).
inline bool& eval_huge_pages() {
    static bool on = true;
    return on;
}

template <class T>
struct eval_allocator {
    using value_type = T;
    static constexpr std::size_t huge = std::size_t(2) << 20;

    eval_allocator() = default;
    template <class U>
    eval_allocator(const eval_allocator<U>&) noexcept {}

    static std::size_t mapped_bytes(std::size_t n) { return (n * sizeof(T) + huge - 1) / huge * huge; }

    T* allocate(std::size_t n) {
#if defined(__linux__)
        // Map 2 MiB more, keep the 2 MiB-aligned part, unmap the rest.
        const std::size_t len = mapped_bytes(n);
        void* raw = ::mmap(nullptr, len + huge, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (raw == MAP_FAILED) throw std::bad_alloc();
        const auto r = reinterpret_cast<std::uintptr_t>(raw), a = (r + huge - 1) / huge * huge;
        if (a > r) ::munmap(raw, a - r);
        if (r + huge > a) ::munmap(reinterpret_cast<void*>(a + len), r + huge - a);
        ::madvise(reinterpret_cast<void*>(a), len, eval_huge_pages() ? MADV_HUGEPAGE : MADV_NOHUGEPAGE);
        return reinterpret_cast<T*>(a);
#else
        return static_cast<T*>(::operator new(n * sizeof(T), std::align_val_t(huge)));
#endif
    }
    void deallocate(T* p, std::size_t n) noexcept {
#if defined(__linux__)
        ::munmap(p, mapped_bytes(n));
#else
        ::operator delete(p, std::align_val_t(huge));
        (void)n;
#endif
    }
    template <class U>
    bool operator==(const eval_allocator<U>&) const noexcept { return true; }
};

template <class T>
using eval_vector = std::vector<T, eval_allocator<T>>;

/// The share of the mapping that holds p backed by huge pages
/// (/proc/self/smaps: AnonHugePages over Rss); -1 where unknown.
inline double huge_page_share(const void* p) {
    std::ifstream f("/proc/self/smaps");
    const auto x = reinterpret_cast<std::uintptr_t>(p);
    std::string line;
    bool in = false;
    double rss = -1, anon_huge = -1;
    while (std::getline(f, line)) {
        const auto dash = line.find('-'), space = line.find(' ');
        if (dash != std::string::npos && space != std::string::npos && dash < space &&
            line.find_first_not_of("0123456789abcdef") == dash) {
            if (in) break;
            const auto lo = std::stoull(line.substr(0, dash), nullptr, 16);
            const auto hi = std::stoull(line.substr(dash + 1, space - dash - 1), nullptr, 16);
            in = lo <= x && x < hi;
        } else if (in && line.rfind("Rss:", 0) == 0) {
            rss = std::stod(line.substr(4));
        } else if (in && line.rfind("AnonHugePages:", 0) == 0) {
            anon_huge = std::stod(line.substr(14));
        }
    }
    return rss > 0 && anon_huge >= 0 ? anon_huge / rss : -1;
}

}  // namespace crspline_bench
