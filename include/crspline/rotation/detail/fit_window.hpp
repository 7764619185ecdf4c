// crspline: internals of rotation keyframe reduction (rotation/fit.hpp).
//
// A segment of the open Catmull-Rom rotation curve (quaternion_spline,
// natural ends, explicit grid) depends on four keys at most: its own two and
// one neighbour each side (the tangent-space construction), the first and
// last segments on three (the natural end takes the neighbouring control),
// a two-key curve on two (slerp). fit_window rebuilds one segment from those
// keys with the same formulas, in the same order of operations, as
// quaternion_spline::build_kochanek_bartels, and evaluates it as the scalar
// evaluate() does (De Casteljau of so3::slerp_jet), so the search judges the
// segment the fitted curve will have. The search still proves nothing: fit()
// re-proves every sample on the curve it returns.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "../quaternion.hpp"
#include "../so3.hpp"

namespace crspline::rotation::detail_fit {

inline constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

/// A proved upper bound on the rotation angle between the rotations of
/// quaternion r (a curve value: unit to rounding) and of unit q (a sample,
/// normalized), both as computed.
///
/// The angle of unit a, b is 4 atan2(|a - b|, |a + b|) once b . a >= 0 (q
/// and -q are one rotation); atan2 keeps every digit for tiny angles and
/// near pi, where 2 acos|a . b| loses half of them. Rounding, with eps the
/// machine epsilon:
/// - |r - q| and |r + q| are each computed to a relative 4 eps (one
///   rounding per difference, three per sum of squares, one square root),
///   so their ratio to 8 eps; atan(z (1 + e)) <= atan(z) (1 + e) because
///   z / (1 + z^2) <= atan z, and atan2 itself is within 2 ulps: the angle
///   of r and q as vectors is at most computed * (1 + 16 eps);
/// - r is not exactly unit: r = rho r^ moves |r - q| and |r + q| by at most
///   |rho - 1| each, a point at distance 2 from the origin, where atan2's
///   gradient is 1/2: the angle moves by at most 4 * sqrt(2)/2 |rho - 1| <
///   4 |rho - 1|; q is unit to 2 eps (normalized by its computed norm) and
///   rho itself is computed to 2 eps: 4 * (2 + 2) eps = 16 eps, doubled for
///   the second-order terms of both, 32 eps absolute.
template <class T>
T angle_bound(quaternion<T> r, const quaternion<T>& q) noexcept {
    constexpr T eps = std::numeric_limits<T>::epsilon();
    if (dot(r, q) < 0) r = -r;
    const T computed = T(4) * std::atan2(norm(r - q), norm(r + q));
    const T rho = norm(r);
    return computed * (1 + 16 * eps) + 4 * std::abs(rho - 1) + 32 * eps;
}

/// The samples (unit, as checked_unit made them) and their times, and the
/// segment test the search and the exact minimum share.
template <class T>
class fit_window {
public:
    using quat = quaternion<T>;

    fit_window(std::span<const T> times, std::span<const quat> samples, T tolerance)
        : t_(times), s_(samples), tol_(tolerance) {}

    std::size_t size() const noexcept { return s_.size(); }
    T tolerance() const noexcept { return tol_; }

    /// The largest angle_bound over the samples that segment (a, b) carries
    /// (a + 1 .. b - 1; sample a is its key exactly, b belongs to the next
    /// segment, or is the end key and evaluated here at u = 1), with p the
    /// key before a and c the key after b (none at the ends). Stops early
    /// once the bound exceeds `stop_above`.
    T segment_error(std::size_t p, std::size_t a, std::size_t b, std::size_t c, T stop_above) const {
        return segment_worst(p, a, b, c, stop_above).first;
    }
    /// The same, with the sample where the largest bound is (none: no sample).
    std::pair<T, std::size_t> segment_worst(std::size_t p, std::size_t a, std::size_t b, std::size_t c, T stop_above) const {
        const auto k = controls(p, a, b, c);
        const T t0 = t_[a], h = t_[b] - t0, du = T(1) / h;
        const std::size_t last = c == none ? b : b - 1;
        T worst = 0;
        std::size_t at = none;
        for (std::size_t i = a + 1; i <= last; ++i) {
            const T e = angle_bound(evaluate(k, (t_[i] - t0) / h, du), s_[i]);
            if (at == none || e > worst) worst = e, at = i;
            if (worst > stop_above) break;
        }
        return {worst, at};
    }
    bool ok(std::size_t p, std::size_t a, std::size_t b, std::size_t c) const {
        return segment_error(p, a, b, c, tol_) <= tol_;
    }

    /// [k_a, c_a+, c_b-, k_b], the keys signed as the curve signs them
    /// (each key the nearer of +-sample to the key before it).
    std::array<quat, 4> controls(std::size_t p, std::size_t a, std::size_t b, std::size_t c) const {
        auto align = [](const quat& q, const quat& prev) { return dot(prev, q) < 0 ? -q : q; };
        const quat kp = p == none ? quat{} : s_[p];
        const quat ka = p == none ? s_[a] : align(s_[a], kp);
        const quat kb = align(s_[b], ka);
        const quat kc = c == none ? quat{} : align(s_[c], kb);
        // The tangent-space construction with T = C = B = 0 (every weight 1),
        // written as build_kochanek_bartels writes it.
        auto control = [&](const quat& prev, const quat& here, const quat& next, T tp, T th, T tn, bool plus) {
            const T dm = th - tp, dp = tn - th;
            const vec3<T> rin = dm > 0 ? log(rel(prev, here)) / dm : vec3<T>{};
            const vec3<T> rout = dp > 0 ? log(rel(here, next)) / dp : vec3<T>{};
            const T one = 1, sum = dm + dp;
            const vec3<T> w = sum > 0 ? (one * dp * rin + one * dm * rout) / sum : vec3<T>{};
            return plus ? exp(w * (dp / 3)) * here : exp(w * (-dm / 3)) * here;
        };
        quat plus{}, minus{};
        if (p == none && c == none) {
            const quat r = rel(ka, kb);  // two keys: exactly slerp
            plus = pow(r, T(1) / 3) * ka;
            minus = pow(r, -T(1) / 3) * kb;
        } else if (p == none) {
            minus = control(ka, kb, kc, t_[a], t_[b], t_[c], false);
            plus = slerp(ka, minus, T(0.5));  // the natural end
        } else if (c == none) {
            plus = control(kp, ka, kb, t_[p], t_[a], t_[b], true);
            minus = slerp(kb, plus, T(0.5));
        } else {
            plus = control(kp, ka, kb, t_[p], t_[a], t_[b], true);
            minus = control(ka, kb, kc, t_[a], t_[b], t_[c], false);
        }
        return {ka, plus, minus, kb};
    }

    /// The segment at local u, as quaternion_spline's scalar evaluate().
    static quat evaluate(const std::array<quat, 4>& k, T u, T du) noexcept {
        std::array<so3::jet<T>, 4> level{};
        for (std::size_t j = 0; j < 4; ++j) level[j] = so3::constant(k[j]);
        for (std::size_t m = 4; m > 1; --m)
            for (std::size_t j = 0; j + 1 < m; ++j) level[j] = so3::slerp_jet(level[j], level[j + 1], u, du, T(0), 0);
        return level[0].q;
    }

private:
    std::span<const T> t_;
    std::span<const quat> s_;
    T tol_;
};

/// Whether segments first .. last (clamped to the curve's) of the curve on
/// key list `keys` (sorted sample indices) pass.
template <class T>
bool segments_ok(const fit_window<T>& w, const std::vector<std::size_t>& keys, std::ptrdiff_t first, std::ptrdiff_t last) {
    const auto m = std::ptrdiff_t(keys.size());
    for (std::ptrdiff_t j = std::max<std::ptrdiff_t>(first, 0); j <= std::min(last, m - 2); ++j) {
        const std::size_t p = j > 0 ? keys[std::size_t(j - 1)] : none, c = j + 2 < m ? keys[std::size_t(j + 2)] : none;
        if (!w.ok(p, keys[std::size_t(j)], keys[std::size_t(j + 1)], c)) return false;
    }
    return true;
}

/// The fewest keys (first and last sample included) whose curve passes
/// every segment test: dynamic programming over the last three keys,
/// O(n^4) segment tests. For tests on short sequences (the true optimum
/// the fit's count is compared with).
template <class T>
std::size_t minimum_keys(const fit_window<T>& w) {
    const std::size_t n = w.size();
    if (n <= 2) return n;
    constexpr std::size_t inf = none;
    // best[p][a][b] (p = n for none): fewest keys up to b, keys ... p, a, b,
    // every segment before (a, b) passed.
    const std::size_t P = n + 1;
    std::vector<std::size_t> best(P * n * n, inf);
    auto at = [&](std::size_t p, std::size_t a, std::size_t b) -> std::size_t& { return best[(p * n + a) * n + b]; };
    for (std::size_t b = 1; b < n; ++b) at(n, 0, b) = 2;
    std::size_t answer = inf;
    for (std::size_t b = 1; b < n; ++b)
        for (std::size_t a = 0; a < b; ++a)
            for (std::size_t p = 0; p <= n; ++p) {
                if (p != n && p >= a) continue;
                const std::size_t here = at(p, a, b);
                if (here == inf) continue;
                const std::size_t pp = p == n ? none : p;
                if (b == n - 1) {
                    if (here < answer && w.ok(pp, a, b, none)) answer = here;
                    continue;
                }
                for (std::size_t c = b + 1; c < n; ++c) {
                    std::size_t& next = at(a, b, c);
                    if (here + 1 < next && w.ok(pp, a, b, c)) next = here + 1;
                }
            }
    return answer;
}

}  // namespace crspline::rotation::detail_fit
