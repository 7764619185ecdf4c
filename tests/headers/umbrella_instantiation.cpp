// Instantiates the main templates of every header through the umbrella:
// catches name clashes between headers (two detail::perpendicular once made
// every analysis call ambiguous when frames.hpp was included too).
#include <crspline/crspline.hpp>
int main() {
    using P = crspline::vec<3>;
    crspline::catmull_rom<3> c({P{{0,0,0}}, P{{1,2,0}}, P{{3,1,1}}, P{{4,0,2}}, P{{5,2,1}}});
    auto a = crspline::analyze(c);
    auto k = crspline::curvature(c, 1.0);
    std::vector<double> t{0.0, 1.0, 2.0};
    auto f = crspline::frenet_frames(c, std::span<const double>(t));
    auto cert = crspline::certify_intersection_free(c);
    auto x = crspline::find_intersections(c);
    return int(a.size() + f.size()) + (k > 0) + cert.certified + int(x.intersections.size());
}
