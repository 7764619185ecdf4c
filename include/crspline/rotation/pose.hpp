// crspline: pose curves on SE(3), a 3-D position curve (crspline::catmull_rom)
// and a rotation curve on one shared grid, evaluated together: the camera
// path, the robot tool path.
//
// The grid comes from the positions (alpha, centripetal by default, as
// crspline::catmull_rom computes it) or is given; the rotation curve is then
// built on that grid: the C2 spline (c2.hpp, default) or a quaternion
// Catmull-Rom (catmull_rom.hpp). Positions that repeat with alpha > 0 give a
// zero knot interval, which a rotation curve cannot take (it may still turn
// there): give a grid, or alpha = 0, for such paths; the error says where.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "../catmull_rom.hpp"
#include "../detail/format.hpp"
#include "../error.hpp"
#include "angle_length.hpp"
#include "batch.hpp"
#include "c2.hpp"
#include "catmull_rom.hpp"

namespace crspline::rotation {

template <class T = double>
struct pose_options {
    std::optional<double> alpha{};         ///< on the positions; default centripetal (0.5)
    std::optional<std::vector<T>> grid{};  ///< explicit shared knots instead (N, or N + 1 closed)
    bool closed = false;
    end_condition<3, T> start = end_condition<3, T>::natural(), end = end_condition<3, T>::natural();  ///< positions
    bool c2_rotation = true;               ///< C2 rotation spline (SciPy's construction); else quaternion Catmull-Rom
    c2_end<T> rotation_start{}, rotation_end_{};  ///< C2 rotation ends (open curves)
};

/// Position, orientation and their rates at one t. Velocities in the frame
/// asked for: world (fixed axes) or body (the object's own axes, R^T v).
template <class T = double>
struct pose_sample {
    vec<3, T> position{};
    quaternion<T> orientation{};
    vec<3, T> velocity{};  ///< dx/dt
    vec3<T> omega{};       ///< angular velocity, rad per unit t
};

template <class T = double>
class pose_curve {
public:
    using point = vec<3, T>;
    using quat = quaternion<T>;

    pose_curve(std::span<const point> positions, std::span<const quat> rotations, const pose_options<T>& opt = {})
        : position_(positions, position_options(opt)), rotation_(build_rotation(positions.size(), rotations, opt)) {
        // The batch kernel's table: each segment's position cubic beside its rotation's.
        if (const auto* r = std::get_if<c2_rotation_spline<T>>(&rotation_)) {
            const auto rot = r->batch_segments();
            for (std::size_t i = 0; i < rot.size(); ++i) {
                const auto seg = position_.segment(i);
                detail_batch::pose_packed<T> p{};
                p.rot = rot[i];
                for (std::size_t d = 0; d < 3; ++d)
                    p.origin[d] = seg.origin[d], p.c1[d] = seg.c1[d], p.c2[d] = seg.c2[d], p.c3[d] = seg.c3[d];
                p.inv_h = seg.inv_h;
                packed_.push_back(p);
            }
        }
    }

    const catmull_rom<3, T>& position_curve() const noexcept { return position_; }
    std::span<const T> grid() const noexcept { return position_.grid(); }

    /// The pose at t; velocities in frame f.
    pose_sample<T> evaluate(T t, frame f = frame::world) const {
        if (!(t >= grid().front() && t <= grid().back()))
            throw out_of_domain("t = " + detail::num(double(t)) + " is outside the pose curve's domain [" +
                                detail::num(double(grid().front())) + ", " + detail::num(double(grid().back())) + "]");
        return at(t, f);
    }

    /// Batch evaluation (any order of t). With the C2 rotation, one kernel
    /// (batch.hpp's pose_block) does the position, velocity, rotation and
    /// angular velocity of each sample from one segment search; with a
    /// quaternion Catmull-Rom, chunks go through the position curve's batch
    /// and the rotation curve's. The same values as evaluate(t) to a few ulps.
    void evaluate(std::span<const T> t, std::span<pose_sample<T>> out, frame f = frame::world) const {
        evaluate(t, out, f, detail_batch::best_isa());
    }
    /// The same on a chosen path (the portable lanes or the AVX2 clone, which
    /// give the same bits): the seam the tests compare the two through.
    void evaluate(std::span<const T> t, std::span<pose_sample<T>> out, frame f, detail_batch::isa path) const {
        check_batch_size(out.size(), t.size(), "poses");
        const T lo = grid().front(), hi = grid().back();
        auto domain = [&](std::size_t k, T x) {
            if (!(x >= lo && x <= hi)) [[unlikely]]
                throw out_of_domain("t = " + detail::num(double(x)) + " (index " + std::to_string(k) +
                                    ") is outside the pose curve's domain [" + detail::num(double(lo)) + ", " +
                                    detail::num(double(hi)) + "]");
        };
        if (!packed_.empty()) {
            // C2 rotation: one pass, each sample's segment found once for both curves.
            const point last = position_.evaluate_unchecked(hi, 0);
            const T* g = grid().data();
            std::size_t hint = 0;
            detail_batch::run<T>(
                t,
                [&](std::size_t k, T x) {
                    domain(k, x);
                    if (!detail_batch::in_segment(g, hint, x)) hint = position_.locate(x);
                    return hint;
                },
                [&](auto lanes, const std::size_t* seg, const T* tl, std::size_t k, int valid) CRSPLINE_ROTATION_BLOCK {
                    detail_batch::pose_block<T, typename decltype(lanes)::type>(packed_.data(), seg, tl, k, valid, f, hi,
                                                                                 &last[0], out.data());
                },
                path);
            return;
        }
        constexpr std::size_t chunk = 1024;  // the chunk's arrays stay in the L1/L2 cache
        const std::size_t m = std::min(chunk, t.size());
        std::vector<point> pos(m), vel(m);
        std::vector<T> q(4 * m), w(3 * m);
        for (std::size_t k0 = 0; k0 < t.size(); k0 += chunk) {
            const std::size_t n = std::min(chunk, t.size() - k0);
            const std::span<const T> sub = t.subspan(k0, n);
            for (std::size_t k = 0; k < n; ++k) domain(k0 + k, sub[k]);
            position_.evaluate(sub, std::span<point>(pos.data(), n), 0);
            position_.evaluate(sub, std::span<point>(vel.data(), n), 1);
            batch_rows<T> rows;
            rows.q = q.data(), rows.omega = w.data();
            std::visit([&](const auto& r) { r.evaluate(sub, rows, 1, f); }, rotation_);
            for (std::size_t k = 0; k < n; ++k) {
                pose_sample<T>& s = out[k0 + k];
                s.position = pos[k];
                s.orientation = {q[4 * k], q[4 * k + 1], q[4 * k + 2], q[4 * k + 3]};
                s.velocity = f == frame::body ? rotate(conj(s.orientation), vel[k]) : vel[k];
                s.omega = vec3<T>{{w[3 * k], w[3 * k + 1], w[3 * k + 2]}};
            }
        }
    }
    std::vector<pose_sample<T>> evaluate(std::span<const T> t, frame f = frame::world) const {
        std::vector<pose_sample<T>> out(t.size());
        evaluate(t, std::span<pose_sample<T>>(out), f);
        return out;
    }

    /// n parameter values at constant speed of the weighted mix
    /// position_weight |dx/dt| + angle_weight |omega| (1, 0: constant speed
    /// along the path; 0, 1: constant angular speed; a length scale per radian
    /// in between), to relative accuracy `accuracy`.
    std::vector<T> constant_speed_times(std::size_t n, T position_weight = 1, T angle_weight = 0,
                                        T accuracy = T(default_angle_accuracy)) const {
        if (!(position_weight >= 0 && angle_weight >= 0 && position_weight + angle_weight > 0) ||
            !std::isfinite(position_weight) || !std::isfinite(angle_weight))
            throw invalid_input("constant_speed_times: weights must be finite, nonnegative and not both 0, got " +
                                detail::num(double(position_weight)) + " and " + detail::num(double(angle_weight)));
        const pose_curve* self = this;
        return speed_table<T>(grid(),
                              [self, position_weight, angle_weight](std::size_t i, T t) {
                                  T s = 0;
                                  if (position_weight > 0)
                                      {
                                      const auto seg = self->position_.segment(i);
                                      s += position_weight * crspline::norm(seg.dt(seg.local(t), 1));
                                  }
                                  if (angle_weight > 0) s += angle_weight * crspline::norm(self->rotation_jet(i, t, 1).omega);
                                  return s;
                              },
                              accuracy)
            .equal_steps(n);
    }

private:
    catmull_rom<3, T> position_;
    std::variant<c2_rotation_spline<T>, quaternion_spline<T>> rotation_;
    std::vector<detail_batch::pose_packed<T>> packed_;  // batch, C2 rotation: position and rotation per segment

    static options<3, T> position_options(const pose_options<T>& opt) {
        options<3, T> o;
        o.alpha = opt.alpha;
        o.grid = opt.grid;
        if (!opt.grid && !opt.alpha) o.alpha = 0.5;
        o.closed = opt.closed;
        o.start = opt.start, o.end = opt.end;
        return o;
    }

    decltype(rotation_) build_rotation(std::size_t npos, std::span<const quat> rotations, const pose_options<T>& opt) const {
        if (rotations.size() != npos)
            throw invalid_input("pose curve: " + std::to_string(npos) + " positions but " + std::to_string(rotations.size()) +
                                " rotations");
        const auto g = position_.grid();
        for (std::size_t k = 1; k < g.size(); ++k)
            if (!(g[k] > g[k - 1]))
                throw invalid_input("pose curve: positions " + std::to_string(k - 1) + " and " + std::to_string(k % npos) +
                                    " coincide, so the shared grid has a zero interval there (knot " + detail::num(double(g[k])) +
                                    "); give a grid or alpha = 0");
        if (opt.c2_rotation) {
            c2_options<T> o;
            o.closed = opt.closed, o.start = opt.rotation_start, o.end = opt.rotation_end_;
            return c2_rotation_spline<T>(g, rotations, o);
        }
        rotation_options<T> o;
        o.closed = opt.closed;
        o.grid = std::vector<T>(g.begin(), g.end());
        return quaternion_spline<T>(rotations, o);
    }

    so3::jet<T> rotation_jet(std::size_t i, T t, int order) const noexcept {
        return std::visit([&](const auto& r) { return r.evaluate_on(i, t, order); }, rotation_);
    }

    pose_sample<T> at(T t, frame f) const {
        const std::size_t i = position_.locate(t);
        const auto seg = position_.segment(i);
        const T u = seg.local(t);
        pose_sample<T> s;
        s.position = t == grid().back() ? position_.evaluate_unchecked(t, 0) : seg.at(u);
        s.velocity = seg.dt(u, 1);
        const auto j = rotation_jet(i, t, 1);
        s.orientation = j.q, s.omega = j.omega;
        if (f == frame::body) {
            s.velocity = rotate(conj(j.q), s.velocity);
            s.omega = rotate(conj(j.q), s.omega);
        }
        return s;
    }
};

}  // namespace crspline::rotation
