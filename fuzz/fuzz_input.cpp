// libFuzzer target and shared entry point: the CLI's input parsers (JSON with
// the flat points fast path, CSV/TSV, option number lists) and the JSON
// contract's validation, down to building the curve and running the
// subcommand. See fuzz/README.md.
#include "fuzz_input.hpp"

#include <string>

#include <crspline/error.hpp>

#include "commands.hpp"
#include "csv_input.hpp"
#include "json_input.hpp"

namespace {

// Keeps the work per input small: a subcommand on a huge curve is slow, not wrong.
constexpr std::size_t max_input = 1 << 16;

void run_document(unsigned mode, const crspline::cli::document& doc) {
    using namespace crspline::cli;
    if (mode % 5 == 3) {
        // sample: a count of 10^9 or a tolerance of 1e-300 is slow, not wrong.
        const auto& r = doc.root;
        if (!r.is_object() || r.contains("tolerance")) return;
        if (r.contains("count") && !(r["count"].is_number() && r["count"].get<double>() <= 1000)) return;
    }
    switch (mode % 5) {
        case 0: render(run_bezier(doc)); break;
        case 1: render(run_eval(doc)); break;
        case 2: render(run_length(doc)); break;
        case 3: render(run_sample(doc)); break;
        case 4: convert_output("bezier", "csv", run_bezier(doc), doc); break;
    }
}

}  // namespace

int crspline_fuzz_one(const std::uint8_t* data, std::size_t size) {
    using namespace crspline::cli;
    if (size == 0 || size > max_input) return 0;
    const unsigned mode = data[0];
    input_text in{"<fuzz>", std::string(reinterpret_cast<const char*>(data) + 1, size - 1)};
    try {
        switch ((mode >> 4) % 4) {
            case 0: {  // JSON document, fast points path, one subcommand
                run_document(mode, parse_json_document(in));
                break;
            }
            case 1: {  // the same text through the tree only: both paths must agree
                document d;
                d.root = parse_json(in);
                run_document(mode, d);
                break;
            }
            case 2: {  // CSV, auto or chosen columns, then a subcommand
                csv_options c;
                if (mode & 1) c.columns = {"2", "1"};
                if (mode & 2) c.delimiter = ';';
                document d;
                d.points = parse_csv(in, c);
                run_document(mode >> 2, d);
                break;
            }
            case 3: {  // an option's number list
                number_list("--grid", in.text, mode & 1, false);
                break;
            }
        }
    } catch (const input_error&) {
    } catch (const crspline::invalid_input&) {
    } catch (const crspline::out_of_domain&) {
    }
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return crspline_fuzz_one(data, size);
}
