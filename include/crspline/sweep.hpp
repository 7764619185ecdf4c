// crspline: sweeps. A cross-section carried along a 3-D curve by a frame,
// as a triangle mesh within a proved distance of the swept surface.
//
//   auto mesh = crspline::sweep(curve, {.profile = crspline::sweep_profile::circle(0.1)});
//   // mesh.positions, mesh.normals (3 per vertex), mesh.uvs (2), mesh.indices (3 per triangle)
//
// The frame is rotation-minimizing (no twist that the curve does not
// force); on a closed curve the twist it gathers once around (the
// holonomy) is spread evenly in t, so the last ring meets the first: the
// surface closes with no seam (the closing ring's positions and normals are
// the first ring's, bit for bit; texture u is the same, v runs 0 to 1).
// Optional: roll keys (angles about the tangent at the knots or at arc
// lengths, interpolated by the rotation splines), an up vector (the normal
// follows the up vector's projection and never flips: see
// sweep/rings.hpp for the poles), and a scale along arc length (keys,
// a Catmull-Rom interpolant in s). How the tolerance is proved:
// sweep/sampling.hpp, and sweep/drift.hpp for the rings' frames against the
// exact rotation-minimizing frame. Everything is in double; the result is plain arrays
// (what WASM and NumPy take as they are).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "arc_length.hpp"
#include "bounds.hpp"
#include "catmull_rom.hpp"
#include "decision.hpp"
#include "detail/format.hpp"
#include "error.hpp"
#include "sweep/keys.hpp"
#include "sweep/profile.hpp"
#include "sweep/rings.hpp"
#include "sweep/sampling.hpp"
#include "vec.hpp"

namespace crspline {

/// The default sweep tolerance, relative to the curve's bounding-box
/// diagonal plus twice the largest radius.
inline constexpr double default_sweep_tolerance = 1e-3;

/// The share of the along-curve tolerance that placing the rings keeps for
/// the frames' drift from the exact rotation-minimizing frame.
inline constexpr double sweep_drift_share = 0.01;

/// The cross-section, in the plane of the frame's normal (first
/// coordinate) and binormal (second).
struct sweep_profile {
    enum class kind { circle, polyline, curve };
    kind type = kind::circle;
    double radius = 1;            ///< circle
    std::vector<vec<2>> points{}; ///< polyline vertices or curve control points
    bool closed = true;           ///< polyline: a closed polygon; curve: a closed curve
    double alpha = 0.5;           ///< curve: knot exponent

    static sweep_profile circle(double r) { return {kind::circle, r, {}, true, 0.5}; }
    static sweep_profile polyline(std::vector<vec<2>> p, bool closed = false) {
        return {kind::polyline, 1, std::move(p), closed, 0.5};
    }
    static sweep_profile curve(std::vector<vec<2>> p, bool closed = true, double alpha = 0.5) {
        return {kind::curve, 1, std::move(p), closed, alpha};
    }
};

/// Where roll keys sit: one angle per knot (a closed curve's knots without
/// the repeated last), or at given arc lengths.
enum class roll_position { knots, arc_length };

struct sweep_options {
    sweep_profile profile = sweep_profile::circle(1);
    std::vector<double> roll{};            ///< angles (radians) about the tangent, empty: none
    roll_position roll_at = roll_position::knots;
    std::vector<double> roll_s{};          ///< arc lengths of the roll keys (roll_at == arc_length)
    std::vector<double> scale{};           ///< scale of the profile at the arc lengths scale_s; empty: 1
    std::vector<double> scale_s{};
    std::optional<vec<3>> up{};            ///< the normal follows this vector's projection
    double tolerance = 0;                  ///< distance; 0: default_sweep_tolerance x (diagonal + 2 radius)
    std::size_t tubular_segments = 0;      ///< > 0: this many pieces along, equal in arc length
    std::size_t radial_segments = 0;       ///< > 0: a circle or curve profile in this many pieces
    bool clearance = true;                 ///< measure the centre line's clearance for the report
    bool spread_holonomy = true;           ///< false: a closed curve's frame is not closed up (a seam; for comparison)
};

/// What the sweep found.
struct sweep_report {
    double tolerance = 0;            ///< the tolerance asked for (adaptive) or 0 (given counts)
    double bound = 0;                ///< the mesh's distance bound to the surface (+inf: not proved)
    bool tolerance_met = true;       ///< bound <= tolerance (adaptive)
    bool proved = true;              ///< false with an up vector where rings outside the cones around it are too far apart (given counts) for the frame's turn between them to be bounded below a radian
    double holonomy = 0;             ///< the rotation-minimizing frame's twist after one loop (closed, no up), radians
    double frame_drift = 0;          ///< a bound on the ring frames' angle from the exact frame (rotation-minimizing; with up, 0 but in the cones around it), radians; `bound` includes it times the radius
    double length = 0;               ///< the curve's arc length (v = s / length)
    double largest_radius = 0;       ///< largest scale x |profile point|
    double clearance = std::numeric_limits<double>::infinity();  ///< centre line, non-adjacent segments
    double min_radius_of_curvature = std::numeric_limits<double>::infinity();  ///< a lower bound over the whole curve (between the rings too)
    bool far_contact = false;        ///< clearance < 2 largest_radius: distant parts of the tube may meet
    bool local_fold = false;         ///< somewhere the radius may reach the radius of curvature (by the bounds: false proves it does not)
    bool self_intersects = false;    ///< far_contact or local_fold
    double seam_gap = 0;             ///< closed: largest coordinate difference of the computed closing ring from the first
    double seam_normal_gap = 0;      ///< the same for the normals (the closing ring is then set to the first exactly)
};

struct sweep_mesh {
    std::vector<double> positions, normals, uvs;  ///< 3, 3 and 2 per vertex; vertex k * ring_size + j
    std::vector<std::uint32_t> indices;           ///< 3 per triangle
    std::size_t rings = 0, ring_size = 0;
    std::vector<double> t, s;                     ///< the curve parameter and arc length of each ring
    sweep_report report;
};

namespace detail {

inline void sweep_error(const char* field, std::optional<std::size_t> index, double value, const std::string& what) {
    throw spec_error(field, index, std::nullopt, num(value), std::string(field) + ": " + what);
}

inline void check_sweep_options(const catmull_rom<3>& c, const sweep_options& o) {
    const auto& p = o.profile;
    if (p.type == sweep_profile::kind::circle) {
        if (!(p.radius > 0) || !std::isfinite(p.radius))
            sweep_error("radius", std::nullopt, p.radius, "must be positive and finite, got " + num(p.radius));
    } else {
        check_profile_points(p.points);
    }
    if (!(o.tolerance >= 0) || !std::isfinite(o.tolerance))
        sweep_error("tolerance", std::nullopt, o.tolerance, "must be positive and finite (0: the default), got " +
                                                                num(o.tolerance));
    if (o.up) {
        for (std::size_t i = 0; i < 3; ++i)
            if (!std::isfinite((*o.up)[i])) sweep_error("up", i, (*o.up)[i], "coordinate is not finite");
        if (!(norm(*o.up) > 0)) sweep_error("up", std::nullopt, 0, "must not be the zero vector");
    }
    if (!o.roll.empty() && o.roll_at == roll_position::knots) {
        const std::size_t knots = c.points().size();
        if (o.roll.size() != knots)
            throw spec_error("roll", std::nullopt, std::nullopt, std::to_string(o.roll.size()),
                             "roll: " + std::to_string(o.roll.size()) + " angles for " + std::to_string(knots) +
                                 " knots (one per curve point)");
    }
}

}  // namespace detail

/// The sweep of opt.profile along the curve (see the top of this file).
/// Throws spec_error naming the field ("radius", "profile", "roll",
/// "scale", "up", "tolerance") for bad options.
inline sweep_mesh sweep(const catmull_rom<3>& curve, const sweep_options& opt = {}) {
    using namespace detail;
    check_sweep_options(curve, opt);
    sweep_mesh out;
    const arc_length_table<3> table(curve);
    const double length = table.total();
    const bool closed = curve.closed();
    const double period = curve.t_max() - curve.t_min();
    // 1. Roll and scale functions.
    piecewise_cubic roll, scale;
    const bool roll_in_s = opt.roll_at == roll_position::arc_length;
    double roll_turn = 0;
    if (!opt.roll.empty()) {
        if (roll_in_s) {
            roll = roll_function(opt.roll_s, opt.roll, closed ? std::optional<double>(length) : std::nullopt);
        } else {
            std::vector<double> w(curve.grid().begin(), curve.grid().begin() + std::ptrdiff_t(opt.roll.size()));
            roll = roll_function(w, opt.roll, closed ? std::optional<double>(period) : std::nullopt);
        }
        if (roll.periodic) roll_turn = roll.pieces.back().b[3] - roll.pieces.front().b[0];
    }
    if (!opt.scale.empty())
        scale = scale_function(opt.scale_s, opt.scale, closed ? std::optional<double>(length) : std::nullopt);
    double scale_max = 1;
    if (!scale.empty()) {
        scale_max = 0;
        for (const auto& p : scale.pieces) scale_max = std::max(scale_max, p.max_abs());
    }
    // 2. The tolerance and the profile's share of it.
    double rho0 = opt.profile.type == sweep_profile::kind::circle ? opt.profile.radius : 0.0;
    if (opt.profile.type != sweep_profile::kind::circle)
        for (const auto& q : opt.profile.points) rho0 = std::max(rho0, norm(q));
    const bool given_counts = opt.tubular_segments > 0 || opt.radial_segments > 0;
    const double tol = opt.tolerance > 0 ? opt.tolerance
                                         : default_sweep_tolerance *
                                               (double(bounding_box(curve).diagonal()) + 2 * rho0 * scale_max);
    profile_polyline prof;
    double around_share = opt.profile.type == sweep_profile::kind::polyline ? 0.0 : tol / 2;
    switch (opt.profile.type) {
        case sweep_profile::kind::circle:
            prof = circle_profile(opt.profile.radius,
                                  given_counts ? std::max<std::size_t>(opt.radial_segments ? opt.radial_segments : 8, 3)
                                               : circle_pieces(opt.profile.radius, around_share / scale_max));
            break;
        case sweep_profile::kind::polyline: prof = polyline_profile(opt.profile.points, opt.profile.closed); break;
        case sweep_profile::kind::curve: {
            std::optional<catmull_rom<2>> pc;
            try {
                options<2> po;
                po.alpha = opt.profile.alpha;
                po.closed = opt.profile.closed;
                pc.emplace(std::span<const vec<2>>(opt.profile.points), po);
            } catch (const std::exception& e) {
                throw spec_error("profile", std::nullopt, std::nullopt, "", std::string("profile: ") + e.what());
            }
            prof = curve_profile(*pc, around_share / scale_max, given_counts ? opt.radial_segments : 0);
            break;
        }
    }
    const double around = scale_max * prof.chord;
    const double along_tol = std::max(tol - around, tol * 1e-3);
    // 3. Breakpoints: roll and scale keys at arc lengths become rings.
    std::vector<double> key_t;
    auto add_key = [&](double s) {
        if (s > 0 && s < length) key_t.push_back(table.t_at(s));
    };
    if (roll_in_s)
        for (double s : opt.roll_s) add_key(closed ? std::fmod(std::fmod(s, length) + length, length) : s);
    for (double s : opt.scale_s) add_key(closed ? std::fmod(std::fmod(s, length) + length, length) : s);
    const auto grid = curve.grid();
    // Up mode: where the tangent crosses the cones within 5 degrees of up
    // (the zones, sweep/rings.hpp) become rings too, and each zone's extent
    // in t is kept for the placement's rates.
    std::vector<std::array<double, 2>> cone_zones;
    if (opt.up && !given_counts) {
        const vec<3> up = *opt.up / norm(*opt.up);
        std::vector<double> roots;
        bool inside = false, started = false;
        double t_in = curve.t_min();
        for (std::size_t i = 0; i < curve.segment_count(); ++i) {
            const auto& s = curve.segment(i);
            if (constant_segment(s)) continue;
            const double dt = grid[i + 1] - grid[i];
            if (!started) {
                const vec<3> d = s.du(0, 1);
                inside = norm(cross(up, d)) < up_clear_sin * norm(d), started = true;
            }
            roots.clear();
            cone_crossings(s, up, roots);
            for (double u : roots) {
                const double t = grid[i] + u * dt;
                key_t.push_back(t);
                if (inside) cone_zones.push_back({t_in, t});
                else t_in = t;
                inside = !inside;
            }
        }
        if (inside) cone_zones.push_back({t_in, curve.t_max()});
    }
    std::sort(key_t.begin(), key_t.end());
    // 4. The rates over an interval of a segment (for the bound); zone: the
    // blend's rates per unit t where the piece is in a zone (up mode).
    struct zone_rates {
        double t1 = 0, t2 = 0;
    };
    auto rates_for = [&](std::size_t i, double ua, double ub, double twist, std::optional<zone_rates> zone = std::nullopt) {
        piece_rates q;
        q.rho = prof.rho;
        q.edge = prof.edge;
        q.dt_du = grid[i + 1] - grid[i];
        const double ta = grid[i] + ua * q.dt_du, tb = ub == 1 ? grid[i + 1] : grid[i] + ub * q.dt_du;
        const bool in_s = !scale.empty() || (!roll.empty() && roll_in_s);
        const double sa = in_s ? table.s_at(ta) : 0.0, sb = in_s ? table.s_at(tb) : 0.0;
        if (!scale.empty()) {
            const auto b = scale.bounds(sa, sb);
            q.scale = b[0], q.scale_s1 = b[1], q.scale_s2 = b[2];
        }
        if (!roll.empty()) {
            const auto b = roll_in_s ? roll.bounds(sa, sb) : roll.bounds(ta, tb);
            q.roll_w1 = b[1], q.roll_w2 = b[2];
            q.roll_in_s = roll_in_s;
        }
        q.twist_t = twist;
        if (opt.up) q.has_up = true, q.up = *opt.up / norm(*opt.up);
        if (zone) q.in_zone = true, q.zone_t1 = zone->t1, q.zone_t2 = zone->t2;
        return q;
    };
    auto site = [&](std::size_t i, double u) {
        ring_site r;
        r.segment = i;
        r.u = u;
        r.t = u == 1 ? grid[i + 1] : grid[i] + u * (grid[i + 1] - grid[i]);
        r.s = table.s_at(r.t);
        return r;
    };
    auto constant = [&](std::size_t i) { return constant_segment(curve.segment(i)); };
    // Each piece between consecutive rings, split at knots: f(k, i, ua, ub)
    // on segment i between rings k - 1 and k (constant segments left out);
    // stops at the first false.
    auto every_piece = [&](const std::vector<ring_site>& rs, auto&& f) {
        for (std::size_t k = 1; k < rs.size(); ++k)
            for (std::size_t i = rs[k - 1].segment; i <= rs[k].segment; ++i) {
                if (constant(i)) continue;
                const double ua = i == rs[k - 1].segment ? rs[k - 1].u : 0.0, ub = i == rs[k].segment ? rs[k].u : 1.0;
                if (ub > ua && !f(k, i, ua, ub)) return false;
            }
        return true;
    };
    // Up mode: proved where every zone's drift is bounded and every piece
    // between rings outside the zones keeps its tangent off up and turns
    // the frame less than a radian (sweep/sampling.hpp).
    auto up_proved = [&](const std::vector<ring_site>& rs, const ring_frames& fr) {
        if (!opt.up) return true;
        const vec<3> up = *opt.up / norm(*opt.up);
        for (const auto& z : fr.zones)
            if (!std::isfinite(z.delta)) return false;
        return every_piece(rs, [&](std::size_t k, std::size_t i, double ua, double ub) {
            return fr.step_zone[k] >= 0 || up_piece_proved(curve.segment(i), ua, ub, up);
        });
    };
    // A step's zone rates from the rings' frames.
    auto frame_zone = [&](const ring_frames& fr, std::size_t k) -> std::optional<zone_rates> {
        if (fr.step_zone.empty() || fr.step_zone[k] < 0) return std::nullopt;
        const auto& z = fr.zones[std::size_t(fr.step_zone[k])];
        return zone_rates{z.rate_t1(), z.rate_t2()};
    };
    ring_inputs in;
    in.curve = &curve;
    in.roll = &roll;
    in.roll_in_s = roll_in_s;
    in.roll_turn = roll_turn;
    in.scale = &scale;
    if (opt.up) in.up = *opt.up;
    in.spread_holonomy = opt.spread_holonomy;
    // The bound a set of rings achieves: the along bound of each step's
    // pieces (the closed frame's twist rate from the measured holonomy and
    // the carried frame's drift, which bounds how far the exact one is),
    // the profile's (around), and the ring frames' drift from the exact
    // rotation-minimizing frame times the largest profile radius at the
    // ring (sweep/drift.hpp).
    struct achieved_bound {
        double along = 0, frame = 0;
        std::vector<double> step_along, step_width;
    };
    // The closed frame's twist rate: the exact holonomy's bound, spread.
    auto exact_twist = [&](const ring_frames& fr) {
        return closed && !opt.up && opt.spread_holonomy ? (std::abs(fr.holonomy) + fr.end_drift) / period : 0.0;
    };
    // The frames' drift times the largest profile radius, ring by ring.
    auto frame_term = [&](const ring_frames& fr) {
        double t = 0;
        for (std::size_t k = 0; k < fr.drift.size(); ++k) t = std::max(t, fr.scale[k] * prof.rho * fr.drift[k]);
        return t;
    };
    auto achieved = [&](const std::vector<ring_site>& rs, const ring_frames& fr) {
        achieved_bound b;
        const double twist = exact_twist(fr);
        b.step_along.assign(rs.size(), 0.0);
        b.step_width.assign(rs.size(), 0.0);
        every_piece(rs, [&](std::size_t k, std::size_t i, double ua, double ub) {
            const double a = along_bound(curve.segment(i), ua, ub, rates_for(i, ua, ub, twist, frame_zone(fr, k)));
            b.step_along[k] = std::max(b.step_along[k], a);
            b.step_width[k] += ub - ua;
            b.along = std::max(b.along, a);
            return true;
        });
        b.frame = frame_term(fr);
        return b;
    };
    std::vector<ring_site> sites;
    ring_frames frames;
    bool met = true;
    double bound = 0;
    if (!given_counts) {
        // The rings are placed for the along bound with a hundredth of its share
        // kept for the frames' drift; steps over their share are then split
        // until the whole bound holds.
        const double along_target = along_tol * (1 - sweep_drift_share);
        double placed_along = 0, placed_twist = 0;  // the placement's largest along bound, and the twist it used
        // An interval's zone rates for the placement: its cone zone's length in
        // t and a bound on Delta (pi / 2 and a margin for the drift before
        // the rings measure it, then the measured bound).
        auto placement_zone = [&](std::size_t i, double ua, double ub) -> std::optional<zone_rates> {
            const double tm = grid[i] + (ua + ub) / 2 * (grid[i + 1] - grid[i]);
            for (const auto& z : cone_zones) {
                if (!(z[0] <= tm && tm <= z[1]) || !(z[1] > z[0])) continue;
                double delta = std::numbers::pi / 2 + 0.01;
                for (const auto& fz : frames.zones)
                    if (fz.t_in <= tm && tm <= fz.t_out) delta = std::min(delta, fz.delta * 1.01 + 1e-9);
                const double T = z[1] - z[0];
                return zone_rates{1.5 * delta / T, 6 * delta / (T * T)};
            }
            return std::nullopt;
        };
        auto place = [&](double twist) {
            sites.clear();
            met = true;
            placed_along = 0, placed_twist = twist;
            std::vector<double> cuts;
            for (std::size_t i = 0; i < curve.segment_count(); ++i) {
                if (constant(i)) continue;
                if (sites.empty()) sites.push_back(site(i, 0));
                std::vector<double> br{0.0};
                for (double t : key_t)
                    if (t > grid[i] && t < grid[i + 1]) br.push_back((t - grid[i]) / (grid[i + 1] - grid[i]));
                br.push_back(1.0);
                for (std::size_t b = 0; b + 1 < br.size(); ++b) {
                    cuts.clear();
                    met &= cut_interval(curve.segment(i), br[b], br[b + 1],
                                        rates_for(i, br[b], br[b + 1], twist, placement_zone(i, br[b], br[b + 1])),
                                        along_target, 1u << 16, cuts, placed_along);
                    for (double u : cuts) sites.push_back(site(i, u));
                    sites.push_back(site(i, br[b + 1]));
                }
            }
            if (sites.empty()) sites = {site(0, 0), site(curve.segment_count() - 1, 1)};  // a single point
        };
        // (A closed curve's first rings only measure its holonomy: their
        // drift is bounded on the rings placed with its twist.)
        in.drift = !(closed && !opt.up && opt.spread_holonomy);
        place(0);
        frames = compute_rings(sites, in);
        const bool first_drift = in.drift;
        in.drift = true;
        // Again with the twist the holonomy needs, or the zones' measured turn.
        const double twist = closed && !opt.up && opt.spread_holonomy ? std::abs(frames.holonomy) / period * 1.01 : 0.0;
        if (twist > 0 || !first_drift || !cone_zones.empty()) {
            if (twist > 0 || !cone_zones.empty()) place(twist);
            frames = compute_rings(sites, in);
        }
        // drift_k + f_k drift_last (spread holonomy), or + sigma_k drift_zone (up)
        const double spread = (closed && !opt.up && opt.spread_holonomy) || opt.up ? 2.0 : 1.0;
        for (int round = 0;; ++round) {
            if (round == 0 && met) {
                // The placement's own bounds hold where its twist was at
                // least the final one (along_bound grows with it).
                bound = placed_along + around + frame_term(frames);
                if (exact_twist(frames) <= placed_twist && frames.zones.empty() && bound <= tol * (1 + 1e-12)) break;
            }
            const auto b = achieved(sites, frames);
            bound = met ? b.along + around + b.frame : std::numeric_limits<double>::infinity();
            if (!met || bound <= tol * (1 + 1e-12) || round == 8) break;
            double r_max = 0, width = 0;
            for (double r : frames.scale) r_max = std::max(r_max, r * prof.rho);
            for (double w : b.step_width) width += w;
            const double room = std::max(tol - around - along_target, 0.0) / (spread * r_max * width);
            std::vector<ring_site> next{sites[0]};
            for (std::size_t k = 1; k < sites.size(); ++k) {
                const bool split = b.step_along[k] > along_target ||
                                   (!frames.step_drift.empty() && frames.step_drift[k] > room * b.step_width[k]);
                if (split && b.step_width[k] > 0) {
                    const auto& p = sites[k - 1];
                    const auto& q = sites[k];
                    next.push_back(p.segment == q.segment ? site(q.segment, (p.u + q.u) / 2) : site(q.segment, q.u / 2));
                }
                next.push_back(sites[k]);
            }
            if (next.size() == sites.size()) break;
            sites = std::move(next);
            frames = compute_rings(sites, in);
        }
        out.report.tolerance = tol;
    } else {
        // Given counts: rings equally spaced in arc length (three.js' tubularSegments).
        const std::size_t K = opt.tubular_segments ? opt.tubular_segments : 64;
        std::vector<double> s(K + 1), t(K + 1);
        for (std::size_t k = 0; k <= K; ++k) s[k] = k == K ? length : length * double(k) / double(K);
        table.t_at(std::span<const double>(s), std::span<double>(t));
        for (std::size_t k = 0; k <= K; ++k) {
            ring_site r;
            r.segment = k == K ? curve.segment_count() - 1 : curve.locate(t[k]);
            const double d = grid[r.segment + 1] - grid[r.segment];
            r.t = k == K ? curve.t_max() : t[k];
            r.u = k == K ? 1.0 : (d > 0 ? (r.t - grid[r.segment]) / d : 0.0);
            r.s = s[k];
            sites.push_back(r);
        }
        frames = compute_rings(sites, in);
        const auto b = achieved(sites, frames);
        bound = b.along + around + b.frame;
    }
    // 5. The mesh.
    write_mesh(frames, sites, prof, length, closed, closed && opt.spread_holonomy, out.positions, out.normals, out.uvs,
               out.indices, out.report.seam_gap, out.report.seam_normal_gap);
    out.rings = sites.size();
    out.ring_size = prof.points.size();
    for (const auto& r : sites) out.t.push_back(r.t), out.s.push_back(r.s);
    // 6. The report.
    auto& rep = out.report;
    rep.bound = bound;
    rep.tolerance_met = given_counts || bound <= tol * (1 + 1e-12);
    rep.proved = up_proved(sites, frames);
    rep.holonomy = frames.holonomy;
    for (double d : frames.drift) rep.frame_drift = std::max(rep.frame_drift, d);
    rep.length = length;
    for (std::size_t k = 0; k < sites.size(); ++k) rep.largest_radius = std::max(rep.largest_radius, frames.scale[k] * prof.rho);
    // The fold test, proved between the rings: each piece's curvature bound
    // against its largest profile radius (the scale's bound over the piece).
    every_piece(sites, [&](std::size_t, std::size_t i, double ua, double ub) {
        const double kappa = curvature_upper(curve.segment(i), ua, ub);
        if (kappa > 0) rep.min_radius_of_curvature = std::min(rep.min_radius_of_curvature, 1 / kappa);
        const double extent = (scale.empty() ? 1.0 : rates_for(i, ua, ub, 0).scale) * prof.rho;
        if (extent * kappa >= 1) rep.local_fold = true;
        return true;
    });
    if (opt.clearance && curve.segment_count() >= 3) rep.clearance = clearance(curve).distance;
    rep.far_contact = rep.clearance < 2 * rep.largest_radius;
    rep.self_intersects = rep.far_contact || rep.local_fold;
    return out;
}

/// Sweeps need a 3-D curve: for another dimension, a spec_error naming "curve".
template <std::size_t D>
    requires(D != 3)
sweep_mesh sweep(const catmull_rom<D>&, const sweep_options& = {}) {
    throw spec_error("curve", std::nullopt, std::nullopt, std::to_string(D),
                     "curve: sweep needs a 3-D curve, got a " + std::to_string(D) + "-D one");
}

}  // namespace crspline
