// crspline sweeps, internals: how far the frame at each ring may be from
// the exact rotation-minimizing frame, proved.
//
// The rings carry their normal by double reflection (frames.hpp), a
// fourth-order approximation of the rotation-minimizing frame (RMF). The
// exact RMF's normal is the parallel transport, on the unit sphere, of a
// tangent vector along the tangent's path T(u); the minimal rotation that
// takes T_a to T_b (about T_a x T_b) is the transport along the great
// circle between them. They differ by a turn about T_b equal to the area
// between the path and that great circle (Gauss-Bonnet): with n the unit
// vector along T_a x T_b, latitude beta (sin beta = T.n) and longitude
// lambda about n,
//     A = -integral of sin(beta) dlambda
//       = -integral of g(u) h(u) du,   g = x'.n,   h = det(n, x', x'') / (v (v^2 - g^2)),
// v = |x'|. g is a quadratic that vanishes at u_a and u_b (n is normal to
// x'(u_a) and x'(u_b)), so g = q (u - u_a)(u - u_b) with q = 3 c3.n (plus
// the rounding of its end values, a linear term kept apart); the first
// factor has one sign, so the integral is q times the integral of
// |(u - u_a)(u - u_b)| (a polynomial) times a mean value of h. h is
// enclosed on each of two sub-intervals: its numerator n.(x' x x'') is a
// quadratic (its range from its ends and its vertex), v lies within
// (|x'(a)| + |x'(b)|  -+ (b - a) max|x''|) / 2 and |g| below its bound.
// That encloses A in an interval of width O(w^4) on a piece of width w.
//
// Per ring step, the double reflection's turn alpha against the minimal
// rotation is measured (the minimal rotations chained through the knots the
// step crosses); its error against the exact RMF is then at most
// |alpha - mid(A)| + radius(A), plus a rounding slack of 64 ulps of a
// radian. Transports are isometries of the normal planes, so the errors
// add: the drift at ring k is the sum over the steps before it. A closed
// curve's spread holonomy is measured on the carried frame, so it is off by
// at most the last ring's drift: the spread frame at ring k is within
// drift_k + f_k drift_last of the exact RMF with the exact holonomy spread
// (f_k the fraction of the period; the holonomy taken on the branch nearest
// the measured one). A profile point at distance r |p| from the centre
// then moves by at most r |p| times that angle, and so does every point of
// a triangle (a convex combination of its corners). A piece whose speed
// bound is not positive, or whose tangent path may reach the pole n (a
// turn near 90 degrees between rings), has no enclosure: rings.hpp halves
// it (up to 2^6 parts), and where that is not enough the drift is infinite.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "../frames.hpp"
#include "../segment.hpp"
#include "../vec.hpp"

namespace crspline::detail {

/// A segment that does not move (a repeated point): no tangent, no piece.
inline bool constant_segment(const cubic_segment<3, double>& s) {
    return s.c1 == vec<3>{} && s.c2 == vec<3>{} && s.c3 == vec<3>{};
}

/// v carried by the minimal rotation that takes the unit vector a to the
/// unit vector b (about a x b); nullopt when they are more than 120
/// degrees apart (not a ring step).
inline std::optional<vec<3>> minimal_rotation(const vec<3>& a, const vec<3>& b, const vec<3>& v) {
    const double c = dot(a, b);
    if (!(c > -0.5)) return std::nullopt;
    const vec<3> k = cross(a, b);
    return c * v + cross(k, v) + (dot(k, v) / (1 + c)) * k;
}

/// The exact RMF's turn about the tangent against the minimal rotation over
/// the piece [ua, ub] of s (see above): an enclosing interval, with the
/// unit tangents at the piece's ends.
struct rmf_turn {
    double lo = 0, hi = 0;
    vec<3> ta{}, tb{};
};

inline std::optional<rmf_turn> enclose_rmf_turn(const cubic_segment<3, double>& s, double ua, double ub) {
    const vec<3> da = s.du(ua, 1), db = s.du(ub, 1);
    const double va = norm(da), vb = norm(db);
    if (!(va > 0 && vb > 0) || !std::isfinite(va + vb)) return std::nullopt;
    rmf_turn r;
    r.ta = da / va, r.tb = db / vb;
    vec<3> nh = cross(r.ta, r.tb);
    const double sn = norm(nh);
    nh = sn > 0 ? nh / sn : any_perpendicular(r.ta);
    const double w = ub - ua;
    const double k2 = std::max(norm(s.du(ua, 2)), norm(s.du(ub, 2)));
    const double q = dot(s.du(0, 3), nh) / 2;                                 // 3 c3.n
    const double glin = std::max(std::abs(dot(da, nh)), std::abs(dot(db, nh)));  // rounding only
    // n.(x' x x'') = 2 n.(c1 x c2) + 6 n.(c1 x c3) u + 6 n.(c2 x c3) u^2.
    const double n0 = 2 * dot(nh, cross(s.c1, s.c2)), n1 = 6 * dot(nh, cross(s.c1, s.c3)),
                 n2 = 6 * dot(nh, cross(s.c2, s.c3));
    auto numer = [&](double u) { return n0 + u * (n1 + u * n2); };
    auto p_abs = [&](double u) { return (u - ua) * (ub - u); };
    auto p_int = [&](double u) {  // the integral of |p| from ua to u
        const double x = u - ua;
        return w * x * x / 2 - x * x * x / 3;
    };
    constexpr int m = 2;
    double a = ua, na = numer(ua), v_a = va, extra = 0;
    for (int j = 0; j < m; ++j) {
        const double b = j + 1 == m ? ub : ua + w * double(j + 1) / m;
        const double nb = numer(b), v_b = j + 1 == m ? vb : norm(s.du(b, 1));
        double n_lo = std::min(na, nb), n_hi = std::max(na, nb);
        if (n2 != 0) {  // the quadratic's vertex, where it lies inside
            const double uv = -n1 / (2 * n2);
            if (uv > a && uv < b) n_lo = std::min(n_lo, numer(uv)), n_hi = std::max(n_hi, numer(uv));
        }
        const double v_lo = (v_a + v_b - (b - a) * k2) / 2, v_hi = (v_a + v_b + (b - a) * k2) / 2;
        const double mid = (ua + ub) / 2;
        const double p_max = a <= mid && mid <= b ? w * w / 4 : std::max(p_abs(a), p_abs(b));
        const double g_max = glin + std::abs(q) * p_max;
        if (!(v_lo > g_max)) return std::nullopt;
        const double d_lo = v_lo * (v_lo - g_max) * (v_lo + g_max), d_hi = v_hi * v_hi * v_hi;
        const double h_lo = n_lo >= 0 ? n_lo / d_hi : n_lo / d_lo;
        const double h_hi = n_hi >= 0 ? n_hi / d_lo : n_hi / d_hi;
        const double P = p_int(b) - p_int(a);
        if (q >= 0) r.lo += q * P * h_lo, r.hi += q * P * h_hi;
        else r.lo += q * P * h_hi, r.hi += q * P * h_lo;
        extra += glin * (b - a) * std::max(std::abs(h_lo), std::abs(h_hi));
        a = b, na = nb, v_a = v_b;
    }
    r.lo -= extra, r.hi += extra;
    if (!std::isfinite(r.lo) || !std::isfinite(r.hi)) return std::nullopt;
    return r;
}

/// The rounding slack of one ring step's drift (the angles and rotations
/// of a step are a few operations on unit vectors): 64 ulps of a radian.
inline constexpr double drift_slack = 64 * std::numeric_limits<double>::epsilon();

}  // namespace crspline::detail
