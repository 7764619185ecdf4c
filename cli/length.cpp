// crspline length: the arc length of the whole curve and of each segment.
//
// A curve read from GeoJSON is in WGS 84 longitude and latitude (RFC 7946),
// so its length is in metres on the ellipsoid: the curve, drawn in
// (longitude, latitude), is measured by integrating the ellipsoid's metric
// along it, ds^2 = (M dphi)^2 + (N cos(phi) dlambda)^2, with M and N the
// meridional and transverse radii of curvature from GeographicLib. A piece
// of a meridian is a geodesic, so a curve along one has the geodesic's
// length; heights (a third coordinate) are not counted. Other inputs keep
// their unitless lengths (no "unit" key).
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <GeographicLib/Ellipsoid.hpp>

#include <crspline/arc_length.hpp>

#include "commands.hpp"
#include "dispatch.hpp"
#include "json_input.hpp"

namespace crspline::cli {

namespace {

// Gauss-Kronrod 7-15 nodes and weights on [-1, 1] (the standard table; the
// Gauss weights belong to the odd Kronrod nodes).
constexpr std::array<double, 8> gk_x = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                                        0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                                        0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                                        0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
constexpr std::array<double, 8> gk_wk = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                                         0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                                         0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                                         0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr std::array<double, 4> gk_wg = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                                         0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

struct gk_result {
    double kronrod, gauss;
};

template <class F>
gk_result gauss_kronrod(const F& f, double a, double b) {
    const double c = (a + b) / 2, h = (b - a) / 2;
    gk_result r{gk_wk[7] * f(c), gk_wg[3] * f(c)};
    for (std::size_t i = 0; i < 7; ++i) {
        const double s = f(c - h * gk_x[i]) + f(c + h * gk_x[i]);
        r.kronrod += gk_wk[i] * s;
        if (i % 2 == 1) r.gauss += gk_wg[i / 2] * s;
    }
    return {r.kronrod * h, r.gauss * h};
}

// Adaptive: an interval is accepted when Kronrod and Gauss agree within its
// share of the absolute tolerance. The speed is smooth except where it
// vanishes (a cusp of a non-centripetal curve), which bisection isolates.
template <class F>
double integrate(const F& f, double a, double b, double tol, int depth) {
    const gk_result r = gauss_kronrod(f, a, b);
    if (std::abs(r.kronrod - r.gauss) <= tol || depth == 0 || !(b - a > 1e-14)) return r.kronrod;
    const double m = (a + b) / 2;
    return integrate(f, a, m, tol / 2, depth - 1) + integrate(f, m, b, tol / 2, depth - 1);
}

// Length in metres on WGS 84 of one segment whose first two coordinates are
// longitude and latitude in degrees, to relative accuracy `accuracy`.
template <class Segment>
double ellipsoid_length(const Segment& seg, double accuracy) {
    const GeographicLib::Ellipsoid& e = GeographicLib::Ellipsoid::WGS84();
    constexpr double deg = std::numbers::pi / 180;
    auto speed = [&](double u) {
        const auto p = seg.du(u, 0);
        const auto d = seg.du(u, 1);
        const double lat = p[1];
        const double m = e.MeridionalCurvatureRadius(lat) * d[1] * deg;
        const double n = e.TransverseCurvatureRadius(lat) * std::cos(lat * deg) * d[0] * deg;
        return std::hypot(m, n);
    };
    const double rough = gauss_kronrod(speed, 0, 1).kronrod;
    if (rough == 0) return 0;
    return integrate(speed, 0, 1, accuracy * rough, 60);
}

// A GeoJSON curve: latitudes must be latitudes.
void check_latitudes(const document& input, const curve_spec& spec) {
    const std::size_t d = spec.dimension;
    for (std::size_t i = 0; i * d < spec.points.size(); ++i) {
        const double lat = spec.points[i * d + 1];
        if (!(lat >= -90 && lat <= 90))
            throw input_error((input.file.empty() ? std::string("input") : input.file) + ": " +
                              (input.id.empty() ? std::string() : input.id + ": ") + "point " + std::to_string(i) +
                              ": latitude " + format_number(lat) + " is outside [-90, 90] (GeoJSON is longitude, latitude)");
    }
}

}  // namespace

output_json run_length(const document& input) {
    const length_spec spec = parse_length(input);
    const bool geographic = input.geojson_pointer.has_value();
    if (geographic) check_latitudes(input, spec.curve);
    return with_dimension(spec.curve.dimension, [&](auto dim) {
        constexpr std::size_t D = decltype(dim)::value;
        // One number per segment and their sum: no arc-length table (its
        // pieces and copied segments would be held for every segment at
        // once), and the curve is released before the output is built.
        std::vector<double> segments;
        {
            const catmull_rom<D, double> curve = make_curve<D>(spec.curve);
            if constexpr (D >= 2) {
                if (geographic) {
                    segments.reserve(curve.segment_count());
                    for (const auto& seg : curve.segments()) segments.push_back(ellipsoid_length(seg, spec.accuracy));
                }
            }
            if (!geographic) segments = segment_arc_lengths(curve, spec.accuracy);
        }
        double total = 0;
        for (double len : segments) total += len;
        output_json out;
        out["total"] = total;
        output_json list = output_json::array();
        list.get_ref<output_json::array_t&>().reserve(segments.size());
        for (double len : segments) list.push_back(len);
        segments = {};
        out["segments"] = std::move(list);
        out["accuracy"] = spec.accuracy;
        if (geographic) {
            out["unit"] = "m";
            out["crs"] = "EPSG:4326";
        }
        return out;
    });
}

}  // namespace crspline::cli
