// Properties of the rotation and pose splines, on seeded random keys (the
// seed is printed on failure; CRSPLINE_SEED reruns one). Tolerances are
// multiples of eps = 2.2e-16 with the reason beside each, or finite-difference
// bounds derived where they are used.
#include <gtest/gtest.h>

#include <crspline/rotation/angle_length.hpp>
#include <crspline/rotation/c2.hpp>
#include <crspline/rotation/catmull_rom.hpp>
#include <crspline/rotation/pose.hpp>

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

using crspline::test::eps;

quat random_quat(std::mt19937_64& rng) {
    std::normal_distribution<double> g;
    return normalized(quat{g(rng), g(rng), g(rng), g(rng)});
}

v3 props_random_vec(std::mt19937_64& rng, double length) {
    std::normal_distribution<double> g;
    v3 v{{g(rng), g(rng), g(rng)}};
    return v * (length / crspline::norm(v));
}

/// A walk: each key turns from the last by an angle in [lo, hi] degrees about
/// a random axis; signs random (the curves must not care).
std::vector<quat> props_random_keys(std::mt19937_64& rng, std::size_t n, double lo_deg, double hi_deg) {
    std::uniform_real_distribution<double> a(lo_deg, hi_deg), coin(0, 1);
    std::vector<quat> k{random_quat(rng)};
    while (k.size() < n) {
        const double ang = a(rng) * std::numbers::pi / 180;
        quat q = from_rotation_vector(props_random_vec(rng, ang)) * k.back();
        k.push_back(coin(rng) < 0.5 ? q : -q);
    }
    return k;
}

std::vector<double> props_random_times(std::mt19937_64& rng, std::size_t n) {
    std::uniform_real_distribution<double> d(0.3, 2.0);
    std::vector<double> t{d(rng) - 1};
    while (t.size() < n) t.push_back(t.back() + d(rng));
    return t;
}

double props_qdiff(const quat& a, const quat& b) {
    return std::max({std::abs(a.w - b.w), std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}
double props_qdiff_sign(const quat& a, const quat& b) { return std::min(props_qdiff(a, b), props_qdiff(a, -b)); }

const spline_kind quaternion_kinds[] = {spline_kind::catmull_rom, spline_kind::kochanek_bartels, spline_kind::piecewise_slerp,
                                        spline_kind::barry_goldman, spline_kind::squad};

rotation_options<double> make_options(spline_kind k, bool closed, std::optional<double> alpha) {
    rotation_options<double> o;
    o.kind = k;
    o.closed = closed;
    o.alpha = alpha;
    if (k == spline_kind::kochanek_bartels) o.kb = {{0.2, 0, 0.3}};  // continuity 0 keeps C1
    return o;
}

/// World angular velocity from the rotation by central differences:
/// omega = 2 vec(dq/dt conj(q)). Error: h^2/6 |q'''| (truncation) + eps/h
/// (rounding of q, which is O(1)); with h = 1e-5 and |q'''| <= (|omega| +
/// |alpha|^(1/2))^3 ~ 1e3 at most here, under 2e-8 + 2e-11.
template <class F>
v3 fd_omega(F q, double t, double h) {
    const quat d = (1 / (2 * h)) * (q(t + h) - q(t - h));
    const quat p = d * conj(q(t));
    return 2.0 * p.vector();
}

}  // namespace

TEST(RotationProperties, UnitNormAndKeys) {
    CRSPLINE_SEEDED(seed, 2811);
    std::mt19937_64 rng(seed);
    int checked = 0;
    for (int round = 0; round < 20; ++round) {
        const std::size_t n = 2 + rng() % 8;
        const auto keys = props_random_keys(rng, n, 1, 170);
        for (bool closed : {false, true})
            for (auto kind : quaternion_kinds)
                for (std::optional<double> alpha : {std::optional<double>{}, std::optional<double>{0.5}}) {
                    const quaternion_spline<double> c(keys, make_options(kind, closed, alpha));
                    // At the keys: the canonical key exactly at u = 0 (a slerp by 0 is
                    // exp(0) a = a, up to one rounding of the product: 4 eps).
                    for (std::size_t k = 0; k + 1 < c.grid().size(); ++k)
                        EXPECT_LE(props_qdiff(c.evaluate_on(k, c.grid()[k]).q, c.keys()[k]), 4 * eps) << "key " << k;
                    // The last knot: the De Casteljau value at u = 1, within a few roundings per level (3 levels, 16 eps).
                    EXPECT_LE(props_qdiff(c(c.grid().back()), c.keys().back()), 16 * eps);
                    std::uniform_real_distribution<double> u(c.grid().front(), c.grid().back());
                    for (int s = 0; s < 20; ++s) {
                        const auto j = c.evaluate(u(rng), 2);
                        // Unit norm: products of unit quaternions, a few roundings each (De Casteljau's 6 slerps, 32 eps).
                        EXPECT_LE(std::abs(norm(j.q) - 1), 32 * eps);
                        EXPECT_TRUE(std::isfinite(j.omega[0] + j.omega[1] + j.omega[2] + j.alpha[0] + j.alpha[1] + j.alpha[2]));
                        ++checked;
                    }
                }
    }
    EXPECT_EQ(checked, 20 * 2 * 5 * 2 * 20);
}

// dq/dt = 1/2 [0, omega] q in the world frame, and the body frame's omega =
// R^T omega_world; alpha = d omega/dt likewise by central differences of the
// exact omega (error h^2/6 |omega'''| + eps |omega|/h; tolerance 1e-6 of the
// scale (1 + |omega| + |alpha|)^3 covers both with h = 1e-5).
TEST(RotationProperties, AngularVelocityIsTheDerivative) {
    CRSPLINE_SEEDED(seed, 2812);
    std::mt19937_64 rng(seed);
    int checked = 0;
    const double h = 1e-5;
    for (int round = 0; round < 10; ++round) {
        const std::size_t n = 3 + rng() % 6;
        const auto keys = props_random_keys(rng, n, 5, 150);
        const auto times = props_random_times(rng, n);
        auto check = [&](const auto& c, double t) {
            const auto j = c.evaluate(t, 2);
            const double scale = std::pow(1 + crspline::max_abs(j.omega) + crspline::max_abs(j.alpha), 3);
            const v3 w = fd_omega([&](double x) { return c.evaluate_on(c.locate(t), x).q; }, t, h);
            EXPECT_LE(crspline::max_abs(w - j.omega), 1e-6 * scale) << "t " << t;
            const v3 a = (c.evaluate_on(c.locate(t), t + h, 1).omega - c.evaluate_on(c.locate(t), t - h, 1).omega) / (2 * h);
            EXPECT_LE(crspline::max_abs(a - j.alpha), 1e-6 * scale) << "t " << t;
            const auto b = c.evaluate(t, 2, frame::body);
            EXPECT_LE(crspline::max_abs(rotate(j.q, b.omega) - j.omega), 8 * eps * scale);
            EXPECT_LE(crspline::max_abs(rotate(j.q, b.alpha) - j.alpha), 8 * eps * scale);
            ++checked;
        };
        for (bool closed : {false, true}) {
            for (auto kind : quaternion_kinds) {
                const quaternion_spline<double> c(keys, make_options(kind, closed, 0.5));
                std::uniform_real_distribution<double> u(c.grid().front() + 2 * h, c.grid().back() - 2 * h);
                for (int s = 0; s < 10; ++s) check(c, u(rng));
            }
            auto t = times;
            if (closed) t.push_back(t.back() + 1);
            for (auto end : {c2_end<double>::scipy(), c2_end<double>::natural()}) {
                c2_options<double> o;
                o.closed = closed, o.start = o.end = end;
                const c2_rotation_spline<double> c(t, keys, o);
                std::uniform_real_distribution<double> u(t.front() + 2 * h, t.back() - 2 * h);
                for (int s = 0; s < 10; ++s) check(c, u(rng));
            }
        }
    }
    EXPECT_EQ(checked, 10 * 2 * (5 + 2) * 10);
}

// C1 at every key and across the closed seam (Catmull-Rom, Kochanek-Bartels
// with continuity 0, Barry-Goldman, Squad); C2 for the C2 spline. The two
// sides' omega at a knot are each exact to rounding of their construction
// (a few hundred eps of the scale); the acceleration jump of the C2 spline
// is its residual, at most 1e-9 of the acceleration scale.
TEST(RotationProperties, ContinuityAcrossKeysAndSeam) {
    CRSPLINE_SEEDED(seed, 2813);
    std::mt19937_64 rng(seed);
    int joins = 0;
    for (int round = 0; round < 10; ++round) {
        const std::size_t n = 3 + rng() % 8;
        const auto keys = props_random_keys(rng, n, 1, 170);
        for (bool closed : {false, true}) {
            for (auto kind : {spline_kind::catmull_rom, spline_kind::kochanek_bartels, spline_kind::barry_goldman, spline_kind::squad}) {
                const quaternion_spline<double> c(keys, make_options(kind, closed, 0.5));
                const std::size_t nseg = c.segment_count();
                for (std::size_t k = 1; k <= nseg; ++k) {
                    if (k == nseg && !closed) break;
                    const std::size_t after = k % nseg;
                    const double t = c.grid()[k];
                    const auto l = c.evaluate_on(k - 1, t, 1);
                    // At the seam the far side is segment 0 at t0 (the same rotation, maybe the other sign).
                    const auto r = c.evaluate_on(after, after == 0 ? c.grid()[0] : t, 1);
                    const double scale = 1 + crspline::max_abs(l.omega);
                    EXPECT_LE(props_qdiff_sign(l.q, r.q), 64 * eps) << "key " << k;
                    EXPECT_LE(crspline::max_abs(l.omega - r.omega), 1e-12 * scale) << "key " << k << " kind " << int(kind);
                    ++joins;
                }
            }
            auto t = props_random_times(rng, n + (closed ? 1 : 0));
            c2_options<double> o;
            o.closed = closed;
            const c2_rotation_spline<double> c(t, keys, o);
            double ascale = 1;
            for (std::size_t k = 0; k + 1 < t.size(); ++k) ascale = std::max(ascale, crspline::max_abs(c.evaluate_on(k, t[k], 2).alpha));
            EXPECT_LE(c.residual(), 1e-9 * ascale);
            for (std::size_t k = 1; k < t.size(); ++k) {
                if (k + 1 == t.size() && !closed) break;
                const std::size_t after = k + 1 == t.size() ? 0 : k;
                const auto l = c.evaluate_on(k - 1, t[k], 2), r = c.evaluate_on(after, after == 0 ? t[0] : t[k], 2);
                EXPECT_LE(props_qdiff_sign(l.q, r.q), 64 * eps);
                EXPECT_LE(crspline::max_abs(l.omega - r.omega), 1e-12 * (1 + crspline::max_abs(l.omega)));
                EXPECT_LE(crspline::max_abs(l.alpha - r.alpha), 1e-9 * ascale) << "key " << k;
                ++joins;
            }
        }
    }
    EXPECT_GE(joins, 10 * 2 * 5 * 2);
}

// The C2 spline with 200 keys and 170 degree steps: converged, every
// acceleration jump at rounding (<= 1e-9 of the scale), and the ends as asked.
TEST(RotationProperties, C2ManyKeysLargeSteps) {
    CRSPLINE_SEEDED(seed, 2814);
    std::mt19937_64 rng(seed);
    const std::size_t n = 200;
    const auto keys = props_random_keys(rng, n, 160, 170);
    const auto t = props_random_times(rng, n);
    const v3 w0{{0.3, -0.2, 0.5}}, w1{{-1, 0.5, 0.25}};
    int ends = 0;
    for (int variant = 0; variant < 3; ++variant) {
        c2_options<double> o;
        if (variant == 1) o.start = o.end = c2_end<double>::natural();
        if (variant == 2) o.start = c2_end<double>::velocity(w0), o.end = c2_end<double>::velocity(w1, frame::body);
        const c2_rotation_spline<double> c(t, keys, o);
        double ascale = 1;
        for (std::size_t k = 0; k + 1 < n; ++k) ascale = std::max(ascale, crspline::max_abs(c.evaluate_on(k, t[k], 2).alpha));
        EXPECT_LE(c.residual(), 1e-9 * ascale) << "variant " << variant << " iterations " << c.iterations();
        for (std::size_t k = 1; k + 1 < n; ++k)
            ASSERT_LE(crspline::max_abs(c.evaluate_on(k - 1, t[k], 2).alpha - c.evaluate_on(k, t[k], 2).alpha), 1e-9 * ascale)
                << "variant " << variant << " key " << k;
        if (variant == 1) {
            EXPECT_LE(crspline::max_abs(c.evaluate(t.front(), 2).alpha), 1e-9 * ascale);
            EXPECT_LE(crspline::max_abs(c.evaluate(t.back(), 2).alpha), 1e-9 * ascale);
            ends += 2;
        }
        if (variant == 2) {
            EXPECT_LE(crspline::max_abs(c.angular_velocity(t.front()) - w0), 1e-13);
            EXPECT_LE(crspline::max_abs(c.angular_velocity(t.back(), frame::body) - w1), 1e-13);
            ends += 2;
        }
    }
    EXPECT_EQ(ends, 4);
}

// Time reversal: the keys and times reversed give the same rotations at
// mirrored t (slerp(a, b, u) = slerp(b, a, 1 - u); the tangent construction
// is symmetric). Closed curves, Kochanek-Bartels, De Casteljau and the pose
// curve: TimeReversalClosedAndOtherKinds. The C2 spline is reversible only
// where its keys commute (SciPy's segments are anchored at their left key,
// R_i Exp(theta(t)), and Exp(-r) Exp(theta) is not Exp of a cubic):
// C2TimeReversal* below.
TEST(RotationProperties, TimeReversal) {
    CRSPLINE_SEEDED(seed, 2815);
    std::mt19937_64 rng(seed);
    int checked = 0;
    for (int round = 0; round < 10; ++round) {
        const std::size_t n = 3 + rng() % 6;
        auto keys = props_random_keys(rng, n, 1, 150);
        auto rev = std::vector<quat>(keys.rbegin(), keys.rend());
        for (auto kind : {spline_kind::catmull_rom, spline_kind::piecewise_slerp, spline_kind::barry_goldman, spline_kind::squad}) {
            auto o = make_options(kind, false, 0.5);
            const quaternion_spline<double> a(keys, o), b(rev, o);
            const double T = a.grid().back();
            EXPECT_NEAR(b.grid().back(), T, 64 * eps * T);
            std::uniform_real_distribution<double> u(0, T);
            for (int s = 0; s < 20; ++s) {
                const double t = u(rng);
                // Tolerance: the two evaluations round differently through up to 6
                // slerps of O(1) values: 1e-13 leaves room for that, not for a wrong construction.
                EXPECT_LE(props_qdiff_sign(a(t), b(std::clamp(b.grid().back() - t, 0.0, b.grid().back()))), 1e-13)
                    << "kind " << int(kind) << " t " << t;
                ++checked;
            }
        }
    }
    EXPECT_EQ(checked, 10 * 4 * 20);
}

// Invariance: keys g q_k give g q(t) (a fixed rotation in the world frame),
// keys q_k g give q(t) g (in the body frame); omega rotates with g on the left.
TEST(RotationProperties, FixedRotationOnEitherSide) {
    CRSPLINE_SEEDED(seed, 2816);
    std::mt19937_64 rng(seed);
    int checked = 0;
    for (int round = 0; round < 10; ++round) {
        const std::size_t n = 3 + rng() % 6;
        const auto keys = props_random_keys(rng, n, 1, 150);
        const auto times = props_random_times(rng, n);
        const quat g = random_quat(rng);
        std::vector<quat> left, right;
        for (const auto& q : keys) left.push_back(g * q), right.push_back(q * g);
        for (auto kind : quaternion_kinds) {
            const auto o = make_options(kind, round % 2 == 1, 0.5);
            const quaternion_spline<double> a(keys, o), l(left, o), r(right, o);
            std::uniform_real_distribution<double> u(a.grid().front(), a.grid().back());
            for (int s = 0; s < 10; ++s) {
                const double t = u(rng);
                const auto ja = a.evaluate(t, 1), jl = l.evaluate(t, 1);
                // Rounding only (a few slerps, one extra product): 1e-13.
                EXPECT_LE(props_qdiff_sign(g * ja.q, jl.q), 1e-13);
                EXPECT_LE(props_qdiff_sign(ja.q * g, r(t)), 1e-13);
                EXPECT_LE(crspline::max_abs(rotate(g, ja.omega) - jl.omega), 1e-12 * (1 + crspline::max_abs(ja.omega)));
                ++checked;
            }
        }
        const c2_rotation_spline<double> a(times, keys), l(times, left), r(times, right);
        std::uniform_real_distribution<double> u(times.front(), times.back());
        for (int s = 0; s < 10; ++s) {
            const double t = u(rng);
            EXPECT_LE(props_qdiff_sign(g * a(t), l(t)), 1e-13);
            EXPECT_LE(props_qdiff_sign(a(t) * g, r(t)), 1e-13);
            ++checked;
        }
    }
    EXPECT_EQ(checked, 10 * (5 + 1) * 10);
}

// q and -q: random sign flips of the keys give the same rotations.
TEST(RotationProperties, SignsOfKeysDoNotMatter) {
    CRSPLINE_SEEDED(seed, 2817);
    std::mt19937_64 rng(seed);
    int checked = 0;
    for (int round = 0; round < 10; ++round) {
        const std::size_t n = 2 + rng() % 7;
        const auto keys = props_random_keys(rng, n, 1, 179);
        auto flipped = keys;
        for (auto& q : flipped)
            if (rng() % 2) q = -q;
        const auto times = props_random_times(rng, n);
        for (auto kind : quaternion_kinds) {
            const auto o = make_options(kind, round % 2 == 1, 0.5);
            const quaternion_spline<double> a(keys, o), b(flipped, o);
            std::uniform_real_distribution<double> u(a.grid().front(), a.grid().back());
            for (int s = 0; s < 10; ++s) {
                const double t = u(rng);
                EXPECT_LE(props_qdiff_sign(a(t), b(t)), 4 * eps);  // the same canonical keys up to one overall sign
                ++checked;
            }
        }
        const c2_rotation_spline<double> a(times, keys), b(times, flipped);
        std::uniform_real_distribution<double> u(times.front(), times.back());
        for (int s = 0; s < 10; ++s) {
            const double t = u(rng);
            EXPECT_LE(props_qdiff_sign(a(t), b(t)), 1e-14);  // conj(q_i) q_(i+1) changes sign, the short-way step does not
            ++checked;
        }
    }
    EXPECT_EQ(checked, 10 * 6 * 10);
}

// Two keys: every class is slerp(k0, k1, u) (the C2 spline with SciPy's ends too).
TEST(RotationProperties, TwoKeysGiveSlerp) {
    CRSPLINE_SEEDED(seed, 2818);
    std::mt19937_64 rng(seed);
    int checked = 0;
    for (int round = 0; round < 20; ++round) {
        auto keys = props_random_keys(rng, 2, 1, 179);
        if (dot(keys[0], keys[1]) < 0) keys[1] = -keys[1];
        const std::vector<double> times{0.5, 2.0};
        for (auto kind : {spline_kind::catmull_rom, spline_kind::kochanek_bartels, spline_kind::piecewise_slerp}) {
            auto o = make_options(kind, false, std::nullopt);
            o.grid = times;
            const quaternion_spline<double> c(keys, o);
            for (int s = 0; s <= 10; ++s) {
                const double u = s / 10.0;
                EXPECT_LE(props_qdiff_sign(c(0.5 + 1.5 * u), slerp(keys[0], keys[1], u)), 1e-14);
                ++checked;
            }
        }
        const c2_rotation_spline<double> c(times, keys);
        for (int s = 0; s <= 10; ++s) {
            const double u = s / 10.0;
            EXPECT_LE(props_qdiff_sign(c(0.5 + 1.5 * u), slerp(keys[0], keys[1], u)), 1e-14);
            ++checked;
        }
    }
    EXPECT_EQ(checked, 20 * 4 * 11);
}

// The small-angle limit: keys exp(e v_k / 2) with e = 1e-6; the rotation
// vectors of the quaternion Catmull-Rom (documented natural ends) follow the
// Euclidean crspline::catmull_rom through e v_k on the same grid to O(e^2)
// (the first correction is a commutator, |[a, b]| <= |a| |b|): tolerance
// 10 e^2 max|v|^2 (1e-5 of the key spacing e |v| here). The package's
// natural end misses it by a fraction of the spacing (5% in the reference
// file's note): more than 1e-3 of the spacing in at least 8 of 10 draws.
TEST(RotationProperties, SmallAngleLimitIsEuclidean) {
    CRSPLINE_SEEDED(seed, 2819);
    std::mt19937_64 rng(seed);
    const double e = 1e-6;
    int checked = 0, package_far = 0;
    for (int round = 0; round < 10; ++round) {
        const std::size_t n = 4 + rng() % 5;
        std::vector<crspline::vec<3, double>> v;
        std::vector<quat> keys;
        std::normal_distribution<double> g;
        for (std::size_t k = 0; k < n; ++k) {
            v.push_back(crspline::vec<3, double>{{g(rng), g(rng), g(rng)}});
            keys.push_back(from_rotation_vector(v.back() * e));
        }
        double vmax = 0;
        for (const auto& x : v) vmax = std::max(vmax, crspline::max_abs(x));
        const auto times = props_random_times(rng, n);
        crspline::options<3, double> eo;
        eo.grid = times;
        std::vector<crspline::vec<3, double>> ev;
        for (const auto& x : v) ev.push_back(x * e);
        const crspline::catmull_rom<3, double> euclid(ev, eo);
        rotation_options<double> ro;
        ro.grid = times;
        const quaternion_spline<double> rot(keys, ro);
        ro.start = ro.end = rotation_end<double>::natural_splines();
        const quaternion_spline<double> pkg(keys, ro);
        double pkg_dev = 0;
        std::uniform_real_distribution<double> u(times.front(), times.back());
        for (int s = 0; s < 50; ++s) {
            const double t = u(rng);
            const auto x = euclid(t);
            EXPECT_LE(crspline::max_abs(to_rotation_vector(rot(t)) - x), 10 * e * e * vmax * vmax) << "t " << t;
            pkg_dev = std::max(pkg_dev, crspline::max_abs(to_rotation_vector(pkg(t)) - x));
            ++checked;
        }
        if (pkg_dev > 1e-3 * e * vmax) ++package_far;
    }
    EXPECT_EQ(checked, 500);
    EXPECT_GE(package_far, 8);  // the package's end is a different curve (at least 8 of 10 draws show it)
}

// Angle length: a piecewise slerp turns through the sum of its key-to-key
// angles exactly (constant angular speed per segment), so the table's total
// and its inverse are checked against closed forms, to the 1e-12 promised.
TEST(RotationProperties, AngleLengthAndConstantAngularSpeed) {
    CRSPLINE_SEEDED(seed, 2820);
    std::mt19937_64 rng(seed);
    int checked = 0;
    for (int round = 0; round < 10; ++round) {
        const std::size_t n = 2 + rng() % 8;
        const auto keys = props_random_keys(rng, n, 1, 170);
        auto o = make_options(spline_kind::piecewise_slerp, false, std::nullopt);
        o.grid = props_random_times(rng, n);
        const quaternion_spline<double> c(keys, o);
        double exact = 0;
        for (std::size_t k = 0; k + 1 < n; ++k) exact += angle_between(c.keys()[k], c.keys()[k + 1]);
        const auto table = angle_table(c);
        EXPECT_NEAR(table.total(), exact, 1e-12 * exact);
        // Round trip s -> t -> s, and t at equal angle steps.
        const auto ts = table.equal_steps(33);
        ASSERT_EQ(ts.size(), 33u);
        for (std::size_t k = 0; k < ts.size(); ++k) {
            EXPECT_NEAR(table.length_at(ts[k]), exact * double(k) / 32, 1e-11 * exact) << "sample " << k;
            ++checked;
        }
        // Catmull-Rom: length_at is monotone and its derivative is |omega|.
        const quaternion_spline<double> cr(keys, make_options(spline_kind::catmull_rom, false, 0.5));
        const auto t2 = angle_table(cr);
        std::uniform_real_distribution<double> u(cr.grid().front() + 1e-3, cr.grid().back() - 1e-3);
        for (int s = 0; s < 10; ++s) {
            const double t = u(rng), h = 1e-4;
            // Central difference of the integral: error h^2/6 |speed''| ~ 1e-9 here.
            const double d = (t2.length_at(t + h) - t2.length_at(t - h)) / (2 * h);
            EXPECT_NEAR(d, crspline::norm(cr.angular_velocity(t)), 1e-6 * (1 + d));
            EXPECT_NEAR(t2.t_at(t2.length_at(t)), t, 1e-12 * (1 + std::abs(t)));
            ++checked;
        }
    }
    EXPECT_EQ(checked, 10 * (33 + 10));
}

// Repeated keys with alpha > 0: the zero-interval limit (finite values, the
// curve rests there), refused under strict with both indices.
TEST(RotationProperties, RepeatedKeys) {
    std::vector<quat> keys{quat{1, 0, 0, 0}, from_rotation_vector(v3{{0.5, 0, 0}}), from_rotation_vector(v3{{0.5, 0, 0}}),
                           from_rotation_vector(v3{{0.5, 1, 0}})};
    for (auto kind : quaternion_kinds) {
        auto o = make_options(kind, false, 0.5);
        const quaternion_spline<double> c(keys, o);
        EXPECT_EQ(c.grid()[1], c.grid()[2]);
        for (int s = 0; s <= 100; ++s) {
            const double t = c.grid().back() * s / 100;
            const auto j = c.evaluate(t, 2);
            ASSERT_TRUE(std::isfinite(j.q.w + j.q.x + j.q.y + j.q.z + j.omega[0] + j.omega[1] + j.omega[2] + j.alpha[0] + j.alpha[1] + j.alpha[2]))
                << "kind " << int(kind) << " t " << t;
        }
        o.strict = true;
        try {
            const quaternion_spline<double> s(keys, o);
            ADD_FAILURE() << "strict accepted a repeated key";
        } catch (const crspline::invalid_input& e) {
            EXPECT_NE(std::string(e.what()).find("keys 1 and 2"), std::string::npos) << e.what();
        }
    }
}

TEST(RotationProperties, BadInputIsNamed) {
    const quat a{1, 0, 0, 0}, b = from_rotation_vector(v3{{0.5, 0, 0}});
    auto message = [](auto f) {
        try {
            f();
        } catch (const crspline::invalid_input& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    // Keys are normalized, as SciPy's from_quat does (issue 42); a finite
    // unit_tolerance (the splines drop-in's 1e-6) refuses them instead.
    const std::vector<quat> nonunit{a, quat{0.9, 0, 0, 0}, b};
    const quaternion_spline<double> normalized(nonunit);
    EXPECT_LE(std::abs(norm(normalized.keys()[1]) - 1), eps);
    EXPECT_EQ(normalized.keys()[1].w, 1.0);  // 0.9 / 0.9 exactly
    rotation_options<double> checked;
    checked.unit_tolerance = 1e-6;
    EXPECT_NE(message([&] { quaternion_spline<double> c(nonunit, checked); }).find("key 1 [0.9, 0, 0, 0] is not a unit quaternion"), std::string::npos);
    c2_options<double> checked_c2;
    checked_c2.unit_tolerance = 1e-6;
    const std::vector<double> t3{0, 1, 2};
    EXPECT_NE(message([&] { c2_rotation_spline<double> c(t3, nonunit, checked_c2); }).find("key 1 [0.9, 0, 0, 0] is not a unit quaternion"), std::string::npos);
    EXPECT_LE(std::abs(norm(c2_rotation_spline<double>(t3, nonunit).keys()[1]) - 1), eps);
    // Zero is no rotation, whatever the tolerance; tiny and huge keys are scaled first.
    const std::vector<quat> zero{a, quat{0, 0, 0, 0}, b};
    EXPECT_NE(message([&] { quaternion_spline<double> c(zero); }).find("key 1 [0, 0, 0, 0] has norm 0: not a rotation"), std::string::npos);
    EXPECT_NE(message([&] { c2_rotation_spline<double> c(t3, zero); }).find("key 1 [0, 0, 0, 0] has norm 0"), std::string::npos);
    const std::vector<quat> extreme{quat{1e-320, 0, 0, 0}, quat{1e300, 1e300, 0, 0}};
    const quaternion_spline<double> scaled(extreme);
    EXPECT_EQ(scaled.keys()[0].w, 1.0);
    EXPECT_LE(std::abs(norm(scaled.keys()[1]) - 1), eps);
    const std::vector<quat> nan{a, b, quat{1, std::nan(""), 0, 0}};
    EXPECT_NE(message([&] { quaternion_spline<double> c(nan); }).find("key 2: component 1 (x) is not finite (nan)"), std::string::npos);
    const std::vector<quat> nearly{a, quat{1 + 1e-9, 0, 0, 0}};
    const quaternion_spline<double> ok(nearly);  // within the tolerance: normalized
    EXPECT_LE(std::abs(norm(ok.keys()[1]) - 1), eps);
    const std::vector<quat> two{a, b};
    const std::vector<double> bad_t{0, 0};
    EXPECT_NE(message([&] { c2_rotation_spline<double> c(bad_t, two); }).find("time 1 (0) follows 0"), std::string::npos);
    rotation_options<double> o;
    o.alpha = 1.5;
    EXPECT_NE(message([&] { quaternion_spline<double> c(two, o); }).find("alpha must be in [0, 1], got 1.5"), std::string::npos);
    o.alpha = 0.5, o.grid = std::vector<double>{0, 1};
    EXPECT_NE(message([&] { quaternion_spline<double> c(two, o); }).find("either a grid or alpha"), std::string::npos);
    EXPECT_THROW(quaternion_spline<double>(two).evaluate(1.5), crspline::out_of_domain);
}

TEST(RotationProperties, Conversions) {
    CRSPLINE_SEEDED(seed, 2821);
    std::mt19937_64 rng(seed);
    int checked = 0;
    const char* conventions[] = {"xyz", "xzy", "yxz", "yzx", "zxy", "zyx", "xyx", "xzx", "yxy", "yzy", "zxz", "zyz"};
    for (int round = 0; round < 50; ++round) {
        quat q = random_quat(rng);
        if (round < 10) {
            // Gimbal lock: a second angle of exactly 0 or pi / +-pi/2 in some convention.
            q = from_euler(euler_convention::parse(round % 2 ? "zyx" : "zxz"),
                           std::array<double, 3>{0.3, round % 2 ? std::numbers::pi / 2 : 0.0, -1.1});
        }
        // Matrix, rotation vector and axis-angle round trips (up to sign), and rotate = matrix product.
        EXPECT_LE(props_qdiff_sign(from_matrix(to_matrix(q)), q), 8 * eps);
        EXPECT_LE(props_qdiff_sign(from_rotation_vector(to_rotation_vector(q)), q), 8 * eps);
        const auto aa = to_axis_angle(q);
        EXPECT_LE(props_qdiff_sign(from_axis_angle(aa.axis, aa.angle), q), 8 * eps);
        const v3 x = props_random_vec(rng, 2.0);
        const auto m = to_matrix(q);
        v3 mx{};
        for (std::size_t i = 0; i < 3; ++i) mx[i] = m[i][0] * x[0] + m[i][1] * x[1] + m[i][2] * x[2];
        EXPECT_LE(crspline::max_abs(rotate(q, x) - mx), 16 * eps);
        for (const char* name : conventions)
            for (bool upper : {false, true}) {
                std::string s = name;
                if (upper)
                    for (auto& ch : s) ch = char(ch - 'a' + 'A');
                const auto c = euler_convention::parse(s);
                const auto e = to_euler(c, q);
                // Near gimbal lock an angle's error grows like eps / sin(second angle): 1e-9 holds there too.
                EXPECT_LE(props_qdiff_sign(from_euler(c, e), q), round < 10 ? 1e-9 : 1e-14) << s;
                ++checked;
            }
    }
    EXPECT_EQ(checked, 50 * 24);
    EXPECT_THROW(euler_convention::parse("xxy"), crspline::invalid_input);
    EXPECT_THROW(euler_convention::parse("xYz"), crspline::invalid_input);
    // Extrinsic xyz is R_z R_y R_x: a quarter turn about x then about z.
    const quat q = from_euler(euler_convention::parse("xyz"), std::array<double, 3>{std::numbers::pi / 2, 0, std::numbers::pi / 2});
    const v3 y = rotate(q, v3{{0, 1, 0}});  // x-turn takes y to z; the z-turn leaves z
    EXPECT_LE(crspline::max_abs(y - v3{{0, 0, 1}}), 4 * eps);
}

// The pose curve: positions are crspline::catmull_rom's, orientations the C2
// rotation spline's on the same grid, body-frame rates R^T of the world ones;
// a batch of 10^6 samples evaluates every one.
TEST(RotationProperties, PoseCurve) {
    CRSPLINE_SEEDED(seed, 2822);
    std::mt19937_64 rng(seed);
    const std::size_t n = 12;
    const auto keys = props_random_keys(rng, n, 5, 120);
    const auto pos = crspline::test::random_polygon<3>(rng, n);
    const pose_curve<double> p(pos, keys);
    crspline::options<3, double> eo;
    eo.alpha = 0.5;
    const crspline::catmull_rom<3, double> pc(pos, eo);
    const c2_rotation_spline<double> rc(pc.grid(), keys);
    std::uniform_real_distribution<double> u(pc.grid().front(), pc.grid().back());
    for (int s = 0; s < 50; ++s) {
        const double t = u(rng);
        const auto w = p.evaluate(t), b = p.evaluate(t, frame::body);
        EXPECT_LE(crspline::max_abs(w.position - pc(t)), 0.0);
        EXPECT_LE(crspline::max_abs(w.velocity - pc.evaluate(t, 1)), 8 * eps * crspline::max_abs(w.velocity));
        EXPECT_LE(props_qdiff(w.orientation, rc(t)), 0.0);
        EXPECT_LE(crspline::max_abs(rotate(b.orientation, b.velocity) - w.velocity), 8 * eps * (1 + crspline::max_abs(w.velocity)));
        EXPECT_LE(crspline::max_abs(rotate(b.orientation, b.omega) - w.omega), 8 * eps * (1 + crspline::max_abs(w.omega)));
    }
    std::vector<double> ts(1000000);
    for (auto& t : ts) t = u(rng);
    const auto out = p.evaluate(ts);
    ASSERT_EQ(out.size(), ts.size());
    std::size_t good = 0;
    for (const auto& s : out) good += std::abs(norm(s.orientation) - 1) <= 32 * eps && std::isfinite(s.omega[0]);
    EXPECT_EQ(good, ts.size());
    // Constant speed along the path: equal position arc lengths between samples.
    const auto cs = p.constant_speed_times(21);
    const auto table = crspline::rotation::speed_table<double>(
        pc.grid(), [&](std::size_t, double t) { return crspline::norm(pc.evaluate(t, 1)); });
    for (std::size_t k = 0; k < cs.size(); ++k) EXPECT_NEAR(table.length_at(cs[k]), table.total() * double(k) / 20, 1e-10 * table.total());
}

// keep_signs: a key given with a negative dot is reached the long way (the
// piecewise slerp turns through 2 pi - theta instead of theta; a closed form
// to 1e-12 relative, the angle table's promise); by default the short way.
TEST(RotationProperties, KeepSignsTakesTheLongWay) {
    CRSPLINE_SEEDED(seed, 2823);
    std::mt19937_64 rng(seed);
    int checked = 0;
    for (int round = 0; round < 20; ++round) {
        auto keys = props_random_keys(rng, 2, 10, 170);
        if (dot(keys[0], keys[1]) > 0) keys[1] = -keys[1];
        const double theta = angle_between(keys[0], keys[1]);
        auto o = make_options(spline_kind::piecewise_slerp, false, std::nullopt);
        const quaternion_spline<double> short_way(keys, o);
        o.keep_signs = true;
        const quaternion_spline<double> long_way(keys, o);
        EXPECT_NEAR(angle_length(short_way), theta, 1e-12 * theta);
        EXPECT_NEAR(angle_length(long_way), 2 * std::numbers::pi - theta, 1e-12 * 2 * std::numbers::pi);
        // Both end at the same rotation.
        EXPECT_LE(props_qdiff_sign(short_way(1.0), long_way(1.0)), 8 * eps);
        ++checked;
    }
    EXPECT_EQ(checked, 20);
}

// Given angular velocities at the ends of an open Catmull-Rom curve: the
// curve's own omega there is the given one (world frame, or body frame
// rotated by the end key), to rounding of the control quaternion exp(w h/6) k
// and of the exact derivative (1e-13 of the scale).
TEST(RotationProperties, GivenEndAngularVelocity) {
    CRSPLINE_SEEDED(seed, 2824);
    std::mt19937_64 rng(seed);
    int checked = 0;
    for (int round = 0; round < 20; ++round) {
        const std::size_t n = 3 + rng() % 5;
        const auto keys = props_random_keys(rng, n, 5, 120);
        const v3 w0 = props_random_vec(rng, 1.5), w1 = props_random_vec(rng, 0.7);
        auto o = make_options(spline_kind::catmull_rom, false, 0.5);
        o.start = rotation_end<double>::velocity(w0);
        o.end = rotation_end<double>::velocity(w1, frame::body);
        const quaternion_spline<double> c(keys, o);
        const auto g = c.grid();
        EXPECT_LE(crspline::max_abs(c.angular_velocity(g.front()) - w0), 1e-13 * (1 + crspline::norm(w0)));
        EXPECT_LE(crspline::max_abs(c.angular_velocity(g.back(), frame::body) - w1), 1e-13 * (1 + crspline::norm(w1)));
        ++checked;
    }
    EXPECT_EQ(checked, 20);
}

// ----- time reversal of the C2 spline and of the classes not covered above -----

namespace {

/// Keys and times reversed (open), or the cycle reversed from key 0 (closed:
/// keys q0, q_(n-1), ..., q1), with times mirrored: t' = t_0 + t_end - t.
struct reversed_curve {
    std::vector<quat> keys;
    std::vector<double> times;
};
reversed_curve reverse_keys(const std::vector<quat>& keys, const std::vector<double>& times, bool closed) {
    reversed_curve r;
    if (closed) {
        r.keys.push_back(keys[0]);
        for (std::size_t k = keys.size() - 1; k >= 1; --k) r.keys.push_back(keys[k]);
    } else {
        r.keys.assign(keys.rbegin(), keys.rend());
    }
    for (std::size_t k = times.size(); k-- > 0;) r.times.push_back(times.front() + times.back() - times[k]);
    return r;
}

/// The largest rotation difference (either sign) between a(t) on [t0, t1]
/// and b at the mirrored t, t0 + t1 - t, kept in b's domain [b0, b1] (the
/// mirrored knots may differ from a's by rounding), over `samples` equal steps.
template <class A, class B>
double reversal_defect(const A& a, const B& b, double t0, double t1, double b0, double b1, int samples = 400) {
    double worst = 0;
    for (int j = 0; j <= samples; ++j) {
        const double t = std::min(t0 + (t1 - t0) * j / samples, t1);
        worst = std::max(worst, props_qdiff_sign(a(t), b(std::clamp(t0 + t1 - t, b0, b1))));
    }
    return worst;
}

}  // namespace

// Keys that commute (all about one axis; random angles up to 170 degrees,
// random signs and times): the C2 spline reversed is the same curve at
// mirrored t, for SciPy's end (its chord rates are symmetric), the natural
// end, given angular velocities (start w_s, end w_e reversed to -w_e, -w_s,
// along the axis) and closed. Tolerance: rounding through the Newton solve
// and the cubic's exp on O(1) quaternions. Usually a few 1e-16, but the
// solve's conditioning with up to 11 keys of 170 degrees amplifies the
// rates' rounding (2e-13 seen once in 180 seeds): 1e-12, ten orders below
// what non-commuting keys of such steps give (about 1e-2).
TEST(RotationProperties, C2TimeReversalCommutingKeys) {
    CRSPLINE_SEEDED(seed, 2850);
    std::mt19937_64 rng(seed);
    int checked = 0;
    std::uniform_real_distribution<double> ang(-170, 170), coin(0, 1);
    for (int round = 0; round < 8; ++round) {
        const v3 axis = props_random_vec(rng, 1.0);
        const std::size_t n = 2 + rng() % 10;
        std::vector<quat> keys{from_rotation_vector(axis * (ang(rng) * std::numbers::pi / 180))};
        while (keys.size() < n) {
            const quat q = from_rotation_vector(axis * (ang(rng) * std::numbers::pi / 180)) * keys.back();
            keys.push_back(coin(rng) < 0.5 ? q : -q);
        }
        for (int end = 0; end < 4; ++end) {
            c2_options<double> o, r;
            o.closed = r.closed = end == 3;
            if (end == 1) o.start = o.end = r.start = r.end = c2_end<double>::natural();
            if (end == 2) {
                std::uniform_real_distribution<double> w(-2, 2);
                const v3 ws = axis * w(rng), we = axis * w(rng);
                o.start = c2_end<double>::velocity(ws), o.end = c2_end<double>::velocity(we);
                r.start = c2_end<double>::velocity(-1.0 * we), r.end = c2_end<double>::velocity(-1.0 * ws);
            }
            const auto times = props_random_times(rng, o.closed ? n + 1 : n);
            const auto rev = reverse_keys(keys, times, o.closed);
            const c2_rotation_spline<double> a{std::span<const double>(times), std::span<const quat>(keys), o};
            const c2_rotation_spline<double> b{std::span<const double>(rev.times), std::span<const quat>(rev.keys), r};
            EXPECT_LE(reversal_defect(a, b, times.front(), times.back(), rev.times.front(), rev.times.back()), 1e-12) << "end " << end << ", " << n << " keys";
            ++checked;
        }
    }
    EXPECT_EQ(checked, 8 * 4);
}

// Keys that do not commute: the reversed C2 spline differs, by a defect of
// third order in the step (the commutator terms of Exp(r) Exp(theta)):
// halving every step angle divides it by 8. Asserted as a ratio in [6, 10]
// between steps of up to 0.1 and 0.05 rad (measured 7.8 to 8.3 down to
// 0.06 rad), and the defect well above rounding, so a construction that
// broke the symmetry at first or second order (a wrong end, a wrong
// acceleration match) would fail; scipy, natural and closed ends.
TEST(RotationProperties, C2TimeReversalIsThirdOrderInTheStep) {
    CRSPLINE_SEEDED(seed, 2851);
    std::mt19937_64 rng(seed);
    int checked = 0;
    for (int round = 0; round < 6; ++round) {
        const std::size_t n = 4 + rng() % 6;
        std::vector<v3> steps;
        std::uniform_real_distribution<double> a(0.5, 1.0);
        for (std::size_t k = 0; k < n; ++k) steps.push_back(props_random_vec(rng, a(rng)));
        for (int end = 0; end < 3; ++end) {
            c2_options<double> o;
            o.closed = end == 2;
            if (end == 1) o.start = o.end = c2_end<double>::natural();
            const auto times = props_random_times(rng, o.closed ? n + 1 : n);
            double defect[2];
            for (int h = 0; h < 2; ++h) {
                const double scale = h == 0 ? 0.1 : 0.05;
                std::vector<quat> keys{quat::identity()};
                for (std::size_t k = 1; k < n; ++k) keys.push_back(from_rotation_vector(steps[k] * scale) * keys.back());
                const auto rev = reverse_keys(keys, times, o.closed);
                const c2_rotation_spline<double> fa{std::span<const double>(times), std::span<const quat>(keys), o};
                const c2_rotation_spline<double> fb{std::span<const double>(rev.times), std::span<const quat>(rev.keys), o};
                defect[h] = reversal_defect(fa, fb, times.front(), times.back(), rev.times.front(), rev.times.back());
            }
            EXPECT_GT(defect[1], 1e6 * eps) << "end " << end;
            const double ratio = defect[0] / defect[1];
            EXPECT_GE(ratio, 6.0) << "end " << end << ": " << defect[0] << " then " << defect[1];
            EXPECT_LE(ratio, 10.0) << "end " << end << ": " << defect[0] << " then " << defect[1];
            ++checked;
        }
    }
    EXPECT_EQ(checked, 6 * 3);
}

// Reversal where the existing TimeReversal test does not go: every kind
// closed (the cycle reversed from key 0), Kochanek-Bartels open and closed
// (bias negated: reversal swaps the incoming and outgoing tangents, whose
// weights differ by the sign of the bias), De Casteljau (each segment's
// controls and the segments reversed) and the pose curve with Catmull-Rom
// rotations (positions reversed too; both agree at mirrored t). Tolerance:
// 1e-13 as there (up to 6 slerps of O(1) values); positions 1e-12 of the
// path's scale (a few roundings of the cubic's coefficients).
TEST(RotationProperties, TimeReversalClosedAndOtherKinds) {
    CRSPLINE_SEEDED(seed, 2852);
    std::mt19937_64 rng(seed);
    int checked = 0;
    for (int round = 0; round < 6; ++round) {
        const std::size_t n = 3 + rng() % 6;
        const auto keys = props_random_keys(rng, n, 1, 150);
        std::uniform_real_distribution<double> tcb(-0.5, 0.5);
        const double T = tcb(rng), C = tcb(rng), B = tcb(rng);
        for (bool closed : {false, true})
            for (auto kind : quaternion_kinds) {
                if (!closed && kind != spline_kind::kochanek_bartels) continue;  // open ones: TimeReversal
                auto o = make_options(kind, closed, 0.5), r = o;
                if (kind == spline_kind::kochanek_bartels) o.kb = {{T, C, B}}, r.kb = {{T, C, -B}};
                const auto rev = reverse_keys(keys, std::vector<double>{0, 1}, closed);
                const quaternion_spline<double> a(keys, o), b(rev.keys, r);
                const double end = a.grid().back();
                EXPECT_NEAR(b.grid().back(), end, 64 * eps * end);
                EXPECT_LE(reversal_defect(a, b, 0.0, end, 0.0, b.grid().back()), 1e-13)
                    << "kind " << int(kind) << (closed ? " closed" : " open");
                ++checked;
            }
        // De Casteljau: random controls per segment, 2 to 5 of them, each
        // segment starting where the one before ends (at a knot the segment
        // on the right is evaluated, so a jump there would not mirror).
        std::vector<std::vector<quat>> segs, rsegs;
        for (std::size_t i = 0; i + 1 < n; ++i) {
            auto c = props_random_keys(rng, 2 + rng() % 4, 1, 60);
            if (i > 0) c[0] = segs.back().back();
            segs.push_back(c);
        }
        for (std::size_t i = segs.size(); i-- > 0;) rsegs.emplace_back(segs[i].rbegin(), segs[i].rend());
        const auto da = quaternion_spline<double>::de_casteljau(segs), db = quaternion_spline<double>::de_casteljau(rsegs);
        EXPECT_LE(reversal_defect(da, db, 0.0, double(segs.size()), 0.0, double(segs.size())), 1e-13) << "de_casteljau";
        ++checked;
        // Pose curve, Catmull-Rom rotations, centripetal positions, open and closed.
        std::normal_distribution<double> g;
        std::vector<crspline::vec<3, double>> p{{{0, 0, 0}}};
        while (p.size() < n) p.push_back(p.back() + crspline::vec<3, double>{{1 + std::abs(g(rng)), g(rng), g(rng)}});
        for (bool closed : {false, true}) {
            pose_options<double> o;
            o.c2_rotation = false;
            o.closed = closed;
            std::vector<crspline::vec<3, double>> rp;
            if (closed) {
                rp.push_back(p[0]);
                for (std::size_t k = n - 1; k >= 1; --k) rp.push_back(p[k]);
            } else {
                rp.assign(p.rbegin(), p.rend());
            }
            const auto rk = reverse_keys(keys, std::vector<double>{0, 1}, closed).keys;
            const pose_curve<double> a{std::span<const crspline::vec<3, double>>(p), std::span<const quat>(keys), o};
            const pose_curve<double> b{std::span<const crspline::vec<3, double>>(rp), std::span<const quat>(rk), o};
            const double end = a.grid().back();
            double scale = 1;
            for (const auto& x : p) scale = std::max(scale, crspline::max_abs(x));
            for (int j = 0; j <= 200; ++j) {
                const double t = std::min(end * j / 200, end), tr = std::clamp(end - t, 0.0, b.grid().back());
                const auto sa = a.evaluate(t), sb = b.evaluate(tr);
                EXPECT_LE(crspline::max_abs(sa.position - sb.position), 1e-12 * scale) << "pose t " << t;
                EXPECT_LE(props_qdiff_sign(sa.orientation, sb.orientation), 1e-13) << "pose t " << t;
            }
            ++checked;
        }
    }
    EXPECT_EQ(checked, 6 * (5 + 1 + 1 + 2));
}
