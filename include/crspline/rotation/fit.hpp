// crspline: rotation keyframe reduction. From a dense orientation stream
// (motion capture: times and unit quaternions) to the fewest keys, a subset
// of the samples, whose Catmull-Rom rotation curve (quaternion_spline, the
// samples' times as its grid, natural ends) is within an angle of every
// sample, proved at the samples.
//
// "Proved": for every sample time t_i, the rotation the returned curve gives
// at t_i (both evaluation paths, scalar evaluate() and the batch kernels)
// is within angle_tolerance of sample i, by detail_fit::angle_bound, whose
// rounding terms are derived beside it. The curve is not checked between the
// samples: a sample stream says nothing there.
//
// How the keys are chosen (detail/fit_window.hpp tests one segment, which
// depends on its two keys and one neighbour each side):
// 1. greedy: from the last key, the farthest next key whose segment passes,
//    the key after it guessed at the same spacing (gallop, then bisection);
//    then every segment tested with its true neighbours, a failing one
//    given its worst sample as a key;
// 2. removal: each interior key is dropped where the three segments that
//    change still pass;
// 3. proof on the curve itself; a segment whose samples fail (the guess of
//    step 1 was wrong, or the batch path rounds differently) gets its worst
//    sample as a key, and steps 2-3 run again.
// The count stays within a few percent of the true minimum (dynamic
// programming over three keys, detail_fit::minimum_keys) on the test
// corpus, tests/rotation/test_rotation_fit.cpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "../detail/format.hpp"
#include "../error.hpp"
#include "catmull_rom.hpp"
#include "detail/fit_window.hpp"
#include "quaternion.hpp"

namespace crspline::rotation {

template <class T = double>
struct rotation_fit_options {
    /// Samples are normalized (as the curves' keys are, and SciPy's from_quat);
    /// zero and non-finite ones are refused, and with a finite tolerance also
    /// those farther than it from unit norm.
    T unit_tolerance = std::numeric_limits<T>::infinity();
};

/// What fit() returns: the kept samples and their curve.
template <class T = double>
struct rotation_fit {
    std::vector<std::size_t> indices;    ///< kept sample indices, increasing; first and last always
    std::vector<T> times;                ///< their times (the curve's grid)
    std::vector<quaternion<T>> keys;     ///< their quaternions, normalized and signed as the curve signs them
    quaternion_spline<T> curve;          ///< Catmull-Rom, grid = times, natural ends
    T max_angle = 0;                     ///< the proved largest angle at the samples (radians, <= tolerance)
    std::size_t worst = 0;               ///< the sample where max_angle is reached
    std::size_t count() const noexcept { return indices.size(); }
};

namespace detail_fit {

/// The smallest tolerance the proof can resolve: a key's own bound is
/// 32 eps (angle_bound), the last sample's (evaluated at u = 1) a few eps
/// more; 1e4 eps leaves room for both.
template <class T>
constexpr T min_tolerance() noexcept { return T(1e4) * std::numeric_limits<T>::epsilon(); }

template <class T>
quaternion_spline<T> curve_on(std::span<const T> times, std::span<const quaternion<T>> s, const std::vector<std::size_t>& keys) {
    std::vector<quaternion<T>> k;
    std::vector<T> g;
    for (const std::size_t i : keys) k.push_back(s[i]), g.push_back(times[i]);
    rotation_options<T> o;
    o.grid = std::move(g);
    return quaternion_spline<T>(k, o);
}

/// The bound at every sample, the larger of the scalar and the batch path's.
template <class T>
std::vector<T> sample_bounds(const quaternion_spline<T>& c, std::span<const T> times, std::span<const quaternion<T>> s) {
    std::vector<quaternion<T>> batch(times.size());
    c.evaluate(times, std::span<quaternion<T>>(batch));
    std::vector<T> e(times.size());
    for (std::size_t i = 0; i < times.size(); ++i) e[i] = std::max(angle_bound(c(times[i]), s[i]), angle_bound(batch[i], s[i]));
    return e;
}

template <class T>
std::vector<std::size_t> greedy(const fit_window<T>& w, std::span<const T>) {
    const std::size_t n = w.size();
    std::vector<std::size_t> keys{0};
    std::size_t p = none, a = 0;
    while (a + 1 < n) {
        // The key after b is guessed at b's spacing: the tangent at b sees a
        // chord of about the segment's own length, as the next segment will.
        auto good = [&](std::size_t b) { return w.ok(p, a, b, b + 1 >= n ? none : std::min(n - 1, b + (b - a))); };
        std::size_t lo = a + 1, hi = none;  // (a, a + 1) carries no sample: it always passes
        for (std::size_t d = 2;; d *= 2) {
            const std::size_t b = std::min(n - 1, a + d);
            if (!good(b)) {
                hi = b;
                break;
            }
            lo = b;
            if (b == n - 1) break;
        }
        while (hi != none && hi - lo > 1) {
            const std::size_t mid = lo + (hi - lo) / 2;
            (good(mid) ? lo : hi) = mid;
        }
        keys.push_back(lo);
        p = a, a = lo;
    }
    return keys;
}

/// Makes every segment pass the window test with its true neighbours (the
/// greedy step guessed the key after each): a failing segment gets its
/// worst sample as a key, and the test steps back over the two segments
/// whose windows that key entered.
template <class T>
void window_repair(const fit_window<T>& w, std::vector<std::size_t>& keys) {
    const T tol = w.tolerance();
    for (std::size_t j = 0; j + 1 < keys.size();) {
        const std::size_t p = j > 0 ? keys[j - 1] : none, c = j + 2 < keys.size() ? keys[j + 2] : none;
        const auto [e, at] = w.segment_worst(p, keys[j], keys[j + 1], c, std::numeric_limits<T>::infinity());
        if (!(e > tol) || at == none || at == keys[j + 1]) {
            ++j;  // passed (or only the end key fails: the proof below reports that)
            continue;
        }
        keys.insert(keys.begin() + std::ptrdiff_t(j + 1), at);
        j = j >= 2 ? j - 2 : 0;
    }
}

/// Drops interior keys while the segments that change (new indices j - 2 ..
/// j, whose windows lie within old keys j - 3 .. j + 3) still pass. A window
/// cut short of the curve's ends is never looked past: the changed segments'
/// neighbours are inside it. Pinned samples (added by the proof) stay.
template <class T>
bool remove_keys(const fit_window<T>& w, std::vector<std::size_t>& keys, const std::vector<bool>& pinned) {
    bool changed = false;
    std::vector<std::size_t> local;
    for (std::size_t j = 1; j + 1 < keys.size();) {
        if (pinned[keys[j]]) {
            ++j;
            continue;
        }
        const std::size_t from = j >= 3 ? j - 3 : 0, to = std::min(keys.size() - 1, j + 3);
        local.clear();
        for (std::size_t k = from; k <= to; ++k)
            if (k != j) local.push_back(keys[k]);
        const auto jl = std::ptrdiff_t(j - from);
        if (segments_ok(w, local, jl - 2, jl)) {
            keys.erase(keys.begin() + std::ptrdiff_t(j));
            changed = true;
        } else {
            ++j;
        }
    }
    return changed;
}

}  // namespace detail_fit

/// The fewest keys (a subset of the samples, the first and last kept) whose
/// Catmull-Rom rotation curve is within angle_tolerance (radians) of every
/// sample at its time. times: finite, strictly increasing; samples:
/// quaternions [w, x, y, z], nonzero (normalized here; signs free). Bad input
/// is an invalid_input naming the field, index and value.
template <class T>
rotation_fit<T> fit(std::span<const T> times, std::span<const quaternion<T>> samples, T angle_tolerance,
                    const rotation_fit_options<T>& opt = {}) {
    using namespace detail_fit;
    // 1. Check the input once, here.
    if (!(angle_tolerance > 0) || !std::isfinite(angle_tolerance))
        throw invalid_input("angle_tolerance must be a positive finite angle in radians, got " + detail::num(double(angle_tolerance)));
    if (angle_tolerance < min_tolerance<T>())
        throw invalid_input("angle_tolerance " + detail::num(double(angle_tolerance)) +
                            " rad is below what rounding lets the proof resolve (" + detail::num(double(min_tolerance<T>())) +
                            " rad)");
    if (times.size() != samples.size())
        throw invalid_input("times has " + std::to_string(times.size()) + " values and quaternions " +
                            std::to_string(samples.size()) + " rows: one time per sample");
    const std::size_t n = samples.size();
    if (n < 2) throw invalid_input("a rotation fit needs at least 2 samples, got " + std::to_string(n));
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(times[i]))
            throw invalid_input("times " + std::to_string(i) + " is not finite (" + detail::num(double(times[i])) + ")");
        if (i > 0 && !(times[i] > times[i - 1]))
            throw invalid_input("times is not increasing at index " + std::to_string(i) + " (" +
                                detail::num(double(times[i - 1])) + " then " + detail::num(double(times[i])) + ")");
    }
    std::vector<quaternion<T>> s(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto a = samples[i].array();
        const bool finite = std::all_of(a.begin(), a.end(), [](T x) { return std::isfinite(x); });
        if (finite && !(norm(samples[i]) > 0))
            throw invalid_input("sample " + std::to_string(i) + " [0, 0, 0, 0] has norm 0: not a rotation");  // as checked_unit words it
        s[i] = checked_unit(samples[i], i, opt.unit_tolerance, "sample");  // names a non-finite component
    }
    const fit_window<T> w(times, s, angle_tolerance);

    // 2. Choose, then prove on the curve and repair, until proved.
    std::vector<std::size_t> keys = greedy(w, times);
    window_repair(w, keys);
    std::vector<bool> pinned(n, false);
    remove_keys(w, keys, pinned);
    for (;;) {
        const auto c = curve_on<T>(times, s, keys);
        const auto e = sample_bounds(c, times, std::span<const quaternion<T>>(s));
        std::vector<std::size_t> add;
        for (std::size_t j = 0; j + 1 < keys.size(); ++j) {
            const std::size_t end = j + 2 == keys.size() ? keys[j + 1] : keys[j + 1] - 1;
            std::size_t worst = none;
            for (std::size_t i = keys[j]; i <= end; ++i)
                if (e[i] > angle_tolerance && (worst == none || e[i] > e[worst])) worst = i;
            if (worst == none) continue;
            if (worst == keys[j] || worst == keys[j + 1])
                throw invalid_input("angle_tolerance " + detail::num(double(angle_tolerance)) +
                                    " rad cannot be proved even at key " + std::to_string(worst) + " (bound " +
                                    detail::num(double(e[worst])) + " rad): it is below the rounding of the evaluation");
            add.push_back(worst);
            pinned[worst] = true;  // the window test passed what the curve fails: keep it, or the two would loop
        }
        if (add.empty()) {
            rotation_fit<T> r{keys, {}, {}, c, 0, 0};
            for (const std::size_t i : keys) r.times.push_back(times[i]);
            r.keys.assign(c.keys().begin(), c.keys().end());
            const auto it = std::max_element(e.begin(), e.end());
            r.max_angle = *it;
            r.worst = std::size_t(it - e.begin());
            return r;
        }
        keys.insert(keys.end(), add.begin(), add.end());
        std::sort(keys.begin(), keys.end());
        // The added keys changed their neighbours' segments too: test them
        // again and let removal look again (the proof above decides).
        window_repair(w, keys);
        remove_keys(w, keys, pinned);
    }
}

template <class T>
rotation_fit<T> fit(const std::vector<T>& times, const std::vector<quaternion<T>>& samples, T angle_tolerance,
                    const rotation_fit_options<T>& opt = {}) {
    return fit(std::span<const T>(times), std::span<const quaternion<T>>(samples), angle_tolerance, opt);
}

}  // namespace crspline::rotation
