// crspline: a curve's description at run time, the one all front ends share.
//
// catmull_rom<D, T> fixes the dimension at compile time; a front end (the
// command line, Python, WebAssembly) learns it from its input. curve_spec is
// that input in one named form: the dimension, the points as flat doubles,
// alpha or an explicit grid, closed, the two ends, tension, the
// Kochanek-Bartels values and strict. validate() checks it once, by the same
// code as catmull_rom's constructor (detail/validate.hpp), and throws a
// spec_error (error.hpp) naming the field, the index, the value and the
// problem; each front end renders that in its own idiom instead of checking
// again. make_curve<D>() builds the curve, to_spec() describes one.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "catmull_rom.hpp"
#include "detail/validate.hpp"
#include "end_condition.hpp"
#include "error.hpp"
#include "vec.hpp"

namespace crspline {

/// The dimensions a curve_spec may have.
inline constexpr std::size_t max_spec_dimension = 16;

/// One end of an open curve, at run time.
struct end_spec {
    enum class kind { natural, reflect, tangent };
    kind type = kind::natural;
    std::vector<double> velocity{};  ///< dx/dt, one value per dimension, for kind::tangent
    friend bool operator==(const end_spec&, const end_spec&) = default;
};

/// Everything that describes a curve. The defaults are options<D>'s.
struct curve_spec {
    std::size_t dimension = 0;               ///< 1..max_spec_dimension
    std::vector<double> points{};            ///< flat: point i is points[i * dimension .. (i + 1) * dimension)
    std::optional<double> alpha{};           ///< knot exponent in [0, 1]; none with a grid, 0.5 by default
    std::optional<std::vector<double>> grid{};  ///< explicit knots (N, or N + 1 when closed)
    bool closed = false;                     ///< periodic; the first point is not repeated
    end_spec start{}, end{};                 ///< open curves only
    double tension = 0;                      ///< in [0, 1]
    kochanek_bartels<double> kb{};           ///< per vertex; empty = zeros; ends of an open curve ignored
    bool strict = false;                     ///< reject coincident consecutive points (alpha > 0)

    std::size_t point_count() const noexcept { return dimension == 0 ? 0 : points.size() / dimension; }
};

/// Throws spec_error unless the specification describes a curve. (Coincident
/// points in strict mode are found when the curve is built.)
inline void validate(const curve_spec& s) {
    if (s.dimension < 1 || s.dimension > max_spec_dimension)
        detail::spec_fail("dimension", std::nullopt, std::nullopt, std::to_string(s.dimension),
                          "dimension must be 1 to " + std::to_string(max_spec_dimension) + ", got " +
                              std::to_string(s.dimension));
    if (s.points.size() % s.dimension != 0)
        detail::spec_fail("points", std::nullopt, std::nullopt, std::to_string(s.points.size()),
                          "points has " + std::to_string(s.points.size()) +
                              " coordinates, not a whole number of points of dimension " +
                              std::to_string(s.dimension));
    const auto end_of = [](const end_spec& e) {
        const detail::end_kind type = e.type == end_spec::kind::tangent   ? detail::end_kind::tangent
                                      : e.type == end_spec::kind::reflect ? detail::end_kind::reflect
                                                                          : detail::end_kind::natural;
        return detail::end_view<double>{type, std::span<const double>(e.velocity)};
    };
    const std::size_t dim = s.dimension;
    detail::validate_description<double>(
        s.point_count(), dim, [&](std::size_t i, std::size_t k) { return s.points[i * dim + k]; }, s.alpha,
        s.grid, s.closed, end_of(s.start), end_of(s.end), s.tension, s.kb.tension, s.kb.continuity, s.kb.bias);
}

/// The library's options for a curve of dimension D from a validated
/// specification of dimension D or less (end tangents padded with zeros).
template <std::size_t D, class T = double>
options<D, T> to_options(const curve_spec& s) {
    const auto end_of = [](const end_spec& e) {
        switch (e.type) {
            case end_spec::kind::reflect: return end_condition<D, T>::reflect();
            case end_spec::kind::tangent: {
                vec<D, T> v{};
                for (std::size_t k = 0; k < D && k < e.velocity.size(); ++k) v[k] = T(e.velocity[k]);
                return end_condition<D, T>::tangent(v);
            }
            case end_spec::kind::natural: break;
        }
        return end_condition<D, T>::natural();
    };
    const auto values = [](const std::vector<double>& v) { return std::vector<T>(v.begin(), v.end()); };
    options<D, T> opt;
    opt.alpha = s.alpha;
    if (s.grid) opt.grid = values(*s.grid);
    opt.closed = s.closed;
    opt.start = end_of(s.start);
    opt.end = end_of(s.end);
    opt.tension = T(s.tension);
    opt.kb = {values(s.kb.tension), values(s.kb.continuity), values(s.kb.bias)};
    opt.strict = s.strict;
    return opt;
}

/// Builds the curve a specification describes; throws spec_error for a bad
/// one. D may exceed the specification's dimension: the points (and end
/// tangents) are then padded with zero coordinates, which leaves the first
/// coordinates exactly as a curve of the specification's own dimension has
/// them (see dispatch.hpp); D below it is an error.
template <std::size_t D, class T = double>
catmull_rom<D, T> make_curve(const curve_spec& s) {
    validate(s);
    const std::size_t d = s.dimension;
    if (d > D)
        detail::spec_fail("dimension", std::nullopt, std::nullopt, std::to_string(d),
                          "dimension is " + std::to_string(d) + ", more than the " + std::to_string(D) +
                              " of the curve type");
    std::vector<vec<D, T>> pts(s.point_count());
    for (std::size_t i = 0; i < pts.size(); ++i)
        for (std::size_t k = 0; k < d; ++k) pts[i][k] = T(s.points[i * d + k]);
    return catmull_rom<D, T>(std::span<const vec<D, T>>(pts), to_options<D, T>(s));
}

/// The specification of points and options (the inverse of make_curve).
template <std::size_t D, class T>
curve_spec to_spec(std::span<const vec<D, T>> points, const options<D, T>& opt) {
    const auto end_of = [](const end_condition<D, T>& e) {
        using k = typename end_condition<D, T>::kind;
        end_spec r;
        if (e.type == k::reflect) r.type = end_spec::kind::reflect;
        if (e.type == k::tangent) {
            r.type = end_spec::kind::tangent;
            for (std::size_t c = 0; c < D; ++c) r.velocity.push_back(double(e.velocity[c]));
        }
        return r;
    };
    const auto values = [](const std::vector<T>& v) { return std::vector<double>(v.begin(), v.end()); };
    curve_spec s;
    s.dimension = D;
    s.points.reserve(points.size() * D);
    for (const auto& p : points)
        for (std::size_t k = 0; k < D; ++k) s.points.push_back(double(p[k]));
    s.alpha = opt.alpha;
    if (opt.grid) s.grid = values(*opt.grid);
    s.closed = opt.closed;
    s.start = end_of(opt.start);
    s.end = end_of(opt.end);
    s.tension = double(opt.tension);
    s.kb = {values(opt.kb.tension), values(opt.kb.continuity), values(opt.kb.bias)};
    s.strict = opt.strict;
    return s;
}

/// One end condition by its name, as every front end spells it: "natural"
/// or "reflect" (a tangent is given by its numbers, not by name). `field` is
/// "start" or "end"; any other name is a spec_error naming that field.
inline end_spec end_from_name(const std::string& field, const std::string& name) {
    if (name == "natural") return {};
    if (name == "reflect") return {end_spec::kind::reflect, {}};
    detail::spec_fail(field, std::nullopt, std::nullopt, name,
                      field + " condition must be 'natural', 'reflect' or a tangent, got '" + name + "'");
}

/// Both ends by one name, as the curve file's "end" and Python's
/// `endconditions` spell them: "natural", "reflect" or "closed" (periodic).
inline void set_ends(curve_spec& s, const std::string& name) {
    if (name == "closed") {
        s.closed = true;
        s.start = s.end = {};
        return;
    }
    if (name != "natural" && name != "reflect")
        detail::spec_fail("end", std::nullopt, std::nullopt, name,
                          "end conditions must be 'natural', 'reflect', 'closed' or one for each end, got '" + name +
                              "'");
    s.closed = false;
    s.start = s.end = end_from_name("end", name);
}

}  // namespace crspline
