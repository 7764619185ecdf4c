// The per-segment analysis against the 50-digit oracle (tests/reference/
// oracle.json): classification exactly, distances and Bézier points to
// 1e-13 of the local scale, the two-sided Eq. 6 bound, the projected
// derivative and the curvature.
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include <crspline/analysis.hpp>

#include "test_support.hpp"

namespace {
using namespace crspline;
using json = nlohmann::json;

json load_oracle() {
    std::ifstream in(std::string(CRSPLINE_REFERENCE_DIR) + "/oracle.json");
    EXPECT_TRUE(in.good()) << "cannot open oracle.json";
    return json::parse(in);
}

template <std::size_t D>
vec<D> to_point(const json& j) {
    vec<D> p;
    for (std::size_t k = 0; k < D; ++k) p[k] = j.at(k).get<double>();
    return p;
}

// Number of checks made, so the test can assert it looked at everything.
struct counts {
    std::size_t cases = 0, classifications = 0, distances = 0, bounds = 0, curvatures = 0;
};

template <std::size_t D>
void check_case(const json& c, counts& n) {
    const std::string name = c.at("name");
    SCOPED_TRACE(name);
    std::array<vec<D>, 4> p;
    for (std::size_t i = 0; i < 4; ++i) p[i] = to_point<D>(c.at("points").at(i));
    const double alpha = c.at("alpha"), tension = c.at("tension");
    const auto a = analyze_segment(p, alpha, tension);
    // Local scale: the size of the configuration around P1 (not its offset).
    double scale = 0;
    for (const auto& q : p) scale = std::max(scale, norm(q - p[1]));
    const double tol = 1e-13 * std::max(scale, 1e-300);

    // Bézier points.
    for (std::size_t k = 0; k < 4; ++k)
        EXPECT_LE(norm(a.bezier[k] - to_point<D>(c.at("bezier").at(k))), tol) << "B" << k;

    // Classification: exactly.
    EXPECT_EQ(a.has_cusp(), c.at("has_cusp").get<bool>());
    EXPECT_EQ(a.has_self_intersection(), c.at("has_self_intersection").get<bool>());
    EXPECT_EQ(a.fold, c.at("fold_1d").get<bool>());
    EXPECT_EQ(a.rank, c.at("rank").get<std::size_t>());
    const auto zs = c.at("zero_speed_u").get<std::vector<double>>();
    ASSERT_EQ(a.zero_speed_u.size(), zs.size());
    for (std::size_t k = 0; k < zs.size(); ++k) EXPECT_NEAR(a.zero_speed_u[k], zs[k], 1e-12);
    const auto cu = c.at("cusp_u").get<std::vector<double>>();
    ASSERT_EQ(a.cusp_u.size(), cu.size());
    for (std::size_t k = 0; k < cu.size(); ++k) EXPECT_NEAR(a.cusp_u[k], cu[k], 1e-12);
    const auto si = c.at("self_intersection_uv");
    ASSERT_EQ(a.self_intersection.size(), si.size());
    for (std::size_t k = 0; k < si.size(); ++k) {
        // The loop parameters solve a quadratic: accurate to ~1e-15 here.
        EXPECT_NEAR(a.self_intersection[k][0], si[k][0].get<double>(), 1e-12);
        EXPECT_NEAR(a.self_intersection[k][1], si[k][1].get<double>(), 1e-12);
    }
    ++n.classifications;

    // Measured distances: exact critical points, to 1e-13 of the scale.
    EXPECT_NEAR(a.max_chord_line_distance, c.at("max_dist_to_chord_line").get<double>(), tol);
    EXPECT_NEAR(a.max_chord_distance, c.at("max_dist_to_chord_segment").get<double>(), tol);
    ++n.distances;

    // Eq. 6, two-sided; null in the oracle exactly where the paper's
    // formulas do not apply (tension, a zero edge or interval).
    if (c.at("eq6_bound_two_sided").is_null()) {
        EXPECT_FALSE(a.bounds.has_value());
    } else {
        ASSERT_TRUE(a.bounds.has_value());
        const double e6 = c.at("eq6_bound_two_sided");
        EXPECT_NEAR(a.bounds->eq6, e6, 1e-14 * e6);
        ++n.bounds;
    }

    // Projected derivative and chord projection range (dimensionless).
    if (c.at("projected_derivative_min").is_null()) {
        EXPECT_FALSE(a.projection.has_value() && a.rank > 0);
    } else {
        ASSERT_TRUE(a.projection.has_value());
        const double pd = c.at("projected_derivative_min");
        // lambda' is a ratio of the coefficients to the chord: its rounding
        // grows with the ratio |c| / |chord| (1e6 for the extreme cases).
        const double ptol = 1e-13 * std::max({1.0, std::abs(pd), std::abs(c.at("chord_projection_range")[0].get<double>()),
                                              std::abs(c.at("chord_projection_range")[1].get<double>())});
        EXPECT_NEAR(a.projection->derivative_min, pd, ptol);
        EXPECT_NEAR(a.projection->range[0], c.at("chord_projection_range")[0].get<double>(), ptol);
        EXPECT_NEAR(a.projection->range[1], c.at("chord_projection_range")[1].get<double>(), ptol);
    }

    // Curvature at the oracle's u values (null where the speed is zero).
    const auto us = c.at("u").get<std::vector<double>>();
    const cubic_segment<D>& seg = a.segment;
    for (std::size_t k = 0; k < us.size(); ++k) {
        const auto& want = c.at("curvature").at(k);
        const auto got = curvature(seg, us[k]);
        if (want.is_null()) {
            EXPECT_FALSE(got.has_value() && a.rank > 0) << "u = " << us[k];
        } else {
            ASSERT_TRUE(got.has_value()) << "u = " << us[k];
            // Conditioning of |C' x C''| / |C'|^3: absolute error about eps
            // |C''| / |C'|^2 (cancellation in the cross product).
            const double sp = norm(seg.du(us[k], 1));
            const double ctol = 1e-11 * want.get<double>() + 1e-12 * norm(seg.du(us[k], 2)) / (sp * sp);
            EXPECT_NEAR(*got, want.get<double>(), ctol) << "u = " << us[k];
        }
        ++n.curvatures;
    }
    ++n.cases;
}

TEST(SegmentOracle, MatchesEveryCase) {
    const json o = load_oracle();
    counts n;
    for (const auto& c : o.at("cases")) {
        switch (c.at("dim").get<int>()) {
            case 1: check_case<1>(c, n); break;
            case 2: check_case<2>(c, n); break;
            case 3: check_case<3>(c, n); break;
            case 4: check_case<4>(c, n); break;
            default: ADD_FAILURE() << "unexpected dimension";
        }
    }
    EXPECT_EQ(n.cases, 38u);
    EXPECT_EQ(n.classifications, 38u);
    EXPECT_EQ(n.distances, 38u);
    EXPECT_GE(n.bounds, 25u);
    EXPECT_EQ(n.curvatures, 38u * 5);
}

}  // namespace
