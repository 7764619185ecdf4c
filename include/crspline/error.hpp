// crspline: the library's exception types. User-facing errors only; internal
// invariants are debug asserts.
#pragma once

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace crspline {

/// Bad input to a constructor or factory: non-finite coordinates, too few
/// points, alpha outside [0, 1], a grid that is not increasing or has the
/// wrong length, coincident points in strict mode, bad end conditions.
/// The message names the index and the value.
class invalid_input : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

/// A curve description that does not describe a curve (see spec.hpp), with
/// the pieces a front end needs to say so in its own idiom: the field of the
/// specification ("points", "alpha", "grid", "closed", "start", "end",
/// "tension", "kb.tension", "kb.continuity", "kb.bias", "strict",
/// "dimension"), the index in it (point, knot or vertex) and the coordinate
/// when there is one, the offending value as text ("" when the problem is not
/// one value) and what() the whole sentence, the same for every front end.
class spec_error : public invalid_input {
public:
    spec_error(std::string field, std::optional<std::size_t> index, std::optional<std::size_t> component,
               std::string value, const std::string& message)
        : invalid_input(message), field_(std::move(field)), index_(index), component_(component),
          value_(std::move(value)) {}
    const std::string& field() const noexcept { return field_; }
    std::optional<std::size_t> index() const noexcept { return index_; }
    std::optional<std::size_t> component() const noexcept { return component_; }
    const std::string& value() const noexcept { return value_; }

private:
    std::string field_;
    std::optional<std::size_t> index_, component_;
    std::string value_;
};

/// A parameter outside the curve's domain in a checked call.
class out_of_domain : public std::domain_error {
public:
    using std::domain_error::domain_error;
};

}  // namespace crspline
