// The batch kernels of the rotation curves (include/crspline/rotation/batch.hpp)
// against the scalar evaluation, on seeded random curves and parameters (the
// seed is printed on failure; CRSPLINE_SEED reruns one), and the polynomial
// sine and cosine against std::sin and std::cos.
#include <gtest/gtest.h>

#include <crspline/rotation/batch.hpp>
#include <crspline/rotation/c2.hpp>
#include <crspline/rotation/catmull_rom.hpp>
#include <crspline/rotation/pose.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "test_support.hpp"

using namespace crspline::rotation;
using quat = quaternion<double>;
using v3 = vec3<double>;

namespace {

using crspline::test::eps;

v3 random_vec(std::mt19937_64& rng, double length) {
    std::normal_distribution<double> g;
    v3 v{{g(rng), g(rng), g(rng)}};
    return v * (length / crspline::norm(v));
}

/// A walk of n keys, steps of lo..hi radians about random axes, random signs.
std::vector<quat> random_keys(std::mt19937_64& rng, std::size_t n, double lo, double hi) {
    std::uniform_real_distribution<double> a(lo, hi), coin(0, 1);
    std::normal_distribution<double> g;
    std::vector<quat> k{normalized(quat{g(rng), g(rng), g(rng), g(rng)})};
    while (k.size() < n) {
        const quat q = from_rotation_vector(random_vec(rng, a(rng))) * k.back();
        k.push_back(coin(rng) < 0.5 ? q : -q);
    }
    return k;
}

std::vector<double> random_times(std::mt19937_64& rng, std::size_t n) {
    std::uniform_real_distribution<double> d(0.2, 2.0);
    std::vector<double> t{d(rng) - 1};
    while (t.size() < n) t.push_back(t.back() + d(rng));
    return t;
}

/// Parameters over [lo, hi]: random ones, every knot, both ends; sorted
/// (the run the sorted walk takes) when asked.
std::vector<double> sample_t(std::mt19937_64& rng, std::span<const double> knots, std::size_t n, bool sorted) {
    std::uniform_real_distribution<double> u(knots.front(), knots.back());
    std::vector<double> t;
    for (std::size_t k = 0; k < n; ++k) t.push_back(u(rng));
    t.insert(t.end(), knots.begin(), knots.end());
    t.push_back(knots.front());
    t.push_back(knots.back());
    if (sorted) std::sort(t.begin(), t.end());
    else std::shuffle(t.begin(), t.end(), rng);
    return t;
}

struct batch_result {
    std::vector<double> q, w, a;
};

template <class Curve, class... Extra>
batch_result run_batch(const Curve& c, std::span<const double> t, int order, frame f, Extra... extra) {
    batch_result r{std::vector<double>(4 * t.size()), std::vector<double>(3 * t.size()), std::vector<double>(3 * t.size())};
    batch_rows<double> rows;
    rows.q = r.q.data();
    if (order >= 1) rows.omega = r.w.data();
    if (order >= 2) rows.alpha = r.a.data();
    c.evaluate(t, rows, order, f, extra...);
    return r;
}

/// Compares a batch with evaluate_on(segment(t), t) sample by sample; returns
/// the samples checked. Tolerances: the rotation, an O(1) quaternion, to 8
/// eps (the kernel's sine and cosine and the scalar ones are each within 1
/// ulp, and about ten more roundings follow in either); the rates to 64 eps
/// of the largest rate in the batch (the same roundings through the
/// Jacobian's two cross products and the frame's rotation, measured at 7 eps
/// at most, so a factor of 9 of room and none for a wrong term).
template <class Curve, class Locate>
int compare(const Curve& c, std::span<const double> t, const batch_result& r, int order, frame f, Locate locate,
            const std::string& what, double q_ulps = 8) {
    std::vector<so3::jet<double>> ref;
    double ws = 1, as = 1;
    for (double x : t) {
        ref.push_back(c.evaluate_on(locate(x), x, order, f));
        ws = std::max(ws, crspline::max_abs(ref.back().omega));
        as = std::max(as, crspline::max_abs(ref.back().alpha));
    }
    int checked = 0;
    for (std::size_t k = 0; k < t.size(); ++k) {
        const quat& q = ref[k].q;
        const double dq = std::max({std::abs(r.q[4 * k] - q.w), std::abs(r.q[4 * k + 1] - q.x), std::abs(r.q[4 * k + 2] - q.y),
                                    std::abs(r.q[4 * k + 3] - q.z)});
        EXPECT_LE(dq, q_ulps * eps) << what << " order " << order << " sample " << k << " t " << t[k];
        for (std::size_t d = 0; d < 3 && order >= 1; ++d)
            EXPECT_LE(std::abs(r.w[3 * k + d] - ref[k].omega[d]), 64 * eps * ws) << what << " omega, sample " << k;
        for (std::size_t d = 0; d < 3 && order >= 2; ++d)
            EXPECT_LE(std::abs(r.a[3 * k + d] - ref[k].alpha[d]), 64 * eps * as) << what << " alpha, sample " << k;
        ++checked;
    }
    return checked;
}

}  // namespace

// poly_sincos against std::sin and std::cos: within eps (one ulp of 1) in
// absolute terms on |x| <= 1000 (the reduction is exact to 2^-70 |n|, the
// kernels within 2^-58, so the error is the final rounding and std::'s own
// half ulp), and within one ulp relative on |x| <= pi/4, where no reduction
// happens and both are correctly rounded to within half an ulp. Beyond the
// polynomial's range, and for NaN, it is std:: itself.
#if CRSPLINE_ROTATION_LANES
TEST(RotationBatch, PolySinCos) {
    CRSPLINE_SEEDED(seed, 2840);
    std::mt19937_64 rng(seed);
    int checked = 0;
    auto ulp = [](double y) { return std::max(std::abs(y), std::numeric_limits<double>::min()) * eps; };
    for (double range : {1e-300, 1e-8, 0.5, std::numbers::pi / 4, 4.0, 100.0, 1000.0}) {
        std::uniform_real_distribution<double> u(-range, range);
        for (int k = 0; k < 20000; ++k) {
            const double a = u(rng), b = u(rng);
            const auto sc = detail_batch::poly_sincos(detail_batch::vd(a, b, a, b));
            const double x[2] = {a, b};
            for (int l = 0; l < 2; ++l) {
                const double s = std::sin(x[l]), c = std::cos(x[l]);
                EXPECT_LE(std::abs(sc.s[l] - s), eps) << "sin(" << x[l] << ")";
                EXPECT_LE(std::abs(sc.c[l] - c), eps) << "cos(" << x[l] << ")";
                if (range <= std::numbers::pi / 4) {
                    EXPECT_LE(std::abs(sc.s[l] - s), ulp(s)) << "sin(" << x[l] << "), relative";
                    EXPECT_LE(std::abs(sc.c[l] - c), ulp(c)) << "cos(" << x[l] << "), relative";
                }
                ++checked;
            }
        }
    }
    EXPECT_EQ(checked, 7 * 20000 * 2);
    // Multiples of pi/2 (the quadrant switch) and their neighbours.
    for (int n = -40; n <= 40; ++n)
        for (double x : {n * std::numbers::pi / 2, std::nextafter(n * std::numbers::pi / 2, 1e9),
                         std::nextafter(n * std::numbers::pi / 2, -1e9)}) {
            const auto sc = detail_batch::poly_sincos(detail_batch::vd(x, -x, x, -x));
            EXPECT_LE(std::abs(sc.s[0] - std::sin(x)), eps) << x;
            EXPECT_LE(std::abs(sc.c[0] - std::cos(x)), eps) << x;
            EXPECT_LE(std::abs(sc.s[1] + std::sin(x)), eps) << x;
        }
    // One lane out of range sends the whole vector to std:: (the others then
    // agree with std:: exactly).
    const double big = 1e7;
    const auto sc = detail_batch::poly_sincos(detail_batch::vd(big, std::numeric_limits<double>::quiet_NaN(), 0.5, 0.5));
    EXPECT_EQ(sc.s[0], std::sin(big));
    EXPECT_EQ(sc.c[0], std::cos(big));
    EXPECT_TRUE(std::isnan(sc.s[1]) && std::isnan(sc.c[1]));
    EXPECT_EQ(sc.s[2], std::sin(0.5));
}
#endif

// The short tier of the Jacobian coefficients' series (c2_lanes: the first
// jacobian_short_terms terms of k1 = (1 - cos)/theta^2 and k2 = (theta -
// sin)/theta^3 for z = theta^2 < 2) against the sum of 20 terms in long
// double (the first term left out below 2^20/42! ~ 7e-46 of either), and
// against the 16 terms the next tier takes. Bound: 3 eps relative (the
// truncation is below 1% of an ulp by c2_lanes' comment; the rest is
// Estrin's roundings: the last sum's half ulp, and the inner sums' on
// terms at most z/12 of the first; measured 1.8 eps at seed 2848), and
// within an ulp and a half of the 16 terms (measured 0.83; their sums
// share the first 8 terms' Estrin group and differ in the last roundings
// only). z runs over [0, 2) at random, with both ends and tiny values.
TEST(RotationBatch, JacobianSeriesTiers) {
    namespace db = crspline::rotation::detail_batch;
    CRSPLINE_SEEDED(seed, 2848);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> uz(0, 2);
    auto truth = [](long double z, int first) {  // sum_m (-1)^m z^m / (2m + first)!
        long double term = 1, sum = 0;
        for (int k = 2; k <= first; ++k) term /= k;
        for (int m = 0; m < 20; ++m) {
            sum += term;
            term *= -z / ((2.0L * m + first + 1) * (2.0L * m + first + 2));
        }
        return sum;
    };
    double worst = 0, worst16 = 0;
    int checked = 0;
    for (int i = 0; i < 100000; ++i) {
        const double z = i == 0 ? 0.0 : i == 1 ? std::nextafter(2.0, 0.0) : i == 2 ? 1e-300 : i % 100 == 3 ? uz(rng) * 1e-9 : uz(rng);
        const double k1 = db::estrin<double, db::jacobian_short_terms>(db::series.k1, z);
        const double k2 = db::estrin<double, db::jacobian_short_terms>(db::series.k2, z);
        const long double t1 = truth(z, 2), t2 = truth(z, 3);
        const double e1 = double(std::abs(k1 - t1) / t1) / eps, e2 = double(std::abs(k2 - t2) / t2) / eps;
        worst = std::max({worst, e1, e2});
        EXPECT_LE(e1, 3.0) << "k1 at z = " << z;
        EXPECT_LE(e2, 3.0) << "k2 at z = " << z;
        const double d1 = std::abs(k1 - db::horner16<double>(db::series.k1, z)) / (k1 * eps);
        const double d2 = std::abs(k2 - db::horner16<double>(db::series.k2, z)) / (k2 * eps);
        worst16 = std::max({worst16, d1, d2});
        EXPECT_LE(d1, 1.5) << "k1 at z = " << z << " against 16 terms";
        EXPECT_LE(d2, 1.5) << "k2 at z = " << z << " against 16 terms";
        ++checked;
    }
    EXPECT_EQ(checked, 100000);
    std::printf("jacobian series, %d terms on z < 2: worst %.2f eps from the truth, %.2f from 16 terms\n",
                db::jacobian_short_terms, worst, worst16);
}

// The C2 spline's batch against evaluate_on: every end condition, closed,
// steps up to 170 degrees, and tiny ones (the series side of the Jacobian
// coefficients), long-way steps (keep_signs, up to 2 pi), sorted and
// shuffled parameters with every knot, orders 0-2, both frames; and with
// extrapolate, t beyond both ends (SciPy's call).
TEST(RotationBatch, C2MatchesScalar) {
    CRSPLINE_SEEDED(seed, 2841);
    std::mt19937_64 rng(seed);
    int checked = 0, curves = 0;
    for (int round = 0; round < 12; ++round) {
        const std::size_t n = 2 + rng() % 12;
        const double hi = round % 4 == 0 ? 1e-6 : round % 4 == 1 ? 0.5 : 170 * std::numbers::pi / 180;
        const auto keys = random_keys(rng, n, hi / 10, hi);
        c2_options<double> o;
        o.closed = round % 3 == 2;
        if (round % 3 == 1) o.start = c2_end<double>::natural(), o.end = c2_end<double>::velocity(random_vec(rng, 1.0));
        o.keep_signs = round % 6 == 5;
        const auto times = random_times(rng, o.closed ? n + 1 : n);
        const c2_rotation_spline<double> c{std::span<const double>(times), std::span<const quat>(keys), o};
        ++curves;
        for (bool sorted : {false, true}) {
            const auto t = sample_t(rng, times, 300, sorted);
            for (int order = 0; order <= 2; ++order)
                for (frame f : {frame::world, frame::body}) {
                    const auto r = run_batch(c, std::span<const double>(t), order, f);
                    checked += compare(c, t, r, order, f, [&](double x) { return c.locate(x); }, "c2");
                }
        }
        // Extrapolation: t up to one domain length beyond either end.
        const double span = times.back() - times.front();
        std::uniform_real_distribution<double> u(times.front() - span, times.back() + span);
        std::vector<double> t(200);
        for (double& x : t) x = u(rng);
        const auto r = run_batch(c, std::span<const double>(t), 2, frame::body, true);
        checked += compare(c, t, r, 2, frame::body, [&](double x) { return c.locate(x); }, "c2 extrapolated");
    }
    EXPECT_EQ(curves, 12);
    EXPECT_GT(checked, 12 * 2 * 6 * 300 + 12 * 200);
}

// Piecewise slerp's batch: alpha grids with a repeated key (a zero-length
// segment, the curve resting there), closed, long-way steps under keep_signs.
TEST(RotationBatch, SlerpMatchesScalar) {
    CRSPLINE_SEEDED(seed, 2842);
    std::mt19937_64 rng(seed);
    int checked = 0;
    for (int round = 0; round < 12; ++round) {
        const std::size_t n = 2 + rng() % 12;
        auto keys = random_keys(rng, n, 0.01, 3.0);
        if (round % 2 == 1) keys.insert(keys.begin() + std::ptrdiff_t(rng() % keys.size()), keys[rng() % keys.size()]);
        if (round % 4 == 3) keys.push_back(keys.back());  // a zero-length last segment
        rotation_options<double> o;
        o.kind = spline_kind::piecewise_slerp;
        o.alpha = 0.5;
        o.closed = round % 3 == 2;
        o.keep_signs = round % 4 == 1;
        const quaternion_spline<double> c(keys, o);
        for (bool sorted : {false, true}) {
            const auto t = sample_t(rng, c.grid(), 300, sorted);
            for (int order = 0; order <= 2; ++order)
                for (frame f : {frame::world, frame::body}) {
                    const auto r = run_batch(c, std::span<const double>(t), order, f);
                    checked += compare(c, t, r, order, f, [&](double x) { return c.locate(x); }, "slerp");
                }
        }
    }
    EXPECT_GT(checked, 12 * 2 * 6 * 300);
}

// The other kinds' rates keep the scalar path inside the batch call (order
// 2 here); and the span<quat> overloads equal the rows ones at order 0
// exactly (the same kernel).
TEST(RotationBatch, OtherKindsAndQuaternionOutput) {
    CRSPLINE_SEEDED(seed, 2843);
    std::mt19937_64 rng(seed);
    int checked = 0;
    const auto keys = random_keys(rng, 7, 0.1, 2.5);
    for (auto kind : {spline_kind::catmull_rom, spline_kind::squad, spline_kind::barry_goldman, spline_kind::piecewise_slerp}) {
        rotation_options<double> o;
        o.kind = kind;
        o.alpha = 0.5;
        const quaternion_spline<double> c(keys, o);
        const auto t = sample_t(rng, c.grid(), 200, false);
        const auto r = run_batch(c, std::span<const double>(t), 2, frame::body);
        checked += compare(c, t, r, 2, frame::body, [&](double x) { return c.locate(x); }, "kind");
        std::vector<quat> out(t.size());
        c.evaluate(std::span<const double>(t), std::span<quat>(out));
        const auto r0 = run_batch(c, std::span<const double>(t), 0, frame::world);
        for (std::size_t k = 0; k < t.size(); ++k)
            EXPECT_EQ(out[k], (quat{r0.q[4 * k], r0.q[4 * k + 1], r0.q[4 * k + 2], r0.q[4 * k + 3]})) << k;
    }
    EXPECT_EQ(checked, 4 * (200 + 7 + 2));
}

// Bad input: t outside the domain names its index; a wrong order is refused.
TEST(RotationBatch, BadInputIsNamed) {
    std::mt19937_64 rng(2844);
    const auto keys = random_keys(rng, 5, 0.1, 1.0);
    const std::vector<double> times{0, 1, 2, 3, 4};
    const c2_rotation_spline<double> c{std::span<const double>(times), std::span<const quat>(keys)};
    std::vector<double> t{0.5, 1.5, 2.5, 9.0, 1.0};
    std::vector<double> q(4 * t.size());
    batch_rows<double> rows;
    rows.q = q.data();
    try {
        c.evaluate(std::span<const double>(t), rows, 0);
        ADD_FAILURE() << "no error";
    } catch (const crspline::out_of_domain& e) {
        EXPECT_NE(std::string(e.what()).find("(index 3)"), std::string::npos) << e.what();
    }
    EXPECT_THROW(c.evaluate(std::span<const double>(t), rows, 3), crspline::invalid_input);
    t[3] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(c.evaluate(std::span<const double>(t), rows, 0), crspline::out_of_domain);
    rotation_options<double> o;
    o.kind = spline_kind::piecewise_slerp;
    const quaternion_spline<double> s(keys, o);
    t[3] = -1;
    try {
        s.evaluate(std::span<const double>(t), rows, 0);
        ADD_FAILURE() << "no error";
    } catch (const crspline::out_of_domain& e) {
        EXPECT_NE(std::string(e.what()).find("(index 3)"), std::string::npos) << e.what();
    }
}

// The pose curve's batch (chunks of positions, velocities and rotations)
// against its one-sample evaluate: C2 and Catmull-Rom rotations, both
// frames, more samples than one chunk. Positions and velocities come from
// the same segment arithmetic (16 eps of the path's scale); rotations and
// angular velocities as in compare().
TEST(RotationBatch, PoseMatchesScalar) {
    CRSPLINE_SEEDED(seed, 2845);
    std::mt19937_64 rng(seed);
    int checked = 0;
    std::normal_distribution<double> g;
    for (int round = 0; round < 4; ++round) {
        const std::size_t n = 3 + rng() % 10;
        const auto keys = random_keys(rng, n, 0.1, 2.5);
        std::vector<crspline::vec<3, double>> p{{{0, 0, 0}}};
        while (p.size() < n) p.push_back(p.back() + crspline::vec<3, double>{{1 + std::abs(g(rng)), g(rng), g(rng)}});
        pose_options<double> o;
        o.c2_rotation = round % 2 == 0;
        o.closed = round >= 2;
        const pose_curve<double> c{std::span<const crspline::vec<3, double>>(p), std::span<const quat>(keys), o};
        const auto t = sample_t(rng, c.grid(), 2500, round % 2 == 1);
        double scale = 1;
        for (const auto& x : p) scale = std::max(scale, crspline::max_abs(x));
        for (frame f : {frame::world, frame::body}) {
            const auto out = c.evaluate(std::span<const double>(t), f);
            ASSERT_EQ(out.size(), t.size());
            double vs = 1, ws = 1;
            std::vector<pose_sample<double>> ref;
            for (double x : t) {
                ref.push_back(c.evaluate(x, f));
                vs = std::max(vs, crspline::max_abs(ref.back().velocity));
                ws = std::max(ws, crspline::max_abs(ref.back().omega));
            }
            for (std::size_t k = 0; k < t.size(); ++k) {
                EXPECT_LE(crspline::max_abs(out[k].position - ref[k].position), 16 * eps * scale) << k;
                EXPECT_LE(crspline::max_abs(out[k].velocity - ref[k].velocity), 64 * eps * vs) << k;
                EXPECT_LE(crspline::max_abs(out[k].omega - ref[k].omega), 64 * eps * ws) << k;
                const quat &a = out[k].orientation, &b = ref[k].orientation;
                EXPECT_LE(std::max({std::abs(a.w - b.w), std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)}), 8 * eps) << k;
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 4 * 2 * 2500);
}

// poly_atan2 (the half angle of the sample-dependent slerps' logs) against
// std::atan2 on y >= 0: within 2 ulps of the result (its comment counts the
// roundings: two in r, one in c_k + atan r, one each for pi/2 - a and pi -
// a, each at most half an ulp of a result at least as large, plus std::'s
// own half ulp), over ratios y/|x| from 1e-300 to 1e300 and both signs of x;
// the edges exactly (0, pi/2, pi) and NaN through.
#if CRSPLINE_ROTATION_LANES
TEST(RotationBatch, PolyAtan2) {
    CRSPLINE_SEEDED(seed, 2846);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> e(-12, 12), m(0, 1), coin(0, 1);
    int checked = 0;
    double worst = 0;
    for (int k = 0; k < 200000; ++k) {
        const double scale = std::pow(10.0, e(rng));
        const double y = m(rng) * (k % 4 == 0 ? scale : 1.0), x = (coin(rng) < 0.5 ? -1 : 1) * m(rng) * (k % 4 == 1 ? scale : 1.0);
        const double b = std::nextafter(y, 2.0);
        const auto a = detail_batch::poly_atan2(detail_batch::vd(y, b, y, b), detail_batch::vd(x, x, -x, -x));
        const double in[4][2] = {{y, x}, {b, x}, {y, -x}, {b, -x}};
        for (int l = 0; l < 4; ++l) {
            const double want = std::atan2(in[l][0], in[l][1]);
            const double ulp = std::nextafter(want, 4.0) - want;  // want >= 0
            const double err = std::abs(a[l] - want) / ulp;
            worst = std::max(worst, err);
            EXPECT_LE(err, 2.0) << "atan2(" << in[l][0] << ", " << in[l][1] << ") = " << want << ", got " << a[l];
            ++checked;
        }
    }
    EXPECT_EQ(checked, 4 * 200000);
    // The edges: exact.
    const auto a = detail_batch::poly_atan2(detail_batch::vd(0, 0, 1, 1e-300), detail_batch::vd(1, -1, 0, 1));
    EXPECT_EQ(a[0], 0.0);
    EXPECT_EQ(a[1], std::numbers::pi);
    EXPECT_EQ(a[2], std::numbers::pi / 2);
    EXPECT_EQ(a[3], 1e-300);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const auto n = detail_batch::poly_atan2(detail_batch::vd(nan, 1, nan, 0), detail_batch::vd(1, nan, nan, nan));
    for (int l = 0; l < 4; ++l) EXPECT_TRUE(std::isnan(n[l])) << l;
    std::printf("poly_atan2: worst %.2f ulps over %d values\n", worst, checked);
}
#endif

namespace {

/// A curve of each kind that has a vector kernel for its rotations besides
/// slerp: Catmull-Rom, Kochanek-Bartels, Barry-Goldman, Squad (alpha grids,
/// open and closed), and a De Casteljau curve from 4 controls per segment.
std::vector<std::pair<std::string, quaternion_spline<double>>> pyramid_curves(std::mt19937_64& rng, int round) {
    std::vector<std::pair<std::string, quaternion_spline<double>>> out;
    const std::size_t n = 2 + rng() % 10;
    auto keys = random_keys(rng, n, round % 3 == 0 ? 1e-7 : 0.01, round % 3 == 2 ? 3.0 : 1.5);
    if (round % 2 == 1) keys.insert(keys.begin() + std::ptrdiff_t(rng() % keys.size()), keys[rng() % keys.size()]);
    std::uniform_real_distribution<double> tcb(-0.9, 0.9);
    for (auto kind : {spline_kind::catmull_rom, spline_kind::kochanek_bartels, spline_kind::barry_goldman, spline_kind::squad}) {
        rotation_options<double> o;
        o.kind = kind;
        o.alpha = round % 4 == 3 ? 0.0 : 0.5;
        o.closed = round % 3 == 1;
        o.keep_signs = round % 4 == 2;
        if (kind == spline_kind::kochanek_bartels) o.kb = {{tcb(rng), tcb(rng), tcb(rng)}};
        out.emplace_back("kind " + std::to_string(int(kind)) + " round " + std::to_string(round), quaternion_spline<double>(keys, o));
    }
    std::vector<std::vector<quat>> segs;
    for (std::size_t i = 0; i + 1 < keys.size(); ++i)
        segs.push_back({keys[i], from_rotation_vector(random_vec(rng, 0.4)) * keys[i],
                        from_rotation_vector(random_vec(rng, 0.4)) * keys[i + 1], keys[i + 1]});
    out.emplace_back("de_casteljau", quaternion_spline<double>::de_casteljau(segs));
    return out;
}

}  // namespace

// The pyramid and Squad kernels (rotations) against evaluate_on: tiny,
// moderate and long-way steps (keep_signs, up to 3 rad), a repeated key (a
// zero-length segment with alpha, where the curve rests), closed curves,
// TCB, 4-control De Casteljau; sorted and shuffled t with every knot. The
// tolerance is 8 eps: a pyramid is three levels of slerps, each within a
// few ulps of the scalar one (atan2 within 2 ulps, the scalar log's within
// 1, the sine and cosine within 1 each, about ten products and sums), and
// the levels' errors do not grow for the angles here; measured at most
// 4.3 eps over seeds 2847-2866. Under keep_signs (every fourth round) keys
// may be nearly antipodal and Squad's and Barry-Goldman's outer slerps then
// join quaternions up to 2 pi apart as travelled, where the slerp's axis
// is known only to eps / sin(angle / 2) and both evaluations' roundings are
// amplified alike (measured up to 2.3e-13 over the same seeds): 1e-10 there,
// still far below any wrong term.
TEST(RotationBatch, PyramidAndSquadMatchScalar) {
    CRSPLINE_SEEDED(seed, 2847);
    std::mt19937_64 rng(seed);
    int checked = 0, curves = 0;
    for (int round = 0; round < 12; ++round)
        for (const auto& [what, c] : pyramid_curves(rng, round)) {
            ++curves;
            for (bool sorted : {false, true}) {
                const auto t = sample_t(rng, c.grid(), 300, sorted);
                const auto r = run_batch(c, std::span<const double>(t), 0, frame::world);
                checked += compare(c, t, r, 0, frame::world, [&](double x) { return c.locate(x); }, what,
                                   round % 4 == 2 ? 1e-10 / eps : 8);
            }
        }
    EXPECT_EQ(curves, 12 * 5);
    EXPECT_GT(checked, 12 * 5 * 2 * 300);
}

// The AVX2 clone against the portable lanes: the same bits for every
// kernel (C2 at orders 0-2 in both frames and extrapolated, slerp, the
// pyramids, Squad, the pose curve). Skipped where the CPU has no AVX2 (or
// the build has no clone).
TEST(RotationBatch, Avx2AndPortableGiveTheSameBits) {
    if (detail_batch::best_isa() != detail_batch::isa::avx2) GTEST_SKIP() << "no AVX2 clone on this CPU or build";
    CRSPLINE_SEEDED(seed, 2848);
    std::mt19937_64 rng(seed);
    int compared = 0;
    auto same = [&](const batch_result& a, const batch_result& b, const std::string& what) {
        ASSERT_EQ(a.q.size(), b.q.size());
        EXPECT_EQ(0, std::memcmp(a.q.data(), b.q.data(), a.q.size() * sizeof(double))) << what << " rotations";
        EXPECT_EQ(0, std::memcmp(a.w.data(), b.w.data(), a.w.size() * sizeof(double))) << what << " omega";
        EXPECT_EQ(0, std::memcmp(a.a.data(), b.a.data(), a.a.size() * sizeof(double))) << what << " alpha";
        ++compared;
    };
    using detail_batch::isa;
    for (int round = 0; round < 6; ++round) {
        // C2, every order and frame, extrapolated too.
        const std::size_t n = 2 + rng() % 12;
        const double hi = round % 3 == 0 ? 1e-6 : round % 3 == 1 ? 0.5 : 3.0;
        const auto keys = random_keys(rng, n, hi / 10, hi);
        const auto times = random_times(rng, n);
        const c2_rotation_spline<double> c{std::span<const double>(times), std::span<const quat>(keys)};
        const auto t = sample_t(rng, times, 401, round % 2 == 0);
        for (int order = 0; order <= 2; ++order)
            for (frame f : {frame::world, frame::body})
                for (bool ex : {false, true})
                    same(run_batch(c, std::span<const double>(t), order, f, ex, isa::portable),
                         run_batch(c, std::span<const double>(t), order, f, ex, isa::avx2), "c2");
        // Slerp, the pyramids, Squad.
        for (const auto& [what, q] : pyramid_curves(rng, round)) {
            const auto tq = sample_t(rng, q.grid(), 401, round % 2 == 1);
            same(run_batch(q, std::span<const double>(tq), 0, frame::world, isa::portable),
                 run_batch(q, std::span<const double>(tq), 0, frame::world, isa::avx2), what);
        }
        rotation_options<double> o;
        o.kind = spline_kind::piecewise_slerp;
        const quaternion_spline<double> s(keys, o);
        const auto ts = sample_t(rng, s.grid(), 401, false);
        for (int order = 0; order <= 2; ++order)
            same(run_batch(s, std::span<const double>(ts), order, frame::body, isa::portable),
                 run_batch(s, std::span<const double>(ts), order, frame::body, isa::avx2), "slerp");
        // The pose curve (C2 rotation).
        std::vector<crspline::vec<3, double>> p{{{0, 0, 0}}};
        std::normal_distribution<double> g;
        while (p.size() < n) p.push_back(p.back() + crspline::vec<3, double>{{1 + std::abs(g(rng)), g(rng), g(rng)}});
        if (n >= 3) {
            const pose_curve<double> pc{std::span<const crspline::vec<3, double>>(p), std::span<const quat>(keys)};
            const auto tp = sample_t(rng, pc.grid(), 401, false);
            std::vector<pose_sample<double>> a(tp.size()), b(tp.size());
            pc.evaluate(std::span<const double>(tp), std::span<pose_sample<double>>(a), frame::body, isa::portable);
            pc.evaluate(std::span<const double>(tp), std::span<pose_sample<double>>(b), frame::body, isa::avx2);
            EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(pose_sample<double>))) << "pose";
            ++compared;
        }
    }
    EXPECT_GE(compared, 6 * (12 + 5 + 3));
}

// The rates alone (batch_rows without q or quats, as SciPy's spline(t, 1)
// asks): the same bits as the rates of a call that writes the rotations
// too, in both frames and at orders 1 and 2 (the body frame skips forming
// the rotation, the world frame needs it for the frame change).
TEST(RotationBatch, RatesAloneEqualTheFullCall) {
    CRSPLINE_SEEDED(seed, 2849);
    std::mt19937_64 rng(seed);
    int compared = 0;
    for (int round = 0; round < 4; ++round) {
        const std::size_t n = 3 + rng() % 10;
        const auto keys = random_keys(rng, n, 0.1, 2.5);
        const auto times = random_times(rng, n);
        const c2_rotation_spline<double> c{std::span<const double>(times), std::span<const quat>(keys)};
        const auto t = sample_t(rng, times, 333, false);
        for (int order = 1; order <= 2; ++order)
            for (frame f : {frame::world, frame::body}) {
                const auto full = run_batch(c, std::span<const double>(t), order, f);
                std::vector<double> w(3 * t.size()), a(3 * t.size());
                batch_rows<double> rows;
                rows.omega = w.data();
                if (order >= 2) rows.alpha = a.data();
                c.evaluate(std::span<const double>(t), rows, order, f);
                EXPECT_EQ(0, std::memcmp(w.data(), full.w.data(), w.size() * sizeof(double))) << "omega, order " << order;
                if (order >= 2) {
                    EXPECT_EQ(0, std::memcmp(a.data(), full.a.data(), a.size() * sizeof(double))) << "alpha";
                }
                ++compared;
            }
    }
    EXPECT_EQ(compared, 4 * 2 * 2);
}
