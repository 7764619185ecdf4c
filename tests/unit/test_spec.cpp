// The run-time curve specification (spec.hpp): validated by the same code as
// catmull_rom's constructor, with structured errors, and building the same
// curve as the compile-time API.
#include "test_support.hpp"

#include <crspline/arc_length.hpp>
#include <crspline/dispatch.hpp>
#include <crspline/spec.hpp>

#include <cmath>
#include <functional>
#include <string>

namespace {
using namespace crspline;

struct caught {
    std::string what, field, value;
    std::optional<std::size_t> index, component;
};

caught catch_spec_error(const std::function<void()>& f) {
    try {
        f();
    } catch (const spec_error& e) {
        return {e.what(), e.field(), e.value(), e.index(), e.component()};
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not a spec_error: " << e.what();
        return {};
    }
    ADD_FAILURE() << "no exception";
    return {};
}

curve_spec square_spec() {
    curve_spec s;
    s.dimension = 2;
    s.points = {0, 0, 1, 0, 1, 1, 0, 1};
    return s;
}

TEST(Spec, StructuredErrorsNameFieldIndexAndValue) {
    auto s = square_spec();
    s.points[5] = NAN;  // point 2, coordinate 1
    auto e = catch_spec_error([&] { validate(s); });
    EXPECT_EQ(e.what, "point 2, coordinate 1 is not finite (nan)");
    EXPECT_EQ(e.field, "points");
    EXPECT_EQ(e.index, 2u);
    EXPECT_EQ(e.component, 1u);
    EXPECT_EQ(e.value, "nan");

    s = square_spec();
    s.grid = std::vector<double>{0, 1, 1, 3};
    e = catch_spec_error([&] { validate(s); });
    EXPECT_EQ(e.what, "grid must be strictly increasing: grid[2] = 1 is not greater than grid[1] = 1");
    EXPECT_EQ(e.field, "grid");
    EXPECT_EQ(e.index, 2u);

    s = square_spec();
    s.alpha = 1.5;
    e = catch_spec_error([&] { validate(s); });
    EXPECT_EQ(e.what, "alpha must be in [0, 1], got 1.5");
    EXPECT_EQ(e.field, "alpha");
    EXPECT_EQ(e.value, "1.5");

    s = square_spec();
    s.kb.bias = {0, 0.5, NAN, 0};
    e = catch_spec_error([&] { validate(s); });
    EXPECT_EQ(e.what, "kb bias[2] is not finite (nan)");
    EXPECT_EQ(e.field, "kb.bias");
    EXPECT_EQ(e.index, 2u);

    s = square_spec();
    s.end = {end_spec::kind::tangent, {1}};
    e = catch_spec_error([&] { validate(s); });
    EXPECT_EQ(e.what, "end tangent has 1 coordinates, expected 2 like the points");
    EXPECT_EQ(e.field, "end");

    s = square_spec();
    s.dimension = 17;
    e = catch_spec_error([&] { validate(s); });
    EXPECT_EQ(e.what, "dimension must be 1 to 16, got 17");
    EXPECT_EQ(e.field, "dimension");

    s = square_spec();
    s.dimension = 3;
    e = catch_spec_error([&] { validate(s); });
    EXPECT_EQ(e.what, "points has 8 coordinates, not a whole number of points of dimension 3");
}

// The same bad description gives the same error, word for word, through
// validate(curve_spec) and through catmull_rom's constructor: one copy of
// the validation, not two.
TEST(Spec, SameWordsAsTheConstructor) {
    std::vector<std::function<void(curve_spec&)>> breakages = {
        [](curve_spec& s) { s.points.resize(2); },
        [](curve_spec& s) { s.closed = true, s.points.resize(2); },
        [](curve_spec& s) { s.points[3] = INFINITY; },
        [](curve_spec& s) { s.alpha = -0.25; },
        [](curve_spec& s) { s.alpha = 0.5, s.grid = std::vector<double>{0, 1, 2, 3}; },
        [](curve_spec& s) { s.grid = std::vector<double>{0, 1, 2}; },
        [](curve_spec& s) { s.closed = true, s.grid = std::vector<double>{0, 1, 2, 3}; },
        [](curve_spec& s) { s.grid = std::vector<double>{0, 1, NAN, 3}; },
        [](curve_spec& s) { s.tension = 1.25; },
        [](curve_spec& s) { s.closed = true, s.start.type = end_spec::kind::reflect; },
        [](curve_spec& s) { s.end = {end_spec::kind::tangent, {1, NAN}}; },
        [](curve_spec& s) { s.kb.tension = {0, 0, 0}; },
        [](curve_spec& s) { s.kb.continuity = {0, NAN, 0, 0}; },
        [](curve_spec& s) { s.strict = true, s.points = {0, 0, 1, 0, 1, 0, 2, 1}; },
    };
    for (std::size_t i = 0; i < breakages.size(); ++i) {
        SCOPED_TRACE("breakage " + std::to_string(i));
        auto s = square_spec();
        breakages[i](s);
        const auto via_spec = catch_spec_error([&] { (void)make_curve<2>(s); });
        const auto via_core = catch_spec_error([&] {
            std::vector<vec<2>> pts(s.point_count());
            for (std::size_t k = 0; k < pts.size(); ++k) pts[k] = vec<2>{{s.points[2 * k], s.points[2 * k + 1]}};
            catmull_rom<2> c(std::span<const vec<2>>(pts), to_options<2>(s));
        });
        EXPECT_FALSE(via_spec.what.empty());
        EXPECT_EQ(via_spec.what, via_core.what);
        EXPECT_EQ(via_spec.field, via_core.field);
        EXPECT_EQ(via_spec.index, via_core.index);
    }
    // Ignored end values of an open curve: NaN accepted by both.
    auto s = square_spec();
    s.kb.bias = {NAN, 0.5, 0.25, NAN};
    EXPECT_NO_THROW(validate(s));
    EXPECT_NO_THROW((void)make_curve<2>(s));
}

// A 7-D specification builds the same curve as catmull_rom<7> from the
// compile-time API, bit for bit, and to_spec() inverts make_curve().
TEST(Spec, SevenDimensionsBuildTheCompileTimeCurve) {
    std::vector<vec<7>> pts;
    for (int i = 0; i < 6; ++i) {
        vec<7> p;
        for (int k = 0; k < 7; ++k) p[std::size_t(k)] = std::sin(0.7 * i + 1.3 * k) * (k + 1);
        pts.push_back(p);
    }
    options<7> opt;
    opt.alpha = 0.3;
    opt.tension = 0.25;
    opt.start = end_condition<7>::reflect();
    const curve_spec s = to_spec(std::span<const vec<7>>(pts), opt);
    EXPECT_EQ(s.dimension, 7u);
    EXPECT_EQ(s.point_count(), 6u);
    const auto a = make_curve<7>(s);
    const catmull_rom<7> b(std::span<const vec<7>>(pts), opt);
    for (double t = a.t_min(); t <= a.t_max(); t += 0.01)
        for (int order = 0; order <= 3; ++order) EXPECT_EQ(a.evaluate(t, order), b.evaluate(t, order));
    EXPECT_THROW((void)make_curve<3>(s), spec_error);  // never cut to fewer coordinates
}

// Dimensions 5..16 run as one wide curve of 16 coordinates, zero-padded
// (dispatch.hpp): its first 7 coordinates are catmull_rom<7>'s, bit for bit,
// for positions, derivatives, knots, Bezier points and arc length.
TEST(Spec, PaddedWideCurveGivesTheSameNumbers) {
    static_assert(storage_dimension(7) == wide_dimension && storage_dimension(3) == 3);
    curve_spec s;
    s.dimension = 7;
    for (int i = 0; i < 9; ++i)
        for (int k = 0; k < 7; ++k) s.points.push_back(std::cos(0.9 * i - 0.4 * k) * (1 + k % 3) + 0.1 * i);
    s.end = {end_spec::kind::tangent, {1, -2, 0.5, 0, 3, 1, -1}};
    s.kb.bias = {0, 0.25, -0.5, 0, 0, 0.1, 0, 0.3, 0};
    const auto narrow = make_curve<7>(s);
    const auto wide = make_curve<wide_dimension>(s);
    ASSERT_EQ(narrow.segment_count(), wide.segment_count());
    for (std::size_t i = 0; i < narrow.grid().size(); ++i) EXPECT_EQ(narrow.grid()[i], wide.grid()[i]);
    for (double t = narrow.t_min(); t <= narrow.t_max(); t += 0.003)
        for (int order = 0; order <= 3; ++order) {
            const auto a = narrow.evaluate(t, order);
            const auto b = wide.evaluate(t, order);
            for (std::size_t k = 0; k < 7; ++k) ASSERT_EQ(a[k], b[k]) << "t " << t << " order " << order;
            for (std::size_t k = 7; k < wide_dimension; ++k) ASSERT_EQ(b[k], 0.0);
        }
    for (std::size_t i = 0; i < narrow.segment_count(); ++i)
        for (std::size_t j = 0; j < 4; ++j)
            for (std::size_t k = 0; k < 7; ++k) EXPECT_EQ(narrow.bezier(i)[j][k], wide.bezier(i)[j][k]);
    EXPECT_EQ(arc_length_table<7>(narrow, 1e-12).total(), arc_length_table<wide_dimension>(wide, 1e-12).total());
    // Narrower than the specification: refused, never cut.
    EXPECT_EQ(catch_spec_error([&] { (void)make_curve<4>(s); }).what,
              "dimension is 7, more than the 4 of the curve type");
}

}  // namespace
