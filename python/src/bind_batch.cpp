// crspline Python module: many curves in one call.
//
// A font, a map or a set of tracks is thousands of small curves; one Python
// call per curve spends most of its time in the interpreter. Here one call
// takes the list of point arrays and the options they share, releases the
// GIL and works through the curves on up to `workers` threads (std::thread;
// Python passes the machine's core count by default). Each curve is a
// crspline::curve_spec validated by the core, as for one curve, so the words
// are the same; an error names the curve's index ("curve 17: point 2,
// coordinate 0 is not finite (nan)") and is the one of the lowest index
// whatever the thread timing. Results come back in input order.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <crspline/arc_length.hpp>
#include <crspline/resolution.hpp>
#ifdef CRSPLINE_PY_GEOMETRY
#include <crspline/tessellate.hpp>
#endif

#include "curve.hpp"

namespace crspline::python {

namespace {

using point_arrays = std::vector<py::array_t<double, py::array::c_style | py::array::forcecast>>;

/// One curve's points, read without the GIL.
struct points_view {
    const double* data;
    std::size_t n, dim;
};

/// What every curve of one call shares.
struct shared_options {
    std::optional<double> alpha;
    ends_arg ends;
    double tension;
    bool strict;
};

/// The error of curve i, with the index in front of the core's words (and,
/// for a spec_error, its field, index and value kept).
[[noreturn]] void rethrow_for_curve(std::exception_ptr e, std::size_t i) {
    const std::string at = "curve " + std::to_string(i) + ": ";
    try {
        std::rethrow_exception(e);
    } catch (const spec_error& x) {
        throw spec_error(x.field(), x.index(), x.component(), x.value(), at + x.what());
    } catch (const invalid_input& x) {
        throw invalid_input(at + x.what());
    } catch (const out_of_domain& x) {
        throw out_of_domain(at + x.what());
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception& x) {
        throw std::runtime_error(at + x.what());
    }
}

/// work(curve, dimension) for every curve, on up to `workers` threads, the
/// GIL released; results in input order. The curves are built as
/// catmull_rom<D> for D = 1..4 and the zero-padded wide curve for 5..16
/// (crspline::with_dimension); `dimension` is the input's, for cutting.
template <class R, class Work>
std::vector<R> for_each_curve(const point_arrays& arrays, const shared_options& shared, std::size_t workers,
                              Work&& work) {
    if (workers < 1) throw invalid_input("workers must be at least 1, got " + std::to_string(workers));
    std::vector<points_view> views;
    views.reserve(arrays.size());
    for (const auto& a : arrays) {
        if (a.ndim() != 2) throw invalid_input("each curve's points must be an N x dim array");
        views.push_back({a.data(), std::size_t(a.shape(0)), std::size_t(a.shape(1))});
    }
    const std::size_t m = views.size();
    std::vector<R> results(m);
    std::vector<std::exception_ptr> errors(m);
    std::atomic<std::size_t> next{0}, first_error{m};

    const auto one = [&](std::size_t i) {
        curve_spec s;
        s.dimension = views[i].dim;
        s.points.assign(views[i].data, views[i].data + views[i].n * views[i].dim);
        s.alpha = shared.alpha;
        apply_ends(s, shared.ends);
        s.tension = shared.tension;
        s.strict = shared.strict;
        // make_curve validates; a dimension outside 1..16 gets validate()'s words.
        results[i] = crspline::with_dimension(
            s.dimension,
            [&](auto d) -> R { return work(crspline::make_curve<decltype(d)::value, double>(s), s.dimension); },
            [&](std::size_t) { validate(s); });
    };
    // Indices are handed out in increasing order and a worker skips those
    // above the lowest failure so far, so every curve below the first
    // failing one is done: the error raised does not depend on timing.
    const auto body = [&] {
        for (;;) {
            const std::size_t i = next.fetch_add(1);
            if (i >= m || i > first_error.load()) return;
            try {
                one(i);
            } catch (...) {
                errors[i] = std::current_exception();
                std::size_t current = first_error.load();
                while (i < current && !first_error.compare_exchange_weak(current, i)) {
                }
            }
        }
    };
    {
        py::gil_scoped_release nogil;
        const std::size_t threads = std::min(workers, m);
        std::vector<std::thread> pool;
        for (std::size_t k = 1; k < threads; ++k) {
            try {
                pool.emplace_back(body);
            } catch (const std::system_error&) {
                break;  // fewer threads than asked: the others share the work
            }
        }
        body();
        for (auto& t : pool) t.join();
    }
    if (first_error.load() < m) rethrow_for_curve(errors[first_error.load()], first_error.load());
    return results;
}

shared_options options_of(std::optional<double> alpha, const ends_arg& ends, double tension, bool strict) {
    return {alpha, ends, tension, strict};
}

}  // namespace

void bind_batch(py::module_& m) {
    m.def("_arc_lengths", [](const point_arrays& curves, std::optional<double> alpha, const ends_arg& ends,
                             double tension, bool strict, double accuracy, std::size_t workers) {
        check_relative_accuracy(accuracy);  // once for all the curves
        const auto lengths = for_each_curve<double>(
            curves, options_of(alpha, ends, tension, strict), workers,
            [accuracy](const auto& c, std::size_t) { return double(arc_length(c, accuracy)); });
        return vector_array<double>(lengths);
    }, py::arg("curves"), py::arg("alpha"), py::arg("ends"), py::arg("tension"), py::arg("strict"),
       py::arg("accuracy"), py::arg("workers"),
       "Arc length of every curve (a list of (N, dim) float64 arrays sharing the options), on up to\n"
       "`workers` threads with the GIL released; errors name the curve's index.");

#ifdef CRSPLINE_PY_GEOMETRY
    m.def("_tessellate_many", [](const point_arrays& curves, std::optional<double> alpha, const ends_arg& ends,
                                 double tension, bool strict, std::optional<double> tolerance, std::size_t workers) {
        struct flat {
            std::vector<double> points, t;
            std::size_t dim = 0;
        };
        const auto lines = for_each_curve<flat>(
            curves, options_of(alpha, ends, tension, strict), workers, [tolerance](const auto& c, std::size_t dim) {
                if (tolerance) check_distance_tolerance(c, *tolerance);  // below it, subdivision never ends
                const auto p = tolerance ? tessellate(c, *tolerance) : tessellate(c);
                flat f{{}, std::vector<double>(p.t.begin(), p.t.end()), dim};
                f.points.reserve(p.points.size() * dim);
                for (const auto& q : p.points)
                    for (std::size_t k = 0; k < dim; ++k) f.points.push_back(q[k]);  // a wide curve cut back
                return f;
            });
        py::list out;
        for (const auto& f : lines) {
            py::array_t<double> pts({py::ssize_t(f.t.size()), py::ssize_t(f.dim)});
            std::copy(f.points.begin(), f.points.end(), pts.mutable_data());
            out.append(py::make_tuple(pts, vector_array<double>(std::span<const double>(f.t))));
        }
        return out;
    }, py::arg("curves"), py::arg("alpha"), py::arg("ends"), py::arg("tension"), py::arg("strict"),
       py::arg("tolerance"), py::arg("workers"),
       "Tessellation of every curve: a list of (points, t), as for one curve, in input order.");
#endif
}

}  // namespace crspline::python
