// crspline internal: the largest magnitude of an array of numbers, and
// whether all of them are finite, in one pass that the construction can
// afford (issue 30).
//
// The curve's constructor checks that its input coordinates are finite and
// that nothing it computed overflowed (finite_geometry.hpp). Checking each
// number with a branch cost more than a third of the construction; a
// reduction over the flat arrays costs a few instructions per number: two
// doubles per SSE2 instruction, four accumulators to hide the latency of
// max and add. Only when it reports a non-finite number or a magnitude near
// overflow does the caller run the element-by-element check that names the
// culprit.
#pragma once

#include <cmath>
#include <cstddef>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace crspline::detail {

template <class T>
struct magnitude {
    T max_abs = 0;      ///< the largest |x| of the finite values seen (meaningless when !finite)
    bool finite = true; ///< every value was finite
};

/// max |x[i]| and whether every x[i] is finite, for i < count. The probe
/// sums x - x, which is 0 for a finite x and NaN for an infinite or NaN one
/// (and NaN stays NaN); max alone could skip a NaN.
template <class T>
magnitude<T> max_abs_finite(const T* x, std::size_t count) noexcept {
    T m = 0, probe = 0;
    std::size_t i = 0;
#if defined(__SSE2__)
    if constexpr (std::is_same_v<T, double>) {
        const __m128d sign = _mm_set1_pd(-0.0);
        __m128d m0 = _mm_setzero_pd(), m1 = m0, p0 = m0, p1 = m0;
        for (; i + 4 <= count; i += 4) {
            const __m128d a = _mm_loadu_pd(x + i), b = _mm_loadu_pd(x + i + 2);
            m0 = _mm_max_pd(m0, _mm_andnot_pd(sign, a));
            m1 = _mm_max_pd(m1, _mm_andnot_pd(sign, b));
            p0 = _mm_add_pd(p0, _mm_sub_pd(a, a));
            p1 = _mm_add_pd(p1, _mm_sub_pd(b, b));
        }
        alignas(16) double mm[2], pp[2];
        _mm_store_pd(mm, _mm_max_pd(m0, m1));
        _mm_store_pd(pp, _mm_add_pd(p0, p1));
        m = mm[0] > mm[1] ? mm[0] : mm[1];
        probe = pp[0] + pp[1];
    }
#endif
    for (; i < count; ++i) {
        const T a = std::abs(x[i]);
        m = a > m ? a : m;
        probe += x[i] - x[i];
    }
    return {m, probe == 0};
}

}  // namespace crspline::detail
