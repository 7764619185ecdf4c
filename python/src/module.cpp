// crspline Python module `crspline._crspline`: the compiled part of the
// `crspline` package. The public API (CatmullRom, KochanekBartels) is the
// pure-Python layer in crspline/__init__.py; this module is private.
#include <crspline/version.hpp>

#include "curve.hpp"

namespace py = pybind11;
using namespace crspline::python;

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
    auto& domain = py::register_exception<crspline::out_of_domain>(m, "OutOfDomain", PyExc_ValueError);
    domain.attr("__doc__") =
        "A parameter t (or arc length s) outside the curve's domain (a ValueError). For arrays the\n"
        "message names the index of the first bad value in the flattened input.";

    py::class_<curve> cls(m, "_Curve", "A Catmull-Rom curve of run-time dimension and scalar type.");
    bind_curve(m, cls);
    bind_arc_length(m, cls);
    bind_hermite(m, cls);
#ifdef CRSPLINE_PY_GEOMETRY
    bind_geometry(m, cls);
#endif
#ifdef CRSPLINE_PY_FRAMES
    bind_frames(m, cls);
#endif
#ifdef CRSPLINE_PY_ANALYSIS
    bind_analysis(m, cls);
#endif
}
