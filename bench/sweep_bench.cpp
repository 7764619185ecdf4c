// Issue 41: the speed of sweep() against the memory floor and three.js.
//
//   crspline_sweep_bench [--dump-points=FILE] [--repetitions=N]
//
// 1. A tube of 10^6 vertices (a closed (2, 3) torus knot through 48 points,
//    5000 rings of 200: three.js' layout at tubularSegments 4999 and
//    radialSegments 199) by sweep() at those counts, against the memory
//    floor measured in the same run: allocating the same four buffers
//    (positions, normals, uvs, indices) and writing each value once.
// 2. The same tube at an adaptive tolerance, for its vertex count and time.
// Times are the fastest of the repetitions (wall clock, one thread). The
// ratios are printed as JSON on stdout; --dump-points writes the knot's
// points for bench/js/tube_bench.mjs (three.js' TubeGeometry at the same
// counts).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <crspline/sweep.hpp>

namespace {

using clock_type = std::chrono::steady_clock;

std::vector<crspline::vec<3>> knot_points(std::size_t n) {
    std::vector<crspline::vec<3>> pts;
    for (std::size_t k = 0; k < n; ++k) {
        const double a = 2 * std::numbers::pi * double(k) / double(n);
        pts.push_back({{(2 + std::cos(3 * a)) * std::cos(2 * a), (2 + std::cos(3 * a)) * std::sin(2 * a), std::sin(3 * a)}});
    }
    return pts;
}

template <class F>
double fastest(int reps, F&& f) {
    double best = 1e300;
    for (int r = 0; r < reps; ++r) {
        const auto t0 = clock_type::now();
        f();
        best = std::min(best, std::chrono::duration<double>(clock_type::now() - t0).count());
    }
    return best;
}

// What any tube of this size must do: get the four buffers and write every
// value once (a value that depends on the index, so nothing is skipped).
struct floor_buffers {
    std::vector<double> positions, normals, uvs;
    std::vector<std::uint32_t> indices;
};

void write_floor(floor_buffers& b, std::size_t rings, std::size_t ring) {
    const std::size_t n = rings * ring;
    b.positions.resize(3 * n);
    b.normals.resize(3 * n);
    b.uvs.resize(2 * n);
    b.indices.resize(6 * (rings - 1) * (ring - 1));
    for (std::size_t k = 0; k < 3 * n; ++k) b.positions[k] = double(k), b.normals[k] = double(k);
    for (std::size_t k = 0; k < 2 * n; ++k) b.uvs[k] = double(k);
    for (std::size_t k = 0; k < b.indices.size(); ++k) b.indices[k] = std::uint32_t(k);
}

}  // namespace

int main(int argc, char** argv) {
    std::string dump;
    int reps = 7;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a.rfind("--dump-points=", 0) == 0) dump = a.substr(14);
        else if (a.rfind("--repetitions=", 0) == 0) reps = std::max(1, std::atoi(a.c_str() + 14));
    }
    const auto pts = knot_points(48);
    if (!dump.empty()) {
        std::FILE* f = std::fopen(dump.c_str(), "w");
        if (!f) return 2;
        std::fprintf(f, "[");
        for (std::size_t k = 0; k < pts.size(); ++k)
            std::fprintf(f, "%s[%.17g, %.17g, %.17g]", k ? ", " : "", pts[k][0], pts[k][1], pts[k][2]);
        std::fprintf(f, "]\n");
        std::fclose(f);
    }
    crspline::options<3> o;
    o.closed = true;
    const crspline::catmull_rom<3> curve(pts, o);
    const std::size_t tubular = 4999, radial = 199;
    crspline::sweep_options so;
    so.profile = crspline::sweep_profile::circle(0.2);
    so.tubular_segments = tubular;
    so.radial_segments = radial;
    so.clearance = false;
    std::size_t vertices = 0;
    const double t_sweep = fastest(reps, [&] {
        const auto m = crspline::sweep(curve, so);
        vertices = m.positions.size() / 3;
    });
    so.clearance = true;
    const double t_sweep_report = fastest(reps, [&] { (void)crspline::sweep(curve, so); });
    const double t_floor = fastest(reps, [&] {
        floor_buffers b;
        write_floor(b, tubular + 1, radial + 1);
    });
    crspline::sweep_options adaptive;
    adaptive.profile = crspline::sweep_profile::circle(0.2);
    adaptive.tolerance = 1e-4;
    std::size_t adaptive_vertices = 0;
    const double t_adaptive = fastest(reps, [&] { adaptive_vertices = crspline::sweep(curve, adaptive).positions.size() / 3; });
    std::printf("{\"vertices\": %zu, \"sweep_s\": %.6f, \"sweep_with_clearance_s\": %.6f, \"floor_s\": %.6f, "
                "\"sweep_over_floor\": %.3f, \"adaptive_tolerance\": 1e-4, \"adaptive_vertices\": %zu, "
                "\"adaptive_s\": %.6f, \"repetitions\": %d}\n",
                vertices, t_sweep, t_sweep_report, t_floor, t_sweep / t_floor, adaptive_vertices, t_adaptive, reps);
    return 0;
}
