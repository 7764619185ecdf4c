// crspline command line: figures. `crspline plot` and `crspline demo` build
// a figure description from the library's results (figure_curve: exact
// Bezier segments and overlays, in data coordinates) and render_figure draws
// it with cairo, on an SVG or a PNG surface.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "json_input.hpp"
#include "options.hpp"

namespace crspline::cli {

using figure_point = std::array<double, 2>;

struct rgb {
    double r = 0, g = 0, b = 0;
};

/// One curve and its overlays, in data coordinates.
struct figure_curve {
    std::string label;
    rgb colour;
    std::vector<std::array<figure_point, 4>> bezier;  ///< exact segments
    std::vector<figure_point> cusps, intersections;
    std::vector<std::array<figure_point, 4>> boxes;              ///< bounding-volume rectangles
    std::vector<std::pair<figure_point, double>> balls;          ///< bounding-volume discs
    std::vector<std::pair<figure_point, figure_point>> comb;     ///< curvature comb: base, tip
    std::vector<std::pair<figure_point, figure_point>> ticks;    ///< arc-length ticks: point, unit normal
    bool handles = false;
};

struct figure {
    std::string title, subtitle;
    std::vector<figure_point> points;
    bool closed = false;
    std::vector<figure_curve> curves;
    int width = 900, height = 640;
    bool equal_aspect = true;                    ///< one scale for both axes (geometry); false: each axis fitted
    std::optional<std::array<double, 2>> xlim, ylim;  ///< visible data ranges (default: fitted to the data)
    std::string xlabel = "x", ylabel = "y";
    bool point_markers = true;                   ///< dots at the points, sized by their density
};

/// What to overlay on each curve.
struct overlay_options {
    bool cusps = false, intersections = false, volumes = false, comb = false, handles = false, ticks = false;
    std::optional<double> comb_scale, tick_step;
};

/// The figure data of one 2-D curve (alpha: the curve's own, for labels and
/// the bounding volumes; nullopt with an explicit grid).
figure_curve make_figure_curve(const curve_spec& spec, const overlay_options& overlays);

/// Label and colour for a curve with this alpha ("uniform (α = 0)", red).
std::pair<std::string, rgb> curve_style(std::optional<double> alpha, std::size_t index);

/// The figure as SVG or PNG bytes ("svg" | "png").
std::string render_figure(const figure& f, const std::string& format);

int run_plot(const cli_options& o);
int run_demo(const cli_options& o);

}  // namespace crspline::cli
