// The crossing decision (issue 27): verdicts against an independent exact
// check, and the properties the issue asks for.
//
//  * Corpus (seeded, seed printed): random walks of 5-12 points (uniform,
//    centripetal, chordal, centripetal with tension 0.3; 150 each, the
//    issue's table), Kochanek-Bartels and Hermite walks, spirals, glyph-like
//    closed curves, a near-tangent family (a dent at gap g over a straight
//    line, g from 1e-1 to 1e-12 of the size, 0 and negative), and walks
//    moved by 1e8 and scaled by 1e8 and 1e-8.
//  * The committed file data/decision_corpus.json holds that corpus's Bézier
//    points (written by this test with CRSPLINE_WRITE_DECISION_CORPUS=path)
//    and the verdicts of tests/analysis/exact_decision.py, which decides
//    each curve in exact integer arithmetic, written apart from the library.
//    Every verdict here must agree with it.
//  * Live, on the seeded corpus: the fast path (the paper's certificate)
//    never disagrees with the full decision; every random walk is decided
//    (simple or crosses, count asserted); every contact is within the floor;
//    no curve of the near-tangent family with a gap above 1e-9 of its size
//    touches. The touches fraction is printed.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "json_tree_builder.hpp"

#include <crspline/decision.hpp>

#include "test_support.hpp"

namespace {
using namespace crspline;
using P = vec<2>;
using json = nlohmann::json;

struct corpus_curve {
    std::string kind;
    std::size_t index = 0;  // within its kind
    catmull_rom<2> curve;
    double gap = 0;         // near_tangent: the dent's gap (relative to the size); else 0
};

std::vector<P> walk(std::mt19937_64& rng, std::size_t n) {
    std::normal_distribution<double> g(0.0, 1.0);
    std::vector<P> p(n);
    for (std::size_t i = 1; i < n; ++i) p[i] = p[i - 1] + P{{g(rng), g(rng)}};
    return p;
}

// The near-tangent family: a straight run along y = 0 and a return whose
// dent reaches down to (3, gap) with a horizontal tangent (by symmetry): the
// nearest approach of the two runs is |gap| (crossing twice when gap < 0).
std::vector<P> dent(double gap) {
    return {P{{0, 0}}, P{{1, 0}}, P{{2, 0}}, P{{3, 0}}, P{{4, 0}}, P{{5, 0}}, P{{6, 0}}, P{{7, 0.5}},
            P{{6, 1}},  P{{5, 1}}, P{{4, 0.6}}, P{{3, gap}}, P{{2, 0.6}}, P{{1, 1}}, P{{0, 1}}};
}

std::vector<corpus_curve> make_corpus(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<std::size_t> npts(5, 12);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    std::vector<corpus_curve> out;
    auto add = [&](std::string kind, std::size_t i, catmull_rom<2> c, double gap = 0) {
        out.push_back({std::move(kind), i, std::move(c), gap});
    };
    // 1. The issue's walks, 150 of each kind.
    for (std::size_t i = 0; i < 150; ++i) add("walk_uniform", i, catmull_rom<2>(walk(rng, npts(rng)), {.alpha = 0.0}));
    for (std::size_t i = 0; i < 150; ++i) add("walk_centripetal", i, catmull_rom<2>(walk(rng, npts(rng)), {.alpha = 0.5}));
    for (std::size_t i = 0; i < 150; ++i) add("walk_chordal", i, catmull_rom<2>(walk(rng, npts(rng)), {.alpha = 1.0}));
    for (std::size_t i = 0; i < 150; ++i)
        add("walk_tension", i, catmull_rom<2>(walk(rng, npts(rng)), {.alpha = 0.5, .tension = 0.3}));
    // 2. Kochanek-Bartels, closed curves of any alpha, Hermite with random tangents.
    for (std::size_t i = 0; i < 40; ++i) {
        const auto p = walk(rng, npts(rng));
        kochanek_bartels<double> kb;
        for (std::size_t k = 0; k < p.size(); ++k) {
            kb.tension.push_back(U(rng) - 0.5);
            kb.continuity.push_back(U(rng) - 0.5);
            kb.bias.push_back(U(rng) - 0.5);
        }
        add("walk_kb", i, catmull_rom<2>(p, {.alpha = U(rng), .kb = kb}));
    }
    for (std::size_t i = 0; i < 40; ++i) add("walk_closed", i, catmull_rom<2>(walk(rng, npts(rng)), {.alpha = U(rng), .closed = true}));
    for (std::size_t i = 0; i < 30; ++i) {
        const auto p = walk(rng, npts(rng));
        std::normal_distribution<double> g(0.0, 1.0);
        std::vector<P> v(p.size());
        std::vector<double> grid(p.size());
        for (std::size_t k = 0; k < p.size(); ++k) {
            v[k] = P{{g(rng), g(rng)}};
            grid[k] = double(k) + (k ? 0.5 * U(rng) : 0.0);
        }
        add("hermite", i, catmull_rom<2>::hermite(p, v, grid));
    }
    // 3. Spirals (simple), and spirals closed back to their start (crossing).
    for (std::size_t i = 0; i < 20; ++i) {
        const std::size_t n = 10 + 2 * i;
        const double turn = 0.3 + 0.6 * U(rng);
        std::vector<P> p(n);
        for (std::size_t k = 0; k < n; ++k) {
            const double th = turn * double(k), r = 0.2 + 0.15 * th;
            p[k] = P{{r * std::cos(th), r * std::sin(th)}};
        }
        const double alphas[] = {0.0, 0.5, 1.0};
        add("spiral", i, catmull_rom<2>(p, {.alpha = alphas[i % 3]}));
        add("spiral_closed", i, catmull_rom<2>(p, {.alpha = alphas[i % 3], .closed = true}));
    }
    // 4. Glyph-like closed curves: star-shaped loops with random radii (some
    //    fold over themselves where the radius jumps).
    for (std::size_t i = 0; i < 60; ++i) {
        const std::size_t n = 5 + i % 10;
        std::vector<P> p(n);
        for (std::size_t k = 0; k < n; ++k) {
            const double th = 2 * std::numbers::pi * (double(k) + 0.4 * U(rng)) / double(n);
            const double r = 0.3 + U(rng);
            p[k] = P{{r * std::cos(th), r * std::sin(th)}};
        }
        add("glyph", i, catmull_rom<2>(p, {.alpha = double(i % 3) / 2, .closed = true}));
    }
    // 5. Near-tangent family.
    std::size_t k = 0;
    for (const double alpha : {0.0, 0.5, 1.0}) {
        for (int e = 1; e <= 12; ++e) {
            add("near_tangent", k++, catmull_rom<2>(dent(std::pow(10.0, -e)), {.alpha = alpha}), std::pow(10.0, -e));
            add("near_tangent", k++, catmull_rom<2>(dent(-std::pow(10.0, -e)), {.alpha = alpha}), -std::pow(10.0, -e));
        }
        add("near_tangent", k++, catmull_rom<2>(dent(0.0), {.alpha = alpha}), 0.0);
    }
    // 6. Figure eights through one of their points (a crossing at a vertex),
    //    and walks with a point repeated (issue 31 point 4: a zero-length
    //    segment for alpha > 0, a loop back to the point for alpha = 0).
    for (std::size_t i = 0; i < 30; ++i) {
        std::normal_distribution<double> g(0.0, 0.15);
        std::vector<P> p{P{{0, 0}}, P{{2, 2}}, P{{4, 0}}, P{{2, -2}}, P{{0, 0}}, P{{-2, 2}}, P{{-4, 0}}, P{{-2, -2}}};
        for (std::size_t j = 0; j < p.size(); ++j)
            if (j % 4 != 0) p[j] += P{{g(rng), g(rng)}};
        add("figure_eight", i, catmull_rom<2>(p, {.alpha = double(i % 3) / 2, .closed = true}));
    }
    for (std::size_t i = 0; i < 30; ++i) {
        auto p = walk(rng, npts(rng));
        const std::size_t j = 1 + i % (p.size() - 2);
        p.insert(p.begin() + std::ptrdiff_t(j), p[j]);
        add("repeated_point", i, catmull_rom<2>(p, {.alpha = double(i % 3) / 2}));
    }
    // 7. Walks moved by 1e8, scaled by 1e8 and 1e-8.
    for (std::size_t i = 0; i < 30; ++i) {
        const auto p = walk(rng, npts(rng));
        const double alpha = double(i % 3) / 2;
        std::vector<P> moved(p), big(p), small(p);
        for (std::size_t j = 0; j < p.size(); ++j) {
            moved[j] = p[j] + P{{1e8, -1e8}};
            big[j] = p[j] * 1e8;
            small[j] = p[j] * 1e-8;
        }
        add("offset_1e8", i, catmull_rom<2>(moved, {.alpha = alpha}));
        add("scale_1e8", i, catmull_rom<2>(big, {.alpha = alpha}));
        add("scale_1e-8", i, catmull_rom<2>(small, {.alpha = alpha}));
    }
    // 8. Hairpins: windows of 8 points around the tight turns of the
    //    10^6-point walk of bench/cli_bench.py (seed 20240601; segments
    //    9992, 16998, 29527, 58385, 61403, 79405 of that walk are the
    //    window's 4th), each behind a point 600 units away so that the
    //    curve is as large as the walk: the turns' tiny loops (a few 1e-9
    //    across) lay below the former floor of 2^-32 of the extent and came
    //    out as contacts; at 2^-42 their crossings are proved.
    const std::vector<std::vector<P>> hairpins{
        {P{{55.940881888653635, -117.58553912300086}}, P{{57.86648835986913, -117.35738397823383}}, P{{60.03453138823462, -116.92853197938256}}, P{{60.21326467628653, -116.72925798870604}}, P{{59.05330489704217, -117.12965564479514}}, P{{59.299928784095925, -117.04466963238862}}, P{{63.19150049798128, -123.45935670557978}}, P{{61.97982383634643, -122.2166437577591}}},
        {P{{195.65234397214113, -242.1156358460793}}, P{{194.60614256986474, -241.91885650621936}}, P{{194.59611105099646, -242.1895375911426}}, P{{195.11295398000922, -242.14110669097605}}, P{{194.85178976259883, -241.70448434730122}}, P{{195.05626285205142, -242.04567288122456}}, P{{194.82577205055344, -241.27869375824298}}, P{{194.636679247141, -241.47074255133307}}},
        {P{{363.4250419871278, -306.6602107093461}}, P{{363.25121928856424, -306.5933174176327}}, P{{361.9304977266898, -306.7107318553127}}, P{{363.2428933839628, -305.419006930174}}, P{{362.6826926800536, -304.60596256805303}}, P{{362.9123260701041, -304.9387283178879}}, P{{364.0182215787864, -304.84009448930175}}, P{{364.43433783732536, -304.83305201832917}}},
        {P{{14.58086509223288, -378.0391254927623}}, P{{13.44155815581793, -376.6845141294466}}, P{{13.15125443258658, -379.94905158123305}}, P{{13.388204439779724, -379.67147405070085}}, P{{12.754555828667307, -379.75964835435315}}, P{{12.872458715109367, -379.74324935356407}}, P{{12.366550799359109, -381.60766877807356}}, P{{11.574951520484273, -381.1456341221086}}},
        {P{{147.91163523357696, -420.8649427784612}}, P{{147.1333488032101, -420.7975100167088}}, P{{147.2498008413794, -420.7359696158883}}, P{{147.98122562108375, -418.47748847927363}}, P{{147.91032275281208, -417.4945084504298}}, P{{147.99121056822426, -418.6138851082799}}, P{{147.8299231785087, -419.2407815035379}}, P{{148.0936931525669, -419.26486075303944}}},
        {P{{486.1404175018032, -327.10197311248834}}, P{{486.94726548085646, -326.71442104492627}}, P{{486.29442106277907, -326.30525690373383}}, P{{487.09940798370826, -323.8867407264958}}, P{{485.3734248248227, -323.8553944531908}}, P{{485.7725662010126, -323.8626257622506}}, P{{489.26566981110096, -324.30274050772556}}, P{{489.3473894377865, -323.3410852289597}}},
    };
    for (std::size_t i = 0; i < hairpins.size(); ++i) {
        std::vector<P> p{hairpins[i][0] - P{{600, 0}}};
        p.insert(p.end(), hairpins[i].begin(), hairpins[i].end());
        add("hairpin", i, catmull_rom<2>(p, {.alpha = 0.5}));
    }
    return out;
}

constexpr std::uint64_t corpus_seed = 27;  // the committed corpus was written with this seed

std::string corpus_path() { return std::string(CRSPLINE_REFERENCE_DIR) + "/../analysis/data/decision_corpus.json"; }

// CRSPLINE_WRITE_DECISION_CORPUS=path writes the corpus (for exact_decision.py).
TEST(Decision, WriteCorpusWhenAsked) {
    const char* path = std::getenv("CRSPLINE_WRITE_DECISION_CORPUS");
    if (!path) GTEST_SKIP() << "set CRSPLINE_WRITE_DECISION_CORPUS=path to write the corpus";
    const auto corpus = make_corpus(corpus_seed);
    std::FILE* f = std::fopen(path, "w");
    ASSERT_TRUE(f);
    std::fprintf(f, "{\"provenance\":\"tests/analysis/test_decision.cpp make_corpus(seed %llu): Bezier points of each "
                    "curve as catmull_rom::bezier() returns them (17 significant digits)\",\"curves\":[\n",
                 (unsigned long long)corpus_seed);
    for (std::size_t i = 0; i < corpus.size(); ++i) {
        const auto& c = corpus[i];
        std::fprintf(f, "%s{\"kind\":\"%s\",\"index\":%zu,\"gap\":%.17g,\"closed\":%s,\"segments\":[", i ? ",\n" : "",
                     c.kind.c_str(), c.index, c.gap, c.curve.closed() ? "true" : "false");
        const auto b = c.curve.bezier();
        for (std::size_t s = 0; s < b.size(); ++s) {
            std::fprintf(f, "%s[", s ? "," : "");
            for (std::size_t q = 0; q < 4; ++q) std::fprintf(f, "%s[%.17g,%.17g]", q ? "," : "", b[s][q][0], b[s][q][1]);
            std::fprintf(f, "]");
        }
        std::fprintf(f, "]}");
    }
    std::fprintf(f, "\n]}\n");
    std::fclose(f);
}

// Each crossing as the exact check names it: a pair of "s<segment>", or
// "v<vertex>" for a crossing at a vertex (u within 1e-9 of a segment's end:
// the corpus has none so close that is not at the vertex itself).
std::set<std::pair<std::string, std::string>> crossing_keys(const decision& d, std::size_t segments) {
    std::set<std::pair<std::string, std::string>> s;
    for (const auto& c : d.crossings) {
        std::string k[2];
        for (std::size_t q = 0; q < 2; ++q) {
            if (std::abs(c.u[q][0] - 1) < 1e-9 && std::abs(c.u[q][1] - 1) < 1e-9)
                k[q] = "v" + std::to_string((c.segment[q] + 1) % segments);
            else if (std::abs(c.u[q][0]) < 1e-9 && std::abs(c.u[q][1]) < 1e-9)
                k[q] = "v" + std::to_string(c.segment[q]);
            else
                k[q] = "s" + std::to_string(c.segment[q]);
        }
        s.insert({std::min(k[0], k[1]), std::max(k[0], k[1])});
    }
    return s;
}

// Every verdict agrees with the exact check.
TEST(Decision, AgreesWithTheExactCheck) {
    std::ifstream in(corpus_path());
    ASSERT_TRUE(in) << corpus_path();
    const json corpus = json::parse(in);
    std::size_t checked = 0, touches = 0;
    std::map<std::string, std::size_t> by_verdict;
    for (const auto& c : corpus["curves"]) {
        SCOPED_TRACE(c["kind"].get<std::string>() + " " + std::to_string(c["index"].get<std::size_t>()));
        std::vector<std::array<P, 4>> segs;
        for (const auto& s : c["segments"]) {
            std::array<P, 4> b;
            for (std::size_t q = 0; q < 4; ++q) b[q] = P{{s[q][0].get<double>(), s[q][1].get<double>()}};
            segs.push_back(b);
        }
        const decision d = decide(bezier_path{segs, c["closed"].get<bool>()});
        const auto& ex = c["exact"];
        const std::string exact = ex["verdict"];
        ++by_verdict[to_string(d.result)];
        if (d.result == verdict::touches) {
            ++touches;
            // A contact is within the floor; the exact check found no crossing either.
            EXPECT_NE(exact, "crosses");
            for (const auto& t : d.touches) {
                EXPECT_FALSE(t.budget_exhausted);
                EXPECT_LE(t.distance, 4 * d.floor);
            }
        } else {
            EXPECT_EQ(to_string(d.result), exact);
            std::set<std::pair<std::string, std::string>> ep;
            for (const auto& p : ex["crossing_keys"]) ep.insert({p[0].get<std::string>(), p[1].get<std::string>()});
            EXPECT_EQ(crossing_keys(d, segs.size()), ep);
        }
        ++checked;
    }
    // The corpus as written: make_corpus's count (a shrunken file checks less).
    EXPECT_EQ(checked, make_corpus(corpus_seed).size());
    std::printf("%zu curves: simple %zu, crosses %zu, touches %zu (%.2f%%)\n", checked, by_verdict["simple"],
                by_verdict["crosses"], touches, 100.0 * double(touches) / double(checked));
}

// Live, on a seeded corpus (CRSPLINE_SEED to vary it).
TEST(Decision, LiveCorpusProperties) {
    CRSPLINE_SEEDED(seed, corpus_seed);
    const auto corpus = make_corpus(seed);
    std::size_t walks = 0, walks_decided = 0, fast = 0, touches = 0, near = 0, nonadjacent_contacts = 0;
    for (const auto& c : corpus) {
        SCOPED_TRACE(c.kind + " " + std::to_string(c.index));
        const decision d = decide(c.curve);
        const decision full = decide(c.curve, {.fast_path = false});
        // The fast path is only ever a shortcut to the same answer.
        if (d.fast_path) {
            ++fast;
            EXPECT_EQ(full.result, verdict::simple);
        } else {
            EXPECT_EQ(d.result, full.result);
        }
        if (full.result == verdict::touches) ++touches;
        const std::size_t n = c.curve.segment_count();
        for (const auto& t : full.touches) {
            EXPECT_FALSE(t.budget_exhausted);
            EXPECT_LE(t.distance, 4 * full.floor);
            // A contact between non-adjacent segments: the clearance sees it
            // too (within its accuracy, 1e-12 here). Contacts of a segment
            // with itself or its neighbour are cusps, folds and turns at a
            // vertex, which the clearance leaves out by definition.
            // Neighbours count through zero-length segments (issue 31 point 4).
            std::size_t between = 0;
            const std::size_t lo = std::min(t.segment[0], t.segment[1]), hi = std::max(t.segment[0], t.segment[1]);
            std::size_t live = 0;
            for (std::size_t q = 0; q < n; ++q) {
                const auto b = c.curve.bezier(q);
                const bool point = b[0] == b[1] && b[1] == b[2] && b[2] == b[3];
                live += !point;
                between += !point && q > lo && q < hi;
            }
            const std::size_t around = live - between - 2;  // the other way round a closed curve
            const bool neighbours = lo == hi || between == 0 || (c.curve.closed() && around == 0);
            if (!neighbours) {
                ++nonadjacent_contacts;
                EXPECT_LE(clearance(c.curve, 1e-12).distance, t.distance + 1e-12);
            }
        }
        if (c.kind.rfind("walk_", 0) == 0 && c.kind != "walk_kb" && c.kind != "walk_closed") {
            ++walks;
            if (full.result != verdict::touches) ++walks_decided;
        }
        if (c.kind == "near_tangent") {
            ++near;
            // The size is about 7 (the curve spans [0, 7] x [0, 1]).
            if (std::abs(c.gap) > 1e-9 * 7) {
                EXPECT_NE(full.result, verdict::touches) << "gap " << c.gap;
            }
            if (c.gap > 1e-9 * 7) {
                EXPECT_EQ(full.result, verdict::simple) << "gap " << c.gap;
            }
            if (c.gap < -1e-9 * 7) {
                EXPECT_EQ(full.result, verdict::crosses) << "gap " << c.gap;
            }
        }
    }
    EXPECT_EQ(walks, 600u);
    EXPECT_EQ(walks_decided, 600u);  // the issue's table, all decided
    EXPECT_EQ(near, 75u);
    EXPECT_GT(fast, 0u);
    EXPECT_GT(nonadjacent_contacts, 0u);  // the near-tangent family's exact tangencies, at least
    std::printf("seed %llu: %zu curves, %zu decided by the paper's certificate, touches %zu (%.2f%%)\n",
                (unsigned long long)seed, corpus.size(), fast, touches, 100.0 * double(touches) / double(corpus.size()));
}

// The floor is a few ulps of the coordinates, and gaps at that scale are
// decided: the dent over the line at gaps of m floors, m from 1/4 to 64,
// on both sides (simple above the line; below, two crossings, both proved),
// at scales 2^-30, 1 and 2^30 (powers of two keep the dent's tangent at
// (3, gap) exactly horizontal, so the nearest approach is |gap| exactly,
// and the answer is known without an exact check). Only the exact tangency
// (gap 0) touches, within 4 floors. Checked to fail before the fine pieces
// (margins a few hundred eps of the extent, floor 2^-42 of it): gaps of one
// floor and less above the line, and crossings 4 floors deep, came out as
// `touches`, and at 64 floors deep only with two contacts beside them.
TEST(Decision, FloorIsAFewUlpsAndGapsAboveItAreDecided) {
    std::size_t decided = 0;
    for (const double scale : {0x1p-30, 1.0, 0x1p30})
        for (const double alpha : {0.0, 0.5, 1.0}) {
            const auto scaled = [&](double gap) {
                auto p = dent(gap);
                for (auto& x : p) x = x * scale;
                return catmull_rom<2>(p, {.alpha = alpha});
            };
            const decision d0 = decide(scaled(0.0), {.fast_path = false});
            SCOPED_TRACE("scale " + std::to_string(scale) + " alpha " + std::to_string(alpha));
            // delta = 4 eps of the largest coordinate (7 scale): 4 to 8 ulps of it.
            const double Mc = 7 * scale, ulp = std::nextafter(Mc, 2 * Mc) - Mc;
            EXPECT_LE(d0.floor, 8 * ulp);
            EXPECT_GE(d0.floor, 4 * ulp);
            ASSERT_EQ(d0.result, verdict::touches);
            for (const auto& t : d0.touches) EXPECT_LE(t.distance, 4 * d0.floor);
            for (const double m : {0.25, 1.0, 4.0, 64.0}) {
                const double gap = m * d0.floor / scale;  // in the unscaled dent (scaling is exact)
                const decision above = decide(scaled(gap), {.fast_path = false});
                const decision below = decide(scaled(-gap), {.fast_path = false});
                EXPECT_EQ(above.result, verdict::simple) << "gap " << m << " floors";
                EXPECT_EQ(below.result, verdict::crosses) << "gap -" << m << " floors";
                EXPECT_EQ(below.crossings.size(), 2u) << "gap -" << m << " floors";
                EXPECT_TRUE(below.touches.empty()) << "gap -" << m << " floors";
                decided += 2;
            }
        }
    EXPECT_EQ(decided, 3u * 3u * 4u * 2u);
}

// Hand-made cases, one argument each.
TEST(Decision, HandMadeCases) {
    // A crossing, proved: uniform curve whose last segment comes back across the first.
    const catmull_rom<2> x(std::vector<P>{P{{0, 0}}, P{{4, 0}}, P{{4, 3}}, P{{2, -2}}}, {.alpha = 0.0});
    const decision dx = decide(x);
    ASSERT_EQ(dx.result, verdict::crosses);
    ASSERT_EQ(dx.crossings.size(), 1u);
    const auto& cr = dx.crossings[0];
    // The two intervals contain the crossing: both curves' points there agree
    // to within the intervals' width times the speed (a few ulps of 4: 1e-13).
    const auto s0 = x.segment(cr.segment[0]), s1 = x.segment(cr.segment[1]);
    const double u0 = (cr.u[0][0] + cr.u[0][1]) / 2, u1 = (cr.u[1][0] + cr.u[1][1]) / 2;
    EXPECT_LT(norm(s0.at(u0) - s1.at(u1)), 1e-12);
    EXPECT_LT(cr.u[0][1] - cr.u[0][0], 1e-12);
    // Issue 31 point 4: a coincident point is not a crossing (neighbours through a zero-length segment).
    const catmull_rom<2> line(std::vector<P>{P{{0, 0}}, P{{1, 0}}, P{{1, 0}}, P{{2, 0}}});
    EXPECT_EQ(decide(line).result, verdict::simple);
    // The README's chordal curve decided (the certificate said not_centripetal).
    const catmull_rom<2> q(std::vector<P>{P{{0, 0}}, P{{1, 2}}, P{{3, 3}}, P{{4, 0}}}, {.alpha = 1.0});
    EXPECT_EQ(decide(q).result, verdict::simple);
    // Exact tangency: the dent touching the line -> touches, at distance 0 near (3, 0).
    const decision dt = decide(catmull_rom<2>(dent(0.0), {.alpha = 0.5}));
    ASSERT_EQ(dt.result, verdict::touches);
    ASSERT_FALSE(dt.touches.empty());
    for (const auto& t : dt.touches) EXPECT_LE(t.distance, 4 * dt.floor);
    // Bad input: a path whose segments do not join names the segment.
    const std::array<P, 4> s0b{P{{0, 0}}, P{{1, 0}}, P{{2, 0}}, P{{3, 0}}}, s1b{P{{3, 1}}, P{{4, 1}}, P{{5, 1}}, P{{6, 1}}};
    const std::array<P, 4> both[2] = {s0b, s1b};
    try {
        (void)decide(bezier_path{both, false});
        ADD_FAILURE() << "no error";
    } catch (const invalid_input& e) {
        EXPECT_NE(std::string(e.what()).find("segment 0 does not end where segment 1 starts"), std::string::npos) << e.what();
    }
}

// Two curves and a set of curves.
TEST(Decision, PairAndSet) {
    const catmull_rom<2> a(std::vector<P>{P{{0, 0}}, P{{1, 1}}, P{{2, 0}}});
    const catmull_rom<2> b(std::vector<P>{P{{0, 1}}, P{{1, 0}}, P{{2, 1}}});
    const catmull_rom<2> c(std::vector<P>{P{{0, 5}}, P{{1, 6}}, P{{2, 5}}});
    const decision ab = decide(a, b);
    EXPECT_EQ(ab.result, verdict::crosses);
    EXPECT_EQ(ab.crossings.size(), 2u);  // the arch and the valley cross twice
    for (const auto& x : ab.crossings) EXPECT_EQ(x.curve, (std::array<std::size_t, 2>{0, 1}));
    EXPECT_EQ(decide(a, c).result, verdict::simple);
    const std::vector<catmull_rom<2>> set{a, c, b};
    const decision s = decide(std::span<const catmull_rom<2>>(set));
    EXPECT_EQ(s.result, verdict::crosses);
    ASSERT_EQ(s.crossings.size(), 2u);
    for (const auto& x : s.crossings) EXPECT_EQ(x.curve, (std::array<std::size_t, 2>{0, 2}));
    // Seeded: n parallel walks shifted far apart never cross each other; set verdict simple.
    CRSPLINE_SEEDED(seed, 2701);
    std::mt19937_64 rng(seed);
    std::vector<catmull_rom<2>> apart;
    for (std::size_t i = 0; i < 50; ++i) {
        auto p = walk(rng, 8);
        for (auto& x : p) x = x * 0.02 + P{{double(i), 0}};
        apart.emplace_back(p);
    }
    EXPECT_EQ(decide(std::span<const catmull_rom<2>>(apart)).result, verdict::simple);
}

}  // namespace

// Clearance against brute force: dense samples of every non-adjacent pair of
// segments. The sampled minimum m is at least the true minimum, and at most
// the true minimum plus the samples' largest spacing s (each curve point is
// within s / 2 of a sample): so distance <= m + accuracy (the promise) and
// distance >= m - s.
template <std::size_t D>
void check_clearance(std::mt19937_64& rng, std::size_t cases) {
    std::normal_distribution<double> g(0.0, 1.0);
    std::size_t measured = 0;
    for (std::size_t i = 0; i < cases; ++i) {
        std::vector<vec<D>> p(6 + i % 6);
        for (std::size_t k = 1; k < p.size(); ++k)
            for (std::size_t d = 0; d < D; ++d) p[k][d] = p[k - 1][d] + g(rng);
        const bool closed = i % 4 == 3;
        const catmull_rom<D> c(p, {.alpha = double(i % 3) / 2, .closed = closed});
        const auto r = clearance(c, 1e-9);
        const std::size_t n = c.segment_count(), m = 400;
        double brute = std::numeric_limits<double>::infinity(), spacing = 0;
        std::vector<std::vector<vec<D>>> samples(n);
        for (std::size_t s = 0; s < n; ++s) {
            const auto b = c.bezier(s);
            for (std::size_t k = 0; k <= m; ++k) samples[s].push_back(bezier_at(b, double(k) / double(m)));
            for (std::size_t k = 0; k < m; ++k) spacing = std::max(spacing, norm(samples[s][k + 1] - samples[s][k]));
        }
        for (std::size_t s = 0; s < n; ++s)
            for (std::size_t t = s + 2; t < n; ++t) {
                if (closed && s == 0 && t == n - 1) continue;
                for (const auto& x : samples[s])
                    for (const auto& y : samples[t]) brute = std::min(brute, norm(x - y));
            }
        if (!std::isfinite(brute)) continue;
        ++measured;
        EXPECT_LE(r.distance, brute + 1e-9 + 1e-12) << "case " << i;
        EXPECT_GE(r.distance, brute - spacing) << "case " << i;
        EXPECT_LE(r.lower_bound, r.distance);
        EXPECT_LE(r.distance - r.lower_bound, 1e-9 * (1 + 1e-9));
        EXPECT_FALSE(r.exhausted);
        // The points reported are the curve's at the parameters reported (rounding: 1e-12 of a unit walk).
        EXPECT_LT(norm(r.points[0] - bezier_at(c.bezier(r.segment[0]), r.u[0])), 1e-12);
        EXPECT_LT(norm(r.points[1] - bezier_at(c.bezier(r.segment[1]), r.u[1])), 1e-12);
        EXPECT_NEAR(norm(r.points[0] - r.points[1]), r.distance, 1e-12);
    }
    EXPECT_EQ(measured, cases);  // every case has non-adjacent segments (at least 5 segments)
}

TEST(Decision, ClearanceAgainstBruteForce) {
    CRSPLINE_SEEDED(seed, 2702);
    std::mt19937_64 rng(seed);
    check_clearance<2>(rng, 20);
    check_clearance<3>(rng, 20);
    // Two curves: the hairpin's runs as two curves, 1e-3 apart.
    const catmull_rom<2> lo(std::vector<P>{P{{0, 0}}, P{{1, 0}}, P{{2, 0}}, P{{3, 0}}});
    const catmull_rom<2> hi(std::vector<P>{P{{0, 1}}, P{{1.5, 1e-3}}, P{{3, 1}}}, {.alpha = 0.0});
    const auto r = clearance(lo, hi, 1e-12);
    EXPECT_NEAR(r.distance, 1e-3, 1e-12);  // by symmetry the lowest point of hi is its vertex (1.5, 1e-3)
    EXPECT_EQ(r.curve, (std::array<std::size_t, 2>{0, 1}));
}

// The report value: the keys report.hpp's writer puts under "decision".
using json_builder = crspline_test::json_tree_builder;

TEST(Decision, ReportValue) {
    const catmull_rom<2> x(std::vector<P>{P{{0, 0}}, P{{4, 0}}, P{{4, 3}}, P{{2, -2}}}, {.alpha = 0.0});
    json_builder b;
    const json r = report_decision(b, decide(x));
    EXPECT_EQ(r["verdict"], "crosses");
    EXPECT_EQ(r["fast_path"], false);
    ASSERT_EQ(r["crossings"].size(), 1u);
    EXPECT_EQ(r["crossings"][0]["segments"], json::parse("[0, 2]"));
    EXPECT_EQ(r["crossings"][0]["u"].size(), 2u);
    EXPECT_TRUE(r["touches"].empty());
    // Every examined pair names at least one argument, and the crossing pair names "crossing".
    std::size_t crossing_named = 0;
    for (const auto& p : r["pairs"]) {
        EXPECT_FALSE(p["arguments"].empty());
        for (const auto& a : p["arguments"]) crossing_named += a == "crossing";
    }
    EXPECT_EQ(crossing_named, 1u);
    const json s = report_decision(b, decide(catmull_rom<2>(std::vector<P>{P{{0, 0}}, P{{1, 2}}, P{{3, 3}}, P{{4, 0}}})));
    EXPECT_EQ(s["verdict"], "simple");
    EXPECT_EQ(s["fast_path"], true);
    EXPECT_EQ(s["pairs"][0]["arguments"], json::parse(R"(["paper_rule"])"));
}
