// crspline internal: how a catmull_rom is built (catmull_rom.hpp, which
// includes this file after the class): build() validates the points at the
// boundary, computes the knots, the tangents and the end conditions;
// build_hermite() stores given tangents. Included alone, it includes the
// class first.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "../catmull_rom.hpp"
#include "../end_condition.hpp"
#include "../error.hpp"
#include "../parameterization.hpp"
#include "finite_geometry.hpp"
#include "format.hpp"

namespace crspline {

template <std::size_t D, class T>
void catmull_rom<D, T>::build_hermite(std::span<const point> p, std::span<const point> outgoing,
                                      std::span<const point> incoming, std::span<const T> grid, bool closed) {
    const std::size_t n = p.size();
    closed_ = closed;
    given_tangents_ = true;
    options_.closed = closed;
    // 1. Validate at the boundary: enough points, finite values, a tangent
    //    per vertex, an increasing grid of the right length.
    detail::check_point_count(n, closed);
    check_finite(p);
    const std::size_t nseg = closed ? n : n - 1;
    const std::pair<std::span<const point>, const char*> given[2] = {{outgoing, "outgoing"}, {incoming, "incoming"}};
    for (const auto& [tangents, name] : given) {
        if (tangents.size() != n)
            throw invalid_input(std::string(name) + " tangents: got " + std::to_string(tangents.size()) +
                                ", expected one per point (" + std::to_string(n) + ")");
        // An open curve does not use the outgoing tangent of its last vertex
        // nor the incoming one of its first.
        const std::size_t skip = closed ? n : (name[0] == 'o' ? n - 1 : 0);
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t k = 0; k < D && i != skip; ++k)
                if (!std::isfinite(tangents[i][k]))
                    throw invalid_input(std::string(name) + " tangent " + std::to_string(i) + ", coordinate " +
                                        std::to_string(k) + " is not finite (" + detail::num(double(tangents[i][k])) +
                                        ")");
    }
    check_grid(grid, nseg + 1, closed);

    // 2. Store points, knots, intervals (the grid's differences) and 1/h as
    //    build() does.
    points_.assign(p.begin(), p.end());
    grid_.assign(grid.begin(), grid.end());
    h_.resize(nseg);
    inv_h_.resize(nseg);
    for (std::size_t i = 0; i < nseg; ++i) h_[i] = grid_[i + 1] - grid_[i], inv_h_[i] = T(1) / h_[i];

    // 3. Tangents: one shared array when incoming and outgoing agree at every
    //    vertex that uses both (bit for bit), else both arrays. An open
    //    curve's last entry of the shared array is its incoming end tangent.
    bool split = false;
    for (std::size_t i = closed ? 0 : 1; i < (closed ? n : n - 1) && !split; ++i)
        for (std::size_t k = 0; k < D; ++k)
            if (!(outgoing[i][k] == incoming[i][k])) split = true;
    tangent_.assign(outgoing.begin(), outgoing.end());
    if (!closed) tangent_[n - 1] = incoming[n - 1];
    if (split) {
        in_.assign(incoming.begin(), incoming.end());
        if (!closed) in_[0] = outgoing[0];  // unused
    } else {
        in_.clear();
    }
    check_finite_geometry();
    index_.build(grid_.data(), nseg);
}

template <std::size_t D, class T>
void catmull_rom<D, T>::build(std::span<const point> p, const options_type& opt) {
    const std::size_t n = p.size();
    closed_ = opt.closed;
    // 1. Validate the input once, here at the boundary, by the same code
    //    as crspline::validate(curve_spec) (detail/validate.hpp). The
    //    coordinates first, as validate_description orders its checks: one
    //    reduction over the flat array (detail/magnitude.hpp), and only if it
    //    finds a NaN or an infinity the check that names it.
    static_assert(sizeof(point) == D * sizeof(T), "points are stored as D contiguous scalars");
    detail::check_point_count(n, closed_);
    const detail::magnitude<T> point_magnitude = detail::max_abs_finite(p.front().data(), n * D);
    if (!point_magnitude.finite) check_finite(p);
    const auto end_of = [](const end_condition<D, T>& e) {
        using k = typename end_condition<D, T>::kind;
        const detail::end_kind type = e.type == k::tangent   ? detail::end_kind::tangent
                                      : e.type == k::reflect ? detail::end_kind::reflect
                                                             : detail::end_kind::natural;
        return detail::end_view<T>{type, std::span<const T>(e.velocity.data(), D)};
    };
    detail::validate_description<T>(
        n, D, [&](std::size_t i, std::size_t k) { return p[i][k]; }, opt.alpha, opt.grid, closed_,
        end_of(opt.start), end_of(opt.end), double(opt.tension), opt.kb.tension, opt.kb.continuity, opt.kb.bias,
        /*coordinates_checked=*/true);

    // 2. Parameterization: intervals from alpha, kept as computed, and the
    //    knots as their running sums; or the given grid and its differences.
    points_.assign(p.begin(), p.end());
    const std::size_t nseg = closed_ ? n : n - 1;
    h_.resize(nseg);
    if (opt.grid) {
        grid_.assign(opt.grid->begin(), opt.grid->end());
        for (std::size_t i = 0; i < nseg; ++i) h_[i] = grid_[i + 1] - grid_[i];
    } else {
        const double alpha = opt.alpha.value_or(centripetal);
        if (opt.strict && alpha > 0) {
            const auto bad = coincident_chords(p, closed_);
            if (!bad.empty()) {
                std::string msg = "coincident consecutive points (strict mode):";
                for (std::size_t i : bad) {
                    msg += ' ';
                    msg += std::to_string(i);
                    msg += " and ";
                    msg += std::to_string((i + 1) % n);
                    msg += ';';
                }
                msg.pop_back();
                detail::spec_fail("points", bad.front(), std::nullopt, "", msg);
            }
        }
        grid_.resize(nseg + 1);
        detail::fill_intervals(p, alpha, closed_, h_.data(), point_magnitude.max_abs);
        grid_[0] = 0;
        for (std::size_t i = 0; i < nseg; ++i) grid_[i + 1] = grid_[i] + h_[i];
    }

    // 3. Chord velocities v(i) = (P(i+1) - P(i)) / h(i), as the product with
    //    1 / h(i); zero for a zero knot interval (the limit convention for
    //    coincident points). h(i) is the interval as computed, never a
    //    difference of the rounded knots (issue 13: a difference of sums near
    //    1e6 keeps only a few digits of an interval of 1e-9).
    inv_h_.resize(nseg);
    for (std::size_t i = 0; i < nseg; ++i) {
        // (Written so that the compiler can divide two at a time: no
        // division under a condition.)
        const T h = h_[i];
        const T r = T(1) / (h > 0 ? h : T(1));
        inv_h_[i] = h > 0 ? r : T(0);
    }
    auto chord_velocity = [&](std::size_t i) { return (p[next(i)] - p[i]) * inv_h_[i]; };

    // 4. Tangents dx/dt at each vertex: incoming (end of the segment before)
    //    and outgoing (start of the segment after). With h0, h1 the intervals
    //    around the vertex, the Catmull-Rom tangent is
    //        (h1 v0 + h0 v1) / (h0 + h1)
    //    = [h1^2 (P1 - P0) + h0^2 (P2 - P1)] / [h0 h1 (h0 + h1)];
    //    Kochanek-Bartels weights the two terms. All-zero TCB gives weights of
    //    exactly 1, so it is bit-for-bit the plain curve. Without continuity
    //    values the incoming and outgoing tangents are the same expression
    //    (weights a = c, b = d exactly) and one array holds both.
    tangent_.resize(n);
    const bool split = !opt.kb.continuity.empty();
    if (split) in_.assign(n, point{});
    else in_.clear();
    auto set_in = [&](std::size_t i, const point& x) {
        if (split) in_[i] = x;
        else tangent_[i] = x;  // only at an open curve's last vertex, or equal to the outgoing one
    };
    auto tcb_at = [&](const std::vector<T>& a, std::size_t i) { return a.empty() ? T(0) : a[i]; };
    const bool plain = opt.kb.empty();
    const std::size_t first_kb = closed_ ? 0 : 1, last_kb = closed_ ? n : n - 1;  // vertices that use TCB
    if (last_kb > first_kb && plain) {
        // The plain tangent (h1 v0 + h0 v1) / (h0 + h1), block by block: the
        // block's reciprocals 1 / (h0 + h1) first, in a loop the compiler
        // runs two (SSE2) divisions at a time, then the tangents, which use
        // them. The same operations on the same values as one division per
        // vertex: the same bits (issue 30: the divisions, not the loads,
        // limit the construction).
        constexpr std::size_t block = 256;
        T inv_sum[block];
        std::size_t before = first_kb == 0 ? nseg - 1 : first_kb - 1;
        point v0 = chord_velocity(before);
        T h0 = h_[before];
        for (std::size_t b0 = first_kb; b0 < last_kb; b0 += block) {
            const std::size_t b1 = std::min(b0 + block, last_kb);
            std::size_t k = b0;
            if (k == 0) {  // a closed curve's vertex 0: the interval before it is the last
                const T sum = h_[nseg - 1] + h_[0];
                inv_sum[0] = sum > 0 ? T(1) / sum : T(0);
                ++k;
            }
            for (; k < b1; ++k) {
                const T sum = h_[k - 1] + h_[k];
                const T r = T(1) / (sum > 0 ? sum : T(1));
                inv_sum[k - b0] = sum > 0 ? r : T(0);
            }
            for (std::size_t i = b0; i < b1; ++i) {
                const point v1 = chord_velocity(i);  // i < nseg: the segment after vertex i
                const T h1 = h_[i];
                if (h0 + h1 > 0) tangent_[i] = (h1 * v0 + h0 * v1) * inv_sum[i - b0];
                else tangent_[i] = point{};
                v0 = v1, h0 = h1;
            }
        }
    } else if (last_kb > first_kb) {
        std::size_t before = first_kb == 0 ? nseg - 1 : first_kb - 1;
        point v0 = chord_velocity(before);
        T h0 = h_[before];
        for (std::size_t i = first_kb; i < last_kb; ++i) {
            const point v1 = chord_velocity(i);  // i < nseg: the segment after vertex i
            const T h1 = h_[i], sum = h0 + h1;
            if (!(sum > 0)) {
                tangent_[i] = point{};
                if (split) in_[i] = point{};
            } else if (plain) {
                tangent_[i] = (h1 * v0 + h0 * v1) * (T(1) / sum);  // one division, not D
            } else {
                const T Tn = tcb_at(opt.kb.tension, i), Cn = tcb_at(opt.kb.continuity, i), Bn = tcb_at(opt.kb.bias, i);
                const T a = (1 - Tn) * (1 + Cn) * (1 + Bn), b = (1 - Tn) * (1 - Cn) * (1 - Bn);
                const T c = (1 - Tn) * (1 - Cn) * (1 + Bn), d = (1 - Tn) * (1 + Cn) * (1 - Bn);
                const T r = T(1) / sum;
                tangent_[i] = ((a * h1) * v0 + (b * h0) * v1) * r;
                if (split) in_[i] = ((c * h1) * v0 + (d * h0) * v1) * r;
            }
            v0 = v1, h0 = h1;
        }
    }
    const T keep = T(1) - opt.tension;  // tension scales every computed tangent
    bool start_given = false, end_given = false;
    if (!closed_) {
        const point v_first = chord_velocity(0), v_last = chord_velocity(n - 2);
        if (n == 2) {
            // Two points: a straight line at constant speed, whatever the end
            // conditions and the tension.
            tangent_[0] = v_first;
            set_in(1, v_first);
            start_given = end_given = true;
        } else {
            using kind = typename end_condition<D, T>::kind;
            // natural: zero second derivative, from the other end's tangent.
            switch (opt.start.type) {
                case kind::natural: tangent_[0] = (T(3) * v_first - in_tangent(1)) / T(2); break;
                case kind::reflect: tangent_[0] = v_first; break;
                case kind::tangent: tangent_[0] = opt.start.velocity; start_given = true; break;
            }
            switch (opt.end.type) {
                case kind::natural: set_in(n - 1, (T(3) * v_last - tangent_[n - 2]) / T(2)); break;
                case kind::reflect: set_in(n - 1, v_last); break;
                case kind::tangent: set_in(n - 1, opt.end.velocity); end_given = true; break;
            }
        }
        if (split) tangent_[n - 1] = in_[n - 1];  // the last vertex has no outgoing tangent
    }
    if (keep != T(1)) {
        // The shared array holds each vertex once; an open curve's last entry
        // is the incoming end tangent.
        for (std::size_t i = 0; i < n; ++i) {
            const bool given = (i == 0 && start_given) || (i == n - 1 && !closed_ && end_given);
            if (!given) tangent_[i] *= keep;
        }
        if (split)
            for (std::size_t i = 0; i < n; ++i)
                if (!(i == n - 1 && end_given)) in_[i] *= keep;
    }
    // 5. The t -> u map: 1 / d(i) of the stored knots, which differs from
    //    1 / h(i) only where a sum was rounded (never for an explicit grid,
    //    but for most segments of a long curve). Written, like step 3, so
    //    that the compiler divides two at a time; where d = h it writes the
    //    same bits as step 3 did.
    for (std::size_t i = 0; i < nseg; ++i) {
        const T d = grid_[i + 1] - grid_[i];
        const T r = T(1) / (d > 0 ? d : T(1));
        inv_h_[i] = d > 0 ? r : T(0);
    }
    // 6. Nothing overflowed: chords, knots, tangents, Bezier points. The
    //    bound of detail::check_finite_geometry from reductions over the
    //    flat arrays; only when it fails, the check that names the points.
    {
        const auto mh = detail::max_abs_finite(h_.data(), nseg);
        auto mm = detail::max_abs_finite(tangent_.front().data(), n * D);
        if (!in_.empty()) {
            const auto mi = detail::max_abs_finite(in_.front().data(), n * D);
            mm = {std::max(mm.max_abs, mi.max_abs), mm.finite && mi.finite};
        }
        if (!(mh.finite && mm.finite &&
              detail::finite_geometry_bounded(point_magnitude.max_abs, mm.max_abs, mh.max_abs, grid_.back())))
            check_finite_geometry();
    }
    index_.build(grid_.data(), nseg);
    // 7. Remember how the curve was built (the grid is grid_, not copied).
    options_.alpha = opt.grid ? std::nullopt : std::optional<double>(opt.alpha.value_or(centripetal));
    options_.grid.reset();
    options_.start = opt.start;
    options_.end = opt.end;
    options_.closed = opt.closed;
    options_.tension = opt.tension;
    options_.kb = opt.kb;
    options_.strict = opt.strict;
}

}  // namespace crspline
