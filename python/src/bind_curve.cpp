// crspline Python module: building a curve, its attributes, evaluation and
// Bézier form.
#include <optional>
#include <string>
#include <vector>


#include "curve.hpp"

namespace crspline::python {

namespace {

template <std::size_t D, class T>
end_condition<D, T> to_end(const std::string& kind, const std::optional<std::vector<double>>& tangent,
                           const char* which) {
    if (kind == "natural") return end_condition<D, T>::natural();
    if (kind == "reflect") return end_condition<D, T>::reflect();
    if (kind == "tangent") {
        if (!tangent) throw invalid_input(std::string(which) + " tangent is missing");
        return end_condition<D, T>::tangent(to_vec<D, T>(*tangent, (std::string(which) + " tangent").c_str()));
    }
    throw invalid_input(std::string(which) + " end condition must be 'natural', 'reflect' or a tangent, got '" +
                        kind + "'");
}

template <class T>
std::vector<T> cast_all(const std::vector<double>& v) {
    return std::vector<T>(v.begin(), v.end());
}

curve make_curve(const py::array& points, std::optional<double> alpha, std::optional<std::vector<double>> grid,
                 const std::string& start, std::optional<std::vector<double>> start_tangent, const std::string& end,
                 std::optional<std::vector<double>> end_tangent, bool closed, double tension,
                 const std::vector<double>& kb_tension, const std::vector<double>& kb_continuity,
                 const std::vector<double>& kb_bias, bool strict) {
    if (points.ndim() != 2)
        throw invalid_input("points must be a 2-D array (one row per point), got " + std::to_string(points.ndim()) +
                            " dimensions");
    const std::size_t n = std::size_t(points.shape(0)), dim = std::size_t(points.shape(1));
    return with_scalar(points, [&](auto scalar) {
        using T = decltype(scalar);
        return with_dimension(dim, [&](auto d) {
            constexpr std::size_t D = decltype(d)::value;
            auto p = contiguous<T>(points);
            options<D, T> opt;
            opt.alpha = alpha;
            if (grid) opt.grid = cast_all<T>(*grid);
            opt.start = to_end<D, T>(start, start_tangent, "start");
            opt.end = to_end<D, T>(end, end_tangent, "end");
            opt.closed = closed;
            opt.tension = T(tension);
            opt.kb.tension = cast_all<T>(kb_tension);
            opt.kb.continuity = cast_all<T>(kb_continuity);
            opt.kb.bias = cast_all<T>(kb_bias);
            opt.strict = strict;
            return curve{catmull_rom<D, T>(std::span<const vec<D, T>>(as_points<D, T>(std::as_const(p)), n), opt)};
        });
    });
}

}  // namespace

void bind_curve(py::module_& m, py::class_<curve>& cls) {
    m.def("_make_curve", &make_curve, py::arg("points"), py::arg("alpha"), py::arg("grid"), py::arg("start"),
          py::arg("start_tangent"), py::arg("end"), py::arg("end_tangent"), py::arg("closed"), py::arg("tension"),
          py::arg("kb_tension"), py::arg("kb_continuity"), py::arg("kb_bias"), py::arg("strict"),
          "Build a curve from validated, normalized arguments (see crspline.CatmullRom).");

    cls.def_property_readonly("dim", [](const curve& c) {
        return c.visit([](const auto& cr) { return dimension_v<decltype(cr)>; });
    }, "Dimension of the points.");
    cls.def_property_readonly("dtype", [](const curve& c) {
        return c.visit([](const auto& cr) { return py::dtype::of<scalar_t<decltype(cr)>>(); });
    }, "Scalar type: float32 or float64.");
    cls.def_property_readonly("closed", [](const curve& c) {
        return c.visit([](const auto& cr) { return cr.closed(); });
    }, "True for a closed (periodic) curve.");
    cls.def_property_readonly("segment_count", [](const curve& c) {
        return c.visit([](const auto& cr) { return cr.segment_count(); });
    }, "Number of cubic segments.");
    cls.def_property_readonly("grid", [](const curve& c) {
        return c.visit([](const auto& cr) -> py::array { return vector_array(cr.grid()); });
    }, "The knots (a new array).");
    cls.def_property_readonly("points", [](const curve& c) {
        return c.visit([](const auto& cr) -> py::array { return points_array(cr.points()); });
    }, "The control points (a new array).");

    cls.def("evaluate", [](const curve& c, const py::array& t, int order) {
        return c.visit([&](const auto& cr) -> py::array {
            using T = scalar_t<decltype(cr)>;
            constexpr std::size_t D = dimension_v<decltype(cr)>;
            auto ts = contiguous<T>(t);
            const std::size_t n = std::size_t(ts.size());
            py::array_t<T, py::array::c_style> out(shape_plus(ts, {py::ssize_t(D)}));
            if (ts.ndim() == 0) {  // one number: the scalar call (its message names no index)
                *as_points<D, T>(out) = cr.evaluate(*ts.data(), order);
                return out;
            }
            std::span<const T> in(ts.data(), n);
            std::span<vec<D, T>> o(as_points<D, T>(out), n);
            {
                py::gil_scoped_release nogil;
                cr.evaluate(in, o, order);
            }
            return out;
        });
    }, py::arg("t"), py::arg("order") = 0,
       "d^order x / dt^order at every t (any shape); result shape t.shape + (dim,). Releases the GIL.");

    cls.def("evaluate_unchecked", [](const curve& c, const py::array& t, int order) {
        return c.visit([&](const auto& cr) -> py::array {
            using T = scalar_t<decltype(cr)>;
            constexpr std::size_t D = dimension_v<decltype(cr)>;
            if (order < 0 || order > 3)
                throw invalid_input("derivative order must be 0, 1, 2 or 3, got " + std::to_string(order));
            auto ts = contiguous<T>(t);
            const std::size_t n = std::size_t(ts.size());
            py::array_t<T, py::array::c_style> out(shape_plus(ts, {py::ssize_t(D)}));
            const T* in = ts.data();
            vec<D, T>* o = as_points<D, T>(out);
            {
                py::gil_scoped_release nogil;
                for (std::size_t k = 0; k < n; ++k) o[k] = cr.evaluate_unchecked(in[k], order);
            }
            return out;
        });
    }, py::arg("t"), py::arg("order") = 0,
       "Like evaluate, but t outside the domain extrapolates the end segments' cubics.");

    cls.def("bezier", [](const curve& c) {
        return c.visit([](const auto& cr) -> py::array {
            using T = scalar_t<decltype(cr)>;
            constexpr std::size_t D = dimension_v<decltype(cr)>;
            const auto b = cr.bezier();
            py::array_t<T> out({py::ssize_t(b.size()), py::ssize_t(4), py::ssize_t(D)});
            T* o = out.mutable_data();
            for (const auto& seg : b)
                for (const auto& q : seg)
                    for (std::size_t k = 0; k < D; ++k) *o++ = q[k];
            return out;
        });
    }, "Bézier control points, shape (segment_count, 4, dim).");

    cls.def("tangents", [](const curve& c) {
        return c.visit([](const auto& cr) -> py::array {
            using T = scalar_t<decltype(cr)>;
            constexpr std::size_t D = dimension_v<decltype(cr)>;
            py::array_t<T> out({py::ssize_t(cr.segment_count()), py::ssize_t(2), py::ssize_t(D)});
            T* o = out.mutable_data();
            for (std::size_t i = 0; i < cr.segment_count(); ++i)
                for (const auto& v : cr.tangents(i))
                    for (std::size_t k = 0; k < D; ++k) *o++ = v[k];
            return out;
        });
    }, "dx/dt at the start and end of every segment, shape (segment_count, 2, dim).");

    cls.def("locate", [](const curve& c, const py::array& t) {
        return c.visit([&](const auto& cr) -> py::array {
            using T = scalar_t<decltype(cr)>;
            auto ts = contiguous<T>(t);
            py::array_t<std::int64_t> out(shape_plus(ts, {}));
            const T* in = ts.data();
            std::int64_t* o = out.mutable_data();
            for (py::ssize_t k = 0; k < ts.size(); ++k) o[k] = std::int64_t(cr.locate(in[k]));
            return out;
        });
    }, py::arg("t"), "Index of the segment that owns each t (clamped to the first and last).");
}

}  // namespace crspline::python
