// crspline Python module: a cubic Hermite curve from points, per-vertex
// tangents and knots (catmull_rom::hermite). crspline.splines builds every
// curve this way, with tangents computed in Python.
#include <optional>
#include <string>
#include <vector>

#include "curve.hpp"

namespace crspline::python {

namespace {

curve make_hermite(const py::array& points, const py::array& outgoing, const std::optional<py::array>& incoming,
                   const std::vector<double>& grid, bool closed) {
    if (points.ndim() != 2)
        throw invalid_input("points must be a 2-D array (one row per point), got " + std::to_string(points.ndim()) +
                            " dimensions");
    const std::size_t n = std::size_t(points.shape(0)), dim = std::size_t(points.shape(1));
    auto check_shape = [&](const py::array& a, const char* name) {
        if (a.ndim() != 2 || std::size_t(a.shape(0)) != n || std::size_t(a.shape(1)) != dim)
            throw invalid_input(std::string(name) + " tangents must have shape (" + std::to_string(n) + ", " +
                                std::to_string(dim) + "), one per point");
    };
    check_shape(outgoing, "outgoing");
    if (incoming) check_shape(*incoming, "incoming");
    return with_scalar(points, [&](auto scalar) {
        using T = decltype(scalar);
        return with_dimension(dim, [&](auto d) {
            constexpr std::size_t D = decltype(d)::value;
            using P = vec<D, T>;
            auto p = contiguous<T>(points);
            auto out = contiguous<T>(outgoing);
            auto in = contiguous<T>(incoming ? *incoming : outgoing);
            const std::vector<T> g(grid.begin(), grid.end());
            return curve{catmull_rom<D, T>::hermite(std::span<const P>(as_points<D, T>(std::as_const(p)), n),
                                                    std::span<const P>(as_points<D, T>(std::as_const(out)), n),
                                                    std::span<const P>(as_points<D, T>(std::as_const(in)), n),
                                                    std::span<const T>(g), closed)};
        });
    });
}

}  // namespace

void bind_hermite(py::module_& m, py::class_<curve>&) {
    m.def("_make_hermite", &make_hermite, py::arg("points"), py::arg("outgoing"), py::arg("incoming"),
          py::arg("grid"), py::arg("closed"),
          "Cubic Hermite curve from points (N, dim), outgoing and incoming tangents dx/dt (N, dim; incoming\n"
          "None: the same as outgoing) and the knots (N, N + 1 when closed).");
}

}  // namespace crspline::python
