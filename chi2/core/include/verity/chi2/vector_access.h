// Reading and writing the caller's own vector and colour types, so that the adapters take
// callables written in them rather than in Verity's. A 2- or 3-vector is read through
// `.x()` methods (Eigen), `.x/.y/.z` members, or `[i]`, in that order of preference, and is
// made by default construction followed by assignment through the same accessor. A value
// (what eval() returns, a sample's weight) is a scalar or three components: those of a
// vector, or `.r/.g/.b` members. A type that none of these fit gets a specialisation of
// VectorAccess<T>. Header-only and C++17, for renderers that are not on C++20.
#pragma once

#include <Eigen/Core>
#include <type_traits>
#include <utility>

namespace verity::chi2 {

namespace detail {

template <class T, class = void>
struct HasXMethod : std::false_type {};
template <class T>
struct HasXMethod<T, std::void_t<decltype(std::declval<T&>().x())>> : std::true_type {};

template <class T, class = void>
struct HasXMember : std::false_type {};
template <class T>
struct HasXMember<T, std::void_t<decltype(std::declval<T&>().x = std::declval<T&>().x)>>
    : std::true_type {};

template <class T, class = void>
struct HasRMember : std::false_type {};
template <class T>
struct HasRMember<T, std::void_t<decltype(std::declval<T&>().r = std::declval<T&>().r)>>
    : std::true_type {};

template <class T, class = void>
struct HasIndex : std::false_type {};
template <class T>
struct HasIndex<T, std::void_t<decltype(std::declval<T&>()[0])>> : std::true_type {};

template <class>
inline constexpr bool kAlwaysFalse = false;

}  // namespace detail

// Component I (0, 1 or 2) of a vector- or colour-like T, as an lvalue of its own type.
template <class T>
struct VectorAccess {
  template <int I, class V>
  static decltype(auto) component(V& v) {
    if constexpr (detail::HasXMethod<T>::value) {
      if constexpr (I == 0)
        return (v.x());
      else if constexpr (I == 1)
        return (v.y());
      else
        return (v.z());
    } else if constexpr (detail::HasXMember<T>::value) {
      if constexpr (I == 0)
        return (v.x);
      else if constexpr (I == 1)
        return (v.y);
      else
        return (v.z);
    } else if constexpr (detail::HasRMember<T>::value) {
      if constexpr (I == 0)
        return (v.r);
      else if constexpr (I == 1)
        return (v.g);
      else
        return (v.b);
    } else if constexpr (detail::HasIndex<T>::value) {
      return (v[I]);
    } else {
      static_assert(detail::kAlwaysFalse<T>,
                    "no .x(), .x, .r or [i] on this type: specialise verity::chi2::VectorAccess");
    }
  }
  template <int I>
  static double get(const T& v) {
    return static_cast<double>(component<I>(v));
  }
  template <int I>
  static void set(T& v, double value) {
    using Scalar = std::remove_reference_t<decltype(component<I>(v))>;
    component<I>(v) = static_cast<Scalar>(value);
  }
};

template <class T>
Eigen::Vector2d readVector2(const T& v) {
  using A = VectorAccess<T>;
  return {A::template get<0>(v), A::template get<1>(v)};
}

template <class T>
Eigen::Vector3d readVector3(const T& v) {
  using A = VectorAccess<T>;
  return {A::template get<0>(v), A::template get<1>(v), A::template get<2>(v)};
}

template <class T>
T makeVector2(double x, double y) {
  using A = VectorAccess<T>;
  T v{};
  A::template set<0>(v, x);
  A::template set<1>(v, y);
  return v;
}

template <class T>
T makeVector3(const Eigen::Vector3d& p) {
  using A = VectorAccess<T>;
  T v{};
  A::template set<0>(v, p.x());
  A::template set<1>(v, p.y());
  A::template set<2>(v, p.z());
  return v;
}

// A value that is a scalar (a grey BSDF: one component, repeated) or three components.
template <class T>
struct ValueAccess {
  static constexpr int kComponents = std::is_arithmetic_v<T> ? 1 : 3;
  static Eigen::Array3d read(const T& v) {
    if constexpr (std::is_arithmetic_v<T>)
      return Eigen::Array3d::Constant(static_cast<double>(v));
    else
      return readVector3(v).array();
  }
};

}  // namespace verity::chi2
