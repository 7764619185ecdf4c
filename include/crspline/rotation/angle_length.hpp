// crspline: the angle a rotation curve turns through, int |omega| dt, its
// inverse, and sampling at constant angular speed. The same table serves
// pose curves (pose.hpp), whose speed is a weighted mix of position speed
// and angular speed.
//
// Accuracy: relative, as arc_length's (default 1e-12): each segment is cut
// until an 8-point Gauss-Legendre rule and its two halves agree to
// accuracy * (the curve's total, estimated first on every segment), so the
// total is met to about that, give or take the rounding of the speed. The
// speed |omega| is analytic inside a segment except where omega passes
// through zero (a kink); the halving finds those too, at the cost of more
// pieces.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "../detail/format.hpp"
#include "../error.hpp"
#include "so3.hpp"

namespace crspline::rotation {

inline constexpr double default_angle_accuracy = 1e-12;

/// Cumulative length of a nonnegative speed over a grid of segments, with
/// its inverse. speed(i, t) is the speed on segment i at t.
template <class T = double>
class speed_table {
public:
    using speed_fn = std::function<T(std::size_t, T)>;

    speed_table(std::span<const T> grid, speed_fn speed, T accuracy = T(default_angle_accuracy))
        : speed_(std::move(speed)), grid_(grid.begin(), grid.end()) {
        if (!(accuracy > 0 && accuracy < 1))
            throw invalid_input("accuracy must be in (0, 1), got " + detail::num(double(accuracy)));
        const T acc = std::max(accuracy, T(8) * std::numeric_limits<T>::epsilon());
        // 1. A first estimate of the total: one rule per segment.
        T rough = 0;
        for (std::size_t i = 0; i + 1 < grid_.size(); ++i) rough += rule(i, grid_[i], grid_[i + 1]);
        tolerance_ = acc * std::max(rough, std::numeric_limits<T>::min());
        // 2. Pieces, segment by segment, each met to its share of the tolerance.
        piece_start_.push_back(0);
        T total = 0;
        for (std::size_t i = 0; i + 1 < grid_.size(); ++i) {
            const T a = grid_[i], b = grid_[i + 1];
            if (b > a) refine(i, a, b, rule(i, a, b), 0, total);
            piece_start_.push_back(pieces_.size());
        }
        total_ = total;
    }

    T total() const noexcept { return total_; }

    /// The length from the start to t (t clamped to the domain).
    T length_at(T t) const noexcept {
        t = std::clamp(t, grid_.front(), grid_.back());
        const auto it = std::upper_bound(pieces_.begin(), pieces_.end(), t, [](T x, const piece& p) { return x < p.t0; });
        if (it == pieces_.begin()) return 0;
        const piece& p = *(it - 1);
        if (t >= p.t1) return p.before + p.length;
        return p.before + rule(p.segment, p.t0, t);
    }

    /// The t where the length from the start is s (s clamped to [0, total]).
    /// Newton's method on the piece that holds s, kept inside its bracket
    /// (bisection when a step leaves it); to a few ulps of t.
    T t_at(T s) const noexcept {
        if (pieces_.empty()) return grid_.front();
        s = std::clamp(s, T(0), total_);
        auto it = std::upper_bound(pieces_.begin(), pieces_.end(), s, [](T x, const piece& p) { return x < p.before; });
        const piece& p = it == pieces_.begin() ? pieces_.front() : *(it - 1);
        const T target = s - p.before;
        if (target <= 0) return p.t0;
        if (target >= p.length) return p.t1;
        T lo = p.t0, hi = p.t1;
        T t = p.t0 + (p.t1 - p.t0) * (target / p.length);
        for (int k = 0; k < 60; ++k) {
            const T f = rule(p.segment, p.t0, t) - target;
            if (f > 0) hi = t;
            else lo = t;
            const T v = speed_(p.segment, t);
            T next = v > 0 ? t - f / v : T(0.5) * (lo + hi);
            if (!(next > lo && next < hi)) next = T(0.5) * (lo + hi);
            if (std::abs(next - t) <= T(4) * std::numeric_limits<T>::epsilon() * std::max(std::abs(t), T(1)) ||
                hi - lo <= T(4) * std::numeric_limits<T>::epsilon() * std::max(std::abs(t), T(1)))
                return next;
            t = next;
        }
        return t;
    }

    /// n parameter values at equal steps of length from the start to the end
    /// (n >= 2; uniform in t when the total is 0: a curve that does not move).
    std::vector<T> equal_steps(std::size_t n) const {
        if (n < 2) throw invalid_input("sampling needs at least 2 samples, got " + std::to_string(n));
        std::vector<T> t(n);
        for (std::size_t k = 0; k < n; ++k) {
            const T f = T(k) / T(n - 1);
            t[k] = total_ > 0 ? t_at(f * total_) : grid_.front() + f * (grid_.back() - grid_.front());
        }
        t.front() = grid_.front(), t.back() = grid_.back();
        return t;
    }

    std::size_t piece_count() const noexcept { return pieces_.size(); }

private:
    struct piece {
        std::size_t segment;
        T t0, t1, before, length;
    };
    speed_fn speed_;
    std::vector<T> grid_;
    std::vector<piece> pieces_;
    std::vector<std::size_t> piece_start_;
    T total_ = 0, tolerance_ = 0;

    // 8-point Gauss-Legendre on [a, b] of segment i.
    T rule(std::size_t i, T a, T b) const {
        static constexpr std::array<double, 4> x{0.1834346424956498049394761, 0.5255324099163289858177390,
                                                 0.7966664774136267395915539, 0.9602898564975362316835609};
        static constexpr std::array<double, 4> w{0.3626837833783619829651504, 0.3137066458778872873379622,
                                                 0.2223810344533744705443560, 0.1012285362903762591525314};
        const T m = (a + b) / 2, h = (b - a) / 2;
        T s = 0;
        for (std::size_t k = 0; k < 4; ++k) s += T(w[k]) * (speed_(i, m - h * T(x[k])) + speed_(i, m + h * T(x[k])));
        return s * h;
    }

    void refine(std::size_t i, T a, T b, T whole, int depth, T& total) {
        const T m = (a + b) / 2;
        const T left = rule(i, a, m), right = rule(i, m, b);
        // The piece's share of the tolerance is its share of the parameter range.
        const T share = tolerance_ * (b - a) / (grid_.back() - grid_.front());
        if (std::abs(left + right - whole) <= share || depth >= 40 || !(m > a && m < b)) {
            pieces_.push_back({i, a, b, total, left + right});
            total += left + right;
            return;
        }
        refine(i, a, m, left, depth + 1, total);
        refine(i, m, b, right, depth + 1, total);
    }
};

/// The angle table of a rotation curve (quaternion_spline or
/// c2_rotation_spline): speed |omega(t)|.
template <class Curve, class T = double>
speed_table<T> angle_table(const Curve& c, T accuracy = T(default_angle_accuracy)) {
    const Curve* p = &c;
    return speed_table<T>(c.grid(), [p](std::size_t i, T t) { return crspline::norm(p->evaluate_on(i, t, 1).omega); },
                          accuracy);
}

/// The total angle int |omega| dt the curve turns through (radians).
template <class Curve, class T = double>
T angle_length(const Curve& c, T accuracy = T(default_angle_accuracy)) {
    return angle_table(c, accuracy).total();
}

/// n parameter values at constant angular speed from the start to the end.
template <class Curve, class T = double>
std::vector<T> constant_angular_speed_times(const Curve& c, std::size_t n, T accuracy = T(default_angle_accuracy)) {
    return angle_table(c, accuracy).equal_steps(n);
}

}  // namespace crspline::rotation
