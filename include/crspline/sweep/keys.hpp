// crspline sweeps, internals: the functions a sweep carries along its curve
// besides the frame, each a piecewise cubic with bounds on its derivatives:
//
//   roll   angles about the tangent, keyed at knots or at arc lengths and
//          interpolated by the rotation splines (rotation/catmull_rom.hpp):
//          keys q_k = rotation by theta_k about one axis. Slerps of
//          rotations about one axis turn about that axis by the linear
//          interpolation of their angles, so the De Casteljau curve of
//          slerps through the keys is, angle for angle, the cubic Bézier
//          curve of its control rotations' angles. That is how the roll is
//          evaluated and bounded here; tests check it against the rotation
//          spline's own evaluate().
//   scale  a factor on the profile keyed at arc lengths, interpolated by a
//          1-D Catmull-Rom curve whose parameter is the arc length itself
//          (an explicit grid), held constant before the first key and after
//          the last.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "../catmull_rom.hpp"
#include "../detail/format.hpp"
#include "../error.hpp"
#include "../rotation/catmull_rom.hpp"

namespace crspline::detail {

/// A cubic Bézier function on [w0, w1] with value and derivative bounds.
struct cubic_piece {
    double w0 = 0, w1 = 1;
    std::array<double, 4> b{};

    double value(double w) const noexcept {
        const double g = w1 - w0, u = g > 0 ? std::clamp((w - w0) / g, 0.0, 1.0) : 0.0, v = 1 - u;
        return v * v * v * b[0] + 3 * u * v * v * b[1] + 3 * u * u * v * b[2] + u * u * u * b[3];
    }
    /// Bounds from the control polygon (the hull property of the Bernstein
    /// basis, for the function and its derivatives' controls):
    /// |f| <= max|b|, |f'| <= 3 max|b_(j+1) - b_j| / g, |f''| <= 6 max|second differences| / g^2.
    double max_abs() const noexcept {
        return std::max({std::abs(b[0]), std::abs(b[1]), std::abs(b[2]), std::abs(b[3])});
    }
    double max_d1() const noexcept {
        const double g = w1 - w0;
        if (!(g > 0)) return 0;
        return 3 * std::max({std::abs(b[1] - b[0]), std::abs(b[2] - b[1]), std::abs(b[3] - b[2])}) / g;
    }
    double max_d2() const noexcept {
        const double g = w1 - w0;
        if (!(g > 0)) return 0;
        return 6 * std::max(std::abs(b[2] - 2 * b[1] + b[0]), std::abs(b[3] - 2 * b[2] + b[1])) / (g * g);
    }
    double min_value() const noexcept {
        // The exact minimum: the ends and the zeros of the derivative (a quadratic).
        double m = std::min(b[0], b[3]);
        const double a = 3 * (-b[0] + 3 * b[1] - 3 * b[2] + b[3]), bb = 6 * (b[0] - 2 * b[1] + b[2]),
                     c = 3 * (b[1] - b[0]);
        const auto at = [&](double u) {
            if (u > 0 && u < 1) m = std::min(m, value(w0 + u * (w1 - w0)));
        };
        if (std::abs(a) > 1e-300) {
            const double disc = bb * bb - 4 * a * c;
            if (disc >= 0) {
                const double r = std::sqrt(disc);
                at((-bb + r) / (2 * a));
                at((-bb - r) / (2 * a));
            }
        } else if (std::abs(bb) > 1e-300) {
            at(-c / bb);
        }
        return m;
    }
};

/// A piecewise cubic over increasing breaks, constant outside them.
struct piecewise_cubic {
    std::vector<cubic_piece> pieces;
    bool periodic = false;  ///< arguments wrap into [front.w0, back.w1)

    bool empty() const noexcept { return pieces.empty(); }
    double wrap(double w) const noexcept {
        if (!periodic || pieces.empty()) return w;
        const double a = pieces.front().w0, p = pieces.back().w1 - a;
        double x = std::fmod(w - a, p);
        if (x < 0) x += p;
        return a + x;
    }
    std::size_t locate(double w) const noexcept {
        std::size_t lo = 0, hi = pieces.size();
        while (hi - lo > 1) {
            const std::size_t mid = (lo + hi) / 2;
            if (pieces[mid].w0 <= w) lo = mid;
            else hi = mid;
        }
        return lo;
    }
    /// Periodic: the value carries whole turns (`turn` per period) so that
    /// it continues across periods.
    double value(double w, double turn = 0) const noexcept {
        if (pieces.empty()) return 0;
        double shift = 0;
        if (periodic) {
            const double a = pieces.front().w0, p = pieces.back().w1 - a;
            shift = std::floor((w - a) / p) * turn;
            w = wrap(w);
        }
        if (w <= pieces.front().w0) return pieces.front().b[0] + shift;
        if (w >= pieces.back().w1) return pieces.back().b[3] + shift;
        return pieces[locate(w)].value(w) + shift;
    }
    /// df/dw (0 outside the keys).
    double slope(double w) const noexcept {
        if (pieces.empty()) return 0;
        w = wrap(w);
        if (w < pieces.front().w0 || w > pieces.back().w1) return 0;
        const auto& p = pieces[locate(w)];
        const double g = p.w1 - p.w0;
        if (!(g > 0)) return 0;
        const double u = std::clamp((w - p.w0) / g, 0.0, 1.0), v = 1 - u;
        return 3 * (v * v * (p.b[1] - p.b[0]) + 2 * u * v * (p.b[2] - p.b[1]) + u * u * (p.b[3] - p.b[2])) / g;
    }
    /// Bounds on |f|, |f'|, |f''| over [a, b] (b - a less than one period).
    std::array<double, 3> bounds(double a, double b) const noexcept {
        std::array<double, 3> r{0, 0, 0};
        if (pieces.empty()) return r;
        if (periodic) {
            const double wa = wrap(a), wb = wa + (b - a);
            const double end = pieces.back().w1, p = end - pieces.front().w0;
            if (wb > end) {
                const auto x = bounds_in(wa, end), y = bounds_in(pieces.front().w0, wb - p);
                return {std::max(x[0], y[0]), std::max(x[1], y[1]), std::max(x[2], y[2])};
            }
            return bounds_in(wa, wb);
        }
        return bounds_in(a, b);
    }

private:
    std::array<double, 3> bounds_in(double a, double b) const noexcept {
        std::array<double, 3> r{0, 0, 0};
        bool any = false;
        for (const auto& p : pieces) {
            if (p.w1 <= a || p.w0 >= b) continue;
            any = true;
            r = {std::max(r[0], p.max_abs()), std::max(r[1], p.max_d1()), std::max(r[2], p.max_d2())};
        }
        if (!any) {  // constant stretch outside the keys, or [a, b] inside one piece boundary
            r[0] = std::max(std::abs(value(a)), std::abs(value(b)));
            if (a >= pieces.front().w0 && b <= pieces.back().w1) {
                const auto& p = pieces[locate(a)];
                r = {p.max_abs(), p.max_d1(), p.max_d2()};
            }
        }
        return r;
    }
};

inline void check_keys(const char* field, const std::vector<double>& at, const std::vector<double>& values,
                       const char* value_name) {
    if (at.size() != values.size())
        throw spec_error(field, std::nullopt, std::nullopt, std::to_string(values.size()),
                         std::string(field) + ": " + std::to_string(values.size()) + " " + value_name + " for " +
                             std::to_string(at.size()) + " positions");
    for (std::size_t k = 0; k < values.size(); ++k) {
        if (!std::isfinite(at[k]))
            throw spec_error(field, k, std::nullopt, num(at[k]),
                             std::string(field) + "[" + std::to_string(k) + "]: position " + num(at[k]) +
                                 " is not finite");
        if (!std::isfinite(values[k]))
            throw spec_error(field, k, std::nullopt, num(values[k]),
                             std::string(field) + "[" + std::to_string(k) + "]: " + value_name + " " +
                                 num(values[k]) + " is not finite");
        if (k > 0 && !(at[k] > at[k - 1]))
            throw spec_error(field, k, std::nullopt, num(at[k]),
                             std::string(field) + "[" + std::to_string(k) + "]: positions must increase, got " +
                                 num(at[k - 1]) + " then " + num(at[k]));
    }
}

/// The roll as a piecewise cubic in w (t or arc length) through the keys
/// (w_k, theta_k): the rotation spline's curve through the rotations by
/// theta_k about one axis, read as angles. Consecutive keys (and on a
/// closed sweep the last and the first) must differ by less than pi: a
/// rotation spline takes the short way between keys. The pieces' end
/// controls are the keys themselves, so the roll hits each key exactly.
/// `period`: a closed sweep's length in w (keys in [w_0, w_0 + period)).
inline piecewise_cubic roll_function(const std::vector<double>& w, const std::vector<double>& theta,
                                     std::optional<double> period) {
    check_keys("roll", w, theta, "angles");
    piecewise_cubic f;
    const std::size_t n = theta.size();
    if (n == 0) return f;
    if (n == 1) {  // one key: a constant roll
        f.pieces.push_back({w[0], w[0], {theta[0], theta[0], theta[0], theta[0]}});
        return f;
    }
    const bool closed = period.has_value();
    if (closed && !(w.back() < w.front() + *period))
        throw spec_error("roll", n - 1, std::nullopt, num(w.back()),
                         "roll[" + std::to_string(n - 1) + "]: position " + num(w.back()) +
                             " is not within one period (" + num(*period) + ") of the first key");
    for (std::size_t k = 0; k + 1 < n + (closed ? 1 : 0); ++k) {
        const double a = theta[k], b = k + 1 < n ? theta[k + 1] : theta[0];
        // On a closed sweep the last step wraps to the first key, whole turns apart.
        const double step = k + 1 < n ? b - a : std::remainder(b - a, 2 * std::numbers::pi);
        if (!(std::abs(step) < std::numbers::pi))
            throw spec_error("roll", k + 1 < n ? k + 1 : 0, std::nullopt, num(b),
                             "roll[" + std::to_string(k + 1 < n ? k + 1 : 0) + "]: angle " + num(b) +
                                 " is pi or more from the previous key (" + num(a) +
                                 "); rotation splines take the short way, so add a key between them");
    }
    using quat = rotation::quaternion<double>;
    std::vector<quat> keys(n);
    for (std::size_t k = 0; k < n; ++k) keys[k] = {std::cos(theta[k] / 2), 0, 0, std::sin(theta[k] / 2)};
    rotation::rotation_options<double> opt;
    opt.kind = rotation::spline_kind::catmull_rom;
    std::vector<double> grid = w;
    if (closed) grid.push_back(w.front() + *period);
    opt.grid = grid;
    opt.closed = closed;
    const rotation::quaternion_spline<double> spline(std::span<const quat>(keys), opt);
    const auto controls = spline.control_quaternions();
    // Angles of the controls, each taken nearest the previous one (the short way).
    auto angle_near = [](const quat& q, double near) {
        const double a = 2 * std::atan2(q.z, q.w);
        return a + 2 * std::numbers::pi * std::round((near - a) / (2 * std::numbers::pi));
    };
    for (std::size_t i = 0; i + 1 < grid.size(); ++i) {
        const double a = theta[i];
        const double b = i + 1 < n ? theta[i + 1] : a + std::remainder(theta[0] - a, 2 * std::numbers::pi);
        cubic_piece p{grid[i], grid[i + 1], {a, a, b, b}};
        if (controls.size() > i && controls[i].size() == 4) {
            p.b[1] = angle_near(controls[i][1], a);
            p.b[2] = angle_near(controls[i][2], b);
        }
        f.pieces.push_back(p);
    }
    f.periodic = closed;
    return f;
}

/// The scale through the keys (s_k, scale_k): a 1-D Catmull-Rom curve
/// (natural ends) with the arc lengths as its grid, held constant before
/// the first key and after the last; on a closed sweep (`period`, the
/// length) a closed curve, so that the scale closes up too. Keys must be
/// positive; the interpolant must stay positive (it can dip between keys:
/// the error names where).
inline piecewise_cubic scale_function(const std::vector<double>& s, const std::vector<double>& scale,
                                      std::optional<double> period = std::nullopt) {
    check_keys("scale", s, scale, "values");
    for (std::size_t k = 0; k < scale.size(); ++k)
        if (!(scale[k] > 0))
            throw spec_error("scale", k, std::nullopt, num(scale[k]),
                             "scale[" + std::to_string(k) + "]: value " + num(scale[k]) + " must be positive");
    piecewise_cubic f;
    if (scale.empty()) return f;
    if (scale.size() == 1) {
        f.pieces.push_back({s[0], s[0], {scale[0], scale[0], scale[0], scale[0]}});
        return f;
    }
    const bool closed = period.has_value();
    if (closed && !(s.back() < s.front() + *period))
        throw spec_error("scale", s.size() - 1, std::nullopt, num(s.back()),
                         "scale[" + std::to_string(s.size() - 1) + "]: position " + num(s.back()) +
                             " is not within one length (" + num(*period) + ") of the first key");
    std::vector<vec<1>> pts(scale.size());
    for (std::size_t k = 0; k < scale.size(); ++k) pts[k][0] = scale[k];
    options<1> opt;
    std::vector<double> grid = s;
    if (closed) grid.push_back(s.front() + *period);
    opt.grid = grid;
    opt.closed = closed;
    const catmull_rom<1> c(pts, opt);
    for (std::size_t i = 0; i + 1 < grid.size(); ++i) {
        const auto b = c.bezier(i);
        cubic_piece p{grid[i], grid[i + 1], {b[0][0], b[1][0], b[2][0], b[3][0]}};
        const double m = p.min_value();
        if (!(m > 0))
            throw spec_error("scale", (i + 1) % scale.size(), std::nullopt, num(scale[(i + 1) % scale.size()]),
                             "scale: the interpolated scale falls to " + num(m) + " between keys " +
                                 std::to_string(i) + " and " + std::to_string((i + 1) % scale.size()) +
                                 " (it must stay positive); add keys there");
        f.pieces.push_back(p);
    }
    f.periodic = closed;
    return f;
}

}  // namespace crspline::detail
