// crspline Python module: per-segment analysis (cusps, self-intersections,
// chord distances, the paper's bounds) as plain dicts.
#include <optional>

#include <crspline/analysis.hpp>
#include <crspline/certify.hpp>
#include <crspline/intersections.hpp>

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

/// find_intersections' result as a dict of arrays (k meetings).
template <std::size_t D, class T>
py::dict to_dict(const intersection_result<D, T>& r, std::span<const T> grid) {
    const std::size_t k = r.intersections.size();
    py::array_t<std::int64_t> seg({py::ssize_t(k), py::ssize_t(2)});
    py::array_t<T> u({py::ssize_t(k), py::ssize_t(2)}), t({py::ssize_t(k), py::ssize_t(2)});
    py::array_t<T> dist{py::ssize_t(k)};
    std::vector<vec<D, T>> pts;
    for (std::size_t i = 0; i < k; ++i) {
        const auto& x = r.intersections[i];
        for (std::size_t j = 0; j < 2; ++j) {
            const std::size_t sg = x.segments[j];
            seg.mutable_data()[2 * i + j] = std::int64_t(sg);
            u.mutable_data()[2 * i + j] = x.u[j];
            const T h = grid[sg + 1] - grid[sg];
            t.mutable_data()[2 * i + j] = x.u[j] == T(1) ? grid[sg + 1] : grid[sg] + x.u[j] * h;
        }
        dist.mutable_data()[i] = x.distance;
        pts.push_back(x.point);
    }
    std::vector<std::int64_t> folds(r.folds.begin(), r.folds.end());
    py::dict d;
    d["segments"] = seg;
    d["u"] = u;
    d["t"] = t;
    d["point"] = points_array<D, T>(pts);
    d["distance"] = dist;
    d["folds"] = vector_array<std::int64_t>(folds);
    d["complete"] = r.complete;
    d["any"] = r.any();
    return d;
}

py::object optional_index(const std::optional<std::size_t>& i) {
    return i ? py::object(py::int_(*i)) : py::object(py::none());
}

}  // namespace

void bind_analysis(py::module_& m, py::class_<curve>& cls) {
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

    m.attr("default_intersection_tolerance") = default_intersection_tolerance;
    m.attr("safe_adjacent_angle") = safe_adjacent_angle;

    cls.def("intersections", [](const curve& c, std::optional<double> tolerance) {
        return c.visit([&](const auto& cr) -> py::dict {
            using T = scalar_t<decltype(cr)>;
            constexpr std::size_t D = dimension_v<decltype(cr)>;
            if (tolerance && !(*tolerance > 0 && std::isfinite(*tolerance)))
                throw invalid_input("tolerance must be positive and finite, got " + detail::num(*tolerance));
            intersection_result<D, T> r;
            {
                py::gil_scoped_release nogil;
                r = find_intersections(cr, T(tolerance.value_or(0)));
            }
            return to_dict(r, cr.grid());
        });
    }, py::arg("tolerance") = py::none(), "Self-intersections of the whole curve, as a dict of arrays.");

    cls.def("certify_intersection_free", [](const curve& c, double safe_angle, bool search_on_failure,
                                            std::optional<double> tolerance) {
        return c.visit([&](const auto& cr) -> py::dict {
            using T = scalar_t<decltype(cr)>;
            constexpr std::size_t D = dimension_v<decltype(cr)>;
            if (tolerance && !(*tolerance > 0 && std::isfinite(*tolerance)))
                throw invalid_input("tolerance must be positive and finite, got " + detail::num(*tolerance));
            certify_options opt;
            opt.safe_angle = safe_angle;
            opt.search_on_failure = search_on_failure;
            opt.tolerance = tolerance.value_or(0);
            certificate<D, T> r;
            {
                py::gil_scoped_release nogil;
                r = certify_intersection_free(cr, opt);
            }
            py::dict d;
            d["certified"] = r.certified;
            d["failed_rule"] = to_string(r.failed_rule);
            d["vertex"] = optional_index(r.vertex);
            d["segment"] = optional_index(r.segment);
            d["segments"] = r.segments ? py::object(py::make_tuple((*r.segments)[0], (*r.segments)[1]))
                                       : py::object(py::none());
            d["angle"] = double(r.angle);
            d["detail"] = r.detail;
            d["intersects"] = r.intersects ? py::object(py::bool_(*r.intersects)) : py::object(py::none());
            d["search"] = r.intersects ? py::object(to_dict(r.search, cr.grid())) : py::object(py::none());
            return d;
        });
    }, py::arg("safe_angle") = safe_adjacent_angle, py::arg("search_on_failure") = true,
       py::arg("tolerance") = py::none(), "Section 5's certificate that the curve does not intersect itself.");
}

}  // namespace crspline::python
