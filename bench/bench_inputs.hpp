// crspline benchmarks: the inputs the cases share (crspline_bench.cpp and
// its parts eval_bench.cpp, length_bench.cpp): the 1000-point walk as a
// crspline and a Boost curve, 10^7 sorted and random parameters, the output
// buffers (one per point type, shared by the floors and the kernels), built
// once on first use (function-local statics of inline functions: one copy
// for the whole executable, and a filtered run builds only what it needs).
#pragma once

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

namespace crspline_bench {

using crspline::vec;
using v3 = vec<3, double>;
using curve3 = crspline::catmull_rom<3, double>;
using boost_point = std::array<double, 3>;
using boost_curve = boost::math::catmull_rom<boost_point>;

inline constexpr std::size_t big = 10'000'000;  // points per batch in the eval cases
inline constexpr std::size_t control_points = 1000;

inline std::vector<boost_point> to_boost(std::span<const v3> p) {
    std::vector<boost_point> b(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) b[i] = {p[i][0], p[i][1], p[i][2]};
    return b;
}

inline const std::vector<v3>& points() { static const auto p = walk(control_points); return p; }
inline const curve3& curve() { static const curve3 c(points()); return c; }
inline const boost_curve& bcurve() { static const boost_curve b(to_boost(points()), false, 0.5); return b; }

/// n evenly spaced increasing t over [a, b], the last exactly b.
template <class T, class V = std::vector<T>>
inline V linspace(T a, T b, std::size_t n) {
    V t(n);
    for (std::size_t k = 0; k < n; ++k) t[k] = std::min(b, a + (b - a) * (T(k) / T(n - 1)));
    t.back() = b;
    return t;
}
template <class T, class V = std::vector<T>>
inline V uniform_random(T a, T b, std::size_t n) {
    std::mt19937_64 rng(seed + 1);
    std::uniform_real_distribution<T> U(a, b);
    V t(n);
    for (auto& x : t) x = std::min(b, U(rng));
    return t;
}
// The batches' parameters and outputs are eval_vectors: 2 MiB pages
// (bench/memory_policy.hpp says why; --pages=4k for 4 KiB ones).
inline const eval_vector<double>& t_sorted() {
    static const auto t = linspace<double, eval_vector<double>>(curve().t_min(), curve().t_max(), big);
    return t;
}
inline const eval_vector<double>& t_random() {
    static const auto t = uniform_random<double, eval_vector<double>>(curve().t_min(), curve().t_max(), big);
    return t;
}

// Boost's parameter is the raw knot value, the same cumulative chord^alpha
// as crspline's grid (to rounding): clamp into its own domain.
inline double boost_t(double t) { return std::min(t, bcurve().max_parameter()); }

/// The output buffer, reused across iterations and cases (its pages are
/// already mapped: no case pays page faults; see store_floor/fresh), one
/// per point type: the floors and the kernels of a type share it.
template <class P>
inline eval_vector<P>& output(std::size_t n) {
    static eval_vector<P> out;
    if (out.size() != n) out.assign(n, P{});
    return out;
}

template <class P, class Q>
inline double max_diff(const P& a, const Q& b) {
    double m = 0;
    for (std::size_t d = 0; d < 3; ++d) m = std::max(m, std::abs(double(a[d]) - double(b[d])));
    return m;
}

/// crspline and Boost agree on interior segments (Boost closes the ends
/// with wrapped neighbours, crspline with natural end conditions): the
/// largest coordinate difference over 10^5 interior samples, relative to the
/// bounding-box diagonal. Printed beside eval_sorted: both compute the same
/// curve.
inline double agreement_with_boost() {
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


}  // namespace crspline_bench
