// The curve's array allocator (detail/storage.hpp): large arrays aligned to
// 2 MiB for transparent huge pages on Linux, small ones from std::allocator.
// Whether the kernel really backs them with huge pages depends on its THP
// setting and free memory, so that is measured (bench/construct_rusage.cpp
// prints page faults), not asserted; what must hold everywhere is that the
// data is intact through construction, copies and moves, and that every
// allocation is freed the way it was made (the ASan+UBSan run of this test
// catches an aligned new paired with a plain delete).
#include "test_support.hpp"

#include <cstdint>
#include <cstring>

namespace {
using namespace crspline;
using crspline::test::random_polygon;
using P3 = vec<3>;

bool aligned_to(const void* p, std::size_t a) { return reinterpret_cast<std::uintptr_t>(p) % a == 0; }

TEST(Storage, AllocatorAlignsLargeArraysAndFreesEveryKind) {
    detail::storage_allocator<double> a;
    const std::size_t at = detail::large_array_bytes / sizeof(double);
    for (std::size_t n : {std::size_t(1), std::size_t(1000), at - 1, at, at + 12345}) {
        SCOPED_TRACE("n = " + std::to_string(n));
        double* p = a.allocate(n);
        ASSERT_NE(p, nullptr);
        EXPECT_TRUE(aligned_to(p, alignof(double)));
#ifdef CRSPLINE_HUGE_PAGES
        if (n >= at) {
            EXPECT_TRUE(aligned_to(p, detail::huge_page_bytes));
        }
#endif
        // Every element writable and readable back.
        for (std::size_t i = 0; i < n; ++i) p[i] = double(i);
        std::size_t wrong = 0;
        for (std::size_t i = 0; i < n; ++i) wrong += p[i] != double(i);
        EXPECT_EQ(wrong, 0u);
        a.deallocate(p, n);
    }
    EXPECT_THROW((void)a.allocate(std::numeric_limits<std::size_t>::max() / 4), std::bad_array_new_length);
}

TEST(Storage, LargeCurveKeepsItsDataThroughCopiesAndMoves) {
    CRSPLINE_SEEDED(s, 20261121);
    std::mt19937_64 rng(s);
    // 200000 points: the point and tangent arrays (4.8 MB each) are large,
    // the knot and bucket arrays are not; both kinds are exercised.
    const std::size_t n = 200000;
    static_assert(200000 * sizeof(P3) >= detail::large_array_bytes);
    const auto p = random_polygon<3>(rng, n, 3.0);
    const catmull_rom<3> c(p);
#ifdef CRSPLINE_HUGE_PAGES
    EXPECT_TRUE(aligned_to(c.points().data(), detail::huge_page_bytes));
#endif
    ASSERT_EQ(c.points().size(), n);
    EXPECT_EQ(std::memcmp(c.points().data(), p.data(), n * sizeof(P3)), 0);
    // The knots stored are the free function's, bit for bit.
    const auto t = knots(std::span<const P3>(p), centripetal);
    ASSERT_EQ(c.grid().size(), t.size());
    EXPECT_EQ(std::memcmp(c.grid().data(), t.data(), t.size() * sizeof(double)), 0);

    // Copy, copy-assign, move: the same curve bit for bit at seeded random t.
    catmull_rom<3> copy(c);
    catmull_rom<3> assigned(std::vector<P3>{P3{0, 0, 0}, P3{1, 0, 0}});
    assigned = copy;
    catmull_rom<3> moved(std::move(copy));
    std::uniform_real_distribution<double> u(c.t_min(), c.t_max());
    std::size_t differ = 0;
    for (int k = 0; k < 2000; ++k) {
        const double x = u(rng);
        const P3 a = c(x), b = assigned(x), m = moved(x);
        differ += std::memcmp(&a, &b, sizeof a) != 0 || std::memcmp(&a, &m, sizeof a) != 0;
    }
    EXPECT_EQ(differ, 0u);
}

}  // namespace
