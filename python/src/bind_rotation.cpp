// crspline Python module: rotation and pose splines (include/crspline/rotation/),
// the compiled part of crspline.rotation and crspline.splines.quaternion.
// Quaternions cross the boundary as float64 arrays of rows [w, x, y, z].
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <limits>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <crspline/rotation/angle_length.hpp>
#include <crspline/rotation/c2.hpp>
#include <crspline/rotation/catmull_rom.hpp>
#include <crspline/rotation/fit.hpp>
#include <crspline/rotation/pose.hpp>

namespace py = pybind11;

namespace crspline::python {

namespace {

using namespace crspline::rotation;
using quat = quaternion<double>;
using v3 = vec3<double>;
using farray = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::vector<quat> to_quats(const farray& a, const char* what) {
    if (a.ndim() != 2 || a.shape(1) != 4)
        throw invalid_input(std::string(what) + " must have shape (n, 4), rows [w, x, y, z]; got " + std::to_string(a.ndim()) +
                            " dimensions" + (a.ndim() == 2 ? " and " + std::to_string(a.shape(1)) + " columns" : ""));
    std::vector<quat> q(std::size_t(a.shape(0)));
    const double* p = a.data();
    for (std::size_t i = 0; i < q.size(); ++i) q[i] = {p[4 * i], p[4 * i + 1], p[4 * i + 2], p[4 * i + 3]};
    return q;
}

farray from_quats(const std::vector<quat>& q) {
    farray a({py::ssize_t(q.size()), py::ssize_t(4)});
    double* p = a.mutable_data();
    for (std::size_t i = 0; i < q.size(); ++i) p[4 * i] = q[i].w, p[4 * i + 1] = q[i].x, p[4 * i + 2] = q[i].y, p[4 * i + 3] = q[i].z;
    return a;
}

std::vector<double> to_vector(const farray& a) { return std::vector<double>(a.data(), a.data() + a.size()); }

v3 to_v3(const farray& a, const char* what) {
    if (a.size() != 3) throw invalid_input(std::string(what) + " must be a 3-vector, got " + std::to_string(a.size()) + " values");
    return v3{{a.data()[0], a.data()[1], a.data()[2]}};
}

frame to_frame(const std::string& f) {
    if (f == "world") return frame::world;
    if (f == "body") return frame::body;
    throw invalid_input("frame must be 'world' or 'body', got '" + f + "'");
}

/// Evaluates a rotation curve at every t, each on the segment given for it
/// (evaluate_on: one-sided at knots, extrapolating outside the segment):
/// (q (m, 4), omega (m, 3) or None, alpha (m, 3) or None).
template <class Curve>
py::tuple evaluate_on_many(const Curve& c, const farray& t, const py::array_t<long long>& seg, int order,
                           const std::string& frame_name) {
    if (order < 0 || order > 2) throw invalid_input("derivative order must be 0, 1 or 2, got " + std::to_string(order));
    const frame f = to_frame(frame_name);
    const std::size_t m = std::size_t(t.size());
    if (std::size_t(seg.size()) != m) throw invalid_input("segments and t differ in length");
    const long long* sp = seg.data();
    for (std::size_t k = 0; k < m; ++k)
        if (sp[k] < 0 || std::size_t(sp[k]) >= c.segment_count())
            throw invalid_input("segment index " + std::to_string(sp[k]) + " (index " + std::to_string(k) +
                                ") is out of range (the curve has " + std::to_string(c.segment_count()) + " segments)");
    farray q({py::ssize_t(m), py::ssize_t(4)}), w({py::ssize_t(m), py::ssize_t(3)}), a({py::ssize_t(m), py::ssize_t(3)});
    const double* tp = t.data();
    double *qp = q.mutable_data(), *wp = w.mutable_data(), *ap = a.mutable_data();
    {
        py::gil_scoped_release release;
        for (std::size_t k = 0; k < m; ++k) {
            const auto j = c.evaluate_on(std::size_t(sp[k]), tp[k], order, f);
            qp[4 * k] = j.q.w, qp[4 * k + 1] = j.q.x, qp[4 * k + 2] = j.q.y, qp[4 * k + 3] = j.q.z;
            for (std::size_t d = 0; d < 3; ++d) wp[3 * k + d] = j.omega[d], ap[3 * k + d] = j.alpha[d];
        }
    }
    return py::make_tuple(q, order >= 1 ? py::object(w) : py::object(py::none()), order >= 2 ? py::object(a) : py::object(py::none()));
}

/// Evaluates a rotation curve at every t through its batch kernels
/// (batch.hpp), the GIL released: (q (m, 4) or None, omega (m, 3) or None,
/// alpha (m, 3) or None); q as rows [x, y, z, w] with xyzw (SciPy's order).
/// Only the arrays the order asks for are made, and q only with rotations
/// (SciPy's spline(t, 1) wants the rates alone).
template <class Curve, class... Extra>
py::tuple evaluate_many(const Curve& c, const farray& t, int order, const std::string& frame_name, bool xyzw,
                        bool rotations, Extra... extra) {
    if (order < 0 || order > 2) throw invalid_input("derivative order must be 0, 1 or 2, got " + std::to_string(order));
    const frame f = to_frame(frame_name);
    const auto m = py::ssize_t(t.size());
    py::object qo = py::none();
    py::object w = py::none(), a = py::none();
    batch_rows<double> rows;
    rows.xyzw = xyzw;
    if (rotations || order == 0) {
        farray q({m, py::ssize_t(4)});
        rows.q = q.mutable_data();
        qo = q;
    }
    if (order >= 1) {
        farray x({m, py::ssize_t(3)});
        rows.omega = x.mutable_data();
        w = x;
    }
    if (order >= 2) {
        farray x({m, py::ssize_t(3)});
        rows.alpha = x.mutable_data();
        a = x;
    }
    const std::span<const double> ts(t.data(), std::size_t(m));
    {
        py::gil_scoped_release release;
        c.evaluate(ts, rows, order, f, extra...);
    }
    return py::make_tuple(qo, w, a);
}

spline_kind to_kind(const std::string& k) {
    if (k == "catmull_rom") return spline_kind::catmull_rom;
    if (k == "kochanek_bartels") return spline_kind::kochanek_bartels;
    if (k == "piecewise_slerp") return spline_kind::piecewise_slerp;
    if (k == "barry_goldman") return spline_kind::barry_goldman;
    if (k == "squad") return spline_kind::squad;
    throw invalid_input("kind must be one of 'catmull_rom', 'kochanek_bartels', 'piecewise_slerp', 'barry_goldman', "
                        "'squad', got '" + k + "'");
}

rotation_end<double> to_end(const py::object& e, const std::string& frame_name, const char* which) {
    if (py::isinstance<py::str>(e)) {
        const auto s = e.cast<std::string>();
        if (s == "natural") return rotation_end<double>::natural();
        if (s == "natural_splines") return rotation_end<double>::natural_splines();
        throw invalid_input(std::string(which) + " must be 'natural', 'natural_splines' or an angular velocity (3-vector), got '" + s + "'");
    }
    return rotation_end<double>::velocity(to_v3(e.cast<farray>(), which), to_frame(frame_name));
}

c2_end<double> to_c2_end(const py::object& e, const std::string& frame_name, const char* which) {
    if (py::isinstance<py::str>(e)) {
        const auto s = e.cast<std::string>();
        if (s == "scipy") return c2_end<double>::scipy();
        if (s == "natural") return c2_end<double>::natural();
        throw invalid_input(std::string(which) + " must be 'scipy', 'natural' or an angular velocity (3-vector), got '" + s + "'");
    }
    return c2_end<double>::velocity(to_v3(e.cast<farray>(), which), to_frame(frame_name));
}

template <class Curve>
farray angle_times(const Curve& c, std::size_t n, double accuracy) {
    const auto t = constant_angular_speed_times(c, n, accuracy);
    farray out(py::ssize_t(t.size()));
    std::copy(t.begin(), t.end(), out.mutable_data());
    return out;
}

farray grid_of(std::span<const double> g) {
    farray out(py::ssize_t(g.size()));
    std::copy(g.begin(), g.end(), out.mutable_data());
    return out;
}

}  // namespace

void bind_rotation(py::module_& m) {
    using QS = quaternion_spline<double>;
    py::class_<QS>(m, "_QuaternionSpline", "A rotation spline on unit quaternions (crspline::rotation::quaternion_spline).")
        .def(py::init([](const farray& keys, const std::string& kind, bool closed, std::optional<double> alpha,
                         std::optional<farray> grid, const py::object& start, const py::object& end,
                         const std::string& velocity_frame, std::optional<farray> tcb, bool keep_signs, bool strict,
                         double unit_tolerance) {
                 rotation_options<double> o;
                 o.kind = to_kind(kind);
                 o.closed = closed;
                 o.alpha = alpha;
                 if (grid) o.grid = to_vector(*grid);
                 o.start = to_end(start, velocity_frame, "start");
                 o.end = to_end(end, velocity_frame, "end");
                 if (tcb) {
                     if (tcb->size() % 3 != 0) throw invalid_input("tcb must be triples (tension, continuity, bias)");
                     for (py::ssize_t i = 0; i < tcb->size() / 3; ++i)
                         o.kb.push_back({tcb->data()[3 * i], tcb->data()[3 * i + 1], tcb->data()[3 * i + 2]});
                 }
                 o.keep_signs = keep_signs, o.strict = strict, o.unit_tolerance = unit_tolerance;
                 const auto q = to_quats(keys, "keys");
                 return QS(q, o);
             }),
             py::arg("keys"), py::arg("kind") = "catmull_rom", py::arg("closed") = false, py::arg("alpha") = py::none(),
             py::arg("grid") = py::none(), py::arg("start") = "natural", py::arg("end") = "natural",
             py::arg("velocity_frame") = "world", py::arg("tcb") = py::none(), py::arg("keep_signs") = false,
             py::arg("strict") = false, py::arg("unit_tolerance") = 1e-6)
        .def_static(
            "de_casteljau",
            [](const std::vector<farray>& segments, std::optional<farray> grid) {
                std::vector<std::vector<quat>> s;
                for (const auto& a : segments) s.push_back(to_quats(a, "segment"));
                std::optional<std::vector<double>> g;
                if (grid) g = to_vector(*grid);
                return QS::de_casteljau(s, g);
            },
            py::arg("segments"), py::arg("grid") = py::none())
        .def_property_readonly("grid", [](const QS& c) { return grid_of(c.grid()); })
        .def_property_readonly("keys", [](const QS& c) { return from_quats({c.keys().begin(), c.keys().end()}); })
        .def_property_readonly("closed", &QS::closed)
        .def_property_readonly("segment_count", &QS::segment_count)
        .def_property_readonly("control_quaternions",
                               [](const QS& c) {
                                   py::list l;
                                   for (const auto& s : c.control_quaternions()) l.append(from_quats(s));
                                   return l;
                               })
        .def("evaluate",
             [](const QS& c, const farray& t, int order, const std::string& f, bool xyzw) {
                 return evaluate_many(c, t, order, f, xyzw, true);
             },
             py::arg("t"), py::arg("order") = 0, py::arg("frame") = "world", py::arg("xyzw") = false)
        .def("evaluate_on",
             [](const QS& c, const py::array_t<long long>& seg, const farray& t, int order, const std::string& f) {
                 return evaluate_on_many(c, t, seg, order, f);
             },
             py::arg("segment"), py::arg("t"), py::arg("order") = 0, py::arg("frame") = "world")
        .def("angle_length", [](const QS& c, double acc) { return angle_length(c, acc); }, py::arg("accuracy") = default_angle_accuracy)
        .def("constant_angular_speed_times", [](const QS& c, std::size_t n, double acc) { return angle_times(c, n, acc); },
             py::arg("n"), py::arg("accuracy") = default_angle_accuracy);

    using C2 = c2_rotation_spline<double>;
    py::class_<C2>(m, "_C2Spline", "The C2 rotation spline (SciPy's RotationSpline construction, solved to convergence).")
        .def(py::init([](const farray& times, const farray& keys, const py::object& start, const py::object& end,
                         const std::string& velocity_frame, bool closed, bool keep_signs, double unit_tolerance) {
                 c2_options<double> o;
                 o.start = to_c2_end(start, velocity_frame, "start");
                 o.end = to_c2_end(end, velocity_frame, "end");
                 o.closed = closed, o.keep_signs = keep_signs, o.unit_tolerance = unit_tolerance;
                 const auto t = to_vector(times);
                 const auto q = to_quats(keys, "keys");
                 return C2(t, q, o);
             }),
             py::arg("times"), py::arg("keys"), py::arg("start") = "scipy", py::arg("end") = "scipy",
             py::arg("velocity_frame") = "world", py::arg("closed") = false, py::arg("keep_signs") = false,
             py::arg("unit_tolerance") = 1e-6)
        .def_property_readonly("grid", [](const C2& c) { return grid_of(c.grid()); })
        .def_property_readonly("keys", [](const C2& c) { return from_quats({c.keys().begin(), c.keys().end()}); })
        .def_property_readonly("closed", &C2::closed)
        .def_property_readonly("segment_count", &C2::segment_count)
        .def_property_readonly("residual", &C2::residual)
        .def_property_readonly("acceleration_scale", &C2::acceleration_scale)
        .def_property_readonly("iterations", &C2::iterations)
        .def_property_readonly("key_rates",
                               [](const C2& c) {
                                   const auto r = c.key_rates();
                                   farray a({py::ssize_t(r.size()), py::ssize_t(3)});
                                   for (std::size_t i = 0; i < r.size(); ++i)
                                       for (std::size_t d = 0; d < 3; ++d) a.mutable_data()[3 * i + d] = r[i][d];
                                   return a;
                               })
        .def("evaluate",
             [](const C2& c, const farray& t, int order, const std::string& f, bool extrapolate, bool xyzw, bool rotations) {
                 return evaluate_many(c, t, order, f, xyzw, rotations, extrapolate);
             },
             py::arg("t"), py::arg("order") = 0, py::arg("frame") = "world", py::arg("extrapolate") = false,
             py::arg("xyzw") = false, py::arg("rotations") = true)
        .def("evaluate_on",
             [](const C2& c, const py::array_t<long long>& seg, const farray& t, int order, const std::string& f) {
                 return evaluate_on_many(c, t, seg, order, f);
             },
             py::arg("segment"), py::arg("t"), py::arg("order") = 0, py::arg("frame") = "world")
        .def("angle_length", [](const C2& c, double acc) { return angle_length(c, acc); }, py::arg("accuracy") = default_angle_accuracy)
        .def("constant_angular_speed_times", [](const C2& c, std::size_t n, double acc) { return angle_times(c, n, acc); },
             py::arg("n"), py::arg("accuracy") = default_angle_accuracy);

    using PC = pose_curve<double>;
    py::class_<PC>(m, "_PoseCurve", "A pose curve: 3-D position and rotation on one grid.")
        .def(py::init([](const farray& positions, const farray& rotations, std::optional<double> alpha,
                         std::optional<farray> grid, bool closed, bool c2) {
                 if (positions.ndim() != 2 || positions.shape(1) != 3)
                     throw invalid_input("positions must have shape (n, 3)");
                 pose_options<double> o;
                 o.alpha = alpha;
                 if (grid) o.grid = to_vector(*grid);
                 o.closed = closed, o.c2_rotation = c2;
                 std::vector<vec<3, double>> p(std::size_t(positions.shape(0)));
                 for (std::size_t i = 0; i < p.size(); ++i)
                     for (std::size_t d = 0; d < 3; ++d) p[i][d] = positions.data()[3 * i + d];
                 const auto q = to_quats(rotations, "rotations");
                 return PC(p, q, o);
             }),
             py::arg("positions"), py::arg("rotations"), py::arg("alpha") = py::none(), py::arg("grid") = py::none(),
             py::arg("closed") = false, py::arg("c2") = true)
        .def_property_readonly("grid", [](const PC& c) { return grid_of(c.grid()); })
        .def("evaluate",
             [](const PC& c, const farray& t, const std::string& f) {
                 const std::size_t count = std::size_t(t.size());
                 std::vector<pose_sample<double>> out(count);
                 {
                     py::gil_scoped_release release;
                     c.evaluate(std::span<const double>(t.data(), count), std::span<pose_sample<double>>(out), to_frame(f));
                 }
                 farray pos({py::ssize_t(count), py::ssize_t(3)}), q({py::ssize_t(count), py::ssize_t(4)}),
                     vel({py::ssize_t(count), py::ssize_t(3)}), w({py::ssize_t(count), py::ssize_t(3)});
                 for (std::size_t k = 0; k < count; ++k) {
                     const auto& s = out[k];
                     for (std::size_t d = 0; d < 3; ++d) {
                         pos.mutable_data()[3 * k + d] = s.position[d];
                         vel.mutable_data()[3 * k + d] = s.velocity[d];
                         w.mutable_data()[3 * k + d] = s.omega[d];
                     }
                     const auto a = s.orientation.array();
                     for (std::size_t d = 0; d < 4; ++d) q.mutable_data()[4 * k + d] = a[d];
                 }
                 return py::make_tuple(pos, q, vel, w);
             },
             py::arg("t"), py::arg("frame") = "world")
        .def("constant_speed_times",
             [](const PC& c, std::size_t n, double pw, double aw, double acc) {
                 const auto t = c.constant_speed_times(n, pw, aw, acc);
                 return grid_of(t);
             },
             py::arg("n"), py::arg("position_weight") = 1.0, py::arg("angle_weight") = 0.0,
             py::arg("accuracy") = default_angle_accuracy);

    // Conversions, row by row.
    // Keyframe reduction (rotation/fit.hpp): (indices, times, keys, curve,
    // max_angle, worst); the fit runs with the GIL released.
    m.def(
        "_rotation_fit",
        [](const farray& times, const farray& quaternions, double angle_tolerance, double unit_tolerance) {
            if (times.ndim() != 1)
                throw invalid_input("times must be 1-dimensional, got " + std::to_string(times.ndim()) + " dimensions");
            const auto t = to_vector(times);
            const auto q = to_quats(quaternions, "quaternions");
            std::optional<rotation_fit<double>> r;
            {
                py::gil_scoped_release release;
                r.emplace(fit(t, q, angle_tolerance, rotation_fit_options<double>{unit_tolerance}));
            }
            py::array_t<long long> idx(py::ssize_t(r->count()));
            for (std::size_t k = 0; k < r->count(); ++k) idx.mutable_data()[k] = (long long)r->indices[k];
            return py::make_tuple(idx, grid_of(r->times), from_quats(r->keys), r->curve, r->max_angle, r->worst);
        },
        py::arg("times"), py::arg("quaternions"), py::arg("angle_tolerance"),
        py::arg("unit_tolerance") = std::numeric_limits<double>::infinity());
    m.def("_rotation_slerp", [](const farray& a, const farray& b, const farray& u) {
        const auto qa = to_quats(a, "a"), qb = to_quats(b, "b");
        if (qa.size() != qb.size() || qa.size() != std::size_t(u.size())) throw invalid_input("slerp: a, b and u differ in length");
        std::vector<quat> out(qa.size());
        for (std::size_t i = 0; i < out.size(); ++i) out[i] = slerp(qa[i], qb[i], u.data()[i]);
        return from_quats(out);
    });
    m.def("_rotation_to_matrix", [](const farray& q) {
        const auto qs = to_quats(q, "quaternions");
        farray out({py::ssize_t(qs.size()), py::ssize_t(3), py::ssize_t(3)});
        for (std::size_t i = 0; i < qs.size(); ++i) {
            const auto mtx = to_matrix(qs[i]);
            for (std::size_t r = 0; r < 3; ++r)
                for (std::size_t c = 0; c < 3; ++c) out.mutable_data()[9 * i + 3 * r + c] = mtx[r][c];
        }
        return out;
    });
    m.def("_rotation_from_matrix", [](const farray& mm, double tol) {
        if (mm.ndim() != 3 || mm.shape(1) != 3 || mm.shape(2) != 3) throw invalid_input("matrices must have shape (n, 3, 3)");
        std::vector<quat> out(std::size_t(mm.shape(0)));
        for (std::size_t i = 0; i < out.size(); ++i) {
            matrix3<double> mtx{};
            for (std::size_t r = 0; r < 3; ++r)
                for (std::size_t c = 0; c < 3; ++c) mtx[r][c] = mm.data()[9 * i + 3 * r + c];
            try {
                out[i] = from_matrix(mtx, tol);
            } catch (const invalid_input& e) {
                throw invalid_input("matrix " + std::to_string(i) + ": " + e.what());
            }
        }
        return from_quats(out);
    });
    m.def("_rotation_to_rotvec", [](const farray& q) {
        const auto qs = to_quats(q, "quaternions");
        farray out({py::ssize_t(qs.size()), py::ssize_t(3)});
        for (std::size_t i = 0; i < qs.size(); ++i) {
            const auto r = to_rotation_vector(qs[i]);
            for (std::size_t d = 0; d < 3; ++d) out.mutable_data()[3 * i + d] = r[d];
        }
        return out;
    });
    m.def("_rotation_from_rotvec", [](const farray& r) {
        if (r.ndim() != 2 || r.shape(1) != 3) throw invalid_input("rotation vectors must have shape (n, 3)");
        std::vector<quat> out(std::size_t(r.shape(0)));
        for (std::size_t i = 0; i < out.size(); ++i)
            out[i] = from_rotation_vector(v3{{r.data()[3 * i], r.data()[3 * i + 1], r.data()[3 * i + 2]}});
        return from_quats(out);
    });
    m.def("_rotation_to_euler", [](const farray& q, const std::string& seq) {
        const auto c = euler_convention::parse(seq);
        const auto qs = to_quats(q, "quaternions");
        farray out({py::ssize_t(qs.size()), py::ssize_t(3)});
        for (std::size_t i = 0; i < qs.size(); ++i) {
            const auto e = to_euler(c, qs[i]);
            for (std::size_t d = 0; d < 3; ++d) out.mutable_data()[3 * i + d] = e[d];
        }
        return out;
    });
    m.def("_rotation_from_euler", [](const std::string& seq, const farray& a) {
        const auto c = euler_convention::parse(seq);
        if (a.ndim() != 2 || a.shape(1) != 3) throw invalid_input("angles must have shape (n, 3)");
        std::vector<quat> out(std::size_t(a.shape(0)));
        for (std::size_t i = 0; i < out.size(); ++i)
            out[i] = from_euler(c, std::array<double, 3>{a.data()[3 * i], a.data()[3 * i + 1], a.data()[3 * i + 2]});
        return from_quats(out);
    });
}

}  // namespace crspline::python
