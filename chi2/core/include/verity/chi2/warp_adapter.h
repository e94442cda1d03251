// Checking a sampling routine written in another renderer's own types: a warp of the unit
// square onto the square, the disk, the triangle, the hemisphere or the sphere (points and
// densities as in warp_model.h). The caller gives two callables,
//
//   sample(u) -> P or std::optional<P>   u is a Uniform2, which converts to any 2D point type
//   pdf(const P& p) -> a number          the density at p
//
// P being its own 2D point (planar domains) or 3-vector (hemisphere, sphere), read as
// vector_access.h says. checkWarp runs the chi-square test on the domain, the pdf-integral
// test and the per-sample checks (finite points, unit directions, finite non-negative pdf)
// at the caller's `significance`; see check_result.h.
//
//   CheckResult r = checkWarp(diskWarp<Vec2>(concentricDisk, diskPdf), options);
#pragma once

#include <verity/chi2/check_result.h>
#include <verity/chi2/warp_model.h>

#include <optional>
#include <string>
#include <type_traits>

namespace verity::chi2 {

namespace detail {

template <class T>
struct OptionalValue {
  using type = T;
  static bool has(const T&) { return true; }
  static const T& get(const T& t) { return t; }
};
template <class T>
struct OptionalValue<std::optional<T>> {
  using type = T;
  static bool has(const std::optional<T>& t) { return t.has_value(); }
  static const T& get(const std::optional<T>& t) { return *t; }
};

template <class P, int Dimensions, class SampleFn, class PdfFn>
WarpModel warpModel(WarpDomain domain, SampleFn sample, PdfFn pdf) {
  WarpModel m;
  m.domain = domain;
  m.sample = [sample](const Uniform2& u) -> std::optional<Eigen::Vector3d> {
    const auto s = sample(u);
    using O = OptionalValue<std::decay_t<decltype(s)>>;
    static_assert(std::is_same_v<std::decay_t<typename O::type>, P>,
                  "sample(u) must return the point type the pdf takes (or an optional of it)");
    if (!O::has(s)) return std::nullopt;
    if constexpr (Dimensions == 2) {
      const Eigen::Vector2d p = readVector2(O::get(s));
      return Eigen::Vector3d(p.x(), p.y(), 0);
    } else {
      return readVector3(O::get(s));
    }
  };
  m.pdf = [pdf](const Eigen::Vector3d& p) {
    if constexpr (Dimensions == 2)
      return static_cast<double>(pdf(makeVector2<P>(p.x(), p.y())));
    else
      return static_cast<double>(pdf(makeVector3<P>(p)));
  };
  return m;
}

}  // namespace detail

// P is the caller's point type: 2D for the square, disk and triangle, 3D otherwise.
template <class P, class SampleFn, class PdfFn>
WarpModel squareWarp(SampleFn sample, PdfFn pdf) {
  return detail::warpModel<P, 2>(WarpDomain::Square, std::move(sample), std::move(pdf));
}
template <class P, class SampleFn, class PdfFn>
WarpModel diskWarp(SampleFn sample, PdfFn pdf) {
  return detail::warpModel<P, 2>(WarpDomain::Disk, std::move(sample), std::move(pdf));
}
template <class P, class SampleFn, class PdfFn>
WarpModel triangleWarp(SampleFn sample, PdfFn pdf) {
  return detail::warpModel<P, 2>(WarpDomain::Triangle, std::move(sample), std::move(pdf));
}
template <class P, class SampleFn, class PdfFn>
WarpModel hemisphereWarp(SampleFn sample, PdfFn pdf) {
  return detail::warpModel<P, 3>(WarpDomain::Hemisphere, std::move(sample), std::move(pdf));
}
template <class P, class SampleFn, class PdfFn>
WarpModel sphereWarp(SampleFn sample, PdfFn pdf) {
  return detail::warpModel<P, 3>(WarpDomain::Sphere, std::move(sample), std::move(pdf));
}

using WarpCheckOptions = CheckOptions;

CheckResult checkWarp(const WarpModel& model, const WarpCheckOptions& options);

}  // namespace verity::chi2
