// The batch kernels: the run-time dispatched AVX2 kernels for 3-D doubles
// (detail/x86_kernels.hpp) against the portable ones and against the
// single-point path, and locate() against a plain binary search.
//
// Exactness: the AVX2 kernels do the same IEEE operations in the same order
// as the portable code (no FMA), so positions must agree bit for bit; so
// must sorted derivatives (both fold 1/h into the coefficients the same way).
// On a CPU without AVX2 both sides run the portable code and the comparison
// is trivially equal; the test says so.
#include "test_support.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace {
using namespace crspline;
using crspline::test::random_polygon;
using P3 = vec<3>;

bool same_bits(const P3& a, const P3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Runs f with the AVX2 kernels on (if the CPU has them) and off, restoring the setting.
template <class F>
auto both_paths(F&& f) {
    bool& on = detail::avx2_enabled();
    const bool had = on;
    auto fast = f();
    on = false;
    auto portable = f();
    on = had;
    return std::pair(std::move(fast), std::move(portable));
}

/// Curves that exercise every storage case: open and closed, split
/// incoming/outgoing tangents (KB continuity), tension, repeated points
/// (zero knot intervals), and very uneven knots (crowded locate buckets).
std::vector<catmull_rom<3>> curves(std::mt19937_64& rng) {
    std::vector<catmull_rom<3>> out;
    for (int rep = 0; rep < 6; ++rep) {
        auto p = random_polygon<3>(rng, 7 + 13 * rep, rep % 2 ? 6.0 : 1.0);
        if (rep >= 2) p[3] = p[2];  // a coincident pair: a zero interval
        options<3> o{.alpha = rep % 3 == 0 ? 1.0 : 0.5, .closed = rep % 2 == 1};
        if (rep == 4) o.tension = 0.3;
        if (rep == 5) o.kb.continuity.assign(p.size(), 0.4);
        out.emplace_back(p, o);
    }
    return out;
}

TEST(Kernels, LocateAgreesWithBinarySearch) {
    CRSPLINE_SEEDED(s, 71);
    std::mt19937_64 rng(s);
    std::size_t checked = 0;
    for (const auto& c : curves(rng)) {
        const auto g = c.grid();
        std::vector<double> t(g.begin(), g.end());  // every knot exactly
        std::uniform_real_distribution<double> U(c.t_min() - 1, c.t_max() + 1);
        for (int k = 0; k < 2000; ++k) t.push_back(U(rng));
        for (double x : t) {
            // The owner: the last segment starting at or before x, clamped.
            const std::size_t ref = std::min<std::size_t>(
                c.segment_count() - 1, std::size_t(std::max<std::ptrdiff_t>(0, std::upper_bound(g.begin(), g.end(), x) - g.begin() - 1)));
            ASSERT_EQ(c.locate(x), ref) << "t = " << x;
            ++checked;
        }
    }
    EXPECT_GT(checked, 6u * 2000u);
}

TEST(Kernels, AvxAndPortableBatchesAgreeBitForBit) {
    CRSPLINE_SEEDED(s, 72);
    std::mt19937_64 rng(s);
    // Without AVX2 both sides would run the portable kernels: nothing to compare.
    if (!detail::avx2_enabled()) GTEST_SKIP() << "no AVX2 kernels on this CPU or build: nothing to compare";
    std::size_t checked = 0;
    for (const auto& c : curves(rng)) {
        std::uniform_real_distribution<double> U(c.t_min(), c.t_max());
        // Sizes around the vector widths and the head/tail cases, and one
        // above the streaming threshold (non-temporal stores).
        for (std::size_t n : {std::size_t(1), std::size_t(3), std::size_t(5), std::size_t(37), std::size_t(1000),
                              detail::streaming_threshold / sizeof(P3) + 5}) {
            std::vector<double> t(n);
            for (auto& x : t) x = U(rng);
            t[0] = c.t_max();  // the last knot must give the last point exactly
            if (n > 2) t[n / 2] = c.grid()[c.segment_count() / 2];
            std::vector<double> sorted = t;
            std::sort(sorted.begin(), sorted.end());
            for (std::size_t shift : {0u, 1u}) {  // output 32-byte aligned or not
                for (int order : {0, 1}) {
                    for (const auto* in : {&t, &sorted}) {
                        const auto [fast, portable] = both_paths([&] {
                            std::vector<P3> buf(n + shift);
                            c.evaluate(std::span<const double>(*in), std::span<P3>(buf).subspan(shift), order);
                            return buf;
                        });
                        for (std::size_t k = 0; k < n; k += (n > 5000 ? 97 : 1)) {
                            ASSERT_TRUE(same_bits(fast[k + shift], portable[k + shift]))
                                << "n " << n << " order " << order << " sorted " << (in == &sorted) << " k " << k;
                            // Unsorted positions also match the single-point path.
                            if (order == 0 && in == &t) {
                                ASSERT_TRUE(same_bits(fast[k + shift], c.evaluate((*in)[k]))) << "k " << k;
                            }
                            ++checked;
                        }
                    }
                }
            }
        }
    }
    EXPECT_GT(checked, 6u * 2 * 2 * 2 * 1000u);
}

TEST(Kernels, FloatSortedBatchesAgreeBitForBit) {
    // The float kernels (16-lane AVX-512 where the CPU has it, 8-lane AVX2)
    // against the portable 4-lane one, positions and derivatives, with the
    // output aligned and not, small and streaming. Which ran is printed.
    CRSPLINE_SEEDED(s, 74);
    std::mt19937_64 rng(s);
    using F3 = vec<3, float>;
    std::size_t checked = 0;
    for (int rep = 0; rep < 4; ++rep) {
        const auto pd = random_polygon<3>(rng, 9 + 11 * rep, 2.0);
        std::vector<F3> p(pd.size());
        for (std::size_t i = 0; i < p.size(); ++i) p[i] = F3{{float(pd[i][0]), float(pd[i][1]), float(pd[i][2])}};
        const catmull_rom<3, float> c(p, {.alpha = 0.5, .closed = rep % 2 == 1});
        for (std::size_t n : {std::size_t(7), std::size_t(1001), detail::streaming_threshold / sizeof(F3) + 9}) {
            std::vector<float> t(n);
            for (std::size_t k = 0; k < n; ++k) t[k] = c.t_min() + (c.t_max() - c.t_min()) * float(k) / float(n - 1);
            t.back() = c.t_max();
            for (std::size_t shift : {0u, 1u, 3u}) {
                for (int order : {0, 1}) {
                    auto run = [&] {
                        std::vector<F3> buf(n + shift);
                        c.evaluate(std::span<const float>(t), std::span<F3>(buf).subspan(shift), order);
                        return buf;
                    };
                    const auto [fast, portable] = both_paths(run);
#if CRSPLINE_X86_DISPATCH
                    // And the 8-lane AVX2 loop where the 16-lane AVX-512 one
                    // ran above (issue 30).
                    bool& wide = detail::avx512_enabled();
                    const bool had = wide;
                    wide = false;
                    const auto avx2 = run();
                    wide = had;
#else
                    const auto& avx2 = fast;
#endif
                    for (std::size_t k = 0; k < n; k += (n > 5000 ? 101 : 1)) {
                        ASSERT_EQ(std::memcmp(&fast[k + shift], &portable[k + shift], sizeof(F3)), 0)
                            << "n " << n << " order " << order << " shift " << shift << " k " << k;
                        ASSERT_EQ(std::memcmp(&avx2[k + shift], &portable[k + shift], sizeof(F3)), 0)
                            << "AVX2 loop: n " << n << " order " << order << " shift " << shift << " k " << k;
                        ++checked;
                    }
                }
            }
        }
    }
    EXPECT_GT(checked, 4u * 3 * 2 * 1000u);
#if CRSPLINE_X86_DISPATCH
    std::printf("float kernels compared: %s\n", detail::avx512_enabled() ? "AVX-512, AVX2 and portable"
                                                 : detail::avx2_enabled() ? "AVX2 and portable"
                                                                          : "portable only");
#endif
}

// Sorted 3-D batch evaluation of c on one path: 0 the widest walk (AVX-512F
// where the CPU has it), 1 the AVX2 walk, 2 the portable kernel; t from
// `from` on, written to an output shifted by `shift` points (other
// alignments), returned without the shift.
template <class T>
std::vector<vec<3, T>> evaluate_on_path(const catmull_rom<3, T>& c, const std::vector<T>& t, int path, std::size_t from,
                                        std::size_t shift, int order) {
#if CRSPLINE_X86_DISPATCH
    bool &avx2 = detail::avx2_enabled(), &wide = detail::avx512_enabled();
    const bool had2 = avx2, had512 = wide;
    wide = wide && path == 0;
    avx2 = avx2 && path <= 1;
#else
    (void)path;
#endif
    std::vector<vec<3, T>> buf(t.size() - from + shift);
    c.evaluate(std::span<const T>(t).subspan(from), std::span<vec<3, T>>(buf).subspan(shift), order);
#if CRSPLINE_X86_DISPATCH
    avx2 = had2, wide = had512;
#endif
    return std::vector<vec<3, T>>(buf.begin() + std::ptrdiff_t(shift), buf.end());
}

TEST(Kernels, FloatWalkCrossesKnotsInsideSteps) {
    // The AVX-512 float walk (detail::sorted_walk3_512, issue 30) computes a
    // 16-point step that crosses knots on each segment it meets and blends
    // the lanes. With about 4 points a segment (several knots a step), every
    // knot hit exactly, a repeated parameter, a coincident pair of points (a
    // zero interval) and all 16 output offsets mod 64 bytes (12-byte points
    // shifted by 0..15), each point must equal the AVX2 walk's (8 lanes,
    // sorted_walk3_256) and the portable kernel's bit for bit, and
    // positions the single-point path;
    // input unsorted deep inside must fall back and still agree, a NaN must
    // give the unsorted path's out_of_domain error.
    CRSPLINE_SEEDED(s, 77);
    std::mt19937_64 rng(s);
    using F3 = vec<3, float>;
    std::size_t checked = 0;
    for (int rep = 0; rep < 4; ++rep) {
        auto p = random_polygon<3, float>(rng, 40 + 30 * rep, 3.0);
        if (rep >= 1) p[5] = p[4];
        const catmull_rom<3, float> c(p, {.alpha = rep % 2 ? 0.5 : 1.0, .closed = rep == 3});
        const auto g = c.grid();
        std::vector<float> t(g.begin(), g.end());
        std::uniform_real_distribution<float> U(c.t_min(), c.t_max());
        for (std::size_t k = 0; k < 4 * g.size(); ++k) t.push_back(std::min(U(rng), c.t_max()));
        t.push_back(t[t.size() / 2]);
        std::sort(t.begin(), t.end());
        // Each path: the 16-lane walk (where the CPU has AVX-512F), the
        // 8-lane walk (where it has AVX2), the portable kernel; t from `from` to the end, out shifted.
        auto run = [&](int path, std::size_t from, std::size_t shift, int order) {
            return evaluate_on_path(c, t, path, from, shift, order);
        };
        for (std::size_t shift = 0; shift < 16; ++shift) {
            for (int order : {0, 1}) {
                // The whole batch, and short ones (head and tail steps only).
                for (std::size_t from : {std::size_t(0), t.size() - 1 - shift, t.size() - 17 - shift}) {
                    const auto walk = run(0, from, shift, order), walk8 = run(1, from, shift, order),
                               portable = run(2, from, shift, order);
                    for (std::size_t k = 0; k < walk.size(); ++k) {
                        ASSERT_EQ(std::memcmp(&walk[k], &portable[k], sizeof(F3)), 0)
                            << "rep " << rep << " shift " << shift << " order " << order << " from " << from << " k " << k;
                        ASSERT_EQ(std::memcmp(&walk8[k], &portable[k], sizeof(F3)), 0)
                            << "8 lanes: rep " << rep << " shift " << shift << " order " << order << " k " << k;
                        if (order == 0) {
                            const F3 x = c.evaluate(t[from + k]);
                            ASSERT_EQ(std::memcmp(&walk[k], &x, sizeof(F3)), 0) << "rep " << rep << " k " << k;
                        }
                        ++checked;
                    }
                }
            }
        }
        // Unsorted: an adjacent pair swapped across a knot (t[k0 + 1] a knot,
        // so the swapped t[k0 + 1] lies on an earlier segment and a missed
        // check would give other bits), at the first three knots and deep
        // inside, in batches that start 0..17 points before the pair (the
        // pair in every lane of the first step) and at 4 output offsets;
        // then a NaN.
        std::vector<std::size_t> across;
        for (std::size_t k = 0; k + 1 < t.size(); ++k)
            if (t[k] < t[k + 1] && std::binary_search(g.begin(), g.end(), t[k + 1])) across.push_back(k);
        ASSERT_GT(across.size(), 10u);
        std::uniform_int_distribution<std::size_t> deep(across.size() / 2, across.size() - 1);
        std::size_t k0 = 0;
        for (const std::size_t a : {std::size_t(0), std::size_t(1), std::size_t(2), deep(rng)}) {
            k0 = across[a];
            std::swap(t[k0], t[k0 + 1]);
            for (std::size_t j = 0; j <= std::min<std::size_t>(k0, 17); ++j) {
                for (std::size_t shift : {0u, 5u, 10u, 15u}) {
                    for (int path : {0, 1}) {
                        const auto swapped = run(path, k0 - j, shift, 0);
                        for (std::size_t k = 0; k < swapped.size(); ++k) {
                            const F3 x = c.evaluate(t[k0 - j + k]);
                            ASSERT_EQ(std::memcmp(&swapped[k], &x, sizeof(F3)), 0)
                                << "path " << path << " from " << k0 - j << " shift " << shift << " k " << k
                                << " (swapped at " << k0 << ")";
                        }
                    }
                }
            }
            std::swap(t[k0], t[k0 + 1]);
        }
        t[k0] = std::numeric_limits<float>::quiet_NaN();
        EXPECT_THROW(run(0, 0, 0, 0), out_of_domain) << "NaN at " << k0;
        EXPECT_THROW(run(1, 0, 0, 0), out_of_domain) << "NaN at " << k0;
    }
    EXPECT_GT(checked, 4u * 16 * 2 * 200u);
}

TEST(Kernels, DoubleWalkCrossesKnotsInsideSteps) {
    // The double walks (detail::sorted_walk3_512 and _256 on doubles, issue
    // 30): 8- or 4-point steps that cross knots are computed on each segment
    // they meet and blended. With about 4 points a segment, every knot hit exactly, a
    // repeated parameter, a zero interval, all 8 output offsets mod 64 bytes
    // (24-byte points shifted by 0..7), whole and short batches, and one
    // batch large enough for non-temporal stores, each point must equal the
    // 4-lane walk's and the portable kernel's bit for bit, and positions the
    // single-point path; an adjacent pair swapped across a knot must fall
    // back and still agree, a NaN must give the out_of_domain error.
    CRSPLINE_SEEDED(s, 78);
    std::mt19937_64 rng(s);
    std::size_t checked = 0;
    for (int rep = 0; rep < 5; ++rep) {
        auto p = random_polygon<3, double>(rng, 40 + 30 * rep, 3.0);
        if (rep >= 1) p[5] = p[4];
        const catmull_rom<3, double> c(p, {.alpha = rep % 2 ? 0.5 : 1.0, .closed = rep == 3});
        const auto g = c.grid();
        std::vector<double> t(g.begin(), g.end());
        std::uniform_real_distribution<double> U(c.t_min(), c.t_max());
        // rep 4: 400,000 points (9.6 MB of output, above the 8 MiB
        // streaming threshold: the non-temporal steps).
        const std::size_t extra = rep == 4 ? 400000 : 4 * g.size();
        for (std::size_t k = 0; k < extra; ++k) t.push_back(std::min(U(rng), c.t_max()));
        t.push_back(t[t.size() / 2]);
        std::sort(t.begin(), t.end());
        // Paths: 0 the 8-lane walk (where the CPU has AVX-512F), 1 the 4-lane
        // walk (where it has AVX2), 2 the portable kernel; t from `from` on,
        // out shifted.
        auto run = [&](int path, std::size_t from, std::size_t shift, int order) {
            return evaluate_on_path(c, t, path, from, shift, order);
        };
        for (std::size_t shift = 0; shift < 8; ++shift) {
            if (rep == 4 && shift % 3 != 0) continue;  // the large batch at offsets 0, 24 and 48 bytes mod 64
            for (int order : {0, 1}) {
                for (std::size_t from : {std::size_t(0), t.size() - 1 - shift, t.size() - 9 - shift}) {
                    const auto walk = run(0, from, shift, order), walk4 = run(1, from, shift, order),
                               portable = run(2, from, shift, order);
                    ASSERT_EQ(walk.size(), t.size() - from);
                    for (std::size_t k = 0; k < walk.size(); ++k) {
                        ASSERT_TRUE(same_bits(walk[k], portable[k]))
                            << "rep " << rep << " shift " << shift << " order " << order << " from " << from << " k " << k;
                        ASSERT_TRUE(same_bits(walk4[k], portable[k]))
                            << "4 lanes: rep " << rep << " shift " << shift << " order " << order << " k " << k;
                        if (order == 0) {
                            ASSERT_TRUE(same_bits(walk[k], c.evaluate(t[from + k]))) << "rep " << rep << " k " << k;
                        }
                        ++checked;
                    }
                }
            }
        }
        if (rep == 4) continue;
        // Unsorted: a pair swapped across a knot, at the first knots and
        // deep inside, in batches starting 0..9 points before it (the pair
        // in every lane of the first step), at 4 output offsets; then a NaN.
        std::vector<std::size_t> across;
        for (std::size_t k = 0; k + 1 < t.size(); ++k)
            if (t[k] < t[k + 1] && std::binary_search(g.begin(), g.end(), t[k + 1])) across.push_back(k);
        ASSERT_GT(across.size(), 10u);
        std::uniform_int_distribution<std::size_t> deep(across.size() / 2, across.size() - 1);
        std::size_t k0 = 0;
        for (const std::size_t a : {std::size_t(0), std::size_t(1), deep(rng)}) {
            k0 = across[a];
            std::swap(t[k0], t[k0 + 1]);
            for (std::size_t j = 0; j <= std::min<std::size_t>(k0, 9); ++j)
                for (std::size_t shift : {0u, 1u, 3u, 6u})
                    for (int path : {0, 1}) {
                        const auto swapped = run(path, k0 - j, shift, 0);
                        for (std::size_t k = 0; k < swapped.size(); ++k)
                            ASSERT_TRUE(same_bits(swapped[k], c.evaluate(t[k0 - j + k])))
                                << "path " << path << " from " << k0 - j << " shift " << shift << " k " << k
                                << " (swapped at " << k0 << ")";
                    }
            std::swap(t[k0], t[k0 + 1]);
        }
        t[k0] = std::numeric_limits<double>::quiet_NaN();
        EXPECT_THROW(run(0, 0, 0, 0), out_of_domain) << "NaN at " << k0;
        EXPECT_THROW(run(1, 0, 0, 0), out_of_domain) << "NaN at " << k0;
    }
    // 4 small curves x 8 offsets x 2 orders x 3 batches of at least 160
    // points, and the large batch: 3 offsets x 2 orders x 400,000.
    EXPECT_GT(checked, 4u * 8 * 2 * 160u + 3u * 2 * 400000u);
}

TEST(Kernels, NearlySortedInputFallsBackAndStillAgrees) {
    if (!detail::avx2_enabled()) GTEST_SKIP() << "no AVX2 kernels on this CPU or build: nothing to compare";
    // Sorted input with one adjacent pair swapped deep inside a run (the
    // sorted kernels evaluate whole runs before the sortedness flag is read,
    // and find each run's end as they go): every point must still equal the
    // single-point path, with the AVX2 kernels and without.
    CRSPLINE_SEEDED(s, 73);
    std::mt19937_64 rng(s);
    for (const auto& c : curves(rng)) {
        const std::size_t n = 20000;
        std::vector<double> t(n);
        for (std::size_t k = 0; k < n; ++k) t[k] = c.t_min() + (c.t_max() - c.t_min()) * double(k) / double(n - 1);
        t.back() = c.t_max();
        std::uniform_int_distribution<std::size_t> at(1, n - 3);
        const std::size_t k0 = at(rng);
        std::swap(t[k0], t[k0 + 1]);
        const auto [fast, portable] = both_paths([&] { return c.evaluate(std::span<const double>(t)); });
        for (std::size_t k = 0; k < n; ++k) {
            const P3 x = c.evaluate(t[k]);
            ASSERT_TRUE(same_bits(fast[k], x)) << "k " << k << " (swapped at " << k0 << ")";
            ASSERT_TRUE(same_bits(portable[k], x)) << "k " << k << " (swapped at " << k0 << ")";
        }
    }
}

TEST(Kernels, ArcLengthRulesAgreeBitForBit) {
    // The Gauss-Legendre rules compiled for AVX2 (gauss_length_rule_avx2,
    // issue 30) against the portable ones: total lengths, per-segment
    // lengths and the table's inverse, at two accuracies, 2-D and 3-D, on
    // the storage cases of curves() and on uneven random walks.
    CRSPLINE_SEEDED(s, 75);
    std::mt19937_64 rng(s);
    std::size_t checked = 0;
    auto compare = [&](const auto& c) {
        for (double acc : {1e-12, 1e-7}) {
            const auto [fast, portable] = both_paths([&] {
                std::vector<double> out{arc_length(c, acc)};
                const arc_length_table tab(c, acc);
                for (std::size_t i = 0; i < c.segment_count(); ++i) out.push_back(tab.segment_length(i));
                for (int k = 0; k <= 16; ++k) out.push_back(tab.t_at(tab.total() * k / 16));
                return out;
            });
            ASSERT_EQ(fast.size(), portable.size());
            for (std::size_t k = 0; k < fast.size(); ++k) {
                ASSERT_EQ(std::memcmp(&fast[k], &portable[k], sizeof(double)), 0) << "acc " << acc << " value " << k;
                ++checked;
            }
        }
    };
    for (const auto& c : curves(rng)) compare(c);
    std::lognormal_distribution<double> step(0.0, 1.0);
    std::normal_distribution<double> g;
    for (int rep = 0; rep < 4; ++rep) {
        std::vector<vec<2>> p(40);
        for (std::size_t i = 1; i < p.size(); ++i) {
            vec<2> d{{g(rng), g(rng)}};
            p[i] = p[i - 1] + (step(rng) / norm(d)) * d;
        }
        compare(catmull_rom<2>(p, {.alpha = rep % 2 ? 0.5 : 1.0, .closed = rep == 3}));
    }
    EXPECT_GT(checked, 2u * (6 + 4) * 20u);
    // Every rule of rule_sizes by itself (the AVX2 clone takes the nodes'
    // square roots four at a time, the portable code two: issue 30), on
    // random 3-D segments over random sub-intervals, the sub-interval's ends
    // also at 0 and 1.
    std::size_t rules = 0;
    std::uniform_real_distribution<double> U(0, 1);
    for (int rep = 0; rep < 50; ++rep) {
        cubic_segment<3> seg;
        for (std::size_t k = 0; k < 3; ++k) seg.c1[k] = g(rng), seg.c2[k] = g(rng), seg.c3[k] = g(rng);
        seg.h = seg.inv_h = 1;
        double a = U(rng), b = U(rng);
        if (a > b) std::swap(a, b);
        if (rep % 5 == 0) a = 0, b = 1;
        for (int n : detail::rule_sizes) {
            const auto [fast, portable] = both_paths([&] { return detail::gauss_length_rule(seg, a, b, n); });
            ASSERT_EQ(std::memcmp(&fast, &portable, sizeof(double)), 0)
                << n << " points, rep " << rep << " on [" << a << ", " << b << "]";
            ++rules;
        }
    }
    EXPECT_EQ(rules, 50u * std::size(detail::rule_sizes));
}

TEST(Kernels, ArcLengthHardSegmentsAgreeBitForBit) {
    // The arc-length cases of issue 30's tail, through the batch (Halley in
    // lanes, the rule choice, the halves' rules, the slower path) with AVX2
    // and without: a speed zero at an end (tension 1), C'(u) = A + C (u -
    // v)^2 (Halley's start on a line of symmetry), and near-cusps (branch
    // points close to [0, 1]). Every piece's ends, length and rule, bit for
    // bit.
    CRSPLINE_SEEDED(s, 76);
    std::mt19937_64 rng(s);
    std::normal_distribution<double> g;
    std::uniform_real_distribution<double> U(0, 1);
    auto rv = [&] { return P3{{g(rng), g(rng), g(rng)}}; };
    std::vector<cubic_segment<3>> segs;
    for (int k = 0; k < 64; ++k) {
        const P3 m = rv();
        segs.push_back(cubic_segment<3>::hermite(rv(), rv(), k % 2 ? P3{} : m, k % 2 ? m : P3{}, 0.0, 1.0));
        const P3 A = rv(), C0 = rv(), C = dot(A, C0) > 0 ? C0 : -1.0 * C0;
        const double v = 0.25 * double(k % 5);
        cubic_segment<3> e;
        e.c1 = A + (v * v) * C, e.c2 = -v * C, e.c3 = C / 3.0, e.h = e.inv_h = 1;
        segs.push_back(e);
        const P3 n = rv(), E = rv(), F = rv();
        const double w = -0.3 + 1.6 * U(rng), d = norm(E) * std::pow(10.0, -3 * U(rng));
        cubic_segment<3> c;
        c.c1 = (d / norm(n)) * n - w * E + (w * w) * F, c.c2 = (E - (2 * w) * F) / 2.0, c.c3 = F / 3.0;
        c.h = c.inv_h = 1;
        segs.push_back(c);
    }
    std::size_t checked = 0;
    for (double acc : {1e-12, 1e-7}) {
        const auto [fast, portable] = both_paths([&] {
            std::vector<double> out;
            detail::for_each_segment_length_piece(
                segs.size(), [&](std::size_t i) { return segs[i]; }, acc,
                [&](std::size_t i, double u0, double u1, double len, const detail::rule_choice& rc) {
                    out.insert(out.end(), {double(i), u0, u1, len, double(rc.n), rc.bound});
                });
            return out;
        });
        ASSERT_EQ(fast.size(), portable.size()) << "acc " << acc;
        for (std::size_t k = 0; k < fast.size(); ++k, ++checked)
            ASSERT_EQ(std::memcmp(&fast[k], &portable[k], sizeof(double)), 0) << "acc " << acc << " value " << k;
    }
    // At least one piece per segment at each accuracy, six numbers each.
    EXPECT_GE(checked, 2u * 6u * segs.size());
    // The batch (lanes of four) against one segment at a time (the rule
    // choice in scalar, choose_rule), on either path: the same pieces, rules
    // and bounds (both proofs of the rule, issue 30).
    std::size_t single = 0;
    for (double acc : {1e-12, 1e-7}) {
        const auto [batch, one] = both_paths([&] {
            std::vector<double> b, o;
            detail::for_each_segment_length_piece(
                segs.size(), [&](std::size_t i) { return segs[i]; }, acc,
                [&](std::size_t, double u0, double u1, double len, const detail::rule_choice& rc) {
                    b.insert(b.end(), {u0, u1, len, double(rc.n), rc.bound, rc.rho, rc.ratio});
                });
            for (const auto& seg : segs)
                detail::for_each_length_piece(seg, 0.0, 1.0, acc, [&](double u0, double u1, double len,
                                                                      const detail::rule_choice& rc) {
                    o.insert(o.end(), {u0, u1, len, double(rc.n), rc.bound, rc.rho, rc.ratio});
                });
            return std::pair(b, o);
        });
        for (const auto& [b, o] : {batch, one}) {
            ASSERT_EQ(b.size(), o.size()) << "acc " << acc;
            for (std::size_t k = 0; k < b.size(); ++k, ++single)
                ASSERT_EQ(std::memcmp(&b[k], &o[k], sizeof(double)), 0) << "acc " << acc << " value " << k;
        }
    }
    EXPECT_GE(single, 2u * 2u * 7u * segs.size());
}

/// Every vertex parameter and point of tessellate(c, tol) on each path
/// (AVX-512 where the CPU has it: eight lanes a group; AVX2: four; portable:
/// one segment at a time), bit for bit against the portable one; returns how
/// many numbers were compared.
template <std::size_t D>
std::size_t compare_tessellations(const catmull_rom<D>& c, double tol, const char* what) {
    bool& wide = detail::avx512_enabled();
    const bool had = wide;
    std::vector<std::pair<polyline<D>, const char*>> fast;
    polyline<D> portable;
    if (had) {
        fast.emplace_back(tessellate(c, tol), "AVX-512");
        wide = false;
    }
    auto [avx2, one_by_one] = both_paths([&] { return tessellate(c, tol); });
    wide = had;
    fast.emplace_back(std::move(avx2), "AVX2");
    portable = std::move(one_by_one);
    std::size_t n = 0;
    for (const auto& [pl, path] : fast) {
        EXPECT_EQ(pl.t.size(), portable.t.size()) << what << " " << path << " tol " << tol;
        if (pl.t.size() != portable.t.size()) continue;
        for (std::size_t k = 0; k < pl.t.size(); ++k) {
            EXPECT_EQ(std::memcmp(&pl.t[k], &portable.t[k], sizeof(double)), 0)
                << what << " " << path << " tol " << tol << " t " << k;
            EXPECT_EQ(std::memcmp(&pl.points[k], &portable.points[k], sizeof(vec<D>)), 0)
                << what << " " << path << " tol " << tol << " point " << k;
            n += 1 + D;
        }
    }
    return n;
}

TEST(Kernels, TessellationLanesAgreeBitForBit) {
    // The greedy cut of tessellate() in two groups of four lanes with AVX2,
    // of eight with AVX-512 (detail/tessellate_lanes.hpp, issue 30), each
    // against the portable cut, one
    // segment at a time: the same vertices, bit for bit, on walks long
    // enough that every lane refills many times (blocks of 1,024 segments),
    // at tolerances from a few vertices a segment to hundreds, in 1 to 5
    // dimensions, open and closed, with repeated points (constant segments),
    // tension 1 (speed zeros at the knots) and coordinates near 1e-150 and
    // 1e150 (the norms' rescaled path).
    if (!detail::avx2_enabled()) GTEST_SKIP() << "no AVX2 on this CPU or build: one path only";
    CRSPLINE_SEEDED(s, 77);
    std::mt19937_64 rng(s);
    std::normal_distribution<double> g;
    std::size_t checked = 0;
    for (int rep = 0; rep < 12; ++rep) {
        const double scale = rep % 4 == 1 ? 1e-150 : rep % 4 == 2 ? 1e150 : 1.0;
        std::vector<vec<3>> p(rep < 2 ? 2500 : 70 + 7 * rep);
        for (auto& q : p) q = P3{{scale * g(rng), scale * g(rng), scale * g(rng)}};
        for (std::size_t k = 5; k + 1 < p.size(); k += 11) p[k + 1] = p[k];  // constant segments
        options<3> o{.alpha = rep % 3 * 0.5, .closed = rep % 2 == 1};
        if (rep == 5) o.tension = 1.0;
        const catmull_rom<3> c(p, o);
        const double diag = tessellation_tolerance(c, 1.0);
        for (double rel : {1e-2, 1e-4, 1e-6}) checked += compare_tessellations(c, rel * diag, "3-D");
    }
    for (int rep = 0; rep < 4; ++rep) {
        // (At least detail::cut_lanes_from segments: shorter curves are cut
        // one by one on both paths.)
        std::vector<vec<1>> p1(80 + rep);
        std::vector<vec<2>> p2(80 + rep);
        std::vector<vec<5>> p5(80 + rep);
        for (auto& q : p1) q[0] = g(rng);
        for (auto& q : p2) q = vec<2>{{g(rng), g(rng)}};
        for (auto& q : p5)
            for (std::size_t k = 0; k < 5; ++k) q[k] = g(rng);
        checked += compare_tessellations(catmull_rom<1>(p1), 1e-4, "1-D");
        checked += compare_tessellations(catmull_rom<2>(p2, {.closed = rep % 2 == 1}), 1e-4, "2-D");
        checked += compare_tessellations(catmull_rom<5>(p5), 1e-4, "5-D");
    }
    // At least: the two long walks at 1e-6 of their diagonal cut into more
    // than 10 vertices a segment, 4 numbers each, on each fast path.
    const std::size_t paths = detail::avx512_enabled() ? 2 : 1;
    EXPECT_GT(checked, paths * 2u * 2500u * 10u * 4u);
}

TEST(Kernels, MagnitudeReductionMatchesALoop) {
    // detail::max_abs_finite (SSE2, four accumulators; the construction's
    // checks, issue 30) against a plain loop: the same maximum, and "not
    // finite" exactly when the array holds a NaN or an infinity, at every
    // length around the vector width and every position of the bad value.
    CRSPLINE_SEEDED(s, 76);
    std::mt19937_64 rng(s);
    std::uniform_real_distribution<double> U(-1e3, 1e3);
    std::size_t checked = 0;
    for (std::size_t n = 0; n < 23; ++n) {
        std::vector<double> x(n);
        for (auto& v : x) v = U(rng);
        double m = 0;
        for (double v : x) m = std::max(m, std::abs(v));
        const auto r = detail::max_abs_finite(x.data(), n);
        ASSERT_TRUE(r.finite) << "n " << n;
        ASSERT_EQ(r.max_abs, m) << "n " << n;
        for (std::size_t at = 0; at < n; ++at)
            for (double bad : {std::nan(""), HUGE_VAL, -HUGE_VAL}) {
                std::vector<double> y = x;
                y[at] = bad;
                ASSERT_FALSE(detail::max_abs_finite(y.data(), n).finite) << "n " << n << " at " << at << " " << bad;
                ++checked;
            }
    }
    EXPECT_EQ(checked, 3u * (22 * 23 / 2));
}

TEST(Kernels, AvxBatchReportsTheFirstBadIndex) {
    const std::vector<P3> p{P3{{0, 0, 0}}, P3{{1, 0, 0}}, P3{{1, 1, 0}}, P3{{0, 1, 1}}};
    const catmull_rom<3> c(p);
    std::vector<double> t(100, c.t_min());
    for (std::size_t k = 0; k < t.size(); ++k) t[k] = c.t_max() * double(k % 7) / 7.0;  // unsorted
    t[41] = std::nan("");
    t[63] = c.t_max() + 1;
    try {
        (void)c.evaluate(std::span<const double>(t));
        FAIL() << "no error";
    } catch (const out_of_domain& e) {
        EXPECT_NE(std::string(e.what()).find("index 41"), std::string::npos) << e.what();
    }
}

}  // namespace
