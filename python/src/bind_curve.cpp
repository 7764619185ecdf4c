// crspline Python module: building a curve, its attributes, evaluation and
// Bézier form.
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <crspline/spec.hpp>


#include "curve.hpp"

namespace crspline::python {

namespace {

/// The specification of a curve from Python's normalized arguments; points
/// (N, dim) of float32 or float64. make_curve validates it (crspline::validate).
curve_spec to_curve_spec(const py::array& points, std::optional<double> alpha, std::optional<std::vector<double>> grid,
                         const ends_arg& ends, double tension, std::vector<double> kb_tension,
                         std::vector<double> kb_continuity, std::vector<double> kb_bias, bool strict) {
    if (points.ndim() != 2)
        throw invalid_input("points must be a 2-D array (one row per point), got " + std::to_string(points.ndim()) +
                            " dimensions");
    curve_spec s;
    s.dimension = std::size_t(points.shape(1));
    auto p = contiguous<double>(points);
    s.points.assign(p.data(), p.data() + p.size());
    s.alpha = alpha;
    s.grid = std::move(grid);
    apply_ends(s, ends);
    s.tension = tension;
    s.kb = {std::move(kb_tension), std::move(kb_continuity), std::move(kb_bias)};
    s.strict = strict;
    return s;
}

curve make_curve(const py::array& points, std::optional<double> alpha, std::optional<std::vector<double>> grid,
                 const ends_arg& ends, double tension, std::vector<double> kb_tension,
                 std::vector<double> kb_continuity, std::vector<double> kb_bias, bool strict) {
    const curve_spec s = to_curve_spec(points, alpha, std::move(grid), ends, tension, std::move(kb_tension),
                                       std::move(kb_continuity), std::move(kb_bias), strict);
    return with_scalar(points, [&](auto scalar) {
        using T = decltype(scalar);
        // 1..4 exactly, 5..16 as the zero-padded wide curve (make_curve pads
        // and validates); any other dimension gets validate()'s words.
        return crspline::with_dimension(
            s.dimension,
            [&](auto d) { return curve{crspline::make_curve<decltype(d)::value, T>(s)}; },
            [&](std::size_t) { validate(s); });
    });
}

/// The specification a curve was built from (crspline::to_spec), as a dict
/// of plain Python values; a wide curve gives its padded dimension.
py::dict spec_dict(const curve& c) {
    const curve_spec s = c.visit([](const auto& cr) {
        using T = scalar_t<decltype(cr)>;
        constexpr std::size_t D = dimension_v<decltype(cr)>;
        auto o = cr.options();  // the knots are the curve's own when they came from a grid
        if (!o.alpha) o.grid.emplace(cr.grid().begin(), cr.grid().end());
        return to_spec<D, T>(cr.points(), o);
    });
    const auto end_of = [](const end_spec& e) -> py::object {
        switch (e.type) {
            case end_spec::kind::reflect: return py::str("reflect");
            case end_spec::kind::tangent: return py::cast(e.velocity);
            case end_spec::kind::natural: break;
        }
        return py::str("natural");
    };
    py::dict d;
    d["dimension"] = s.dimension;
    d["points"] = s.points;
    d["alpha"] = s.alpha ? py::object(py::float_(*s.alpha)) : py::none();
    d["grid"] = s.grid ? py::cast(*s.grid) : py::none();
    d["closed"] = s.closed;
    d["start"] = end_of(s.start);
    d["end"] = end_of(s.end);
    d["tension"] = s.tension;
    d["kb_tension"] = s.kb.tension;
    d["kb_continuity"] = s.kb.continuity;
    d["kb_bias"] = s.kb.bias;
    d["strict"] = s.strict;
    return d;
}

}  // namespace

void bind_curve(py::module_& m, py::class_<curve>& cls) {
    m.def("_make_curve", &make_curve, py::arg("points"), py::arg("alpha"), py::arg("grid"), py::arg("ends"),
          py::arg("tension"), py::arg("kb_tension"), py::arg("kb_continuity"), py::arg("kb_bias"), py::arg("strict"),
          "Build a curve from its specification, validated by the core (crspline::validate): points (N, dim),\n"
          "alpha or grid, ends ('natural', 'reflect', 'closed' or (start, end), each a name or a tangent),\n"
          "tension, per-vertex Kochanek-Bartels values (or empty lists) and strict.");
    m.def(
        "_check_grid",
        [](const std::vector<double>& grid) {
            detail::check_grid_values(std::span<const double>(grid), grid.size(), false);
        },
        py::arg("grid"),
        "The core's check of a given grid's values (finite, strictly increasing): the spec error, or nothing.");
    cls.def("spec", &spec_dict, "The specification the curve was built from (crspline::to_spec), as a dict.");

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
            // Values outside the domain, infinities included, clamp to the
            // first or last segment; NaN has no side to clamp to.
            for (py::ssize_t k = 0; k < ts.size(); ++k) {
                if (std::isnan(in[k]))
                    throw out_of_domain(std::string("t = nan") +
                                        (ts.ndim() == 0 ? "" : " (index " + std::to_string(k) + ")") +
                                        " is not a number: segment_index clamps t outside the domain to the "
                                        "first or last segment, but NaN is on neither side");
                o[k] = std::int64_t(cr.locate(in[k]));
            }
            return out;
        });
    }, py::arg("t"),
       "Index of the segment that owns each t (t outside the domain clamped to the first or last; NaN refused).");
}

}  // namespace crspline::python
