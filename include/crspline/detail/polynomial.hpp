// crspline internal: real polynomials in the power basis (ascending
// coefficients) and their real roots on an interval.
//
// Roots are isolated by recursion on the derivative (between consecutive
// critical points a polynomial is monotone), then each sign change is closed
// by bisection-safeguarded Newton to full precision. Robust for the low
// degrees crspline needs (up to 6), with no tolerance to tune.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace crspline::detail {

/// p(x) = c[0] + c[1] x + ... + c[N-1] x^(N-1), Horner.
template <class T, std::size_t N>
constexpr T horner(const std::array<T, N>& c, T x) noexcept {
    T r = 0;
    for (std::size_t i = N; i-- > 0;) r = r * x + c[i];
    return r;
}

template <class T, std::size_t N>
constexpr std::array<T, (N > 1 ? N - 1 : 1)> derivative(const std::array<T, N>& c) noexcept {
    std::array<T, (N > 1 ? N - 1 : 1)> d{};
    for (std::size_t i = 1; i < N; ++i) d[i - 1] = T(i) * c[i];
    return d;
}

/// Product of two polynomials.
template <class T, std::size_t N, std::size_t M>
constexpr std::array<T, N + M - 1> multiply(const std::array<T, N>& p, const std::array<T, M>& q) noexcept {
    std::array<T, N + M - 1> r{};
    for (std::size_t i = 0; i < N; ++i)
        for (std::size_t j = 0; j < M; ++j) r[i + j] += p[i] * q[j];
    return r;
}

/// Root of a continuous function on [lo, hi] whose values at the ends have
/// opposite signs (or one is zero): Newton steps kept inside the shrinking
/// bracket, bisection whenever Newton leaves it or stalls; stops when the
/// bracket cannot shrink any more in floating point.
template <class T, class F, class DF>
T solve_bracketed(F f, DF df, T lo, T hi) noexcept {
    const T flo = f(lo), fhi = f(hi);
    if (flo == 0) return lo;
    if (fhi == 0) return hi;
    const bool rising = flo < 0;
    T x = lo + (hi - lo) * (flo / (flo - fhi));  // regula falsi start
    if (!(x > lo && x < hi)) x = lo + (hi - lo) / 2;
    for (int it = 0; it < 300; ++it) {
        const T fx = f(x);
        if (fx == 0) return x;
        if ((fx < 0) == rising) lo = x;
        else hi = x;
        const T mid = lo + (hi - lo) / 2;
        if (!(mid > lo && mid < hi)) break;  // bracket is two adjacent floats
        const T d = df(x);
        T next = d != 0 ? x - fx / d : mid;
        if (!(next > lo && next < hi) || it % 8 == 7) next = mid;  // keep O(log) worst case
        x = next;
    }
    return std::abs(f(lo)) <= std::abs(f(hi)) ? lo : hi;
}

/// At most N values in place (no heap): the roots of a polynomial of
/// degree < N. Iterable like a container.
template <class T, std::size_t N>
struct root_list {
    std::array<T, (N > 0 ? N : 1)> v{};
    std::size_t n = 0;
    void push_back(T x) noexcept { v[n++] = x; }
    bool empty() const noexcept { return n == 0; }
    std::size_t size() const noexcept { return n; }
    T back() const noexcept { return v[n - 1]; }
    T operator[](std::size_t i) const noexcept { return v[i]; }
    const T* begin() const noexcept { return v.data(); }
    const T* end() const noexcept { return v.data() + n; }
};

/// Real roots of p in [a, b], sorted, each once. A root of even
/// multiplicity (p touches zero without crossing) is reported only when p is
/// exactly zero at that critical point; callers that care about
/// near-tangencies examine the critical points themselves.
template <class T, std::size_t N>
root_list<T, N> real_roots(const std::array<T, N>& c, T a, T b) {
    root_list<T, N> out;
    if constexpr (N <= 1) {
        return out;
    } else if constexpr (N == 2) {
        if (c[1] != 0) {
            const T r = -c[0] / c[1];
            if (r >= a && r <= b) out.push_back(r);
        }
        return out;
    } else {
        if (c[N - 1] == 0) {  // lower degree
            std::array<T, N - 1> low{};
            for (std::size_t i = 0; i + 1 < N; ++i) low[i] = c[i];
            for (T r : real_roots(low, a, b)) out.push_back(r);
            return out;
        }
        // Critical points split [a, b] into monotone pieces.
        root_list<T, N + 1> cuts;
        cuts.push_back(a);
        for (T x : real_roots(derivative(c), a, b))
            if (x > cuts.back() && x < b) cuts.push_back(x);
        cuts.push_back(b);
        const auto dc = derivative(c);
        auto f = [&](T x) { return horner(c, x); };
        auto df = [&](T x) { return horner(dc, x); };
        for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
            const T lo = cuts[i], hi = cuts[i + 1];
            const T flo = f(lo), fhi = f(hi);
            T r;
            if (flo == 0) r = lo;
            else if (fhi == 0) r = hi;
            else if ((flo < 0) != (fhi < 0)) r = solve_bracketed<T>(f, df, lo, hi);
            else continue;
            if (out.empty() || r > out.back()) out.push_back(r);
        }
        return out;
    }
}

/// Roots in [0, 1] where p crosses zero from below (p < 0 before, > 0
/// after): for p the derivative of a function, its strict local minima.
/// Bernstein-form isolation: on an interval whose Bernstein coefficients
/// change sign once (Descartes' rule for the Bernstein basis) there is
/// exactly one root, closed by bracketed Newton; no sign change means none;
/// otherwise the interval is split by de Casteljau. Intervals whose single
/// root is a falling one are skipped without solving, which is what makes
/// this cheaper than real_roots() when only minima matter.
template <class T, std::size_t N>
root_list<T, N> rising_roots(const std::array<T, N>& c) {
    static_assert(N >= 2);
    constexpr std::size_t n = N - 1;  // degree
    root_list<T, N> out;
    // Power -> Bernstein on [0, 1]: b_i = sum_{j <= i} C(i, j) / C(n, j) a_j.
    std::array<T, N> b{};
    for (std::size_t i = 0; i <= n; ++i) {
        T sum = 0, cij = 1;  // C(i, j), built up along j
        for (std::size_t j = 0; j <= i; ++j) {
            T cnj = 1;
            for (std::size_t k = 0; k < j; ++k) cnj = cnj * T(n - k) / T(k + 1);
            sum += cij / cnj * c[j];
            cij = cij * T(i - j) / T(j + 1);
        }
        b[i] = sum;
    }
    const auto dc = derivative(c);
    auto f = [&](T x) { return horner(c, x); };
    auto df = [&](T x) { return horner(dc, x); };
    struct job {
        std::array<T, N> b;
        T lo, hi;
        int depth;
    };
    job stack[2 * 64];
    int top = 0;
    stack[top++] = {b, T(0), T(1), 0};
    // Coefficients within the conversion's rounding of zero have no
    // reliable sign: an interval with one is split, never decided.
    T magnitude = 0;
    for (T x : b) magnitude += std::abs(x);
    const T fuzz = T(64) * std::numeric_limits<T>::epsilon() * magnitude;
    root_list<T, N> found;  // in discovery order; sorted at the end
    int budget = 4096;      // intervals examined at most: a safety net, never reached in tests
    while (top > 0 && found.size() < n && budget-- > 0) {
        const job j = stack[--top];
        int changes = 0;
        std::size_t unsure = 0;
        T last = 0;
        for (T x : j.b) {
            if (std::abs(x) <= fuzz) {
                ++unsure;
                continue;
            }
            if (last != 0 && (x < 0) != (last < 0)) ++changes;
            last = x;
        }
        if (changes == 0 && unsure == 0) continue;
        if (unsure == N) {
            // p is zero to rounding on the whole interval (near a multiple
            // root): splitting cannot decide; its middle if p rises across.
            if (f(j.lo) <= 0 && f(j.hi) >= 0) found.push_back(j.lo + (j.hi - j.lo) / 2);
            continue;
        }
        const T first = j.b[0], final = j.b[n];
        if (changes == 1 && unsure == 0) {
            // The end coefficients are p(lo), p(hi) only up to the rounding of
            // the conversion: decide on the values themselves. A zero at an
            // end (a root on the boundary next to the counted one) is split.
            const T flo = f(j.lo), fhi = f(j.hi);
            if (flo < 0 && fhi > 0) {
                found.push_back(solve_bracketed<T>(f, df, j.lo, j.hi));
                continue;
            }
            if (flo > 0 && fhi < 0) continue;  // a falling root: not a minimum
        }
        const T mid = j.lo + (j.hi - j.lo) / 2;
        if (j.depth >= 60 || !(mid > j.lo && mid < j.hi)) {
            // Unresolved (a cluster of roots, or a zero at rounding level):
            // its middle, if p rises across it.
            if (f(j.lo) <= 0 && f(j.hi) >= 0 && (first <= 0 || final >= 0)) found.push_back(mid);
            continue;
        }
        // de Casteljau at 1/2: left and right control polygons.
        std::array<T, N> left{}, right{}, w = j.b;
        for (std::size_t r = 0; r <= n; ++r) {
            left[r] = w[0];
            right[n - r] = w[n - r];
            for (std::size_t i = 0; i + r < n; ++i) w[i] = (w[i] + w[i + 1]) / 2;
        }
        stack[top++] = {right, mid, j.hi, j.depth + 1};  // popped second
        stack[top++] = {left, j.lo, mid, j.depth + 1};
    }
    for (std::size_t i = 1; i < found.size(); ++i)  // insertion sort: at most n values
        for (std::size_t k = i; k > 0 && found.v[k] < found.v[k - 1]; --k) std::swap(found.v[k], found.v[k - 1]);
    for (T x : found)
        if (out.empty() || x > out.back()) out.push_back(x);
    return out;
}

}  // namespace crspline::detail
