// crspline: the command line front end of the crspline library.
//
//   crspline eval   [INPUT]   positions and derivatives at parameter values
//   crspline bezier [INPUT]   Bézier control points of every segment
//
// Reads one JSON object (INPUT, or stdin for '-' or none), writes JSON to
// stdout. Exit status: 0 on success, 2 on any input or usage error, with one
// line "crspline: <what, where, which value>" on stderr and nothing on stdout.
// Status 1 is never used.
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <crspline/crspline.hpp>

#include "commands.hpp"
#include "json_input.hpp"

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

}  // namespace

int main(int argc, char** argv) {
    using namespace crspline::cli;

    CLI::App app{std::string("crspline ") + crspline::version +
                 ": cubic Catmull-Rom curves through points in 1 to 4 dimensions. "
                 "Reads one JSON object, writes JSON to stdout.",
                 "crspline"};
    app.set_version_flag("--version", std::string("crspline ") + crspline::version, "Print the version and exit");
    app.require_subcommand(1);
    app.footer(
        "Example:\n"
        "  echo '{\"points\": [[0, 0], [1, 1], [2, 0]], \"t\": [0, 0.5, 1]}' | crspline eval\n"
        "  crspline bezier curve.json\n"
        "Run 'crspline COMMAND --help' for the input fields of a command and its example.\n"
        "Exit status: 0 on success, 2 on bad input (one line on stderr naming the field).");

    std::string input = "-";
    std::vector<std::pair<CLI::App*, const command*>> subcommands;
    for (const command& c : commands()) {
        CLI::App* sub = app.add_subcommand(std::string(c.name), std::string(c.summary));
        sub->add_option("input", input, "JSON input file; '-' or absent reads stdin");
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

    try {
        // The whole output is built before anything is written.
        const std::string text = render(chosen->run(parse_json(read_input(input))));
        std::cout << text << std::flush;
        if (!std::cout) return fail("cannot write the output");
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
