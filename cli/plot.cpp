// crspline plot: one or more curves through the same points, with overlays
// computed by the library (cusps, self-intersections, the paper's bounding
// volumes, a curvature comb, Bézier handles, arc-length ticks).
#include <algorithm>
#include <array>
#include <cmath>
#include <cctype>
#include <iostream>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <crspline/analysis.hpp>
#include <crspline/arc_length.hpp>
#include <crspline/certify.hpp>
#include <crspline/intersections.hpp>

#include "csv_input.hpp"
#include "dispatch.hpp"
#include "plot.hpp"

namespace crspline::cli {

namespace {

using curve2 = catmull_rom<2, double>;
figure_point fp(const vec<2, double>& p) { return {p[0], p[1]}; }

std::string trim_number(double a) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", a);
    return buf;
}

}  // namespace

std::pair<std::string, rgb> curve_style(std::optional<double> alpha, std::size_t index) {
    static const rgb palette[] = {{0.58, 0.40, 0.74}, {1.00, 0.50, 0.05}, {0.55, 0.34, 0.29},
                                  {0.89, 0.47, 0.76}, {0.74, 0.74, 0.13}, {0.09, 0.75, 0.81}};
    if (!alpha) return {"explicit grid", palette[index % 6]};
    if (*alpha == 0) return {"uniform (\u03b1 = 0)", {0.84, 0.15, 0.16}};
    if (*alpha == 0.5) return {"centripetal (\u03b1 = 0.5)", {0.12, 0.47, 0.71}};
    if (*alpha == 1) return {"chordal (\u03b1 = 1)", {0.17, 0.63, 0.17}};
    return {"\u03b1 = " + trim_number(*alpha), palette[index % 6]};
}

figure_curve make_figure_curve(const curve_spec& spec, const overlay_options& ov) {
    if (spec.dimension != 2)
        throw input_error("plot: needs 2-D points, got " + std::to_string(spec.dimension) + "-D");
    const curve2 curve = make_curve<2>(spec);
    figure_curve fc;
    for (const auto& b : curve.bezier()) fc.bezier.push_back({fp(b[0]), fp(b[1]), fp(b[2]), fp(b[3])});
    fc.handles = ov.handles;
    const auto& segs = curve.segments();

    // Scale of the figure, for automatic comb lengths and tick steps.
    const auto lo = bounding_box(curve);
    const double diag = std::max(lo.diagonal(), 1e-300);

    if (ov.cusps) {
        for (const auto& a : analyze(curve))
            for (const double u : a.cusp_u) fc.cusps.push_back(fp(segs[a.index].at(u)));
    }
    if (ov.intersections) {
        for (const auto& x : find_intersections(curve).intersections) fc.intersections.push_back(fp(x.point));
    }
    if (ov.volumes) {
        const auto vol = paper_bounding_volumes(curve);
        for (const auto& e : vol.boxes) {
            const vec<2, double> d = e.b - e.a;
            const double L = norm(d);
            if (!(L > 0)) continue;
            const vec<2, double> n{{-d[1] / L * e.half_width, d[0] / L * e.half_width}};
            const vec<2, double> p = e.a + e.lambda_min * d, q = e.a + e.lambda_max * d;
            fc.boxes.push_back({fp(p + n), fp(q + n), fp(q - n), fp(p - n)});
        }
        for (const auto& b : vol.balls) fc.balls.emplace_back(fp(b.center), b.radius);
    }
    if (ov.comb) {
        // Teeth along the outward normal, of length scale * curvature.
        struct tooth {
            vec<2, double> p, n;
            double k;
        };
        std::vector<tooth> teeth;
        constexpr int per_segment = 24;
        for (const auto& s : segs) {
            if (!(s.h > 0)) continue;
            for (int j = 0; j <= per_segment; ++j) {
                const double u = double(j) / per_segment;
                const auto d1 = s.du(u, 1), d2 = s.du(u, 2);
                const double sp = norm(d1);
                if (!(sp > 0)) continue;
                const double k = (d1[0] * d2[1] - d1[1] * d2[0]) / (sp * sp * sp);
                teeth.push_back({s.at(u), vec<2, double>{{-d1[1] / sp, d1[0] / sp}}, k});
            }
        }
        double scale = ov.comb_scale.value_or(0);
        if (!ov.comb_scale && !teeth.empty()) {
            // The 90th percentile of |k| gets a tooth of a tenth of the diagonal.
            std::vector<double> ks;
            for (const auto& t : teeth) ks.push_back(std::abs(t.k));
            std::nth_element(ks.begin(), ks.begin() + std::ptrdiff_t(ks.size() * 9 / 10), ks.end());
            const double k90 = ks[ks.size() * 9 / 10];
            scale = k90 > 0 ? 0.1 * diag / k90 : 0;
        }
        for (const auto& t : teeth) {
            const double len = std::clamp(-scale * t.k, -0.25 * diag, 0.25 * diag);
            fc.comb.emplace_back(fp(t.p), fp(t.p + len * t.n));
        }
    }
    if (ov.ticks) {
        const arc_length_table<2, double> table(curve, 1e-9);
        const double total = table.total();
        double step = ov.tick_step.value_or(0);
        if (!ov.tick_step) {
            const double raw = total / 25, mag = std::pow(10.0, std::floor(std::log10(raw)));
            step = mag;
            for (double m : {1.0, 2.0, 5.0, 10.0})
                if (m * mag >= raw) {
                    step = m * mag;
                    break;
                }
        }
        if (total > 0 && step > 0 && total / step <= 100000) {
            for (double s = 0; s <= total; s += step) {
                const double t = table.t_at(std::min(s, total));
                const auto p = curve.evaluate(t), d = curve.evaluate(t, 1);
                const double sp = norm(d);
                if (sp > 0) fc.ticks.emplace_back(fp(p), figure_point{-d[1] / sp, d[0] / sp});
            }
        }
    }
    return fc;
}

namespace {

// --pair "I,J": two different coordinates of a `dimension`-D point,
// counted from 1; returned from 0.
std::array<std::size_t, 2> pair_option(const std::string& text, std::size_t dimension) {
    const auto comma = text.find(',');
    const auto a = comma == std::string::npos ? std::nullopt : parse_number(text.substr(0, comma));
    const auto b = comma == std::string::npos ? std::nullopt : parse_number(text.substr(comma + 1));
    const auto valid = [dimension](const std::optional<double>& x) {
        return x && *x >= 1 && *x <= double(dimension) && *x == std::floor(*x);
    };
    if (!valid(a) || !valid(b) || *a == *b)
        throw input_error("--pair: expected two different coordinates I,J from 1 to " + std::to_string(dimension) +
                          ", got '" + text + "'");
    return {std::size_t(*a) - 1, std::size_t(*b) - 1};
}

// The projection on coordinates (i, j) of the curve `full` describes: each
// coordinate of a Catmull-Rom curve is the 1-D curve of that coordinate on
// the same knots (the tangents, ends, tension and Kochanek-Bartels values
// act on each coordinate alone), so the plane curve through the projected
// points on the full curve's knots is the projection (up to the rounding
// of the knots' running sums).
curve_spec projection(const curve_spec& full, std::array<std::size_t, 2> pair) {
    if (!full.tangents_out.empty())
        throw input_error("plot: a curve with given tangents is drawn in 2-D only (choose two columns with --columns)");
    const std::size_t d = full.dimension, n = full.point_count();
    curve_spec p = full;
    p.dimension = 2;
    p.points.clear();
    for (std::size_t i = 0; i < n; ++i) p.points.insert(p.points.end(), {full.points[i * d + pair[0]], full.points[i * d + pair[1]]});
    for (auto* e : {&p.start, &p.end})
        if (e->type == crspline::end_spec::kind::tangent) e->velocity = {e->velocity[pair[0]], e->velocity[pair[1]]};
    p.grid = with_dimension(d, [&](auto dim) {
        const auto curve = make_curve<decltype(dim)::value>(full);
        const auto g = curve.grid();
        return std::vector<double>(g.begin(), g.end());
    });
    p.alpha.reset();
    // Coincidence was judged on the whole points (strict); projected points
    // may meet where the curve's do not.
    p.strict = false;
    for (std::size_t k = 1; k < p.grid->size(); ++k)
        if (!((*p.grid)[k] > (*p.grid)[k - 1]))
            throw input_error("plot: the curve has coincident consecutive points (knots " + std::to_string(k - 1) +
                              " and " + std::to_string(k) + " are equal); its projection cannot be drawn: choose "
                              "two coordinates with --columns, or alpha 0");
    return p;
}

// --xlim / --ylim: "A,B" with A < B, finite.
std::array<double, 2> range_option(const std::string& option, const std::string& text) {
    const auto comma = text.find(',');
    const auto a = comma == std::string::npos ? std::nullopt : parse_number(text.substr(0, comma));
    const auto b = comma == std::string::npos ? std::nullopt : parse_number(text.substr(comma + 1));
    if (!a || !b || !(*a < *b))
        throw input_error(option + ": expected two increasing numbers A,B, got '" + text + "'");
    return {*a, *b};
}

}  // namespace

int run_plot(const cli_options& o) {
    const std::string format = output_format(o, {"svg", "png"}, "svg");
    // --png FILE writes PNG bytes: a name that says otherwise is refused.
    if (!o.png.empty()) {
        std::string ext = std::filesystem::path(o.png).extension().string();
        for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
        if (ext != ".png")
            throw input_error("--png: writes a PNG file, but " + o.png + " does not end in .png (for SVG use -o)");
    }
    const loaded_input in = load_input(o);
    figure f;
    if (!o.size.empty()) {
        int w = 0, h = 0;
        char x = 0, extra = 0;
        if (std::sscanf(o.size.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') || w < 200 ||
            h < 150 || w > 10000 || h > 10000)
            throw input_error("--size: expected WIDTHxHEIGHT in pixels, 200x150 to 10000x10000, got '" + o.size + "'");
        f.width = w, f.height = h;
    }
    if (!o.aspect.empty() && o.aspect != "equal" && o.aspect != "auto")
        throw input_error("--aspect: expected equal or auto, got '" + o.aspect + "'");
    f.equal_aspect = o.aspect != "auto";
    if (!o.xlim.empty()) f.xlim = range_option("--xlim", o.xlim);
    if (!o.ylim.empty()) f.ylim = range_option("--ylim", o.ylim);
    f.point_markers = !o.no_points;
    // Axis labels: the names of the two coordinate columns in a CSV file's
    // header (whether chosen with --columns or not); "x" and "y" otherwise,
    // and for a column without a name.
    if (const auto& pts = in.curves.front().points; pts && pts->column_names.size() == 2) {
        if (!pts->column_names[0].empty()) f.xlabel = pts->column_names[0];
        if (!pts->column_names[1].empty()) f.ylabel = pts->column_names[1];
    }
    overlay_options ov;
    ov.cusps = o.cusps || o.all_overlays;
    ov.intersections = o.intersections || o.all_overlays;
    ov.volumes = o.volumes || o.all_overlays;
    ov.comb = o.comb_on || !o.comb.empty() || o.all_overlays;
    ov.handles = o.handles || o.all_overlays;
    ov.ticks = o.ticks_on || !o.ticks.empty() || o.all_overlays;
    auto positive = [](const std::string& option, const std::string& text) {
        const auto x = parse_number(text);
        if (!x || !(*x > 0) || !std::isfinite(*x))
            throw input_error(option + ": expected a number > 0, got '" + text + "'");
        return *x;
    };
    if (!o.comb.empty()) ov.comb_scale = positive("--comb-scale", o.comb);
    if (!o.ticks.empty()) ov.tick_step = positive("--tick-step", o.ticks);

    std::vector<double> alphas = alpha_values(o);
    if (!alphas.empty() && !o.grid.empty())
        throw input_error("--grid: give --grid or an alpha (--alpha, --uniform, --centripetal, --chordal), not both");
    if (in.curves.size() > 1)
        throw input_error("plot: one curve per figure, and " + in.name + " holds " + std::to_string(in.curves.size()) +
                          " curves");
    const curve_spec spec = parse_analyze(in.curves.front());
    const std::size_t dim = spec.dimension;
    if (dim < 2) throw input_error("plot: needs 2 or more coordinates per point, got 1 (choose two with --columns)");
    if (dim == 2 && !o.pair.empty()) throw input_error("--pair: for points of 3 or more coordinates; these have 2");
    // Of a 3-D or higher curve, the projection on two coordinates (1 and 2
    // unless --pair says otherwise), named on the axes and in the subtitle.
    const std::array<std::size_t, 2> pair = dim > 2 && !o.pair.empty() ? pair_option(o.pair, dim) : std::array<std::size_t, 2>{0, 1};
    if (dim > 2) {
        const auto name = [&](std::size_t k) {
            const auto& pts = in.curves.front().points;
            if (pts && pts->column_names.size() == dim && !pts->column_names[k].empty()) return pts->column_names[k];
            return dim <= 4 ? std::string(1, "xyzw"[k]) : "x" + std::to_string(k + 1);
        };
        f.xlabel = name(pair[0]), f.ylabel = name(pair[1]);
        f.subtitle = std::to_string(dim) + "-D curve shown as its projection on " + f.xlabel + ", " + f.ylabel +
                     " (coordinates " + std::to_string(pair[0] + 1) + " and " + std::to_string(pair[1] + 1) + ")";
    }
    for (std::size_t i = 0; i < spec.point_count(); ++i)
        f.points.push_back({spec.points[dim * i + pair[0]], spec.points[dim * i + pair[1]]});
    f.closed = spec.closed;
    if (alphas.empty()) alphas.push_back(spec.grid ? NAN : spec.alpha.value_or(0.5));
    for (std::size_t i = 0; i < alphas.size(); ++i) {
        curve_spec s = spec;
        std::optional<double> a;
        if (!std::isnan(alphas[i])) {
            a = alphas[i];
            s.alpha = a;
            s.grid.reset();
        }
        if (dim > 2) s = projection(s, pair);
        figure_curve c = make_figure_curve(s, ov);
        std::tie(c.label, c.colour) = curve_style(a, i);
        f.curves.push_back(std::move(c));
    }
    f.title = !o.title.empty() ? o.title
              : "Catmull-Rom " + std::string(alphas.size() > 1 ? "curves" : "curve") + " through " +
                    std::to_string(spec.point_count()) + " points";
    // Everything is drawn before anything is written.
    const std::string main_bytes = render_figure(f, format);
    const std::string png_bytes = o.png.empty() ? std::string() : render_figure(f, "png");
    write_output(o.output, main_bytes);
    if (!o.png.empty()) write_output(o.png, png_bytes);
    for (const std::string& note : in.curves.front().notes) std::cerr << "crspline: note: " << note << '\n';
    return 0;
}

}  // namespace crspline::cli
