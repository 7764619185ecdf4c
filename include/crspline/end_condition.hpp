// crspline: end conditions of an open curve, chosen per end.
#pragma once

#include <cstddef>

#include "vec.hpp"

namespace crspline {

/// What happens at one end of an open curve. The peers chose three different
/// defaults (splines: natural, three.js: reflect, d3: zero tangent), so
/// crspline makes the choice visible at the call site; ours is natural.
template <std::size_t D, class T = double>
struct end_condition {
    enum class kind {
        natural,  ///< zero second derivative at the end
        reflect,  ///< phantom point 2 P0 - P1 with the first knot interval (three.js)
        tangent,  ///< the given first derivative dx/dt, taken as is
    };
    kind type = kind::natural;
    vec<D, T> velocity{};  ///< dx/dt at the end, for kind::tangent

    static constexpr end_condition natural() noexcept { return {kind::natural, {}}; }
    static constexpr end_condition reflect() noexcept { return {kind::reflect, {}}; }
    static constexpr end_condition tangent(const vec<D, T>& dxdt) noexcept { return {kind::tangent, dxdt}; }
    friend constexpr bool operator==(const end_condition&, const end_condition&) = default;
};

}  // namespace crspline
