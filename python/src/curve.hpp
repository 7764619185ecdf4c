// crspline Python module: the run-time curve and the helpers every binding
// file shares.
//
// The library fixes dimension and scalar at compile time (catmull_rom<D, T>);
// NumPy fixes them at run time. A curve here is a std::variant over D = 1..4
// and T = float, double; each binding visits it and instantiates its body
// once per alternative. Only public headers are used.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <optional>
#include <utility>
#include <variant>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>  // in every file: type casters must agree across translation units

#include <crspline/catmull_rom.hpp>
#include <crspline/dispatch.hpp>
#include <crspline/error.hpp>
#include <crspline/spec.hpp>

namespace crspline::python {

namespace py = pybind11;

/// The dimensions the module accepts: 1 to 4 as curves of exactly that
/// dimension, 5 to 16 as the one wide curve of crspline::with_dimension
/// (16 coordinates, zero-padded; see crspline/dispatch.hpp). _make_curve and
/// the many-curve calls pad through crspline::make_curve; the Python layer
/// (crspline/_curve.py) cuts results back to the input's dimension, and
/// hands _make_hermite only 1 to 4 columns.
inline constexpr std::size_t max_dimension = max_runtime_dimension;

/// f(std::integral_constant<std::size_t, D>{}) for D = 1..4 and 16, else the
/// module's error.
template <class F>
decltype(auto) with_dimension(std::size_t dimension, F&& f) {
    switch (dimension) {
        case 1: return std::forward<F>(f)(std::integral_constant<std::size_t, 1>{});
        case 2: return std::forward<F>(f)(std::integral_constant<std::size_t, 2>{});
        case 3: return std::forward<F>(f)(std::integral_constant<std::size_t, 3>{});
        case 4: return std::forward<F>(f)(std::integral_constant<std::size_t, 4>{});
        case wide_dimension: return std::forward<F>(f)(std::integral_constant<std::size_t, wide_dimension>{});
        default: break;
    }
    if (dimension > max_exact_dimension && dimension < wide_dimension)
        throw invalid_input("points with " + std::to_string(dimension) +
                            " coordinates must be padded to " + std::to_string(wide_dimension) +
                            " (crspline.CatmullRom does this)");
    throw invalid_input("points must have 1 to " + std::to_string(max_dimension) + " coordinates each, got " +
                        std::to_string(dimension));
}

/// f(T{}) for the scalar of a NumPy array that is float32 or float64.
template <class F>
decltype(auto) with_scalar(const py::array& a, F&& f) {
    if (a.dtype().is(py::dtype::of<float>())) return std::forward<F>(f)(float{});
    if (a.dtype().is(py::dtype::of<double>())) return std::forward<F>(f)(double{});
    throw py::type_error("expected a float32 or float64 array, got dtype " +
                         std::string(py::str(a.dtype())));
}

template <class T>
using curves_of = std::variant<catmull_rom<1, T>, catmull_rom<2, T>, catmull_rom<3, T>, catmull_rom<4, T>,
                               catmull_rom<wide_dimension, T>>;
template <class A, class B>
struct concat;
template <class... A, class... B>
struct concat<std::variant<A...>, std::variant<B...>> {
    using type = std::variant<A..., B...>;
};

/// Every curve type the module knows.
using curve_variant = concat<curves_of<double>, curves_of<float>>::type;

/// A curve of run-time dimension and scalar: what Python's _Curve holds.
struct curve {
    curve_variant v;

    template <class F>
    decltype(auto) visit(F&& f) const { return std::visit(std::forward<F>(f), v); }
};

template <class C>
using scalar_t = typename std::remove_cvref_t<C>::scalar;
template <class C>
inline constexpr std::size_t dimension_v = std::remove_cvref_t<C>::dimension;

/// A C-contiguous array of T: the argument itself when it already is one,
/// else a converted copy (the caller keeps it alive while using its data).
template <class T>
py::array_t<T, py::array::c_style> contiguous(const py::handle& a) {
    auto r = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!r) throw py::error_already_set();
    return r;
}

/// The shape of a, as a vector, with `extra` appended.
inline std::vector<py::ssize_t> shape_plus(const py::array& a, std::initializer_list<py::ssize_t> extra) {
    std::vector<py::ssize_t> s(a.shape(), a.shape() + a.ndim());
    s.insert(s.end(), extra);
    return s;
}

/// The data of a C-contiguous array of N x D values as points. vec<D, T> is
/// an implicit-lifetime aggregate of exactly D scalars, so a C-contiguous
/// buffer of scalars holds an array of them.
template <std::size_t D, class T>
vec<D, T>* as_points(py::array_t<T, py::array::c_style>& a) {
    static_assert(sizeof(vec<D, T>) == D * sizeof(T) && alignof(vec<D, T>) == alignof(T));
    return reinterpret_cast<vec<D, T>*>(a.mutable_data());
}
template <std::size_t D, class T>
const vec<D, T>* as_points(const py::array_t<T, py::array::c_style>& a) {
    static_assert(sizeof(vec<D, T>) == D * sizeof(T) && alignof(vec<D, T>) == alignof(T));
    return reinterpret_cast<const vec<D, T>*>(a.data());
}

/// A new array of points (shape ... x D) filled from a vector of vec<D, T>.
template <std::size_t D, class T>
py::array_t<T> points_array(std::span<const vec<D, T>> p, std::vector<py::ssize_t> shape = {}) {
    if (shape.empty()) shape = {py::ssize_t(p.size())};
    shape.push_back(py::ssize_t(D));
    py::array_t<T> out(shape);
    T* o = out.mutable_data();
    for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t k = 0; k < D; ++k) o[i * D + k] = p[i][k];
    return out;
}

/// A new 1-D array copied from a span.
template <class T>
py::array_t<T> vector_array(std::span<const T> v) {
    py::array_t<T> out(py::ssize_t(v.size()));
    std::copy(v.begin(), v.end(), out.mutable_data());
    return out;
}

/// Every t of an array with at least one axis inside [lo, hi], or
/// out_of_domain naming the first that is not, with its index in t.ravel()
/// and its value, in the words of catmull_rom::evaluate on a batch
/// ("t = 5 (index 2) is outside the domain [0, 3]"). A number (0-d) is left
/// to the scalar call, whose message names no index, as evaluate does.
template <class T>
void check_batch_domain(const py::array_t<T, py::array::c_style>& t, T lo, T hi) {
    if (t.ndim() == 0) return;
    const T* in = t.data();
    for (py::ssize_t k = 0; k < t.size(); ++k)
        if (!(in[k] >= lo && in[k] <= hi))
            throw out_of_domain("t = " + detail::num(double(in[k])) + " (index " + std::to_string(k) +
                                ") is outside the domain [" + detail::num(double(lo)) + ", " +
                                detail::num(double(hi)) + "]");
}

/// A query point of dimension D from a 1-D sequence (validated length).
template <std::size_t D, class T>
vec<D, T> to_vec(const std::vector<double>& c, const char* what) {
    if (c.size() != D)
        throw invalid_input(std::string(what) + " has " + std::to_string(c.size()) + " coordinates, expected " +
                            std::to_string(D));
    vec<D, T> p;
    for (std::size_t k = 0; k < D; ++k) p[k] = T(c[k]);
    return p;
}

/// One end as Python passes it: a name ("natural", "reflect") or a tangent
/// dx/dt. The names and the tangent's length and values are the core's to
/// check (crspline::validate in spec.hpp), so every front end says the same.
using end_arg = std::variant<std::string, std::vector<double>>;
/// Both ends: one name ("natural", "reflect", "closed") or (start, end).
using ends_arg = std::variant<std::string, std::pair<end_arg, end_arg>>;

/// Sets the ends of a specification from Python's form (names checked by the core).
inline void apply_ends(curve_spec& s, const ends_arg& ends) {
    const auto one = [](const end_arg& e, const std::string& field) {
        if (const auto* name = std::get_if<std::string>(&e)) return end_from_name(field, *name);
        return end_spec{end_spec::kind::tangent, std::get<std::vector<double>>(e)};
    };
    if (const auto* name = std::get_if<std::string>(&ends)) {
        set_ends(s, *name);
        return;
    }
    const auto& [start, end] = std::get<std::pair<end_arg, end_arg>>(ends);
    s.start = one(start, "start");
    s.end = one(end, "end");
}

// The report's values as Python objects (a crspline::report_builder, for
// report() and report_decision()): dicts, lists, floats, ints, bools,
// strings and None.
struct py_builder {
    using value = py::object;
    value object() { return py::dict(); }
    value array() { return py::list(); }
    void set(value& o, std::string_view key, value v) { o[py::str(std::string(key))] = std::move(v); }
    void push(value& a, value v) { a.cast<py::list>().append(std::move(v)); }
    value number(double x) { return py::float_(x); }
    value integer(std::size_t i) { return py::int_(i); }
    value boolean(bool f) { return py::bool_(f); }
    value string(std::string_view s) { return py::str(std::string(s)); }
    value null() { return py::none(); }
};

// Each binding file adds its part of the module.
void bind_curve(py::module_& m, py::class_<curve>& cls);
void bind_arc_length(py::module_& m, py::class_<curve>& cls);
void bind_geometry(py::module_& m, py::class_<curve>& cls);
void bind_frames(py::module_& m, py::class_<curve>& cls);
void bind_analysis(py::module_& m, py::class_<curve>& cls);
void bind_hermite(py::module_& m, py::class_<curve>& cls);
void bind_batch(py::module_& m);

}  // namespace crspline::python
