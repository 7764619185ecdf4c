// crspline fit benchmark (issue 40): counts against Ramer-Douglas-Peucker
// and speed on the real corpus (tests/reference/fit: DEM contours traced by
// marching squares at half a grid cell, NYC borough outlines at half their
// vertex spacing), and the time's growth with the input: one long line of
// concatenated DEM contours, 10^4 points up to --max; one period of a sine
// sampled 4,000 times up to --dense-max, whose segments cover more points
// the more there are. Thread CPU time. Run bench/js/fit_peers.mjs for the
// peers (simplify-js, paper.js) on the same lines.
//
//   crspline_fit_bench [--corpus DIR] [--max N] [--free-max N] [--dense-max N]
#include <time.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <crspline/fit.hpp>

#include "../tests/fit/fit_corpus.hpp"

namespace {

double thread_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

struct totals {
    std::size_t lines = 0, points = 0, rdp = 0, fit = 0, within = 0, tensioned = 0;
    double seconds = 0, worst = 0;
};

totals run(const std::vector<fit_corpus::line>& lines, crspline::fit_mode mode) {
    totals t;
    for (const auto& l : lines) {
        crspline::fit_options<2> o;
        o.tolerance = l.tolerance;
        o.closed = l.closed;
        o.mode = mode;
        const double t0 = thread_seconds();
        const auto r = crspline::fit(l.points, o);
        t.seconds += thread_seconds() - t0;
        t.points += l.points.size();
        t.fit += r.count;
        t.tensioned += r.tensioned;
        t.within += r.deviation <= l.tolerance;
        t.worst = std::max(t.worst, r.deviation / l.tolerance);
        t.rdp += fit_corpus::rdp(l.points, l.tolerance, l.closed).size();
        ++t.lines;
    }
    return t;
}

/// One row of a growth table: the fit of p timed, printed, and its
/// log(n), log(time) kept for the exponent.
void growth_row(const std::vector<crspline::vec<2>>& p, double tolerance, crspline::fit_mode mode,
                std::vector<double>& lx, std::vector<double>& ly) {
    crspline::fit_options<2> o;
    o.tolerance = tolerance;
    o.mode = mode;
    const double t0 = thread_seconds();
    const auto r = crspline::fit(p, o);
    const double s = thread_seconds() - t0;
    std::printf("%-7s %9zu  %9.3f  %9.0f   (%zu control points)\n", mode == crspline::fit_mode::free ? "free" : "subset",
                p.size(), s, double(p.size()) / s, r.count);
    lx.push_back(std::log(double(p.size())));
    ly.push_back(std::log(s));
}

/// The least-squares slope of log(time) against log(n).
void print_exponent(crspline::fit_mode mode, const std::vector<double>& lx, const std::vector<double>& ly) {
    if (lx.size() < 2) return;
    double mx = 0, my = 0;
    for (std::size_t i = 0; i < lx.size(); ++i) mx += lx[i], my += ly[i];
    mx /= double(lx.size()), my /= double(ly.size());
    double sxy = 0, sxx = 0;
    for (std::size_t i = 0; i < lx.size(); ++i) sxy += (lx[i] - mx) * (ly[i] - my), sxx += (lx[i] - mx) * (lx[i] - mx);
    std::printf("%-7s fitted exponent (time ~ n^k): k = %.3f\n", mode == crspline::fit_mode::free ? "free" : "subset",
                sxy / sxx);
}

}  // namespace

int main(int argc, char** argv) {
    std::setvbuf(stdout, nullptr, _IOLBF, 0);  // each line as it is measured
    std::string dir = CRSPLINE_FIT_CORPUS_DIR;
    std::size_t max_n = 1000000, free_max = 100000, dense_max = 64000;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--corpus") dir = argv[i + 1];
        else if (a == "--max") max_n = std::size_t(std::atof(argv[i + 1]));
        else if (a == "--free-max") free_max = std::size_t(std::atof(argv[i + 1]));
        else if (a == "--dense-max") dense_max = std::size_t(std::atof(argv[i + 1]));
        else {
            std::fprintf(stderr, "usage: crspline_fit_bench [--corpus DIR] [--max N] [--free-max N] [--dense-max N]\n");
            return 2;
        }
    }
    // 1. Counts and speed on the corpus, line by line.
    std::printf("corpus                 mode    lines  points   rdp     fit     fit/rdp  tensioned  "
                "deviation/tol  points/s\n");
    for (const char* file : {"dem_jacksboro.txt", "dem_topobathy.txt", "outlines_nybb.txt"}) {
        const auto lines = fit_corpus::read(dir + "/" + file);
        for (auto mode : {crspline::fit_mode::subset, crspline::fit_mode::free}) {
            const totals t = run(lines, mode);
            std::printf("%-22s %-7s %5zu %7zu %7zu %7zu   %.3f   %7zu    <= %.4f   %9.0f\n", file,
                        mode == crspline::fit_mode::free ? "free" : "subset", t.lines, t.points, t.rdp, t.fit,
                        double(t.fit) / double(t.rdp), t.tensioned, t.worst, double(t.points) / t.seconds);
            if (t.within != t.lines) std::printf("  !! %zu lines over their tolerance\n", t.lines - t.within);
        }
    }
    // 2. Growth: one line of the Jacksboro contours end to end (grid units,
    //    tolerance half a cell), first n points.
    std::vector<crspline::vec<2>> all;
    for (const auto& l : fit_corpus::read(dir + "/dem_jacksboro.txt")) all.insert(all.end(), l.points.begin(), l.points.end());
    const std::size_t base = all.size();
    for (std::size_t k = 1; all.size() < max_n; ++k)  // repeated, shifted past the DEM
        for (std::size_t i = 0; i < base && all.size() < max_n; ++i) all.push_back(all[i] + crspline::vec<2>{{450.0 * double(k), 0}});
    std::printf("\ngrowth (one line of concatenated contours, tolerance 0.5 cell)\nmode    points      seconds   points/s\n");
    for (auto mode : {crspline::fit_mode::subset, crspline::fit_mode::free}) {
        std::vector<double> lx, ly;
        for (std::size_t n = 10000; n <= (mode == crspline::fit_mode::free ? free_max : max_n); n *= 10) {
            growth_row(std::vector<crspline::vec<2>>(all.begin(), all.begin() + std::ptrdiff_t(n)), 0.5, mode, lx, ly);
        }
        print_exponent(mode, lx, ly);
    }
    // 3. Growth on a densely sampled smooth line: one period of a sine,
    //    tolerance 0.01, whose segments cover more input points the more
    //    there are (the choice's bounds of fit_model.hpp keep it linear).
    std::printf("\ngrowth (one period of a sine sampled densely, tolerance 0.01)\nmode    points      seconds   points/s\n");
    for (auto mode : {crspline::fit_mode::subset, crspline::fit_mode::free}) {
        std::vector<double> lx, ly;
        for (std::size_t n = 4000; n <= dense_max; n *= 4) {
            std::vector<crspline::vec<2>> p(n);
            for (std::size_t i = 0; i < n; ++i) {
                const double t = 2 * 3.141592653589793 * double(i) / double(n - 1);
                p[i] = crspline::vec<2>{{t, std::sin(t)}};
            }
            growth_row(p, 0.01, mode, lx, ly);
        }
        print_exponent(mode, lx, ly);
    }
    return 0;
}
