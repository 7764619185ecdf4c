// crspline Python module: sweeps and strokes (crspline/sweep.hpp,
// crspline/stroke.hpp, issue 41). The Python API is crspline/_sweep.py; the
// core validates every option and names the field.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <crspline/stroke.hpp>
#include <crspline/sweep.hpp>

#include "curve.hpp"

namespace crspline::python {

namespace {

std::vector<vec<2>> points2(const std::optional<py::array>& a, const char* field) {
    std::vector<vec<2>> out;
    if (!a) return out;
    auto p = contiguous<double>(*a);
    if (p.ndim() != 2 || p.shape(1) != 2)
        throw spec_error(field, std::nullopt, std::nullopt, "",
                         std::string(field) + ": expected an (n, 2) array of profile points");
    for (py::ssize_t k = 0; k < p.shape(0); ++k) out.push_back({{p.at(k, 0), p.at(k, 1)}});
    return out;
}

template <class T>
py::array_t<T> matrix(const std::vector<T>& v, std::size_t cols) {
    py::array_t<T> a({py::ssize_t(v.size() / cols), py::ssize_t(cols)});
    std::copy(v.begin(), v.end(), a.mutable_data());
    return a;
}

py::dict report_dict(const sweep_report& r) {
    py::dict d;
    d["tolerance"] = r.tolerance;
    d["bound"] = r.bound;
    d["tolerance_met"] = r.tolerance_met;
    d["proved"] = r.proved;
    d["holonomy"] = r.holonomy;
    d["frame_drift"] = r.frame_drift;
    d["length"] = r.length;
    d["largest_radius"] = r.largest_radius;
    d["clearance"] = r.clearance;
    d["min_radius_of_curvature"] = r.min_radius_of_curvature;
    d["far_contact"] = r.far_contact;
    d["local_fold"] = r.local_fold;
    d["self_intersects"] = r.self_intersects;
    d["seam_gap"] = r.seam_gap;
    d["seam_normal_gap"] = r.seam_normal_gap;
    return d;
}

template <class C>
const catmull_rom<dimension_v<C>>& as_double(const C& cr, const char* what) {
    if constexpr (!std::is_same_v<scalar_t<C>, double>) {
        throw invalid_input(std::string("curve: ") + what + " works in float64; build the curve from float64 points");
    } else {
        return cr;
    }
}

}  // namespace

void bind_sweep(py::module_& m) {
    m.def("_sweep",
          [](const curve& c, const std::string& profile_kind, double radius, std::optional<py::array> profile_points,
             bool profile_closed, double profile_alpha, std::vector<double> roll, const std::string& roll_at,
             std::vector<double> roll_s, std::vector<double> scale, std::vector<double> scale_s,
             std::optional<std::vector<double>> up, double tolerance, std::size_t tubular, std::size_t radial,
             bool spread_holonomy, bool with_clearance) {
              sweep_options o;
              if (profile_kind == "circle") o.profile = sweep_profile::circle(radius);
              else if (profile_kind == "polyline") o.profile = sweep_profile::polyline(points2(profile_points, "profile"), profile_closed);
              else if (profile_kind == "curve") o.profile = sweep_profile::curve(points2(profile_points, "profile"), profile_closed, profile_alpha);
              else throw spec_error("profile", std::nullopt, std::nullopt, profile_kind, "profile: unknown kind '" + profile_kind + "'");
              o.roll = std::move(roll);
              if (roll_at == "arc_length") o.roll_at = roll_position::arc_length;
              else if (roll_at != "knots")
                  throw spec_error("roll_at", std::nullopt, std::nullopt, roll_at,
                                   "roll_at: must be 'knots' or 'arc_length', got '" + roll_at + "'");
              o.roll_s = std::move(roll_s);
              o.scale = std::move(scale);
              o.scale_s = std::move(scale_s);
              if (up) {
                  if (up->size() != 3)
                      throw spec_error("up", std::nullopt, std::nullopt, std::to_string(up->size()),
                                       "up: needs 3 coordinates, got " + std::to_string(up->size()));
                  o.up = vec<3>{{(*up)[0], (*up)[1], (*up)[2]}};
              }
              o.tolerance = tolerance;
              o.tubular_segments = tubular;
              o.radial_segments = radial;
              o.spread_holonomy = spread_holonomy;
              o.clearance = with_clearance;
              return c.visit([&](const auto& cr) -> py::dict {
                  constexpr std::size_t D = dimension_v<decltype(cr)>;
                  sweep_mesh mesh;
                  if constexpr (D != 3) {
                      throw spec_error("curve", std::nullopt, std::nullopt, std::to_string(D),
                                       "curve: sweep needs a 3-D curve, got a " + std::to_string(D) + "-D one");
                  } else {
                      const auto& c3 = as_double(cr, "sweep");
                      py::gil_scoped_release nogil;
                      mesh = sweep(c3, o);
                  }
                  py::dict d;
                  d["positions"] = matrix(mesh.positions, 3);
                  d["normals"] = matrix(mesh.normals, 3);
                  d["uvs"] = matrix(mesh.uvs, 2);
                  d["indices"] = matrix(mesh.indices, 3);
                  d["rings"] = mesh.rings;
                  d["ring_size"] = mesh.ring_size;
                  d["t"] = py::array_t<double>(py::ssize_t(mesh.t.size()), mesh.t.data());
                  d["s"] = py::array_t<double>(py::ssize_t(mesh.s.size()), mesh.s.data());
                  d["report"] = report_dict(mesh.report);
                  return d;
              });
          },
          py::arg("curve"), py::arg("profile_kind"), py::arg("radius"), py::arg("profile_points"),
          py::arg("profile_closed"), py::arg("profile_alpha"), py::arg("roll"), py::arg("roll_at"), py::arg("roll_s"),
          py::arg("scale"), py::arg("scale_s"), py::arg("up"), py::arg("tolerance"), py::arg("tubular_segments"),
          py::arg("radial_segments"), py::arg("spread_holonomy"), py::arg("clearance"),
          "The sweep of a profile along a 3-D curve (crspline/sweep.hpp); crspline.sweep is the API.");

    m.def("_stroke",
          [](const curve& c, double width, const std::string& join, const std::string& cap, double miter_limit,
             double tolerance) {
              stroke_options o;
              if (join == "round") o.join = stroke_join::round;
              else if (join == "miter") o.join = stroke_join::miter;
              else if (join == "bevel") o.join = stroke_join::bevel;
              else throw spec_error("join", std::nullopt, std::nullopt, join, "join: must be 'round', 'miter' or 'bevel', got '" + join + "'");
              if (cap == "butt") o.cap = stroke_cap::butt;
              else if (cap == "round") o.cap = stroke_cap::round;
              else if (cap == "square") o.cap = stroke_cap::square;
              else throw spec_error("cap", std::nullopt, std::nullopt, cap, "cap: must be 'butt', 'round' or 'square', got '" + cap + "'");
              o.miter_limit = miter_limit;
              o.tolerance = tolerance;
              return c.visit([&](const auto& cr) -> py::tuple {
                  constexpr std::size_t D = dimension_v<decltype(cr)>;
                  stroke_result r;
                  if constexpr (D != 2) {
                      throw spec_error("curve", std::nullopt, std::nullopt, std::to_string(D),
                                       "curve: stroke needs a 2-D curve, got a " + std::to_string(D) + "-D one");
                  } else {
                      const auto& c2 = as_double(cr, "stroke");
                      py::gil_scoped_release nogil;
                      r = stroke(c2, width, o);
                  }
                  py::list polys;
                  for (const auto& p : r.polygons) {
                      py::list rings;
                      rings.append(points_array<2, double>(p.exterior));
                      for (const auto& h : p.holes) rings.append(points_array<2, double>(h));
                      polys.append(rings);
                  }
                  return py::make_tuple(polys, r.tolerance, r.tessellation_vertices);
              });
          },
          py::arg("curve"), py::arg("width"), py::arg("join"), py::arg("cap"), py::arg("miter_limit"),
          py::arg("tolerance"), "The stroke of a 2-D curve (crspline/stroke.hpp); crspline.stroke is the API.");
}

}  // namespace crspline::python
