// crspline eval: positions and derivatives at given parameter values.
#include <span>
#include <string>
#include <vector>

#include "commands.hpp"
#include "dispatch.hpp"
#include "json_input.hpp"

namespace crspline::cli {

namespace {

template <std::size_t D>
output_json points_json(const std::vector<vec<D, double>>& pts) {
    output_json a = output_json::array();
    for (const auto& p : pts) a.push_back(std::vector<double>(p.v.begin(), p.v.end()));
    return a;
}

}  // namespace

output_json run_eval(const nlohmann::json& input) {
    const eval_spec spec = parse_eval(input);
    return with_dimension(spec.curve.dimension, [&](auto dim) {
        constexpr std::size_t D = decltype(dim)::value;
        const catmull_rom<D, double> curve = make_curve<D>(spec.curve);

        // 1. Every t inside the domain, reported by its index in the input.
        const double lo = curve.t_min(), hi = curve.t_max();
        for (std::size_t i = 0; i < spec.t.size(); ++i)
            if (!(spec.t[i] >= lo && spec.t[i] <= hi))
                throw input_error("t[" + std::to_string(i) + "]: t = " + format_number(spec.t[i]) +
                                  " is outside the domain [" + format_number(lo) + ", " + format_number(hi) + "]");

        // 2. One array of points per requested order, in the order requested.
        output_json out;
        out["grid"] = std::vector<double>(curve.grid().begin(), curve.grid().end());
        output_json values = output_json::object();
        for (const int order : spec.derivatives)
            values[std::to_string(order)] = points_json<D>(curve.evaluate(std::span<const double>(spec.t), order));
        out["values"] = std::move(values);
        return out;
    });
}

}  // namespace crspline::cli
