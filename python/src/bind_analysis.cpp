// crspline Python module: per-segment analysis (cusps, self-intersections,
// chord distances, the paper's bounds) as plain dicts.
#include <crspline/analysis.hpp>

#include "curve.hpp"

namespace crspline::python {

namespace {

template <class T>
py::array_t<T> pairs_array(const std::vector<std::array<T, 2>>& v) {
    py::array_t<T> out({py::ssize_t(v.size()), py::ssize_t(2)});
    T* o = out.mutable_data();
    for (const auto& p : v) { *o++ = p[0]; *o++ = p[1]; }
    return out;
}

template <class T>
py::array_t<T> two(const std::array<T, 2>& a) {
    return vector_array<T>(std::span<const T>(a.data(), 2));
}

template <std::size_t D, class T>
py::dict to_dict(const segment_analysis<D, T>& a, T t0, T h) {
    py::dict d;
    auto to_t = [&](std::span<const T> u) {
        std::vector<T> t(u.size());
        for (std::size_t k = 0; k < u.size(); ++k) t[k] = u[k] == T(1) ? t0 + h : t0 + u[k] * h;
        return vector_array<T>(t);
    };
    d["index"] = a.index;
    d["rank"] = a.rank;
    d["bezier"] = points_array<D, T>(std::span<const vec<D, T>>(a.bezier.data(), 4));
    d["zero_speed_u"] = vector_array<T>(a.zero_speed_u);
    d["cusp_u"] = vector_array<T>(a.cusp_u);
    d["cusp_t"] = to_t(a.cusp_u);
    d["self_intersection_u"] = pairs_array<T>(a.self_intersection);
    d["fold"] = a.fold;
    d["has_cusp"] = a.has_cusp();
    d["has_self_intersection"] = a.has_self_intersection();
    if (a.projection) {
        const auto& p = *a.projection;
        py::dict q;
        q["bezier"] = two<T>(p.bezier);
        q["theorem2"] = p.theorem2;
        q["derivative_min"] = double(p.derivative_min);
        q["derivative_min_u"] = double(p.derivative_min_u);
        q["range"] = two<T>(p.range);
        d["projection"] = q;
    } else {
        d["projection"] = py::none();
    }
    d["bezier_height"] = two<T>(a.bezier_height);
    d["bezier_bound"] = double(a.bezier_bound);
    d["max_chord_line_distance"] = double(a.max_chord_line_distance);
    d["max_chord_line_distance_u"] = double(a.max_chord_line_distance_u);
    d["max_chord_distance"] = double(a.max_chord_distance);
    d["max_chord_distance_u"] = double(a.max_chord_distance_u);
    d["overshoot"] = two<T>(a.overshoot);
    if (a.bounds) {
        const auto& b = *a.bounds;
        py::dict q;
        q["d1"] = double(b.d1);
        q["d2"] = double(b.d2);
        q["d3"] = double(b.d3);
        q["theta1"] = double(b.theta1);
        q["theta2"] = double(b.theta2);
        q["h1"] = double(b.h1);
        q["h2"] = double(b.h2);
        q["eq6_one_sided"] = double(b.eq6_one_sided);
        q["eq6"] = double(b.eq6);
        q["eq8_start"] = double(b.eq8_start);
        q["eq8_end"] = double(b.eq8_end);
        d["bounds"] = q;
    } else {
        d["bounds"] = py::none();
    }
    return d;
}

}  // namespace

void bind_analysis(py::module_&, py::class_<curve>& cls) {
    cls.def("analyze", [](const curve& c) {
        return c.visit([](const auto& cr) -> py::list {
            using T = scalar_t<decltype(cr)>;
            constexpr std::size_t D = dimension_v<decltype(cr)>;
            std::vector<segment_analysis<D, T>> a;
            {
                py::gil_scoped_release nogil;
                a = analyze(cr);
            }
            py::list out;
            const auto grid = cr.grid();
            for (const auto& s : a) out.append(to_dict(s, grid[s.index], grid[s.index + 1] - grid[s.index]));
            return out;
        });
    }, "Analysis of every segment, as a list of dicts.");
}

}  // namespace crspline::python
