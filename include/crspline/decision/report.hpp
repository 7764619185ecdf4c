// crspline: what a decision says (decision.hpp): the verdict, the proved
// crossings, the contacts, the arguments of each pair of segments, the
// options, the Bezier paths it takes, and the decision as a report value
// (report_decision, written once for every front end).
#pragma once

#include <array>
#include <cstddef>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

#include "../vec.hpp"

namespace crspline {

enum class verdict { simple, crosses, touches };

inline const char* to_string(verdict v) noexcept {
    switch (v) {
        case verdict::simple: return "simple";
        case verdict::crosses: return "crosses";
        case verdict::touches: return "touches";
    }
    return "unknown";
}

/// The arguments that decide a pair of segments, as bit flags (a pair cut
/// into pieces may need several).
enum decision_argument : unsigned {
    paper_rule = 1,   ///< the paper's certificate (Section 5) certified the whole curve
    separation = 2,   ///< a separating axis between convex hulls, with rounding margins
    joint = 4,        ///< consecutive pieces meet only at their shared point (half-space test)
    monotone = 8,     ///< a piece is monotone in a direction: it does not meet itself
    crossing = 16,    ///< Krawczyk's test proved a transversal crossing
    unresolved = 32,  ///< a contact within the floor (or the budget ran out)
};

/// "separation+joint" for the flags set in `arguments`.
inline std::string argument_names(unsigned arguments) {
    static constexpr std::pair<unsigned, const char*> names[] = {{paper_rule, "paper_rule"}, {separation, "separation"},
                                                                 {joint, "joint"},           {monotone, "monotone"},
                                                                 {crossing, "crossing"},     {unresolved, "unresolved"}};
    std::string s;
    for (const auto& [bit, name] : names)
        if (arguments & bit) s += (s.empty() ? "" : "+") + std::string(name);
    return s;
}

/// A proved crossing: the two pieces meet exactly once, transversally, at
/// local parameters u in [u[0][0], u[0][1]] of segment[0] of curve[0] and
/// [u[1][0], u[1][1]] of segment[1] of curve[1]. At a vertex an interval
/// may reach past its segment's end (below 0 or above 1): that part lies in
/// the neighbouring segment (u - 1, or u + 1, there).
struct proved_crossing {
    std::array<std::size_t, 2> curve{};
    std::array<std::size_t, 2> segment{};
    std::array<std::array<double, 2>, 2> u{};
    vec<2> point{};  ///< the curve at the middle of the first interval (rounded)
};

/// Two pieces within the floor that could not be proved apart or crossing.
struct contact {
    std::array<std::size_t, 2> curve{};
    std::array<std::size_t, 2> segment{};  ///< equal for a contact inside one segment (cusp, fold)
    std::array<double, 2> u{};             ///< local parameters where it was found
    double distance = 0;                   ///< |A(u0) - B(u1)| there (rounded)
    std::size_t pieces = 0;                ///< unresolved piece pairs merged into this contact
    bool budget_exhausted = false;         ///< the work budget ran out (distance may exceed the floor)
};

/// Which arguments decided a pair of segments (i <= j; i == j: within one segment).
struct decided_pair {
    std::array<std::size_t, 2> curve{};
    std::array<std::size_t, 2> segment{};
    unsigned arguments = 0;
};

struct decision_options {
    bool fast_path = true;             ///< try the paper's certificate first (single curves)
    std::size_t budget = 0;            ///< visits in all before every remaining pair is a contact (0: 2^24 or 256 per piece, the larger)
    std::size_t pair_budget = 1u << 17;  ///< visits for one pair of pieces (an overlap or a near tangency)
    bool record_pairs = true;          ///< fill decision::pairs
    bool first_crossing = false;       ///< stop at the first proved crossing: the same verdict, the lists partial (and in the box tree's order)
};

struct decision {
    crspline::verdict result = verdict::simple;
    bool fast_path = false;                  ///< decided by the paper's certificate alone
    std::vector<proved_crossing> crossings;  ///< in order of (curve, segment) pairs
    std::vector<contact> touches;
    std::vector<decided_pair> pairs;         ///< every pair of segments examined (not with fast_path)
    double floor = 0;                        ///< delta: the contact floor (see the header comment)
    std::size_t pieces = 0;                  ///< monotone pieces the curves were cut into
    std::size_t visits = 0;                  ///< pairs of pieces examined
    std::size_t candidate_pairs = 0;         ///< pairs of pieces whose boxes met
};

/// A piecewise cubic Bézier curve in the plane: segment i runs from
/// segments[i][0] to segments[i][3]; consecutive segments share that point
/// exactly (segments[i][3] == segments[i + 1][0], and back to the first when
/// closed) -- the decision checks it.
struct bezier_path {
    std::span<const std::array<vec<2>, 4>> segments;
    bool closed = false;
};

/// The decision as a report value, made by a report_builder B (report.hpp):
///
///     {"verdict": "simple" | "crosses" | "touches", "fast_path": bool,
///      "floor": number,
///      "crossings": [{"curves": [i, j], "segments": [a, b],
///                     "u": [[lo, hi], [lo, hi]], "point": [x, y]}],
///      "touches": [{"curves", "segments", "u": [u, v], "distance",
///                   "budget_exhausted"}],
///      "pairs": [{"curves", "segments", "arguments": ["separation", ...]}]}
///
/// Every front end's decide() returns this object (its keys written here
/// once: docs/report.md, "The decision object"); the whole-curve report
/// carries only its verdict, as "verdict" at its top (report.hpp).
template <class B>
typename B::value report_decision(B& b, const decision& d) {
    auto idx2 = [&](const std::array<std::size_t, 2>& a) {
        auto v = b.array();
        for (const std::size_t i : a) b.push(v, b.integer(i));
        return v;
    };
    auto nums = [&](std::initializer_list<double> xs) {
        auto v = b.array();
        for (const double x : xs) b.push(v, b.number(x));
        return v;
    };
    auto o = b.object();
    b.set(o, "verdict", b.string(to_string(d.result)));
    b.set(o, "fast_path", b.boolean(d.fast_path));
    b.set(o, "floor", b.number(d.floor));
    auto crossings = b.array();
    for (const auto& c : d.crossings) {
        auto x = b.object();
        b.set(x, "curves", idx2(c.curve));
        b.set(x, "segments", idx2(c.segment));
        auto u = b.array();
        b.push(u, nums({c.u[0][0], c.u[0][1]}));
        b.push(u, nums({c.u[1][0], c.u[1][1]}));
        b.set(x, "u", std::move(u));
        b.set(x, "point", nums({c.point[0], c.point[1]}));
        b.push(crossings, std::move(x));
    }
    b.set(o, "crossings", std::move(crossings));
    auto touches = b.array();
    for (const auto& t : d.touches) {
        auto x = b.object();
        b.set(x, "curves", idx2(t.curve));
        b.set(x, "segments", idx2(t.segment));
        b.set(x, "u", nums({t.u[0], t.u[1]}));
        b.set(x, "distance", b.number(t.distance));
        b.set(x, "budget_exhausted", b.boolean(t.budget_exhausted));
        b.push(touches, std::move(x));
    }
    b.set(o, "touches", std::move(touches));
    auto pairs = b.array();
    for (const auto& p : d.pairs) {
        auto x = b.object();
        b.set(x, "curves", idx2(p.curve));
        b.set(x, "segments", idx2(p.segment));
        auto names = b.array();
        for (unsigned bit = 1; bit <= unresolved; bit <<= 1)
            if (p.arguments & bit) b.push(names, b.string(argument_names(bit)));
        b.set(x, "arguments", std::move(names));
        b.push(pairs, std::move(x));
    }
    b.set(o, "pairs", std::move(pairs));
    return o;
}

}  // namespace crspline
