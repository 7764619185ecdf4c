// The builder report.hpp's writers take, making an nlohmann::json tree: one
// definition for the analysis tests that read a report as a value
// (test_report.cpp, test_decision.cpp, test_decision_report.cpp).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>

#include <nlohmann/json.hpp>

namespace crspline_test {

struct json_tree_builder {
    using value = nlohmann::json;
    value object() { return value::object(); }
    value array() { return value::array(); }
    void set(value& o, std::string_view key, value v) { o[std::string(key)] = std::move(v); }
    void push(value& a, value v) { a.push_back(std::move(v)); }
    value number(double x) { return x; }
    value integer(std::size_t n) { return n; }
    value boolean(bool f) { return f; }
    value string(std::string_view s) { return std::string(s); }
    value null() { return nullptr; }
};

}  // namespace crspline_test
