// crspline command line: drawing a figure with cairo (SVG and PNG surfaces).
// Axes with equal scales fitted to the data, light grid, tick labels, a
// title, a legend placed in the emptiest corner; curves as exact cubic
// Béziers (cairo_curve_to), never sampled.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include <cairo-svg.h>
#include <cairo.h>

#include "json_input.hpp"
#include "plot.hpp"

namespace crspline::cli {

namespace {

struct view {
    double x0, y0, x1, y1;         // visible data range
    double px0, py0, px1, py1;     // plot area in pixels
    double scale;                  // pixels per data unit (both axes)
    double X(double x) const { return px0 + (x - x0) * scale; }
    double Y(double y) const { return py1 - (y - y0) * scale; }
};

figure_point bezier_at(const std::array<figure_point, 4>& b, double u) {
    const double v = 1 - u;
    const double w0 = v * v * v, w1 = 3 * v * v * u, w2 = 3 * v * u * u, w3 = u * u * u;
    return {w0 * b[0][0] + w1 * b[1][0] + w2 * b[2][0] + w3 * b[3][0],
            w0 * b[0][1] + w1 * b[1][1] + w2 * b[2][1] + w3 * b[3][1]};
}

// A round step giving about `target` intervals over `span`.
double nice_step(double span, int target) {
    const double raw = span / target;
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * mag >= raw) return m * mag;
    return 10 * mag;
}

std::string label_of(double v, double step) {
    const int decimals = std::max(0, int(-std::floor(std::log10(step) + 1e-9)));
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", std::min(decimals, 12), std::abs(v) < step * 1e-9 ? 0.0 : v);
    return buf;
}

void set(cairo_t* cr, const rgb& c, double a = 1) { cairo_set_source_rgba(cr, c.r, c.g, c.b, a); }

void text_at(cairo_t* cr, const std::string& s, double x, double y, double ax, double ay) {
    cairo_text_extents_t e;
    cairo_text_extents(cr, s.c_str(), &e);
    cairo_move_to(cr, x - ax * e.width - e.x_bearing, y - ay * e.height - e.y_bearing);
    cairo_show_text(cr, s.c_str());
}

void cross_mark(cairo_t* cr, double x, double y, double r) {
    cairo_move_to(cr, x - r, y - r);
    cairo_line_to(cr, x + r, y + r);
    cairo_move_to(cr, x - r, y + r);
    cairo_line_to(cr, x + r, y - r);
}

void curve_path(cairo_t* cr, const view& v, const figure_curve& c) {
    for (std::size_t i = 0; i < c.bezier.size(); ++i) {
        const auto& b = c.bezier[i];
        if (i == 0) cairo_move_to(cr, v.X(b[0][0]), v.Y(b[0][1]));
        cairo_curve_to(cr, v.X(b[1][0]), v.Y(b[1][1]), v.X(b[2][0]), v.Y(b[2][1]), v.X(b[3][0]), v.Y(b[3][1]));
    }
}

void draw(cairo_t* cr, const figure& f) {
    const double W = f.width, H = f.height;
    const rgb black{0, 0, 0}, grey{0.55, 0.55, 0.55}, light{0.91, 0.91, 0.91};
    const rgb cusp_colour{0.05, 0.05, 0.05}, meet_colour{0.55, 0.0, 0.55};
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);

    // 1. Data range: points, curves (sampled for the range only), overlays.
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    auto add = [&](const figure_point& p, double r = 0) {
        x0 = std::min(x0, p[0] - r), x1 = std::max(x1, p[0] + r);
        y0 = std::min(y0, p[1] - r), y1 = std::max(y1, p[1] + r);
    };
    for (const auto& p : f.points) add(p);
    for (const auto& c : f.curves) {
        for (const auto& b : c.bezier)
            for (int k = 0; k <= 32; ++k) add(bezier_at(b, k / 32.0));
        for (const auto& b : c.boxes)
            for (const auto& p : b) add(p);
        for (const auto& [p, r] : c.balls) add(p, r);
        for (const auto& [p, q] : c.comb) add(q);
        if (c.handles)
            for (const auto& b : c.bezier) add(b[1]), add(b[2]);
    }
    if (!(x1 >= x0)) x0 = y0 = 0, x1 = y1 = 1;
    double dx = x1 - x0, dy = y1 - y0;
    const double pad = 0.06 * std::max({dx, dy, 1e-300});
    if (dx == 0 && dy == 0) dx = dy = 1;
    x0 -= pad, x1 += pad, y0 -= pad, y1 += pad;

    // 2. Plot area and equal scales, centred.
    const bool subtitle = !f.subtitle.empty();
    view v{};
    v.px0 = 64, v.px1 = W - 24, v.py0 = subtitle ? 64 : 48, v.py1 = H - 44;
    v.scale = std::min((v.px1 - v.px0) / (x1 - x0), (v.py1 - v.py0) / (y1 - y0));
    const double cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
    v.x0 = cx - (v.px1 - v.px0) / 2 / v.scale, v.x1 = cx + (v.px1 - v.px0) / 2 / v.scale;
    v.y0 = cy - (v.py1 - v.py0) / 2 / v.scale, v.y1 = cy + (v.py1 - v.py0) / 2 / v.scale;

    // 3. Background, grid, axes with tick labels.
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    const double step = nice_step(std::max(v.x1 - v.x0, v.y1 - v.y0), 10);
    cairo_set_line_width(cr, 1);
    cairo_set_font_size(cr, 11);
    for (double x = std::ceil(v.x0 / step) * step; x <= v.x1; x += step) {
        set(cr, light);
        cairo_move_to(cr, std::round(v.X(x)) + 0.5, v.py0);
        cairo_line_to(cr, std::round(v.X(x)) + 0.5, v.py1);
        cairo_stroke(cr);
        set(cr, black);
        text_at(cr, label_of(x, step), v.X(x), v.py1 + 6, 0.5, 0);
    }
    for (double y = std::ceil(v.y0 / step) * step; y <= v.y1; y += step) {
        set(cr, light);
        cairo_move_to(cr, v.px0, std::round(v.Y(y)) + 0.5);
        cairo_line_to(cr, v.px1, std::round(v.Y(y)) + 0.5);
        cairo_stroke(cr);
        set(cr, black);
        text_at(cr, label_of(y, step), v.px0 - 6, v.Y(y), 1, 0.5);
    }
    set(cr, black);
    cairo_rectangle(cr, v.px0, v.py0, v.px1 - v.px0, v.py1 - v.py0);
    cairo_stroke(cr);
    text_at(cr, "x", (v.px0 + v.px1) / 2, H - 8, 0.5, 1);
    text_at(cr, "y", 12, (v.py0 + v.py1) / 2, 0.5, 0.5);

    // 4. Inside the plot area: volumes, polygon, handles, combs, curves, marks.
    cairo_save(cr);
    cairo_rectangle(cr, v.px0, v.py0, v.px1 - v.px0, v.py1 - v.py0);
    cairo_clip(cr);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    for (const auto& c : f.curves) {
        for (const auto& b : c.boxes) {
            cairo_move_to(cr, v.X(b[0][0]), v.Y(b[0][1]));
            for (int k = 1; k < 4; ++k) cairo_line_to(cr, v.X(b[k][0]), v.Y(b[k][1]));
            cairo_close_path(cr);
        }
        for (const auto& [p, r] : c.balls) {
            cairo_new_sub_path(cr);
            cairo_arc(cr, v.X(p[0]), v.Y(p[1]), r * v.scale, 0, 2 * M_PI);
        }
        set(cr, c.colour, 0.08);
        cairo_fill_preserve(cr);
        set(cr, c.colour, 0.45);
        cairo_set_line_width(cr, 0.8);
        cairo_stroke(cr);
    }
    // Control polygon.
    set(cr, grey);
    cairo_set_line_width(cr, 1.2);
    const double dash[] = {5, 4};
    cairo_set_dash(cr, dash, 2, 0);
    for (std::size_t i = 0; i < f.points.size(); ++i)
        (i == 0 ? cairo_move_to : cairo_line_to)(cr, v.X(f.points[i][0]), v.Y(f.points[i][1]));
    if (f.closed) cairo_close_path(cr);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
    for (const auto& c : f.curves) {
        // Curvature comb: teeth and the line through their tips.
        if (!c.comb.empty()) {
            set(cr, c.colour, 0.5);
            cairo_set_line_width(cr, 0.7);
            for (const auto& [p, q] : c.comb) {
                cairo_move_to(cr, v.X(p[0]), v.Y(p[1]));
                cairo_line_to(cr, v.X(q[0]), v.Y(q[1]));
            }
            cairo_stroke(cr);
            for (std::size_t i = 0; i < c.comb.size(); ++i)
                (i == 0 ? cairo_move_to : cairo_line_to)(cr, v.X(c.comb[i].second[0]), v.Y(c.comb[i].second[1]));
            cairo_stroke(cr);
        }
        if (c.handles) {
            set(cr, c.colour, 0.8);
            cairo_set_line_width(cr, 0.8);
            for (const auto& b : c.bezier) {
                cairo_move_to(cr, v.X(b[0][0]), v.Y(b[0][1]));
                cairo_line_to(cr, v.X(b[1][0]), v.Y(b[1][1]));
                cairo_move_to(cr, v.X(b[3][0]), v.Y(b[3][1]));
                cairo_line_to(cr, v.X(b[2][0]), v.Y(b[2][1]));
            }
            cairo_stroke(cr);
            for (const auto& b : c.bezier)
                for (int k : {1, 2}) cairo_rectangle(cr, v.X(b[k][0]) - 2.5, v.Y(b[k][1]) - 2.5, 5, 5);
            cairo_fill(cr);
        }
    }
    for (const auto& c : f.curves) {
        set(cr, c.colour, 0.95);
        cairo_set_line_width(cr, 2.2);
        curve_path(cr, v, c);
        cairo_stroke(cr);
        // Arc-length ticks: short strokes across the curve.
        set(cr, c.colour);
        cairo_set_line_width(cr, 1.2);
        for (const auto& [p, n] : c.ticks) {
            cairo_move_to(cr, v.X(p[0]) - 5 * n[0], v.Y(p[1]) + 5 * n[1]);
            cairo_line_to(cr, v.X(p[0]) + 5 * n[0], v.Y(p[1]) - 5 * n[1]);
        }
        cairo_stroke(cr);
    }
    set(cr, black);
    for (const auto& p : f.points) {
        cairo_new_sub_path(cr);
        cairo_arc(cr, v.X(p[0]), v.Y(p[1]), 3.5, 0, 2 * M_PI);
    }
    cairo_fill(cr);
    for (const auto& c : f.curves) {
        set(cr, meet_colour);
        cairo_set_line_width(cr, 2);
        for (const auto& p : c.intersections) {
            cairo_new_sub_path(cr);
            cairo_arc(cr, v.X(p[0]), v.Y(p[1]), 7, 0, 2 * M_PI);
        }
        cairo_stroke(cr);
        set(cr, cusp_colour);
        cairo_set_line_width(cr, 2.4);
        for (const auto& p : c.cusps) cross_mark(cr, v.X(p[0]), v.Y(p[1]), 6);
        cairo_stroke(cr);
    }
    cairo_restore(cr);

    // 5. Title.
    set(cr, black);
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    cairo_set_font_size(cr, 16);
    text_at(cr, f.title, W / 2, 14, 0.5, 0);
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    if (subtitle) {
        cairo_set_font_size(cr, 12);
        text_at(cr, f.subtitle, W / 2, 38, 0.5, 0);
    }

    // 6. Legend: the curves, then the marks that are drawn.
    struct entry {
        std::string text;
        int kind;  // 0 curve, 1 polygon, 2 cusp, 3 intersection, 4 volume
        rgb colour;
    };
    std::vector<entry> entries;
    bool any_cusp = false, any_meet = false, any_volume = false;
    for (const auto& c : f.curves) {
        entries.push_back({c.label, 0, c.colour});
        any_cusp |= !c.cusps.empty();
        any_meet |= !c.intersections.empty();
        any_volume |= !c.boxes.empty();
    }
    entries.push_back({"control polygon", 1, grey});
    if (any_cusp) entries.push_back({"cusp", 2, cusp_colour});
    if (any_meet) entries.push_back({"self-intersection", 3, meet_colour});
    if (any_volume) entries.push_back({"bounding volumes", 4, grey});
    cairo_set_font_size(cr, 12);
    double tw = 0;
    for (const auto& e : entries) {
        cairo_text_extents_t ext;
        cairo_text_extents(cr, e.text.c_str(), &ext);
        tw = std::max(tw, ext.x_advance);
    }
    const double lw = tw + 48, lh = 18.0 * double(entries.size()) + 10;
    // The corner where the legend covers the fewest curve samples.
    double best_x = v.px1 - lw - 8, best_y = v.py0 + 8;
    int best = std::numeric_limits<int>::max();
    for (const auto& [lx, ly] : {std::pair{v.px1 - lw - 8, v.py0 + 8}, std::pair{v.px0 + 8, v.py0 + 8},
                                 std::pair{v.px1 - lw - 8, v.py1 - lh - 8}, std::pair{v.px0 + 8, v.py1 - lh - 8}}) {
        int covered = 0;
        for (const auto& c : f.curves)
            for (const auto& b : c.bezier)
                for (int k = 0; k <= 16; ++k) {
                    const auto p = bezier_at(b, k / 16.0);
                    const double X = v.X(p[0]), Y = v.Y(p[1]);
                    covered += X >= lx && X <= lx + lw && Y >= ly && Y <= ly + lh;
                }
        for (const auto& p : f.points) {
            const double X = v.X(p[0]), Y = v.Y(p[1]);
            covered += 4 * (X >= lx && X <= lx + lw && Y >= ly && Y <= ly + lh);
        }
        if (covered < best) best = covered, best_x = lx, best_y = ly;
    }
    cairo_rectangle(cr, best_x, best_y, lw, lh);
    cairo_set_source_rgba(cr, 1, 1, 1, 0.9);
    cairo_fill_preserve(cr);
    set(cr, grey);
    cairo_set_line_width(cr, 0.8);
    cairo_stroke(cr);
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const auto& e = entries[i];
        const double y = best_y + 14 + 18.0 * double(i), x = best_x + 8;
        set(cr, e.colour);
        cairo_new_path(cr);
        switch (e.kind) {
            case 0:
                cairo_set_line_width(cr, 2.2);
                cairo_move_to(cr, x, y);
                cairo_line_to(cr, x + 24, y);
                cairo_stroke(cr);
                break;
            case 1:
                cairo_set_line_width(cr, 1.2);
                cairo_set_dash(cr, dash, 2, 0);
                cairo_move_to(cr, x, y);
                cairo_line_to(cr, x + 24, y);
                cairo_stroke(cr);
                cairo_set_dash(cr, nullptr, 0, 0);
                set(cr, black);
                cairo_new_path(cr);
                cairo_arc(cr, x + 12, y, 3.5, 0, 2 * M_PI);
                cairo_fill(cr);
                break;
            case 2:
                cairo_set_line_width(cr, 2.4);
                cross_mark(cr, x + 12, y, 5);
                cairo_stroke(cr);
                break;
            case 3:
                cairo_set_line_width(cr, 2);
                cairo_arc(cr, x + 12, y, 6, 0, 2 * M_PI);
                cairo_stroke(cr);
                break;
            case 4:
                cairo_rectangle(cr, x + 2, y - 5, 20, 10);
                cairo_set_source_rgba(cr, 0.5, 0.5, 0.5, 0.15);
                cairo_fill_preserve(cr);
                set(cr, grey);
                cairo_set_line_width(cr, 0.8);
                cairo_stroke(cr);
                break;
        }
        set(cr, black);
        text_at(cr, e.text, x + 32, y, 0, 0.5);
    }
}

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}

}  // namespace

std::string render_figure(const figure& f, const std::string& format) {
    std::string bytes;
    cairo_surface_t* surface = format == "png"
                                   ? cairo_image_surface_create(CAIRO_FORMAT_ARGB32, f.width, f.height)
                                   : cairo_svg_surface_create_for_stream(append, &bytes, f.width, f.height);
    cairo_t* cr = cairo_create(surface);
    draw(cr, f);
    const cairo_status_t status = cairo_status(cr);
    cairo_destroy(cr);
    if (format == "png") cairo_surface_write_to_png_stream(surface, append, &bytes);
    cairo_surface_finish(surface);
    const cairo_status_t surface_status = cairo_surface_status(surface);
    cairo_surface_destroy(surface);
    if (status != CAIRO_STATUS_SUCCESS || surface_status != CAIRO_STATUS_SUCCESS)
        throw input_error(std::string("cannot draw the figure: ") +
                          cairo_status_to_string(status != CAIRO_STATUS_SUCCESS ? status : surface_status));
    return bytes;
}

}  // namespace crspline::cli
