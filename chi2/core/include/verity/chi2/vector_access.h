// Reading and writing the caller's own vector and colour types, so that the adapters take
// callables written in them rather than in Verity's. A 2- or 3-vector is read through
// `.x()` methods (Eigen), `.x/.y/.z` members, or `[i]`, in that order of preference, and is
// made by default construction followed by assignment through the same accessor. A value
// (what eval() returns, a sample's weight) has any number of components (ValueAccess below).
// A type that none of these fit gets a specialisation of VectorAccess<T>. Header-only and C++17,
// for renderers that are not on C++20.
#pragma once

#include <Eigen/Core>
#include <tuple>
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

namespace detail {

// The number of components a value type declares at compile time, or 0.
template <class T, class = void>
struct DeclaredSize : std::integral_constant<int, 0> {};
// std::array and any type the caller gave a std::tuple_size (Eigen's own size below, should
// a version of Eigen give its vectors one too).
template <class T>
struct DeclaredSize<T, std::void_t<decltype(std::tuple_size<T>::value),
                                   std::enable_if_t<!std::is_base_of_v<Eigen::EigenBase<T>, T>>>>
    : std::integral_constant<int, int(std::tuple_size<T>::value)> {};
// Eigen's fixed-size vectors and arrays (a dynamic one declares -1: read at run time).
template <class T>
struct DeclaredSize<T, std::enable_if_t<std::is_base_of_v<Eigen::EigenBase<T>, T>>>
    : std::integral_constant<
          int, T::SizeAtCompileTime == Eigen::Dynamic ? 0 : int(T::SizeAtCompileTime)> {};

template <class T, class = void>
struct HasSize : std::false_type {};
template <class T>
struct HasSize<T, std::void_t<decltype(std::declval<const T&>().size())>> : std::true_type {};

}  // namespace detail

// The number of components of a value type, when its type says so: a specialisation for a
// spectrum type that has operator[] and a size the compiler cannot see, e.g.
//   template <> struct verity::chi2::ValueSize<pbrt::SampledSpectrum>
//       : std::integral_constant<int, pbrt::NSpectrumSamples> {};
template <class T>
struct ValueSize : detail::DeclaredSize<T> {};

// A value (what eval() returns, a sample's weight) with any number of components, read into
// an Eigen::ArrayXd in this order of preference:
//   a scalar                           one component (a grey BSDF)
//   a size known at compile time       ValueSize<T> components through [i]: std::array,
//                                      Eigen's fixed vectors, a specialised ValueSize
//   .x/.y/.z or .r/.g/.b               three components (an RGB colour)
//   a run-time size() and [i]          std::vector, Eigen::VectorXd: kComponents is 0, and
//                                      checkBsdf holds every value to the size of eval at
//                                      wi's mirror direction
// A spectral value (several wavelengths) is one of the first two.
template <class T>
struct ValueAccess {
  static constexpr int kComponents =
      std::is_arithmetic_v<T>   ? 1
      : ValueSize<T>::value > 0 ? ValueSize<T>::value
      // An Eigen::VectorXd has .x() too, and any size.
      : std::is_base_of_v<Eigen::EigenBase<T>, T> ? 0
      : detail::HasXMethod<T>::value || detail::HasXMember<T>::value || detail::HasRMember<T>::value
          ? 3
          : 0;
  static Eigen::ArrayXd read(const T& v) {
    if constexpr (std::is_arithmetic_v<T>) {
      return Eigen::ArrayXd::Constant(1, static_cast<double>(v));
    } else if constexpr (kComponents == 3 && ValueSize<T>::value == 0) {
      return readVector3(v).array();
    } else if constexpr (kComponents > 0) {
      Eigen::ArrayXd out(kComponents);
      for (int i = 0; i < kComponents; ++i) out[i] = static_cast<double>(v[i]);
      return out;
    } else {
      static_assert(detail::HasSize<T>::value && detail::HasIndex<T>::value,
                    "a value is a scalar, has a size and [i], or .x/.y/.z or .r/.g/.b: "
                    "specialise verity::chi2::ValueSize or verity::chi2::ValueAccess");
      Eigen::ArrayXd out(static_cast<Eigen::Index>(v.size()));
      for (Eigen::Index i = 0; i < out.size(); ++i) out[i] = static_cast<double>(v[i]);
      return out;
    }
  }
};

}  // namespace verity::chi2
