// crspline benchmarks, arc length, tessellation, nearest point and the
// native equivalents of three.js's CatmullRomCurve3 calls. Part of
// crspline_bench (see crspline_bench.cpp for the conventions; inputs in
// bench_inputs.hpp).
#include "bench_inputs.hpp"

namespace {

using namespace crspline_bench;
using crspline::vec;

// ---------------------------------------------------------------------------
// Arc length. The reference: composite 8-point Gauss-Legendre in long double
// on 1024 equal pieces per segment (and 2048 to show it has converged: the
// uneven walk has tight turns where 64 pieces still leave 1.5e-11); it is
// independent of crspline's adaptive cuts.

long double ref_length(const crspline::cubic_segment<3, double>& s, long double a, long double b, int pieces) {
    static const long double x[4] = {0.18343464249564980494L, 0.52553240991632898582L, 0.79666647741362673959L,
                                     0.96028985649753623168L};
    static const long double w[4] = {0.36268378337836198297L, 0.31370664587788728734L, 0.22238103445337447054L,
                                     0.10122853629037625915L};
    auto speed = [&](long double u) {
        long double q = 0;
        for (int d = 0; d < 3; ++d) {
            const long double v = s.c1[d] + u * (2.0L * s.c2[d] + 3.0L * u * s.c3[d]);
            q += v * v;
        }
        return std::sqrt(q);
    };
    long double sum = 0;
    const long double h = (b - a) / pieces;
    for (int p = 0; p < pieces; ++p) {
        const long double m = a + (p + 0.5L) * h, r = h / 2;
        for (int i = 0; i < 4; ++i) sum += w[i] * r * (speed(m - r * x[i]) + speed(m + r * x[i]));
    }
    return sum;
}

/// Cumulative reference length at each knot.
const std::vector<long double>& ref_knot_lengths() {
    static const std::vector<long double> s = [] {
        std::vector<long double> r{0.0L};
        for (const auto& seg : curve().segments()) r.push_back(r.back() + ref_length(seg, 0, 1, 1024));
        return r;
    }();
    return s;
}

void arc_length(benchmark::State& state) {
    const auto& c = curve();
    double L = 0;
    for (auto _ : state) {
        L = crspline::arc_length(c, 1e-12);
        benchmark::DoNotOptimize(L);
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * c.segment_count()));  // per segment
    long double ref2048 = 0;
    for (const auto& seg : c.segments()) ref2048 += ref_length(seg, 0, 1, 2048);
    const long double ref = ref_knot_lengths().back();
    state.counters["rel_err"] = double(std::abs((long double)L - ref) / ref);
    state.counters["ref_converged"] = double(std::abs(ref2048 - ref) / ref);
}

void t_at_arc_length(benchmark::State& state) {
    const auto& c = curve();
    static const crspline::arc_length_table<3> table(c, 1e-12);
    const std::size_t n = 1'000'000;
    static const auto s = linspace(0.0, table.total(), n);
    static std::vector<double> t(n);
    for (auto _ : state) {
        table.t_at(std::span<const double>(s), std::span<double>(t));
        benchmark::DoNotOptimize(t.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * n));
    // Accuracy: every 997th query, |s_ref(t) - s| / total with the reference
    // integrator from the segment's start.
    double err = 0;
    const auto& ref = ref_knot_lengths();
    for (std::size_t k = 0; k < n; k += 997) {
        const std::size_t i = c.locate(t[k]);
        const auto& seg = c.segment(i);
        const long double u = std::clamp<long double>(((long double)t[k] - seg.t0) / seg.h, 0, 1);
        const long double sr = ref[i] + ref_length(seg, 0, u, 1024);
        err = std::max(err, double(std::abs(sr - (long double)s[k])));
    }
    state.counters["rel_err"] = err / table.total();
}

// Issue 16: arc length on a 20,000-point walk against one plain 16-point
// Gauss-Legendre rule per segment on the same segments, both errors
// against a long-double reference (16 points on 256 panels per segment).
const curve3& walk20k() { static const curve3 c(walk(20'000)); return c; }

long double walk20k_reference() {
    static const long double ref = [] {
        using G = crspline::detail::gauss_legendre<16, long double>;
        long double sum = 0;
        for (const auto& s : walk20k().segments())
            for (int p = 0; p < 256; ++p) {
                const long double m = (p + 0.5L) / 256, r = 0.5L / 256;
                for (int i = 0; i < 8; ++i)
                    for (long double u : {m - r * G::x[i], m + r * G::x[i]}) {
                        long double q = 0;
                        for (int d = 0; d < 3; ++d) {
                            const long double v = s.c1[d] + u * (2.0L * s.c2[d] + 3.0L * u * s.c3[d]);
                            q += v * v;
                        }
                        sum += G::w[i] * r * std::sqrt(q);
                    }
            }
        return sum;
    }();
    return ref;
}

void arc_length_walk(benchmark::State& state) {
    const auto& c = walk20k();
    double L = 0;
    for (auto _ : state) {
        L = crspline::arc_length(c, 1e-12);
        benchmark::DoNotOptimize(L);
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * c.segment_count()));  // per segment
    const long double ref = walk20k_reference();
    state.counters["rel_err"] = double(std::abs((long double)L - ref) / ref);
    // Quadrature nodes per segment, over the pieces arc_length integrates.
    const auto segments = c.segments();
    double nodes = 0;
    crspline::detail::for_each_segment_length_piece(
        c.segment_count(), [&](std::size_t i) { return segments[i]; }, 1e-12,
        [&](std::size_t, double, double, double, const crspline::detail::rule_choice& rc) { nodes += rc.n; });
    state.counters["nodes_per_segment"] = nodes / double(c.segment_count());
}

void arc_length_walk_gl16(benchmark::State& state) {
    const auto& c = walk20k();
    double L = 0;
    for (auto _ : state) {
        L = 0;
        for (const auto& s : c.segments()) L += crspline::detail::gauss_length_n<16>(s, 0.0, 1.0);
        benchmark::DoNotOptimize(L);
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * c.segment_count()));
    const long double ref = walk20k_reference();
    state.counters["rel_err"] = double(std::abs((long double)L - ref) / ref);
}

// Tessellation of the same walk at tol 1e-3 and 1e-5 (steps are ~1): per
// output vertex, with the vertex count over the asymptotic optimum
// integral sqrt(kappa / (8 tol)) ds (computed here by a 16-point rule on 64
// panels per segment); the baseline is a sorted batch evaluation of as
// many points.
double tessellation_optimum(const curve3& c, double tol) {
    using G = crspline::detail::gauss_legendre<16, double>;
    double sum = 0;
    for (const auto& s : c.segments())
        for (int p = 0; p < 64; ++p) {
            const double m = (p + 0.5) / 64, r = 0.5 / 64;
            for (int i = 0; i < 8; ++i)
                for (double u : {m - r * G::x[i], m + r * G::x[i]}) {
                    const v3 d1 = s.du(u, 1), d2 = s.du(u, 2);
                    const double v2 = crspline::dot(d1, d1);
                    const double cross2 = std::max(0.0, v2 * crspline::dot(d2, d2) - std::pow(crspline::dot(d1, d2), 2));
                    // sqrt(kappa) |C'| du with kappa = |C' x C''| / |C'|^3
                    if (v2 > 0) sum += G::w[i] * r * std::sqrt(std::sqrt(cross2) / (v2 * std::sqrt(v2))) * std::sqrt(v2);
                }
        }
    return sum / std::sqrt(8 * tol);
}

void tessellate_walk(benchmark::State& state) {
    const auto& c = walk20k();
    const double tol = state.range(0) == 3 ? 1e-3 : 1e-5;
    crspline::polyline<3, double> pl;
    for (auto _ : state) {
        pl = crspline::tessellate(c, tol);
        benchmark::DoNotOptimize(pl.points.data());
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * pl.points.size()));  // per vertex
    state.counters["vertices"] = double(pl.points.size());
    state.counters["over_optimum"] = double(pl.points.size() - 1) / tessellation_optimum(c, tol);
}

void tessellate_walk_eval(benchmark::State& state) {
    const auto& c = walk20k();
    const double tol = state.range(0) == 3 ? 1e-3 : 1e-5;
    static std::size_t n3 = 0, n5 = 0;
    std::size_t& n = tol == 1e-3 ? n3 : n5;
    if (n == 0) n = crspline::tessellate(c, tol).points.size();
    const auto t = linspace(c.t_min(), c.t_max(), n);
    std::vector<v3> out(n);
    for (auto _ : state) {
        c.evaluate(std::span<const double>(t), std::span<v3>(out), 0);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * n));
}

// Tessellation at an absolute tolerance of 1e-6 (the walk's steps are ~1).
// Accuracy: the largest distance from 15 curve points inside every piece to
// its chord, over the tolerance (must be <= 1).
void tessellate(benchmark::State& state) {
    const auto& c = curve();
    const double tol = 1e-6;
    crspline::polyline<3, double> pl;
    for (auto _ : state) {
        pl = crspline::tessellate(c, tol);
        benchmark::DoNotOptimize(pl.points.data());
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * c.segment_count()));  // per segment
    double worst = 0;
    for (std::size_t k = 0; k + 1 < pl.t.size(); ++k) {
        const v3 a = pl.points[k], b = pl.points[k + 1], ab = b - a;
        const double ab2 = crspline::dot(ab, ab);
        for (int j = 1; j < 16; ++j) {
            const v3 x = c.evaluate(pl.t[k] + (pl.t[k + 1] - pl.t[k]) * (j / 16.0));
            const double w = ab2 > 0 ? std::clamp(crspline::dot(x - a, ab) / ab2, 0.0, 1.0) : 0.0;
            worst = std::max(worst, crspline::norm(x - (a + w * ab)));
        }
    }
    state.counters["vertices"] = double(pl.points.size());
    state.counters["err_over_tol"] = worst / tol;
}

// ---------------------------------------------------------------------------
// Nearest point: nearest_index on curves of 10^3 .. 10^6 segments (the same
// walk generator), 10^5 queries within about one step of a random curve
// point. The `nearest` case of the table is 10^6 segments. Accuracy: the
// index must equal the global O(N) search (checked on 10 queries).

struct nearest_setup {
    std::vector<v3> p;
    curve3 c;
    crspline::nearest_index<3> index;
    std::vector<v3> q;
    double mismatch = 0;
    explicit nearest_setup(std::size_t nseg) : p(walk(nseg + 1, seed + nseg)), c(p), index(c), q(100000) {
        std::mt19937_64 rng(seed + 2);
        std::uniform_real_distribution<double> U(c.t_min(), c.t_max());
        std::normal_distribution<double> g(0.0, 1.0);
        for (auto& x : q) x = c.evaluate(U(rng)) + v3{{g(rng), g(rng), g(rng)}};
        for (std::size_t j = 0; j < 10; ++j)
            mismatch = std::max(mismatch, std::abs(index.nearest(q[j]).distance_sq - crspline::nearest(c, q[j]).distance_sq));
    }
};

void nearest(benchmark::State& state) {
    const std::size_t nseg = std::size_t(state.range(0));
    // One setup per size, kept across repetitions (the index refers to its curve).
    static std::map<std::size_t, std::unique_ptr<nearest_setup>> cache;
    auto& slot = cache[nseg];
    if (!slot) slot = std::make_unique<nearest_setup>(nseg);
    const nearest_setup& S = *slot;
    std::size_t nodes = 0, solved = 0, queries = 0;
    for (auto _ : state) {
        for (const auto& x : S.q) {
            const auto r = S.index.search(x);
            nodes += r.nodes_visited;
            solved += r.segments_solved;
            benchmark::DoNotOptimize(r.result.distance_sq);
        }
        queries += S.q.size();
    }
    state.SetItemsProcessed(std::int64_t(queries));
    state.counters["nodes_per_query"] = double(nodes) / double(queries);
    state.counters["solved_per_query"] = double(solved) / double(queries);
    state.counters["vs_global_abs"] = S.mismatch;
}

// ---------------------------------------------------------------------------
// Native equivalents of three.js CatmullRomCurve3 (timed by bench/js):
// getPoint(u) for 10^6 increasing u is a sorted batch evaluation; getPointAt
// (by arc length) is evaluate_at_arc_length on a prebuilt table.

void threejs_getPoint_crspline(benchmark::State& state) {
    const auto& c = curve();
    const std::size_t n = 1'000'000;
    static const auto t = linspace(c.t_min(), c.t_max(), n);
    auto& out = output<v3>(n);
    for (auto _ : state) {
        c.evaluate(std::span<const double>(t), std::span<v3>(out), 0);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * n));
}

void threejs_getPointAt_crspline(benchmark::State& state) {
    const auto& c = curve();
    static const crspline::arc_length_table<3> table(c, 1e-12);
    const std::size_t n = 1'000'000;
    static const auto s = linspace(0.0, table.total(), n);
    for (auto _ : state) {
        auto out = crspline::evaluate_at_arc_length(c, table, std::span<const double>(s));
        benchmark::DoNotOptimize(out.data());
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * n));
}


}  // namespace

// Registration (in the table's order).
BENCHMARK(arc_length)->Name("arc_length")->Unit(benchmark::kMicrosecond);
BENCHMARK(arc_length_walk)->Name("arc_length_walk20k/crspline")->Unit(benchmark::kMillisecond);
BENCHMARK(arc_length_walk_gl16)->Name("arc_length_walk20k/gl16")->Unit(benchmark::kMillisecond);
BENCHMARK(tessellate_walk)->Name("tessellate_walk20k/crspline")->Arg(3)->Arg(5)->Unit(benchmark::kMillisecond);
BENCHMARK(tessellate_walk_eval)->Name("tessellate_walk20k/eval")->Arg(3)->Arg(5)->Unit(benchmark::kMillisecond);
BENCHMARK(t_at_arc_length)->Name("t_at_arc_length")->Unit(benchmark::kMillisecond);
BENCHMARK(tessellate)->Name("tessellate")->Unit(benchmark::kMillisecond);
BENCHMARK(nearest)->Name("nearest")->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(nearest)->Name("nearest_scaling")->Arg(1000)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond);
BENCHMARK(threejs_getPoint_crspline)->Name("threejs_getPoint/crspline")->Unit(benchmark::kMillisecond);
BENCHMARK(threejs_getPointAt_crspline)->Name("threejs_getPointAt/crspline")->Unit(benchmark::kMillisecond);
