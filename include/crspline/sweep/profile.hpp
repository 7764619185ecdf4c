// crspline sweeps, internals: the cross-section as the mesh uses it, a
// polyline in the profile plane with its chord bound.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>
#include <vector>

#include "../catmull_rom.hpp"
#include "../detail/format.hpp"
#include "../error.hpp"
#include "../tessellate.hpp"
#include "../vec.hpp"

namespace crspline::detail {

/// The profile's vertices (a closed one repeats its first vertex at the
/// end, for the texture's seam column), the unit direction of the profile
/// at each (for the normals), the texture coordinate u of each (profile
/// length so far over the whole), and what the bound needs.
struct profile_polyline {
    std::vector<vec<2>> points, directions;
    std::vector<double> u;
    bool closed = true;
    double rho = 0;    ///< largest |p|
    double edge = 0;   ///< longest edge
    double chord = 0;  ///< distance of the polygon to the true profile, both ways
};

inline void finish_profile(profile_polyline& p) {
    const std::size_t m = p.points.size();
    p.u.assign(m, 0.0);
    double len = 0;
    for (std::size_t j = 1; j < m; ++j) {
        const double e = norm(p.points[j] - p.points[j - 1]);
        p.edge = std::max(p.edge, e);
        len += e;
        p.u[j] = len;
    }
    for (auto& x : p.u) x = len > 0 ? x / len : 0.0;
    if (p.closed && m > 0) p.u.back() = 1.0;
    for (const auto& x : p.points) p.rho = std::max(p.rho, norm(x));
}

/// A circle of radius r in n pieces, starting along the normal (angle 0)
/// and turning towards the binormal; its polygon is inscribed, within
/// r (1 - cos(pi / n)) of the circle.
inline profile_polyline circle_profile(double r, std::size_t n) {
    profile_polyline p;
    p.points.resize(n + 1);
    p.directions.resize(n + 1);
    for (std::size_t j = 0; j <= n; ++j) {
        const double a = 2 * std::numbers::pi * double(j % n) / double(n);
        p.points[j] = {{r * std::cos(a), r * std::sin(a)}};
        p.directions[j] = {{-std::sin(a), std::cos(a)}};
    }
    p.closed = true;
    finish_profile(p);
    p.chord = r * (1 - std::cos(std::numbers::pi / double(n)));
    return p;
}

/// The fewest pieces of a circle of radius r whose polygon is within tol.
inline std::size_t circle_pieces(double r, double tol) {
    if (!(tol < r)) return 3;
    const double n = std::ceil(std::numbers::pi / std::acos(1 - tol / r));
    return std::size_t(std::clamp(n, 3.0, 1e7));
}

/// A polyline or polygon profile: its own polygon (chord 0). Each vertex's
/// direction is the mean of its edges' (smooth shading across corners).
inline profile_polyline polyline_profile(const std::vector<vec<2>>& pts, bool closed) {
    profile_polyline p;
    p.points = pts;
    if (closed) p.points.push_back(pts.front());
    const std::size_t m = p.points.size();
    p.directions.resize(m);
    auto edge_dir = [&](std::size_t j) {  // direction of edge j -> j + 1
        const vec<2> d = p.points[j + 1] - p.points[j];
        const double l = norm(d);
        return l > 0 ? d / l : vec<2>{};
    };
    for (std::size_t j = 0; j < m; ++j) {
        vec<2> d{};
        if (j + 1 < m) d += edge_dir(j);
        if (j > 0) d += edge_dir(j - 1);
        if (closed && (j == 0 || j + 1 == m)) d = edge_dir(0) + edge_dir(m - 2);
        const double l = norm(d);
        p.directions[j] = l > 0 ? d / l : vec<2>{{1, 0}};
    }
    p.closed = closed;
    finish_profile(p);
    return p;
}

/// A Catmull-Rom profile tessellated within tol (tessellate.hpp's proof),
/// or in n equal steps of t when n > 0 (then its chord is the largest
/// flatness bound of the steps).
inline profile_polyline curve_profile(const catmull_rom<2>& c, double tol, std::size_t n) {
    profile_polyline p;
    std::vector<double> t;
    if (n > 0) {
        for (std::size_t j = 0; j <= n; ++j)
            t.push_back(j == n ? c.t_max() : c.t_min() + (c.t_max() - c.t_min()) * double(j) / double(n));
    } else {
        t = tessellate(c, tol).t;
    }
    for (std::size_t j = 0; j < t.size(); ++j) {
        p.points.push_back(c.evaluate(t[j]));
        vec<2> d = c.evaluate(t[j], 1);
        if (!(norm(d) > 0)) d = c.evaluate(t[j], 2);
        const double l = norm(d);
        p.directions.push_back(l > 0 ? d / l : vec<2>{{1, 0}});
        if (n > 0 && j > 0) {
            const std::size_t i = c.locate(t[j - 1]);
            const auto& s = c.segment(i);
            const double ua = s.local(t[j - 1]), ub = std::min(1.0, s.local(t[j]));
            p.chord = std::max(p.chord, flatness_bound(s, ua, ub));
        }
    }
    if (c.closed()) p.points.back() = p.points.front(), p.directions.back() = p.directions.front();
    p.closed = c.closed();
    finish_profile(p);
    if (n == 0) p.chord = tol;
    return p;
}

inline void check_profile_points(const std::vector<vec<2>>& pts) {
    if (pts.size() < 2)
        throw spec_error("profile", std::nullopt, std::nullopt, std::to_string(pts.size()),
                         "profile: needs at least 2 points, got " + std::to_string(pts.size()));
    for (std::size_t k = 0; k < pts.size(); ++k)
        for (std::size_t i = 0; i < 2; ++i)
            if (!std::isfinite(pts[k][i]))
                throw spec_error("profile", k, i, num(pts[k][i]),
                                 "profile[" + std::to_string(k) + "][" + std::to_string(i) + "]: coordinate " +
                                     num(pts[k][i]) + " is not finite");
}

}  // namespace crspline::detail
