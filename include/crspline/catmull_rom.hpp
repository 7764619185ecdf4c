// crspline: the Catmull-Rom spline, its construction and evaluation.
//
// This file is the curve: its options, how it is built (knot intervals,
// tangents, end conditions), what it stores and how one point is
// evaluated. The batch paths of evaluate(span, span) live in
// detail/batch_kernels.hpp, the table behind locate() in
// detail/knot_index.hpp.
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

#include "detail/batch_kernels.hpp"
#include "detail/finite_geometry.hpp"
#include "detail/format.hpp"
#include "detail/knot_index.hpp"
#include "detail/magnitude.hpp"
#include "detail/storage.hpp"
#include "end_condition.hpp"
#include "error.hpp"
#include "parameterization.hpp"
#include "point_traits.hpp"
#include "segment.hpp"
#include "vec.hpp"

namespace crspline {


/// Kochanek-Bartels tension / continuity / bias, one value per vertex (the
/// conventions of the Python `splines` package). Empty vectors mean 0. Open
/// curves ignore the values at their two end vertices.
template <class T = double>
struct kochanek_bartels {
    std::vector<T> tension{}, continuity{}, bias{};
    bool empty() const noexcept { return tension.empty() && continuity.empty() && bias.empty(); }
};

/// How to build a curve. Every choice has a visible default.
template <std::size_t D, class T = double>
struct options {
    std::optional<double> alpha{};        ///< knot exponent in [0, 1]; default centripetal (0.5)
    std::optional<std::vector<T>> grid{}; ///< explicit knots instead of alpha (N, or N+1 when closed)
    end_condition<D, T> start = end_condition<D, T>::natural();  ///< open curves only
    end_condition<D, T> end = end_condition<D, T>::natural();    ///< open curves only
    bool closed = false;                  ///< periodic; the first point is not repeated
    T tension = 0;                        ///< tau in [0, 1]: computed tangents scaled by 1 - tau
    kochanek_bartels<T> kb{};             ///< per-vertex TCB; empty = plain Catmull-Rom
    bool strict = false;                  ///< reject coincident consecutive points (alpha > 0)
};

/// A cubic Catmull-Rom curve through N points in D dimensions.
///
/// Parameter t runs over [grid().front(), grid().back()]. Segment i joins
/// points[i] and points[i+1] (points[0] for the last segment of a closed
/// curve) on [grid[i], grid[i+1]]; an interior knot belongs to the segment on
/// its right, the last knot to the last segment.
///
/// Knot intervals and knots. Each segment keeps its knot interval h(i) as it
/// was computed, |P(i+1) - P(i)|^alpha (or, for an explicit grid, the grid's
/// difference), and the shape comes from these intervals only: tangents at
/// the vertices, Bézier points, segment(i) as a cubic in u, and every
/// analysis. The knots grid() are the running sums of the intervals, rounded:
/// an interval far below the sum before it (a short chord after long ones)
/// would lose most of its digits if it were recovered as a difference of
/// knots. The map from t to a segment's u uses the stored knots, u = (t -
/// grid[i]) / (grid[i+1] - grid[i]), so that t over [grid[i], grid[i+1]]
/// traces the whole segment, no more, and the curve is continuous in t.
/// Within segment i the speed dx/dt is therefore the exact curve's times
/// h(i) / d(i), d(i) = grid[i+1] - grid[i], where |d(i) - h(i)| <= eps *
/// grid[i+1] (eps = machine epsilon of T: one rounding of the sum, one of the
/// difference): the knots' own precision. See intervals(), tangents().
///
/// Rebuilding: options() (with grid() when explicit_grid()) gives the same
/// curve bit for bit. grid() passed back as an explicit grid of an alpha
/// curve gives the same knots bit for bit but intervals d(i) instead of h(i)
/// (equal whenever the sums are exact, as for alpha = 0), a curve whose
/// shape is that of intervals each within eps * grid[i+1] of the originals.
template <std::size_t D, class T = double>
class catmull_rom {
public:
    using point = vec<D, T>;
    using scalar = T;
    using segment_type = cubic_segment<D, T>;
    using options_type = crspline::options<D, T>;
    static constexpr std::size_t dimension = D;

    explicit catmull_rom(std::span<const point> points, const options_type& opt = {}) { build(points, opt); }
    catmull_rom(std::initializer_list<point> points, const options_type& opt = {})
        : catmull_rom(std::span<const point>(points.begin(), points.size()), opt) {}

    /// A cubic Hermite curve: the points, their knots and a tangent dx/dt at
    /// every vertex, taken as given (Catmull-Rom and Kochanek-Bartels are the
    /// special cases whose tangents come from the neighbours). `grid` has N
    /// values, N + 1 when closed (the last knot closes the loop back to
    /// points[0]). `outgoing[i]` starts the segment leaving vertex i,
    /// `incoming[i]` ends the segment arriving at it; an open curve uses
    /// outgoing[0 .. N-2] and incoming[1 .. N-1] only (the other two entries
    /// are ignored). Throws invalid_input naming the index and value of a
    /// bad point, tangent or knot.
    static catmull_rom hermite(std::span<const point> points, std::span<const point> outgoing,
                               std::span<const point> incoming, std::span<const T> grid, bool closed = false) {
        catmull_rom c(hermite_tag{});
        c.build_hermite(points, outgoing, incoming, grid, closed);
        return c;
    }
    /// The same with one tangent per vertex, incoming = outgoing (a C1 curve).
    static catmull_rom hermite(std::span<const point> points, std::span<const point> tangents,
                               std::span<const T> grid, bool closed = false) {
        return hermite(points, tangents, tangents, grid, closed);
    }

    // --- what the curve is made of ------------------------------------------
    std::span<const point> points() const noexcept { return points_; }
    std::span<const T> grid() const noexcept { return grid_; }
    /// Knot interval h(i) of each segment as computed: |P(i+1) - P(i)|^alpha
    /// (0 for coincident points), or grid[i+1] - grid[i] for an explicit grid
    /// and hermite(). The shape is made from these; grid() holds their
    /// rounded running sums (see the class comment).
    std::span<const T> intervals() const noexcept { return h_; }
    bool closed() const noexcept { return closed_; }

    /// How the curve was built: the options given to the constructor, so that
    /// the analysis (and anyone else) reads the construction instead of
    /// guessing it from the numbers. Two differences from what was passed:
    /// `alpha` holds the exponent actually used (centripetal when none was
    /// given) when the knots came from alpha, and is empty when they came
    /// from an explicit grid; and `grid` is always empty, since the knots are
    /// stored once, as grid(). To rebuild the same curve:
    /// `auto o = c.options(); if (!o.alpha) o.grid.emplace(c.grid().begin(), c.grid().end());`
    const options_type& options() const noexcept { return options_; }
    /// The knots came from an explicit grid, not from alpha.
    bool explicit_grid() const noexcept { return !options_.alpha.has_value(); }
    /// The tangents were given (hermite()), not computed from the neighbours:
    /// no Catmull-Rom formula (the paper's bounds, the angle rule) applies.
    bool given_tangents() const noexcept { return given_tangents_; }

    std::size_t segment_count() const noexcept { return inv_h_.size(); }
    T t_min() const noexcept { return grid_.front(); }
    T t_max() const noexcept { return grid_.back(); }

    /// Segment i in power-basis form: its u-tangents h(i) dx/dt come from the
    /// interval h(i), its t0, h and inv_h from the stored knots (see the class
    /// comment). The curve stores points, knots, intervals, 1/h and one
    /// tangent per vertex (76 bytes per 3-D point with its bucket entry, not
    /// the 120 of a cubic_segment): segments are computed on
    /// access, by the same arithmetic every time, so every path sees the
    /// same bits.
    segment_type segment(std::size_t i) const {
        check_segment_index(i);
        return make_segment(i);
    }

    /// A random-access range over the segments, by value (each computed on
    /// access, as segment() without the range check). Refers to the curve:
    /// valid while the curve lives.
    class segment_view {
    public:
        class iterator {
        public:
            using iterator_concept = std::random_access_iterator_tag;
            using iterator_category = std::input_iterator_tag;  // yields values, not references
            using value_type = segment_type;
            using difference_type = std::ptrdiff_t;
            using reference = segment_type;
            iterator() = default;
            segment_type operator*() const noexcept { return c_->make_segment(i_); }
            segment_type operator[](difference_type k) const noexcept { return c_->make_segment(std::size_t(difference_type(i_) + k)); }
            iterator& operator++() noexcept { ++i_; return *this; }
            iterator operator++(int) noexcept { iterator r = *this; ++i_; return r; }
            iterator& operator--() noexcept { --i_; return *this; }
            iterator operator--(int) noexcept { iterator r = *this; --i_; return r; }
            iterator& operator+=(difference_type k) noexcept { i_ = std::size_t(difference_type(i_) + k); return *this; }
            iterator& operator-=(difference_type k) noexcept { return *this += -k; }
            friend iterator operator+(iterator a, difference_type k) noexcept { return a += k; }
            friend iterator operator+(difference_type k, iterator a) noexcept { return a += k; }
            friend iterator operator-(iterator a, difference_type k) noexcept { return a -= k; }
            friend difference_type operator-(const iterator& a, const iterator& b) noexcept {
                return difference_type(a.i_) - difference_type(b.i_);
            }
            friend bool operator==(const iterator& a, const iterator& b) noexcept { return a.i_ == b.i_; }
            friend auto operator<=>(const iterator& a, const iterator& b) noexcept { return a.i_ <=> b.i_; }

        private:
            friend class segment_view;
            iterator(const catmull_rom* c, std::size_t i) noexcept : c_(c), i_(i) {}
            const catmull_rom* c_ = nullptr;
            std::size_t i_ = 0;
        };

        segment_view() = default;
        std::size_t size() const noexcept { return c_ ? c_->segment_count() : 0; }
        bool empty() const noexcept { return size() == 0; }
        segment_type operator[](std::size_t i) const noexcept { return c_->make_segment(i); }
        segment_type front() const noexcept { return c_->make_segment(0); }
        segment_type back() const noexcept { return c_->make_segment(size() - 1); }
        iterator begin() const noexcept { return iterator(c_, 0); }
        iterator end() const noexcept { return iterator(c_, size()); }

    private:
        friend class catmull_rom;
        explicit segment_view(const catmull_rom* c) noexcept : c_(c) {}
        const catmull_rom* c_ = nullptr;
    };

    /// All segments, as a random-access range of values (see segment()).
    segment_view segments() const noexcept { return segment_view(this); }

    /// Tangents dx/dt at the start and end of segment i, as evaluate(t, 1)
    /// gives them: the vertex tangents of the exact curve times h(i) / d(i)
    /// (exactly them when the stored knots' difference d(i) is the interval
    /// h(i), as it is for explicit grids and whenever the sums are exact; see
    /// the class comment). With the stored knots' difference they give the
    /// Bézier points, B1 = B0 + d(i)/3 v0 as bezier() computes it from h(i).
    /// Equal at interior knots (up to that factor) unless Kochanek-Bartels
    /// continuity breaks them.
    std::array<point, 2> tangents(std::size_t i) const {
        check_segment_index(i);
        const T d = grid_[i + 1] - grid_[i];
        if (d == h_[i]) return {out_tangent(i), in_tangent(next(i))};
        const T r = h_[i] * inv_h_[i];  // h / d; 0 when d is 0 (no t to evaluate at)
        return {r * out_tangent(i), r * in_tangent(next(i))};
    }

    // --- evaluation -----------------------------------------------------------
    /// Index of the segment that owns t, clamped to the first and last
    /// segment (NaN gives the first). O(1) on average: a bucket table over
    /// the domain narrows the candidates to a few segments, counted without
    /// a branch; a branch-free binary search finishes the rare crowded
    /// bucket (O(log N) at worst, for very uneven knots).
    std::size_t locate(T t) const noexcept {
        return index_.locate(t, grid_.data(), segment_count());
    }

    /// Position (order 0) or derivative d^k x / dt^k (order 1-3) at t.
    /// Throws out_of_domain when t is outside [t_min, t_max] or not a number.
    point evaluate(T t, int order = 0) const {
        check_order(order);
        check_t(t, std::nullopt);
        return evaluate_unchecked(t, order);
    }
    point operator()(T t) const { return evaluate(t, 0); }

    /// Same without checks: t outside the domain extrapolates the first or last
    /// segment's cubic; order outside 0-3 gives zero.
    point evaluate_unchecked(T t, int order = 0) const noexcept {
        // The last knot gives the last point exactly (the cubic at u = 1 is
        // only within rounding of it).
        if (order == 0 && t == grid_.back()) return points_[closed_ ? 0 : points_.size() - 1];
        const segment_type s = make_segment(locate(t));
        return s.dt(s.local(t), order);
    }

    /// Position at t without checks: evaluate_unchecked(t, 0) with no
    /// order switch (the single-point kernel of unsorted batches).
    point position_unchecked(T t) const noexcept {
        if (t == grid_.back()) return points_[closed_ ? 0 : points_.size() - 1];
        const segment_type s = make_segment(locate(t));
        return s.at(s.local(t));
    }

    /// Evaluate into a user point type.
    template <point_like P>
    P evaluate_as(T t, int order = 0) const { return from_vec<P>(evaluate(t, order)); }

    /// Batch evaluation: out[k] = d^order x / dt^order at t[k]. Sorted input
    /// walks the segments without searching; unsorted input locates each t
    /// by branch-free search. Throws out_of_domain naming the first bad index.
    void evaluate(std::span<const T> t, std::span<point> out, int order = 0) const {
        check_order(order);
        if (out.size() != t.size())
            throw invalid_input("output has " + std::to_string(out.size()) + " points for " +
                                std::to_string(t.size()) + " parameter values");
        if (t.empty()) return;
        detail::batch_kernels<D, T>::evaluate(*this, t, out, order);
    }
    std::vector<point> evaluate(std::span<const T> t, int order = 0) const {
        std::vector<point> out(t.size());
        evaluate(t, std::span<point>(out), order);
        return out;
    }

    /// Bézier control points of segment i: B0 = points[i], B3 = the next
    /// point, exactly; B1 and B2 from the vertex tangents and the interval
    /// h(i) (not the difference of the rounded knots).
    std::array<point, 4> bezier(std::size_t i) const {
        check_segment_index(i);
        const point& v0 = out_tangent(i);
        const point& v1 = in_tangent(next(i));
        const point& p0 = points_[i];
        const point& p1 = points_[next(i)];
        const T h = h_[i];
        return {p0, p0 + (h / T(3)) * v0, p1 - (h / T(3)) * v1, p1};
    }
    std::vector<std::array<point, 4>> bezier() const {
        std::vector<std::array<point, 4>> b(segment_count());
        for (std::size_t i = 0; i < b.size(); ++i) b[i] = bezier(i);
        return b;
    }

private:
    // What the curve stores, per point: the point, its knot, the interval h
    // and 1 / d of the segment starting there and one tangent dx/dt (plus a
    // bucket entry of the knot index).
    // Segment i runs from points_[i] to points_[next(i)] with tangents
    // out_tangent(i) and in_tangent(next(i)).
    detail::storage<point> points_;
    detail::storage<T> grid_;
    detail::storage<T> h_;            // knot interval h(i) as computed (see intervals()); one per segment
    detail::storage<T> inv_h_;        // 1 / (grid[i+1] - grid[i]), 0 for a zero difference: the t -> u map
    detail::storage<point> tangent_;  // outgoing dx/dt at each vertex; for an open curve the last is the incoming one
    detail::storage<point> in_;       // incoming dx/dt at each vertex, only when continuity can make it differ
    bool closed_ = false;
    options_type options_;            // how it was built (alpha resolved, grid not copied): see options()
    bool given_tangents_ = false;     // built by hermite(): options_ holds only the defaults

    std::size_t next(std::size_t i) const noexcept { return i + 1 == points_.size() ? 0 : i + 1; }
    const point& out_tangent(std::size_t i) const noexcept { return tangent_[i]; }
    const point& in_tangent(std::size_t j) const noexcept { return in_.empty() ? tangent_[j] : in_[j]; }

    /// Segment i, unchecked: the Hermite segment of segment_type::hermite,
    /// its u-tangents from the interval h(i), its t-range [grid[i],
    /// grid[i+1]] with 1/d from the table (no division). (detail::hermite_point3
    /// is the same arithmetic in 4-lane registers.)
    segment_type make_segment(std::size_t i) const noexcept {
        const std::size_t j = next(i);
        const T h = h_[i];
        return segment_type::hermite(points_[i], points_[j], h * out_tangent(i), h * in_tangent(j), grid_[i],
                                     grid_[i + 1] - grid_[i], inv_h_[i]);
    }
    // locate(): the bucket table over the knots (detail/knot_index.hpp).
    detail::knot_index<T> index_;

    // The batch paths of evaluate(span, span) read the arrays above directly.
    friend struct detail::batch_kernels<D, T>;

    void check_segment_index(std::size_t i) const {
        if (i >= segment_count())
            throw invalid_input("segment index " + std::to_string(i) + " is out of range (the curve has " +
                                std::to_string(segment_count()) + " segments)");
    }
    static void check_order(int order) {
        if (order < 0 || order > 3)
            throw invalid_input("derivative order must be 0, 1, 2 or 3, got " + std::to_string(order));
    }

    void check_t(T t, std::optional<std::size_t> index) const {
        if (!(t >= grid_.front() && t <= grid_.back()))
            throw out_of_domain("t = " + detail::num(double(t)) +
                                (index ? " (index " + std::to_string(*index) + ")" : std::string()) +
                                " is outside the domain [" + detail::num(double(grid_.front())) + ", " +
                                detail::num(double(grid_.back())) + "]");
    }


    void build(std::span<const point> p, const options_type& opt);
    // Refuses, naming the points, a chord, knot, tangent or Bezier point
    // that overflowed (detail/finite_geometry.hpp).
    void check_finite_geometry() const {
        detail::check_finite_geometry<D, T>(
            points_, h_, grid_, [&](std::size_t i) -> const point& { return out_tangent(i); },
            [&](std::size_t i) -> const point& { return in_tangent(i); });
    }

    struct hermite_tag {};
    explicit catmull_rom(hermite_tag) noexcept {}
    void build_hermite(std::span<const point> p, std::span<const point> outgoing, std::span<const point> incoming,
                       std::span<const T> grid, bool closed);
};

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

/// Build a curve from any range of user points (std::array, Eigen, glm, a
/// struct with point_traits); dimension and scalar come from the point type.
template <class Range, class P = std::remove_cvref_t<decltype(*std::begin(std::declval<const Range&>()))>>
    requires point_like<P>
auto make_catmull_rom(const Range& range, const options<dimension_of<P>, scalar_of<P>>& opt = {}) {
    std::vector<vec<dimension_of<P>, scalar_of<P>>> pts;
    for (const auto& p : range) pts.push_back(to_vec(p));
    return catmull_rom<dimension_of<P>, scalar_of<P>>(std::span<const vec<dimension_of<P>, scalar_of<P>>>(pts), opt);
}

}  // namespace crspline
