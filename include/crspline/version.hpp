// crspline: library version.
#pragma once

#define CRSPLINE_VERSION_MAJOR 0
#define CRSPLINE_VERSION_MINOR 1
#define CRSPLINE_VERSION_PATCH 0

namespace crspline {
inline constexpr const char* version = "0.1.0";
}
