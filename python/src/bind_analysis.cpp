// crspline Python module: the analysis report of crspline/report.hpp (per
// segment cusps, loops, chord distances and the paper's bounds; the curve's
// self-intersections; the Section 5 certificate) as plain dicts, lists,
// floats, ints, bools, strings and None: the same keys and values as
// `crspline analyze` prints (docs/report.md).
#include <optional>
#include <string>

#include <crspline/report.hpp>

#include "curve.hpp"

namespace crspline::python {

namespace {

// The coordinates to report: the caller's (a wide curve's input dimension),
// or the curve's own.
template <std::size_t D>
std::size_t report_dimension(std::optional<std::size_t> dimension) {
    if (dimension && (*dimension < 1 || *dimension > D))
        throw invalid_input("dimension must be 1 to " + std::to_string(D) + ", got " + std::to_string(*dimension));
    return dimension.value_or(D);
}

void check_tolerance(const std::optional<double>& tolerance) {
    if (tolerance && !(*tolerance > 0 && std::isfinite(*tolerance)))
        throw invalid_input("tolerance must be positive and finite, got " + detail::num(*tolerance));
}

}  // namespace

void bind_analysis(py::module_& m, py::class_<curve>& cls) {
    cls.def("analyze", [](const curve& c, bool search, std::optional<double> tolerance,
                          std::optional<std::size_t> dimension) {
        return c.visit([&](const auto& cr) -> py::object {
            using T = scalar_t<decltype(cr)>;
            constexpr std::size_t D = dimension_v<decltype(cr)>;
            check_tolerance(tolerance);
            report_options opt;
            opt.search = search;
            opt.tolerance = tolerance.value_or(0);
            analysis_report<D, T> r;
            const std::size_t dim = report_dimension<D>(dimension);
            {
                py::gil_scoped_release nogil;
                r = make_report(cr, opt, dim);
            }
            py_builder b;
            return report(b, r);
        });
    }, py::arg("search") = true, py::arg("tolerance") = py::none(), py::arg("dimension") = py::none(),
       "The analysis report (docs/report.md), as a dict.");

    m.attr("default_intersection_tolerance") = default_intersection_tolerance;
    m.attr("safe_adjacent_angle") = safe_adjacent_angle;

    cls.def("intersections", [](const curve& c, std::optional<double> tolerance,
                                std::optional<std::size_t> dimension) {
        return c.visit([&](const auto& cr) -> py::object {
            using T = scalar_t<decltype(cr)>;
            constexpr std::size_t D = dimension_v<decltype(cr)>;
            check_tolerance(tolerance);
            const std::size_t dim = report_dimension<D>(dimension);
            intersection_result<D, T> r;
            {
                py::gil_scoped_release nogil;
                r = find_intersections(cr, T(tolerance.value_or(0)));
            }
            py_builder b;
            return report_search(b, r, cr.grid(), dim);
        });
    }, py::arg("tolerance") = py::none(), py::arg("dimension") = py::none(),
       "Self-intersections of the whole curve (the report's search object), as a dict.");

    cls.def("certify_intersection_free", [](const curve& c, double safe_angle, bool search_on_failure,
                                            std::optional<double> tolerance, std::optional<std::size_t> dimension) {
        return c.visit([&](const auto& cr) -> py::object {
            using T = scalar_t<decltype(cr)>;
            constexpr std::size_t D = dimension_v<decltype(cr)>;
            check_tolerance(tolerance);
            const std::size_t dim = report_dimension<D>(dimension);
            certify_options opt;
            opt.safe_angle = safe_angle;
            opt.search_on_failure = search_on_failure;
            opt.tolerance = tolerance.value_or(0);
            certificate<D, T> r;
            {
                py::gil_scoped_release nogil;
                r = certify_intersection_free(cr, opt);
            }
            py_builder b;
            return report_certificate(b, r, cr.grid(), dim);
        });
    }, py::arg("safe_angle") = safe_adjacent_angle, py::arg("search_on_failure") = true,
       py::arg("tolerance") = py::none(), py::arg("dimension") = py::none(),
       "Section 5's certificate that the curve does not intersect itself (the report's certificate object).");
}

}  // namespace crspline::python
