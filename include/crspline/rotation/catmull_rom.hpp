// crspline: rotation splines on unit quaternions, as `splines.quaternion`
// (0.3.3) builds them, with exact derivatives.
//
// Classes of curve (one type, quaternion_spline, the kind a named choice):
//   catmull_rom / kochanek_bartels: cubic De Casteljau segments of slerps,
//       [k_i, c_i+, c_(i+1)-, k_(i+1)], the control quaternions from the
//       tangent-space construction (see build_kochanek_bartels).
//   piecewise_slerp: slerp(k_i, k_(i+1), u), C0.
//   de_casteljau: given control quaternions per segment (any m >= 2).
//   barry_goldman: the Barry-Goldman pyramid of slerps.
//   squad: slerp(slerp(q_i, q_(i+1), u), slerp(s_i+, s_(i+1)-, u), 2u(1-u)).
// Every kind open or closed. Keys are made hemisphere-continuous by default,
// as `splines` does: walk the keys with p = [1, 0, 0, 0], negate q when
// dot(p, q) < 0, then p = q. keep_signs keeps them as given (a negative dot
// then takes the long way).
//
// The grid: explicit, or alpha: t(i+1) = t(i) + theta_i^alpha, theta_i the
// rotation angle between consecutive keys as travelled, 4 atan2(|a - b|,
// |a + b|) (2 acos(a . b) loses half the digits for near keys). A repeated
// key (theta 0) with alpha > 0 gives a zero interval: the curve's continuous
// limit, as coincident points in crspline::catmull_rom; strict refuses it.
//
// Derivatives (order 1 and 2) are exact: the angular velocity and
// acceleration of the curve itself in the world or the body frame, analytic
// inside segments (so3::slerp_jet), not the package's evaluate(t, 1)
// formula, which is exact at the keys only.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "../detail/format.hpp"
#include "../detail/knot_index.hpp"
#include "../error.hpp"
#include "batch.hpp"
#include "quaternion.hpp"
#include "so3.hpp"

namespace crspline::rotation {

enum class spline_kind { catmull_rom, kochanek_bartels, piecewise_slerp, de_casteljau, barry_goldman, squad };

/// An end of an open Catmull-Rom / Kochanek-Bartels rotation curve.
template <class T = double>
struct rotation_end {
    enum class kind {
        natural,          ///< the documented form: c_0+ = slerp(k_0, c_1-, 1/2) (the Euclidean natural end's analogue)
        natural_splines,  ///< what `splines` 0.3.3 computes: c_0+ = slerp(k_0, k_1, 1/2)
        angular_velocity  ///< the given angular velocity at the end key (rad per unit t)
    };
    kind type = kind::natural;
    vec3<T> omega{};
    frame omega_frame = frame::world;

    static rotation_end natural() { return {}; }
    static rotation_end natural_splines() { return {kind::natural_splines, {}, frame::world}; }
    static rotation_end velocity(const vec3<T>& w, frame f = frame::world) { return {kind::angular_velocity, w, f}; }
};

template <class T = double>
struct tcb {
    T tension = 0, continuity = 0, bias = 0;
};

template <class T = double>
struct rotation_options {
    spline_kind kind = spline_kind::catmull_rom;
    std::optional<double> alpha{};         ///< on the rotation angle, in [0, 1]; none and no grid: uniform 0, 1, 2...
    std::optional<std::vector<T>> grid{};  ///< explicit knots (N, or N + 1 closed); strictly increasing
    bool closed = false;
    rotation_end<T> start{}, end{};        ///< open Catmull-Rom / Kochanek-Bartels only
    std::vector<tcb<T>> kb{};              ///< one triple for all keys, or one per key that uses it
    bool keep_signs = false;               ///< do not make the keys hemisphere-continuous
    bool strict = false;                   ///< refuse repeated consecutive keys when alpha > 0
    /// Keys are normalized (as SciPy's from_quat); zero and non-finite keys are
    /// refused. A finite tolerance also refuses keys farther from unit norm.
    T unit_tolerance = std::numeric_limits<T>::infinity();
};

/// A rotation curve through unit quaternions. t runs over [grid.front(),
/// grid.back()]; segment i is [grid[i], grid[i+1]] (an interior knot belongs
/// to the segment on its right, the last knot to the last segment).
template <class T = double>
class quaternion_spline {
public:
    using quat = quaternion<T>;

    quaternion_spline(std::span<const quat> keys, const rotation_options<T>& opt = {}) { build(keys, opt); }

    /// De Casteljau curve from control quaternions per segment (as given, no
    /// sign change) and a grid of segments + 1 values (default 0, 1, 2...).
    static quaternion_spline de_casteljau(const std::vector<std::vector<quat>>& segments,
                                          std::optional<std::vector<T>> grid = std::nullopt,
                                          T unit_tolerance = T(1e-6)) {
        quaternion_spline s;
        s.kind_ = spline_kind::de_casteljau;
        if (segments.empty()) throw invalid_input("de_casteljau: needs at least one segment");
        for (std::size_t i = 0; i < segments.size(); ++i) {
            if (segments[i].size() < 2)
                throw invalid_input("de_casteljau: segment " + std::to_string(i) + " has " +
                                    std::to_string(segments[i].size()) + " control quaternions (at least 2)");
            std::vector<quat> c;
            for (std::size_t j = 0; j < segments[i].size(); ++j)
                c.push_back(checked_unit(segments[i][j], j, unit_tolerance, ("segment " + std::to_string(i) + " control").c_str()));
            s.controls_.push_back(std::move(c));
        }
        s.set_grid(segments.size() + 1, grid, std::nullopt, false);
        for (const auto& c : s.controls_) s.keys_.push_back(c.front());
        s.keys_.push_back(s.controls_.back().back());
        s.finish();
        return s;
    }

    spline_kind kind() const noexcept { return kind_; }
    bool closed() const noexcept { return closed_; }
    /// The keys the curve interpolates, after the sign rule (closed: N + 1, the last +-key 0).
    std::span<const quat> keys() const noexcept { return keys_; }
    std::span<const T> grid() const noexcept { return grid_; }
    std::size_t segment_count() const noexcept { return grid_.size() - 1; }
    /// Control quaternions per segment (De Casteljau family: the Bézier-like
    /// controls; squad: [q_i, s_i+, s_(i+1)-, q_(i+1)]; others empty).
    std::span<const std::vector<quat>> control_quaternions() const noexcept { return controls_; }

    /// The segment that t falls in (t clamped to the domain).
    std::size_t locate(T t) const noexcept {
        const std::size_t nseg = segment_count();
        std::size_t i = std::size_t(std::upper_bound(grid_.begin(), grid_.end(), t) - grid_.begin());
        i = i == 0 ? 0 : i - 1;
        if (i >= nseg) i = nseg - 1;
        while (i > 0 && !(grid_[i + 1] > grid_[i]) && t >= grid_[i + 1]) --i;  // zero-length segments at the end
        return i;
    }

    /// The rotation at t, and with order 1 and 2 its angular velocity and
    /// acceleration (rad per unit t, rad per unit t^2) in frame f.
    so3::jet<T> evaluate(T t, int order = 0, frame f = frame::world) const {
        check(t, order);
        return evaluate_on(locate(t), t, order, f);
    }
    quat operator()(T t) const { return evaluate(t, 0).q; }
    vec3<T> angular_velocity(T t, frame f = frame::world) const { return evaluate(t, 1, f).omega; }
    vec3<T> angular_acceleration(T t, frame f = frame::world) const { return evaluate(t, 2, f).alpha; }

    /// On a given segment (t may lie on its closed interval or outside: extrapolation).
    so3::jet<T> evaluate_on(std::size_t i, T t, int order = 0, frame f = frame::world) const {
        if (i >= segment_count())
            throw invalid_input("segment index " + std::to_string(i) + " is out of range (the curve has " +
                                std::to_string(segment_count()) + " segments)");
        so3::jet<T> j = world_jet(i, t, order);
        if (f == frame::body && order >= 1) {
            j.omega = rotate(conj(j.q), j.omega);
            j.alpha = rotate(conj(j.q), j.alpha);
        }
        return j;
    }

    /// Batch: rotations at every t (sorted or not), into out.
    void evaluate(std::span<const T> t, std::span<quat> out) const {
        check_batch_size(out.size(), t.size(), "rotations");
        batch_rows<T> rows;
        rows.quats = out.data();
        evaluate(t, rows, 0);
    }

    /// Batch: at every t (sorted or not), the rotation and with order 1 and 2
    /// the angular velocity and acceleration in frame f, written where out
    /// says (batch_rows: room for t.size() samples); t outside the domain is
    /// an out_of_domain error naming its index. Piecewise slerp goes through
    /// a vector kernel at every order, the other kinds' rotations (order 0)
    /// too (batch.hpp: the same values as evaluate() to a few ulps); their
    /// rates go through evaluate_on() one sample at a time.
    void evaluate(std::span<const T> t, const batch_rows<T>& out, int order, frame f = frame::world) const {
        evaluate(t, out, order, f, detail_batch::best_isa());
    }
    /// The same on a chosen path (the portable lanes or the AVX2 clone, which
    /// give the same bits): the seam the tests compare the two through.
    void evaluate(std::span<const T> t, const batch_rows<T>& out, int order, frame f, detail_batch::isa path) const {
        if (order < 0 || order > 2) throw invalid_input("derivative order must be 0, 1 or 2, got " + std::to_string(order));
        detail_batch::locator<T> find{grid_.data(), segment_count(), &index_};
        const T lo = grid_.front(), hi = grid_.back();
        auto locate_checked = [&](std::size_t k, T x) {
            if (!(x >= lo && x <= hi)) [[unlikely]] check_t(x, k);
            std::size_t i = find(x);
            while (i > 0 && !(grid_[i + 1] > grid_[i]) && x >= grid_[i + 1]) --i;  // as locate()
            return i;
        };
        if (kind_ == spline_kind::piecewise_slerp) {
            detail_batch::run<T>(
                t, locate_checked,
                [&](auto lanes, const std::size_t* seg, const T* tl, std::size_t k, int valid) CRSPLINE_ROTATION_BLOCK {
                    detail_batch::slerp_block<T, typename decltype(lanes)::type>(slerp_.data(), seg, tl, k, valid, order, f, out);
                },
                path);
            return;
        }
        if (order == 0 && !pyramid_.empty()) {
            const bool uniform = kind_ != spline_kind::barry_goldman;
            detail_batch::run<T>(
                t, locate_checked,
                [&](auto lanes, const std::size_t* seg, const T* tl, std::size_t k, int valid) CRSPLINE_ROTATION_BLOCK {
                    using V = typename decltype(lanes)::type;
                    if (uniform) detail_batch::pyramid_block<T, V, true>(pyramid_.data(), seg, tl, k, valid, out);
                    else detail_batch::pyramid_block<T, V, false>(pyramid_.data(), seg, tl, k, valid, out);
                },
                path);
            return;
        }
        if (order == 0 && !squad_.empty()) {
            detail_batch::run<T>(
                t, locate_checked,
                [&](auto lanes, const std::size_t* seg, const T* tl, std::size_t k, int valid) CRSPLINE_ROTATION_BLOCK {
                    detail_batch::squad_block<T, typename decltype(lanes)::type>(squad_.data(), seg, tl, k, valid, out);
                },
                path);
            return;
        }
        for (std::size_t k = 0; k < t.size(); ++k) {
            so3::jet<T> j = world_jet(locate_checked(k, t[k]), t[k], order);
            if (f == frame::body && order >= 1) {
                j.omega = rotate(conj(j.q), j.omega);
                j.alpha = rotate(conj(j.q), j.alpha);
            }
            const detail_batch::v3l<T> w{j.omega[0], j.omega[1], j.omega[2]}, a{j.alpha[0], j.alpha[1], j.alpha[2]};
            detail_batch::store<T, T>(out, k, 1, detail_batch::ql<T>{j.q.w, j.q.x, j.q.y, j.q.z}, order >= 1 ? &w : nullptr,
                                      order >= 2 ? &a : nullptr);
        }
    }

private:
    quaternion_spline() = default;

    spline_kind kind_ = spline_kind::catmull_rom;
    bool closed_ = false;
    std::vector<quat> keys_;                  // canonical keys (closed: N + 1)
    std::vector<T> grid_;
    std::vector<std::vector<quat>> controls_;
    quat before_{}, after_{};                 // neighbours beyond the ends (barry_goldman, squad)
    T t_before_ = 0, t_after_ = 0;
    detail::knot_index<T> index_;             // batch: segment of t in O(1)
    std::vector<detail_batch::slerp_packed<T>> slerp_;  // batch: piecewise slerp's steps, per segment
    std::vector<detail_batch::pyramid_packed<T>> pyramid_;  // batch: De Casteljau (4 controls) and Barry-Goldman
    std::vector<detail_batch::squad_packed<T>> squad_;      // batch: Squad

    // exp(s log(rel(a, b))) a, packed: log's half angle, a, and [0, axis] a.
    static detail_batch::fixed_slerp<T> pack_slerp(const quat& a, const quat& b) {
        detail_batch::fixed_slerp<T> p{};
        const vec3<T> L = log(rel(a, b));
        const T ang = crspline::norm(L);
        p.angle = ang;
        const quat o = ang > 0 ? quat{0, L[0] / ang, L[1] / ang, L[2] / ang} * a : quat{0, 0, 0, 0};
        p.a[0] = a.w, p.a[1] = a.x, p.a[2] = a.y, p.a[3] = a.z;
        p.o[0] = o.w, p.o[1] = o.x, p.o[2] = o.y, p.o[3] = o.z;
        return p;
    }

    // The pyramid and Squad tables (batch, order 0).
    void pack_pyramids() {
        const std::size_t nseg = segment_count();
        const bool bg = kind_ == spline_kind::barry_goldman;
        if (kind_ == spline_kind::squad) {
            for (std::size_t i = 0; i < nseg; ++i) {
                const auto& c = controls_[i];
                detail_batch::squad_packed<T> p{};
                const T h = grid_[i + 1] - grid_[i];
                p.t0 = grid_[i];
                p.inv_h = h > 0 ? T(1) / h : T(0);
                p.f[0] = h > 0 ? pack_slerp(c[0], c[3]) : pack_slerp(keys_[i], keys_[i]);
                p.f[1] = h > 0 ? pack_slerp(c[1], c[2]) : pack_slerp(keys_[i], keys_[i]);
                squad_.push_back(p);
            }
            return;
        }
        if (!bg) {
            if (kind_ == spline_kind::piecewise_slerp) return;
            for (const auto& c : controls_)
                if (c.size() != 4) return;  // the vector kernel knows 4 controls; others stay scalar
        }
        for (std::size_t i = 0; i < nseg; ++i) {
            detail_batch::pyramid_packed<T> p{};
            const T t0 = grid_[i], t1 = grid_[i + 1], h = t1 - t0;
            if (!(h > 0)) {
                // A repeated key: every parameter 0, every slerp at the key.
                for (int j = 0; j < 6; ++j) p.ta[j] = t0;
                for (auto& f : p.f) f = pack_slerp(keys_[i], keys_[i]);
                pyramid_.push_back(p);
                continue;
            }
            auto param = [&](int j, T ta, T tb) {
                const T d = tb - ta;
                p.ta[j] = ta;
                p.inv[j] = d != 0 ? T(1) / d : T(0);  // world_jet's safe_div
            };
            if (bg) {
                const auto k = std::ptrdiff_t(i);
                const T tm = time(k - 1), tp = time(k + 2);
                param(0, tm, t0), param(1, t0, t1), param(2, t1, tp), param(3, tm, t1), param(4, t0, tp), param(5, t0, t1);
                p.f[0] = pack_slerp(key(k - 1), key(k)), p.f[1] = pack_slerp(key(k), key(k + 1));
                p.f[2] = pack_slerp(key(k + 1), key(k + 2));
            } else {
                for (int j = 0; j < 6; ++j) param(j, t0, t1);
                const auto& c = controls_[i];
                for (int j = 0; j < 3; ++j) p.f[j] = pack_slerp(c[std::size_t(j)], c[std::size_t(j) + 1]);
            }
            pyramid_.push_back(p);
        }
    }

    // The batch's tables, once the grid and the keys are final.
    void finish() {
        index_.build(grid_.data(), segment_count());
        if (kind_ != spline_kind::piecewise_slerp) return pack_pyramids();
        for (std::size_t i = 0; i < segment_count(); ++i) {
            detail_batch::slerp_packed<T> p{};
            const quat& a = keys_[i];
            p.t0 = grid_[i];
            p.a[0] = a.w, p.a[1] = a.x, p.a[2] = a.y, p.a[3] = a.z;
            const T h = grid_[i + 1] - grid_[i];
            if (h > 0) {
                // world_jet's slerp_jet: exp(u log(b a*)) a; L = log(b a*) = half_angle * axis.
                const vec3<T> L = log(rel(a, keys_[i + 1]));
                const T ang = crspline::norm(L);
                p.inv_h = T(1) / h;
                p.half_angle = ang;
                if (ang > 0) p.axis[0] = L[0] / ang, p.axis[1] = L[1] / ang, p.axis[2] = L[2] / ang;
            }
            slerp_.push_back(p);
        }
    }

    void check(T t, int order) const {
        if (order < 0 || order > 2)
            throw invalid_input("derivative order must be 0, 1 or 2, got " + std::to_string(order));
        check_t(t, std::nullopt);
    }
    void check_t(T t, std::optional<std::size_t> index) const {
        if (!(t >= grid_.front() && t <= grid_.back()))
            throw out_of_domain("t = " + detail::num(double(t)) +
                                (index ? " (index " + std::to_string(*index) + ")" : std::string()) +
                                " is outside the curve's domain [" + detail::num(double(grid_.front())) + ", " +
                                detail::num(double(grid_.back())) + "]");
    }

    static T safe_div(T a, T b) noexcept { return b != 0 ? a / b : T(0); }

    // Key and time with index k in -1 .. keys + 1 (the neighbours beyond the ends).
    quat key(std::ptrdiff_t k) const noexcept {
        if (k < 0) return before_;
        if (std::size_t(k) >= keys_.size()) return after_;
        return keys_[std::size_t(k)];
    }
    T time(std::ptrdiff_t k) const noexcept {
        if (k < 0) return t_before_;
        if (std::size_t(k) >= grid_.size()) return t_after_;
        return grid_[std::size_t(k)];
    }

    so3::jet<T> world_jet(std::size_t i, T t, int order) const noexcept {
        const T t0 = grid_[i], t1 = grid_[i + 1], h = t1 - t0;
        if (!(h > 0)) return so3::constant(keys_[i]);  // a repeated key: the curve rests there
        const T u = (t - t0) / h, du = T(1) / h;
        switch (kind_) {
            case spline_kind::barry_goldman: {
                const auto k = std::ptrdiff_t(i);
                const T tm = time(k - 1), tp = time(k + 2);
                auto lin = [&](const so3::jet<T>& a, const so3::jet<T>& b, T ta, T tb) {
                    const T d = tb - ta;
                    return so3::slerp_jet(a, b, safe_div(t - ta, d), safe_div(T(1), d), T(0), order);
                };
                const auto q0 = so3::constant(key(k - 1)), q1 = so3::constant(key(k)), q2 = so3::constant(key(k + 1)),
                           q3 = so3::constant(key(k + 2));
                const auto A = lin(q0, q1, tm, t0), B = lin(q1, q2, t0, t1), C = lin(q2, q3, t1, tp);
                const auto D = lin(A, B, tm, t1), E = lin(B, C, t0, tp);
                return lin(D, E, t0, t1);
            }
            case spline_kind::squad: {
                const auto& c = controls_[i];
                const auto a = so3::slerp_jet(so3::constant(c[0]), so3::constant(c[3]), u, du, T(0), order);
                const auto b = so3::slerp_jet(so3::constant(c[1]), so3::constant(c[2]), u, du, T(0), order);
                return so3::slerp_jet(a, b, 2 * u * (1 - u), (2 - 4 * u) * du, -4 * du * du, order);
            }
            default: {
                // De Casteljau: replace the list by slerps of neighbours until one remains.
                const auto& c = controls_[i];
                std::array<so3::jet<T>, 8> small{};
                std::vector<so3::jet<T>> big;
                so3::jet<T>* level = small.data();
                if (c.size() > small.size()) {
                    big.resize(c.size());
                    level = big.data();
                }
                for (std::size_t j = 0; j < c.size(); ++j) level[j] = so3::constant(c[j]);
                for (std::size_t m = c.size(); m > 1; --m)
                    for (std::size_t j = 0; j + 1 < m; ++j) level[j] = so3::slerp_jet(level[j], level[j + 1], u, du, T(0), order);
                return level[0];
            }
        }
    }

    void set_grid(std::size_t count, const std::optional<std::vector<T>>& grid, std::optional<double> alpha, bool strict) {
        grid_.assign(count, T(0));
        if (grid && alpha) throw invalid_input("give either a grid or alpha, not both");
        if (grid) {
            if (grid->size() != count)
                throw invalid_input("grid has " + std::to_string(grid->size()) + " values, the curve needs " +
                                    std::to_string(count) + (closed_ ? " (keys + 1: the curve is closed)" : ""));
            for (std::size_t k = 0; k < count; ++k) {
                if (!std::isfinite((*grid)[k]))
                    throw invalid_input("grid value " + std::to_string(k) + " is not finite (" + detail::num(double((*grid)[k])) + ")");
                if (k > 0 && !((*grid)[k] > (*grid)[k - 1]))
                    throw invalid_input("grid is not increasing at index " + std::to_string(k) + " (" +
                                        detail::num(double((*grid)[k - 1])) + " then " + detail::num(double((*grid)[k])) + ")");
            }
            grid_ = *grid;
            return;
        }
        if (!alpha) {
            for (std::size_t k = 0; k < count; ++k) grid_[k] = T(k);
            return;
        }
        const double a = *alpha;
        if (!(a >= 0 && a <= 1)) throw invalid_input("alpha must be in [0, 1], got " + detail::num(a));
        for (std::size_t k = 0; k + 1 < count; ++k) {
            const quat &p = keys_[k], &q = keys_[k + 1];
            // The angle travelled from p to q with the signs as they are:
            // 4 atan2(|p - q|, |p + q|), in [0, 2 pi] (pi at most for canonical keys).
            const T theta = T(4) * std::atan2(norm(p - q), norm(p + q));
            const bool repeated = theta <= T(16) * std::numeric_limits<T>::epsilon();
            if (repeated && strict && a > 0) {
                const std::size_t keys = closed_ ? count - 1 : count;  // the closing chord wraps to key 0
                throw invalid_input("keys " + std::to_string(k) + " and " + std::to_string((k + 1) % keys) +
                                    " are the same rotation (angle " + detail::num(double(theta)) +
                                    " rad; strict mode refuses repeated keys with alpha > 0)");
            }
            const T h = a == 0 ? T(1) : repeated ? T(0) : T(std::pow(double(theta), a));
            grid_[k + 1] = grid_[k] + h;
        }
    }

    void build(std::span<const quat> in, const rotation_options<T>& opt) {
        kind_ = opt.kind;
        closed_ = opt.closed;
        if (kind_ == spline_kind::de_casteljau)
            throw invalid_input("de_casteljau curves take control quaternions per segment: use quaternion_spline::de_casteljau");
        if (in.size() < 2) throw invalid_input("a rotation curve needs at least 2 keys, got " + std::to_string(in.size()));
        // 1. Unit keys, then the sign rule (closed: key 0 appended before it).
        for (std::size_t k = 0; k < in.size(); ++k) keys_.push_back(checked_unit(in[k], k, opt.unit_tolerance));
        if (closed_) keys_.push_back(keys_.front());
        if (!opt.keep_signs) {
            quat p = quat::identity();
            for (auto& q : keys_) {
                if (dot(p, q) < 0) q = -q;
                p = q;
            }
        }
        const std::size_t n = in.size(), nseg = closed_ ? n : n - 1;
        // 2. The grid.
        set_grid(nseg + 1, opt.grid, opt.alpha, opt.strict);
        // 3. Neighbours beyond the ends: closed, cyclic (sign agreeing with
        //    the end key); open, the reflection rel(k1, k0) k0 at t0 - (t1 - t0).
        auto agree = [&](quat q, const quat& with) { return !opt.keep_signs && dot(q, with) < 0 ? -q : q; };
        if (closed_) {
            before_ = agree(keys_[n - 1], keys_[0]);
            t_before_ = grid_[0] - (grid_[n] - grid_[n - 1]);
            after_ = agree(keys_[1], keys_[n]);
            t_after_ = grid_[n] + (grid_[1] - grid_[0]);
        } else {
            before_ = rel(keys_[1], keys_[0]) * keys_[0];
            t_before_ = grid_[0] - (grid_[1] - grid_[0]);
            after_ = rel(keys_[n - 2], keys_[n - 1]) * keys_[n - 1];
            t_after_ = grid_[n - 1] + (grid_[n - 1] - grid_[n - 2]);
        }
        // 4. Control quaternions.
        switch (kind_) {
            case spline_kind::piecewise_slerp:
                for (std::size_t i = 0; i < nseg; ++i) controls_.push_back({keys_[i], keys_[i + 1]});
                break;
            case spline_kind::catmull_rom:
            case spline_kind::kochanek_bartels: build_kochanek_bartels(opt); break;
            case spline_kind::squad: build_squad(); break;
            default: break;
        }
        finish();
    }

    /// The tangent-space construction of `splines.quaternion.KochanekBartels`:
    /// for key i with neighbours at t_(i-1), t_(i+1), rho_in = log(rel(k_(i-1),
    /// k_i))/(t_i - t_(i-1)), rho_out = log(rel(k_i, k_(i+1)))/(t_(i+1) - t_i),
    /// w(p, r) = [p D+ rho_in + r D- rho_out]/(D- + D+) with D- = t_i - t_(i-1),
    /// D+ = t_(i+1) - t_i (half-angle units: the key's angular velocity is 2w),
    /// c_i+ = exp(w(a, b) D+/3) k_i, c_i- = exp(-w(c, d) D-/3) k_i.
    void build_kochanek_bartels(const rotation_options<T>& opt) {
        const std::size_t nk = keys_.size();  // closed: N + 1
        const std::size_t n = closed_ ? nk - 1 : nk, nseg = grid_.size() - 1;
        const std::size_t first = closed_ ? 0 : 1, last = closed_ ? n : n - 1;  // keys that get the formula
        const std::size_t kb_keys = last > first ? last - first : 0;
        if (!opt.kb.empty() && opt.kb.size() != 1 && opt.kb.size() != kb_keys)
            throw invalid_input("kochanek_bartels: " + std::to_string(opt.kb.size()) + " TCB triples for " +
                                std::to_string(kb_keys) + " keys (give 1, or one per " +
                                (closed_ ? "key" : "interior key") + ")");
        for (std::size_t k = 0; k < opt.kb.size(); ++k) {
            const auto& v = opt.kb[k];
            if (!std::isfinite(v.tension) || !std::isfinite(v.continuity) || !std::isfinite(v.bias))
                throw invalid_input("kochanek_bartels: TCB triple " + std::to_string(k) + " is not finite");
        }
        std::vector<quat> plus(nk), minus(nk);
        for (std::size_t i = first; i < last; ++i) {
            const auto k = std::ptrdiff_t(i);
            const quat prev = key(k - 1), here = keys_[i], next = key(k + 1);
            const T dm = grid_[i] - time(k - 1), dp = time(k + 1) - grid_[i];
            const vec3<T> rin = dm > 0 ? log(rel(prev, here)) / dm : vec3<T>{};
            const vec3<T> rout = dp > 0 ? log(rel(here, next)) / dp : vec3<T>{};
            tcb<T> p{};
            if (!opt.kb.empty()) p = opt.kb.size() == 1 ? opt.kb[0] : opt.kb[i - first];
            const T a = (1 - p.tension) * (1 + p.continuity) * (1 + p.bias), b = (1 - p.tension) * (1 - p.continuity) * (1 - p.bias);
            const T c = (1 - p.tension) * (1 - p.continuity) * (1 + p.bias), d = (1 - p.tension) * (1 + p.continuity) * (1 - p.bias);
            const T sum = dm + dp;
            auto w = [&](T x, T y) { return sum > 0 ? (x * dp * rin + y * dm * rout) / sum : vec3<T>{}; };
            plus[i] = exp(w(a, b) * (dp / 3)) * here;
            minus[i] = exp(w(c, d) * (-dm / 3)) * here;
        }
        if (closed_) {
            // The appended key is key 0 with the sign it got: its incoming control follows.
            const T s = dot(keys_[n], keys_[0]) < 0 ? T(-1) : T(1);
            minus[n] = s * minus[0];
        } else if (n == 2) {
            // Two keys: exactly slerp(k0, k1, u).
            const quat r = rel(keys_[0], keys_[1]);
            plus[0] = pow(r, T(1) / 3) * keys_[0];
            minus[1] = pow(r, -T(1) / 3) * keys_[1];
        } else {
            auto end_control = [&](const rotation_end<T>& e, std::size_t at, std::size_t other, T dt, bool start) {
                switch (e.type) {
                    case rotation_end<T>::kind::natural:
                        return slerp(keys_[at], start ? minus[other] : plus[other], T(0.5));
                    case rotation_end<T>::kind::natural_splines: return slerp(keys_[at], keys_[other], T(0.5));
                    default: {
                        vec3<T> w = e.omega;
                        for (std::size_t c = 0; c < 3; ++c)
                            if (!std::isfinite(w[c]))
                                throw invalid_input(std::string(start ? "start" : "end") + " angular velocity component " +
                                                    std::to_string(c) + " is not finite (" + detail::num(double(w[c])) + ")");
                        if (e.omega_frame == frame::body) w = rotate(keys_[at], w);
                        // The cubic's end rate is 3 * 2 log(c k*)/h: c = exp(omega h/6) k.
                        return exp(w * ((start ? dt : -dt) / 6)) * keys_[at];
                    }
                }
            };
            plus[0] = end_control(opt.start, 0, 1, grid_[1] - grid_[0], true);
            minus[n - 1] = end_control(opt.end, n - 1, n - 2, grid_[n - 1] - grid_[n - 2], false);
        }
        for (std::size_t i = 0; i < nseg; ++i) controls_.push_back({keys_[i], plus[i], minus[i + 1], keys_[i + 1]});
    }

    /// Squad's inner controls: with Dm = t_i - t_(i-1), Dp = t_(i+1) - t_i,
    /// Lo = log(rel(q_i, q_(i+1))), Li = log(rel(q_i, q_(i-1))):
    /// s_i- = exp(-Dm/(2(Dm+Dp)) (Dm/Dp Lo + Li)) q_i,
    /// s_i+ = exp(-Dp/(2(Dm+Dp)) (Lo + Dp/Dm Li)) q_i.
    void build_squad() {
        const std::size_t nk = keys_.size(), nseg = grid_.size() - 1;
        std::vector<quat> plus(nk), minus(nk);
        for (std::size_t i = 0; i < nk; ++i) {
            const auto k = std::ptrdiff_t(i);
            const quat here = keys_[i];
            const T dm = grid_[i] - time(k - 1), dp = time(k + 1) - grid_[i], sum = dm + dp;
            const vec3<T> lo = log(rel(here, key(k + 1))), li = log(rel(here, key(k - 1)));
            if (!(dm > 0) || !(dp > 0)) {
                plus[i] = minus[i] = here;  // a repeated key: no turn to smooth
                continue;
            }
            minus[i] = exp((dm / dp * lo + li) * (-dm / (2 * sum))) * here;
            plus[i] = exp((lo + dp / dm * li) * (-dp / (2 * sum))) * here;
        }
        for (std::size_t i = 0; i < nseg; ++i) controls_.push_back({keys_[i], plus[i], minus[i + 1], keys_[i + 1]});
    }
};

}  // namespace crspline::rotation
