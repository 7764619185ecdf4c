// crspline Python module: arc length, its inverse and arc-length sampling.
#include <optional>

#include <crspline/arc_length.hpp>
#include <crspline/resolution.hpp>

#include "curve.hpp"

namespace crspline::python {

namespace {

/// One table type per curve type of curve_variant.
template <class T>
using tables_of = std::variant<arc_length_table<1, T>, arc_length_table<2, T>, arc_length_table<3, T>,
                               arc_length_table<4, T>, arc_length_table<wide_dimension, T>>;

/// The cumulative arc-length table of one curve (it copies the segments, so
/// it does not refer to the curve), and the curve's domain [t_min, t_max]
/// (its first and last knot, exactly) for naming a t outside it.
struct table {
    concat<tables_of<double>, tables_of<float>>::type v;
    double t_min = 0, t_max = 0;
    template <class F>
    decltype(auto) visit(F&& f) const { return std::visit(std::forward<F>(f), v); }
};

template <class Tb>
using table_scalar_t = decltype(std::declval<const Tb&>().total());

}  // namespace

void bind_arc_length(py::module_& m, py::class_<curve>& cls) {
    m.attr("default_accuracy") = default_accuracy;

    cls.def("arc_length", [](const curve& c, double accuracy) {
        return c.visit([&](const auto& cr) {
            using T = scalar_t<decltype(cr)>;
            check_relative_accuracy(accuracy);
            py::gil_scoped_release nogil;
            return double(arc_length(cr, T(accuracy)));
        });
    }, py::arg("accuracy") = default_accuracy, "Length of the whole curve, to the relative accuracy.");

    cls.def("arc_length_between", [](const curve& c, double ta, double tb, double accuracy) {
        return c.visit([&](const auto& cr) {
            using T = scalar_t<decltype(cr)>;
            check_relative_accuracy(accuracy);
            py::gil_scoped_release nogil;
            return double(arc_length(cr, T(ta), T(tb), T(accuracy)));
        });
    }, py::arg("t0"), py::arg("t1"), py::arg("accuracy") = default_accuracy, "Length of the curve over [t0, t1].");

    py::class_<table> tb(m, "_ArcLengthTable", "Cumulative arc length of a curve, and its inverse.");
    cls.def("arc_length_table", [](const curve& c, double accuracy) {
        return c.visit([&](const auto& cr) {
            using T = scalar_t<decltype(cr)>;
            constexpr std::size_t D = dimension_v<decltype(cr)>;
            check_relative_accuracy(accuracy);
            const double t_min = double(cr.grid().front()), t_max = double(cr.grid().back());
            py::gil_scoped_release nogil;
            return table{arc_length_table<D, T>(cr, T(accuracy)), t_min, t_max};
        });
    }, py::arg("accuracy") = default_accuracy, "Build the arc-length table (releases the GIL).");

    tb.def_property_readonly("total", [](const table& t) {
        return t.visit([](const auto& x) { return double(x.total()); });
    }, "Total length.");
    tb.def_property_readonly("accuracy", [](const table& t) {
        return t.visit([](const auto& x) { return double(x.accuracy()); });
    }, "The relative accuracy it was built with.");
    tb.def_property_readonly("knot_lengths", [](const table& t) {
        return t.visit([](const auto& x) -> py::array { return vector_array(x.knot_lengths()); });
    }, "Cumulative length at every knot (a new array).");
    tb.def_property_readonly("segment_lengths", [](const table& t) {
        return t.visit([](const auto& x) -> py::array {
            using T = table_scalar_t<decltype(x)>;
            const std::size_t n = x.knot_lengths().size() - 1;
            py::array_t<T> out{py::ssize_t(n)};
            for (std::size_t i = 0; i < n; ++i) out.mutable_data()[i] = x.segment_length(i);
            return out;
        });
    }, "Length of every segment (a new array).");
    tb.def("t_at", [](const table& t, const py::array& s) {
        return t.visit([&](const auto& x) -> py::array {
            using T = table_scalar_t<decltype(x)>;
            auto ss = contiguous<T>(s);
            py::array_t<T, py::array::c_style> out(shape_plus(ss, {}));
            if (ss.ndim() == 0) {  // one number: the scalar call (its message names no index)
                *out.mutable_data() = x.t_at(*ss.data());
                return out;
            }
            std::span<const T> in(ss.data(), std::size_t(ss.size()));
            std::span<T> o(out.mutable_data(), std::size_t(out.size()));
            {
                py::gil_scoped_release nogil;
                x.t_at(in, o);
            }
            return out;
        });
    }, py::arg("s"), "Parameter t at every arc length s (any shape). Releases the GIL.");
    tb.def("s_at", [](const table& t, const py::array& tv) {
        return t.visit([&](const auto& x) -> py::array {
            using T = table_scalar_t<decltype(x)>;
            auto ts = contiguous<T>(tv);
            check_batch_domain<T>(ts, T(t.t_min), T(t.t_max));  // exact: the knots are T
            py::array_t<T, py::array::c_style> out(shape_plus(ts, {}));
            const T* in = ts.data();
            T* o = out.mutable_data();
            const std::size_t n = std::size_t(ts.size());
            {
                py::gil_scoped_release nogil;
                for (std::size_t k = 0; k < n; ++k) o[k] = x.s_at(in[k]);
            }
            return out;
        });
    }, py::arg("t"), "Arc length from the start at every t (any shape). Releases the GIL.");

    cls.def("sample_arc_length", [](const curve& c, std::size_t n, double accuracy) {
        return c.visit([&](const auto& cr) -> py::tuple {
            using T = scalar_t<decltype(cr)>;
            constexpr std::size_t D = dimension_v<decltype(cr)>;
            samples<D, T> r;
            check_relative_accuracy(accuracy);
            {
                py::gil_scoped_release nogil;
                r = sample_arc_length(cr, n, T(accuracy));
            }
            return py::make_tuple(vector_array<T>(r.t), vector_array<T>(r.s),
                                  points_array<D, T>(r.points));
        });
    }, py::arg("n"), py::arg("accuracy") = default_accuracy,
       "n points evenly spaced in arc length: (t, s, points).");
}

}  // namespace crspline::python
