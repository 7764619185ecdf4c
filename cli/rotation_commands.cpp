// crspline eval and sample on a rotation or pose curve file (issue 28): the
// file read by rotation_input.cpp, the curve built by the core
// (crspline/rotation/), the output written as JSON or CSV/TSV:
//   rotation: {"t": [...], ("grid": [...] with "knots": true,) "frame": "world", "quaternions": [[w, x, y, z], ...],
//              "angular_velocities": [[x, y, z], ...], "angular_accelerations": [...]}
//   pose:     {"t": [...], "frame": "world", "positions": [...], "quaternions": [...],
//              "velocities": [...], "angular_velocities": [...]}
// (each array present when its derivative order is asked; "frame" when a
// rate is written). CSV: one row per t: t, qw, qx, qy, qz, wx, wy, wz, ax, ay, az
// (pose: t, x, y, z, qw, qx, qy, qz, vx, vy, vz, wx, wy, wz).
#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include <crspline/rotation/angle_length.hpp>
#include <crspline/rotation/c2.hpp>
#include <crspline/rotation/catmull_rom.hpp>
#include <crspline/rotation/pose.hpp>

#include "commands.hpp"
#include "rotation_input.hpp"
#include "rotation_commands.hpp"

namespace crspline::cli {

namespace {

using quat = rotation::quaternion<double>;
using rotation_curve = std::variant<rotation::quaternion_spline<double>, rotation::c2_rotation_spline<double>>;

rotation::spline_kind kind_of(const std::string& k) {
    using K = rotation::spline_kind;
    if (k == "kochanek_bartels") return K::kochanek_bartels;
    if (k == "slerp") return K::piecewise_slerp;
    if (k == "barry_goldman") return K::barry_goldman;
    if (k == "squad") return K::squad;
    return K::catmull_rom;
}

rotation_curve build_rotation(const rotation_file& f) {
    const std::span<const quat> keys(f.keys);
    if (f.kind != "c2") {
        rotation::rotation_options<double> o;
        o.kind = kind_of(f.kind);
        o.alpha = f.alpha, o.grid = f.grid, o.closed = f.closed;
        o.start = f.start_cr, o.end = f.end_cr;
        o.kb = f.tcb, o.keep_signs = f.keep_signs, o.strict = f.strict;
        return rotation::quaternion_spline<double>(keys, o);
    }
    // The C2 spline takes times: the grid, or alpha's grid on the rotation
    // angle (as the Catmull-Rom family computes it), or 0, 1, 2, ...
    std::vector<double> times;
    if (f.grid) {
        times = *f.grid;
    } else if (f.alpha) {
        rotation::rotation_options<double> o;
        o.kind = rotation::spline_kind::piecewise_slerp;
        o.alpha = f.alpha, o.closed = f.closed, o.keep_signs = f.keep_signs, o.strict = f.strict;
        const rotation::quaternion_spline<double> s(keys, o);
        times.assign(s.grid().begin(), s.grid().end());
        for (std::size_t k = 1; k < times.size(); ++k)
            if (!(times[k] > times[k - 1]))
                throw input_error("alpha: keys " + std::to_string(k - 1) + " and " + std::to_string(k % f.keys.size()) +
                                  " are the same rotation, so alpha's grid has a zero interval there, which the c2 "
                                  "spline cannot take (give a grid, or alpha 0)");
    } else {
        for (std::size_t k = 0; k < f.keys.size() + (f.closed ? 1 : 0); ++k) times.push_back(double(k));
    }
    rotation::c2_options<double> o;
    o.start = f.start_c2, o.end = f.end_c2, o.closed = f.closed, o.keep_signs = f.keep_signs;
    return rotation::c2_rotation_spline<double>(std::span<const double>(times), keys, o);
}

rotation::pose_curve<double> build_pose(const rotation_file& f) {
    rotation::pose_options<double> o;
    o.alpha = f.alpha, o.grid = f.grid, o.closed = f.closed;
    o.c2_rotation = f.kind == "c2";
    return rotation::pose_curve<double>(std::span<const vec<3, double>>(f.positions), std::span<const quat>(f.keys), o);
}

}  // namespace

void stream_rotation(const document& input, const output_settings& settings, output_stream& out,
                     const std::string& command) {
    if (settings.format != "json" && settings.format != "csv" && settings.format != "tsv")
        throw input_error("--format " + settings.format + ": a rotation curve file gives json, csv or tsv");
    const rotation_file f = parse_rotation_file(input, command);
    const std::string prefix = input.file.empty() || input.file == "<stdin>" ? "" : input.file + ": ";

    // 1. The curve (the core validates alpha, the grid, the keys, the ends).
    std::optional<rotation_curve> curve;
    std::optional<rotation::pose_curve<double>> pose;
    try {
        if (f.pose()) pose.emplace(build_pose(f));
        else curve.emplace(build_rotation(f));
    } catch (const crspline::invalid_input& e) {
        throw input_error(prefix + e.what());
    }
    const std::span<const double> grid = pose ? pose->grid() : std::visit([](const auto& c) { return c.grid(); }, *curve);
    const double lo = grid.front(), hi = grid.back();

    // 2. The parameters: given (eval), or count of them in t, angle or arc length (sample).
    std::vector<double> t;
    if (command == "eval") {
        t = f.t;
        for (std::size_t i = 0; i < t.size(); ++i)
            if (!(t[i] >= lo && t[i] <= hi))
                throw input_error(prefix + f.t_name + "[" + std::to_string(i) + "]: t = " + format_number(t[i]) +
                                  " is outside the domain [" + format_number(lo) + ", " + format_number(hi) + "]");
    } else if (f.spacing == "t") {
        t.resize(f.count);
        for (std::size_t k = 0; k < f.count; ++k) t[k] = lo + (hi - lo) * (double(k) / double(f.count - 1));
        t.back() = hi;
    } else if (pose) {
        t = f.spacing == "angle" ? pose->constant_speed_times(f.count, 0, 1) : pose->constant_speed_times(f.count, 1, 0);
    } else {
        t = std::visit([&](const auto& c) { return rotation::constant_angular_speed_times(c, f.count); }, *curve);
    }

    // 3. The columns: (name in JSON, CSV headers, width).
    struct column {
        const char* key;
        std::vector<std::string> headers;
    };
    std::vector<column> columns;
    const auto asked = [&](int order) { return std::find(f.derivatives.begin(), f.derivatives.end(), order) != f.derivatives.end(); };
    const int top = *std::max_element(f.derivatives.begin(), f.derivatives.end());
    if (pose) {
        if (asked(0)) {
            columns.push_back({"positions", {"x", "y", "z"}});
            columns.push_back({"quaternions", {"qw", "qx", "qy", "qz"}});
        }
        if (asked(1)) {
            columns.push_back({"velocities", {"vx", "vy", "vz"}});
            columns.push_back({"angular_velocities", {"wx", "wy", "wz"}});
        }
    } else {
        if (asked(0)) columns.push_back({"quaternions", {"qw", "qx", "qy", "qz"}});
        if (asked(1)) columns.push_back({"angular_velocities", {"wx", "wy", "wz"}});
        if (asked(2)) columns.push_back({"angular_accelerations", {"ax", "ay", "az"}});
    }
    // The values of column c at sample i.
    const auto values = [&](std::size_t i, std::vector<std::vector<double>>& cols) {
        cols.assign(columns.size(), {});
        std::size_t c = 0;
        if (pose) {
            const auto s = pose->evaluate(t[i], f.out_frame);
            if (asked(0)) {
                cols[c++] = {s.position[0], s.position[1], s.position[2]};
                cols[c++] = {s.orientation.w, s.orientation.x, s.orientation.y, s.orientation.z};
            }
            if (asked(1)) {
                cols[c++] = {s.velocity[0], s.velocity[1], s.velocity[2]};
                cols[c++] = {s.omega[0], s.omega[1], s.omega[2]};
            }
            return;
        }
        const auto j = std::visit([&](const auto& r) { return r.evaluate(t[i], top, f.out_frame); }, *curve);
        if (asked(0)) cols[c++] = {j.q.w, j.q.x, j.q.y, j.q.z};
        if (asked(1)) cols[c++] = {j.omega[0], j.omega[1], j.omega[2]};
        if (asked(2)) cols[c++] = {j.alpha[0], j.alpha[1], j.alpha[2]};
    };

    // 4. The output.
    const number_format& nf = settings.numbers;
    std::string& buf = out.buffer();
    std::vector<std::vector<double>> cols;
    if (settings.format == "json") {
        buf += '{';
        out.json_list("t", t, nf);
        if (f.knots) {
            buf += ',';
            out.json_list("grid", grid, nf);
        }
        if (top > 0) buf += std::string(",\"frame\":\"") + (f.out_frame == rotation::frame::world ? "world" : "body") + '"';
        // One array per column: computed once per sample, held per column
        // (a row of at most 14 numbers per sample).
        std::vector<std::string> texts(columns.size());
        for (std::size_t i = 0; i < t.size(); ++i) {
            values(i, cols);
            for (std::size_t c = 0; c < columns.size(); ++c) {
                std::string& s = texts[c];
                s += i ? ",[" : "[";
                for (std::size_t k = 0; k < cols[c].size(); ++k) {
                    if (k) s += ',';
                    std::string one;
                    if (!std::isfinite(cols[c][k]))
                        output_stream::not_finite(std::string(columns[c].key) + "[" + std::to_string(i) + "][" + std::to_string(k) + "]");
                    append_json_number(one, cols[c][k], nf);
                    s += one;
                }
                s += ']';
            }
        }
        for (std::size_t c = 0; c < columns.size(); ++c) {
            buf += std::string(",\"") + columns[c].key + "\":[";
            buf += texts[c];
            buf += ']';
            out.written();
        }
        out.put("}\n");
        return;
    }
    // CSV / TSV: one row per t.
    const char sep = settings.format == "tsv" ? '\t' : ',';
    buf += 't';
    for (const column& c : columns)
        for (const std::string& h : c.headers) buf += sep + h;
    buf += '\n';
    for (std::size_t i = 0; i < t.size(); ++i) {
        values(i, cols);
        out.number(t[i], nf, false, [&] { return "t[" + std::to_string(i) + "]"; });
        for (std::size_t c = 0; c < columns.size(); ++c)
            for (std::size_t k = 0; k < cols[c].size(); ++k) {
                buf += sep;
                out.number(cols[c][k], nf, false, [&] {
                    return std::string(columns[c].key) + "[" + std::to_string(i) + "][" + std::to_string(k) + "]";
                });
            }
        buf += '\n';
        out.written();
    }
}

}  // namespace crspline::cli
