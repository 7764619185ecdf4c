// Nearest-point index scaling: build time, queries per second and work per
// query (hierarchy nodes tested, segments solved) for curves of 10^3 to 10^6
// segments, against the global search (every segment bounded) on the small
// ones. Standalone:
//   g++ -std=c++20 -O2 -DNDEBUG -Iinclude bench/nearest_scaling.cpp -o nearest_scaling
#include <crspline/nearest.hpp>

#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

using namespace crspline;
using clock_type = std::chrono::steady_clock;

static double seconds_since(clock_type::time_point t0) {
    return std::chrono::duration<double>(clock_type::now() - t0).count();
}

int main() {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> g(0.0, 1.0);
    std::printf("%10s %10s %12s %12s %12s %14s\n", "segments", "build s", "queries/s", "nodes/query",
                "solved/query", "global q/s");
    for (std::size_t n : {1000u, 10000u, 100000u, 1000000u}) {
        // A 3-D random walk with unit steps: a long, tangled curve.
        std::vector<vec<3>> p(n + 1);
        for (std::size_t i = 1; i <= n; ++i) p[i] = p[i - 1] + vec<3>{{g(rng), g(rng), g(rng)}};
        const catmull_rom<3> c(p);
        auto t0 = clock_type::now();
        const nearest_index<3> index(c);
        const double build = seconds_since(t0);
        // Queries near random curve points (within about one step).
        std::uniform_real_distribution<double> U(c.t_min(), c.t_max());
        std::vector<vec<3>> q(20000);
        for (auto& x : q) x = c.evaluate(U(rng)) + vec<3>{{g(rng), g(rng), g(rng)}};
        std::size_t nodes = 0, solved = 0;
        double sink = 0;
        t0 = clock_type::now();
        for (const auto& x : q) {
            const auto s = index.search(x);
            nodes += s.nodes_visited;
            solved += s.segments_solved;
            sink += s.result.distance_sq;
        }
        const double qps = double(q.size()) / seconds_since(t0);
        // The global search, on a few queries (it is O(N) per query).
        const std::size_t nq = n <= 10000 ? 200 : 20;
        t0 = clock_type::now();
        for (std::size_t j = 0; j < nq; ++j) sink += nearest(c, q[j]).distance_sq;
        const double gqps = double(nq) / seconds_since(t0);
        std::printf("%10zu %10.3f %12.0f %12.1f %12.2f %14.1f\n", n, build, qps, double(nodes) / double(q.size()),
                    double(solved) / double(q.size()), gqps);
        if (sink < 0) std::printf("impossible\n");
    }
}
