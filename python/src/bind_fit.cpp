// crspline Python module: crspline.fit (issue 40), the core's fit() over
// NumPy points. Returns the fitted control points and the report as a dict;
// crspline/_fit.py builds the curve object from them (the same construction,
// so the same curve bit for bit).
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include <crspline/fit.hpp>

#include "curve.hpp"

namespace crspline::python {

namespace {

template <std::size_t D, class T>
py::dict fit_points(const T* data, std::size_t n, std::size_t dim, const fit_options<D, T>& opt) {
    // Points of fewer coordinates than D (5 to 15 in the wide curve) are zero-padded.
    std::vector<vec<D, T>> pts(n);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k < dim; ++k) pts[i][k] = data[i * dim + k];
    fit_result<D, T> r = [&] {
        py::gil_scoped_release nogil;
        return fit(std::span<const vec<D, T>>(pts), opt);
    }();
    const auto cp = r.curve.points();
    py::array_t<T> out({py::ssize_t(cp.size()), py::ssize_t(dim)});
    auto o = out.template mutable_unchecked<2>();
    for (std::size_t i = 0; i < cp.size(); ++i)
        for (std::size_t k = 0; k < dim; ++k) o(py::ssize_t(i), py::ssize_t(k)) = cp[i][k];
    py::dict d;
    d["points"] = out;
    const auto& kb = r.curve.options().kb.tension;
    if (kb.empty()) d["kb_tension"] = py::none();
    else d["kb_tension"] = std::vector<double>(kb.begin(), kb.end());
    d["deviation"] = double(r.deviation);
    d["curve_to_input"] = double(r.curve_to_input);
    d["input_to_curve"] = double(r.input_to_curve);
    d["count"] = r.count;
    d["tensioned"] = r.tensioned;
    d["rounding_floor"] = double(r.rounding_floor);
    if (opt.mode == fit_mode::subset) {
        py::array_t<std::int64_t> idx(py::ssize_t(r.indices.size()));
        auto w = idx.mutable_unchecked<1>();
        for (std::size_t i = 0; i < r.indices.size(); ++i) w(py::ssize_t(i)) = std::int64_t(r.indices[i]);
        d["indices"] = idx;
    } else {
        d["indices"] = py::none();
    }
    return d;
}

py::dict fit_py(const py::array& points, double tolerance, double alpha, bool closed, const std::string& mode,
                double tension, const std::string& start, const std::string& end) {
    if (points.ndim() != 2)
        throw invalid_input("points must be a 2-D array (one row per point), got " + std::to_string(points.ndim()) +
                            " dimensions");
    if (mode != "subset" && mode != "free")
        throw invalid_input("mode must be 'subset' or 'free', got '" + mode + "'");
    auto end_of = [](const std::string& name, const char* which) {
        if (name == "natural") return 0;
        if (name == "reflect") return 1;
        throw invalid_input(std::string("fit: the ") + which + " end must be 'natural' or 'reflect', got '" + name + "'");
    };
    const int s_end = end_of(start, "start"), e_end = end_of(end, "end");
    const std::size_t n = std::size_t(points.shape(0)), dim = std::size_t(points.shape(1));
    const std::size_t run_dim = dim > max_exact_dimension && dim <= wide_dimension ? wide_dimension : dim;
    return with_scalar(points, [&](auto scalar) {
        using T = decltype(scalar);
        return with_dimension(run_dim, [&](auto d) {
            constexpr std::size_t D = decltype(d)::value;
            fit_options<D, T> o;
            o.tolerance = tolerance;
            o.alpha = alpha;
            o.closed = closed;
            o.mode = mode == "free" ? fit_mode::free : fit_mode::subset;
            o.tension = T(tension);
            if (s_end) o.start = end_condition<D, T>::reflect();
            if (e_end) o.end = end_condition<D, T>::reflect();
            auto p = contiguous<T>(points);
            return fit_points<D, T>(p.data(), n, dim, o);
        });
    });
}

}  // namespace

void bind_fit(py::module_& m) {
    m.def("_fit", &fit_py, py::arg("points"), py::arg("tolerance"), py::arg("alpha"), py::arg("closed"),
          py::arg("mode"), py::arg("tension"), py::arg("start"), py::arg("end"),
          "Fit (crspline.fit's core): the control points (K, dim), the Kochanek-Bartels tension per vertex\n"
          "(None when not raised) and the report (deviation, curve_to_input, input_to_curve, count,\n"
          "tensioned, rounding_floor, indices: None in free mode). The GIL is released while fitting.");
}

}  // namespace crspline::python
