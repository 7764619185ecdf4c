// The root finders under the geometry: rising_roots (Bernstein isolation,
// minima only, used by the nearest-point search) held to polynomials built
// from known roots, and to real_roots (every root, derivative recursion).
#include "test_support.hpp"

#include <crspline/detail/polynomial.hpp>

namespace {
using namespace crspline::detail;

std::array<double, 6> from_roots(const std::array<double, 5>& r, double lead) {
    std::array<double, 6> p{lead, 0, 0, 0, 0, 0};
    for (double x : r) {  // p *= (u - x)
        std::array<double, 6> q{};
        for (std::size_t i = 0; i < 5; ++i) {
            q[i + 1] += p[i];
            q[i] -= x * p[i];
        }
        p = q;
    }
    return p;
}

TEST(Polynomial, RisingRootsOfSeparatedRoots) {
    // Five simple roots at least 0.02 apart: each is well conditioned, so
    // both finders recover it to 1e-9 and rising_roots returns exactly the
    // ones inside (0, 1) where p goes from negative to positive.
    CRSPLINE_SEEDED(s, 701);
    std::mt19937_64 rng(s);
    std::uniform_real_distribution<double> U(-0.3, 1.3);
    std::size_t polynomials = 0, rising = 0;
    while (polynomials < 5000) {
        std::array<double, 5> r;
        for (auto& x : r) x = U(rng);
        std::sort(r.begin(), r.end());
        bool separated = true;
        for (std::size_t i = 0; i + 1 < 5; ++i) separated = separated && r[i + 1] - r[i] >= 0.02;
        for (double x : r) separated = separated && std::abs(x) >= 0.02 && std::abs(x - 1) >= 0.02;
        if (!separated) continue;
        const double lead = (rng() % 2 ? 1.0 : -1.0) * std::exp(U(rng) * 5);
        const auto p = from_roots(r, lead);
        std::vector<double> want;
        for (std::size_t i = 0; i < 5; ++i)  // sign of p just after r[i]: lead * (-1)^(roots above)
            if (r[i] > 0 && r[i] < 1 && (lead > 0) == ((4 - i) % 2 == 0)) want.push_back(r[i]);
        const auto got = rising_roots(p);
        ASSERT_EQ(got.size(), want.size()) << "polynomial " << polynomials;
        for (std::size_t k = 0; k < want.size(); ++k) EXPECT_NEAR(got[k], want[k], 1e-9);
        std::size_t all = 0;
        for (double x : real_roots(p, 0.0, 1.0)) {
            EXPECT_NEAR(x, *std::min_element(r.begin(), r.end(), [&](double a, double b) {
                return std::abs(a - x) < std::abs(b - x);
            }), 1e-9);
            ++all;
        }
        EXPECT_EQ(all, std::size_t(std::count_if(r.begin(), r.end(), [](double x) { return x > 0 && x < 1; })));
        rising += want.size();
        ++polynomials;
    }
    EXPECT_EQ(polynomials, 5000u);
    EXPECT_GT(rising, 2500u);
}

TEST(Polynomial, ClustersAndBoundaryRootsTerminateWithSmallResiduals) {
    // Roots exactly at the ends, within 1e-15 of them, repeated: ill
    // conditioned (a cluster is only determined to ~eps^(1/m)), so the
    // promise is termination, at most 5 roots, and each a zero of p to
    // rounding of its coefficients' size.
    CRSPLINE_SEEDED(s, 702);
    std::mt19937_64 rng(s);
    std::uniform_real_distribution<double> U(-0.3, 1.3);
    std::size_t reported = 0;
    for (int rep = 0; rep < 20000; ++rep) {
        std::array<double, 5> r;
        for (auto& x : r) {
            switch (rng() % 6) {
                case 0: x = 0; break;
                case 1: x = 1; break;
                case 2: x = 1 - 1e-15 * double(rng() % 8); break;
                default: x = U(rng);
            }
        }
        const auto p = from_roots(r, (rng() % 2 ? 1.0 : -1.0) * std::exp(U(rng) * 5));
        double size = 0;
        for (double c : p) size += std::abs(c);
        const auto got = rising_roots(p);
        EXPECT_LE(got.size(), 5u);
        for (std::size_t k = 0; k < got.size(); ++k) {
            EXPECT_GE(got[k], 0.0);
            EXPECT_LE(got[k], 1.0);
            if (k > 0) {
                EXPECT_GT(got[k], got[k - 1]);
            }
            EXPECT_LE(std::abs(horner(p, got[k])), 1e-6 * size) << "rep " << rep;
        }
        reported += got.size();
    }
    EXPECT_GT(reported, 1000u);
}

}  // namespace
