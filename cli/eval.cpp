// crspline eval: positions and derivatives at given parameter values.
#include <span>
#include <string>
#include <vector>

#include <crspline/arc_length.hpp>

#include "commands.hpp"
#include "dispatch.hpp"
#include "json_input.hpp"

namespace crspline::cli {

namespace {

template <std::size_t D>
output_json points_json(const std::vector<vec<D, double>>& pts, std::size_t dimension) {
    output_json a = output_json::array();
    for (const auto& p : pts) a.push_back(coords(p, dimension));
    return a;
}

}  // namespace

output_json run_eval(const document& input) {
    const eval_spec spec = parse_eval(input);
    return with_dimension(spec.curve.dimension, [&](auto dim) {
        constexpr std::size_t D = decltype(dim)::value;
        const catmull_rom<D, double> curve = make_curve<D>(spec.curve);

        // 0. Arc lengths instead of t: each s in [0, length], then t of s.
        output_json out;
        std::vector<double> t_of_s;
        if (spec.s) {
            const arc_length_table<D, double> table(curve, spec.accuracy);
            for (std::size_t i = 0; i < spec.s->size(); ++i)
                if (!((*spec.s)[i] >= 0 && (*spec.s)[i] <= table.total()))
                    throw input_error(spec.s_name + "[" + std::to_string(i) + "]: s = " + format_number((*spec.s)[i]) +
                                      " is outside the arc-length range [0, " + format_number(table.total()) + "]");
            t_of_s = table.t_at(std::span<const double>(*spec.s));
        }
        const std::vector<double>& t = spec.s ? t_of_s : spec.t;

        // 1. Every t inside the domain, reported by its index in the input.
        const double lo = curve.t_min(), hi = curve.t_max();
        for (std::size_t i = 0; i < spec.t.size(); ++i)
            if (!(spec.t[i] >= lo && spec.t[i] <= hi))
                throw input_error(spec.t_name + "[" + std::to_string(i) + "]: t = " + format_number(spec.t[i]) +
                                  " is outside the domain [" + format_number(lo) + ", " + format_number(hi) + "]");

        // 2. One array of points per requested order, in the order requested.
        out["grid"] = std::vector<double>(curve.grid().begin(), curve.grid().end());
        output_json values = output_json::object();
        for (const int order : spec.derivatives)
            values[std::to_string(order)] = points_json<D>(curve.evaluate(std::span<const double>(t), order), spec.curve.dimension);
        if (spec.s) out["t_of_s"] = t_of_s;
        out["values"] = std::move(values);
        return out;
    });
}

}  // namespace crspline::cli
