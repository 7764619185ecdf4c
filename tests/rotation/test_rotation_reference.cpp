// Rotation splines against the reference files (tests/reference/, see
// PROVENANCE.md): the 40-digit q_exact and omega_exact of
// quaternion_splines.json through the native classes, and SciPy's
// RotationSpline `converged` block of rotation_spline_scipy.json through the
// C2 spline. Tolerances are the files' own (`tol` per case; the SciPy file's
// 1e-12 on rotations and 1e-10 of the rate scale on rates).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <crspline/rotation/c2.hpp>
#include <crspline/rotation/catmull_rom.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <vector>

using namespace crspline::rotation;
using json = nlohmann::json;
using quat = quaternion<double>;

namespace {

json load(const std::string& name) {
    std::ifstream f(std::string(CRSPLINE_REFERENCE_DIR) + "/" + name);
    if (!f) throw std::runtime_error("cannot open " + name);
    return json::parse(f);
}

quat to_quat(const json& a) { return {a[0].get<double>(), a[1].get<double>(), a[2].get<double>(), a[3].get<double>()}; }
std::vector<quat> quats(const json& a) {
    std::vector<quat> v;
    for (const auto& x : a) v.push_back(to_quat(x));
    return v;
}
vec3<double> to_vec(const json& a) { return {{a[0].get<double>(), a[1].get<double>(), a[2].get<double>()}}; }

double ref_qdiff(const quat& a, const quat& b) {
    return std::max({std::abs(a.w - b.w), std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}
double ref_qdiff_sign(const quat& a, const quat& b) { return std::min(ref_qdiff(a, b), ref_qdiff(a, -b)); }

rotation_options<double> options_of(const json& c, bool documented_natural) {
    rotation_options<double> o;
    const std::string cls = c["class"];
    o.kind = cls == "PiecewiseSlerp"    ? spline_kind::piecewise_slerp
             : cls == "KochanekBartels" ? spline_kind::kochanek_bartels
             : cls == "BarryGoldman"    ? spline_kind::barry_goldman
             : cls == "Squad"           ? spline_kind::squad
                                        : spline_kind::catmull_rom;
    o.closed = c["closed"].get<bool>() || cls == "BarryGoldman" || cls == "Squad";
    if (!c["alpha"].is_null()) o.alpha = c["alpha"].get<double>();
    if (!c["grid"].is_null()) o.grid = c["grid"].get<std::vector<double>>();
    if (!documented_natural) o.start = o.end = rotation_end<double>::natural_splines();
    const auto& t = c["tcb"];
    if (!t.is_null()) {
        if (t[0].is_array())
            for (const auto& x : t) o.kb.push_back({x[0].get<double>(), x[1].get<double>(), x[2].get<double>()});
        else
            o.kb.push_back({t[0].get<double>(), t[1].get<double>(), t[2].get<double>()});
    }
    return o;
}

}  // namespace

// Every case of quaternion_splines.json: q_exact (with the sign rule of the
// file, which crspline follows) and omega_exact at every sample, the
// canonical keys, and for open natural curves the documented end
// (doc_natural). Tolerances: the case's tol.q_exact and tol.omega_exact
// (1e-10 of the omega scale: room for an analytic derivative in double).
TEST(RotationReference, QuaternionSplines) {
    const json d = load("quaternion_splines.json");
    std::map<std::string, int> per_class;
    int samples = 0, doc_samples = 0;
    for (const auto& c : d["cases"]) {
        const std::string id = c["id"], cls = c["class"];
        SCOPED_TRACE(id);
        const auto& s = c["samples"];
        const double tol_q = c["tol"]["q_exact"], tol_w = c["tol"]["omega_exact"];
        const std::size_t ns = s["seg"].size();
        auto check = [&](auto eval, const json& q_exact, const json& w_exact, int& count) {
            for (std::size_t k = 0; k < ns; ++k) {
                const std::size_t seg = s["seg"][k];
                const double t = s["t_exact"][k];
                const so3::jet<double> j = eval(seg, t);
                EXPECT_LE(ref_qdiff(j.q, to_quat(q_exact[k])), tol_q) << "sample " << k << " t " << t;
                const auto w = to_vec(w_exact[k]);
                EXPECT_LE(crspline::max_abs(j.omega - w), tol_w) << "sample " << k << " t " << t;
                ++count;
            }
        };
        if (cls == "slerp") {
            const auto k = quats(c["keys"]);
            check(
                [&](std::size_t, double t) {
                    return so3::slerp_jet(so3::constant(k[0]), so3::constant(k[1]), t, 1.0, 0.0, 1);
                },
                s["q_exact"], s["omega_exact"], samples);
        } else if (cls == "DeCasteljau") {
            std::vector<std::vector<quat>> segs;
            for (const auto& x : c["segments"]) segs.push_back(quats(x));
            std::optional<std::vector<double>> g;
            if (!c["grid"].is_null()) g = c["grid"].get<std::vector<double>>();
            const auto curve = quaternion_spline<double>::de_casteljau(segs, g);
            check([&](std::size_t seg, double t) { return curve.evaluate_on(seg, t, 1); }, s["q_exact"], s["omega_exact"], samples);
        } else {
            const auto keys = quats(c["keys"]);
            const quaternion_spline<double> curve(keys, options_of(c, false));
            const auto canon = quats(c["keys_canonical"]);
            ASSERT_EQ(curve.keys().size(), canon.size());
            for (std::size_t k = 0; k < canon.size(); ++k) EXPECT_LE(ref_qdiff(curve.keys()[k], canon[k]), 4e-16) << "key " << k;
            const auto ge = c["grid_exact"].get<std::vector<double>>();
            ASSERT_EQ(curve.grid().size(), ge.size());
            // The grid: atan2 angles agree with the exact grid to a few ulps of its
            // values (the package's acos grid does not: lib_grid_inaccurate).
            for (std::size_t k = 0; k < ge.size(); ++k) EXPECT_NEAR(curve.grid()[k], ge[k], 1e-14 * (1 + ge.back())) << "knot " << k;
            check([&](std::size_t seg, double t) { return curve.evaluate_on(seg, t, 1); }, s["q_exact"], s["omega_exact"], samples);
            if (!c["doc_natural"].is_null()) {
                const quaternion_spline<double> doc(keys, options_of(c, true));
                check([&](std::size_t seg, double t) { return doc.evaluate_on(seg, t, 1); }, c["doc_natural"]["q_exact"],
                      c["doc_natural"]["omega_exact"], doc_samples);
            }
        }
        ++per_class[cls];
    }
    // The file's own counts (about.counts): every case was run.
    EXPECT_EQ(per_class["slerp"], 2);
    EXPECT_EQ(per_class["PiecewiseSlerp"], 6);
    EXPECT_EQ(per_class["CatmullRom"], 17);
    EXPECT_EQ(per_class["KochanekBartels"], 9);
    EXPECT_EQ(per_class["BarryGoldman"], 7);
    EXPECT_EQ(per_class["Squad"], 6);
    EXPECT_EQ(per_class["DeCasteljau"], 5);
    EXPECT_GE(samples, 500);
    EXPECT_GE(doc_samples, 100);
    std::printf("quaternion_splines.json: %d samples, %d documented-natural samples\n", samples, doc_samples);
}

// SciPy's RotationSpline, converged: rotations to 1e-12 (up to sign), body
// rates and accelerations to 1e-10 of their scale (the largest |rate|,
// |accel| in the case, at least 1); and the acceleration jump at every key
// at rounding: at most 1e-9 of the acceleration scale (the C2 solve's own
// residual, and the jump measured from the two segments' evaluations).
TEST(RotationReference, ScipyRotationSplineConverged) {
    const json d = load("rotation_spline_scipy.json");
    int cases = 0, samples = 0, slerps = 0;
    for (const auto& c : d["cases"]) {
        const std::string name = c["name"];
        SCOPED_TRACE(name);
        const auto times = c["times"].get<std::vector<double>>();
        const auto keys = quats(c["keys"]);
        const auto ts = c["t"].get<std::vector<double>>();
        if (c["class"] == "Slerp") {
            // Piecewise slerp on the given times, short way per step.
            rotation_options<double> o;
            o.kind = spline_kind::piecewise_slerp;
            o.grid = times;
            const quaternion_spline<double> curve(keys, o);
            for (std::size_t k = 0; k < ts.size(); ++k) EXPECT_LE(ref_qdiff_sign(curve(ts[k]), to_quat(c["q"][k])), 1e-12) << k;
            ++slerps;
            continue;
        }
        const c2_rotation_spline<double> s(times, keys);
        const auto& ref = c["converged"];
        double rate_scale = 1, accel_scale = 1;
        for (std::size_t k = 0; k < ts.size(); ++k) {
            rate_scale = std::max(rate_scale, crspline::max_abs(to_vec(ref["rate"][k])));
            accel_scale = std::max(accel_scale, crspline::max_abs(to_vec(ref["accel"][k])));
        }
        for (std::size_t k = 0; k < ts.size(); ++k) {
            const auto j = s.evaluate(ts[k], 2, frame::body);
            EXPECT_LE(ref_qdiff_sign(j.q, to_quat(ref["q"][k])), 1e-12) << "t " << ts[k];
            EXPECT_LE(crspline::max_abs(j.omega - to_vec(ref["rate"][k])), 1e-10 * rate_scale) << "t " << ts[k];
            EXPECT_LE(crspline::max_abs(j.alpha - to_vec(ref["accel"][k])), 1e-10 * accel_scale) << "t " << ts[k];
            ++samples;
        }
        EXPECT_LE(s.residual(), 1e-9 * accel_scale) << "iterations " << s.iterations();
        for (std::size_t k = 1; k + 1 < times.size(); ++k) {
            const auto before = s.evaluate_on(k - 1, times[k], 2, frame::body), after = s.evaluate_on(k, times[k], 2, frame::body);
            EXPECT_LE(crspline::max_abs(before.alpha - after.alpha), 1e-9 * accel_scale) << "key " << k;
        }
        ++cases;
    }
    EXPECT_EQ(cases, 8);
    EXPECT_EQ(slerps, 3);
    EXPECT_GE(samples, 8 * 26);
}
