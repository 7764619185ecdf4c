// crspline Python module: tessellation, bounding boxes, nearest points.
#include <optional>

#include <crspline/bounds.hpp>
#include <crspline/nearest.hpp>
#include <crspline/resolution.hpp>
#include <crspline/tessellate.hpp>

#include "curve.hpp"

namespace crspline::python {

void bind_geometry(py::module_& m, py::class_<curve>& cls) {
    m.attr("default_tessellation_tolerance") = default_tessellation_tolerance;

    cls.def("tessellate", [](const curve& c, std::optional<double> tolerance) {
        return c.visit([&](const auto& cr) -> py::tuple {
            using T = scalar_t<decltype(cr)>;
            constexpr std::size_t D = dimension_v<decltype(cr)>;
            polyline<D, T> p;
            if (tolerance) check_distance_tolerance(cr, *tolerance);  // below it, subdivision never ends
            {
                py::gil_scoped_release nogil;
                p = tolerance ? tessellate(cr, T(*tolerance)) : tessellate(cr);
            }
            return py::make_tuple(points_array<D, T>(p.points), vector_array<T>(p.t));
        });
    }, py::arg("tolerance") = py::none(),
       "Adaptive polyline within tolerance (default 1e-3 x bounding-box diagonal): (points, t).");

    cls.def("bounding_box", [](const curve& c, bool tight) {
        return c.visit([&](const auto& cr) -> py::array {
            using T = scalar_t<decltype(cr)>;
            constexpr std::size_t D = dimension_v<decltype(cr)>;
            const box<D, T> b = tight ? bounding_box(cr) : control_box(cr);
            const vec<D, T> corners[2] = {b.lo, b.hi};
            return points_array<D, T>(std::span<const vec<D, T>>(corners, 2));
        });
    }, py::arg("tight") = true, "[lo, hi] of the tight box (or of the Bézier control points), shape (2, dim).");

    cls.def("nearest", [](const curve& c, const py::array& queries) {
        return c.visit([&](const auto& cr) -> py::tuple {
            using T = scalar_t<decltype(cr)>;
            constexpr std::size_t D = dimension_v<decltype(cr)>;
            auto q = contiguous<T>(queries);
            if (q.ndim() != 2 || q.shape(1) != py::ssize_t(D))
                throw invalid_input("query points must have shape (n, " + std::to_string(D) + ")");
            const std::size_t n = std::size_t(q.shape(0));
            std::vector<nearest_result<D, T>> r;
            {
                py::gil_scoped_release nogil;
                r = nearest(cr, std::span<const vec<D, T>>(as_points<D, T>(std::as_const(q)), n));
            }
            py::array_t<T> t{py::ssize_t(n)}, d2{py::ssize_t(n)};
            py::array_t<std::int64_t> seg{py::ssize_t(n)};
            py::array_t<T> p({py::ssize_t(n), py::ssize_t(D)});
            T* pt = t.mutable_data();
            T* pd = d2.mutable_data();
            std::int64_t* ps = seg.mutable_data();
            T* pp = p.mutable_data();
            for (std::size_t k = 0; k < n; ++k) {
                pt[k] = r[k].t;
                pd[k] = r[k].distance_sq;
                ps[k] = std::int64_t(r[k].segment);
                for (std::size_t j = 0; j < D; ++j) pp[k * D + j] = r[k].point[j];
            }
            return py::make_tuple(t, d2, seg, p);
        });
    }, py::arg("queries"), "Nearest curve point to each query (n x dim): (t, distance_sq, segment, point).");
}

}  // namespace crspline::python
