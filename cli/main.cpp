// crspline: the command line front end of the crspline library.
//
//   crspline eval    [INPUT]  positions and derivatives at parameter values
//   crspline bezier  [INPUT]  Bézier control points of every segment
//   crspline length  [INPUT]  arc lengths
//   crspline sample  [INPUT]  points evenly spaced, or within a tolerance
//   crspline analyze [INPUT]  cusps, self-intersections, distances, certificate
//   crspline plot    [INPUT]  a figure (SVG / PNG through cairo)
//   crspline demo             the paper's comparison: figure and table
//
// Reads one JSON object or CSV/TSV points (INPUT, or stdin for '-' or none),
// writes JSON, CSV, SVG or PNG to stdout or to -o FILE. Exit status: 0 on success, 2 on any input or usage error, with one
// line "crspline: <what, where, which value>" on stderr and nothing on stdout.
// Status 1 is never used.
#include <exception>
#include <iostream>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <string_view>
#include <crspline/crspline.hpp>

#include "commands.hpp"
#include "csv_input.hpp"
#include "json_input.hpp"
#include "options.hpp"
#include "plot.hpp"
#include "rotation_input.hpp"

namespace {

constexpr int exit_usage = 2;  // bad input or bad command line

// Length of the valid UTF-8 sequence starting at s[i], or 0.
std::size_t utf8_length(const std::string& s, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char c = byte(i);
    std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    if (n == 0 || i + n > s.size()) return 0;
    for (std::size_t k = 1; k < n; ++k)
        if ((byte(i + k) >> 6) != 0x2) return 0;
    return n;
}

int fail(const std::string& message) {
    // One line of valid UTF-8, whatever the source of the message (a parser
    // message quotes the raw input): line breaks become spaces, bytes that are
    // not UTF-8 become <0xHH>.
    std::string line;
    for (std::size_t i = 0; i < message.size();) {
        const std::size_t n = utf8_length(message, i);
        if (n == 0) {
            static const char hex[] = "0123456789ABCDEF";
            const auto c = static_cast<unsigned char>(message[i]);
            line += std::string("<0x") + hex[c >> 4] + hex[c & 0xF] + ">";
            i += 1;
        } else {
            const char c = message[i];
            line += (c == '\n' || c == '\r') ? std::string(" ") : message.substr(i, n);
            i += n;
        }
    }
    std::cerr << "crspline: " << line << '\n';
    return exit_usage;
}

using namespace crspline::cli;

// --- the command line before CLI11 reads it ---------------------------------------

// Edit distance (insertions, deletions, substitutions, adjacent swaps).
std::size_t distance(std::string_view a, std::string_view b) {
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
        for (std::size_t j = 1; j <= b.size(); ++j) {
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

// The nearest name within a third of the word's length (at least 1, at
// most 3 edits), or "" when none is that near.
std::string nearest(std::string_view word, const std::vector<std::string>& names) {
    std::string best;
    std::size_t best_d = std::min<std::size_t>(3, std::max<std::size_t>(1, word.size() / 3)) + 1;
    for (const std::string& n : names)
        if (const std::size_t k = distance(word, n); k < best_d) best_d = k, best = n;
    return best;
}

// Checks the subcommand and the long options before CLI11 parses them, so
// that a typo is named as one with the nearest correct word ("crspline
// lenght", "--aplha"), not reported as a missing subcommand or a stray
// input file. Rewrites plot's "--comb 5" and "--ticks 0.5" (an optional
// value that is a number) to --comb-scale / --tick-step, so that the value
// is neither taken for the input file nor the input file for the value.
// Returns the arguments to parse, or throws input_error.
std::vector<std::string> preflight(int argc, char** argv, const CLI::App& app) {
    std::vector<std::string> args(argv, argv + argc);
    std::size_t at = 1;
    while (at < args.size() && args[at].size() > 1 && args[at][0] == '-') ++at;  // --help, --version
    if (at >= args.size()) return args;
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(sub->get_name());
    const std::string& word = args[at];
    if (std::find(names.begin(), names.end(), word) == names.end()) {
        std::string list;
        for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
        const std::string near = nearest(word, names);
        throw input_error("unknown command '" + word + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)") +
                          "; the commands are " + list + " (see 'crspline --help')");
    }
    const CLI::App* sub = app.get_subcommand(word);
    std::vector<std::string> options = {"--help"};
    for (const CLI::Option* opt : sub->get_options())
        for (const std::string& l : opt->get_lnames()) options.push_back("--" + l);
    for (std::size_t i = at + 1; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "--") break;
        if (a.rfind("--", 0) != 0) continue;
        const std::string name = a.substr(0, a.find('='));
        if (std::find(options.begin(), options.end(), name) == options.end()) {
            const std::string near = nearest(name, options);
            throw input_error("unknown option " + name + " for 'crspline " + word + "'" +
                              (near.empty() ? "" : " (did you mean " + near + "?)") + "; see 'crspline " + word +
                              " --help'");
        }
        if (word == "plot" && (a == "--comb" || a == "--ticks") && i + 1 < args.size() &&
            crspline::cli::parse_number(args[i + 1])) {
            args[i] = (a == "--comb" ? "--comb-scale=" : "--tick-step=") + args[i + 1];
            args.erase(args.begin() + std::ptrdiff_t(i) + 1);
        }
    }
    return args;
}

// --- many curves ------------------------------------------------------------------------

// A CSV field: quoted when it holds the separator, a quote or a line break.
std::string csv_field(const std::string& s, char sep) {
    if (s.find_first_of(std::string(1, sep) + "\"\r\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

// --format geojson of a many-curve input (sample): the polyline of one curve
// as GeoJSON positions. A closed curve's last sample is its first point to
// rounding; GeoJSON rings repeat the first position exactly (RFC 7946,
// 3.1.6), so the last is made a copy of the first.
output_json geojson_positions(const output_json& out, const document& doc) {
    output_json points = out.at("points");
    const std::size_t dim = points.empty() ? 0 : points[0].size();
    if (dim != 2 && dim != 3)
        throw input_error("--format geojson: needs 2-D or 3-D points, got " + std::to_string(dim) +
                          "-D (use json or csv)");
    const bool closed = (doc.root.contains("end") && doc.root["end"] == "closed") ||
                        (doc.root.contains("closed") && doc.root["closed"] == true) || (doc.flags && doc.flags->closed);
    if (closed && points.size() >= 2) points.back() = points.front();
    return points;
}

// Drops every "bbox" member: the boxes of the input do not bound the
// sampled polylines.
void drop_bboxes(output_json& v) {
    if (v.is_object()) {
        v.erase("bbox");
        for (auto& [key, member] : v.items()) drop_bboxes(member);
    } else if (v.is_array()) {
        for (auto& member : v) drop_bboxes(member);
    }
}

// The many curves' polylines as one FeatureCollection (docs/cli.md, MANY
// CURVES). From GeoJSON: the input itself, each curve's positions replaced
// by its polyline where they were, so ids, properties, foreign members and
// the structure (a Polygon's rings, a Multi* geometry's parts, a
// GeometryCollection) come back as they came in; a Feature or a bare
// geometry is wrapped in a FeatureCollection. From other inputs (a JSON
// list, SVG paths, CSV blocks): one Feature per curve, a LineString, with
// the curve's id and properties.
output_json feature_collection(const loaded_input& in, std::vector<output_json> lines) {
    if (!in.geojson.is_null()) {
        output_json root(in.geojson);
        for (std::size_t i = 0; i < in.curves.size(); ++i)
            root[output_json::json_pointer(*in.curves[i].geojson_pointer)] = std::move(lines[i]);
        drop_bboxes(root);
        const std::string type = root["type"].get<std::string>();
        if (type == "FeatureCollection") return root;
        output_json fc = {{"type", "FeatureCollection"}, {"features", output_json::array()}};
        if (type == "Feature") {
            fc["features"].push_back(std::move(root));
        } else {
            output_json f = {{"type", "Feature"}, {"properties", nullptr}};
            f["geometry"] = std::move(root);
            fc["features"].push_back(std::move(f));
        }
        return fc;
    }
    output_json fc = {{"type", "FeatureCollection"}, {"features", output_json::array()}};
    for (std::size_t i = 0; i < in.curves.size(); ++i) {
        const document& doc = in.curves[i];
        output_json f = {{"type", "Feature"}};
        f["id"] = doc.source_id.is_null() ? output_json(doc.id) : output_json(doc.source_id);
        f["properties"] = output_json(doc.properties);
        f["geometry"] = {{"type", "LineString"}, {"coordinates", std::move(lines[i])}};
        fc["features"].push_back(std::move(f));
    }
    return fc;
}

// Runs the command on every curve of a many-curve input, in input order,
// and joins the results (docs/cli.md, "MANY CURVES"): JSON, a list of
// {"id", "properties", "result"}; CSV/TSV, one table with the curve's id in
// a first column "curve"; svg-path, one line of path data per curve;
// geojson, one FeatureCollection (feature_collection); svg, the figure of
// an input that holds one curve (a figure shows one curve). Every
// error names the input and the curve; nothing is written unless all
// curves succeed.
std::string run_many(const command& cmd, const std::string& format, const loaded_input& in,
                     const number_format& numbers) {
    if (format == "svg" && in.curves.size() != 1)
        throw input_error("--format svg: one curve per figure, and " + in.name + " holds " +
                          std::to_string(in.curves.size()) + " curves (use json, csv or svg-path)");
    const char sep = format == "tsv" ? '\t' : ',';
    std::string text;
    output_json list = output_json::array();
    std::vector<output_json> lines;  // geojson: each curve's polyline
    std::vector<std::string> notes;
    for (std::size_t i = 0; i < in.curves.size(); ++i) {
        const document& doc = in.curves[i];
        const std::string where = in.name + ": curve " + doc.id + ": ";
        try {
            const output_json out = cmd.run(doc);
            for (const std::string& note : doc.notes) notes.push_back(where + note);
            if (format == "json") {
                output_json item;
                item["id"] = doc.id;
                if (!doc.properties.is_null()) item["properties"] = doc.properties;
                item["result"] = out;
                list.push_back(std::move(item));
                continue;
            }
            if (format == "geojson") {
                lines.push_back(geojson_positions(out, doc));
                continue;
            }
            const std::string one = convert_output(cmd.name, format, out, doc, numbers);
            if (format == "svg-path" || format == "svg") {  // svg: the one curve's figure
                text += one;
                continue;
            }
            // CSV/TSV: the header once, each row after the curve's id.
            std::size_t pos = 0, row = 0;
            while (pos < one.size()) {
                const std::size_t nl = one.find('\n', pos);
                const std::string line = one.substr(pos, nl - pos);
                pos = nl == std::string::npos ? one.size() : nl + 1;
                if (row++ == 0) {
                    if (i == 0) text += "curve" + std::string(1, sep) + line + "\n";
                    continue;
                }
                text += csv_field(doc.id, sep) + sep + line + "\n";
            }
        } catch (const input_error& e) {
            throw input_error(where + e.what());
        } catch (const crspline::invalid_input& e) {
            throw input_error(where + e.what());
        } catch (const crspline::out_of_domain& e) {
            throw input_error(where + e.what());
        }
    }
    for (const std::string& note : notes) std::cerr << "crspline: note: " << note << '\n';
    if (format == "geojson") return render(feature_collection(in, std::move(lines)), numbers) ;
    return format == "json" ? render(list) : text;
}

// The options of one subcommand, in groups for its --help.
void add_options(CLI::App* sub, std::string_view name, cli_options& o) {
    if (name == "demo") {
        sub->add_option("-o,--output", o.output, "Folder for demo.svg and demo.png (default: the current folder)");
        return;
    }
    sub->add_option("input", o.input, "Input file (JSON, CSV or TSV); '-' or absent reads stdin");
    const std::string in = "Input", out = "Output", curve = "Curve", work = "What to compute", fig = "Figure";
    sub->add_option("--input-format", o.input_format, "json, csv, tsv or svg (default: by extension, else by content)")->group(in);
    sub->add_option("--columns", o.columns, "CSV columns to read: names (x,y) or numbers from 1 (2,3)")->group(in);
    sub->add_option("--delimiter", o.delimiter, "CSV delimiter: , ; | : tab space (default: detected)")->group(in);
    sub->add_option("--curve-column", o.curve_column,
                    "CSV column naming the curve of each row (many curves per file): a name or a number from 1")
        ->group(in);
    sub->add_option("-o,--output", o.output, "Output file (default: stdout); written whole or not at all")->group(out);
    std::string formats;
    for (const command& c : commands())
        if (c.name == name) formats = std::string(c.formats);
    sub->add_option("--format", o.format, "Output format: " + formats + " (default: by extension of -o, else the first)")
        ->group(out);
    sub->add_option("--alpha", o.alpha,
                    name == "plot" ? "Knot exponents in [0, 1], one curve each: 0,0.5,1" : "Knot exponent in [0, 1] (default 0.5)")
        ->group(curve);
    sub->add_flag("--uniform", o.uniform, "alpha = 0")->group(curve);
    sub->add_flag("--centripetal", o.centripetal, "alpha = 0.5")->group(curve);
    sub->add_flag("--chordal", o.chordal, "alpha = 1")->group(curve);
    sub->add_option("--grid", o.grid, "Explicit knots: a list 0,1,2.5 or a file (instead of alpha)")->group(curve);
    sub->add_flag("--closed", o.closed, "A closed curve")->group(curve);
    sub->add_option("--start", o.start, "Start condition: natural, reflect or a tangent dx/dt like 1,0")->group(curve);
    sub->add_option("--end", o.end, "End condition: natural, reflect or a tangent dx/dt like 1,0")->group(curve);
    sub->add_option("--tension", o.tension, "Tension in [0, 1]: tangents scaled by 1 - tension")->group(curve);
    sub->add_option("--kb-tension", o.kb_tension, "Kochanek-Bartels tension per point: a list or a file")->group(curve);
    sub->add_option("--kb-continuity", o.kb_continuity, "Kochanek-Bartels continuity per point")->group(curve);
    sub->add_option("--kb-bias", o.kb_bias, "Kochanek-Bartels bias per point")->group(curve);
    sub->add_flag("--strict", o.strict, "Reject coincident consecutive points")->group(curve);
    if (name == "eval") {
        sub->add_option("--t", o.t, "Parameter values: a list 0,0.5,1 or a file")->group(work);
        sub->add_option("--s", o.s, "Arc lengths from the start instead of t: a list or a file")->group(work);
        sub->add_option("--derivatives", o.derivatives, "Orders to evaluate, 0..3: 0,1")->group(work);
    }
    if (name == "sample") {
        sub->add_option("--count", o.count, "Number of points, >= 2")->group(work);
        sub->add_option("--spacing", o.spacing, "t or arc_length (with --count)")->group(work);
        sub->add_option("--tolerance", o.tolerance, "Largest distance of the polyline to the curve")->group(work);
    }
    if (name == "eval" || name == "length" || name == "sample")
        sub->add_option("--accuracy", o.accuracy, "Relative accuracy of arc lengths (default 1e-12)")->group(work);
    if (name == "eval") {
        sub->add_option("--u", o.u, "Normalised parameters in [0, 1], each segment an equal share (three.js getPoint)")
            ->group(work);
        sub->add_option("--arc-fraction", o.arc_fraction, "Fractions of the arc length in [0, 1] (three.js getPointAt)")
            ->group(work);
        sub->add_flag("--knots", o.knots, "Include the knot grid in the JSON output")->group(out);
    }
    if (name == "analyze") {
        sub->add_flag("--summary", o.summary, "Counts only (cusps, loops, intersections, overlaps), no lists")->group(work);
        sub->add_flag("--no-intersections", o.no_search, "Skip the search for self-intersections (the slow part)")
            ->group(work);
    }
    if (name == "eval" || name == "bezier" || name == "length" || name == "sample")
        sub->add_option("--precision", o.precision,
                        "Significant digits of output numbers, 1..17 (default: the shortest text that reads back "
                        "exactly)")
            ->group(out);
    if (name == "plot") {
        sub->add_option("--title", o.title, "Figure title")->group(fig);
        sub->add_option("--size", o.size, "Figure size in pixels, WIDTHxHEIGHT (default 900x640)")->group(fig);
        sub->add_option("--png", o.png, "Also write a PNG to this file")->group(fig);
        sub->add_flag("--cusps", o.cusps, "Mark cusps")->group(fig);
        sub->add_flag("--intersections", o.intersections, "Mark self-intersections")->group(fig);
        sub->add_flag("--volumes", o.volumes, "Draw the paper's bounding volumes")->group(fig);
        sub->add_flag("--comb", o.comb_on, "Draw a curvature comb")->group(fig);
        sub->add_option("--comb-scale", o.comb, "Length of a comb tooth per unit curvature (default: auto)")->group(fig);
        sub->add_flag("--handles", o.handles, "Draw the Bezier handles")->group(fig);
        sub->add_flag("--ticks", o.ticks_on, "Draw arc-length ticks")->group(fig);
        sub->add_option("--tick-step", o.ticks, "Arc length between ticks (default: auto)")->group(fig);
        sub->add_flag("--all", o.all_overlays, "All overlays")->group(fig);
        sub->add_option("--aspect", o.aspect, "equal (one scale, for geometry; default) or auto (each axis fitted)")
            ->group(fig);
        sub->add_option("--xlim", o.xlim, "Visible x range A,B (default: fitted to the data)")->group(fig);
        sub->add_option("--ylim", o.ylim, "Visible y range A,B (default: fitted to the data)")->group(fig);
        sub->add_flag("--no-points", o.no_points, "No point markers (they shrink with density otherwise)")->group(fig);
        sub->add_option("--pair", o.pair,
                        "Of 3-D and higher points, the two coordinates drawn, I,J counted from 1 (default 1,2): the "
                        "projection of the whole curve")
            ->group(fig);
    }
}

}  // namespace

namespace crspline::cli { int smooth_main(int argc, char** argv); }  // smooth.cpp: crspline smooth (issue 29)
namespace crspline::cli { int fit_main(int argc, char** argv); }     // fit.cpp: crspline fit (issue 40)
namespace crspline::cli { int sweep_main(int argc, char** argv); }   // sweep.cpp: crspline sweep (issue 41)
namespace crspline::cli { int stroke_main(int argc, char** argv); }  // sweep.cpp: crspline stroke (issue 41)

int main(int argc, char** argv) {
    using namespace crspline::cli;
    if (argc > 1 && std::string_view(argv[1]) == "smooth") return smooth_main(argc - 1, argv + 1);
#ifdef CRSPLINE_CLI_FIT
    if (argc > 1 && std::string_view(argv[1]) == "fit") return fit_main(argc - 1, argv + 1);
#endif
#ifdef CRSPLINE_CLI_SWEEP
    if (argc > 1 && std::string_view(argv[1]) == "sweep") return sweep_main(argc - 1, argv + 1);
    if (argc > 1 && std::string_view(argv[1]) == "stroke") return stroke_main(argc - 1, argv + 1);
#endif

    CLI::App app{std::string("crspline ") + crspline::version +
                 ": cubic Catmull-Rom curves through points in 1 to 16 dimensions. "
                 "Reads JSON or CSV points, writes JSON, CSV, SVG or PNG.",
                 "crspline"};
    app.set_version_flag("--version", std::string("crspline ") + crspline::version, "Print the version and exit");
    app.require_subcommand(1);
    app.footer(
        "What crspline does (each with its page under docs/):\n"
        "  curves          eval, bezier, length, sample, plot: a curve through the points, its\n"
        "                  derivatives, arc length, Bezier form and figures (docs/cli.md)\n"
        "  decision        analyze: cusps and self-intersections, and a proved verdict on\n"
        "                  crossings: simple, crosses or touches (docs/analysis.md)\n"
        "  rotations       eval, sample on a \"rotations\" file: quaternion splines, SciPy's C2\n"
        "                  spline, pose curves (docs/rotation.md)\n"
        "  GIS smoothing   smooth: GeoJSON lines and polygons smoothed, shared borders and\n"
        "                  containment kept, proved (docs/geo.md)\n"
        "  fit             fit: the fewest control points within a proved tolerance of dense\n"
        "                  or noisy samples (docs/fit.md)\n"
        "  sweeps/strokes  sweep, stroke: tubes and roads along a 3-D curve as meshes, a 2-D\n"
        "                  curve's outline as polygons (docs/sweep.md)\n"
        "  rotation fit    the fewest keys within an angle of an orientation stream (Python and\n"
        "                  C++: crspline.rotation.fit, docs/rotation.md)\n"
        "Example:\n"
        "  echo '{\"points\": [[0, 0], [1, 1], [2, 0]], \"t\": [0, 0.5, 1]}' | crspline eval\n"
        "  crspline bezier curve.json\n"
        "  crspline plot --alpha 0,0.5,1 --cusps --intersections points.csv -o figure.png\n"
        "  crspline demo\n"
        "Run 'crspline COMMAND --help' for the input fields and options of a command and examples.\n"
        "Exit status: 0 on success, 2 on bad input (one line on stderr naming the file and line, or\n"
        "the field or option).");

    cli_options o;
    std::vector<std::pair<CLI::App*, const command*>> subcommands;
    for (const command& c : commands()) {
        CLI::App* sub = app.add_subcommand(std::string(c.name), std::string(c.summary));
        add_options(sub, c.name, o);
        sub->footer(std::string(c.details));
        subcommands.emplace_back(sub, &c);
    }

    try {
        std::vector<std::string> args;
        try {
            args = preflight(argc, argv, app);
        } catch (const input_error& e) {
            return fail(e.what());
        }
        std::vector<char*> argp;
        for (std::string& a : args) argp.push_back(a.data());
        app.parse(int(argp.size()), argp.data());
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version: printed to stdout
        return fail(std::string(e.what()) + " (see 'crspline --help')");
    }

    const command* chosen = nullptr;
    for (const auto& [sub, c] : subcommands)
        if (sub->parsed()) chosen = c;
    if (!chosen) return fail("no command given (see 'crspline --help')");
    o.command = std::string(chosen->name);

    try {
        if (chosen->name == "demo") return run_demo(o);
        if (chosen->name == "plot") return run_plot(o);
        // Streamed or built whole; nothing is left behind on failure.
        std::vector<std::string> formats;
        for (std::size_t b = 0, e; b < chosen->formats.size(); b = e + 1) {
            e = chosen->formats.find(' ', b);
            if (e == std::string_view::npos) e = chosen->formats.size();
            formats.emplace_back(chosen->formats.substr(b, e - b));
        }
        const std::string format = output_format(o, formats, "json");
        const number_format numbers{precision_of(o)};
        const loaded_input in = load_input(o);
        if (!in.many) {
            const document& doc = in.curves.front();
            // The notes (a dropped ring repeat, the columns read) are made
            // while the command reads the document.
            const auto notes = [&] {
                for (const std::string& note : doc.notes) std::cerr << "crspline: note: " << note << '\n';
            };
            if (format == "svg" && is_rotation_document(doc))  // issue 28: no figure of a rotation file
                throw input_error("--format svg: a rotation curve file gives json, csv or tsv");
            if (chosen->stream && format != "svg") {
                // Written as computed: -o FILE through a temporary file renamed
                // when complete; stdout after its first MiB (output_stream.hpp).
                output_stream out(o.output);
                chosen->stream(doc, {format, numbers}, out);
                notes();
                out.commit();
                return 0;
            }
            const output_json out = chosen->run(doc);
            const std::string bytes = convert_output(chosen->name, format, out, doc, numbers);
            notes();
            write_output(o.output, bytes);
            return 0;
        }
        write_output(o.output, run_many(*chosen, format, in, numbers));
        return 0;
    } catch (const input_error& e) {
        return fail(e.what());
    } catch (const crspline::invalid_input& e) {  // what() names the index and the value
        return fail(e.what());
    } catch (const crspline::out_of_domain& e) {
        return fail(e.what());
    } catch (const std::bad_alloc&) {
        return fail("out of memory");
    } catch (const std::exception& e) {
        return fail(std::string("internal error: ") + e.what());
    }
}
