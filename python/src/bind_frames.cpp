// crspline Python module: curvature, torsion and moving frames.
#include <optional>
#include <string>


#include <crspline/frames.hpp>

#include "curve.hpp"

namespace crspline::python {

namespace {

/// out[k] = f(t[k]) for every t (any shape), with the GIL released; an
/// array's t outside the curve's domain is named with its index first.
template <class T, class C, class F>
py::array map_t(const C& cr, const py::array& t, F&& f) {
    auto ts = contiguous<T>(t);
    check_batch_domain<T>(ts, cr.grid().front(), cr.grid().back());
    py::array_t<T, py::array::c_style> out(shape_plus(ts, {}));
    const T* in = ts.data();
    T* o = out.mutable_data();
    const std::size_t n = std::size_t(ts.size());
    {
        py::gil_scoped_release nogil;
        for (std::size_t k = 0; k < n; ++k) o[k] = f(in[k]);
    }
    return out;
}

}  // namespace

void bind_frames(py::module_&, py::class_<curve>& cls) {
    cls.def("curvature", [](const curve& c, const py::array& t) {
        return c.visit([&](const auto& cr) -> py::array {
            using T = scalar_t<decltype(cr)>;
            return map_t<T>(cr, t, [&](T x) { return curvature(cr, x); });
        });
    }, py::arg("t"), "Curvature at every t (any shape).");

    cls.def("signed_curvature", [](const curve& c, const py::array& t) {
        return c.visit([&](const auto& cr) -> py::array {
            using T = scalar_t<decltype(cr)>;
            if constexpr (dimension_v<decltype(cr)> == 2) {
                return map_t<T>(cr, t, [&](T x) { return signed_curvature(cr, x); });
            } else {
                throw invalid_input("signed curvature needs a 2-D curve, this one is " +
                                    std::to_string(dimension_v<decltype(cr)>) + "-D");
            }
        });
    }, py::arg("t"), "Signed curvature of a plane curve at every t.");

    cls.def("torsion", [](const curve& c, const py::array& t) {
        return c.visit([&](const auto& cr) -> py::array {
            using T = scalar_t<decltype(cr)>;
            if constexpr (dimension_v<decltype(cr)> == 3) {
                return map_t<T>(cr, t, [&](T x) { return torsion(cr, x); });
            } else {
                throw invalid_input("torsion needs a 3-D curve, this one is " +
                                    std::to_string(dimension_v<decltype(cr)>) + "-D");
            }
        });
    }, py::arg("t"), "Torsion of a space curve at every t.");

    cls.def("frames", [](const curve& c, const py::array& t, const std::string& kind,
                         std::optional<std::vector<double>> initial_normal) {
        return c.visit([&](const auto& cr) -> py::tuple {
            using T = scalar_t<decltype(cr)>;
            constexpr std::size_t D = dimension_v<decltype(cr)>;
            auto ts = contiguous<T>(t);
            if (ts.ndim() != 1) throw invalid_input("t must be a 1-D array for frames");
            std::span<const T> in(ts.data(), std::size_t(ts.size()));
            std::vector<crspline::frame<D, T>> f;
            if (kind == "frenet") {
                if constexpr (D == 3) {
                    if (initial_normal) throw invalid_input("Frenet frames take no initial normal");
                    py::gil_scoped_release nogil;
                    f = frenet_frames(cr, in);
                } else {
                    throw invalid_input("Frenet frames need a 3-D curve, this one is " + std::to_string(D) + "-D");
                }
            } else if (kind == "rotation_minimizing") {
                if constexpr (D == 2 || D == 3) {
                    std::optional<vec<D, T>> n0;
                    if (initial_normal) n0 = to_vec<D, T>(*initial_normal, "initial normal");
                    py::gil_scoped_release nogil;
                    f = rotation_minimizing_frames(cr, in, n0);
                } else {
                    throw invalid_input("rotation-minimizing frames need a 2-D or 3-D curve, this one is " +
                                        std::to_string(D) + "-D");
                }
            } else {
                throw invalid_input("kind must be 'rotation_minimizing' or 'frenet', got '" + kind + "'");
            }
            std::vector<vec<D, T>> cols[4];
            for (auto& col : cols) col.reserve(f.size());
            for (const auto& fk : f) {
                cols[0].push_back(fk.position);
                cols[1].push_back(fk.tangent);
                cols[2].push_back(fk.normal);
                cols[3].push_back(fk.binormal);
            }
            return py::make_tuple(points_array<D, T>(cols[0]), points_array<D, T>(cols[1]),
                                  points_array<D, T>(cols[2]), points_array<D, T>(cols[3]));
        });
    }, py::arg("t"), py::arg("kind") = "rotation_minimizing", py::arg("initial_normal") = py::none(),
       "Frames at t: (position, tangent, normal, binormal), each len(t) x dim.");
}

}  // namespace crspline::python
