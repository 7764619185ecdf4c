// crspline: the library's exception types. User-facing errors only; internal
// invariants are debug asserts.
#pragma once

#include <stdexcept>
#include <string>

namespace crspline {

/// Bad input to a constructor or factory: non-finite coordinates, too few
/// points, alpha outside [0, 1], a grid that is not increasing or has the
/// wrong length, coincident points in strict mode, bad end conditions.
/// The message names the index and the value.
class invalid_input : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

/// A parameter outside the curve's domain in a checked call.
class out_of_domain : public std::domain_error {
public:
    using std::domain_error::domain_error;
};

}  // namespace crspline
