// The candidate-pair search of find_intersections and of the certificate's
// rule 3 (a bounding-volume hierarchy, detail/box_tree.hpp) against a
// brute-force all-pairs reference written here: the same pairs of boxes,
// and through the seam (detail::find_intersections_among,
// detail::certify_among) exactly the same results, on seeded random curves
// in 2-D and 3-D, open and closed, with many crossings and near misses.
#include <cstdio>

#include <crspline/certify.hpp>
#include <crspline/detail/box_tree.hpp>
#include <crspline/intersections.hpp>

#include "test_support.hpp"

namespace {
using namespace crspline;
using crspline::test::pi;

// The reference enumeration: every pair i < j, in nested-loop order. The
// per-pair code then does its own box test, exactly as the all-pairs loops
// did before the tree.
struct all_pairs {
    template <std::size_t D, class T>
    detail::pair_rows operator()(const std::vector<detail::box<D, T>>& boxes, T) const {
        const std::size_t n = boxes.size();
        detail::pair_rows r;
        r.offsets.push_back(0);
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t j = i + 1; j < n; ++j) r.partners.push_back(std::uint32_t(j));
            r.offsets.push_back(r.partners.size());
        }
        return r;
    }
};

// Brute-force meeting pairs, the box test written out here.
template <std::size_t D, class T>
std::vector<std::array<std::uint32_t, 2>> brute_meeting_pairs(const std::vector<detail::box<D, T>>& b, T pad) {
    std::vector<std::array<std::uint32_t, 2>> out;
    for (std::size_t i = 0; i < b.size(); ++i)
        for (std::size_t j = i + 1; j < b.size(); ++j) {
            bool meet = true;
            for (std::size_t k = 0; k < D; ++k)
                meet = meet && !(b[i].lo[k] > b[j].hi[k] + pad) && !(b[j].lo[k] > b[i].hi[k] + pad);
            if (meet) out.push_back({std::uint32_t(i), std::uint32_t(j)});
        }
    return out;
}

std::vector<std::array<std::uint32_t, 2>> flatten(const detail::pair_rows& r, std::size_t n) {
    std::vector<std::array<std::uint32_t, 2>> out;
    for (std::size_t i = 0; i < n; ++i)
        for (const auto j : r.row(i)) out.push_back({std::uint32_t(i), j});
    return out;
}

template <std::size_t D, class T>
void expect_same(const intersection_result<D, T>& a, const intersection_result<D, T>& b, const std::string& what) {
    ASSERT_EQ(a.intersections.size(), b.intersections.size()) << what;
    for (std::size_t k = 0; k < a.intersections.size(); ++k) {
        const auto &x = a.intersections[k], &y = b.intersections[k];
        EXPECT_EQ(x.segments, y.segments) << what << " meeting " << k;
        EXPECT_EQ(x.u, y.u) << what << " meeting " << k;
        EXPECT_EQ(x.point, y.point) << what << " meeting " << k;
        EXPECT_EQ(x.distance, y.distance) << what << " meeting " << k;
    }
    ASSERT_EQ(a.overlaps.size(), b.overlaps.size()) << what;
    for (std::size_t k = 0; k < a.overlaps.size(); ++k) {
        EXPECT_EQ(a.overlaps[k].segments, b.overlaps[k].segments) << what << " overlap " << k;
        EXPECT_EQ(a.overlaps[k].u, b.overlaps[k].u) << what << " overlap " << k;
        EXPECT_EQ(a.overlaps[k].v, b.overlaps[k].v) << what << " overlap " << k;
    }
    EXPECT_EQ(a.folds, b.folds) << what;
    EXPECT_EQ(a.complete, b.complete) << what;
}

template <std::size_t D, class T>
void expect_same(const certificate<D, T>& a, const certificate<D, T>& b, const std::string& what) {
    EXPECT_EQ(a.certified, b.certified) << what;
    EXPECT_EQ(a.failed_rule, b.failed_rule) << what;
    EXPECT_EQ(a.vertex, b.vertex) << what;
    EXPECT_EQ(a.segment, b.segment) << what;
    EXPECT_EQ(a.segments, b.segments) << what;
    EXPECT_EQ(a.angle, b.angle) << what;
    EXPECT_EQ(a.detail, b.detail) << what;
    EXPECT_EQ(a.intersects, b.intersects) << what;
    expect_same(a.search, b.search, what + " (search)");
}

// A random walk snapped to a coarse integer grid (boxes that touch exactly,
// shared coordinates, many crossings in 2-D); consecutive duplicates removed.
template <std::size_t D>
std::vector<vec<D>> grid_walk(std::mt19937_64& rng, std::size_t n, int reach) {
    std::uniform_int_distribution<int> step(-reach, reach);
    std::vector<vec<D>> p{vec<D>{}};
    while (p.size() < n) {
        vec<D> q = p.back();
        for (std::size_t k = 0; k < D; ++k) q[k] += step(rng);
        if (!(q == p.back()) && (p.size() < 2 || !(q == p[p.size() - 2]))) p.push_back(q);
    }
    return p;
}

// A wavy strand out and its mirror image back, the mirror across the
// plane x[D-1] = 0, each strand at least delta / 2 from it at the control
// points: the strands come within about delta of each other once per wave
// (near misses, or near touches where the curve dips between points).
template <std::size_t D>
std::vector<vec<D>> hairpin(std::mt19937_64& rng, std::size_t half, double delta) {
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    std::vector<vec<D>> out;
    for (std::size_t i = 0; i < half; ++i) {
        vec<D> q{};
        q[0] = double(i) + 0.3 * U(rng);
        for (std::size_t k = 1; k + 1 < D; ++k) q[k] = 0.5 * U(rng);
        q[D - 1] = 0.4 + 0.4 * std::sin(0.7 * double(i)) + delta / 2;
        out.push_back(q);
    }
    for (std::size_t i = half; i-- > 0;) {
        vec<D> q = out[i];
        q[D - 1] = -q[D - 1];
        out.push_back(q);
    }
    return out;
}

// A planar spiral (in the first two axes; other axes a gentle wave) with
// `pitch` between turns and chords of about 1, with some jitter: tight
// pitches fail rule 3 somewhere, loose ones are certified.
template <std::size_t D>
std::vector<vec<D>> spiral(std::mt19937_64& rng, std::size_t n, double pitch, double jitter) {
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    std::vector<vec<D>> p(n);
    double theta = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double r = 4 + pitch * theta / (2 * pi);
        vec<D> q{};
        q[0] = r * std::cos(theta) + jitter * U(rng);
        q[1] = r * std::sin(theta) + jitter * U(rng);
        for (std::size_t k = 2; k < D; ++k) q[k] = 0.2 * std::sin(0.1 * double(i) + double(k));
        p[i] = q;
        theta += 1 / r;
    }
    return p;
}

// A polygon with turns of at most max_turn (polygon angles >= pi - max_turn).
template <std::size_t D>
std::vector<vec<D>> smooth_walk(std::mt19937_64& rng, std::size_t n, double max_turn) {
    std::uniform_real_distribution<double> U(0.0, 1.0);
    std::normal_distribution<double> G(0.0, 1.0);
    std::vector<vec<D>> p(n);
    vec<D> dir{};
    dir[0] = 1;
    for (std::size_t i = 1; i < n; ++i) {
        vec<D> r{};
        for (std::size_t k = 0; k < D; ++k) r[k] = G(rng);
        r = r - dot(r, dir) * dir;
        if (norm(r) > 0) r = r / norm(r);
        const double t = max_turn * (2 * U(rng) - 1);
        dir = std::cos(t) * dir + std::sin(t) * r;
        p[i] = p[i - 1] + (0.5 + U(rng)) * dir;
    }
    return p;
}

// The tree finds exactly the pairs of boxes that meet, in nested-loop order:
// random boxes on a coarse grid (many exact touches, identical and
// degenerate boxes), infinite ones, with and without padding.
TEST(PairSearch, TreeFindsExactlyTheMeetingPairs) {
    CRSPLINE_SEEDED(seed, 4101);
    std::mt19937_64 rng(seed);
    std::size_t sets = 0, pairs = 0;
    for (int rep = 0; rep < 300; ++rep) {
        const std::size_t n = std::size_t(1 + rep % 97 + (rep % 5 == 0 ? 300 : 0));
        std::uniform_int_distribution<int> pos(0, 40), size(0, rep % 3 == 0 ? 0 : 6);
        std::vector<detail::box<3, double>> b(n);
        for (auto& x : b)
            for (std::size_t k = 0; k < 3; ++k) {
                x.lo[k] = pos(rng) / (rep % 2 ? 1.0 : 7.0);
                x.hi[k] = x.lo[k] + size(rng) / (rep % 2 ? 1.0 : 7.0);
            }
        const double inf = std::numeric_limits<double>::infinity();
        if (rep % 11 == 0) b[n / 2] = {vec<3>{{-inf, -inf, -inf}}, vec<3>{{inf, inf, inf}}};
        const double pad = std::array{0.0, 0.5, 1.0 / 7}[rep % 3];
        const auto want = brute_meeting_pairs(b, pad);
        const auto got = flatten(detail::tree_pairs{}(b, pad), n);
        EXPECT_EQ(got, want) << "rep " << rep << " n " << n << " pad " << pad;
        pairs += want.size();
        ++sets;
    }
    std::printf("pair search: %zu box sets, %zu meeting pairs\n", sets, pairs);
    EXPECT_EQ(sets, 300u);
    EXPECT_GT(pairs, 20000u);  // most sets are crowded, with exact touches
}

// find_intersections through the tree equals the all-pairs search: same
// meetings in the same order, bit for bit.
template <std::size_t D>
void check_intersections(std::uint64_t seed, std::size_t& curves, std::size_t& meetings) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    for (int rep = 0; rep < 60; ++rep) {
        const bool closed = rep % 2 == 1;
        std::vector<vec<D>> p;
        double tol = 0;
        switch (rep % 4) {
            case 0: p = crspline::test::random_polygon<D>(rng, 20 + rep, 1.0); break;
            case 1: p = grid_walk<D>(rng, 30 + rep, 3); break;
            case 2: {
                // Facing strands delta apart; the tolerance straddles delta.
                const double delta = std::pow(10.0, -1 - 8 * U(rng));
                p = hairpin<D>(rng, 15 + rep / 4, delta);
                tol = delta * std::array{0.5, 0.999, 1.001, 2.0}[std::size_t(rep / 4) % 4];
                break;
            }
            default:
                p = smooth_walk<D>(rng, 40 + rep, 2.0);
                tol = D == 2 ? 0.0 : 0.05;  // 3-D: closest approaches within 0.05
                break;
        }
        const catmull_rom<D> c(p, {.alpha = std::array{0.0, 0.5, 1.0}[std::size_t(rep) % 3], .closed = closed});
        const auto fast = find_intersections(c, tol);
        const auto ref = detail::find_intersections_among(c, tol, all_pairs{});
        expect_same(fast, ref, "D " + std::to_string(D) + " rep " + std::to_string(rep));
        meetings += ref.intersections.size();
        ++curves;
    }
}

TEST(PairSearch, FindIntersectionsEqualsAllPairs) {
    CRSPLINE_SEEDED(seed, 4102);
    std::size_t curves = 0, meetings2 = 0, meetings3 = 0;
    check_intersections<2>(seed, curves, meetings2);
    check_intersections<3>(seed + 1, curves, meetings3);
    std::printf("pair search: %zu curves, %zu meetings in 2-D, %zu in 3-D\n", curves, meetings2, meetings3);
    EXPECT_EQ(curves, 120u);
    EXPECT_GT(meetings2, 500u);  // many crossings: random and grid walks cross themselves often
    EXPECT_GT(meetings3, 20u);   // near misses within the tolerance
}

// The certificate through the tree equals the all-pairs certificate: same
// decision, same failed rule and pair (the smallest), same search.
template <std::size_t D>
void check_certificates(std::uint64_t seed, std::size_t& curves, std::array<std::size_t, 6>& rules) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    for (int rep = 0; rep < 80; ++rep) {
        const bool closed = rep % 2 == 1;
        std::vector<vec<D>> p;
        if (rep % 3 == 0)
            p = smooth_walk<D>(rng, 20 + 2 * std::size_t(rep), 0.3 + 1.4 * U(rng));
        else
            p = spiral<D>(rng, 100 + 3 * std::size_t(rep), 0.6 + 2.5 * U(rng), 0.1 * U(rng));
        const catmull_rom<D> c(p, {.closed = closed});
        const certify_options opt{.search_on_failure = rep % 4 < 2};
        const auto fast = certify_intersection_free(c, opt);
        const auto ref = detail::certify_among(c, opt, all_pairs{});
        expect_same(fast, ref, "D " + std::to_string(D) + " rep " + std::to_string(rep));
        ASSERT_LT(std::size_t(ref.failed_rule), rules.size());
        ++rules[std::size_t(ref.failed_rule)];
        ++curves;
    }
}

TEST(PairSearch, CertificateEqualsAllPairs) {
    CRSPLINE_SEEDED(seed, 4103);
    std::size_t curves = 0;
    std::array<std::size_t, 6> rules{};  // by certify_rule
    check_certificates<2>(seed, curves, rules);
    check_certificates<3>(seed + 1, curves, rules);
    std::printf("pair search: %zu certificates: %zu certified, %zu failed rule 3 (boxes), %zu other rules\n", curves,
                rules[0], rules[4], rules[1] + rules[2] + rules[3] + rules[5]);
    EXPECT_EQ(curves, 160u);
    EXPECT_GE(rules[0], 20u);  // certified: every pair was checked and none overlapped
    EXPECT_GE(rules[4], 20u);  // failed at a pair: the same (smallest) pair reported
}

}  // namespace
