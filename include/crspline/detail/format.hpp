// crspline internal: number formatting for error messages (shortest form that
// reads back to the same value; no <format>, which libc++ 13 lacks).
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace crspline::detail {

inline std::string num(double x) {
    if (std::isnan(x)) return "nan";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    char buf[40];
    for (int prec = 6; prec <= 17; ++prec) {
        std::snprintf(buf, sizeof buf, "%.*g", prec, x);
        if (std::strtod(buf, nullptr) == x) break;
    }
    return buf;
}

inline std::string num(std::size_t i) { return std::to_string(i); }

/// An angle given in radians, in degrees to 4 significant digits (for
/// messages: "19.94", "60").
inline std::string degrees(double radians) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.4g", radians * (180 / 3.14159265358979323846));
    return buf;
}

}  // namespace crspline::detail
