// Rotation keyframe reduction (rotation/fit.hpp, issue 40 point 4), on a
// seeded corpus of motion-capture-like streams (the seed is printed on
// failure; CRSPLINE_SEED reruns one): smooth motion with sensor noise at
// 120 Hz, fast spins, near-180 degree steps between sparse samples, a still
// stretch with random signs. Every fit is re-checked here against an
// independent angle (long double, 2 asin of the half chord), its count
// against the true minimum (dynamic programming) on short streams.
#include <gtest/gtest.h>

#include <crspline/rotation/fit.hpp>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "test_support.hpp"

using namespace crspline::rotation;
using quat = quaternion<double>;
using v3 = vec3<double>;

namespace {

constexpr double deg = std::numbers::pi / 180;

struct stream {
    std::string name;
    std::vector<double> t;
    std::vector<quat> q;
};

/// Motion capture: the rotation vector a sum of sinusoids per component
/// (0.2-2 Hz, amplitudes up to 0.8 rad) times a fixed base, at `hz`, each
/// sample turned by noise of about `noise` radians about a random axis,
/// signs random (files do not agree on them).
stream mocap(std::mt19937_64& rng, std::size_t n, double hz, double noise) {
    std::uniform_real_distribution<double> U(0, 1);
    std::normal_distribution<double> G;
    double amp[3][3], freq[3][3], phase[3][3];
    for (auto* a : {amp, freq, phase})
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k) a[i][k] = U(rng);
    const quat base = normalized(quat{G(rng), G(rng), G(rng), G(rng)});
    stream s{"mocap", {}, {}};
    for (std::size_t i = 0; i < n; ++i) {
        const double t = double(i) / hz;
        v3 r{};
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k) r[std::size_t(c)] += 0.8 * amp[c][k] * std::sin(2 * std::numbers::pi * (0.2 + 1.8 * freq[c][k]) * t + 6.3 * phase[c][k]) / 3;
        const v3 e{{G(rng) * noise, G(rng) * noise, G(rng) * noise}};
        quat q = from_rotation_vector(e) * from_rotation_vector(r) * base;
        s.t.push_back(t);
        s.q.push_back(U(rng) < 0.5 ? -q : q);
    }
    return s;
}

/// A spin at `rate` rad/s about a slowly wandering axis, with noise.
stream spin(std::mt19937_64& rng, std::size_t n, double hz, double rate, double noise) {
    std::normal_distribution<double> G;
    stream s{"spin", {}, {}};
    for (std::size_t i = 0; i < n; ++i) {
        const double t = double(i) / hz;
        const v3 axis{{std::cos(0.5 * t), std::sin(0.5 * t), 1.0}};
        const v3 e{{G(rng) * noise, G(rng) * noise, G(rng) * noise}};
        s.t.push_back(t);
        s.q.push_back(from_rotation_vector(e) * from_axis_angle(axis, rate * t));
    }
    return s;
}

/// Sparse samples, each turned 150-179 degrees from the last about a random
/// axis, at uneven times: the fit must keep about all of them.
stream big_steps(std::mt19937_64& rng, std::size_t n) {
    std::uniform_real_distribution<double> U(0, 1);
    std::normal_distribution<double> G;
    stream s{"near-180 steps", {}, {}};
    quat q = quat::identity();
    double t = 0;
    for (std::size_t i = 0; i < n; ++i) {
        s.t.push_back(t);
        s.q.push_back(q);
        q = from_axis_angle(v3{{G(rng), G(rng), G(rng)}}, (150 + 29 * U(rng)) * deg) * q;
        t += 0.5 + U(rng);
    }
    return s;
}

/// Smooth motion, then a still stretch (one rotation, noise below the
/// tolerance, signs random), then motion again.
stream with_still(std::mt19937_64& rng, std::size_t n, double hz) {
    stream a = mocap(rng, n, hz, 0.0);
    std::uniform_real_distribution<double> U(0, 1);
    const std::size_t from = n / 3, to = 2 * n / 3;
    for (std::size_t i = from; i < to; ++i) a.q[i] = U(rng) < 0.5 ? -a.q[from] : a.q[from];
    a.name = "still stretch";
    return a;
}

/// The corpus: `count` streams of each kind (lengths as given).
std::vector<stream> corpus(std::mt19937_64& rng, std::size_t n, std::size_t count) {
    std::vector<stream> out;
    for (std::size_t k = 0; k < count; ++k) {
        out.push_back(mocap(rng, n, 120, 0.05 * deg));
        out.push_back(spin(rng, n, 120, 4 * std::numbers::pi, 0.05 * deg));
        out.push_back(big_steps(rng, std::max<std::size_t>(n / 20, 8)));
        out.push_back(with_still(rng, n, 120));
    }
    return out;
}

/// The angle between the rotations of q and r, independently of the fit's
/// bound: long double, 4 asin(|q - r| / 2) on unit-normalized inputs, the
/// nearer sign.
long double true_angle(const quat& a, const quat& b) {
    long double x[4] = {a.w, a.x, a.y, a.z}, y[4] = {b.w, b.x, b.y, b.z}, na = 0, nb = 0, d = 0;
    for (int i = 0; i < 4; ++i) na += x[i] * x[i], nb += y[i] * y[i], d += x[i] * y[i];
    na = std::sqrt(na), nb = std::sqrt(nb);
    const long double sign = d < 0 ? -1 : 1;
    long double c = 0;
    for (int i = 0; i < 4; ++i) {
        const long double e = x[i] / na - sign * y[i] / nb;
        c += e * e;
    }
    return 4 * std::asin(std::min<long double>(1, std::sqrt(c) / 2));
}

/// Every sample within the tolerance by the independent angle; the report
/// consistent with itself.
void expect_proved(const stream& s, const rotation_fit<double>& r, double tol) {
    SCOPED_TRACE(s.name + ", " + std::to_string(s.t.size()) + " samples, tolerance " + std::to_string(tol));
    ASSERT_GE(r.count(), 2u);
    EXPECT_EQ(r.indices.front(), 0u);
    EXPECT_EQ(r.indices.back(), s.t.size() - 1);
    for (std::size_t k = 1; k < r.count(); ++k) ASSERT_LT(r.indices[k - 1], r.indices[k]);
    ASSERT_EQ(r.keys.size(), r.count());
    for (std::size_t k = 0; k < r.count(); ++k) {
        EXPECT_EQ(r.times[k], s.t[r.indices[k]]);
        EXPECT_LE(true_angle(r.keys[k], s.q[r.indices[k]]), 2e-15L);  // the same rotation: normalized in double, a few ulps per component
    }
    EXPECT_LE(r.max_angle, tol);
    std::vector<quat> batch(s.t.size());
    r.curve.evaluate(std::span<const double>(s.t), std::span<quat>(batch));
    long double worst = 0;
    std::size_t at = 0;
    for (std::size_t i = 0; i < s.t.size(); ++i)
        for (const quat& c : {r.curve(s.t[i]), batch[i]}) {
            const long double e = true_angle(c, s.q[i]);
            if (e > worst) worst = e, at = i;
        }
    EXPECT_LE(worst, (long double)tol) << "sample " << at;
    // The bound is an upper bound (not below the true angle), and tight:
    // within 1e-13 rad of it (its slack is 16 eps relative + 4 |rho - 1| + 32 eps).
    EXPECT_GE((long double)r.max_angle, worst);
    EXPECT_LE((long double)r.max_angle, worst + 1e-13L);
}

}  // namespace

TEST(RotationFit, ProvedOnTheCorpus) {
    CRSPLINE_SEEDED(seed, 4041);
    std::mt19937_64 rng(seed);
    std::size_t streams = 0, samples = 0, keys = 0;
    for (const double tol_deg : {0.25, 1.0, 3.0})
        for (const auto& s : corpus(rng, 600, 2)) {
            const double tol = tol_deg * deg;
            const auto r = fit(s.t, s.q, tol);
            expect_proved(s, r, tol);
            ++streams, samples += s.t.size(), keys += r.count();
        }
    EXPECT_EQ(streams, 24u);
    // Keyframe reduction is the point: on this corpus (mostly 120 Hz
    // motion) fewer than a fifth of the samples stay.
    EXPECT_LT(keys * 5, samples) << keys << " keys of " << samples << " samples";
}

TEST(RotationFit, CountWithinFifteenPercentOfTheMinimum) {
    CRSPLINE_SEEDED(seed, 4042);
    std::mt19937_64 rng(seed);
    std::size_t fitted = 0, best = 0, cases = 0;
    for (const double tol_deg : {0.5, 2.0})
        for (const auto& s : corpus(rng, 40, 3)) {
            const double tol = tol_deg * deg;
            std::vector<quat> unit;
            for (const auto& q : s.q) unit.push_back(normalized(q));
            const detail_fit::fit_window<double> w(s.t, unit, tol);
            const std::size_t m = detail_fit::minimum_keys(w);
            const auto r = fit(s.t, s.q, tol);
            SCOPED_TRACE(s.name + " tolerance " + std::to_string(tol_deg) + " deg");
            // The fit cannot beat the optimum of its own segment test.
            EXPECT_GE(r.count(), m);
            fitted += r.count(), best += m, ++cases;
        }
    EXPECT_EQ(cases, 24u);
    std::printf("rotation fit: %zu keys against a minimum of %zu (%.3fx) over %zu streams\n", fitted, best,
                double(fitted) / double(best), cases);
    EXPECT_LE(double(fitted), 1.15 * double(best)) << fitted << " keys, minimum " << best;
}

// The bound is never below the true angle: random pairs at every scale from
// 1e-12 rad to pi, near pi too, with curve-like values (norm off by up to
// 1e-15). A bound without its rounding terms fails here.
TEST(RotationFit, AngleBoundIsAnUpperBound) {
    CRSPLINE_SEEDED(seed, 4043);
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> G;
    std::uniform_real_distribution<double> U(0, 1);
    std::size_t checked = 0, tight = 0;
    for (int k = 0; k < 200000; ++k) {
        const quat q = normalized(quat{G(rng), G(rng), G(rng), G(rng)});
        const double a = k % 2 ? std::numbers::pi - std::pow(10.0, -12 * U(rng)) : std::pow(10.0, -12 * U(rng)) * 3;
        quat r = from_axis_angle(v3{{G(rng), G(rng), G(rng)}}, a) * q;
        r = (1 + (U(rng) - 0.5) * 2e-15) * r;
        if (U(rng) < 0.5) r = -r;
        const long double truth = true_angle(r, q);
        const double b = detail_fit::angle_bound(r, q);
        ASSERT_GE((long double)b, truth) << "pair " << k;
        tight += (long double)b - truth < 4e-14L;
        ++checked;
    }
    EXPECT_EQ(checked, 200000u);
    EXPECT_EQ(tight, checked);  // and within 4e-14 rad (the slack's size at angles up to pi)
}

TEST(RotationFit, StillStreamsAndTwoSamplesKeepTwoKeys) {
    CRSPLINE_SEEDED(seed, 4044);
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> G;
    const quat q = normalized(quat{G(rng), G(rng), G(rng), G(rng)});
    std::vector<double> t;
    std::vector<quat> s;
    for (int i = 0; i < 500; ++i) t.push_back(i / 120.0), s.push_back(i % 3 ? q : -q);  // signs free
    const auto r = fit(t, s, 1e-9);
    EXPECT_EQ(r.count(), 2u);
    EXPECT_LE(r.max_angle, 1e-13);
    const std::vector<double> t2{0.0, 1.0};
    const std::vector<quat> s2{q, from_axis_angle(v3{{0, 0, 1}}, 3.0) * q};
    const auto r2 = fit(t2, s2, 1e-6);
    EXPECT_EQ(r2.count(), 2u);
    EXPECT_EQ(r2.indices, (std::vector<std::size_t>{0, 1}));
}

// Signs of the samples do not change the fit: q and -q are one rotation.
TEST(RotationFit, SignsOfTheSamplesDoNotMatter) {
    CRSPLINE_SEEDED(seed, 4045);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(0, 1);
    stream s = mocap(rng, 400, 120, 0.05 * deg);
    quat prev = quat::identity();
    for (auto& q : s.q) q = dot(prev, q) < 0 ? -q : q, prev = q;  // continuous
    const auto a = fit(s.t, s.q, 0.5 * deg);
    for (auto& q : s.q) q = U(rng) < 0.5 ? -q : q;
    const auto b = fit(s.t, s.q, 0.5 * deg);
    EXPECT_EQ(a.indices, b.indices);
    EXPECT_NEAR(a.max_angle, b.max_angle, 1e-15);
}

TEST(RotationFit, BadInputIsNamed) {
    const std::vector<double> t{0, 1, 2};
    const std::vector<quat> q{quat::identity(), from_axis_angle(v3{{1, 0, 0}}, 0.5), from_axis_angle(v3{{1, 0, 0}}, 1.0)};
    auto message = [](auto&& f) -> std::string {
        try {
            f();
        } catch (const crspline::invalid_input& e) {
            return e.what();
        }
        return "no error";
    };
    auto has = [](const std::string& m, const std::string& part) { return m.find(part) != std::string::npos; };
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    for (const double tol : {0.0, -1.0, nan, inf}) EXPECT_TRUE(has(message([&] { fit(t, q, tol); }), "angle_tolerance must be")) << tol;
    EXPECT_TRUE(has(message([&] { fit(t, q, 1e-14); }), "below what rounding"));
    EXPECT_TRUE(has(message([&] { fit(std::vector<double>{0}, std::vector<quat>{q[0]}, 0.1); }), "at least 2 samples, got 1"));
    EXPECT_TRUE(has(message([&] { fit(std::vector<double>{0, 1}, q, 0.1); }), "times has 2 values and quaternions 3 rows"));
    EXPECT_TRUE(has(message([&] { fit(std::vector<double>{0, 2, 2}, q, 0.1); }), "times is not increasing at index 2 (2 then 2)"));
    EXPECT_TRUE(has(message([&] { fit(std::vector<double>{0, nan, 2}, q, 0.1); }), "times 1 is not finite"));
    auto bad = q;
    bad[1] = quat{0, 0, 0, 0};
    EXPECT_TRUE(has(message([&] { fit(t, bad, 0.1); }), "sample 1 [0, 0, 0, 0] has norm 0: not a rotation"));
    bad[1] = 0.9 * q[1];  // normalized by default; a finite unit_tolerance refuses it
    EXPECT_EQ(fit(t, bad, 0.1).indices, fit(t, q, 0.1).indices);
    EXPECT_TRUE(has(message([&] { fit(t, bad, 0.1, rotation_fit_options<double>{1e-6}); }), "sample 1 [0.87"));
    bad[1] = quat{1, nan, 0, 0};
    EXPECT_TRUE(has(message([&] { fit(t, bad, 0.1); }), "sample 1: component 1 (x) is not finite"));
}
