// crspline Python module: GIS smoothing (crspline/geo/smooth.hpp) over flat
// NumPy arrays. crspline.geo (pure Python) turns GeoPandas/Shapely
// geometries into these arrays part by part (no loop over vertices in
// Python) and back; here the arrays are copied into a geo::layer, the GIL
// is released while the core works, and the result comes back as arrays.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <crspline/geo/smooth.hpp>

namespace py = pybind11;

namespace crspline::python {

namespace {

template <class T>
using carray = py::array_t<T, py::array::c_style | py::array::forcecast>;

template <class T>
py::array_t<T> to_numpy(const std::vector<T>& v) {
    py::array_t<T> a(py::ssize_t(v.size()));
    if (!v.empty()) std::copy(v.begin(), v.end(), a.mutable_data());
    return a;
}

py::dict geo_smooth(carray<double> xy, carray<double> extra, carray<std::int64_t> part_offsets,
                    carray<std::uint8_t> part_kinds, carray<std::int64_t> part_features, std::size_t feature_count,
                    double alpha, double tolerance, std::optional<double> max_deviation, bool preserve_topology,
                    std::optional<std::array<double, 4>> domain) {
    if (xy.ndim() != 2 || xy.shape(1) != 2)
        throw crspline::invalid_input("xy must have shape (n, 2), got ndim " + std::to_string(xy.ndim()));
    const std::size_t n = std::size_t(xy.shape(0));
    if (extra.ndim() != 2 || std::size_t(extra.shape(0)) != n)
        throw crspline::invalid_input("extra must have shape (n, k) with n = " + std::to_string(n) + " rows");
    geo::layer l;
    l.extra_dims = std::size_t(extra.shape(1));
    l.xy.assign(xy.data(), xy.data() + 2 * n);
    l.extra.assign(extra.data(), extra.data() + n * l.extra_dims);
    l.part_offsets.clear();
    for (py::ssize_t i = 0; i < part_offsets.size(); ++i) {
        const auto v = part_offsets.data()[i];
        if (v < 0) throw crspline::invalid_input("part_offsets[" + std::to_string(i) + "] is negative");
        l.part_offsets.push_back(std::size_t(v));
    }
    for (py::ssize_t i = 0; i < part_kinds.size(); ++i) l.part_kinds.push_back(geo::part_kind(part_kinds.data()[i]));
    for (py::ssize_t i = 0; i < part_features.size(); ++i) {
        const auto v = part_features.data()[i];
        if (v < 0) throw crspline::invalid_input("part_features[" + std::to_string(i) + "] is negative");
        l.part_features.push_back(std::size_t(v));
    }
    l.feature_count = feature_count;
    geo::smooth_options opt;
    opt.alpha = alpha;
    opt.tolerance = tolerance;
    opt.max_deviation = max_deviation;
    opt.preserve_topology = preserve_topology;
    if (domain) opt.domain = box<2>{vec<2>{{(*domain)[0], (*domain)[1]}}, vec<2>{{(*domain)[2], (*domain)[3]}}};
    geo::smooth_result r;
    {
        py::gil_scoped_release release;
        r = geo::smooth(l, opt);
    }
    const auto& o = r.output;
    py::array_t<double> oxy({py::ssize_t(o.vertex_count()), py::ssize_t(2)});
    if (!o.xy.empty()) std::copy(o.xy.begin(), o.xy.end(), oxy.mutable_data());
    py::array_t<double> oextra({py::ssize_t(o.vertex_count()), py::ssize_t(o.extra_dims)});
    if (!o.extra.empty()) std::copy(o.extra.begin(), o.extra.end(), oextra.mutable_data());
    std::vector<std::int64_t> offs(o.part_offsets.begin(), o.part_offsets.end());
    std::vector<std::uint8_t> status, verdict;
    std::vector<double> length, deviation;
    py::list messages;
    for (const auto& f : r.features) {
        status.push_back(std::uint8_t(f.status));
        verdict.push_back(std::uint8_t(f.verdict));
        length.push_back(f.length);
        deviation.push_back(f.max_deviation);
        messages.append(f.message);
    }
    py::dict stats;
    stats["arcs"] = r.stats.arcs;
    stats["shared_arcs"] = r.stats.shared_arcs;
    stats["junctions"] = r.stats.junctions;
    stats["rounds"] = r.stats.rounds;
    stats["tensioned_vertices"] = r.stats.tensioned_vertices;
    stats["linear_segments"] = r.stats.linear_segments;
    stats["pieces"] = r.stats.pieces;
    stats["pairs_checked"] = r.stats.pairs_checked;
    stats["input_crossings"] = r.stats.input_crossings;
    stats["input_touches"] = r.stats.input_touches;
    py::dict d;
    d["xy"] = oxy;
    d["extra"] = oextra;
    d["part_offsets"] = to_numpy(offs);
    d["status"] = to_numpy(status);
    d["verdict"] = to_numpy(verdict);
    d["length"] = to_numpy(length);
    d["max_deviation"] = to_numpy(deviation);
    d["message"] = messages;
    d["stats"] = stats;
    return d;
}

}  // namespace

void bind_geo(py::module_& m) {
    m.def("_geo_smooth", &geo_smooth, py::arg("xy"), py::arg("extra"), py::arg("part_offsets"),
          py::arg("part_kinds"), py::arg("part_features"), py::arg("feature_count"), py::arg("alpha"),
          py::arg("tolerance"), py::arg("max_deviation"), py::arg("preserve_topology"), py::arg("domain") = py::none(),
          "Smooths a layer given as flat arrays (crspline/geo/smooth.hpp); private: use crspline.geo.smooth.");
    py::list statuses, verdicts;
    for (auto s : {geo::feature_status::ok, geo::feature_status::empty, geo::feature_status::degenerate,
                   geo::feature_status::invalid})
        statuses.append(geo::to_string(s));
    for (auto v : {geo::verdict::simple, geo::verdict::touches, geo::verdict::crosses}) verdicts.append(geo::to_string(v));
    m.attr("_geo_statuses") = statuses;
    m.attr("_geo_verdicts") = verdicts;
}

}  // namespace crspline::python
