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

namespace {

// Issue 31 point 3: finite coordinates whose chord, knots, tangents or Bezier
// points overflow are refused at construction, naming the points (field
// "points", the first point's index), in every alpha, open and closed.
TEST(Errors, OverflowIsRefusedNamingThePoints) {
    const auto refusal = [](auto&& make) -> std::pair<std::string, std::optional<std::size_t>> {
        try {
            make();
        } catch (const spec_error& e) {
            EXPECT_EQ(e.field(), "points") << e.what();
            return {e.what(), e.index()};
        } catch (const std::exception& e) {
            ADD_FAILURE() << "wrong exception type: " << e.what();
            return {};
        }
        ADD_FAILURE() << "no exception";
        return {};
    };
    // The case: |P1 - P0| = 3e308.
    const std::vector<P2> wide{P2{{-1.5e308, 0}}, P2{{1.5e308, 0}}};
    for (const double alpha : {0.0, 0.25, 0.5, 0.75, 1.0})
        for (const bool closed : {false, true}) {
            const auto [msg, index] = refusal([&] { catmull_rom<2> c(wide, {.alpha = alpha, .closed = closed}); });
            EXPECT_EQ(msg, "points 0 and 1: the chord between them overflows (|P1 - P0| is not finite)")
                << "alpha " << alpha << (closed ? " closed" : " open");
            EXPECT_EQ(index, std::optional<std::size_t>(0));
        }
    // Components finite, length not (|(-1.6e308, 1.6e308)| = 2.3e308), on the
    // second chord; and on the closing chord of a closed curve.
    const std::vector<P2> diagonal{P2{{0, 0}}, P2{{1.6e308, 0}}, P2{{0, 1.6e308}}};
    EXPECT_EQ(refusal([&] { catmull_rom<2> c(diagonal, {.alpha = 1.0}); }).first,
              "points 1 and 2: the chord between them overflows (|P2 - P1| is not finite)");
    const std::vector<P2> ring{P2{{0, 1.6e308}}, P2{{0, 0}}, P2{{1.6e308, 0}}};
    EXPECT_EQ(refusal([&] { catmull_rom<2> c(ring, {.closed = true}); }).first,
              "points 2 and 0: the chord between them overflows (|P0 - P2| is not finite)");
    // A sum of finite chordal intervals (1e307 each) passes the largest double
    // at the 18th knot.
    std::vector<P2> zigzag;
    for (int i = 0; i < 30; ++i) zigzag.push_back(P2{{i % 2 ? 1e307 : 0.0, 0}});
    EXPECT_EQ(refusal([&] { catmull_rom<2> c(zigzag, {.alpha = 1.0}); }).first,
              "points 17 and 18: the knot t(18) overflows (the sum of the intervals up to it is inf)");
    // A given grid whose difference overflows.
    const std::vector<P2> two{P2{{0, 0}}, P2{{1, 0}}};
    EXPECT_EQ(refusal([&] { catmull_rom<2> c(two, {.grid = std::vector<double>{-1e308, 1e308}}); }).first,
              "points 0 and 1: the knot interval between them overflows (t(1) - t(0) = inf)");
    // Tangents: 1e-300 then 1e10 of grid makes the chord velocity 1e300 and
    // its weight 1e10 (dx/dt overflows at vertex 1, the natural end's at 0).
    const std::vector<P2> three{P2{{0, 0}}, P2{{1, 0}}, P2{{2, 0}}};
    EXPECT_EQ(refusal([&] { catmull_rom<2> c(three, {.grid = std::vector<double>{0, 1e-300, 1e10}}); }).first,
              "point 0: the tangent there overflows (dx/dt is not finite)");
    // Bezier points: given tangents of 1e308 on an interval of 10.
    const std::vector<P2> tangents{P2{{1e308, 0}}, P2{{1e308, 0}}};
    const std::vector<double> grid{0, 10};
    const auto [hmsg, hindex] = refusal([&] {
        (void)catmull_rom<2>::hermite(std::span<const P2>(two), std::span<const P2>(tangents),
                                      std::span<const double>(grid));
    });
    EXPECT_EQ(hmsg, "points 0 and 1: the segment between them overflows (its Bezier points or coefficients are "
                    "not finite)");
    EXPECT_EQ(hindex, std::optional<std::size_t>(0));
}

// Near the top of the range, either the curve is refused (a spec_error on
// "points") or everything it gives is finite: positions and first
// derivatives, Bezier points, knots, arc length. Seeded random polygons
// scaled from 1e290 to 1e308 (double) and 1e30 to 1e38 (float); both
// outcomes must occur, or the test checked only one side.
template <class T>
void refused_or_finite(std::uint64_t seed, int lo_exp, int hi_exp, int& accepted, int& refused, int& overflowed) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> e(lo_exp, hi_exp);
    std::uniform_real_distribution<double> a(0, 1);
    for (int trial = 0; trial < 200; ++trial) {
        const T scale = T(std::pow(10.0, e(rng)));
        auto p = test::random_polygon<2, T>(rng, 3 + std::size_t(trial % 6), 1.0);
        for (auto& x : p) x = x * scale;
        const bool closed = trial % 4 == 3;
        const double alpha = trial % 5 == 0 ? 0.0 : a(rng);
        bool ok = true;
        std::optional<catmull_rom<2, T>> c;
        try {
            c.emplace(std::span<const vec<2, T>>(p), options<2, T>{.alpha = alpha, .closed = closed});
        } catch (const spec_error& err) {
            EXPECT_EQ(err.field(), "points") << err.what();
            // (The others: a coordinate scaled past the largest double.)
            if (std::string(err.what()).find("overflows") != std::string::npos) ++overflowed;
            ok = false;
        }
        if (!ok) {
            ++refused;
            continue;
        }
        ++accepted;
        const auto all_finite = [](const vec<2, T>& x) { return std::isfinite(x[0]) && std::isfinite(x[1]); };
        for (std::size_t i = 0; i < c->segment_count(); ++i) {
            for (const auto& b : c->bezier(i)) EXPECT_TRUE(all_finite(b)) << "segment " << i << " trial " << trial;
            for (int k = 0; k <= 8; ++k) {
                const T t = std::min(c->grid()[i] + (c->grid()[i + 1] - c->grid()[i]) * T(k) / T(8), c->grid().back());
                EXPECT_TRUE(all_finite(c->evaluate(t))) << "t " << t << " trial " << trial;
                EXPECT_TRUE(all_finite(c->segment(i).du(T(k) / T(8), 1))) << "t " << t << " trial " << trial;
            }
        }
        EXPECT_TRUE(std::isfinite(c->grid().back())) << "trial " << trial;
    }
}

TEST(Errors, NearTheTopOfTheRangeACurveIsRefusedOrFinite) {
    CRSPLINE_SEEDED(seed, 3103);
    int accepted = 0, refused = 0, overflowed = 0;
    refused_or_finite<double>(seed, 290, 308, accepted, refused, overflowed);
    refused_or_finite<float>(seed, 30, 38, accepted, refused, overflowed);
    EXPECT_EQ(accepted + refused, 400);
    std::printf("near the top of the range: %d accepted, %d refused (%d for an overflow)\n", accepted, refused,
                overflowed);
    EXPECT_GT(accepted, 20);
    EXPECT_GT(refused, 20);
    EXPECT_GT(overflowed, 5);
}

}  // namespace
