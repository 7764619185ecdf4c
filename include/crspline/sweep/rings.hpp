// crspline sweeps, internals: the frame at each ring and the mesh written
// from the rings and the profile.
//
// The frame: rotation-minimizing (double reflection, frames.hpp; its drift
// from the exact frame bounded by drift.hpp), turned
// about the tangent by psi = the spread holonomy + the roll; with an up
// vector, by the angle that takes the rotation-minimizing normal to the up
// vector's projection (or its opposite, whichever continues the previous
// ring's: the frame never flips), except in the cones within 5 degrees of
// up (the poles, where the projection turns fast and vanishes): a run of
// ring steps whose middle tangent lies in a cone is a zone, and across it
// the frame is the rotation-minimizing one carried from the ring before
// it, turned by Delta sigma(x), x = (t - t_in) / (t_out - t_in), sigma(x) =
// 3 x^2 - 2 x^3, onto the projection (or its opposite, the nearer) at the
// ring after it: no flip, no jump, and rates sweep/sampling.hpp bounds. (An
// open curve that ends in a cone carries the frame to its end; a closed
// one turns it onto its first ring's.) The adaptive sweep puts rings where
// the tangent crosses a cone, so a zone is the cone's own stretch.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include "../frames.hpp"
#include "../segment.hpp"
#include "../vec.hpp"
#include "drift.hpp"
#include "keys.hpp"
#include "profile.hpp"
#include "sampling.hpp"

namespace crspline::detail {

using v3 = vec<3, double>;

/// Where a ring is on the curve: segment, local u, t, arc length.
struct ring_site {
    std::size_t segment = 0;
    double u = 0, t = 0, s = 0;
};

/// The frame and rates at each ring.
struct ring_frames {
    std::vector<v3> x, dx, normal, binormal, tangent, omega;  ///< omega: the frame's angular velocity per unit t
    std::vector<double> scale, scale_t;                        ///< r and dr/dt
    double holonomy = 0;
    /// At each ring, a bound on the angle between its normal and the exact
    /// frame's: the rotation-minimizing one (with the exact holonomy spread,
    /// closed), and each step's share (drift.hpp); with an up vector, 0 but
    /// in the zones (outside them the frame is the up vector's projection),
    /// and empty where no zone needs it.
    std::vector<double> drift, step_drift;
    double end_drift = 0;  ///< the carried frame's drift at the last ring (before any spread)
    /// Up mode: the zones (runs of steps in a cone around up), each step's
    /// zone (-1: none; step k joins rings k - 1 and k).
    struct zone {
        std::size_t k_in = 0, k_out = 0;
        double t_in = 0, t_out = 0;
        double delta = 0;  ///< a bound on |Delta| of the exact frame: the measured one plus the zone's drift
        double rate_t1() const { return t_out > t_in ? 1.5 * delta / (t_out - t_in) : 0.0; }
        double rate_t2() const { return t_out > t_in ? 6 * delta / ((t_out - t_in) * (t_out - t_in)) : 0.0; }
    };
    std::vector<zone> zones;
    std::vector<int> step_zone;
};

inline double angle_about(const v3& from, const v3& to, const v3& axis) {
    return std::atan2(dot(cross(from, to), axis), dot(from, to));
}

struct ring_inputs {
    const catmull_rom<3>* curve = nullptr;
    const piecewise_cubic* roll = nullptr;
    bool roll_in_s = false;
    double roll_turn = 0;  ///< whole turns the roll makes per period (closed, in s)
    const piecewise_cubic* scale = nullptr;
    std::optional<v3> up;
    bool spread_holonomy = true;
    bool drift = true;  ///< bound the frames' drift (drift.hpp); false for a pass that only measures the holonomy
};

/// The carried normals' drift from the exact rotation-minimizing frame
/// (drift.hpp), ring by ring: each step's double reflection measured
/// against the minimal rotations chained through the knots it crosses, less
/// the enclosed exact turn.
inline void carried_drift(const catmull_rom<3>& c, const std::vector<ring_site>& sites, ring_frames& f) {
    const std::size_t n = sites.size();
    f.drift.assign(n, 0.0);
    f.step_drift.assign(n, 0.0);
    double d = 0;
    for (std::size_t k = 1; k < n; ++k) {
        std::optional<v3> m = f.normal[k - 1];
        v3 cur = f.tangent[k - 1];
        double lo = 0, hi = 0;
        for (std::size_t i = sites[k - 1].segment; i <= sites[k].segment && m; ++i) {
            const auto& s = c.segment(i);
            if (constant_segment(s)) continue;
            const double ua = i == sites[k - 1].segment ? sites[k - 1].u : 0.0, ub = i == sites[k].segment ? sites[k].u : 1.0;
            if (!(ub > ua)) continue;
            // A piece too coarse to enclose is halved (up to 2^6 parts),
            // the minimal rotations chained through the parts' tangents.
            auto add = [&](auto&& self, double a, double b, int depth) -> void {
                const auto e = enclose_rmf_turn(s, a, b);
                if (!e && depth < 6) {
                    self(self, a, (a + b) / 2, depth + 1);
                    if (m) self(self, (a + b) / 2, b, depth + 1);
                    return;
                }
                if (!e) {
                    m.reset();
                    return;
                }
                m = minimal_rotation(cur, e->ta, *m);  // across a knot or a halving: rounding only
                if (m) m = minimal_rotation(e->ta, e->tb, *m);
                cur = e->tb, lo += e->lo, hi += e->hi;
            };
            add(add, ua, ub, 0);
        }
        if (m) m = minimal_rotation(cur, f.tangent[k], *m);
        double step = std::numeric_limits<double>::infinity();
        if (m) {
            const double alpha = angle_about(*m, f.normal[k], f.tangent[k]);
            step = std::abs(alpha - (lo + hi) / 2) + (hi - lo) / 2 + drift_slack;
        }
        d += step;
        f.step_drift[k] = step, f.drift[k] = d;
    }
    f.end_drift = n > 0 ? f.drift[n - 1] : 0.0;
}

inline ring_frames compute_rings(const std::vector<ring_site>& sites, const ring_inputs& in) {
    const catmull_rom<3>& c = *in.curve;
    const std::size_t n = sites.size();
    ring_frames f;
    f.x.resize(n), f.dx.resize(n), f.normal.resize(n), f.binormal.resize(n), f.tangent.resize(n), f.omega.resize(n);
    f.scale.assign(n, 1.0), f.scale_t.assign(n, 0.0);
    const auto grid = c.grid();
    std::vector<v3> d2(n);
    // 1. Positions, derivatives in t and tangents (carried over zero-speed
    //    points; points before the first tangent take that one).
    std::vector<std::optional<v3>> e(n);
    for (std::size_t k = 0; k < n; ++k) {
        const auto& s = c.segment(sites[k].segment);
        const double dt = grid[sites[k].segment + 1] - grid[sites[k].segment];
        const double inv = dt > 0 ? 1 / dt : 0;
        const double u = sites[k].u;
        f.x[k] = s.at(u);
        f.dx[k] = s.du(u, 1) * inv;
        d2[k] = s.du(u, 2) * (inv * inv);
        e[k] = unit_tangent(std::array<v3, 3>{s.du(u, 1), s.du(u, 2), s.du(u, 3)});
    }
    v3 carried{{1, 0, 0}};
    for (const auto& x : e)
        if (x) {
            carried = *x;
            break;
        }
    for (std::size_t k = 0; k < n; ++k) {
        if (e[k]) carried = *e[k];
        f.tangent[k] = carried;
    }
    if (n == 0) return f;
    // 2. Rotation-minimizing normals, from the Frenet normal at the start.
    {
        const double t0 = sites[0].t;
        const auto fr = frenet_frames(c, std::span<const double>(&t0, 1));
        f.normal[0] = perpendicular(fr[0].normal, f.tangent[0]).value_or(any_perpendicular(f.tangent[0]));
        if (in.up) {  // the up vector's projection, where it has one
            if (auto p = perpendicular(*in.up, f.tangent[0])) f.normal[0] = *p;
        }
    }
    for (std::size_t k = 1; k < n; ++k)
        f.normal[k] = double_reflection(f.x[k - 1], f.tangent[k - 1], f.normal[k - 1], f.x[k], f.tangent[k]);
    if (in.up) {  // the zones: runs of steps whose middle tangent is within 5 degrees of up
        const v3 up = *in.up / norm(*in.up);
        f.step_zone.assign(n, -1);
        for (std::size_t k = 1; k < n; ++k) {
            const v3 d = c.evaluate((sites[k - 1].t + sites[k].t) / 2, 1);
            const double sp = norm(d);
            if (!(sp > 0) || !(norm(cross(d, up)) < up_clear_sin * sp)) continue;
            if (f.zones.empty() || f.zones.back().k_out != k - 1) f.zones.push_back({k - 1, k});
            f.zones.back().k_out = k;
            f.step_zone[k] = int(f.zones.size() - 1);
        }
    }
    // (With an up vector the drift matters in the zones only.)
    if (in.drift && (!in.up || !f.zones.empty())) carried_drift(c, sites, f);
    // 3. The turn about the tangent at each ring.
    std::vector<double> psi(n, 0.0), psi_t(n, 0.0);
    const double period = c.t_max() - c.t_min();
    if (in.up) {
        const v3 up = *in.up / norm(*in.up);
        // The projection's angle from the carried normal at ring k, where it has one.
        auto projection = [&](std::size_t k) -> std::optional<double> {
            const double sin_up = norm(cross(f.tangent[k], up));
            if (!(sin_up > 0)) return std::nullopt;
            const v3 p = (up - dot(up, f.tangent[k]) * f.tangent[k]) / sin_up;
            return angle_about(f.normal[k], p, f.tangent[k]);
        };
        // The projection or its opposite: the one nearer `to`.
        auto nearest = [](double a, double to) { return a + std::numbers::pi * std::round((to - a) / std::numbers::pi); };
        // Ring 0's normal is the projection already (where it has one).
        const std::vector<double> cumulative = f.drift;
        if (!f.drift.empty()) f.drift.assign(n, 0.0);
        std::size_t z = 0;
        for (std::size_t k = 1; k < n; ++k) {
            if (z < f.zones.size() && k > f.zones[z].k_in) {
                auto& zn = f.zones[z];
                const std::size_t ki = zn.k_in, ko = zn.k_out;
                zn.t_in = sites[ki].t, zn.t_out = sites[ko].t;
                // Onto the projection where the zone ends; a closed curve's last
                // zone onto its first ring's normal; an open curve ending in
                // the cone: the frame carried on (Delta 0).
                double delta = 0;
                if (ko == n - 1 && c.closed()) {
                    delta = nearest(angle_about(f.normal[n - 1], f.normal[0], f.tangent[n - 1]), psi[ki]) - psi[ki];
                } else if (ko < n - 1) {
                    if (const auto a = projection(ko)) delta = nearest(*a, psi[ki]) - psi[ki];
                }
                const double zone_drift = cumulative.empty() ? std::numeric_limits<double>::infinity() : cumulative[ko] - cumulative[ki];
                zn.delta = std::abs(delta) + zone_drift;
                for (std::size_t j = ki + 1; j <= ko; ++j) {
                    const double x = zn.t_out > zn.t_in ? (sites[j].t - zn.t_in) / (zn.t_out - zn.t_in) : 1.0;
                    const double sigma = x * x * (3 - 2 * x);
                    psi[j] = psi[ki] + delta * sigma;
                    // The exact frame: carried from the entry (its drift) and turned by its own Delta.
                    if (!f.drift.empty()) f.drift[j] = cumulative[j] - cumulative[ki] + sigma * zone_drift;
                }
                k = ko, ++z;
                continue;
            }
            const auto a = projection(k);
            psi[k] = a ? nearest(*a, psi[k - 1]) : psi[k - 1];
        }
        for (std::size_t k = 0; k < n; ++k) {  // rate by differences (for the normals only)
            const std::size_t a = k > 0 ? k - 1 : k, b = k + 1 < n ? k + 1 : k;
            const double dt = sites[b].t - sites[a].t;
            psi_t[k] = dt > 0 ? (psi[b] - psi[a]) / dt : 0.0;
        }
    } else if (c.closed() && n >= 2 && period > 0) {
        // The last ring is the first point again: the carried normal's turn
        // from the first normal, spread evenly in t.
        f.holonomy = angle_about(f.normal[n - 1], f.normal[0], f.tangent[0]);
        for (std::size_t k = 0; k < n && in.spread_holonomy; ++k) {
            const double frac = (sites[k].t - sites[0].t) / period;
            psi[k] = f.holonomy * frac;
            psi_t[k] = f.holonomy / period;
            if (!f.drift.empty()) f.drift[k] += f.end_drift * frac;  // the measured holonomy is off by the carried frame's drift
        }
    }
    if (in.roll && !in.roll->empty()) {
        for (std::size_t k = 0; k < n; ++k) {
            const double w = in.roll_in_s ? sites[k].s : sites[k].t;
            psi[k] += in.roll->value(w, in.roll_turn);
            psi_t[k] += in.roll->slope(w) * (in.roll_in_s ? norm(f.dx[k]) : 1.0);
        }
    }
    // 4. Turned normals, binormals, angular velocities and scales.
    for (std::size_t k = 0; k < n; ++k) {
        const v3& ek = f.tangent[k];
        if (psi[k] != 0) {
            const v3 r = rotate_about(f.normal[k], ek, psi[k]);
            f.normal[k] = perpendicular(r, ek).value_or(r);
        }
        f.binormal[k] = cross(ek, f.normal[k]);
        const double sp2 = dot(f.dx[k], f.dx[k]);
        f.omega[k] = (sp2 > 0 ? cross(f.dx[k], d2[k]) / sp2 : v3{}) + psi_t[k] * ek;
        if (in.scale && !in.scale->empty()) {
            f.scale[k] = in.scale->value(sites[k].s);
            f.scale_t[k] = in.scale->slope(sites[k].s) * norm(f.dx[k]);
        }
    }
    return f;
}

/// Vertex buffers and triangles: ring k, profile vertex j at k * m + j.
/// Triangles wind counterclockwise seen from where the normals point (for a
/// profile counterclockwise in the (normal, binormal) plane, outwards).
inline void write_mesh(const ring_frames& f, const std::vector<ring_site>& sites, const profile_polyline& prof,
                       double length, bool closed, bool seamless, std::vector<double>& positions, std::vector<double>& normals,
                       std::vector<double>& uvs, std::vector<std::uint32_t>& indices, double& seam_gap,
                       double& seam_normal_gap) {
    const std::size_t n = f.x.size(), m = prof.points.size();
    positions.resize(3 * n * m);
    normals.resize(3 * n * m);
    uvs.resize(2 * n * m);
    for (std::size_t k = 0; k < n; ++k) {
        const v3 &x = f.x[k], &nn = f.normal[k], &bb = f.binormal[k], &w = f.omega[k], &e = f.tangent[k];
        const double r = f.scale[k], r1 = f.scale_t[k];
        const double v = length > 0 ? sites[k].s / length : 0.0;
        // The normal S_phi x S_t, S_phi = r F d, S_t = x' + r' F p + r omega x F p,
        // is bilinear in the profile's point p and direction d: six cross
        // products a ring, then a sum a vertex.
        const v3 a = f.dx[k], u = r1 * nn + r * cross(w, nn), b2 = r1 * bb + r * cross(w, bb);
        const v3 na = cross(nn, a), nu = cross(nn, u), nv2 = cross(nn, b2);
        const v3 ba = cross(bb, a), bu = cross(bb, u), bv = cross(bb, b2);
        const v3 ne = cross(nn, e), be = cross(bb, e);
        double* pos = positions.data() + 3 * k * m;
        double* nor = normals.data() + 3 * k * m;
        double* uv = uvs.data() + 2 * k * m;
        for (std::size_t j = 0; j < m; ++j) {
            const double p0 = prof.points[j][0], p1 = prof.points[j][1];
            const double d0 = prof.directions[j][0], d1 = prof.directions[j][1];
            double h[3], o[3], l2 = 0, side = 0;
            for (int i = 0; i < 3; ++i) {
                pos[3 * j + i] = x[i] + r * (p0 * nn[i] + p1 * bb[i]);
                h[i] = d0 * (na[i] + p0 * nu[i] + p1 * nv2[i]) + d1 * (ba[i] + p0 * bu[i] + p1 * bv[i]);
                o[i] = d0 * ne[i] + d1 * be[i];
                l2 += h[i] * h[i];
                side += h[i] * o[i];
            }
            // Where the tube folds (radius past the radius of curvature) S_t
            // turns back; the normal keeps the side the profile faces. A
            // vanishing normal (a cusp) takes the profile's own.
            double scale_n = side < 0 ? -1.0 : 1.0;
            if (!(l2 > 0) || !std::isfinite(l2)) {
                l2 = o[0] * o[0] + o[1] * o[1] + o[2] * o[2];
                for (int i = 0; i < 3; ++i) h[i] = o[i];
                scale_n = 1;
            }
            scale_n /= l2 > 0 ? std::sqrt(l2) : 1.0;
            for (int i = 0; i < 3; ++i) nor[3 * j + i] = scale_n * h[i];
            uv[2 * j] = prof.u[j];
            uv[2 * j + 1] = v;
        }
    }
    // A closed sweep's last ring is its first: the same positions and normals.
    seam_gap = seam_normal_gap = 0;
    if (closed && n >= 2) {
        // (How far the computed closing ring was from the first: rounding
        // when the holonomy is spread; the report says.)
        for (std::size_t i = 0; i < 3 * m; ++i) {
            seam_gap = std::max(seam_gap, std::abs(positions[3 * (n - 1) * m + i] - positions[i]));
            seam_normal_gap = std::max(seam_normal_gap, std::abs(normals[3 * (n - 1) * m + i] - normals[i]));
        }
    }
    if (seamless && n >= 2) {
        std::copy_n(positions.begin(), 3 * m, positions.begin() + 3 * (n - 1) * m);
        std::copy_n(normals.begin(), 3 * m, normals.begin() + 3 * (n - 1) * m);
    }
    indices.resize(n > 0 && m > 0 ? 6 * (n - 1) * (m - 1) : 0);
    std::uint32_t* out = indices.data();
    for (std::size_t k = 0; k + 1 < n; ++k)
        for (std::size_t j = 0; j + 1 < m; ++j) {
            const auto a = std::uint32_t(k * m + j), b = a + 1;
            const auto c = std::uint32_t((k + 1) * m + j), d = c + 1;
            out[0] = a, out[1] = b, out[2] = c, out[3] = b, out[4] = d, out[5] = c;
            out += 6;
        }
}

}  // namespace crspline::detail
