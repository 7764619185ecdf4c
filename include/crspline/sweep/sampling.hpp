// crspline sweeps, internals: where the rings go along the curve, with the
// bound that proves the mesh within the tolerance of the swept surface.
//
// The surface is S(u, p) = x(u) + r(u) F(u) p on a segment's local u, p a
// point of the profile plane, F = [N B] the frame's normal and binormal, r
// the scale. Between rings u_a and u_b (width w) and profile vertices p_j,
// p_(j+1) (edge length e), every point of a mesh triangle is the chord
// point lambda of the surface curve c(lambda) = S(u(lambda), q(lambda)), u
// and q linear in lambda from one triangle corner to a point of the
// opposite edge (q stays on the profile's edge). A chord is within
// max|c''| / 8 of its curve at the same lambda (the Green's function bound
// that tessellate.hpp's flatness bound (1) uses), and
//     c'' = w^2 (x'' + (rF)'' q) + 2 w (rF)' (q_(j+1) - q_j),
// so the mesh is within
//     w^2 / 8 (|x''| + rho |(rF)''|) + w e / 4 |(rF)'|          (along)
// of the surface through the profile's polygon, and that polygon within its
// own chord bound delta of the profile (around): r_max delta. With omega
// the frame's angular velocity (the rotation-minimizing part x' x x'' /
// |x'|^2 plus the roll and the spread holonomy psi' along the tangent):
//     |(rF)'|  <= |r'| + r |omega|,
//     |(rF)''| <= |r''| + 2 |r'| |omega| + r (|omega|^2 + |omega'|),
//     |omega|  <= |x''| / |x'| + |psi'|,
//     |omega'| <= |x'''| / |x'| + 2 |x''|^2 / |x'|^2 + |psi''| + |psi'| |x''| / |x'|,
// With an up vector U (unit) the normal is U's projection on the normal
// plane outside the cones within 5 degrees of U (rings.hpp); there its turn
// about T is psi' = -(U.T)(T'.B) / |U x T|, so with
// theta the angle of T to U and tau >= |T'| (= |x''| / |x'| at most):
//     |psi'|  <= cot(theta) tau,
//     |psi''| <= tau^2 / sin^2(theta) + cot(theta) (|T''| + tau |omega|),
//     |T''|   <= |x'''| / |x'| + 3 tau |x''| / |x'|,
// sin(theta) bounded from below over the piece as |x'| is (|U x x'| has
// derivative |U x x''| <= |x''|) over max |x'| (it must be positive). Inside
// a cone (a pole) the frame is the rotation-minimizing one carried from the
// ring where the curve enters it, turned by psi = Delta sigma((t - t_in) /
// (t_out - t_in)), sigma(x) = 3 x^2 - 2 x^3, onto the projection where it
// leaves (Delta at most pi / 2 plus the drift: rings.hpp); so there
//     |psi'| <= 1.5 |Delta| / (t_out - t_in),  |psi''| <= 6 |Delta| / (t_out - t_in)^2
// per unit t (the zone rates). A piece outside the cones whose sin(theta)
// bound is not positive has no bound: infinite (the placement cuts it
// further; at given counts, rings too far apart around a pole, the report
// says so).
// each maximum taken over the piece: |x''| at an end (x'' is affine),
// |x'''| = 6 |c3|, |x'| from below by (|x'(u_a)| + |x'(u_b)| - w max|x''|) / 2,
// the roll and the scale by their Bézier control polygons. A piece whose
// speed bound is not positive (a cusp) cannot be proved; it is cut until a
// budget runs out and the report says the tolerance is not met.
//
// F here is the exact frame (the exact rotation-minimizing frame, turned);
// the rings' frames, carried by double reflection, are within the angle
// drift.hpp bounds of it, and the mesh's vertices (so its triangles) within
// r |p| times that angle of the mesh on the exact frames: sweep.hpp adds
// that term to the bound.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "../segment.hpp"
#include "../vec.hpp"

namespace crspline::detail {

/// What the bound needs to know besides the curve's segment, over one
/// interval of a segment between breakpoints (knots, roll keys, scale keys).
struct piece_rates {
    double rho = 0;         ///< largest |p| of the profile
    double edge = 0;        ///< longest profile edge
    double scale = 1;       ///< max r over the interval
    double scale_s1 = 0;    ///< max |dr/ds|
    double scale_s2 = 0;    ///< max |d2r/ds2|
    double roll_w1 = 0;     ///< max |dpsi/dw| of the roll keys
    double roll_w2 = 0;     ///< max |d2psi/dw2|
    bool roll_in_s = false; ///< w is arc length (else t)
    double dt_du = 1;       ///< the segment's knot interval (dt/du)
    double twist_t = 0;     ///< |holonomy| / period: the spread twist per unit t (constant)
    bool has_up = false;    ///< up mode: the frame follows `up`'s projection
    bool in_zone = false;   ///< up mode: the piece is inside a cone around `up` (the blend below)
    double zone_t1 = 0;     ///< there: max |dpsi/dt| of the blend onto the projection
    double zone_t2 = 0;     ///< max |d2psi/dt2|
    vec<3> up{};            ///< the unit up vector
};

/// The cones around the up vector where the frame is not its projection
/// (rings.hpp): tangents within 5 degrees of it; sin(5 degrees).
inline const double up_clear_sin = std::sin(5 * 3.14159265358979323846 / 180);

/// The bounds on the centre line's derivatives over the piece [ua, ub] of
/// segment s that the bounds below share (see above): x' at the ends,
/// max |x''| (at an end: x'' is affine), |x'''|, and |x'| from below and
/// above.
struct piece_derivatives {
    double w, k2, k3, v_lo = 0, v_hi = 0;
    vec<3> da, db;
    piece_derivatives(const cubic_segment<3, double>& s, double ua, double ub)
        : w(ub - ua), k2(std::max(norm(s.du(ua, 2)), norm(s.du(ub, 2)))), k3(norm(s.du(0, 3))), da(s.du(ua, 1)),
          db(s.du(ub, 1)) {
        const double va = norm(da), vb = norm(db);
        v_lo = (va + vb - w * k2) / 2;
        v_hi = (va + vb + w * k2) / 2;
    }
};

/// A lower bound on sin(angle(up, tangent)) over the piece (up a unit
/// vector); 0 where it may vanish.
inline double up_sin_lower(const piece_derivatives& d, const vec<3>& up) {
    const double g_lo = (norm(cross(up, d.da)) + norm(cross(up, d.db)) - d.w * d.k2) / 2;
    return d.v_hi > 0 && g_lo > 0 ? std::min(1.0, g_lo / d.v_hi) : 0.0;
}

/// The up frame's turn rates over the piece (see above): {|psi'|, |psi''|}
/// bounds per unit u, or {-1, -1} where the tangent may reach up (or the
/// speed bound is not positive).
inline std::array<double, 2> up_rates(const piece_derivatives& d, const vec<3>& up) {
    const double sn = up_sin_lower(d, up);
    if (!(d.v_lo > 0) || !(sn > 0)) return {-1.0, -1.0};
    const double cot = std::sqrt(std::max(0.0, 1 - sn * sn)) / sn;
    const double tau = d.k2 / d.v_lo, t2 = d.k3 / d.v_lo + 3 * tau * d.k2 / d.v_lo;
    const double psi1 = cot * tau;
    return {psi1, tau * tau / (sn * sn) + cot * (t2 + tau * (tau + psi1))};
}

/// Whether the piece [ua, ub] of segment s (outside the cones) has the up
/// vector's projection for its frame, proved: its tangent never reaches up,
/// and the frame turns less than a radian between its rings (so the ring's
/// choice of the projection or its opposite follows the continuous frame).
inline bool up_piece_proved(const cubic_segment<3, double>& s, double ua, double ub, const vec<3>& up) {
    const auto r = up_rates(piece_derivatives(s, ua, ub), up);
    return r[0] >= 0 && r[0] * (ub - ua) < 1;
}

/// An upper bound on the curvature of segment s over [ua, ub] (for the
/// report's fold test): the largest |x' x x''| (a quadratic in u,
/// 2 c1 x c2 + 6 (c1 x c3) u + 6 (c2 x c3) u^2, bounded by its Taylor form
/// at the middle) over the cube of the speed's lower bound; cut in halves
/// (up to 2^6 parts) where that lower bound is not positive or the bound is
/// over 1.1 times the curvature at the piece's ends and middle (so it is
/// close); +infinity at a cusp (speed zero: any tube folds there).
inline double curvature_upper(const cubic_segment<3, double>& s, double ua, double ub, int depth = 0) {
    const piece_derivatives d(s, ua, ub);
    const double m = (ua + ub) / 2, h = (ub - ua) / 2;
    auto split = [&] { return std::max(curvature_upper(s, ua, m, depth + 1), curvature_upper(s, m, ub, depth + 1)); };
    if (!(d.v_lo > 0)) return depth < 6 ? split() : std::numeric_limits<double>::infinity();
    const vec<3> c0 = 2.0 * cross(s.c1, s.c2), c1 = 6.0 * cross(s.c1, s.c3), c2 = 6.0 * cross(s.c2, s.c3);
    const double top = norm(c0 + m * (c1 + m * c2)) + norm(c1 + (2 * m) * c2) * h + norm(c2) * h * h;
    const double bound = top / (d.v_lo * d.v_lo * d.v_lo) * (1 + 1e-12);  // (rounding: a few ulps of each term)
    if (depth < 6) {
        auto at = [&](double u) {
            const vec<3> x1 = s.du(u, 1);
            const double v = norm(x1);
            return v > 0 ? norm(cross(x1, s.du(u, 2))) / (v * v * v) : std::numeric_limits<double>::infinity();
        };
        if (bound > 1.1 * std::max({at(ua), at(m), at(ub)})) return std::min(bound, split());
    }
    return bound;
}

/// Where the tangent of segment s crosses the cone within 5 degrees of the
/// unit vector up: the roots in (0, 1) of |up x x'|^2 - sin^2(5 deg) |x'|^2
/// (a quartic in u), found by sign changes on 64 steps and bisection;
/// appended to `out`. A root where the tangent only grazes the cone between
/// two samples can be missed: the bound then treats that stretch as it finds
/// it (its own rates, or unproved).
inline void cone_crossings(const cubic_segment<3, double>& s, const vec<3>& up, std::vector<double>& out) {
    const double s2 = up_clear_sin * up_clear_sin;
    auto f = [&](double u) {
        const vec<3> d = s.du(u, 1);
        return dot(cross(up, d), cross(up, d)) - s2 * dot(d, d);
    };
    constexpr int steps = 64;
    double a = 0, fa = f(0);
    for (int j = 1; j <= steps; ++j) {
        const double b = double(j) / steps, fb = f(b);
        if ((fa < 0) != (fb < 0)) {
            double lo = a, hi = b;
            const bool lo_neg = fa < 0;
            for (int it = 0; it < 60 && hi - lo > 0; ++it) {
                const double mid = (lo + hi) / 2;
                if (mid <= lo || mid >= hi) break;
                ((f(mid) < 0) == lo_neg ? lo : hi) = mid;
            }
            const double root = (lo + hi) / 2;
            if (root > 0 && root < 1) out.push_back(root);
        }
        a = b, fa = fb;
    }
}

/// The along-curve bound of the piece [ua, ub] of segment s (see above);
/// +infinity when the speed bound is not positive.
inline double along_bound(const cubic_segment<3, double>& s, double ua, double ub, const piece_rates& q) {
    const piece_derivatives d(s, ua, ub);
    const double w = d.w, k2 = d.k2, k3 = d.k3, v_lo = d.v_lo, v_hi = d.v_hi;
    if (!(v_lo > 0)) return std::numeric_limits<double>::infinity();
    // The up frame's turn: the blend's inside the cones, the projection's
    // outside (not bounded where the tangent may reach up: cut further).
    double up1 = 0, up2 = 0;
    if (q.has_up && q.in_zone) {
        up1 = q.zone_t1 * q.dt_du, up2 = q.zone_t2 * q.dt_du * q.dt_du;
    } else if (q.has_up) {
        const auto r = up_rates(d, q.up);
        if (r[0] < 0) return std::numeric_limits<double>::infinity();
        up1 = r[0], up2 = r[1];
    }
    // Roll, spread holonomy, up and scale per unit u.
    const double p1 = (q.roll_in_s ? q.roll_w1 * v_hi : q.roll_w1 * q.dt_du) + q.twist_t * q.dt_du + up1;
    const double roll2 = (q.roll_in_s ? q.roll_w2 * v_hi * v_hi + q.roll_w1 * k2 : q.roll_w2 * q.dt_du * q.dt_du) + up2;
    const double r = q.scale, r1 = q.scale_s1 * v_hi, r2 = q.scale_s2 * v_hi * v_hi + q.scale_s1 * k2;
    // The frame's angular velocity and its derivative.
    const double turn = k2 / v_lo;
    const double omega = turn + p1;
    const double omega1 = k3 / v_lo + 2 * turn * turn + roll2 + p1 * turn;
    const double rf1 = r1 + r * omega;
    const double rf2 = r2 + 2 * r1 * omega + r * (omega * omega + omega1);
    return w * w / 8 * (k2 + q.rho * rf2) + w * q.edge / 4 * rf1;
}

/// Cuts [u0, u1] of segment s into the fewest equal pieces (searched
/// upwards from one) that along_bound proves within `tol`; appends the
/// inner cut points' u to `out` and raises `largest` to the pieces' largest
/// bound. Returns false when the budget of pieces ran out first (a cusp):
/// the pieces are then as many as the budget.
inline bool cut_interval(const cubic_segment<3, double>& s, double u0, double u1, const piece_rates& q, double tol,
                         std::size_t budget, std::vector<double>& out, double& largest) {
    std::size_t n = 1;
    bool met = false;
    while (true) {
        double worst = 0;
        const double w = (u1 - u0) / double(n);
        for (std::size_t k = 0; k < n && worst <= tol; ++k) {
            const double a = u0 + w * double(k), b = k + 1 == n ? u1 : u0 + w * double(k + 1);
            worst = std::max(worst, along_bound(s, a, b, q));
        }
        if (worst <= tol) {
            met = true;
            largest = std::max(largest, worst);
            break;
        }
        if (n >= budget) break;
        // The bound falls like the width squared (or the width, for the
        // twist term): grow n by the square root of the excess, at least by
        // one, at most eightfold (where a lower bound in it, such as the up
        // frame's angle to up, is poor on wide pieces, it falls faster).
        const double grow = std::isfinite(worst) ? std::min(std::sqrt(worst / tol) * 1.02, 8.0) : 2.0;
        n = std::min(budget, std::max(n + 1, std::size_t(std::ceil(double(n) * grow))));
    }
    const double w = (u1 - u0) / double(n);
    for (std::size_t k = 1; k < n; ++k) out.push_back(u0 + w * double(k));
    return met;
}

}  // namespace crspline::detail
