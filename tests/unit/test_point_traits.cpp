// User point types at the boundary: std::array, Eigen, glm, a struct of one's own.
#include "test_support.hpp"

#include <Eigen/Core>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <vector>

namespace {
struct my_point {
    double xy[2];
    double& operator[](std::size_t i) { return xy[i]; }
    double operator[](std::size_t i) const { return xy[i]; }
};
}  // namespace

template <>
struct crspline::point_traits<my_point> : crspline::subscript_point_traits<my_point, 2, double> {};

namespace {
using namespace crspline;

// Sizes only known at run time cannot be adapted: the traits must know D.
static_assert(!point_like<std::vector<double>>);
static_assert(point_like<std::array<float, 4>>);
static_assert(point_like<Eigen::Vector3d>);
static_assert(!point_like<Eigen::VectorXd>);
static_assert(point_like<glm::dvec2>);
static_assert(dimension_of<glm::vec3> == 3);
static_assert(std::is_same_v<scalar_of<glm::vec3>, float>);
static_assert(dimension_of<Eigen::Vector4f> == 4);

// The same polygon through every adaptor must give the same curve.
const double raw[5][3] = {{0, 0, 0}, {1, 2, 0.5}, {3, 3, 1}, {4, 1, 0}, {6, 2, -1}};

template <class P, std::size_t D>
std::vector<P> make_points() {
    std::vector<P> v;
    for (const auto& r : raw) {
        std::array<typename point_traits<P>::scalar, D> c{};
        for (std::size_t k = 0; k < D; ++k) c[k] = static_cast<typename point_traits<P>::scalar>(r[k]);
        v.push_back(point_traits<P>::make(c));
    }
    return v;
}

template <std::size_t D>
catmull_rom<D> reference() {
    std::vector<vec<D>> v;
    for (const auto& r : raw) {
        vec<D> p;
        for (std::size_t k = 0; k < D; ++k) p[k] = r[k];
        v.push_back(p);
    }
    return catmull_rom<D>(v);
}

TEST(PointTraits, StdArrayEigenGlmAndCustomStructAgree) {
    const auto ref2 = reference<2>();
    const auto ref3 = reference<3>();
    auto c_arr = make_catmull_rom(make_points<std::array<double, 3>, 3>());
    auto c_eig = make_catmull_rom(make_points<Eigen::Vector3d, 3>());
    auto c_glm = make_catmull_rom(make_points<glm::dvec2, 2>());
    auto c_own = make_catmull_rom(make_points<my_point, 2>());
    static_assert(std::is_same_v<decltype(c_eig), catmull_rom<3, double>>);
    static_assert(std::is_same_v<decltype(c_own), catmull_rom<2, double>>);
    int checked = 0;
    for (double t = ref3.t_min(); t <= ref3.t_max(); t += 0.25) {
        EXPECT_EQ(c_arr.evaluate(t), ref3.evaluate(t));
        EXPECT_EQ(c_eig.evaluate(t), ref3.evaluate(t));
        ++checked;
    }
    for (double t = ref2.t_min(); t <= ref2.t_max(); t += 0.25) {
        EXPECT_EQ(c_glm.evaluate(t), ref2.evaluate(t));
        EXPECT_EQ(c_own.evaluate(t), ref2.evaluate(t));
    }
    EXPECT_GT(checked, 10);
    // Results come back as the user's type.
    const Eigen::Vector3d e = c_eig.evaluate_as<Eigen::Vector3d>(c_eig.t_max());
    EXPECT_EQ(e.x(), 6.0);
    const my_point q = c_own.evaluate_as<my_point>(c_own.t_min());
    EXPECT_EQ(q[1], 0.0);
    const glm::dvec2 g = c_glm.evaluate_as<glm::dvec2>(c_glm.grid()[1]);
    EXPECT_EQ(g.y, 2.0);
}

TEST(PointTraits, FloatPointsMakeAFloatCurve) {
    auto c = make_catmull_rom(make_points<glm::vec3, 3>());
    static_assert(std::is_same_v<decltype(c), catmull_rom<3, float>>);
    const auto ref = reference<3>();
    // float knots and coefficients: agreement to a few float ulps of the scale (~7).
    for (std::size_t i = 0; i < 5; ++i) {
        const auto a = c.evaluate(c.grid()[i]);
        const auto b = ref.evaluate(ref.grid()[i]);
        for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 8 * 7 * 1.2e-7);
    }
}

}  // namespace
