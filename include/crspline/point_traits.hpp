// crspline: adapting user point types at the boundary.
//
// The library works on vec<D, T> inside. A user type P is accepted when
// point_traits<P> says, at compile time, its dimension and scalar type, how to
// read a component and how to build a P from components. Provided here:
// std::array<T, D>, T[D], vec<D, T>, fixed-size Eigen column vectors and glm
// vectors (detected by their members; neither header is included). For a
// struct of your own with operator[], write
//
//   template <> struct crspline::point_traits<my_point>
//       : crspline::subscript_point_traits<my_point, 2, double> {};
//
// A type whose size is only known at run time (std::vector) is rejected at
// compile time: the traits must know D statically.
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <type_traits>

#include "vec.hpp"

namespace crspline {

template <class P, class Enable = void>
struct point_traits;  // undefined: not a point type

/// Traits for a default-constructible type with a fixed dimension and
/// `operator[]` for reading and writing components.
template <class P, std::size_t D, class T>
struct subscript_point_traits {
    static constexpr std::size_t dimension = D;
    using scalar = T;
    static T get(const P& p, std::size_t i) { return static_cast<T>(p[i]); }
    static P make(const std::array<T, D>& c) {
        P p{};
        for (std::size_t i = 0; i < D; ++i) p[i] = c[i];
        return p;
    }
};

template <class T, std::size_t D>
struct point_traits<std::array<T, D>> {
    static constexpr std::size_t dimension = D;
    using scalar = T;
    static T get(const std::array<T, D>& p, std::size_t i) { return p[i]; }
    static std::array<T, D> make(const std::array<T, D>& c) { return c; }
};

template <std::size_t D, class T>
struct point_traits<vec<D, T>> {
    static constexpr std::size_t dimension = D;
    using scalar = T;
    static T get(const vec<D, T>& p, std::size_t i) { return p[i]; }
    static vec<D, T> make(const std::array<T, D>& c) { return vec<D, T>{c}; }
};

namespace detail {
// Eigen: Matrix<T, N, 1> with N fixed (> 0).
template <class P>
concept eigen_fixed_vector = requires {
    typename P::Scalar;
    { P::RowsAtCompileTime } -> std::convertible_to<int>;
    { P::ColsAtCompileTime } -> std::convertible_to<int>;
} && (P::RowsAtCompileTime > 0) && (P::ColsAtCompileTime == 1);

// glm: vec<L, T, Q> with a static constexpr length() and value_type.
template <class P>
concept glm_vector = requires(P p) {
    typename P::value_type;
    { P::length() } -> std::convertible_to<int>;
    p[0];
} && !eigen_fixed_vector<P> && (P::length() > 0);
}  // namespace detail

template <class P>
struct point_traits<P, std::enable_if_t<detail::eigen_fixed_vector<P>>>
    : subscript_point_traits<P, std::size_t(P::RowsAtCompileTime), typename P::Scalar> {
    static P make(const std::array<typename P::Scalar, P::RowsAtCompileTime>& c) {
        P p;
        for (int i = 0; i < P::RowsAtCompileTime; ++i) p[i] = c[std::size_t(i)];
        return p;
    }
};

template <class P>
struct point_traits<P, std::enable_if_t<detail::glm_vector<P>>>
    : subscript_point_traits<P, std::size_t(P::length()), typename P::value_type> {
    static typename P::value_type get(const P& p, std::size_t i) {
        return p[static_cast<typename P::length_type>(i)];
    }
    static P make(const std::array<typename P::value_type, std::size_t(P::length())>& c) {
        P p{};
        for (int i = 0; i < P::length(); ++i) p[i] = c[std::size_t(i)];
        return p;
    }
};

/// A type the traits know: fixed dimension, floating-point scalar.
template <class P>
concept point_like = requires(const P& p) {
    { point_traits<P>::dimension } -> std::convertible_to<std::size_t>;
    typename point_traits<P>::scalar;
    { point_traits<P>::get(p, std::size_t{0}) } -> std::convertible_to<typename point_traits<P>::scalar>;
};

template <point_like P>
inline constexpr std::size_t dimension_of = point_traits<P>::dimension;

template <point_like P>
using scalar_of = std::conditional_t<std::is_floating_point_v<typename point_traits<P>::scalar>,
                                     typename point_traits<P>::scalar, double>;

/// Read a user point into the library's value type.
template <point_like P, class T = scalar_of<P>>
vec<dimension_of<P>, T> to_vec(const P& p) {
    vec<dimension_of<P>, T> r;
    for (std::size_t i = 0; i < dimension_of<P>; ++i) r[i] = static_cast<T>(point_traits<P>::get(p, i));
    return r;
}

/// Build a user point from the library's value type.
template <point_like P, std::size_t D, class T>
P from_vec(const vec<D, T>& v) {
    static_assert(D == dimension_of<P>, "crspline: point type has the wrong dimension");
    using S = typename point_traits<P>::scalar;
    std::array<S, D> c;
    for (std::size_t i = 0; i < D; ++i) c[i] = static_cast<S>(v[i]);
    return point_traits<P>::make(c);
}

}  // namespace crspline
