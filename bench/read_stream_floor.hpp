// The float evaluation's own memory traffic (issue 30), shared by
// crspline_bench's store_floor_float/read_write and crspline_float_probe:
// read t (4 bytes each) and write each as a 12-byte point (t, t, t),
// coordinates interleaved, with 64-byte non-temporal stores of whole cache
// lines as the AVX-512 float kernel writes them (16 t, 3 permutes, 3
// stores). From point k, the first points one by one up to the first
// 64-byte boundary of the output; returns where it stopped (fewer than 16
// points left). The caller fences (_mm_sfence) and writes the tail.
#pragma once

#include <crspline/detail/x86_kernels.hpp>

#include <cstddef>
#include <cstdint>

#if CRSPLINE_X86_DISPATCH
#include <immintrin.h>

namespace crspline_bench {

__attribute__((target("avx512f"))) inline std::size_t read_write_float_512(const float* t, float* p, std::size_t k,
                                                                          std::size_t n) {
    for (; k < n && reinterpret_cast<std::uintptr_t>(p + 3 * k) % 64 != 0; ++k) p[3 * k] = p[3 * k + 1] = p[3 * k + 2] = t[k];
    const __m512i i0 = _mm512_setr_epi32(0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 4, 4, 4, 5);
    const __m512i i1 = _mm512_setr_epi32(5, 5, 6, 6, 6, 7, 7, 7, 8, 8, 8, 9, 9, 9, 10, 10);
    const __m512i i2 = _mm512_setr_epi32(10, 11, 11, 11, 12, 12, 12, 13, 13, 13, 14, 14, 14, 15, 15, 15);
    for (; k + 16 <= n; k += 16) {
        const __m512 a = _mm512_loadu_ps(t + k);
        _mm512_stream_ps(p + 3 * k, _mm512_maskz_permutexvar_ps(0xFFFF, i0, a));
        _mm512_stream_ps(p + 3 * k + 16, _mm512_maskz_permutexvar_ps(0xFFFF, i1, a));
        _mm512_stream_ps(p + 3 * k + 32, _mm512_maskz_permutexvar_ps(0xFFFF, i2, a));
    }
    return k;
}

}  // namespace crspline_bench
#endif
