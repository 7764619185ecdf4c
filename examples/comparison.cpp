// Uniform, centripetal and chordal Catmull-Rom curves on one control polygon,
// drawn as an SVG figure (the one at the top of the README).
//
// The polygon has a very short edge between two long ones that keep going
// (where the uniform curve loops) and sharp turns between long edges (where
// the chordal curve swings far from the polygon). The centripetal curve does
// neither: Yuksel, Schaefer and Keyser prove it has no cusp or loop within a
// segment and stays close to the polygon.
//
// Usage: comparison [output.svg]    (default comparison.svg)
//
// The SVG is written by hand: each curve segment is one exact cubic Bézier
// command (`C`) from curve.bezier(i), so the figure shows the curve itself,
// not a sampled approximation.

#include <crspline/crspline.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace {

using point = crspline::vec<2>;
using curve = crspline::catmull_rom<2>;

// The control polygon.
const std::vector<point> polygon = {
    {{0.0, 0.0}}, {{1.0, 5.0}}, {{7.0, 6.0}}, {{7.6, 5.9}}, {{14.0, 5.0}},
    {{15.0, 0.5}}, {{10.5, 1.8}}, {{11.0, 0.0}},
};

struct style {
    double alpha;
    const char* name;
    const char* colour;
};
const std::array<style, 3> styles = {{
    {crspline::uniform, "uniform", "#d62728"},
    {crspline::centripetal, "centripetal", "#1f77b4"},
    {crspline::chordal, "chordal", "#2ca02c"},
}};

// Figure layout in SVG pixels.
constexpr double width = 760, height = 520;
constexpr double left = 60, right = 20, top = 50, bottom = 50;

std::string fmt(double x, int decimals = 2) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, x);
    std::string s = buf;
    // No "-0.00": a negative zero reads badly in a label.
    if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
    return s;
}

// A round tick step giving about `target` intervals over `span`.
double tick_step(double span, int target) {
    const double raw = span / target;
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * mag >= raw) return m * mag;
    return 10 * mag;
}

struct box {
    double x0 = std::numeric_limits<double>::infinity(), y0 = x0;
    double x1 = -x0, y1 = -x0;
    void add(const point& p) {
        x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]);
        y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
    }
};

void write_svg(std::ostream& out, const std::vector<curve>& curves) {
    // 1. Data bounds: a cubic Bézier lies in the hull of its control points.
    box b;
    for (const point& p : polygon) b.add(p);
    for (const curve& c : curves)
        for (const auto& seg : c.bezier())
            for (const point& q : seg) b.add(q);
    // 2. A margin of 5% each side, then an equal scale on both axes.
    const double mx = 0.05 * (b.x1 - b.x0), my = 0.05 * (b.y1 - b.y0);
    b.x0 -= mx, b.x1 += mx, b.y0 -= my, b.y1 += my;
    const double pw = width - left - right, ph = height - top - bottom;
    const double scale = std::min(pw / (b.x1 - b.x0), ph / (b.y1 - b.y0));
    const double ox = left + 0.5 * (pw - scale * (b.x1 - b.x0));
    const double oy = top + 0.5 * (ph - scale * (b.y1 - b.y0));
    // y points up: data y0 is at the bottom of the plot.
    auto X = [&](double x) { return fmt(ox + scale * (x - b.x0)); };
    auto Y = [&](double y) { return fmt(oy + scale * (b.y1 - y)); };
    auto XY = [&](const point& p) { return X(p[0]) + "," + Y(p[1]); };

    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
        << "\" viewBox=\"0 0 " << width << " " << height << "\" font-family=\"sans-serif\" font-size=\"13\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"" << width / 2 << "\" y=\"28\" text-anchor=\"middle\" font-size=\"17\">"
        << "Catmull-Rom curves through one polygon: knot intervals |P(i+1) - P(i)|^alpha</text>\n";

    // 3. Axes: a frame around the data with round ticks and labels.
    const double fx0 = ox, fx1 = ox + scale * (b.x1 - b.x0);
    const double fy0 = oy, fy1 = oy + scale * (b.y1 - b.y0);
    out << "<g stroke=\"#444\" stroke-width=\"1\" fill=\"none\">\n"
        << "<rect x=\"" << fmt(fx0) << "\" y=\"" << fmt(fy0) << "\" width=\"" << fmt(fx1 - fx0) << "\" height=\""
        << fmt(fy1 - fy0) << "\"/>\n</g>\n";
    out << "<g font-size=\"11\" fill=\"#444\">\n";
    const double sx = tick_step(b.x1 - b.x0, 8), sy = tick_step(b.y1 - b.y0, 6);
    for (double x = std::ceil(b.x0 / sx) * sx; x <= b.x1; x += sx)
        out << "<line x1=\"" << X(x) << "\" y1=\"" << fmt(fy1) << "\" x2=\"" << X(x) << "\" y2=\"" << fmt(fy1 + 5)
            << "\" stroke=\"#444\"/><text x=\"" << X(x) << "\" y=\"" << fmt(fy1 + 18)
            << "\" text-anchor=\"middle\">" << fmt(x, sx < 1 ? 1 : 0) << "</text>\n";
    for (double y = std::ceil(b.y0 / sy) * sy; y <= b.y1; y += sy)
        out << "<line x1=\"" << fmt(fx0 - 5) << "\" y1=\"" << Y(y) << "\" x2=\"" << fmt(fx0) << "\" y2=\"" << Y(y)
            << "\" stroke=\"#444\"/><text x=\"" << fmt(fx0 - 8) << "\" y=\"" << Y(y)
            << "\" dy=\"4\" text-anchor=\"end\">" << fmt(y, sy < 1 ? 1 : 0) << "</text>\n";
    out << "</g>\n";

    // 4. The control polygon: grey, dashed, with point markers.
    out << "<polyline fill=\"none\" stroke=\"#999\" stroke-width=\"1.2\" stroke-dasharray=\"6 4\" points=\"";
    for (std::size_t i = 0; i < polygon.size(); ++i) out << (i ? " " : "") << XY(polygon[i]);
    out << "\"/>\n";

    // 5. The curves: one exact cubic Bézier command per segment.
    for (std::size_t k = 0; k < curves.size(); ++k) {
        out << "<path fill=\"none\" stroke=\"" << styles[k].colour << "\" stroke-width=\"2\" d=\"M "
            << XY(curves[k].points()[0]);
        for (const auto& seg : curves[k].bezier())
            out << " C " << XY(seg[1]) << " " << XY(seg[2]) << " " << XY(seg[3]);
        out << "\"><title>" << styles[k].name << " (alpha = " << styles[k].alpha << ")</title></path>\n";
    }
    out << "<g fill=\"#333\">\n";
    for (const point& p : polygon)
        out << "<circle cx=\"" << X(p[0]) << "\" cy=\"" << Y(p[1]) << "\" r=\"3.5\"/>\n";
    out << "</g>\n";

    // 6. Legend, top right inside the frame.
    const double lx = fx1 - 190, ly = fy0 + 12;
    out << "<g>\n<rect x=\"" << fmt(lx) << "\" y=\"" << fmt(ly) << "\" width=\"178\" height=\"92\" fill=\"white\" "
        << "fill-opacity=\"0.9\" stroke=\"#ccc\"/>\n";
    for (std::size_t k = 0; k < styles.size(); ++k) {
        const double y = ly + 20 + 20 * double(k);
        out << "<line x1=\"" << fmt(lx + 10) << "\" y1=\"" << fmt(y) << "\" x2=\"" << fmt(lx + 40) << "\" y2=\""
            << fmt(y) << "\" stroke=\"" << styles[k].colour << "\" stroke-width=\"2\"/>"
            << "<text x=\"" << fmt(lx + 48) << "\" y=\"" << fmt(y + 4) << "\">" << styles[k].name
            << ", alpha = " << fmt(styles[k].alpha, 1) << "</text>\n";
    }
    const double y = ly + 80;
    out << "<line x1=\"" << fmt(lx + 10) << "\" y1=\"" << fmt(y) << "\" x2=\"" << fmt(lx + 40) << "\" y2=\"" << fmt(y)
        << "\" stroke=\"#999\" stroke-width=\"1.2\" stroke-dasharray=\"6 4\"/>"
        << "<text x=\"" << fmt(lx + 48) << "\" y=\"" << fmt(y + 4) << "\">control polygon</text>\n</g>\n";
    out << "</svg>\n";
}

}  // namespace

int main(int argc, char** argv) try {
    const std::filesystem::path path = argc > 1 ? argv[1] : "comparison.svg";

    // Build the three curves on the same points.
    std::vector<curve> curves;
    for (const style& s : styles) curves.emplace_back(std::span<const point>(polygon), curve::options_type{.alpha = s.alpha});

    // Write to a temporary file next to the target, then rename: a reader
    // never sees half a figure.
    std::filesystem::path tmp = path;
    tmp += ".tmp";
    {
        std::ofstream out(tmp);
        if (!out) throw std::runtime_error("cannot write " + tmp.string());
        write_svg(out, curves);
        out.close();
        if (!out) throw std::runtime_error("error writing " + tmp.string());
    }
    std::filesystem::rename(tmp, path);
    std::cout << "wrote " << path.string() << "\n";
    return 0;
} catch (const std::exception& e) {
    std::cerr << "comparison: " << e.what() << "\n";
    return 1;
}
