// crspline: the decision's arguments that two pieces are apart (separation,
// a joint), the filter on where Krawczyk's test is worth trying
// (transversal), and pieces that run along each other within their margins
// (along: a contact at once). Each is a comparison with a margin that
// covers the pieces' rounding (decision.hpp, "Proofs").
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "../vec.hpp"
#include "pieces.hpp"

namespace crspline {
namespace detail {

struct decision_arguments : decision_pieces {
    static bool separated_on(const piece& a, const piece& b, const P& n, double S) {
        if (!(norm1(n) > 0) || !std::isfinite(norm1(n))) return false;
        double a0 = dot(a.b[0], n), a1 = a0, b0 = dot(b.b[0], n), b1 = b0;
        for (std::size_t k = 1; k < 4; ++k) {
            a0 = std::min(a0, dot(a.b[k], n));
            a1 = std::max(a1, dot(a.b[k], n));
            b0 = std::min(b0, dot(b.b[k], n));
            b1 = std::max(b1, dot(b.b[k], n));
        }
        const double pad = margin(a.err + b.err, n, S);
        return a1 + pad < b0 || b1 + pad < a0;
    }
    static bool separated(const piece& a, const piece& b, double S) {
        const P ca = a.b[3] - a.b[0], cb = b.b[3] - b.b[0];
        const P axes[] = {P{{1, 0}}, P{{0, 1}}, P{{-ca[1], ca[0]}}, P{{-cb[1], cb[0]}}};
        for (const auto& n : axes)
            if (separated_on(a, b, n, S)) return true;
        return false;
    }

    // a ends where b starts (J, the same double): do they meet only there?
    static bool apart_at_joint(const piece& a, const piece& b, double S) {
        const P J = a.b[3];
        const P da = J - a.b[3u - a.end_mult], db = b.b[b.start_mult] - J;
        const P dirs[] = {da, db, da / std::max(norm1(da), 1e-300) + db / std::max(norm1(db), 1e-300)};
        for (const auto& d : dirs) {
            if (!(norm1(d) > 0) || !std::isfinite(norm1(d))) continue;
            const double pad = margin(2 * (a.err + b.err), d, S), j = dot(J, d);
            bool ok = true;
            for (std::size_t k = 0; k + a.end_mult < 4 && ok; ++k) ok = dot(a.b[k], d) < j - pad;
            for (std::size_t k = b.start_mult; k < 4 && ok; ++k) ok = dot(b.b[k], d) > j + pad;
            if (ok) return true;
        }
        return false;
    }

    // Worth Krawczyk's test? Only where every tangent of a crosses every
    // tangent of b with one sign: the cross products of their hodographs'
    // control vectors (zero ones left out) all strictly positive or all
    // strictly negative. Elsewhere some Jacobian of F over the pieces may be
    // singular, and then the test cannot succeed (its success proves every
    // Jacobian in the box invertible): the pair is split instead, and its
    // halves' hodographs are tighter. A filter on where to try, rounded
    // plainly: it decides nothing, and a crossing it passes over is proved
    // on smaller pieces (or at the floor, where the test is always tried).
    static bool transversal(const piece& a, const piece& b) {
        // The chords meet (end points on both sides of the other's chord line, or on it).
        const P ca = a.b[3] - a.b[0], cb = b.b[3] - b.b[0];
        if (cross2(ca, b.b[0] - a.b[0]) * cross2(ca, b.b[3] - a.b[0]) > 0) return false;
        if (cross2(cb, a.b[0] - b.b[0]) * cross2(cb, a.b[3] - b.b[0]) > 0) return false;
        int pos = 0, neg = 0;
        for (std::size_t i = 0; i < 3; ++i) {
            const P ha = a.b[i + 1] - a.b[i];
            if (ha[0] == 0 && ha[1] == 0) continue;
            for (std::size_t j = 0; j < 3; ++j) {
                const P hb = b.b[j + 1] - b.b[j];
                if (hb[0] == 0 && hb[1] == 0) continue;
                const double x = cross2(ha, hb);
                pos += x > 0, neg += x < 0;
                if (!(x > 0 || x < 0) || (pos && neg)) return false;
            }
        }
        return true;
    }

    // Do two pieces run along each other within their rounding margins?
    // Both flat (their control points within w of their chord lines, w =
    // 2 (their error bounds) + 16 eps M), their chords parallel to within w
    // over their length, each one's end points within w of the other's
    // chord line, the chords' projections overlapping. Such pieces are
    // within a few w of each other all along (an overlap, as in a fold, or
    // a tangency at the margins' scale); no separating axis can ever be
    // proved for them and their halves repeat the same: a contact at once,
    // instead of 2^32 pieces down to the floor.
    static double along_width(const piece& a, const piece& b, double S) { return 2 * (a.err + b.err) + 16 * eps * S; }
    static bool along(const piece& a, const piece& b, double S) {
        const P ca = a.b[3] - a.b[0], cb = b.b[3] - b.b[0];
        const double la = norm(ca), lb = norm(cb), w = along_width(a, b, S);
        if (!(la > w) || !(lb > w)) return false;
        auto off = [](const P& x, const P& o, const P& c, double l) { return std::abs(cross2(x - o, c)) / l; };
        for (std::size_t k = 1; k < 3; ++k)
            if (off(a.b[k], a.b[0], ca, la) > w || off(b.b[k], b.b[0], cb, lb) > w) return false;
        if (std::abs(cross2(ca, cb)) > w * std::max(la, lb)) return false;
        if (off(b.b[0], a.b[0], ca, la) > w || off(b.b[3], a.b[0], ca, la) > w) return false;
        const double p0 = dot(b.b[0] - a.b[0], ca) / la, p1 = dot(b.b[3] - a.b[0], ca) / la;
        return std::max(p0, p1) > 0 && std::min(p0, p1) < la;
    }
    static double cross2(const P& x, const P& y) noexcept { return x[0] * y[1] - x[1] * y[0]; }
};

}  // namespace detail
}  // namespace crspline
