// crspline Python module: the proved decision on crossings (decision.hpp,
// issue 27) for one curve, a pair and a set, and the clearance between
// non-adjacent parts. The decision comes back as report_decision writes it
// (the "decision" object of docs/report.md): verdict, fast_path, floor,
// crossings, touches, pairs. The Python API is crspline/_decision.py.
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <crspline/decision.hpp>

#include "curve.hpp"

namespace crspline::python {

namespace {

// A plane curve's segments as double Bézier points. A float curve's points
// convert exactly, so the decision is about that curve as built.
using bezier_segments = std::vector<std::array<vec<2>, 4>>;

// The plane curve behind `c`: the double curve itself (the decision then
// tries the paper's certificate first), or a float curve's Bézier form;
// anything else is refused naming its dimension.
struct plane_curve {
    const catmull_rom<2>* exact = nullptr;
    bezier_segments bezier;
    bool closed = false;
};

plane_curve plane(const curve& c, const std::string& what) {
    return c.visit([&](const auto& cr) -> plane_curve {
        using T = scalar_t<decltype(cr)>;
        constexpr std::size_t D = dimension_v<decltype(cr)>;
        if constexpr (D != 2) {
            throw invalid_input(what + " needs plane curves (dimension 2), got dimension " +
                                std::to_string(D) +
                                " (clearance works in any dimension)");
        } else {
            plane_curve p;
            p.closed = cr.closed();
            if constexpr (std::is_same_v<T, double>) {
                p.exact = &cr;
                p.bezier = cr.bezier();
            } else {
                for (const auto& s : cr.bezier()) {
                    std::array<vec<2>, 4> b{};
                    for (std::size_t k = 0; k < 4; ++k) b[k] = {double(s[k][0]), double(s[k][1])};
                    p.bezier.push_back(b);
                }
            }
            return p;
        }
    });
}

decision_options options_from(bool fast_path, std::optional<std::size_t> budget, std::optional<std::size_t> pair_budget,
                              bool record_pairs) {
    decision_options o;
    o.fast_path = fast_path;
    if (budget) o.budget = *budget;
    if (pair_budget) o.pair_budget = *pair_budget;
    o.record_pairs = record_pairs;
    return o;
}

// The decision of curves given as Bézier paths (self: each one's own
// crossings; between: crossings between them).
decision decide_beziers(const std::vector<plane_curve>& curves, bool self, bool between, const decision_options& o) {
    std::vector<bezier_path> p;
    p.reserve(curves.size());
    for (const auto& c : curves) p.push_back({c.bezier, c.closed});
    return detail::decide_paths(p, self, between, o);
}

template <std::size_t D>
py::dict clearance_dict(const clearance_result<D>& r, std::size_t dim) {
    py::dict o;
    o["distance"] = r.distance;
    o["lower_bound"] = r.lower_bound;
    o["curves"] = py::make_tuple(r.curve[0], r.curve[1]);
    o["segments"] = py::make_tuple(r.segment[0], r.segment[1]);
    o["u"] = py::make_tuple(r.u[0], r.u[1]);
    py::array_t<double> pts({py::ssize_t(2), py::ssize_t(dim)});
    for (std::size_t i = 0; i < 2; ++i)
        for (std::size_t k = 0; k < dim; ++k) pts.mutable_at(i, k) = r.points[i][k];
    o["points"] = pts;
    o["exhausted"] = r.exhausted;
    return o;
}

// A curve's segments as double Bézier points relative to `ref` (a float
// curve's convert exactly: clearance measures the curve as built).
template <std::size_t D, class T>
std::vector<std::array<vec<D>, 4>> relative_bezier(const catmull_rom<D, T>& c, const vec<D>& ref) {
    std::vector<std::array<vec<D>, 4>> out;
    out.reserve(c.segment_count());
    for (const auto& s : c.bezier()) {
        std::array<vec<D>, 4> b{};
        for (std::size_t q = 0; q < 4; ++q)
            for (std::size_t k = 0; k < D; ++k) b[q][k] = double(s[q][k]) - ref[k];
        out.push_back(b);
    }
    return out;
}

template <std::size_t D, class T>
vec<D> first_point(const catmull_rom<D, T>& c) {
    vec<D> r{};
    for (std::size_t k = 0; k < D; ++k) r[k] = double(c.points()[0][k]);
    return r;
}

// clearance()'s default work budget (decision.hpp).
constexpr std::size_t default_clearance_budget = std::size_t(1) << 22;

void check_accuracy(double accuracy) {
    if (!(accuracy >= 0) || !std::isfinite(accuracy))
        throw invalid_input("clearance accuracy must be a finite distance >= 0 (0: 1e-10 of the extent), got " +
                            detail::num(accuracy));
}

}  // namespace

void bind_decision(py::module_& m) {
    m.def("_decide", [](const curve& c, bool fast_path, std::optional<std::size_t> budget,
                        std::optional<std::size_t> pair_budget, bool record_pairs) {
        const plane_curve p = plane(c, "the decision");
        const auto o = options_from(fast_path, budget, pair_budget, record_pairs);
        decision d;
        {
            py::gil_scoped_release nogil;
            d = p.exact ? decide(*p.exact, o) : decide(bezier_path{p.bezier, p.closed}, o);
        }
        py_builder b;
        return report_decision(b, d);
    }, py::arg("curve"), py::arg("fast_path"), py::arg("budget"), py::arg("pair_budget"), py::arg("record_pairs"));

    // A pair is a set of two without self (as decision.hpp's decide(a, b)).
    m.def("_decide_set", [](const std::vector<const curve*>& curves, const std::string& of, bool self, bool fast_path,
                            std::optional<std::size_t> budget, std::optional<std::size_t> pair_budget,
                            bool record_pairs) {
        std::vector<plane_curve> p;
        p.reserve(curves.size());
        for (std::size_t i = 0; i < curves.size(); ++i)
            p.push_back(plane(*curves[i], "curve " + std::to_string(i) + " of the " + of + ": the decision"));
        const auto o = options_from(fast_path, budget, pair_budget, record_pairs);
        decision d;
        {
            py::gil_scoped_release nogil;
            d = decide_beziers(p, self, true, o);
        }
        py_builder b;
        return report_decision(b, d);
    }, py::arg("curves"), py::arg("of"), py::arg("self"), py::arg("fast_path"), py::arg("budget"), py::arg("pair_budget"),
       py::arg("record_pairs"));

    m.def("_clearance", [](const curve& c, double accuracy, std::optional<std::size_t> budget,
                           std::size_t dim) -> py::object {
        check_accuracy(accuracy);
        return c.visit([&](const auto& cr) -> py::object {
            constexpr std::size_t D = dimension_v<decltype(cr)>;
            const vec<D> ref = first_point(cr);
            clearance_result<D> r;
            {
                py::gil_scoped_release nogil;
                r = detail::clearance_of<D>({relative_bezier(cr, ref)}, {cr.closed()}, ref, true, false, accuracy,
                                            budget.value_or(default_clearance_budget));
            }
            return clearance_dict(r, std::min(dim, D));
        });
    }, py::arg("curve"), py::arg("accuracy"), py::arg("budget"), py::arg("dim"));

    m.def("_clearance_pair", [](const curve& a, const curve& b, double accuracy, std::optional<std::size_t> budget,
                                std::size_t dim) -> py::object {
        check_accuracy(accuracy);
        return a.visit([&](const auto& ca) -> py::object {
            constexpr std::size_t D = dimension_v<decltype(ca)>;
            return b.visit([&](const auto& cb) -> py::object {
                constexpr std::size_t E = dimension_v<decltype(cb)>;
                if constexpr (D != E) {
                    throw invalid_input("clearance between curves of dimensions " + std::to_string(D) + " and " +
                                        std::to_string(E) + ": they must be equal");
                } else {
                    const vec<D> ref = first_point(ca);
                    clearance_result<D> r;
                    {
                        py::gil_scoped_release nogil;
                        r = detail::clearance_of<D>({relative_bezier(ca, ref), relative_bezier(cb, ref)},
                                                    {ca.closed(), cb.closed()}, ref, false, true, accuracy,
                                                    budget.value_or(default_clearance_budget));
                    }
                    return clearance_dict(r, std::min(dim, D));
                }
            });
        });
    }, py::arg("a"), py::arg("b"), py::arg("accuracy"), py::arg("budget"), py::arg("dim"));
}

}  // namespace crspline::python
