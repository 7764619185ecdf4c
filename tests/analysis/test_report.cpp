// The analysis report (report.hpp, docs/report.md) written through a
// builder: its values are the analysis' own (u to t exactly as documented),
// a wide curve writes only its input's coordinates and the same numbers as
// the curve of that dimension, float and double curves write the same keys,
// and what was not run is null.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "json_tree_builder.hpp"

#include <crspline/report.hpp>
#include <crspline/spec.hpp>

namespace {

using ojson = nlohmann::ordered_json;

using json_builder = crspline_test::json_tree_builder;
static_assert(crspline::report_builder<json_builder>);

template <std::size_t D, class T>
ojson report_of(const crspline::catmull_rom<D, T>& c, const crspline::report_options& o = {},
               std::size_t dimension = D) {
    json_builder b;
    return crspline::report(b, crspline::make_report(c, o, dimension));
}

// Keys of a tree, recursively, in order (values left out).
ojson keys_of(const ojson& j) {
    if (j.is_object()) {
        ojson out = ojson::object();
        for (auto it = j.begin(); it != j.end(); ++it) out[it.key()] = keys_of(it.value());
        return out;
    }
    if (j.is_array() && !j.empty()) return ojson::array({keys_of(j[0])});
    return nullptr;
}

using V2 = crspline::vec<2, double>;
// A short edge between two long ones: the uniform curve loops in segment 1.
const std::vector<V2> loop_points{{{0, 0}}, {{1, 1}}, {{1.1, 1}}, {{2, 0}}};

TEST(Report, ValuesAreTheAnalysisOwn) {
    crspline::options<2> o;
    o.alpha = 0.0;
    const crspline::catmull_rom<2> c(loop_points, o);
    const ojson r = report_of(c);
    const auto a = crspline::analyze(c);
    const auto grid = c.grid();
    ASSERT_EQ(r["segments"].size(), a.size());
    const auto& loop = a[1].self_intersection;
    ASSERT_EQ(loop.size(), 1u);
    const ojson& s = r["segments"][1];
    EXPECT_EQ(s["self_intersection_u"][0][0].get<double>(), loop[0][0]);
    EXPECT_EQ(s["self_intersection_u"][0][1].get<double>(), loop[0][1]);
    // t = t_i + u (t_(i+1) - t_i), as docs/report.md says.
    EXPECT_EQ(s["self_intersection_t"][0][0].get<double>(), grid[1] + loop[0][0] * (grid[2] - grid[1]));
    EXPECT_EQ(s["distance_bound"].get<double>(), a[1].bounds->eq6);
    EXPECT_TRUE(r["segments"][0]["bounds"].is_null());
    EXPECT_EQ(s["bezier"][3], ojson::array({1.1, 1.0}));
    EXPECT_TRUE(r["has_self_intersection"].get<bool>());
    ASSERT_EQ(r["intersections"].size(), 1u);
    EXPECT_EQ(r["intersections"][0]["segments"], ojson::array({1, 1}));
    EXPECT_EQ(r["certificate"]["failed_rule"], "not_centripetal");
    EXPECT_EQ(r["certificate"]["intersects"], true);
    EXPECT_TRUE(r["certificate"]["search"].is_null());
}

TEST(Report, WhatWasNotRunIsNull) {
    const crspline::catmull_rom<2> c(loop_points);
    crspline::report_options o;
    o.search = false;
    o.certify = false;
    const ojson r = report_of(c, o);
    EXPECT_TRUE(r["intersections"].is_null() && r["overlaps"].is_null() && r["folds"].is_null() &&
                r["complete"].is_null());
    EXPECT_TRUE(r["certificate"].is_null());
    // The keys stay, in the same order.
    const ojson full = report_of(c);
    std::vector<std::string> a, b;
    for (auto it = r.begin(); it != r.end(); ++it) a.push_back(it.key());
    for (auto it = full.begin(); it != full.end(); ++it) b.push_back(it.key());
    EXPECT_EQ(a, b);
}

TEST(Report, FloatAndDoubleWriteTheSameKeys) {
    const std::vector<crspline::vec<2, float>> pf{{{0, 0}}, {{1, 1}}, {{1.1f, 1}}, {{2, 0}}};
    crspline::options<2, float> of;
    of.alpha = 0.0;
    crspline::options<2> od;
    od.alpha = 0.0;
    EXPECT_EQ(keys_of(report_of(crspline::catmull_rom<2, float>(pf, of))),
              keys_of(report_of(crspline::catmull_rom<2>(loop_points, od))));
}

TEST(Report, AWideCurveWritesItsOwnCoordinatesAndNumbers) {
    // 7-D, through the zero-padded 16-D curve the front ends use, against
    // catmull_rom<7>: the same tree, number for number.
    crspline::curve_spec s;
    s.dimension = 7;
    for (int k = 0; k < 5; ++k)
        for (int j = 0; j < 7; ++j) s.points.push_back(double((k * (j + 1)) % 5) + 0.25 * j);
    const ojson wide = report_of(crspline::make_curve<16>(s), {}, 7);
    const ojson own = report_of(crspline::make_curve<7>(s));
    EXPECT_EQ(wide["dimension"], 7);
    EXPECT_EQ(wide["segments"][0]["bezier"][0].size(), 7u);
    EXPECT_EQ(wide, own);
}

}  // namespace
