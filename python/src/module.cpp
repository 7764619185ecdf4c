// crspline Python module `crspline._crspline`: the compiled part of the
// `crspline` package. The public API (CatmullRom, KochanekBartels) is the
// pure-Python layer in crspline/ (the curve class in crspline/_curve.py); this module is private.
#include <exception>
#include <optional>

#include <crspline/version.hpp>

#include "curve.hpp"

namespace py = pybind11;
using namespace crspline::python;
namespace crspline::python { void bind_rotation(py::module_& m); }  // bind_rotation.cpp: crspline.rotation's core
namespace crspline::python { void bind_geo(py::module_& m); }  // bind_geo.cpp: crspline.geo's core
namespace crspline::python { void bind_decision(py::module_& m); }  // bind_decision.cpp: the decision (issue 27)
namespace crspline::python { void bind_fit(py::module_& m); }  // bind_fit.cpp: crspline.fit (issue 40)
namespace crspline::python { void bind_sweep(py::module_& m); }  // bind_sweep.cpp: crspline.sweep, stroke (issue 41)

PYBIND11_MODULE(_crspline, m) {
    m.doc() = "Compiled core of the crspline package (private: use crspline.CatmullRom).";
    m.attr("__version__") = crspline::version;
    m.attr("max_dimension") = max_dimension;

    // The library's exceptions keep their messages; both are ValueErrors.
    // (Translators are tried newest first, so the specific ones win over
    // pybind11's std::invalid_argument / std::domain_error defaults.)
    auto& invalid = py::register_exception<crspline::invalid_input>(m, "InvalidInput", PyExc_ValueError);
    invalid.attr("__doc__") =
        "Bad input to a constructor or method (a ValueError): non-finite coordinates, too few points,\n"
        "alpha outside [0, 1], a bad grid, coincident points in strict mode, ... The message names the\n"
        "index and the value.";
    // A bad curve specification (crspline::spec_error): an InvalidInput with
    // the core's words and the pieces a caller may want, as attributes:
    // field ('points', 'alpha', 'grid', 'start', 'end', 'tension',
    // 'kb.tension', ...), index and component (int or None) and value (the
    // offending value as text, '' when there is none).
    static PyObject* spec_error_type = nullptr;
    auto& spec = py::register_exception<crspline::spec_error>(m, "SpecError", invalid.ptr());
    spec.attr("__doc__") =
        "A curve specification the core rejects (an InvalidInput, so a ValueError), with the core's message\n"
        "and its parts: field, index, component (int or None) and value (text).";
    spec_error_type = spec.ptr();
    py::register_exception_translator([](std::exception_ptr p) {  // tried before the plain translator
        if (!p) return;
        try {
            std::rethrow_exception(p);
        } catch (const crspline::spec_error& e) {
            const auto optional_int = [](std::optional<std::size_t> v) {
                return v ? py::object(py::int_(*v)) : py::object(py::none());
            };
            py::object err = py::reinterpret_borrow<py::object>(spec_error_type)(e.what());
            err.attr("field") = e.field();
            err.attr("index") = optional_int(e.index());
            err.attr("component") = optional_int(e.component());
            err.attr("value") = e.value();
            PyErr_SetObject(spec_error_type, err.ptr());
        }
    });
    auto& domain = py::register_exception<crspline::out_of_domain>(m, "OutOfDomain", PyExc_ValueError);
    domain.attr("__doc__") =
        "A parameter t (or arc length s) outside the curve's domain (a ValueError). For arrays the\n"
        "message names the index of the first bad value in the flattened input.";

    py::class_<curve> cls(m, "_Curve", "A Catmull-Rom curve of run-time dimension and scalar type.");
    bind_curve(m, cls);
    bind_arc_length(m, cls);
    bind_hermite(m, cls);
    bind_batch(m);
    bind_rotation(m);
    bind_geo(m);
    bind_decision(m);
#ifdef CRSPLINE_PY_GEOMETRY
    bind_geometry(m, cls);
#endif
#ifdef CRSPLINE_PY_FRAMES
    bind_frames(m, cls);
#endif
#ifdef CRSPLINE_PY_ANALYSIS
    bind_analysis(m, cls);
#endif
#ifdef CRSPLINE_PY_FIT
    bind_fit(m);
#endif
#ifdef CRSPLINE_PY_SWEEP
    bind_sweep(m);
#endif
}
