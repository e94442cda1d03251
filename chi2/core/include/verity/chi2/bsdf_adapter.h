// Checking a BSDF written in another renderer's own types. The caller gives three callables
// in its own vector type V (any 3-vector vector_access.h reads) and value type (a scalar, RGB
// or any number of spectral samples, fixed or sized at run time: ValueAccess in
// vector_access.h):
//
//   sample(const V& wi, const BsdfUniforms& u) -> std::optional<S>, S having members
//       wo (V), weight (value), pdf (a number) and optionally delta (bool), e.g.
//       SampledDirection<V, Value>; nothing when the BSDF cannot scatter from wi (a sample
//       of pdf 0 counts as nothing too, pbrt's convention);
//   eval(const V& wi, const V& wo) -> value          f without the cosine
//   pdf(const V& wi, const V& wo)  -> a number       per unit solid angle
//
// with the conventions of bsdf_model.h (normal +z, both directions pointing away, weight =
// f·|cos θo|/pdf, wo.z < 0 for transmission). checkBsdf then runs every check the suite
// runs on Verity's materials, for one incident direction:
//   chi-square       the histogram of sampled directions against ∫pdf over each cell
//   pdf integral     ∫pdf over the sphere against the fraction of valid samples
//   per sample       weight = eval·|cos θo|/pdf, sample pdf = pdf() (to weightTolerance),
//                    unit finite wo, no NaN, Inf or negative value, every value of the
//                    same size, reciprocity (with the indices, to reciprocityTolerance);
//                    each component by itself
//   delta lobes      each delta sample's direction (mirror, refraction for options.delta.eta
//                    or straight through) and weight; each lobe's share and albedo, against
//                    the caller's expectations where stated (delta_check.h)
// The first two and each stated delta expectation are statistical tests at `significance`,
// chosen by the caller; see check_result.h. A renderer whose sample() draws the incident
// direction and returns f and pdf (pbrt's Sample_f) uses bsdfModelFromSampleF
// (sample_f_adapter.h) instead of bsdfModel.
//
//   auto model = verity::chi2::bsdfModel<Vec3>(sample, eval, pdf);
//   CheckResult r = checkBsdf(model, Vec3{0.5, 0, 0.866}, options);
//   if (!r.passed()) std::cout << r.report();
#pragma once

#include <verity/chi2/audit.h>
#include <verity/chi2/bsdf_model.h>
#include <verity/chi2/check_result.h>
#include <verity/chi2/vector_access.h>

#include <optional>
#include <string>
#include <type_traits>
#include <utility>

namespace verity::chi2 {

// A sample in the caller's own types, for callables that have no such struct of their own.
template <class V, class Value>
struct SampledDirection {
  V wo{};
  Value weight{};
  double pdf = 0;
  bool delta = false;
};

namespace detail {

template <class T, class = void>
struct HasDelta : std::false_type {};
template <class T>
struct HasDelta<T, std::void_t<decltype(bool(std::declval<const T&>().delta))>> : std::true_type {};

template <class T>
struct IsOptional : std::false_type {};
template <class T>
struct IsOptional<std::optional<T>> : std::true_type {};

template <class S>
bool sampledDelta(const S& s) {
  if constexpr (HasDelta<S>::value)
    return bool(s.delta);
  else
    return false;
}

// A model without its sample(): eval and pdf of the caller's callables, taking their
// arguments in the order given, and the number of components of eval's value.
template <class V, class EvalFn, class PdfFn>
BsdfModel evalAndPdf(EvalFn eval, PdfFn pdf) {
  using Value = std::decay_t<decltype(eval(std::declval<const V&>(), std::declval<const V&>()))>;
  BsdfModel m;
  m.components = ValueAccess<Value>::kComponents;
  m.eval = [eval](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return ValueAccess<Value>::read(eval(makeVector3<V>(a), makeVector3<V>(b)));
  };
  m.pdf = [pdf](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return static_cast<double>(pdf(makeVector3<V>(a), makeVector3<V>(b)));
  };
  return m;
}

}  // namespace detail

// The model of callables in the caller's vector type V.
template <class V, class SampleFn, class EvalFn, class PdfFn>
BsdfModel bsdfModel(SampleFn sample, EvalFn eval, PdfFn pdf) {
  using Result = std::decay_t<decltype(sample(std::declval<const V&>(), BsdfUniforms{}))>;
  static_assert(detail::IsOptional<Result>::value,
                "sample(wi, u) must return a std::optional: nothing when it fails");
  BsdfModel m = detail::evalAndPdf<V>(std::move(eval), std::move(pdf));
  m.sample = [sample](const Eigen::Vector3d& wi,
                      const BsdfUniforms& u) -> std::optional<DirectionSample> {
    const Result s = sample(makeVector3<V>(wi), u);
    if (!s) return std::nullopt;
    using Weight = std::decay_t<decltype(s->weight)>;
    DirectionSample d;
    d.wo = readVector3(s->wo);
    d.weight = ValueAccess<Weight>::read(s->weight);
    d.pdf = static_cast<double>(s->pdf);
    d.delta = detail::sampledDelta(*s);
    return d;
  };
  return m;
}

struct BsdfCheckOptions : CheckOptions {
  bool checkReciprocity = true;
  DeltaCheckOptions delta;  // the delta lobes' directions and expectations (delta_check.h)

  // Per-sample tolerances, relative and per component: float arithmetic in a renderer's
  // BSDF may need more than the defaults, which suit double. Each in [0, 1), else checkBsdf
  // throws std::invalid_argument naming it. The report gives the worst |ratio − 1| of each
  // comparison that failed, beside its first example.
  double weightTolerance = kWeightTolerance;            // weight and sample pdf
  double reciprocityTolerance = kReciprocityTolerance;  // eval(wi,wo) against eval(wo,wi)
  // How far rounding may move a component of a sampled direction in [0.5, 1), scaled to each
  // component's magnitude (by default 4 units in the last place of a float; 4·2⁻⁵³ for a BSDF
  // in double). A failed comparison is "within rounding" where moving wo's or wi's components
  // this far moves its reference as far, as a factor either way: the report then says so, and a
  // family's table counts it apart (Audit::onlyRounding).
  double directionRounding = kDirectionRounding;
};

// One incident direction wi (local frame; normalised here unless it is unit to within 10⁻⁷, a
// direction normalised in single precision, which is kept as it is). A model of components 0
// (values sized at run time) is given the size of eval at wi's mirror direction, and every other
// value is held to it.
CheckResult checkBsdf(const BsdfModel& model, const Eigen::Vector3d& wi,
                      const BsdfCheckOptions& options);

template <class V, class = std::enable_if_t<!std::is_same_v<V, Eigen::Vector3d>>>
CheckResult checkBsdf(const BsdfModel& model, const V& wi, const BsdfCheckOptions& options) {
  return checkBsdf(model, readVector3(wi), options);
}

}  // namespace verity::chi2
