// Bad input: every validation names what is wrong, where, and the value.
#include "test_support.hpp"

#include <cmath>
#include <limits>

namespace {
using namespace crspline;
using P2 = vec<2>;

// Runs f, expects exception E, returns its message.
template <class E, class F>
std::string message_of(F&& f) {
    try {
        f();
    } catch (const E& e) {
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "wrong exception type: " << e.what();
        return {};
    }
    ADD_FAILURE() << "no exception";
    return {};
}

const std::vector<P2> square{P2{{0, 0}}, P2{{1, 0}}, P2{{1, 1}}, P2{{0, 1}}};

TEST(Errors, AlphaOutsideUnitIntervalIsRejectedNotClamped) {
    EXPECT_EQ(message_of<invalid_input>([] { catmull_rom<2> c(square, {.alpha = 1.5}); }),
              "alpha must be in [0, 1], got 1.5");
    EXPECT_EQ(message_of<invalid_input>([] { catmull_rom<2> c(square, {.alpha = -0.25}); }),
              "alpha must be in [0, 1], got -0.25");
    EXPECT_EQ(message_of<invalid_input>([] { catmull_rom<2> c(square, {.alpha = std::nan("")}); }),
              "alpha must be in [0, 1], got nan");
}

TEST(Errors, NonFinitePointNamesIndexAndCoordinate) {
    auto p = square;
    p[2][1] = std::numeric_limits<double>::infinity();
    EXPECT_EQ(message_of<invalid_input>([&] { catmull_rom<2> c(p); }), "point 2, coordinate 1 is not finite (inf)");
    p[2][1] = std::nan("");
    EXPECT_EQ(message_of<invalid_input>([&] { catmull_rom<2> c(p); }), "point 2, coordinate 1 is not finite (nan)");
}

TEST(Errors, TooFewPoints) {
    std::vector<P2> one{P2{{0, 0}}};
    EXPECT_EQ(message_of<invalid_input>([&] { catmull_rom<2> c(one); }), "a curve needs at least 2 points, got 1");
    EXPECT_EQ(message_of<invalid_input>([&] { catmull_rom<2> c(one, {.closed = true}); }),
              "a closed curve needs at least 2 points, got 1");
}

TEST(Errors, Grid) {
    EXPECT_EQ(message_of<invalid_input>([] { catmull_rom<2> c(square, {.grid = std::vector<double>{0, 1, 2}}); }),
              "grid has 3 values, expected 4 (one per point)");
    EXPECT_EQ(message_of<invalid_input>(
                  [] { catmull_rom<2> c(square, {.grid = std::vector<double>{0, 1, 2, 3}, .closed = true}); }),
              "grid has 4 values, expected 5 (one per point plus one: a closed curve repeats the first knot)");
    EXPECT_EQ(message_of<invalid_input>([] { catmull_rom<2> c(square, {.grid = std::vector<double>{0, 1, 1, 3}}); }),
              "grid must be strictly increasing: grid[2] = 1 is not greater than grid[1] = 1");
    EXPECT_EQ(message_of<invalid_input>(
                  [] { catmull_rom<2> c(square, {.grid = std::vector<double>{0, 1, INFINITY, 3}}); }),
              "grid[2] is not finite (inf)");
    EXPECT_EQ(message_of<invalid_input>(
                  [] { catmull_rom<2> c(square, {.alpha = 0.5, .grid = std::vector<double>{0, 1, 2, 3}}); }),
              "give alpha or grid, not both");
}

TEST(Errors, TensionAndKochanekBartels) {
    EXPECT_EQ(message_of<invalid_input>([] { catmull_rom<2> c(square, {.tension = 1.25}); }),
              "tension must be in [0, 1], got 1.25");
    EXPECT_EQ(message_of<invalid_input>([] {
                  catmull_rom<2> c(square, {.kb = {.tension = {0, 0, 0}}});
              }),
              "kb tension has 3 values, expected one per point (4)");
    EXPECT_EQ(message_of<invalid_input>([] {
                  catmull_rom<2> c(square, {.kb = {.bias = {0, 0.5, NAN, 0}}});
              }),
              "kb bias[2] is not finite (nan)");
    // Open curves ignore the end vertices' values: NaN there is accepted.
    EXPECT_NO_THROW((catmull_rom<2>(square, {.kb = {.bias = {NAN, 0.5, 0.25, NAN}}})));
}

TEST(Errors, EndConditions) {
    EXPECT_EQ(message_of<invalid_input>([] {
                  catmull_rom<2> c(square, {.start = end_condition<2>::reflect(), .closed = true});
              }),
              "a closed curve takes no end conditions");
    EXPECT_EQ(message_of<invalid_input>([] {
                  catmull_rom<2> c(square, {.end = end_condition<2>::tangent(P2{{1, NAN}})});
              }),
              "end tangent coordinate 1 is not finite (nan)");
}

TEST(Errors, StrictModeNamesCoincidentIndices) {
    std::vector<P2> p{P2{{0, 0}}, P2{{1, 0}}, P2{{1, 0}}, P2{{2, 1}}, P2{{3, 1}}, P2{{3, 1}}};
    EXPECT_EQ(message_of<invalid_input>([&] { catmull_rom<2> c(p, {.strict = true}); }),
              "coincident consecutive points (strict mode): 1 and 2; 4 and 5");
    // Closed: the wrap-around chord counts too.
    std::vector<P2> q{P2{{0, 0}}, P2{{1, 0}}, P2{{1, 1}}, P2{{0, 0}}};
    EXPECT_EQ(message_of<invalid_input>([&] { catmull_rom<2> c(q, {.closed = true, .strict = true}); }),
              "coincident consecutive points (strict mode): 3 and 0");
    // Uniform knots do not see coincident points: nothing to reject.
    EXPECT_NO_THROW((catmull_rom<2>(p, {.alpha = 0.0, .strict = true})));
    // Without strict, the same input is a valid curve.
    EXPECT_NO_THROW((catmull_rom<2>(p)));
}

TEST(Errors, OutOfDomainNamesValueAndIndex) {
    catmull_rom<2> c(square, {.alpha = 0.0});
    EXPECT_EQ(message_of<out_of_domain>([&] { c.evaluate(3.5); }), "t = 3.5 is outside the domain [0, 3]");
    EXPECT_EQ(message_of<out_of_domain>([&] { c.evaluate(-1e-300); }), "t = -1e-300 is outside the domain [0, 3]");
    EXPECT_EQ(message_of<out_of_domain>([&] { c.evaluate(std::nan("")); }), "t = nan is outside the domain [0, 3]");
    std::vector<double> t{0, 1, 2, 7, 1};
    EXPECT_EQ(message_of<out_of_domain>([&] { c.evaluate(std::span<const double>(t)); }),
              "t = 7 (index 3) is outside the domain [0, 3]");
    // NaN inside an otherwise sorted batch is found and named.
    std::vector<double> tn{0, 0.5, std::nan(""), 2};
    EXPECT_EQ(message_of<out_of_domain>([&] { c.evaluate(std::span<const double>(tn)); }),
              "t = nan (index 2) is outside the domain [0, 3]");
    EXPECT_EQ(message_of<invalid_input>([&] { c.evaluate(1.0, 4); }), "derivative order must be 0, 1, 2 or 3, got 4");
    // The unchecked call extrapolates and never throws.
    EXPECT_TRUE(std::isfinite(c.evaluate_unchecked(3.5)[0]));
}

}  // namespace
