// tests/fit: an independent check of a fit's promise by dense sampling (no
// use of the fit's proof nor of nearest.hpp): every sampled curve point's
// distance to the input polyline, and every input point's distance to the
// sampled curve less (a little more than) half the gap of each interval.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include <crspline/fit.hpp>

namespace fit_check {

template <std::size_t D, class T>
double seg_dist(const crspline::vec<D, T>& p, const crspline::vec<D, T>& a, const crspline::vec<D, T>& b) {
    double d2 = 0, l2 = 0, w = 0;
    for (std::size_t k = 0; k < D; ++k) {
        const double dk = double(b[k]) - double(a[k]), wk = double(p[k]) - double(a[k]);
        l2 += dk * dk;
        w += wk * dk;
    }
    const double f = l2 > 0 ? std::clamp(w / l2, 0.0, 1.0) : 0.0;
    for (std::size_t k = 0; k < D; ++k) {
        const double e = double(p[k]) - (double(a[k]) + f * (double(b[k]) - double(a[k])));
        d2 += e * e;
    }
    return std::sqrt(d2);
}

struct measured {
    double curve_to_input = 0;  // largest sampled distance (a lower bound on the true one)
    double input_to_curve = 0;  // largest input distance less half a gap (a lower bound too)
    std::size_t samples = 0;
};

/// Measures a fitted curve against its input by `per_segment` samples a segment.
template <std::size_t D, class T>
measured measure(const crspline::catmull_rom<D, T>& curve, const std::vector<crspline::vec<D, T>>& input, bool closed,
                 std::size_t per_segment = 200) {
    std::vector<crspline::vec<D, T>> poly(input);
    if (closed) poly.push_back(input.front());
    std::vector<crspline::vec<D, T>> samples;
    for (std::size_t s = 0; s < curve.segment_count(); ++s) {
        const auto seg = curve.segment(s);
        for (std::size_t k = 0; k < per_segment; ++k) samples.push_back(seg.at(T(double(k) / double(per_segment))));
    }
    samples.push_back(closed ? curve.points().front() : curve.points().back());
    measured m;
    m.samples = samples.size();
    // Each interval's gap (the chord between consecutive samples).
    std::vector<double> gap(samples.size() - 1);
    for (std::size_t i = 0; i + 1 < samples.size(); ++i) {
        double d2 = 0;
        for (std::size_t k = 0; k < D; ++k) {
            const double e = double(samples[i + 1][k]) - double(samples[i][k]);
            d2 += e * e;
        }
        gap[i] = std::sqrt(d2);
    }
    for (const auto& q : samples) {
        double best = INFINITY;
        for (std::size_t i = 0; i + 1 < poly.size(); ++i) best = std::min(best, seg_dist(q, poly[i], poly[i + 1]));
        m.curve_to_input = std::max(m.curve_to_input, best);
    }
    std::vector<double> d(samples.size());
    for (const auto& p : input) {
        for (std::size_t j = 0; j < samples.size(); ++j) {
            double d2 = 0;
            for (std::size_t k = 0; k < D; ++k) {
                const double e = double(p[k]) - double(samples[j][k]);
                d2 += e * e;
            }
            d[j] = std::sqrt(d2);
        }
        // The nearest curve point lies in some interval, within (about) half
        // its gap of one of the interval's two samples (the arc between two
        // samples is within a few percent of their chord at this density;
        // 0.6 gaps leaves room for that): a lower bound on the distance,
        // interval by interval (a single largest gap, as before, made the
        // bound idle where one segment is long: a closed line's closing one).
        double lower = INFINITY;
        for (std::size_t i = 0; i + 1 < samples.size(); ++i)
            lower = std::min(lower, std::min(d[i], d[i + 1]) - 0.6 * gap[i]);
        m.input_to_curve = std::max(m.input_to_curve, lower);
    }
    return m;
}

/// Seeded test lines: a noisy random curve of n points in D dimensions
/// (a random walk of smoothly turning direction plus uniform noise).
template <std::size_t D, class T>
std::vector<crspline::vec<D, T>> noisy_line(std::mt19937_64& rng, std::size_t n, double noise) {
    std::normal_distribution<double> turn(0.0, 0.25);
    std::uniform_real_distribution<double> u(-noise, noise);
    std::vector<crspline::vec<D, T>> out;
    std::array<double, D> x{}, dir{};
    dir[0] = 1;
    for (std::size_t i = 0; i < n; ++i) {
        crspline::vec<D, T> p;
        for (std::size_t k = 0; k < D; ++k) p[k] = T(x[k] + u(rng));
        out.push_back(p);
        for (std::size_t k = 0; k < D; ++k) dir[k] += turn(rng) * 0.5;
        double len = 0;
        for (double c : dir) len += c * c;
        len = std::sqrt(len);
        for (std::size_t k = 0; k < D; ++k) x[k] += dir[k] / len;
    }
    return out;
}

}  // namespace fit_check
