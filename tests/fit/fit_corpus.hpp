// tests/fit and bench/fit_bench: the fit corpus (tests/reference/fit/*.txt,
// see its README) and Ramer-Douglas-Peucker, the count to beat.
#pragma once

#include <cmath>
#include <cstddef>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <crspline/vec.hpp>

namespace fit_corpus {

using p2 = crspline::vec<2>;

struct line {
    std::string name;
    bool closed = false;
    double tolerance = 0;
    std::vector<p2> points;
};

inline std::vector<line> read(const std::string& path) {
    std::ifstream f(path);
    if (!f) throw std::runtime_error("cannot read " + path);
    std::vector<line> out;
    std::string word;
    while (f >> word) {
        if (word != "line") throw std::runtime_error(path + ": expected 'line', got " + word);
        line l;
        int closed = 0;
        std::size_t n = 0;
        f >> l.name >> closed >> l.tolerance >> n;
        l.closed = closed != 0;
        l.points.resize(n);
        for (auto& p : l.points) f >> p[0] >> p[1];
        if (!f) throw std::runtime_error(path + ": truncated at " + l.name);
        out.push_back(std::move(l));
    }
    return out;
}

inline double segment_distance(const p2& p, const p2& a, const p2& b) {
    const p2 d = b - a, w = p - a;
    const double l2 = crspline::dot(d, d);
    const double f = l2 > 0 ? std::clamp(crspline::dot(w, d) / l2, 0.0, 1.0) : 0.0;
    return crspline::norm(w - f * d);
}

/// Ramer-Douglas-Peucker (distance to the segment, as simplify-js's
/// high-quality mode): the kept indices, first and last included. A closed
/// ring is split at its first point and the point farthest from it.
inline std::vector<std::size_t> rdp(const std::vector<p2>& pts, double tol, bool closed) {
    const std::size_t n = pts.size();
    std::vector<char> keep(n + 1, 0);
    std::vector<p2> p(pts);
    if (closed) p.push_back(pts[0]);
    const std::size_t last = p.size() - 1;
    keep[0] = keep[last] = 1;
    std::vector<std::pair<std::size_t, std::size_t>> stack;
    if (closed) {
        std::size_t far = 1;
        double best = -1;
        for (std::size_t i = 1; i < last; ++i) {
            const double d = crspline::norm(p[i] - p[0]);
            if (d > best) best = d, far = i;
        }
        keep[far] = 1;
        stack = {{0, far}, {far, last}};
    } else {
        stack = {{0, last}};
    }
    while (!stack.empty()) {
        auto [a, b] = stack.back();
        stack.pop_back();
        double best = -1;
        std::size_t at = a;
        for (std::size_t i = a + 1; i < b; ++i) {
            const double d = segment_distance(p[i], p[a], p[b]);
            if (d > best) best = d, at = i;
        }
        if (best > tol) {
            keep[at] = 1;
            stack.push_back({a, at});
            stack.push_back({at, b});
        }
    }
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < (closed ? last : last + 1); ++i)
        if (keep[i]) out.push_back(i);
    return out;
}

}  // namespace fit_corpus
