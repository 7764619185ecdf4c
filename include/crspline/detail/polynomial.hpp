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

}  // namespace crspline::detail
