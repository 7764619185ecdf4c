// crspline command line: drawing a figure with cairo (SVG and PNG surfaces).
// Axes with equal scales fitted to the data, light grid, tick labels, a
// title, a legend placed in the emptiest corner; curves as exact cubic
// Béziers (cairo_curve_to), never sampled.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <cairo-svg.h>
#include <cairo.h>

#include "json_input.hpp"
#include "plot.hpp"

namespace crspline::cli {

namespace {

struct view {
    double x0, y0, x1, y1;         // visible data range
    double px0, py0, px1, py1;     // plot area in pixels
    double sx, sy;                 // pixels per data unit on each axis (equal for --aspect equal)
    double X(double x) const { return px0 + (x - x0) * sx; }
    double Y(double y) const { return py1 - (y - y0) * sy; }
};

// Text for the SVG output: cairo's SVG surface writes glyphs as outlines,
// so text is collected here and written as <text> elements (editable, and
// searchable), at the places cairo would have drawn it.
struct svg_text {
    std::string text;
    double x, y, size, rotate;
    bool bold;
    rgb colour;
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

// Draws s with cairo, or records it in `text_sink` (the SVG output) when given.
void text_at(cairo_t* cr, std::vector<svg_text>* text_sink, const std::string& s, double x, double y, double ax, double ay, bool vertical = false) {
    cairo_text_extents_t e;
    cairo_text_extents(cr, s.c_str(), &e);
    // Baseline start of the text, in its own (possibly rotated) frame.
    const double bx = -ax * e.width - e.x_bearing, by = -ay * e.height - e.y_bearing;
    const double gx = vertical ? x + by : x + bx, gy = vertical ? y - bx : y + by;
    if (text_sink) {
        cairo_matrix_t m;
        cairo_get_font_matrix(cr, &m);
        double r = 0, g = 0, b = 0, a = 1;
        cairo_pattern_get_rgba(cairo_get_source(cr), &r, &g, &b, &a);
        const bool bold = cairo_toy_font_face_get_weight(cairo_get_font_face(cr)) == CAIRO_FONT_WEIGHT_BOLD;
        text_sink->push_back({s, gx, gy, m.yy, vertical ? -90.0 : 0.0, bold, {r, g, b}});
        return;
    }
    cairo_save(cr);
    cairo_move_to(cr, gx, gy);
    if (vertical) cairo_rotate(cr, -M_PI / 2);
    cairo_show_text(cr, s.c_str());
    cairo_restore(cr);
    cairo_new_path(cr);
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

void draw(cairo_t* cr, const figure& f, std::vector<svg_text>* texts) {
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
    if (f.equal_aspect) {
        const double pad = 0.06 * std::max({dx, dy, 1e-300});
        if (dx == 0 && dy == 0) dx = dy = 1;
        x0 -= pad, x1 += pad, y0 -= pad, y1 += pad;
    } else {
        // Each axis fitted on its own (a price against a year): padded by
        // its own span, or by a tenth of its value when the span is zero.
        const auto pad = [](double& a, double& b) {
            const double d = b - a, p = d > 0 ? 0.06 * d : std::max(0.1 * std::abs(a), 0.5);
            a -= p, b += p;
        };
        pad(x0, x1), pad(y0, y1);
    }
    if (f.xlim) x0 = (*f.xlim)[0], x1 = (*f.xlim)[1];
    if (f.ylim) y0 = (*f.ylim)[0], y1 = (*f.ylim)[1];

    // 2. Plot area and the scales: equal and centred, or one per axis.
    const bool subtitle = !f.subtitle.empty();
    view v{};
    v.px0 = 64, v.px1 = W - 24, v.py0 = subtitle ? 64 : 48, v.py1 = H - 44;
    if (f.equal_aspect) {
        v.sx = v.sy = std::min((v.px1 - v.px0) / (x1 - x0), (v.py1 - v.py0) / (y1 - y0));
        const double cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
        v.x0 = cx - (v.px1 - v.px0) / 2 / v.sx, v.x1 = cx + (v.px1 - v.px0) / 2 / v.sx;
        v.y0 = cy - (v.py1 - v.py0) / 2 / v.sy, v.y1 = cy + (v.py1 - v.py0) / 2 / v.sy;
    } else {
        v.sx = (v.px1 - v.px0) / (x1 - x0), v.sy = (v.py1 - v.py0) / (y1 - y0);
        v.x0 = x0, v.x1 = x1, v.y0 = y0, v.y1 = y1;
    }

    // 3. Background, grid, axes with tick labels.
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    const double step = nice_step(std::max(v.x1 - v.x0, v.y1 - v.y0), 10);
    const double xstep = f.equal_aspect ? step : nice_step(v.x1 - v.x0, 10);
    const double ystep = f.equal_aspect ? step : nice_step(v.y1 - v.y0, 8);
    cairo_set_line_width(cr, 1);
    cairo_set_font_size(cr, 11);
    for (double k = std::ceil(v.x0 / xstep); k * xstep <= v.x1; k += 1) {
        const double x = k * xstep;
        set(cr, light);
        cairo_move_to(cr, std::round(v.X(x)) + 0.5, v.py0);
        cairo_line_to(cr, std::round(v.X(x)) + 0.5, v.py1);
        cairo_stroke(cr);
        set(cr, black);
        text_at(cr, texts, label_of(x, xstep), v.X(x), v.py1 + 6, 0.5, 0);
    }
    for (double k = std::ceil(v.y0 / ystep); k * ystep <= v.y1; k += 1) {
        const double y = k * ystep;
        set(cr, light);
        cairo_move_to(cr, v.px0, std::round(v.Y(y)) + 0.5);
        cairo_line_to(cr, v.px1, std::round(v.Y(y)) + 0.5);
        cairo_stroke(cr);
        set(cr, black);
        text_at(cr, texts, label_of(y, ystep), v.px0 - 6, v.Y(y), 1, 0.5);
    }
    set(cr, black);
    cairo_rectangle(cr, v.px0, v.py0, v.px1 - v.px0, v.py1 - v.py0);
    cairo_stroke(cr);
    text_at(cr, texts, f.xlabel, (v.px0 + v.px1) / 2, H - 8, 0.5, 1);
    text_at(cr, texts, f.ylabel, 12, (v.py0 + v.py1) / 2, 0.5, 0.5, f.ylabel.size() > 1);

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
            // A disc of the data, an ellipse when the axes' scales differ.
            cairo_new_sub_path(cr);
            cairo_save(cr);
            cairo_translate(cr, v.X(p[0]), v.Y(p[1]));
            cairo_scale(cr, v.sx, v.sy);
            cairo_arc(cr, 0, 0, r, 0, 2 * M_PI);
            cairo_restore(cr);
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
    // Point markers: 3.5 px, smaller as the points crowd the plot area (each
    // marker's disc about a tenth of the area per point), down to 0.6 px.
    set(cr, black);
    const double dot = std::clamp(0.18 * std::sqrt((v.px1 - v.px0) * (v.py1 - v.py0) / double(std::max<std::size_t>(f.points.size(), 1))), 0.6, 3.5);
    if (f.point_markers)
        for (const auto& p : f.points) {
            cairo_new_sub_path(cr);
            cairo_arc(cr, v.X(p[0]), v.Y(p[1]), dot, 0, 2 * M_PI);
        }
    cairo_fill(cr);
    // Crossings (o) and cusps (x) in the colour of their curve.
    for (const auto& c : f.curves) {
        set(cr, c.colour);
        cairo_set_line_width(cr, 2);
        for (const auto& p : c.intersections) {
            cairo_new_sub_path(cr);
            cairo_arc(cr, v.X(p[0]), v.Y(p[1]), 7, 0, 2 * M_PI);
        }
        cairo_stroke(cr);
        cairo_set_line_width(cr, 2.4);
        for (const auto& p : c.cusps) cross_mark(cr, v.X(p[0]), v.Y(p[1]), 6);
        cairo_stroke(cr);
    }
    cairo_restore(cr);

    // 5. Title.
    set(cr, black);
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    cairo_set_font_size(cr, 16);
    text_at(cr, texts, f.title, W / 2, 14, 0.5, 0);
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    if (subtitle) {
        cairo_set_font_size(cr, 12);
        text_at(cr, texts, f.subtitle, W / 2, 38, 0.5, 0);
    }

    // 6. Legend: the curves, then the marks that are drawn.
    struct entry {
        std::string text;
        int kind;  // 0 curve, 1 polygon, 2 cusp, 3 intersection, 4 volume
        rgb colour;
    };
    std::vector<entry> entries;
    bool any_cusp = false, any_meet = false, any_volume = false;
    rgb cusp_key = cusp_colour, meet_key = meet_colour;  // one curve's colour when only one has them
    int cusp_curves = 0, meet_curves = 0;
    for (const auto& c : f.curves) {
        entries.push_back({c.label, 0, c.colour});
        if (!c.cusps.empty()) cusp_key = c.colour, ++cusp_curves;
        if (!c.intersections.empty()) meet_key = c.colour, ++meet_curves;
        any_cusp |= !c.cusps.empty();
        any_meet |= !c.intersections.empty();
        any_volume |= !c.boxes.empty();
    }
    if (cusp_curves > 1) cusp_key = cusp_colour;
    if (meet_curves > 1) meet_key = meet_colour;
    entries.push_back({"control polygon", 1, grey});
    if (any_cusp) entries.push_back({cusp_curves > 1 ? "cusp (colour of its curve)" : "cusp", 2, cusp_key});
    if (any_meet)
        entries.push_back({meet_curves > 1 ? "self-intersection (colour of its curve)" : "self-intersection", 3, meet_key});
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
        text_at(cr, texts, e.text, x + 32, y, 0, 0.5);
    }
}

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}

}  // namespace

std::string render_figure(const figure& f, const std::string& format) {
    std::string bytes;
    std::vector<svg_text> texts;
    cairo_surface_t* surface = format == "png"
                                   ? cairo_image_surface_create(CAIRO_FORMAT_ARGB32, f.width, f.height)
                                   : cairo_svg_surface_create_for_stream(append, &bytes, f.width, f.height);
    // The SVG's width and height in pixels, as --size gives them (cairo's
    // default unit is pt, which browsers show a third larger).
    if (format != "png") cairo_svg_surface_set_document_unit(surface, CAIRO_SVG_UNIT_PX);
    cairo_t* cr = cairo_create(surface);
    draw(cr, f, format == "png" ? nullptr : &texts);
    const cairo_status_t status = cairo_status(cr);
    cairo_destroy(cr);
    if (format == "png") cairo_surface_write_to_png_stream(surface, append, &bytes);
    cairo_surface_finish(surface);
    const cairo_status_t surface_status = cairo_surface_status(surface);
    cairo_surface_destroy(surface);
    if (status != CAIRO_STATUS_SUCCESS || surface_status != CAIRO_STATUS_SUCCESS)
        throw input_error(std::string("cannot draw the figure: ") +
                          cairo_status_to_string(status != CAIRO_STATUS_SUCCESS ? status : surface_status));
    if (format != "png") {
        // The text as <text> elements, on top of the drawing.
        const auto escape = [](const std::string& t) {
            std::string e;
            for (char c : t) {
                if (c == '&') e += "&amp;";
                else if (c == '<') e += "&lt;";
                else if (c == '>') e += "&gt;";
                else if (c == '"') e += "&quot;";
                else e += c;
            }
            return e;
        };
        std::string g = "<g id=\"text\" font-family=\"DejaVu Sans, sans-serif\">\n";
        for (const auto& t : texts) {
            char head[256];
            std::snprintf(head, sizeof head, "<text x=\"%.2f\" y=\"%.2f\" font-size=\"%g\"%s fill=\"rgb(%d,%d,%d)\"", t.x, t.y,
                          t.size, t.bold ? " font-weight=\"bold\"" : "", int(std::lround(t.colour.r * 255)),
                          int(std::lround(t.colour.g * 255)), int(std::lround(t.colour.b * 255)));
            g += head;
            if (t.rotate != 0) {
                char rot[96];
                std::snprintf(rot, sizeof rot, " transform=\"rotate(%g %.2f %.2f)\"", t.rotate, t.x, t.y);
                g += rot;
            }
            g += " xml:space=\"preserve\">" + escape(t.text) + "</text>\n";
        }
        g += "</g>\n";
        const std::size_t end = bytes.rfind("</svg>");
        if (end != std::string::npos) bytes.insert(end, g);
    }
    return bytes;
}

}  // namespace crspline::cli
