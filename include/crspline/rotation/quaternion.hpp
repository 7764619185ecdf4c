// crspline: unit quaternions for rotations in 3-D, and their conversions.
//
// A quaternion is [w, x, y, z] (scalar first), q = w + x i + y j + z k with
// i^2 = j^2 = k^2 = ijk = -1 (Hamilton). A rotation by angle a about the unit
// axis n is [cos(a/2), sin(a/2) n]; q and -q are the same rotation.
// Composition is in the world frame: applying p after q is p * q, and the
// rotation taking a to b is rel(a, b) = b * conj(a).
//
// exp and log work in half-angle units as in the `splines` package: exp(v) =
// [cos|v|, sin|v| v/|v|], log(q) = the vector part scaled to atan2(|vec|, w)
// (never acos: atan2 keeps every digit of small angles and of angles near
// pi). The rotation vector of q is 2 log(q) after q is taken with w >= 0.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <string>

#include "../detail/format.hpp"
#include "../error.hpp"
#include "../vec.hpp"

namespace crspline::rotation {

template <class T = double>
using vec3 = crspline::vec<3, T>;

template <class T>
constexpr vec3<T> cross(const vec3<T>& a, const vec3<T>& b) noexcept {
    return vec3<T>{{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

/// A quaternion [w, x, y, z]. An aggregate; the rotation classes keep unit
/// quaternions only, but the type itself does not insist (products of unit
/// quaternions drift from unit norm by rounding).
template <class T = double>
struct quaternion {
    T w = 1, x = 0, y = 0, z = 0;

    static constexpr quaternion identity() noexcept { return {1, 0, 0, 0}; }
    constexpr vec3<T> vector() const noexcept { return vec3<T>{{x, y, z}}; }
    static constexpr quaternion from(T w, const vec3<T>& v) noexcept { return {w, v[0], v[1], v[2]}; }
    constexpr std::array<T, 4> array() const noexcept { return {w, x, y, z}; }
    constexpr T operator[](std::size_t i) const noexcept { return i == 0 ? w : i == 1 ? x : i == 2 ? y : z; }

    friend constexpr quaternion operator*(const quaternion& a, const quaternion& b) noexcept {
        return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
                a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
    }
    friend constexpr quaternion operator*(T s, const quaternion& a) noexcept { return {s * a.w, s * a.x, s * a.y, s * a.z}; }
    friend constexpr quaternion operator+(const quaternion& a, const quaternion& b) noexcept {
        return {a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z};
    }
    friend constexpr quaternion operator-(const quaternion& a, const quaternion& b) noexcept {
        return {a.w - b.w, a.x - b.x, a.y - b.y, a.z - b.z};
    }
    friend constexpr quaternion operator-(const quaternion& a) noexcept { return {-a.w, -a.x, -a.y, -a.z}; }
    friend constexpr bool operator==(const quaternion&, const quaternion&) = default;
};

template <class T>
constexpr quaternion<T> conj(const quaternion<T>& q) noexcept { return {q.w, -q.x, -q.y, -q.z}; }

/// The 4-D dot product (cos of half the rotation angle between unit a and b, up to sign).
template <class T>
constexpr T dot(const quaternion<T>& a, const quaternion<T>& b) noexcept {
    return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
}

template <class T>
T norm(const quaternion<T>& q) noexcept {
    return crspline::norm(vec<4, T>{{q.w, q.x, q.y, q.z}});
}

template <class T>
quaternion<T> normalized(const quaternion<T>& q) noexcept {
    const T n = norm(q);
    return {q.w / n, q.x / n, q.y / n, q.z / n};
}

/// The rotation taking a to b, in the world frame: b * conj(a).
template <class T>
constexpr quaternion<T> rel(const quaternion<T>& a, const quaternion<T>& b) noexcept { return b * conj(a); }

/// exp(v) = [cos|v|, sin|v| v/|v|]: half-angle units (v is half the rotation vector).
template <class T>
quaternion<T> exp(const vec3<T>& v) noexcept {
    const T a = crspline::norm(v);
    const T s = a > 0 ? std::sin(a) / a : T(1);  // sin(a)/a keeps full relative accuracy for small a
    return quaternion<T>::from(std::cos(a), v * s);
}

/// The principal log of a unit quaternion: vector part scaled to length
/// atan2(|vec|, w) in [0, pi] (half the rotation angle). log([-1, 0, 0, 0])
/// has no direction: [pi, 0, 0] is returned.
template <class T>
vec3<T> log(const quaternion<T>& q) noexcept {
    const vec3<T> v = q.vector();
    const T s = crspline::norm(v);
    if (!(s > 0)) return q.w >= 0 ? vec3<T>{} : vec3<T>{{std::numbers::pi_v<T>, 0, 0}};
    return v * (std::atan2(s, q.w) / s);
}

/// q^s = exp(s log q).
template <class T>
quaternion<T> pow(const quaternion<T>& q, T s) noexcept { return exp(log(q) * s); }

/// slerp(a, b, u) = rel(a, b)^u * a: no sign change (if a . b < 0 it takes
/// the long way, as `splines.quaternion.slerp` does); u outside [0, 1] extrapolates.
template <class T>
quaternion<T> slerp(const quaternion<T>& a, const quaternion<T>& b, T u) noexcept {
    return pow(rel(a, b), u) * a;
}

/// The rotation angle between unit quaternions a and b, in [0, pi] (the short
/// way: a and -a are the same rotation): 4 atan2(|a - b|, |a + b|) on the
/// nearer of b and -b. Exact to rounding for tiny and for near-pi angles,
/// where 2 acos(a . b) loses half the digits.
template <class T>
T angle_between(const quaternion<T>& a, quaternion<T> b) noexcept {
    if (dot(a, b) < 0) b = -b;
    return T(4) * std::atan2(norm(a - b), norm(a + b));
}

/// The rotation angle of unit q, in [0, pi].
template <class T>
T angle(const quaternion<T>& q) noexcept {
    return T(2) * std::atan2(crspline::norm(q.vector()), std::abs(q.w));
}

/// Rotates the vector v by unit q: q [0, v] conj(q).
template <class T>
vec3<T> rotate(const quaternion<T>& q, const vec3<T>& v) noexcept {
    // v + 2 w (u x v) + 2 u x (u x v), u the vector part: 2 cross products.
    const vec3<T> u = q.vector();
    const vec3<T> t = T(2) * cross(u, v);
    return v + q.w * t + cross(u, t);
}

// ----- conversions --------------------------------------------------------------

/// Rotation vector (axis times angle, angle in [0, pi]) of unit q.
template <class T>
vec3<T> to_rotation_vector(const quaternion<T>& q) noexcept {
    return T(2) * log(q.w < 0 ? -q : q);
}

/// The unit quaternion (w >= 0 for angles up to pi) of a rotation vector.
template <class T>
quaternion<T> from_rotation_vector(const vec3<T>& r) noexcept { return exp(r * T(0.5)); }

/// Axis and angle; the axis of the identity is [1, 0, 0].
template <class T>
struct axis_angle {
    vec3<T> axis{{1, 0, 0}};
    T angle = 0;
};

template <class T>
axis_angle<T> to_axis_angle(const quaternion<T>& q) noexcept {
    const vec3<T> r = to_rotation_vector(q);
    const T a = crspline::norm(r);
    if (!(a > 0)) return {};
    return {r / a, a};
}

/// From an axis (normalized here; a zero axis is refused) and an angle in radians.
template <class T>
quaternion<T> from_axis_angle(const vec3<T>& axis, T angle) {
    const T n = crspline::norm(axis);
    if (!(n > 0) || !std::isfinite(n) || !std::isfinite(angle))
        throw invalid_input("axis-angle: the axis must be finite and nonzero and the angle finite, got axis [" +
                            detail::num(double(axis[0])) + ", " + detail::num(double(axis[1])) + ", " +
                            detail::num(double(axis[2])) + "], angle " + detail::num(double(angle)));
    return quaternion<T>::from(std::cos(angle / 2), axis * (std::sin(angle / 2) / n));
}

/// Row-major 3x3 rotation matrix.
template <class T>
using matrix3 = std::array<std::array<T, 3>, 3>;

template <class T>
matrix3<T> to_matrix(const quaternion<T>& q) noexcept {
    const T w = q.w, x = q.x, y = q.y, z = q.z;
    return {{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
             {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
             {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
}

/// From a rotation matrix (Shepperd's method: the largest of w, x, y, z is
/// taken from the diagonal, the rest from off-diagonal sums, so no square
/// root of a small number). The result has w >= 0. The matrix must be a
/// rotation to within `tolerance` (max |M^T M - I| and |det - 1|), else invalid_input.
template <class T>
quaternion<T> from_matrix(const matrix3<T>& m, T tolerance = T(1e-9)) {
    T worst = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            if (!std::isfinite(m[i][j]))
                throw invalid_input("rotation matrix: entry [" + std::to_string(i) + "][" + std::to_string(j) +
                                    "] is not finite (" + detail::num(double(m[i][j])) + ")");
            T s = 0;
            for (int k = 0; k < 3; ++k) s += m[k][i] * m[k][j];
            worst = std::max(worst, std::abs(s - (i == j ? T(1) : T(0))));
        }
    const T det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                  m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    if (worst > tolerance || std::abs(det - 1) > tolerance)
        throw invalid_input("rotation matrix: not a rotation (max |M^T M - I| = " + detail::num(double(worst)) +
                            ", det = " + detail::num(double(det)) + ", tolerance " + detail::num(double(tolerance)) + ")");
    const T tr = m[0][0] + m[1][1] + m[2][2];
    quaternion<T> q;
    if (tr >= m[0][0] && tr >= m[1][1] && tr >= m[2][2]) {
        const T s = std::sqrt(1 + tr) * 2;  // 4 w
        q = {s / 4, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s};
    } else if (m[0][0] >= m[1][1] && m[0][0] >= m[2][2]) {
        const T s = std::sqrt(1 + m[0][0] - m[1][1] - m[2][2]) * 2;  // 4 x
        q = {(m[2][1] - m[1][2]) / s, s / 4, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s};
    } else if (m[1][1] >= m[2][2]) {
        const T s = std::sqrt(1 + m[1][1] - m[0][0] - m[2][2]) * 2;  // 4 y
        q = {(m[0][2] - m[2][0]) / s, (m[0][1] + m[1][0]) / s, s / 4, (m[1][2] + m[2][1]) / s};
    } else {
        const T s = std::sqrt(1 + m[2][2] - m[0][0] - m[1][1]) * 2;  // 4 z
        q = {(m[1][0] - m[0][1]) / s, (m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, s / 4};
    }
    q = normalized(q);
    return q.w < 0 ? -q : q;
}

/// Euler angles with a named convention, as SciPy names them: three letters
/// from x, y, z; lower case = extrinsic (axes of the fixed world frame, the
/// first letter applied first), upper case = intrinsic (axes of the rotating
/// body, the first letter applied first). "xyz", "ZYX", "zxz", "XYX"... Two
/// consecutive letters must differ.
struct euler_convention {
    std::array<int, 3> axes{0, 1, 2};
    bool intrinsic = false;

    static euler_convention parse(const std::string& s) {
        auto bad = [&](const std::string& why) {
            return invalid_input("euler convention \"" + s + "\": " + why +
                                 " (three of x, y, z, all lower case = extrinsic or all upper case = intrinsic, "
                                 "no letter twice in a row, e.g. \"xyz\", \"ZYX\", \"zxz\")");
        };
        if (s.size() != 3) throw bad("needs three letters");
        euler_convention c;
        const bool upper = s[0] >= 'X' && s[0] <= 'Z';
        for (std::size_t i = 0; i < 3; ++i) {
            const char ch = s[i];
            const bool u = ch >= 'X' && ch <= 'Z', l = ch >= 'x' && ch <= 'z';
            if (!u && !l) throw bad("letter " + std::to_string(i) + " ('" + std::string(1, ch) + "') is not an axis");
            if (u != upper) throw bad("mixes upper and lower case");
            c.axes[i] = u ? ch - 'X' : ch - 'x';
        }
        if (c.axes[0] == c.axes[1] || c.axes[1] == c.axes[2]) throw bad("the same axis twice in a row");
        c.intrinsic = upper;
        return c;
    }
};

/// From Euler angles (radians): extrinsic e1, e2, e3 about world axes a1, a2,
/// a3 is R = R_a3(e3) R_a2(e2) R_a1(e1); intrinsic is the same angles in the
/// reverse product, R = R_a1(e1) R_a2(e2) R_a3(e3).
template <class T>
quaternion<T> from_euler(const euler_convention& c, const std::array<T, 3>& angles) {
    auto elementary = [](int axis, T a) {
        vec3<T> e{};
        e[std::size_t(axis)] = std::sin(a / 2);
        return quaternion<T>::from(std::cos(a / 2), e);
    };
    for (std::size_t i = 0; i < 3; ++i)
        if (!std::isfinite(angles[i]))
            throw invalid_input("euler angle " + std::to_string(i) + " is not finite (" + detail::num(double(angles[i])) + ")");
    const auto q1 = elementary(c.axes[0], angles[0]), q2 = elementary(c.axes[1], angles[1]),
               q3 = elementary(c.axes[2], angles[2]);
    return c.intrinsic ? q1 * q2 * q3 : q3 * q2 * q1;
}

/// Euler angles of unit q in the convention (the inverse of from_euler):
/// the quaternion method of Bernardes and Viollet (2022), as SciPy uses it.
/// The first and third angles are in (-pi, pi], the second in [0, pi] for a
/// symmetric convention (first axis = third) and [-pi/2, pi/2] otherwise. At
/// gimbal lock (second angle within 1e-7 of 0 or pi, resp. +-pi/2) the angle
/// first in the extrinsic order (the last of an intrinsic sequence) is 0
/// and the other outer angle carries the whole turn.
template <class T>
std::array<T, 3> to_euler(const euler_convention& c, const quaternion<T>& q) noexcept {
    // Work extrinsic: an intrinsic sequence is the extrinsic one reversed.
    int i = c.axes[0], j = c.axes[1], k = c.axes[2];
    if (c.intrinsic) std::swap(i, k);
    const bool symmetric = i == k;
    if (symmetric) k = 3 - i - j;
    const int sign = ((i - j) * (j - k) * (k - i)) / 2;  // +1 for an even permutation of (0, 1, 2)
    const std::array<T, 4> qv{q.x, q.y, q.z, q.w};
    T a, b, cc, d;
    if (symmetric) {
        a = qv[3], b = qv[std::size_t(i)], cc = qv[std::size_t(j)], d = qv[std::size_t(k)] * T(sign);
    } else {
        a = qv[3] - qv[std::size_t(j)], b = qv[std::size_t(i)] + qv[std::size_t(k)] * T(sign),
        cc = qv[std::size_t(j)] + qv[3], d = qv[std::size_t(k)] * T(sign) - qv[std::size_t(i)];
    }
    std::array<T, 3> e{};
    e[1] = 2 * std::atan2(std::hypot(cc, d), std::hypot(a, b));
    const T eps = T(1e-7);
    const T half_sum = std::atan2(b, a), half_diff = std::atan2(d, cc);
    if (std::abs(e[1]) <= eps) {
        e[0] = 0, e[2] = 2 * half_sum;  // gimbal lock: only the sum of the angles is defined
    } else if (std::abs(e[1] - std::numbers::pi_v<T>) <= eps) {
        e[0] = 0, e[2] = 2 * half_diff;  // only their difference is defined
    } else {
        e[0] = half_sum - half_diff, e[2] = half_sum + half_diff;
    }
    if (!symmetric) {
        e[2] *= T(sign);
        e[1] -= std::numbers::pi_v<T> / 2;
    }
    auto wrap = [](T x) {
        const T pi = std::numbers::pi_v<T>;
        if (x <= -pi) x += 2 * pi;
        if (x > pi) x -= 2 * pi;
        return x;
    };
    e[0] = wrap(e[0]), e[2] = wrap(e[2]);
    if (c.intrinsic) std::swap(e[0], e[2]);
    return e;
}

/// Checks a key and normalizes it, as SciPy's Rotation.from_quat does: a
/// key with a component that is not finite, or of norm zero, is refused with
/// the index and the value (it is no rotation). With a finite `tolerance`
/// (the `splines` drop-in's 1e-6, the CLI's file check), a key farther than
/// it from unit norm is refused too (a norm of 0.9 there is more likely a
/// wrong field than rounding); the native classes' default is infinity:
/// every other key is normalized.
template <class T>
quaternion<T> checked_unit(const quaternion<T>& q, std::size_t index, T tolerance, const char* what = "key") {
    const std::array<T, 4> a = q.array();
    for (std::size_t c = 0; c < 4; ++c)
        if (!std::isfinite(a[c]))
            throw invalid_input(std::string(what) + " " + std::to_string(index) + ": component " + std::to_string(c) +
                                " (" + "wxyz"[c] + ") is not finite (" + detail::num(double(a[c])) + ")");
    const T n = norm(q);
    if (!(std::abs(n - 1) <= tolerance))
        throw invalid_input(std::string(what) + " " + std::to_string(index) + " [" + detail::num(double(q.w)) + ", " +
                            detail::num(double(q.x)) + ", " + detail::num(double(q.y)) + ", " +
                            detail::num(double(q.z)) + "] is not a unit quaternion (norm " + detail::num(double(n)) +
                            ", allowed 1 +- " + detail::num(double(tolerance)) + ")");
    if (!(n > 0) || !std::isfinite(n)) {
        // Zero, or a norm below or beyond what T holds: scaled by the largest
        // component first (then within [1, 2]).
        T m = 0;
        for (const T x : a) m = std::max(m, std::abs(x));
        if (!(m > 0))
            throw invalid_input(std::string(what) + " " + std::to_string(index) + " [0, 0, 0, 0] has norm 0: not a rotation");
        const quaternion<T> s{q.w / m, q.x / m, q.y / m, q.z / m};
        return checked_unit(s, index, std::numeric_limits<T>::infinity(), what);
    }
    return {q.w / n, q.x / n, q.y / n, q.z / n};
}

/// A batch call's output must hold one result per parameter value: the
/// sizes, in the words every rotation class uses ("output has 3 rotations
/// for 4 parameter values").
inline void check_batch_size(std::size_t out, std::size_t t, const char* what) {
    if (out != t)
        throw invalid_input("output has " + std::to_string(out) + " " + what + " for " + std::to_string(t) +
                            " parameter values");
}

}  // namespace crspline::rotation
