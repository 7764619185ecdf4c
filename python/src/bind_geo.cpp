// crspline Python module: GIS smoothing (crspline/geo/smooth.hpp) over flat
// NumPy arrays. crspline.geo (pure Python) turns GeoPandas/Shapely
// geometries into these arrays part by part (no loop over vertices in
// Python) and back; here the arrays are copied into a geo::layer, the GIL
// is released while the core works, and the result comes back as arrays.
#include <algorithm>
#include <array>
#include <cmath>
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

// The vector's values as a NumPy array of the given shape without a copy:
// the array owns the vector (moved to the heap, freed with the array). At
// 10^6 lines the output polylines are 1.7 GB: a copy was as many fresh
// pages again, zeroed by the kernel, and the time per line grew with them.
template <class T>
py::array_t<T> adopt_numpy(std::vector<T>&& v, std::vector<py::ssize_t> shape) {
    auto* owned = new std::vector<T>(std::move(v));
    py::capsule free_it(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
    return py::array_t<T>(shape, owned->data(), free_it);
}

py::dict geo_smooth(carray<double> xy, carray<double> extra, carray<std::int64_t> part_offsets,
                    carray<std::uint8_t> part_kinds, carray<std::int64_t> part_features, std::size_t feature_count,
                    double alpha, double tolerance, std::optional<double> max_deviation, bool preserve_topology,
                    std::optional<std::array<double, 4>> domain, bool polylines,
                    std::optional<carray<std::uint8_t>> part_roles, std::optional<double> fit) {
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
    l.part_offsets.reserve(std::size_t(part_offsets.size()));
    l.part_kinds.reserve(std::size_t(part_kinds.size()));
    l.part_features.reserve(std::size_t(part_features.size()));
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
    if (part_roles)
        for (py::ssize_t i = 0; i < part_roles->size(); ++i) l.part_roles.push_back(geo::ring_role(part_roles->data()[i]));
    geo::smooth_options opt;
    opt.alpha = alpha;
    opt.tolerance = tolerance;
    opt.max_deviation = max_deviation;
    opt.preserve_topology = preserve_topology;
    opt.polylines = polylines;
    opt.fit = fit;
    if (domain) opt.domain = box<2>{vec<2>{{(*domain)[0], (*domain)[1]}}, vec<2>{{(*domain)[2], (*domain)[3]}}};
    geo::smooth_result r;
    {
        py::gil_scoped_release release;
        r = geo::smooth(std::move(l), opt);  // measures only: the output takes the input's arrays
        l = {};  // the input's copy, before the output's
    }
    auto& o = r.output;
    const std::size_t out_vertices = o.vertex_count();
    const auto extra_dims = py::ssize_t(o.extra_dims);
    // The output's coordinates and extra values handed over, not copied.
    py::array_t<double> oxy = adopt_numpy(std::move(o.xy), {py::ssize_t(out_vertices), py::ssize_t(2)});
    py::array_t<double> oextra = adopt_numpy(std::move(o.extra), {py::ssize_t(out_vertices), extra_dims});
    std::vector<std::int64_t> offs(o.part_offsets.begin(), o.part_offsets.end());
    const std::size_t nf = r.features.size();
    std::vector<std::uint8_t> status(nf), verdict(nf);
    std::vector<double> length(nf), deviation(nf);
    std::vector<std::int64_t> control_points(nf);
    py::list messages(nf);
    for (std::size_t i = 0; i < nf; ++i) {
        const auto& f = r.features[i];
        control_points[i] = std::int64_t(f.control_points);
        status[i] = std::uint8_t(f.status);
        verdict[i] = std::uint8_t(f.verdict);
        length[i] = f.length;
        deviation[i] = f.max_deviation;
        messages[i] = py::str(f.message);
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
    stats["swept_vertices"] = r.stats.swept_vertices;
    stats["restored_vertices"] = r.stats.restored_vertices;
    py::dict d;
    d["xy"] = oxy;
    d["extra"] = oextra;
    d["part_offsets"] = to_numpy(offs);
    d["status"] = to_numpy(status);
    d["verdict"] = to_numpy(verdict);
    d["length"] = to_numpy(length);
    d["max_deviation"] = to_numpy(deviation);
    d["control_points"] = to_numpy(control_points);
    d["message"] = messages;
    d["stats"] = stats;
    return d;
}


// --- The arc-wise pipeline of crspline.geo.dask -----------------------------
// crspline.geo.dask spreads geo::smooth over a cluster: each partition cleans
// its parts (geo_clean), the layer's junctions and arcs are found by shuffles
// keyed by vertex and by arc, and each group of arcs that may meet is
// smoothed by geo_smooth_arcs. These are steps 1 and 3-4 of geo::smooth
// (crspline/geo/smooth.hpp) on the same data, with the layer-wide rounding
// slack passed in, so the numbers are the same to the bit.

// Step 1 of geo::smooth: per feature invalid / empty / degenerate, per part
// the cleaned vertices (no consecutive repeats, a ring without its closing
// repeat). Returns the statuses and messages and the clean parts as layer
// vertex indices.
py::dict geo_clean(carray<double> xy, carray<std::int64_t> part_offsets, carray<std::uint8_t> part_kinds,
                   carray<std::int64_t> part_features, std::size_t feature_count,
                   std::optional<carray<std::uint8_t>> part_roles) {
    if (xy.ndim() != 2 || xy.shape(1) != 2)
        throw crspline::invalid_input("xy must have shape (n, 2), got ndim " + std::to_string(xy.ndim()));
    const std::size_t nparts = std::size_t(part_kinds.size());
    if (std::size_t(part_offsets.size()) != nparts + 1 || std::size_t(part_features.size()) != nparts)
        throw crspline::invalid_input("part_offsets must have one value more than part_kinds, part_features as many");
    const double* p = xy.data();
    const std::int64_t* off = part_offsets.data();
    const std::int64_t* feat = part_features.data();
    for (std::size_t q = 0; q < nparts; ++q)
        if (off[q] < 0 || off[q + 1] < off[q] || off[q + 1] > xy.shape(0) || feat[q] < 0 ||
            std::size_t(feat[q]) >= feature_count)
            throw crspline::invalid_input("part " + std::to_string(q) + ": offsets or feature out of range");
    std::vector<std::uint8_t> status(feature_count, std::uint8_t(geo::feature_status::ok));
    std::vector<std::string> message(feature_count);
    std::vector<std::size_t> feature_vertices(feature_count, 0), part_index(nparts, 0), count(feature_count, 0);
    const auto invalid = std::uint8_t(geo::feature_status::invalid);
    for (std::size_t q = 0; q < nparts; ++q) {
        const std::size_t f = std::size_t(feat[q]);
        part_index[q] = count[f]++;
        feature_vertices[f] += std::size_t(off[q + 1] - off[q]);
        if (status[f] == invalid) continue;
        for (std::size_t v = std::size_t(off[q]); v < std::size_t(off[q + 1]); ++v)
            for (std::size_t k = 0; k < 2; ++k)
                if (!std::isfinite(p[2 * v + k])) {
                    status[f] = invalid;
                    message[f] = "part " + std::to_string(part_index[q]) + " vertex " +
                                 std::to_string(v - std::size_t(off[q])) + ": " + (k ? "y" : "x") + " is " +
                                 crspline::detail::num(p[2 * v + k]);
                    v = std::size_t(off[q + 1]) - 1;
                    break;
                }
    }
    for (std::size_t f = 0; f < feature_count; ++f)
        if (feature_vertices[f] == 0) {
            status[f] = std::uint8_t(geo::feature_status::empty);
            message[f] = "no vertices";
        }
    std::vector<std::int64_t> verts, offsets{0}, parts, features;
    std::vector<std::uint8_t> rings;
    for (std::size_t q = 0; q < nparts; ++q) {
        const std::size_t f = std::size_t(feat[q]);
        if (status[f] == invalid || off[q + 1] == off[q]) continue;
        const bool ring = geo::part_kind(part_kinds.data()[q]) == geo::part_kind::ring;
        std::vector<std::array<double, 2>> pts;
        std::vector<std::int64_t> src;
        for (std::size_t v = std::size_t(off[q]); v < std::size_t(off[q + 1]); ++v) {
            const std::array<double, 2> pt{p[2 * v], p[2 * v + 1]};
            if (!pts.empty() && pts.back() == pt) continue;
            pts.push_back(pt);
            src.push_back(std::int64_t(v));
        }
        if (ring && pts.size() > 1 && pts.back() == pts.front()) {
            pts.pop_back();
            src.pop_back();
        }
        const std::size_t need = ring ? 3 : 2;
        std::vector<std::array<double, 2>> seen;
        for (const auto& s : pts) {
            if (seen.size() == need) break;
            if (std::find(seen.begin(), seen.end(), s) == seen.end()) seen.push_back(s);
        }
        const std::size_t distinct = seen.size();
        if (distinct < need) {
            status[f] = std::uint8_t(geo::feature_status::degenerate);
            message[f] = "part " + std::to_string(part_index[q]) + " (" + (ring ? "ring" : "line") + ") has " +
                         std::to_string(distinct) + " distinct point" + (distinct == 1 ? "" : "s") + ", a " +
                         (ring ? "ring" : "line") + " needs " + std::to_string(need) + ": passed through unchanged";
            continue;
        }
        verts.insert(verts.end(), src.begin(), src.end());
        offsets.push_back(std::int64_t(verts.size()));
        parts.push_back(std::int64_t(q));
        features.push_back(std::int64_t(f));
        rings.push_back(ring ? 1 : 0);
    }
    // Invalid nesting of each feature's rings (geo/nesting.hpp), as
    // geo::smooth finds it for the verdicts: on the features whose status
    // is ok.
    py::list nesting;
    {
        std::vector<std::string> found(feature_count);
        if (part_roles && part_roles->size() > 0) {
            if (std::size_t(part_roles->size()) != nparts)
                throw crspline::invalid_input("part_roles must have one value per part");
            geo::layer l;
            l.xy.assign(p, p + 2 * std::size_t(xy.shape(0)));
            l.part_offsets.assign(off, off + nparts + 1);
            for (std::size_t q = 0; q < nparts; ++q) {
                l.part_kinds.push_back(geo::part_kind(part_kinds.data()[q]));
                l.part_features.push_back(std::size_t(feat[q]));
                l.part_roles.push_back(geo::ring_role(part_roles->data()[q]));
            }
            l.feature_count = feature_count;
            geo::check_layer(l);
            std::vector<bool> skip(feature_count);
            for (std::size_t f = 0; f < feature_count; ++f) skip[f] = status[f] != std::uint8_t(geo::feature_status::ok);
            found = geo::find_nesting(l, skip);
        }
        for (const auto& m : found) nesting.append(m);
    }
    py::list messages;
    for (const auto& m : message) messages.append(m);
    py::dict d;
    d["nesting"] = nesting;
    d["status"] = to_numpy(status);
    d["message"] = messages;
    d["vertices"] = to_numpy(verts);
    d["offsets"] = to_numpy(offsets);
    d["parts"] = to_numpy(parts);
    d["features"] = to_numpy(features);
    d["rings"] = to_numpy(rings);
    return d;
}

// Arcs given as flat arrays (xy (n, 2), offsets, closed flags), as
// geo::smooth's step 2 would have made them.
std::vector<geo::detail::arc_work> arcs_of(const carray<double>& xy, const carray<std::int64_t>& offsets,
                                           const carray<std::uint8_t>& closed) {
    using geo::detail::p2;
    if (xy.ndim() != 2 || xy.shape(1) != 2)
        throw crspline::invalid_input("xy must have shape (n, 2), got ndim " + std::to_string(xy.ndim()));
    const std::size_t n = std::size_t(closed.size());
    if (std::size_t(offsets.size()) != n + 1)
        throw crspline::invalid_input("offsets must have one value more than closed (" + std::to_string(n) + ")");
    std::vector<geo::detail::arc_work> arcs(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto a0 = offsets.data()[i], a1 = offsets.data()[i + 1];
        auto& a = arcs[i];
        a.closed = closed.data()[i] != 0;
        if (a0 < 0 || a1 > xy.shape(0) || a1 - a0 < (a.closed ? 3 : 2))
            throw crspline::invalid_input("arc " + std::to_string(i) + ": vertices [" + std::to_string(a0) + ", " +
                                          std::to_string(a1) + ") out of range or too few");
        for (auto v = a0; v < a1; ++v) a.pts.push_back(p2{{xy.data()[2 * v], xy.data()[2 * v + 1]}});
        a.level.assign(a.pts.size(), a.pts.size() == 2 && !a.closed ? geo::detail::linear_level : 0);
        a.raise.assign(a.segments(), 0);
    }
    return arcs;
}

// Per arc, the box of the Bézier points of its untensioned curve: every
// tension level's curve lies inside it (a tensioned segment's inner Bézier
// points are on the segments from its ends to the untensioned ones).
py::array_t<double> geo_arc_boxes(carray<double> xy, carray<std::int64_t> offsets, carray<std::uint8_t> closed,
                                  double alpha, bool fit) {
    auto arcs = arcs_of(xy, offsets, closed);
    py::array_t<double> out({py::ssize_t(arcs.size()), py::ssize_t(4)});
    double* o = out.mutable_data();
    {
        py::gil_scoped_release release;
        for (std::size_t i = 0; i < arcs.size(); ++i) {
            auto& a = arcs[i];
            box<2> b = box<2>::of(a.pts[0]);
            if (fit) {
                // A fitted arc's curves at every round (detail::fitted_bounds).
                b = geo::detail::fitted_bounds(std::span<const geo::detail::p2>(a.pts));
            } else {
                options<2> opt;
                opt.alpha = alpha;
                opt.closed = a.closed;
                const catmull_rom<2> c(std::span<const geo::detail::p2>(a.pts), opt);
                for (std::size_t s = 0; s < c.segment_count(); ++s)
                    for (const auto& q : c.bezier(s)) b.expand(q);
            }
            o[4 * i] = b.lo[0];
            o[4 * i + 1] = b.lo[1];
            o[4 * i + 2] = b.hi[0];
            o[4 * i + 3] = b.hi[1];
        }
    }
    return out;
}

// Steps 3 and 4 of geo::smooth (the rounds of tension and proof, the arc
// lengths) on a group of arcs that no arc outside can meet at any tension
// (crspline.geo.dask groups them so, with boxes from geo_arc_boxes), with
// the layer's rounding slack: the core's own proof (detail::proof), so the
// numbers are the single-process ones.
py::dict geo_smooth_arcs(carray<double> xy, carray<std::int64_t> offsets, carray<std::uint8_t> closed, double alpha,
                         double tolerance, std::optional<double> max_deviation, bool preserve_topology,
                         std::optional<std::array<double, 4>> domain_box, double slack, std::optional<double> fit) {
    if (!(alpha >= 0 && alpha <= 1))
        throw crspline::invalid_input("alpha must be in [0, 1], got " + crspline::detail::num(alpha));
    if (!(tolerance > 0 && std::isfinite(tolerance)))
        throw crspline::invalid_input("tolerance must be positive and finite, got " + crspline::detail::num(tolerance));
    if (!(slack >= 0 && std::isfinite(slack)))
        throw crspline::invalid_input("slack must be non-negative and finite, got " + crspline::detail::num(slack));
    auto arcs = arcs_of(xy, offsets, closed);
    geo::smooth_options opt;
    opt.alpha = alpha;
    opt.tolerance = tolerance;
    opt.max_deviation = max_deviation;
    opt.preserve_topology = preserve_topology;
    opt.fit = fit;
    if (domain_box)
        opt.domain = box<2>{vec<2>{{(*domain_box)[0], (*domain_box)[1]}}, vec<2>{{(*domain_box)[2], (*domain_box)[3]}}};
    std::vector<std::uint8_t> arc_crossing;
    std::size_t rounds = 0;
    {
        py::gil_scoped_release release;
        // Each arc fitted alone, as geo::smooth does (the layer's checks of
        // the fit distance were made there: crspline.geo.dask checks first).
        if (fit)
            for (auto& a : arcs) geo::detail::fit_arc(a, alpha, *fit);
        geo::detail::proof pr{arcs, opt, slack};
        pr.run();
        arc_crossing = pr.crossing;
        rounds = pr.rounds;
    }
    // Lengths (step 4) and the polylines, knots exact.
    std::vector<double> length(arcs.size(), 0), dev(arcs.size(), 0), vu;
    std::vector<std::int64_t> line_offsets{0}, vseg, vnext, control(arcs.size(), 0);
    std::vector<double> line;
    for (std::size_t i = 0; i < arcs.size(); ++i) {
        auto& a = arcs[i];
        length[i] = geo::detail::arc_curve_length(a);  // as geo::smooth's step 4
        dev[i] = a.max_dev;
        control[i] = std::int64_t(a.pts.size());
        for (std::size_t k = 0; k < a.line.points.size(); ++k) {
            line.push_back(a.line.points[k][0]);
            line.push_back(a.line.points[k][1]);
            // The arc vertices the polyline vertex lies between (a fitted
            // arc's control points are some of its vertices).
            const std::size_t s = a.vseg[k];
            vseg.push_back(std::int64_t(a.fitted() ? a.src[s] % a.full.size() : s));
            vnext.push_back(std::int64_t(a.fitted() ? a.src[a.next(s)] % a.full.size() : a.next(s)));
            vu.push_back(a.vu[k]);
        }
        line_offsets.push_back(std::int64_t(vseg.size()));
    }
    py::array_t<double> lxy({py::ssize_t(vseg.size()), py::ssize_t(2)});
    if (!line.empty()) std::copy(line.begin(), line.end(), lxy.mutable_data());
    py::dict d;
    d["xy"] = lxy;
    d["offsets"] = to_numpy(line_offsets);
    d["vseg"] = to_numpy(vseg);
    d["vnext"] = to_numpy(vnext);
    d["control_points"] = to_numpy(control);
    d["vu"] = to_numpy(vu);
    d["length"] = to_numpy(length);
    d["max_deviation"] = to_numpy(dev);
    d["crossing"] = to_numpy(arc_crossing);
    d["rounds"] = rounds;
    return d;
}

}  // namespace

void bind_geo(py::module_& m) {
    m.def("_geo_smooth", &geo_smooth, py::arg("xy"), py::arg("extra"), py::arg("part_offsets"),
          py::arg("part_kinds"), py::arg("part_features"), py::arg("feature_count"), py::arg("alpha"),
          py::arg("tolerance"), py::arg("max_deviation"), py::arg("preserve_topology"), py::arg("domain") = py::none(),
          py::arg("polylines") = true, py::arg("part_roles") = py::none(), py::arg("fit") = py::none(),
          "Smooths a layer given as flat arrays (crspline/geo/smooth.hpp); private: use crspline.geo.smooth. "
          "polylines=False: the measures only, the input as output (smooth_options::polylines).");
    py::list statuses, verdicts;
    for (auto s : {geo::feature_status::ok, geo::feature_status::empty, geo::feature_status::degenerate,
                   geo::feature_status::invalid})
        statuses.append(geo::to_string(s));
    // Index = the verdict's value.
    for (auto v : {geo::verdict::simple, geo::verdict::touches, geo::verdict::nested, geo::verdict::crosses})
        verdicts.append(geo::to_string(v));
    m.def("_geo_clean", &geo_clean, py::arg("xy"), py::arg("part_offsets"), py::arg("part_kinds"),
          py::arg("part_features"), py::arg("feature_count"), py::arg("part_roles") = py::none(),
          "Step 1 of geo::smooth (statuses, cleaned parts); private: used by crspline.geo.dask.");
    m.def("_geo_arc_boxes", &geo_arc_boxes, py::arg("xy"), py::arg("offsets"), py::arg("closed"), py::arg("alpha"),
          py::arg("fit") = false,
          "Boxes holding every tension level's curve of each arc; private: used by crspline.geo.dask.");
    m.def("_geo_smooth_arcs", &geo_smooth_arcs, py::arg("xy"), py::arg("offsets"), py::arg("closed"),
          py::arg("alpha"), py::arg("tolerance"), py::arg("max_deviation"), py::arg("preserve_topology"),
          py::arg("domain"), py::arg("slack"), py::arg("fit") = py::none(),
          "Steps 3-4 of geo::smooth on a closed group of arcs; private: used by crspline.geo.dask.");
    m.attr("_geo_statuses") = statuses;
    m.attr("_geo_verdicts") = verdicts;
}

}  // namespace crspline::python
