#include <fmt/format.h>
#include <fmt/ranges.h>
#include <tbb/parallel_for.h>
#include <verity/chi2/delta_check.h>
#include <verity/chi2/significance.h>
#include <verity/chi2/subject.h>

#include <algorithm>
#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <stdexcept>

namespace verity::chi2 {

namespace {

constexpr int kLobes = static_cast<int>(DeltaLobe::Count);
// The sampling test uses streams 0, 1, …; these are far above them.
constexpr uint64_t kFirstStream = uint64_t{1} << 62;

// The directions a delta sample may take from wi, by lobe (refraction only with η stated and
// no total internal reflection; pass-through only without η).
std::array<std::optional<Vector3d>, kLobes> acceptedDirections(const Vector3d& wi,
                                                               const std::optional<double>& eta) {
  std::array<std::optional<Vector3d>, kLobes> out;
  out[int(DeltaLobe::Reflection)] = Vector3d(-wi.x(), -wi.y(), wi.z());
  if (!eta) {
    out[int(DeltaLobe::PassThrough)] = Vector3d(-wi);
    return out;
  }
  // Snell's law from wi's side: t = −wi/η' + (cos θi/η' − cos θt)·n, n the normal on wi's side.
  const double etaRel = wi.z() > 0 ? *eta : 1 / *eta;
  const double cosI = std::fabs(wi.z()), sin2T = (1 - cosI * cosI) / (etaRel * etaRel);
  if (sin2T < 1) {
    const double cosT = std::sqrt(1 - sin2T), side = wi.z() > 0 ? 1.0 : -1.0;
    Vector3d t = -wi / etaRel;
    t.z() += side * (cosI / etaRel - cosT);
    out[int(DeltaLobe::Refraction)] = t;
  }
  return out;
}

// One chunk's sums, per component; sized by the first weight the chunk sees (or the model's
// count of components where it states one).
struct Partial {
  std::array<long long, kLobes> count{};
  std::array<Eigen::ArrayXd, kLobes> sum, sumSquares;
  long long wrongDirections = 0;
  std::string wrongDirectionExample;
  Audit audit;
  int components() const { return static_cast<int>(sum[0].size()); }
  void size(int components) {
    for (int l = 0; l < kLobes; ++l) {
      sum[l] = Eigen::ArrayXd::Zero(components);
      sumSquares[l] = Eigen::ArrayXd::Zero(components);
    }
  }
};

std::string formatValue(const Eigen::ArrayXd& v) {
  return v.size() == 1 ? fmt::format("{:.6g}", v[0])
                       : fmt::format("({:.6g})", fmt::join(v.data(), v.data() + v.size(), ", "));
}

}  // namespace

const char* deltaLobeName(DeltaLobe lobe) {
  switch (lobe) {
    case DeltaLobe::Reflection:
      return "reflection";
    case DeltaLobe::Refraction:
      return "refraction";
    case DeltaLobe::PassThrough:
      return "pass-through";
    case DeltaLobe::Count:
      break;
  }
  return "?";
}

int DeltaCheckOptions::statisticalTests() const {
  int n = 0;
  for (const DeltaExpectation& e : expected) n += int(e.share.has_value()) + e.albedo.has_value();
  return n;
}

DeltaCheck checkDeltaLobes(const BsdfModel& model, const Eigen::Vector3d& wi,
                           const DeltaCheckOptions& options, long long samples, double significance,
                           uint64_t seed) {
  if (samples < 1)
    throw std::invalid_argument(
        fmt::format("the number of samples must be at least 1, not {}", samples));
  if (!(significance > 0 && significance < 1))
    throw std::invalid_argument(
        fmt::format("the per-test significance level must be in (0, 1), not {}", significance));
  if (options.eta && !(std::isfinite(*options.eta) && *options.eta > 0))
    throw std::invalid_argument(
        fmt::format("DeltaCheckOptions::eta must be a finite index above 0, not {}", *options.eta));
  if (!(options.directionTolerance > 0))
    throw std::invalid_argument(
        fmt::format("DeltaCheckOptions::directionTolerance must be above 0, not {}",
                    options.directionTolerance));
  for (int k = 0; k < kLobes; ++k) {
    const DeltaExpectation& e = options.expected[k];
    if (e.share && !(*e.share >= 0 && *e.share <= 1))
      throw std::invalid_argument(
          fmt::format("the expected share of the {} lobe must be in [0, 1], not {}",
                      deltaLobeName(DeltaLobe(k)), *e.share));
    if (e.albedo && !(e.albedo->size() > 0 && e.albedo->allFinite() && (*e.albedo >= 0).all()))
      throw std::invalid_argument(
          fmt::format("the expected albedo of the {} lobe must be finite and non-negative",
                      deltaLobeName(DeltaLobe(k))));
  }
  const auto accepted = acceptedDirections(wi, options.eta);

  // Fixed chunks, one stream each, summed in order: the same result on any number of threads.
  constexpr long long kChunk = kSamplesPerStream;
  const long long chunks = (samples + kChunk - 1) / kChunk;
  std::vector<Partial> partial(chunks);
  tbb::parallel_for(0LL, chunks, [&](long long c) {
    pcg32 rng(seed, kFirstStream + static_cast<uint64_t>(c));
    Partial& p = partial[c];
    if (model.components > 0) p.size(model.components);
    std::vector<BsdfUniforms> us(std::min(kChunk, samples - c * kChunk));
    for (BsdfUniforms& u : us) {
      // The draws of BsdfModelSubject::sample: lobe, xy.x, xy.y.
      u.lobe = uniform01(rng);
      u.xy.x = uniform01(rng);
      u.xy.y = uniform01(rng);
    }
    std::vector<std::optional<DirectionSample>> drawn(us.size());
    sampleDirections(model, wi, us, drawn);
    for (size_t k = 0; k < us.size(); ++k) {
      const BsdfUniforms& u = us[k];
      const std::optional<DirectionSample>& s = drawn[k];
      if (!s || !s->delta) continue;
      auto at = [&] {
        return fmt::format("wi=({:.7g}) u=({}, {}, {}) wo=({:.7g})",
                           fmt::join(wi.data(), wi.data() + 3, ", "), u.lobe, u.xy.x, u.xy.y,
                           fmt::join(s->wo.data(), s->wo.data() + 3, ", "));
      };
      if (!s->wo.allFinite()) {
        p.audit.record(Defect::NonFinite, "delta direction " + at());
        continue;
      }
      if (std::fabs(s->wo.norm() - 1) > 1e-3) {
        p.audit.record(Defect::NotUnit, "delta direction not a unit vector: " + at());
        continue;
      }
      int lobe = -1;
      double nearest = INFINITY;
      for (int l = 0; l < kLobes; ++l) {
        if (!accepted[l]) continue;
        const double d = (s->wo - *accepted[l]).norm();
        if (d < nearest) nearest = d, lobe = l;
      }
      if (nearest > options.directionTolerance) {
        if (p.wrongDirections++ == 0)
          p.wrongDirectionExample =
              fmt::format("{}: {:.3g} from the nearest accepted direction ({}){}", at(), nearest,
                          deltaLobeName(DeltaLobe(lobe)),
                          options.eta ? "" : "; a refraction needs DeltaCheckOptions::eta");
        continue;
      }
      if (p.components() == 0 && s->weight.size() > 0) p.size(static_cast<int>(s->weight.size()));
      if (s->weight.size() != p.components()) {
        p.audit.record(Defect::Size, fmt::format("delta weight of {} components, not {}, at {}",
                                                 s->weight.size(), p.components(), at()));
        continue;
      }
      if (!s->weight.allFinite()) {
        p.audit.record(Defect::NonFinite,
                       fmt::format("delta weight {} at {}", formatValue(s->weight), at()));
        continue;
      }
      if (!(s->weight >= 0).all())
        p.audit.record(Defect::Negative,
                       fmt::format("delta weight {} at {}", formatValue(s->weight), at()));
      ++p.count[lobe];
      p.sum[lobe] += s->weight;
      p.sumSquares[lobe] += s->weight.square();
    }
  });

  DeltaCheck r;
  r.samples = samples;
  r.significance = significance;
  r.eta = options.eta;
  r.directionTolerance = options.directionTolerance;
  // The components: the model's, else the first chunk's that saw a delta weight; a chunk of
  // another size is a defect, its sums left out.
  r.components = model.components;
  for (const Partial& p : partial)
    if (r.components == 0) r.components = p.components();
  r.components = std::max(1, r.components);
  Partial total;
  total.size(r.components);
  for (const Partial& p : partial) {
    if (p.components() == r.components) {
      for (int l = 0; l < kLobes; ++l) {
        total.count[l] += p.count[l];
        total.sum[l] += p.sum[l];
        total.sumSquares[l] += p.sumSquares[l];
      }
    } else if (p.components() > 0) {
      r.audit.record(Defect::Size, fmt::format("delta weights of {} components, not {}",
                                               p.components(), r.components));
    }
    if (r.wrongDirections == 0) r.wrongDirectionExample = p.wrongDirectionExample;
    r.wrongDirections += p.wrongDirections;
    r.audit.merge(p.audit);
  }

  for (int l = 0; l < kLobes; ++l) {
    const std::optional<Eigen::ArrayXd>& e = options.expected[l].albedo;
    if (e && e->size() != 1 && e->size() != r.components)
      throw std::invalid_argument(fmt::format(
          "the expected albedo of the {} lobe has {} components; the BSDF's weights have {}",
          deltaLobeName(DeltaLobe(l)), e->size(), r.components));
  }

  using boost::math::binomial_distribution;
  const double n = static_cast<double>(samples), half = significance / 2;
  // The components of an albedo are one test: each at the Šidák level for their number.
  const double tQuantile = boost::math::quantile(boost::math::complement(
      boost::math::students_t(std::max(1.0, n - 1)), sidakLevel(significance, r.components) / 2));
  for (int l = 0; l < kLobes; ++l) {
    DeltaLobeResult& lr = r.lobes[l];
    const long long k = total.count[l];
    r.deltaSamples += k;
    lr.count = k;
    lr.expected = options.expected[l];
    lr.share = k / n;
    lr.shareLower = k == 0 ? 0.0 : binomial_distribution<double>::find_lower_bound_on_p(n, k, half);
    lr.shareUpper =
        k == samples ? 1.0 : binomial_distribution<double>::find_upper_bound_on_p(n, k, half);
    if (lr.expected.share)
      lr.sharePassed = *lr.expected.share >= lr.shareLower && *lr.expected.share <= lr.shareUpper;
    // weight·1[lobe] over all N draws: its mean and the standard error of that mean.
    lr.albedo = total.sum[l] / n;
    const Eigen::ArrayXd variance =
        ((total.sumSquares[l] - n * lr.albedo.square()) / std::max(1.0, n - 1)).max(0.0);
    lr.albedoHalfWidth = tQuantile * (variance / n).sqrt();
    const bool expectsNothing = lr.expected.albedo && (*lr.expected.albedo == 0).all();
    if (lr.expected.albedo && k < kMinAlbedoDraws && !(k == 0 && expectsNothing))
      lr.albedoUntested = fmt::format(
          "the {} lobe was drawn {} times in {} draws (its share at most {:.3g}): a stated "
          "albedo needs {} draws of its lobe for a t interval; draw more, or state its share",
          deltaLobeName(DeltaLobe(l)), k, samples, lr.shareUpper, kMinAlbedoDraws);
    else if (lr.expected.albedo)
      for (int c = 0; c < r.components; ++c) {
        const Eigen::ArrayXd& e = *lr.expected.albedo;
        const double expected = e.size() == 1 ? e[0] : e[c];
        lr.albedoPassed =
            lr.albedoPassed && std::fabs(lr.albedo[c] - expected) <=
                                   lr.albedoHalfWidth[c] + kWeightTolerance * expected;
      }
  }
  return r;
}

std::vector<std::string> DeltaCheck::failures() const {
  std::vector<std::string> out;
  if (wrongDirections > 0) out.push_back("delta direction");
  bool share = true, albedo = true;
  for (const DeltaLobeResult& l : lobes)
    share = share && l.sharePassed, albedo = albedo && l.albedoPassed;
  if (!share) out.push_back("delta share");
  if (!albedo) out.push_back("delta albedo");
  for (int d = 0; d < static_cast<int>(Defect::Count); ++d)
    if (audit.count(static_cast<Defect>(d)) > 0)
      out.push_back(std::string("delta ") + defectName(static_cast<Defect>(d)));
  return out;
}

bool DeltaCheck::passed() const {
  return failures().empty();
}

std::string DeltaCheck::inconclusiveReason() const {
  std::string reason;
  for (const DeltaLobeResult& l : lobes)
    if (!l.albedoUntested.empty()) reason += (reason.empty() ? "" : "; ") + l.albedoUntested;
  return reason;
}

std::string DeltaCheck::report() const {
  std::string s = fmt::format(
      "  delta lobes, on {} draws of their own: {} delta samples; accepted directions: mirror, "
      "{}\n",
      samples, deltaSamples,
      eta ? fmt::format("refraction for eta {}", *eta)
          : std::string("straight through (-wi; no eta stated)"));
  const auto value = [](const Eigen::ArrayXd& v) { return formatValue(v); };
  const double confidence = 100 * (1 - significance);
  for (int l = 0; l < kLobes; ++l) {
    const DeltaLobeResult& r = lobes[l];
    if (r.count == 0 && !r.expected.share && !r.expected.albedo) continue;
    s += fmt::format(
        "  [{}] {}: share {:.6f}, {:.6g}% Clopper-Pearson interval [{:.6f}, {:.6f}]{}\n",
        r.sharePassed ? "pass" : "FAIL", deltaLobeName(DeltaLobe(l)), r.share, confidence,
        r.shareLower, r.shareUpper,
        r.expected.share ? fmt::format(", expected {:.6f}", *r.expected.share) : "");
    if (!r.albedoUntested.empty())
      s += fmt::format("  [untested] {}: albedo {}, expected {}: {}\n", deltaLobeName(DeltaLobe(l)),
                       value(r.albedo), value(*r.expected.albedo), r.albedoUntested);
    else
      s += fmt::format("  [{}] {}: albedo {} +- {} ({:.6g}% t interval){}\n",
                       r.albedoPassed ? "pass" : "FAIL", deltaLobeName(DeltaLobe(l)),
                       value(r.albedo), value(r.albedoHalfWidth), confidence,
                       r.expected.albedo ? ", expected " + value(*r.expected.albedo) : "");
  }
  s += fmt::format("  [{}] delta directions: {} in no accepted direction (tolerance {:.1e}){}\n",
                   wrongDirections == 0 ? "pass" : "FAIL", wrongDirections, directionTolerance,
                   wrongDirections == 0 ? "" : "; first: " + wrongDirectionExample);
  s += fmt::format("  [{}] delta {}", audit.clean() ? "pass" : "FAIL", audit.describe());
  return s;
}

long long deltaDraws(const TestResult& test) {
  if (!test.target || !test.nothingClaimed()) return test.samples;
  const std::vector<double> whole(test.domain.cells(), 1.0 / test.domain.cells());
  return std::min(samplesForTarget(*test.target, whole, 1.0, test.significance), test.maxSamples);
}

}  // namespace verity::chi2
