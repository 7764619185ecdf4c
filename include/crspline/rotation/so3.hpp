// crspline: derivatives on SO(3). The Jacobians of the exponential map and
// the angular velocity and acceleration of curves built from slerps, exact
// (analytic), as "jets": a rotation with its first two derivatives.
//
// phi is a rotation vector (axis times angle theta = |phi|), R = Exp(phi).
// With phi' its derivative, the angular velocity of R is
//     world frame:  omega = J_l(phi) phi',   J_l = I + k1 [phi]x + k2 [phi]x^2
//     body frame:   omega = J_r(phi) phi',   J_r = I - k1 [phi]x + k2 [phi]x^2
// with k1 = (1 - cos theta)/theta^2, k2 = (theta - sin theta)/theta^3, and
// its angular acceleration is J phi'' + N(phi, phi'), N = (dJ/dt) phi':
//     N_l = (phi . phi') (-K1 phi x phi' + K2 phi x (phi x phi')) + k2 phi' x (phi x phi')
//     N_r = (phi . phi') ( K1 phi x phi' + K2 phi x (phi x phi')) + k2 phi' x (phi x phi')
// with K1 = -k1'/theta, K2 = k2'/theta (SciPy's RotationSpline uses N_r).
// The inverses are J_l^-1 = I - [phi]x/2 + kA [phi]x^2, J_r^-1 = I + [phi]x/2
// + kA [phi]x^2, kA = (1 - (theta/2) cot(theta/2))/theta^2.
// Every coefficient is a power series in theta^2 below theta = 2 (summed to
// rounding) and the closed form above, where its cancellation costs at most
// a digit.
#pragma once

#include <cmath>

#include "quaternion.hpp"

namespace crspline::rotation {

/// The frame of an angular velocity or acceleration: world (fixed axes,
/// dq/dt = 1/2 [0, omega] q) or body (axes that turn with the object,
/// dq/dt = 1/2 q [0, omega]).
enum class frame { world, body };

namespace so3 {

template <class T>
struct coefficients {
    T k1, k2, K1, K2;
};

/// k1, k2, K1, K2 at theta = |phi|.
template <class T>
coefficients<T> jacobian_coefficients(T theta) noexcept {
    const T z = theta * theta;
    coefficients<T> c{};
    const T h = theta / 2;
    const T sh = h > 0 ? std::sin(h) / h : T(1);
    c.k1 = sh * sh / 2;  // (1 - cos theta)/theta^2 = 2 sin^2(theta/2)/theta^2, no cancellation
    if (theta < 2) {
        // k2 = sum_j (-1)^j z^j/(2j+3)!; K1 = sum_{j>=1} (-1)^(j+1) 2j z^(j-1)/(2j+2)!;
        // K2 = sum_{j>=1} (-1)^j 2j z^(j-1)/(2j+3)!. 16 terms: the last is below
        // 4^16 / 33! ~ 5e-27 of the first at theta = 2.
        T t = T(1) / 6, k2 = t;
        T u = T(1) / 24, K1 = 2 * u;
        T v = -T(1) / 120, K2 = 2 * v;
        for (int j = 1; j < 16; ++j) {
            t *= -z / T((2 * j + 2) * (2 * j + 3));
            k2 += t;
            const int jj = j + 1;
            u *= -z / T((2 * jj + 1) * (2 * jj + 2));
            K1 += T(2 * jj) * u;
            v *= -z / T((2 * jj + 2) * (2 * jj + 3));
            K2 += T(2 * jj) * v;
            // The terms fall faster than geometrically: stop once the largest
            // (K1's, relative to its sum of about 1/12) is below rounding.
            if (T(2 * jj) * std::abs(u) <= T(1e-17)) break;
        }
        c.k2 = k2, c.K1 = K1, c.K2 = K2;
    } else {
        const T s = std::sin(theta), co = std::cos(theta);
        c.k2 = (theta - s) / (z * theta);
        c.K1 = (T(2) * (T(1) - co) - theta * s) / (z * z);
        c.K2 = (T(3) * s - T(2) * theta - theta * co) / (z * z * theta);
    }
    return c;
}

/// kA = (1 - (theta/2) cot(theta/2))/theta^2, for the inverse Jacobians
/// (theta < 2 pi). With x = theta/2: 1 - x cot x = (sin x - x cos x)/sin x
/// and sin x - x cos x = x^3 S(x), S = sum_{j>=1} (-1)^(j+1) 2j x^(2j-2)/(2j+1)!,
/// so kA = S(x) x / (4 sin x).
template <class T>
T inverse_coefficient(T theta) noexcept {
    const T x = theta / 2, y = x * x;
    if (theta < 2) {
        T s = T(1) / 6, S = 2 * s;
        for (int j = 2; j < 18; ++j) {
            s *= -y / T((2 * j) * (2 * j + 1));
            S += T(2 * j) * s;
            if (T(2 * j) * std::abs(s) <= T(1e-17)) break;  // S is about 1/3: below rounding
        }
        const T xs = x > 0 ? x / std::sin(x) : T(1);
        return S * xs / 4;
    }
    return (T(1) - x * std::cos(x) / std::sin(x)) / (theta * theta);
}

/// J_l(phi) v (world) or J_r(phi) v (body).
template <class T>
vec3<T> jacobian(frame f, const vec3<T>& phi, const vec3<T>& v) noexcept {
    const auto c = jacobian_coefficients(crspline::norm(phi));
    const vec3<T> pv = cross(phi, v);
    return v + (f == frame::world ? c.k1 : -c.k1) * pv + c.k2 * cross(phi, pv);
}

/// J^-1(phi) v: the rotation vector's derivative from an angular velocity.
template <class T>
vec3<T> inverse_jacobian(frame f, const vec3<T>& phi, const vec3<T>& v) noexcept {
    const T kA = inverse_coefficient(crspline::norm(phi));
    const vec3<T> pv = cross(phi, v);
    return v + (f == frame::world ? T(-0.5) : T(0.5)) * pv + kA * cross(phi, pv);
}

/// N(phi, phi') = (dJ/dt) phi'.
template <class T>
vec3<T> jacobian_rate(frame f, const vec3<T>& phi, const vec3<T>& dphi) noexcept {
    const auto c = jacobian_coefficients(crspline::norm(phi));
    const T dp = crspline::dot(phi, dphi);
    const vec3<T> cp = cross(phi, dphi), ccp = cross(phi, cp), dccp = cross(dphi, cp);
    return dp * ((f == frame::world ? -c.K1 : c.K1) * cp + c.K2 * ccp) + c.k2 * dccp;
}

/// A rotation with its angular velocity and acceleration in the world frame,
/// with respect to whatever parameter the jet was built in.
template <class T>
struct jet {
    quaternion<T> q{};
    vec3<T> omega{};
    vec3<T> alpha{};
};

/// The jet of the rotation Exp(phi(t)) * a(t) ... of Exp(phi) alone: from
/// phi, phi', phi''.
template <class T>
jet<T> exp_jet(const vec3<T>& phi, const vec3<T>& dphi, const vec3<T>& ddphi, int order) noexcept {
    jet<T> e;
    e.q = from_rotation_vector(phi);
    if (order >= 1) e.omega = jacobian(frame::world, phi, dphi);
    if (order >= 2) e.alpha = jacobian(frame::world, phi, ddphi) + jacobian_rate(frame::world, phi, dphi);
    return e;
}

/// The jet of E * a for a constant-free E (a jet itself) and a jet a:
/// omega = omega_E + R_E omega_a, alpha = alpha_E + omega_E x (R_E omega_a) + R_E alpha_a.
template <class T>
jet<T> compose(const jet<T>& e, const jet<T>& a, int order) noexcept {
    jet<T> x;
    x.q = e.q * a.q;
    if (order >= 1) {
        const vec3<T> ra = rotate(e.q, a.omega);
        x.omega = e.omega + ra;
        if (order >= 2) x.alpha = e.alpha + cross(e.omega, ra) + rotate(e.q, a.alpha);
    }
    return x;
}

/// slerp(a, b, s) = rel(a, b)^s * a with a, b jets and s a function of the
/// parameter with derivatives s1, s2. With c = b conj(a) and phi_c = 2 log c:
///     omega_c = omega_b - R_c omega_a,
///     alpha_c = alpha_b - omega_c x (R_c omega_a) - R_c alpha_a,
///     phi_c'  = J_l^-1 omega_c,  phi_c'' = J_l^-1 (alpha_c - N_l(phi_c, phi_c')),
/// and Phi = s phi_c is the rotation vector of the slerp's left factor.
template <class T>
jet<T> slerp_jet(const jet<T>& a, const jet<T>& b, T s, T s1, T s2, int order) noexcept {
    const quaternion<T> c = rel(a.q, b.q);
    const vec3<T> phi = T(2) * log(c);
    vec3<T> dphi{}, ddphi{};
    if (order >= 1) {
        const vec3<T> ra = rotate(c, a.omega);
        const vec3<T> wc = b.omega - ra;
        dphi = inverse_jacobian(frame::world, phi, wc);
        if (order >= 2) {
            const vec3<T> ac = b.alpha - cross(wc, ra) - rotate(c, a.alpha);
            ddphi = inverse_jacobian(frame::world, phi, ac - jacobian_rate(frame::world, phi, dphi));
        }
    }
    const vec3<T> Phi = s * phi;
    const vec3<T> dPhi = s1 * phi + s * dphi;
    const vec3<T> ddPhi = s2 * phi + T(2) * s1 * dphi + s * ddphi;
    // The left factor is c^s = exp(s log c): its rotation vector s phi may
    // exceed pi (a long-way slerp); from_rotation_vector handles any length.
    return compose(exp_jet(Phi, dPhi, ddPhi, order), a, order);
}

/// A constant rotation as a jet.
template <class T>
jet<T> constant(const quaternion<T>& q) noexcept { return {q, {}, {}}; }

}  // namespace so3
}  // namespace crspline::rotation
