// crspline for JavaScript: the rotation and pose splines of
// include/crspline/rotation/ (issue 28), bound with Embind beside
// bindings.cpp (web/build.sh links both into one module).
//
// Quaternions cross the boundary as flat Float64Arrays of [w, x, y, z] per
// rotation, crspline's order (the npm package's three.js adapter converts to
// three.js' [x, y, z, w]; the core's order stays the only one in here).
// Angular rates are 3-vectors, in the world frame unless a frame 'body' is
// asked for. A C++ exception becomes a JavaScript Error with the core's
// message, as in bindings.cpp.
//
// Kept inside the subset of libc++ 13 that Emscripten 3.1.6 ships.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <crspline/rotation/angle_length.hpp>
#include <crspline/rotation/c2.hpp>
#include <crspline/rotation/catmull_rom.hpp>
#include <crspline/rotation/pose.hpp>

#include <cmath>
#include <exception>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace {

using emscripten::val;
namespace cr = crspline;
namespace rot = crspline::rotation;
using quat = rot::quaternion<double>;
using v3 = rot::vec3<double>;

// Runs f; a C++ exception becomes a JavaScript Error with the same message
// (copied out of the catch block first, so the C++ exception is freed
// before JavaScript unwinds).
template <class F>
auto guarded(F&& f) -> decltype(f()) {
    std::string message;
    try {
        return f();
    } catch (const std::exception& e) {
        message = e.what();
    } catch (...) {
        message = "crspline: unknown error";
    }
    val::global("Error").new_(message).throw_();
    __builtin_unreachable();
}

bool nullish(const val& v) { return v.isUndefined() || v.isNull(); }

val float64_array(const double* p, std::size_t n) {
    return val::global("Float64Array").new_(emscripten::typed_memory_view(n, p));  // a copy
}
val float64_array(const std::vector<double>& v) { return float64_array(v.data(), v.size()); }

std::vector<double> numbers(const val& a, const char* what) {
    if (nullish(a) || !a["length"].isNumber()) throw cr::invalid_input(std::string(what) + " must be an array of numbers");
    return emscripten::convertJSArrayToNumberVector<double>(a);
}

// Flat [w, x, y, z, ...] as quaternions.
std::vector<quat> quats(const val& a, const char* what) {
    const std::vector<double> f = numbers(a, what);
    if (f.size() % 4 != 0)
        throw cr::invalid_input(std::string(what) + " has " + std::to_string(f.size()) +
                                " numbers, not a multiple of 4 ([w, x, y, z] per rotation)");
    std::vector<quat> q(f.size() / 4);
    for (std::size_t i = 0; i < q.size(); ++i) q[i] = {f[4 * i], f[4 * i + 1], f[4 * i + 2], f[4 * i + 3]};
    return q;
}

v3 vector3(const val& a, const char* what) {
    const std::vector<double> f = numbers(a, what);
    if (f.size() != 3) throw cr::invalid_input(std::string(what) + " must be a 3-vector, got " + std::to_string(f.size()) + " numbers");
    return v3{{f[0], f[1], f[2]}};
}

rot::frame frame_of(const std::string& f) {
    if (f == "world") return rot::frame::world;
    if (f == "body") return rot::frame::body;
    throw cr::invalid_input("frame must be 'world' or 'body', got '" + f + "'");
}

std::optional<double> number_option(const val& o, const char* key) {
    const val v = o[key];
    if (nullish(v)) return std::nullopt;
    if (!v.isNumber()) throw cr::invalid_input(std::string(key) + " must be a number");
    return v.as<double>();
}

bool bool_option(const val& o, const char* key, bool fallback) {
    const val v = o[key];
    if (nullish(v)) return fallback;
    if (!v.isTrue() && !v.isFalse()) throw cr::invalid_input(std::string(key) + " must be true or false");
    return v.as<bool>();
}

// Every option name a constructor knows; any other is an error naming it.
void known_options(const val& o, std::initializer_list<const char*> known) {
    if (nullish(o)) return;
    const val keys = val::global("Object").call<val>("keys", o);
    for (std::size_t i = 0, n = keys["length"].as<std::size_t>(); i < n; ++i) {
        const std::string k = keys[i].as<std::string>();
        if (o[k].isUndefined()) continue;
        bool ok = false;
        std::string list;
        for (const char* x : known) {
            ok = ok || k == x;
            list += (list.empty() ? "" : ", ") + std::string(x);
        }
        if (!ok) throw cr::invalid_input("unknown option '" + k + "' (known: " + list + ")");
    }
}

rot::spline_kind kind_of(const std::string& k) {
    if (k == "catmull_rom") return rot::spline_kind::catmull_rom;
    if (k == "kochanek_bartels") return rot::spline_kind::kochanek_bartels;
    if (k == "piecewise_slerp") return rot::spline_kind::piecewise_slerp;
    if (k == "barry_goldman") return rot::spline_kind::barry_goldman;
    if (k == "squad") return rot::spline_kind::squad;
    throw cr::invalid_input("kind must be 'catmull_rom', 'kochanek_bartels', 'piecewise_slerp', 'barry_goldman' or "
                            "'squad', got '" + k + "'");
}

// An end: a name, or {omega: [x, y, z], frame: 'world' | 'body'}.
template <class End>
End end_of(const val& e, const char* which, const char* names) {
    if (nullish(e)) return End{};
    if (e.isString()) {
        const std::string s = e.as<std::string>();
        if constexpr (std::is_same_v<End, rot::rotation_end<double>>) {
            if (s == "natural") return End::natural();
            if (s == "natural_splines") return End::natural_splines();
        } else {
            if (s == "scipy") return End::scipy();
            if (s == "natural") return End::natural();
        }
        throw cr::invalid_input(std::string(which) + " must be " + names + " or {omega: [x, y, z], frame}, got '" + s + "'");
    }
    const rot::frame f = nullish(e["frame"]) ? rot::frame::world : frame_of(e["frame"].as<std::string>());
    return End::velocity(vector3(e["omega"], (std::string(which) + ".omega").c_str()), f);
}

// One jet as {q: [w, x, y, z], omega: [3] | null, alpha: [3] | null}.
val jet_object(const rot::so3::jet<double>& j, int order) {
    val r = val::object();
    const double q[4] = {j.q.w, j.q.x, j.q.y, j.q.z};
    r.set("q", float64_array(q, 4));
    r.set("omega", order >= 1 ? float64_array(j.omega.data(), 3) : val::null());
    r.set("alpha", order >= 2 ? float64_array(j.alpha.data(), 3) : val::null());
    return r;
}

// A rotation curve: quaternion_spline (the Catmull-Rom family) or the C2
// spline, with one set of calls.
class Rotation {
    std::variant<rot::quaternion_spline<double>, rot::c2_rotation_spline<double>> c_;

    template <class F>
    decltype(auto) visit(F&& f) const { return std::visit(std::forward<F>(f), c_); }

    static rot::quaternion_spline<double> family(const val& keys, const val& o) {
        known_options(o, {"kind", "alpha", "grid", "closed", "start", "end", "kb", "keepSigns", "strict", "unitTolerance"});
        rot::rotation_options<double> opt;
        if (!nullish(o)) {
            if (!nullish(o["kind"])) opt.kind = kind_of(o["kind"].as<std::string>());
            opt.alpha = number_option(o, "alpha");
            if (!nullish(o["grid"])) opt.grid = numbers(o["grid"], "grid");
            opt.closed = bool_option(o, "closed", false);
            opt.keep_signs = bool_option(o, "keepSigns", false);
            opt.strict = bool_option(o, "strict", false);
            if (const auto u = number_option(o, "unitTolerance")) opt.unit_tolerance = *u;
            opt.start = end_of<rot::rotation_end<double>>(o["start"], "start", "'natural', 'natural_splines'");
            opt.end = end_of<rot::rotation_end<double>>(o["end"], "end", "'natural', 'natural_splines'");
            const val kb = o["kb"];
            if (!nullish(kb)) {
                // {tension, continuity, bias}: numbers (all keys) or arrays (per key).
                const auto part = [&](const char* k) {
                    const val v = kb[k];
                    if (nullish(v)) return std::vector<double>{};
                    if (v.isNumber()) return std::vector<double>{v.as<double>()};
                    return numbers(v, (std::string("kb.") + k).c_str());
                };
                const auto t = part("tension"), c = part("continuity"), b = part("bias");
                const std::size_t n = std::max({t.size(), c.size(), b.size(), std::size_t(1)});
                for (std::size_t i = 0; i < n; ++i) {
                    const auto at = [&](const std::vector<double>& v, const char* k) {
                        if (v.empty()) return 0.0;
                        if (v.size() == 1) return v[0];
                        if (v.size() != n)
                            throw cr::invalid_input(std::string("kb.") + k + " has " + std::to_string(v.size()) +
                                                    " values, the others " + std::to_string(n));
                        return v[i];
                    };
                    opt.kb.push_back({at(t, "tension"), at(c, "continuity"), at(b, "bias")});
                }
            }
        }
        const auto q = quats(keys, "keys");
        return rot::quaternion_spline<double>(q, opt);
    }
    static rot::c2_rotation_spline<double> c2(const val& times, const val& keys, const val& o) {
        known_options(o, {"closed", "start", "end", "keepSigns", "unitTolerance"});
        rot::c2_options<double> opt;
        if (!nullish(o)) {
            opt.closed = bool_option(o, "closed", false);
            opt.keep_signs = bool_option(o, "keepSigns", false);
            if (const auto u = number_option(o, "unitTolerance")) opt.unit_tolerance = *u;
            opt.start = end_of<rot::c2_end<double>>(o["start"], "start", "'scipy', 'natural'");
            opt.end = end_of<rot::c2_end<double>>(o["end"], "end", "'scipy', 'natural'");
        }
        const auto t = numbers(times, "times");
        const auto q = quats(keys, "keys");
        return rot::c2_rotation_spline<double>(t, q, opt);
    }

    explicit Rotation(rot::quaternion_spline<double> c) : c_(std::move(c)) {}
    explicit Rotation(rot::c2_rotation_spline<double> c) : c_(std::move(c)) {}

public:
    // The Catmull-Rom family: keys flat [w, x, y, z] per key.
    static Rotation* quaternionSpline(val keys, val o) {
        return guarded([&] { return new Rotation(family(keys, o)); });
    }
    // The C2 spline (SciPy's construction, converged): times and keys.
    static Rotation* c2Spline(val times, val keys, val o) {
        return guarded([&] { return new Rotation(c2(times, keys, o)); });
    }

    std::string kind() const {
        if (const auto* q = std::get_if<rot::quaternion_spline<double>>(&c_)) {
            switch (q->kind()) {
                case rot::spline_kind::catmull_rom: return "catmull_rom";
                case rot::spline_kind::kochanek_bartels: return "kochanek_bartels";
                case rot::spline_kind::piecewise_slerp: return "piecewise_slerp";
                case rot::spline_kind::de_casteljau: return "de_casteljau";
                case rot::spline_kind::barry_goldman: return "barry_goldman";
                case rot::spline_kind::squad: return "squad";
            }
        }
        return "c2";
    }
    bool closed() const { return visit([](const auto& c) { return c.closed(); }); }
    double segmentCount() const { return visit([](const auto& c) { return double(c.segment_count()); }); }
    val grid() const {
        return visit([](const auto& c) { return float64_array(c.grid().data(), c.grid().size()); });
    }
    double tMin() const { return visit([](const auto& c) { return c.grid().front(); }); }
    double tMax() const { return visit([](const auto& c) { return c.grid().back(); }); }
    // The keys the curve interpolates, after the sign rule (closed: one
    // more, the return to key 0), flat [w, x, y, z].
    val keys() const {
        return visit([](const auto& c) {
            std::vector<double> f;
            for (const auto& q : c.keys()) f.insert(f.end(), {q.w, q.x, q.y, q.z});
            return float64_array(f);
        });
    }
    // The C2 spline's Newton residual and iterations (null for the family).
    val residual() const {
        const auto* c = std::get_if<rot::c2_rotation_spline<double>>(&c_);
        return c ? val(c->residual()) : val::null();
    }
    val iterations() const {
        const auto* c = std::get_if<rot::c2_rotation_spline<double>>(&c_);
        return c ? val(double(c->iterations())) : val::null();
    }
    // {q, omega, alpha} at t (checked), rates to `order` in `frame`.
    val evaluate(double t, int order, std::string f) const {
        return guarded([&] {
            const rot::frame fr = frame_of(f);
            return visit([&](const auto& c) { return jet_object(c.evaluate(t, order, fr), order); });
        });
    }
    val evaluate1(double t) const { return evaluate(t, 0, "world"); }
    // Many t: {q: 4 m numbers, omega: 3 m | null, alpha: 3 m | null}.
    val evaluateMany(val tv, int order, std::string f) const {
        return guarded([&] {
            if (order < 0 || order > 2) throw cr::invalid_input("derivative order must be 0, 1 or 2, got " + std::to_string(order));
            const rot::frame fr = frame_of(f);
            const std::vector<double> t = numbers(tv, "t");
            return visit([&](const auto& c) {
                const auto g = c.grid();
                std::vector<double> q(4 * t.size()), w(order >= 1 ? 3 * t.size() : 0), a(order >= 2 ? 3 * t.size() : 0);
                for (std::size_t k = 0; k < t.size(); ++k) {
                    if (!(t[k] >= g.front() && t[k] <= g.back()))
                        throw cr::out_of_domain("t = " + cr::detail::num(t[k]) + " (index " + std::to_string(k) +
                                                ") is outside the curve's domain [" + cr::detail::num(g.front()) + ", " +
                                                cr::detail::num(g.back()) + "]");
                    const auto j = c.evaluate_on(c.locate(t[k]), t[k], order, fr);
                    q[4 * k] = j.q.w, q[4 * k + 1] = j.q.x, q[4 * k + 2] = j.q.y, q[4 * k + 3] = j.q.z;
                    for (std::size_t d = 0; d < 3 && order >= 1; ++d) w[3 * k + d] = j.omega[d];
                    for (std::size_t d = 0; d < 3 && order >= 2; ++d) a[3 * k + d] = j.alpha[d];
                }
                val r = val::object();
                r.set("q", float64_array(q));
                r.set("omega", order >= 1 ? float64_array(w) : val::null());
                r.set("alpha", order >= 2 ? float64_array(a) : val::null());
                return r;
            });
        });
    }
    // The total angle turned through, int |omega| dt (radians).
    double angleLength(double accuracy) const {
        return guarded([&] {
            return visit([&](const auto& c) {
                return rot::angle_length(c, accuracy > 0 ? accuracy : rot::default_angle_accuracy);
            });
        });
    }
    // n values of t at constant angular speed.
    val constantAngularSpeedTimes(double n, double accuracy) const {
        return guarded([&] {
            if (!(n >= 2 && n <= 1e8 && n == std::floor(n)))
                throw cr::invalid_input("count must be an integer in [2, 1e8], got " + cr::detail::num(n));
            return visit([&](const auto& c) {
                return float64_array(rot::constant_angular_speed_times(
                    c, std::size_t(n), accuracy > 0 ? accuracy : rot::default_angle_accuracy));
            });
        });
    }
};

// A pose curve: positions (flat x, y, z) and rotations (flat w, x, y, z) on
// one shared grid.
class Pose {
    rot::pose_curve<double> c_;

    static rot::pose_curve<double> build(const val& positions, const val& rotations, const val& o) {
        known_options(o, {"alpha", "grid", "closed", "c2Rotation"});
        rot::pose_options<double> opt;
        if (!nullish(o)) {
            opt.alpha = number_option(o, "alpha");
            if (!nullish(o["grid"])) opt.grid = numbers(o["grid"], "grid");
            opt.closed = bool_option(o, "closed", false);
            opt.c2_rotation = bool_option(o, "c2Rotation", true);
        }
        const std::vector<double> f = numbers(positions, "positions");
        if (f.size() % 3 != 0)
            throw cr::invalid_input("positions has " + std::to_string(f.size()) + " numbers, not a multiple of 3");
        std::vector<cr::vec<3>> p(f.size() / 3);
        for (std::size_t i = 0; i < p.size(); ++i) p[i] = cr::vec<3>{{f[3 * i], f[3 * i + 1], f[3 * i + 2]}};
        const auto q = quats(rotations, "rotations");
        return rot::pose_curve<double>(p, q, opt);
    }

public:
    Pose(val positions, val rotations, val o) : c_(guarded([&] { return build(positions, rotations, o); })) {}

    val grid() const { return float64_array(c_.grid().data(), c_.grid().size()); }
    double tMin() const { return c_.grid().front(); }
    double tMax() const { return c_.grid().back(); }
    // {position, orientation [w, x, y, z], velocity, omega} at t, rates in `frame`.
    val evaluate(double t, std::string f) const {
        return guarded([&] {
            const auto s = c_.evaluate(t, frame_of(f));
            val r = val::object();
            const double q[4] = {s.orientation.w, s.orientation.x, s.orientation.y, s.orientation.z};
            r.set("position", float64_array(s.position.data(), 3));
            r.set("orientation", float64_array(q, 4));
            r.set("velocity", float64_array(s.velocity.data(), 3));
            r.set("omega", float64_array(s.omega.data(), 3));
            return r;
        });
    }
    val evaluate1(double t) const { return evaluate(t, "world"); }
    // Many t: {positions: 3 m, orientations: 4 m}.
    val evaluateMany(val tv) const {
        return guarded([&] {
            const std::vector<double> t = numbers(tv, "t");
            const auto s = c_.evaluate(std::span<const double>(t));
            std::vector<double> p(3 * t.size()), q(4 * t.size());
            for (std::size_t k = 0; k < s.size(); ++k) {
                for (std::size_t d = 0; d < 3; ++d) p[3 * k + d] = s[k].position[d];
                const auto& o = s[k].orientation;
                q[4 * k] = o.w, q[4 * k + 1] = o.x, q[4 * k + 2] = o.y, q[4 * k + 3] = o.z;
            }
            val r = val::object();
            r.set("positions", float64_array(p));
            r.set("orientations", float64_array(q));
            return r;
        });
    }
    // n values of t at constant speed of positionWeight |dx/dt| + angleWeight |omega|.
    val constantSpeedTimes(double n, double position_weight, double angle_weight, double accuracy) const {
        return guarded([&] {
            if (!(n >= 2 && n <= 1e8 && n == std::floor(n)))
                throw cr::invalid_input("count must be an integer in [2, 1e8], got " + cr::detail::num(n));
            return float64_array(c_.constant_speed_times(std::size_t(n), position_weight, angle_weight,
                                                         accuracy > 0 ? accuracy : rot::default_angle_accuracy));
        });
    }
};

}  // namespace

EMSCRIPTEN_BINDINGS(crspline_rotation) {
    using namespace emscripten;
    class_<Rotation>("RotationCurve")
        .class_function("quaternionSpline", &Rotation::quaternionSpline, allow_raw_pointers())
        .class_function("c2Spline", &Rotation::c2Spline, allow_raw_pointers())
        .function("kind", &Rotation::kind)
        .function("closed", &Rotation::closed)
        .function("segmentCount", &Rotation::segmentCount)
        .function("grid", &Rotation::grid)
        .function("tMin", &Rotation::tMin)
        .function("tMax", &Rotation::tMax)
        .function("keys", &Rotation::keys)
        .function("residual", &Rotation::residual)
        .function("iterations", &Rotation::iterations)
        .function("evaluate", &Rotation::evaluate)
        .function("evaluate", &Rotation::evaluate1)
        .function("evaluateMany", &Rotation::evaluateMany)
        .function("angleLength", &Rotation::angleLength)
        .function("constantAngularSpeedTimes", &Rotation::constantAngularSpeedTimes);
    class_<Pose>("PoseCurve")
        .constructor<val, val, val>()
        .function("grid", &Pose::grid)
        .function("tMin", &Pose::tMin)
        .function("tMax", &Pose::tMax)
        .function("evaluate", &Pose::evaluate)
        .function("evaluate", &Pose::evaluate1)
        .function("evaluateMany", &Pose::evaluateMany)
        .function("constantSpeedTimes", &Pose::constantSpeedTimes);
}
