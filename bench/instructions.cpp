// Instruction counts per item, for BENCHMARKS.md: stable where times are not
// (this machine is shared). Run under callgrind with collection off at start
// (bench/count_instructions.sh); each case switches it on around its kernel
// only and dumps its own counts, named after the case.
//
// Same inputs as crspline_bench.cpp: 3-D double points, a seeded random walk
// with uneven steps, centripetal knots.
#include <crspline/arc_length.hpp>
#include <crspline/catmull_rom.hpp>

#include <boost/math/interpolators/catmull_rom.hpp>
#include <valgrind/callgrind.h>

#include "walk.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace {

using v3 = crspline::vec<3, double>;
using curve3 = crspline::catmull_rom<3, double>;
using boost_point = std::array<double, 3>;

using crspline_bench::walk;  // bench/walk.hpp

/// Runs f with collection on, dumps the counts as `name`, and prints the
/// number of items so that the script can divide.
template <class F>
void count(const char* name, std::size_t items, F&& f) {
    CALLGRIND_ZERO_STATS;
    CALLGRIND_START_INSTRUMENTATION;
    f();
    CALLGRIND_STOP_INSTRUMENTATION;
    CALLGRIND_DUMP_STATS_AT(name);
    std::printf("%s %zu\n", name, items);
}

volatile double sink;

}  // namespace

int main() {
    const std::size_t n = 1'000'000;
    const auto p = walk(1000);  // as crspline_bench
    const curve3 c(p);
    std::vector<boost_point> bp(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) bp[i] = {p[i][0], p[i][1], p[i][2]};
    const boost::math::catmull_rom<boost_point> b(std::vector<boost_point>(bp), false, 0.5);

    std::vector<double> sorted(n), random(n);
    for (std::size_t k = 0; k < n; ++k) sorted[k] = c.t_min() + (c.t_max() - c.t_min()) * double(k) / double(n - 1);
    sorted.back() = c.t_max();
    std::mt19937_64 rng(20240602);
    std::uniform_real_distribution<double> U(c.t_min(), c.t_max());
    for (auto& x : random) x = U(rng);
    std::vector<v3> out(n);
    std::vector<boost_point> bout(n);

    count("eval_sorted/crspline", n, [&] { c.evaluate(std::span<const double>(sorted), std::span<v3>(out), 0); });
    count("deriv_sorted/crspline", n, [&] { c.evaluate(std::span<const double>(sorted), std::span<v3>(out), 1); });
    count("eval_random/crspline", n, [&] { c.evaluate(std::span<const double>(random), std::span<v3>(out), 0); });
    const double bmax = b.max_parameter();
    count("eval_sorted/boost", n, [&] {
        for (std::size_t k = 0; k < n; ++k) bout[k] = b(std::min(sorted[k], bmax));
    });
    count("eval_random/boost", n, [&] {
        for (std::size_t k = 0; k < n; ++k) bout[k] = b(std::min(random[k], bmax));
    });
    count("construct/crspline/1000", 100 * p.size(), [&] {
        for (int r = 0; r < 100; ++r) sink = curve3(p).t_max();
    });
    count("construct/boost/1000", 100 * p.size(), [&] {
        for (int r = 0; r < 100; ++r)
            sink = boost::math::catmull_rom<boost_point>(std::vector<boost_point>(bp), false, 0.5).max_parameter();
    });
    const auto big = walk(n);
    std::vector<boost_point> bbig(n);
    for (std::size_t i = 0; i < n; ++i) bbig[i] = {big[i][0], big[i][1], big[i][2]};
    count("construct/crspline/1000000", n, [&] { sink = curve3(big).t_max(); });
    count("construct/boost/1000000", n, [&] {
        sink = boost::math::catmull_rom<boost_point>(std::vector<boost_point>(bbig), false, 0.5).max_parameter();
    });
    const crspline::arc_length_table<3> table(c, 1e-12);
    const std::size_t q = 100'000;
    std::vector<double> s(q), t(q);
    for (std::size_t k = 0; k < q; ++k) s[k] = table.total() * (double(k) / double(q - 1));  // the last is total() exactly
    count("t_at_arc_length", q, [&] { table.t_at(std::span<const double>(s), std::span<double>(t)); });
    sink = out[n / 2][0] + bout[n / 2][0] + t[q / 2];
    return 0;
}
