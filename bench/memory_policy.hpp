// How the construction benchmarks get their memory (issue 30): one policy
// for Google Benchmark's construct/* cases and for crspline_construct_rusage,
// so that the two measure the same thing.
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

namespace crspline_bench {

inline void fresh_memory() {
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 4 << 20);
    mallopt(M_TRIM_THRESHOLD, 8 << 20);
#endif
}

}  // namespace crspline_bench
