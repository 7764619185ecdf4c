#include <crspline/crspline.hpp>
#include <cstdio>

int main() {
    using P = crspline::vec<2>;
    const crspline::catmull_rom<2> curve({P{{0, 0}}, P{{1, 2}}, P{{3, 3}}, P{{4, 0}}});  // centripetal, natural ends
    const auto g = curve.grid();                  // knots t(i+1) = t(i) + |P(i+1) - P(i)|^0.5
    const double t = (g[1] + g[2]) / 2;           // halfway through segment 1
    const P x = curve(t), v = curve.evaluate(t, 1), b1 = curve.bezier(1)[1];
    std::printf("knots %.4f %.4f %.4f %.4f\n", g[0], g[1], g[2], g[3]);
    std::printf("x(%.4f) = (%.4f, %.4f), dx/dt = (%.4f, %.4f)\n", t, x[0], x[1], v[0], v[1]);
    std::printf("segment 1 Bezier B1 = (%.4f, %.4f), arc length %.12f\n", b1[0], b1[1], crspline::arc_length(curve));
}
