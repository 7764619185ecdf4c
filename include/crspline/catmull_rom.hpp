// crspline: the Catmull-Rom spline, its construction and evaluation.
//
// This file is the curve: its options, how it is built (knot intervals,
// tangents, end conditions), what it stores and how one point is
// evaluated. The batch paths of evaluate(span, span) live in
// detail/batch_kernels.hpp, the table behind locate() in
// detail/knot_index.hpp, how it is built (build(), build_hermite()) in
// detail/catmull_rom_build.hpp.
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

// The construction (the class's build() and build_hermite()).
#include "detail/catmull_rom_build.hpp"
