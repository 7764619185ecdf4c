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
#include <crspline/crspline.hpp>

#include "commands.hpp"
#include "json_input.hpp"
#include "options.hpp"
#include "plot.hpp"

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

// The options of one subcommand, in groups for its --help.
void add_options(CLI::App* sub, std::string_view name, cli_options& o) {
    if (name == "demo") {
        sub->add_option("-o,--output", o.output, "Folder for demo.svg and demo.png (default: the current folder)");
        return;
    }
    sub->add_option("input", o.input, "Input file (JSON, CSV or TSV); '-' or absent reads stdin");
    const std::string in = "Input", out = "Output", curve = "Curve", work = "What to compute", fig = "Figure";
    sub->add_option("--input-format", o.input_format, "json, csv or tsv (default: by extension, else by content)")->group(in);
    sub->add_option("--columns", o.columns, "CSV columns to read: names (x,y) or numbers from 1 (2,3)")->group(in);
    sub->add_option("--delimiter", o.delimiter, "CSV delimiter: , ; | : tab space (default: detected)")->group(in);
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
    }
}

}  // namespace

int main(int argc, char** argv) {
    using namespace crspline::cli;

    CLI::App app{std::string("crspline ") + crspline::version +
                 ": cubic Catmull-Rom curves through points in 1 to 16 dimensions. "
                 "Reads JSON or CSV points, writes JSON, CSV, SVG or PNG.",
                 "crspline"};
    app.set_version_flag("--version", std::string("crspline ") + crspline::version, "Print the version and exit");
    app.require_subcommand(1);
    app.footer(
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
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version: printed to stdout
        return fail(std::string(e.what()) + " (see 'crspline --help')");
    }

    const command* chosen = nullptr;
    for (const auto& [sub, c] : subcommands)
        if (sub->parsed()) chosen = c;
    if (!chosen) return fail("no command given (see 'crspline --help')");
    o.command = std::string(chosen->name);

    std::optional<loaded_input> in;
    try {
        if (chosen->name == "demo") return run_demo(o);
        if (chosen->name == "plot") return run_plot(o);
        // The whole output is built before anything is written.
        std::vector<std::string> formats;
        for (std::size_t b = 0, e; b < chosen->formats.size(); b = e + 1) {
            e = chosen->formats.find(' ', b);
            if (e == std::string_view::npos) e = chosen->formats.size();
            formats.emplace_back(chosen->formats.substr(b, e - b));
        }
        const std::string format = output_format(o, formats, "json");
        const number_format numbers{precision_of(o)};
        in = load_input(o);
        if (chosen->stream && format != "svg") {
            // Written as computed: -o FILE through a temporary file renamed
            // when complete; stdout after its first MiB (output_stream.hpp).
            output_stream out(o.output);
            chosen->stream(in->doc, {format, numbers}, out);
            out.commit();
            return 0;
        }
        const output_json out = chosen->run(in->doc);
        write_output(o.output, convert_output(chosen->name, format, out, in->doc, numbers));
        return 0;
    } catch (const input_error& e) {
        return fail(in ? rename_fields(e.what(), *in) : std::string(e.what()));
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
