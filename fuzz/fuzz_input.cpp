// libFuzzer target and shared entry point: the CLI's input parsers (JSON with
// the flat points fast path, CSV/TSV, option number lists) and the JSON
// contract's validation, down to building the curve and running the
// subcommand. See fuzz/README.md.
#include "fuzz_input.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>

#include <crspline/error.hpp>

#include "commands.hpp"
#include "csv_input.hpp"
#include "json_input.hpp"

namespace {

// Keeps the work per input small: a subcommand on a huge curve is slow, not wrong.
constexpr std::size_t max_input = 1 << 16;

// Runs one subcommand and returns its rendered output ("" when skipped).
std::string run_document(unsigned mode, const crspline::cli::document& doc) {
    using namespace crspline::cli;
    if (mode % 5 == 3) {
        // sample: a count of 10^9 or a tolerance of 1e-300 is slow, not wrong.
        const auto& r = doc.root;
        if (!r.is_object() || r.contains("tolerance")) return "";
        if (r.contains("count") && !(r["count"].is_number() && r["count"].get<double>() <= 1000)) return "";
    }
    switch (mode % 5) {
        case 0: return render(run_bezier(doc));
        case 1: return render(run_eval(doc));
        case 2: return render(run_length(doc));
        case 3: return render(run_sample(doc));
        default: return convert_output("bezier", "csv", run_bezier(doc), doc);
    }
}

// What a user would see: the output, or the kind of error and its message.
template <class F>
std::string outcome(F&& f) {
    using namespace crspline::cli;
    try {
        return "output\n" + f();
    } catch (const input_error& e) {
        return std::string("input_error\n") + e.what();
    } catch (const crspline::invalid_input& e) {
        return std::string("invalid_input\n") + e.what();
    } catch (const crspline::out_of_domain& e) {
        return std::string("out_of_domain\n") + e.what();
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
            case 1: {  // the same text through the fast path and the tree only: both must agree
                const std::string fast = outcome([&] { return run_document(mode, parse_json_document(in)); });
                const std::string tree = outcome([&] {
                    document d;
                    d.root = parse_json(in);
                    return run_document(mode, d);
                });
                if (fast != tree) {
                    std::fprintf(stderr, "fuzz: the points fast path and the JSON tree disagree\nfast: %.2000s\ntree: %.2000s\n",
                                 fast.c_str(), tree.c_str());
                    std::abort();
                }
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
