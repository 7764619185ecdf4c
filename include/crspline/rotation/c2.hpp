// crspline: the C2 interpolating rotation spline of SciPy's RotationSpline,
// solved to convergence.
//
// On segment i (keys q_i, q_(i+1), times t_i, t_(i+1), dt = t_(i+1) - t_i):
//     R(t) = R_i Exp(theta(t - t_i)),  theta(tau) = c3 tau^3 + c2 tau^2 + w_i tau,
// with theta(0) = 0, theta(dt) = r_i (the rotation vector of R_i^-1 R_(i+1),
// the short way unless keep_signs), theta'(0) = w_i, theta'(dt) = rho_i =
// J_r(r_i)^-1 w_(i+1): w_k is the body-frame angular velocity at key k, so
// the angular velocity is continuous. The w_k at the interior keys (and at
// ends that are not fixed) solve the nonlinear system "angular acceleration
// continuous at every key":
//     F_k = a_end(k-1) - a_start(k) = 0,
//     a_start(i) = theta_i''(0) = (6 r_i - 4 dt w_i - 2 dt rho_i)/dt^2,
//     a_end(i)   = J_r(r_i) theta_i''(dt) + N_r(r_i, rho_i)
//                = (-6 r_i + 2 dt J_r(r_i) w_i)/dt^2 + 4 w_(i+1)/dt + N_r(r_i, rho_i).
// SciPy lags N_r and iterates a linear solve at most 10 times (TOL 1e-9): its
// curve is C2 only as far as that gets (0.19 rad/s^2 jumps with 170 degree
// steps). Here Newton's method solves the system to rounding: the Jacobian
// is block tridiagonal (cyclic when closed), so each step is linear in the
// number of keys, and residual() reports the largest acceleration jump left.
//
// Ends: scipy (w_0 = r_0/dt_0, w_(n-1) = r_(n-2)/dt_(n-2), SciPy's only
// choice), natural (zero angular acceleration), a given angular velocity (in
// the world or body frame), or closed (periodic: C2 across the seam too).
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

template <class T = double>
struct c2_end {
    enum class kind { scipy, natural, angular_velocity };
    kind type = kind::scipy;
    vec3<T> omega{};
    frame omega_frame = frame::world;

    static c2_end scipy() { return {}; }
    static c2_end natural() { return {kind::natural, {}, frame::world}; }
    static c2_end velocity(const vec3<T>& w, frame f = frame::world) { return {kind::angular_velocity, w, f}; }
};

template <class T = double>
struct c2_options {
    c2_end<T> start{}, end{};  ///< open curves only
    bool closed = false;       ///< periodic: n keys, n + 1 times (the last: key 0's return)
    bool keep_signs = false;   ///< steps as the given signs say (up to 2 pi), not the short way
    int max_iterations = 100;  ///< Newton steps; convergence takes 3 to 8 in practice
    /// As rotation_options::unit_tolerance: keys normalized, zero and non-finite refused.
    T unit_tolerance = std::numeric_limits<T>::infinity();
};

namespace detail_c2 {

template <class T>
using mat3 = std::array<std::array<T, 3>, 3>;

template <class T>
mat3<T> identity(T s = T(1)) { return {{{s, 0, 0}, {0, s, 0}, {0, 0, s}}}; }

template <class T, class F>
mat3<T> columns(F f) {
    mat3<T> m{};
    for (std::size_t j = 0; j < 3; ++j) {
        vec3<T> e{};
        e[j] = 1;
        const vec3<T> c = f(e);
        for (std::size_t i = 0; i < 3; ++i) m[i][j] = c[i];
    }
    return m;
}

template <class T>
vec3<T> mul(const mat3<T>& m, const vec3<T>& v) {
    vec3<T> r{};
    for (std::size_t i = 0; i < 3; ++i) r[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
    return r;
}

template <class T>
mat3<T> mul(const mat3<T>& a, const mat3<T>& b) {
    mat3<T> r{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
    return r;
}

template <class T>
mat3<T> sub(mat3<T> a, const mat3<T>& b) {
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) a[i][j] -= b[i][j];
    return a;
}

template <class T>
mat3<T> add(mat3<T> a, const mat3<T>& b) {
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) a[i][j] += b[i][j];
    return a;
}

template <class T>
mat3<T> inverse(const mat3<T>& m) {
    const T c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1], c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2],
            c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    const T det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
    const T d = T(1) / det;
    return {{{c00 * d, (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * d, (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * d},
             {c01 * d, (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * d, (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * d},
             {c02 * d, (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * d, (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * d}}};
}

/// Right-hand side: 3 rows, K columns.
template <class T, std::size_t K>
using block = std::array<std::array<T, K>, 3>;

template <class T, std::size_t K>
block<T, K> mul(const mat3<T>& a, const block<T, K>& b) {
    block<T, K> r{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < K; ++j) r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
    return r;
}

template <class T, std::size_t K>
block<T, K> sub(block<T, K> a, const block<T, K>& b) {
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < K; ++j) a[i][j] -= b[i][j];
    return a;
}

/// Block tridiagonal solve (block Thomas): L[k] x[k-1] + D[k] x[k] + U[k] x[k+1] = b[k].
template <class T, std::size_t K>
void block_thomas(std::vector<mat3<T>> L, std::vector<mat3<T>> D, const std::vector<mat3<T>>& U,
                  std::vector<block<T, K>>& b) {
    const std::size_t m = D.size();
    for (std::size_t k = 1; k < m; ++k) {
        const mat3<T> f = mul(L[k], inverse(D[k - 1]));
        D[k] = sub(D[k], mul(f, U[k - 1]));
        b[k] = sub(b[k], mul(f, b[k - 1]));
    }
    b[m - 1] = mul(inverse(D[m - 1]), b[m - 1]);
    for (std::size_t k = m - 1; k-- > 0;) b[k] = mul(inverse(D[k]), sub(b[k], mul(U[k], b[k + 1])));
}

}  // namespace detail_c2

/// The C2 rotation spline through keys at increasing times. Closed: n keys,
/// n + 1 times (the last is the time of key 0's return).
template <class T = double>
class c2_rotation_spline {
public:
    using quat = quaternion<T>;
    using mat3 = detail_c2::mat3<T>;

    c2_rotation_spline(std::span<const T> times, std::span<const quat> keys, const c2_options<T>& opt = {}) {
        build(times, keys, opt);
    }

    std::span<const T> grid() const noexcept { return t_; }
    std::span<const quat> keys() const noexcept { return q_; }
    bool closed() const noexcept { return closed_; }
    std::size_t segment_count() const noexcept { return r_.size(); }
    /// Body-frame angular velocity at each key (closed: n + 1, the last = the first).
    std::span<const vec3<T>> key_rates() const noexcept { return w_; }
    /// The largest angular-acceleration jump left at a key (rad per unit t^2)
    /// after the solve, and the scale it compares with (the largest
    /// |acceleration| at a key, at least 1e-300).
    T residual() const noexcept { return residual_; }
    T acceleration_scale() const noexcept { return accel_scale_; }
    int iterations() const noexcept { return iterations_; }

    std::size_t locate(T t) const noexcept {
        std::size_t i = std::size_t(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin());
        i = i == 0 ? 0 : i - 1;
        return std::min(i, segment_count() - 1);
    }

    so3::jet<T> evaluate(T t, int order = 0, frame f = frame::world) const {
        if (order < 0 || order > 2) throw invalid_input("derivative order must be 0, 1 or 2, got " + std::to_string(order));
        check_t(t, std::nullopt);
        return evaluate_on(locate(t), t, order, f);
    }
    quat operator()(T t) const { return evaluate(t, 0).q; }
    vec3<T> angular_velocity(T t, frame f = frame::world) const { return evaluate(t, 1, f).omega; }
    vec3<T> angular_acceleration(T t, frame f = frame::world) const { return evaluate(t, 2, f).alpha; }

    /// The batch kernels' packed segments (batch.hpp), for pose_curve's batch.
    std::span<const detail_batch::c2_packed<T>> batch_segments() const noexcept { return packed_; }

    /// On segment i (t anywhere: extrapolation outside it).
    so3::jet<T> evaluate_on(std::size_t i, T t, int order = 0, frame f = frame::world) const noexcept {
        const T tau = t - t_[i];
        const auto& c = coeff_[i];
        const vec3<T> th = ((c[0] * tau + c[1]) * tau + c[2]) * tau;
        const vec3<T> d1 = (T(3) * c[0] * tau + T(2) * c[1]) * tau + c[2];
        const vec3<T> d2 = T(6) * c[0] * tau + T(2) * c[1];
        so3::jet<T> j;
        j.q = q_[i] * from_rotation_vector(th);
        if (order >= 1) {
            // Body frame: J_r theta', J_r theta'' + N_r; world: R times those.
            j.omega = so3::jacobian(frame::body, th, d1);
            if (order >= 2) j.alpha = so3::jacobian(frame::body, th, d2) + so3::jacobian_rate(frame::body, th, d1);
            if (f == frame::world) {
                j.omega = rotate(j.q, j.omega);
                j.alpha = rotate(j.q, j.alpha);
            }
        }
        return j;
    }

    /// Batch: the rotations at every t (sorted or not), into out.
    void evaluate(std::span<const T> t, std::span<quat> out) const {
        check_batch_size(out.size(), t.size(), "rotations");
        batch_rows<T> rows;
        rows.quats = out.data();
        evaluate(t, rows, 0);
    }

    /// Batch: at every t (sorted or not), the rotation and with order 1 and 2
    /// the angular velocity and acceleration in frame f, written where out
    /// says (batch_rows: room for t.size() samples). t outside the domain is
    /// an out_of_domain error naming its index, or with extrapolate the
    /// first or last segment continued (SciPy's RotationSpline does that).
    /// The same values as evaluate_on() to a few ulps (batch.hpp).
    void evaluate(std::span<const T> t, const batch_rows<T>& out, int order, frame f = frame::world,
                  bool extrapolate = false) const {
        evaluate(t, out, order, f, extrapolate, detail_batch::best_isa());
    }
    /// The same on a chosen path (the portable lanes or the AVX2 clone, which
    /// give the same bits): the seam the tests compare the two through.
    void evaluate(std::span<const T> t, const batch_rows<T>& out, int order, frame f, bool extrapolate,
                  detail_batch::isa path) const {
        if (order < 0 || order > 2) throw invalid_input("derivative order must be 0, 1 or 2, got " + std::to_string(order));
        detail_batch::locator<T> find{t_.data(), segment_count(), &index_};
        const T lo = t_.front(), hi = t_.back();
        detail_batch::run<T>(
            t,
            [&](std::size_t k, T x) {
                if (!extrapolate && !(x >= lo && x <= hi)) [[unlikely]] check_t(x, k);
                return find(x);
            },
            [&](auto lanes, const std::size_t* seg, const T* tl, std::size_t k, int valid) CRSPLINE_ROTATION_BLOCK {
                detail_batch::c2_block<T, typename decltype(lanes)::type>(packed_.data(), seg, tl, k, valid, order, f, out);
            },
            path);
    }

private:
    bool closed_ = false;
    std::vector<T> t_;
    std::vector<quat> q_;                       // keys (closed: n + 1, the last = the first)
    std::vector<vec3<T>> r_, w_;                // steps per segment, body rates per key
    std::vector<std::array<vec3<T>, 3>> coeff_; // c3, c2, w_i per segment
    T residual_ = 0, accel_scale_ = 0;
    int iterations_ = 0;
    detail::knot_index<T> index_;                   // batch: segment of t in O(1)
    std::vector<detail_batch::c2_packed<T>> packed_;  // batch: coeff_ and the key, per segment

    void check_t(T t, std::optional<std::size_t> index) const {
        if (!(t >= t_.front() && t <= t_.back()))
            throw out_of_domain("t = " + detail::num(double(t)) +
                                (index ? " (index " + std::to_string(*index) + ")" : std::string()) +
                                " is outside the curve's domain [" + detail::num(double(t_.front())) + ", " +
                                detail::num(double(t_.back())) + "]");
    }

    T dt(std::size_t i) const noexcept { return t_[i + 1] - t_[i]; }
    vec3<T> rho(std::size_t i) const noexcept { return so3::inverse_jacobian(frame::body, r_[i], w_[i + 1]); }
    vec3<T> a_start(std::size_t i) const noexcept {
        const T h = dt(i);
        return (T(6) * r_[i] - T(4) * h * w_[i] - T(2) * h * rho(i)) / (h * h);
    }
    vec3<T> a_end(std::size_t i) const noexcept {
        const T h = dt(i);
        return (T(-6) * r_[i] + T(2) * h * so3::jacobian(frame::body, r_[i], w_[i])) / (h * h) + T(4) / h * w_[i + 1] +
               so3::jacobian_rate(frame::body, r_[i], rho(i));
    }
    // d N_r(r_i, rho)/d rho times d rho/d w_(i+1) = A_r(r_i): N_r is a
    // quadratic form in rho, so a central difference is exact (to rounding).
    mat3 dN(std::size_t i) const {
        const vec3<T> p = rho(i);
        const T s = T(1) + crspline::norm(p);
        const mat3 g = detail_c2::columns<T>([&](const vec3<T>& e) {
            return (so3::jacobian_rate(frame::body, r_[i], p + s * e) - so3::jacobian_rate(frame::body, r_[i], p - s * e)) / (2 * s);
        });
        return detail_c2::mul(g, detail_c2::columns<T>([&](const vec3<T>& e) { return so3::inverse_jacobian(frame::body, r_[i], e); }));
    }

    enum class row { fixed, interior, natural_start, natural_end };

    void build(std::span<const T> times, std::span<const quat> keys, const c2_options<T>& opt) {
        closed_ = opt.closed;
        const std::size_t n = keys.size();
        if (n < 2) throw invalid_input("a rotation spline needs at least 2 keys, got " + std::to_string(n));
        const std::size_t nt = closed_ ? n + 1 : n;
        if (times.size() != nt)
            throw invalid_input("times has " + std::to_string(times.size()) + " values for " + std::to_string(n) +
                                " keys (needs " + std::to_string(nt) + (closed_ ? ": closed, the return to key 0 last)" : ")"));
        for (std::size_t k = 0; k < nt; ++k) {
            if (!std::isfinite(times[k]))
                throw invalid_input("time " + std::to_string(k) + " is not finite (" + detail::num(double(times[k])) + ")");
            if (k > 0 && !(times[k] > times[k - 1]))
                throw invalid_input("times must be strictly increasing: time " + std::to_string(k) + " (" +
                                    detail::num(double(times[k])) + ") follows " + detail::num(double(times[k - 1])));
        }
        t_.assign(times.begin(), times.end());
        for (std::size_t k = 0; k < n; ++k) q_.push_back(checked_unit(keys[k], k, opt.unit_tolerance));
        if (closed_) q_.push_back(q_.front());
        const std::size_t nseg = q_.size() - 1, m = n;  // unknown rates: one per key (closed: w_n is w_0)
        for (std::size_t i = 0; i < nseg; ++i) {
            const quat step = conj(q_[i]) * q_[i + 1];
            r_.push_back(opt.keep_signs ? T(2) * log(step) : to_rotation_vector(step));
        }
        // Rows: which equation each key's rate obeys.
        std::vector<row> kind(m, row::interior);
        w_.assign(nseg + 1, vec3<T>{});
        std::vector<vec3<T>> fixed(m);
        for (std::size_t k = 0; k < nseg; ++k) w_[k] = r_[k] / dt(k);  // SciPy's first guess
        w_[nseg] = r_[nseg - 1] / dt(nseg - 1);
        if (closed_) w_[nseg] = w_[0];
        if (!closed_) {
            auto end_row = [&](const c2_end<T>& e, std::size_t k, bool start) {
                switch (e.type) {
                    case c2_end<T>::kind::scipy:
                        kind[k] = row::fixed, fixed[k] = start ? r_[0] / dt(0) : r_[nseg - 1] / dt(nseg - 1);
                        break;
                    case c2_end<T>::kind::natural: kind[k] = start ? row::natural_start : row::natural_end; break;
                    default:
                        for (std::size_t c = 0; c < 3; ++c)
                            if (!std::isfinite(e.omega[c]))
                                throw invalid_input(std::string(start ? "start" : "end") + " angular velocity component " +
                                                    std::to_string(c) + " is not finite (" + detail::num(double(e.omega[c])) + ")");
                        kind[k] = row::fixed;
                        fixed[k] = e.omega_frame == frame::body ? e.omega : rotate(conj(q_[k]), e.omega);
                }
                if (kind[k] == row::fixed) w_[k] = fixed[k];
            };
            end_row(opt.start, 0, true);
            end_row(opt.end, n - 1, false);
        }
        solve(kind, fixed, opt.max_iterations);
        // Coefficients: c3 = (-2 r + dt w_i + dt rho)/dt^3, c2 = (3 r - 2 dt w_i - dt rho)/dt^2.
        for (std::size_t i = 0; i < nseg; ++i) {
            const T h = dt(i);
            const vec3<T> p = rho(i);
            coeff_.push_back({(T(-2) * r_[i] + h * w_[i] + h * p) / (h * h * h), (T(3) * r_[i] - T(2) * h * w_[i] - h * p) / (h * h), w_[i]});
        }
        index_.build(t_.data(), nseg);
        for (std::size_t i = 0; i < nseg; ++i) {
            const auto& c = coeff_[i];
            detail_batch::c2_packed<T> pk{};
            pk.t0 = t_[i];
            for (std::size_t d = 0; d < 3; ++d) pk.c3[d] = c[0][d], pk.c2[d] = c[1][d], pk.c1[d] = c[2][d];
            pk.q[0] = q_[i].w, pk.q[1] = q_[i].x, pk.q[2] = q_[i].y, pk.q[3] = q_[i].z;
            packed_.push_back(pk);
        }
    }

    // Residual of every row (acceleration units; fixed rows: rate units).
    std::vector<vec3<T>> residuals(const std::vector<row>& kind, const std::vector<vec3<T>>& fixed) const {
        const std::size_t m = kind.size(), nseg = r_.size();
        std::vector<vec3<T>> F(m);
        for (std::size_t k = 0; k < m; ++k) {
            switch (kind[k]) {
                case row::fixed: F[k] = w_[k] - fixed[k]; break;
                case row::natural_start: F[k] = a_start(0); break;
                case row::natural_end: F[k] = a_end(nseg - 1); break;
                default: F[k] = a_end(k == 0 ? nseg - 1 : k - 1) - a_start(k);
            }
        }
        return F;
    }

    static T max_norm(const std::vector<vec3<T>>& v) {
        T m = 0;
        for (const auto& x : v) m = std::max(m, max_abs(x));
        return m;
    }

    void set_rate(std::size_t k, const vec3<T>& w) {
        w_[k] = w;
        if (closed_ && k == 0) w_.back() = w;
    }

    void solve(const std::vector<row>& kind, const std::vector<vec3<T>>& fixed, int max_iterations) {
        using namespace detail_c2;
        const std::size_t m = kind.size(), nseg = r_.size();
        bool any = false;
        for (auto k : kind) any = any || k != row::fixed;
        auto F = residuals(kind, fixed);
        iterations_ = 0;
        if (any) {
            for (int it = 0; it < max_iterations; ++it) {
                // Jacobian blocks of row k: L (rate k-1), D (rate k), U (rate k+1); cyclic when closed.
                std::vector<mat3> L(m, mat3{}), D(m, mat3{}), U(m, mat3{});
                for (std::size_t k = 0; k < m; ++k) {
                    switch (kind[k]) {
                        case row::fixed: D[k] = identity<T>(); break;
                        case row::natural_start: {
                            const T h = dt(0);
                            D[k] = identity<T>(T(-4) / h);
                            U[k] = columns<T>([&](const vec3<T>& e) { return so3::inverse_jacobian(frame::body, r_[0], e) * (T(-2) / h); });
                            break;
                        }
                        case row::natural_end: {
                            const std::size_t i = nseg - 1;
                            const T h = dt(i);
                            L[k] = columns<T>([&](const vec3<T>& e) { return so3::jacobian(frame::body, r_[i], e) * (T(2) / h); });
                            D[k] = add(identity<T>(T(4) / h), dN(i));
                            break;
                        }
                        default: {
                            const std::size_t b = k == 0 ? nseg - 1 : k - 1;  // the segment before key k
                            const T hb = dt(b), ha = dt(k);
                            L[k] = columns<T>([&](const vec3<T>& e) { return so3::jacobian(frame::body, r_[b], e) * (T(2) / hb); });
                            D[k] = add(identity<T>(T(4) / hb + T(4) / ha), dN(b));
                            U[k] = columns<T>([&](const vec3<T>& e) { return so3::inverse_jacobian(frame::body, r_[k], e) * (T(2) / ha); });
                        }
                    }
                }
                const std::vector<vec3<T>> delta = linear_solve(L, D, U, F);
                // Damped step: halve while the residual grows (never needed near the solution).
                const std::vector<vec3<T>> w0(w_.begin(), w_.end());
                const T f0 = max_norm(F);
                T lambda = 1;
                std::vector<vec3<T>> Fn;
                for (int h = 0; h < 30; ++h) {
                    for (std::size_t k = 0; k < m; ++k) set_rate(k, w0[k] - lambda * delta[k]);
                    Fn = residuals(kind, fixed);
                    if (max_norm(Fn) <= f0 || !(f0 > 0)) break;
                    lambda /= 2;
                }
                ++iterations_;
                T step = 0, size = 0;
                for (std::size_t k = 0; k < m; ++k) {
                    step = std::max(step, max_abs(w_[k] - w0[k]));
                    size = std::max(size, max_abs(w_[k]));
                }
                const bool stalled = !(max_norm(Fn) < f0);
                F = Fn;
                if (step <= T(4) * std::numeric_limits<T>::epsilon() * size || stalled) break;
            }
        }
        // The report: the largest acceleration jump at a key, against the largest acceleration there.
        residual_ = 0, accel_scale_ = T(1e-300);
        for (std::size_t k = 0; k < m; ++k)
            if (kind[k] != row::fixed) residual_ = std::max(residual_, max_abs(F[k]));
        for (std::size_t i = 0; i < nseg; ++i)
            accel_scale_ = std::max({accel_scale_, max_abs(a_start(i)), max_abs(a_end(i))});
    }

    // Solves J delta = F with J block tridiagonal (cyclic when closed).
    std::vector<vec3<T>> linear_solve(const std::vector<mat3>& L, const std::vector<mat3>& D, const std::vector<mat3>& U,
                                      const std::vector<vec3<T>>& F) const {
        using namespace detail_c2;
        const std::size_t m = D.size();
        std::vector<vec3<T>> x(m);
        if (!closed_) {
            std::vector<block<T, 1>> b(m);
            for (std::size_t k = 0; k < m; ++k)
                for (std::size_t i = 0; i < 3; ++i) b[k][i][0] = F[k][i];
            block_thomas<T, 1>(L, D, U, b);
            for (std::size_t k = 0; k < m; ++k)
                for (std::size_t i = 0; i < 3; ++i) x[k][i] = b[k][i][0];
            return x;
        }
        if (m == 2) {
            // Two keys, closed: both neighbours of each key are the other one.
            const mat3 A = D[0], B = add(L[0], U[0]), C = add(L[1], U[1]), E = D[1];
            // [A B; C E] [x0; x1] = [F0; F1]: Schur complement on x1.
            const mat3 Ai = inverse(A);
            const mat3 S = sub(E, mul(C, mul(Ai, B)));
            x[1] = mul(inverse(S), F[1] - mul(C, mul(Ai, F[0])));
            x[0] = mul(Ai, F[0] - mul(B, x[1]));
            return x;
        }
        // Cyclic: rows 0 .. m-2 on unknowns 0 .. m-2 are block tridiagonal, with
        // x_(m-1) coupled through L[0] (row 0) and U[m-2] (row m-2). Solve for
        // y (the right-hand side) and Z (those coupling columns) at once, then
        // x_(m-1) from the last row's 3x3 Schur complement, x_k = y_k - Z_k x_(m-1).
        const std::size_t r = m - 1;
        std::vector<block<T, 4>> b(r);
        for (std::size_t k = 0; k < r; ++k)
            for (std::size_t i = 0; i < 3; ++i) {
                b[k][i][0] = F[k][i];
                for (std::size_t j = 0; j < 3; ++j) b[k][i][j + 1] = (k == 0 ? L[0][i][j] : T(0)) + (k == r - 1 ? U[r - 1][i][j] : T(0));
            }
        std::vector<mat3> Lr(L.begin(), L.begin() + std::ptrdiff_t(r)), Dr(D.begin(), D.begin() + std::ptrdiff_t(r)),
            Ur(U.begin(), U.begin() + std::ptrdiff_t(r));
        block_thomas<T, 4>(Lr, Dr, Ur, b);
        auto y = [&](std::size_t k) { return vec3<T>{{b[k][0][0], b[k][1][0], b[k][2][0]}}; };
        auto Z = [&](std::size_t k) {
            mat3 z{};
            for (std::size_t i = 0; i < 3; ++i)
                for (std::size_t j = 0; j < 3; ++j) z[i][j] = b[k][i][j + 1];
            return z;
        };
        const mat3 S = sub(sub(D[r], mul(L[r], Z(r - 1))), mul(U[r], Z(0)));
        x[r] = mul(inverse(S), F[r] - mul(L[r], y(r - 1)) - mul(U[r], y(0)));
        for (std::size_t k = 0; k < r; ++k) x[k] = y(k) - mul(Z(k), x[r]);
        return x;
    }
};

}  // namespace crspline::rotation
