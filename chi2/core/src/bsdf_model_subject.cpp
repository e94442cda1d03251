#include <fmt/format.h>
#include <fmt/ranges.h>
#include <tbb/parallel_for.h>
#include <verity/chi2/bsdf_model_subject.h>
#include <verity/chi2/cell_locator.h>
#include <verity/chi2/phase_times.h>

#include <cmath>

namespace verity::chi2 {

namespace {

std::string str(const Vector3d& v) {
  return fmt::format("({:.7g}, {:.7g}, {:.7g})", v.x(), v.y(), v.z());
}

bool validValue(const Eigen::ArrayXd& v) {
  return v.allFinite() && (v >= 0).all();
}

}  // namespace

BsdfModelSubject::BsdfModelSubject(BsdfModel model, BsdfTestSetup setup)
    : model_(std::move(model)),
      setup_(std::move(setup)),
      domain_(sphereDomain(setup_.resolution)) {}

std::string BsdfModelSubject::component(int c) const {
  return model_.components > 1 ? fmt::format("component {} ", c) : "";
}

std::string BsdfModelSubject::format(const Eigen::ArrayXd& v) const {
  if (v.size() == 1) return fmt::format("{:.7g}", v[0]);
  return fmt::format("({:.7g})", fmt::join(v.begin(), v.end(), ", "));
}

template <class Where>
bool BsdfModelSubject::sized(const Eigen::ArrayXd& v, const char* what, Where where,
                             Audit& audit) const {
  if (v.size() == model_.components && v.size() > 0) return true;
  audit.record(Defect::Size, fmt::format("{} {} has {} component(s), the BSDF {}, at {}", what,
                                         format(v), v.size(), model_.components, where()));
  return false;
}

double BsdfModelSubject::pdf(double phi, double z) const {
  return model_.pdf(setup_.wi, setup_.frame.toLocal(sphereDirectionAtLastAzimuth(phi, z)));
}

namespace {

BsdfUniforms drawUniforms(pcg32& rng) {
  BsdfUniforms u;
  u.lobe = uniform01(rng);
  u.xy.x = uniform01(rng);
  u.xy.y = uniform01(rng);
  return u;
}

}  // namespace

bool BsdfModelSubject::evaluable(const std::optional<DirectionSample>& s) {
  return s && !s->delta && s->pdf != 0 && s->wo.allFinite() && std::fabs(s->wo.norm() - 1) <= 1e-3;
}

// eval(wi, wo), pdf(wi, wo) and eval(wo, wi) asked of the model one direction at a time.
struct BsdfModelSubject::PointByPoint {
  const BsdfModelSubject& s;
  Eigen::ArrayXd eval(const Vector3d& wo) const { return s.model_.eval(s.setup_.wi, wo); }
  double pdf(const Vector3d& wo) const { return s.model_.pdf(s.setup_.wi, wo); }
  Eigen::ArrayXd reversed(const Vector3d& wo) const { return s.model_.eval(wo, s.setup_.wi); }
};

std::optional<Point2d> BsdfModelSubject::sample(pcg32& rng, Audit& audit) const {
  const BsdfUniforms u = drawUniforms(rng);
  return audited(u, model_.sample(setup_.wi, u), PointByPoint{*this}, audit);
}

void BsdfModelSubject::sampleBatch(pcg32& rng, std::vector<std::optional<Point2d>>& out,
                                   Audit& audit) const {
  // The samples are drawn first and audited after, which draws from rng as sample() would
  // (the model takes only the uniforms) and lets the audit's cost be timed apart.
  const Vector3d& wi = setup_.wi;
  std::vector<BsdfUniforms> us(out.size());
  std::vector<std::optional<DirectionSample>> drawn(out.size());
  draw(rng, us, drawn);
  const PhaseClock clock;
  if (!model_.evalBatch) {
    for (size_t k = 0; k < out.size(); ++k)
      out[k] = audited(us[k], drawn[k], PointByPoint{*this}, audit);
    audit.addSeconds(clock.seconds());
    return;
  }
  // The directions to evaluate, each evaluation in one batch.
  std::vector<size_t> index(out.size(), 0);
  std::vector<Vector3d> wos;
  for (size_t k = 0; k < drawn.size() && audit.comparesSamples(); ++k)
    if (evaluable(drawn[k])) {
      index[k] = wos.size();
      wos.push_back(drawn[k]->wo);
    }
  const std::vector<Vector3d> one{wi};
  std::vector<Eigen::ArrayXd> f(wos.size()), fr(setup_.checkReciprocity ? wos.size() : 0);
  std::vector<double> p(wos.size());
  if (!wos.empty()) {
    model_.evalBatch(one, wos, f);
    if (model_.pdfBatch)
      model_.pdfBatch(wi, wos, p);
    else
      for (size_t k = 0; k < wos.size(); ++k) p[k] = model_.pdf(wi, wos[k]);
    if (setup_.checkReciprocity) model_.evalBatch(wos, one, fr);
  }
  struct Batch {
    const std::vector<Eigen::ArrayXd>& f;
    const std::vector<double>& p;
    const std::vector<Eigen::ArrayXd>& fr;
    size_t k;
    Eigen::ArrayXd eval(const Vector3d&) const { return f[k]; }
    double pdf(const Vector3d&) const { return p[k]; }
    Eigen::ArrayXd reversed(const Vector3d&) const { return fr[k]; }
  };
  for (size_t k = 0; k < out.size(); ++k)
    out[k] = audited(us[k], drawn[k], Batch{f, p, fr, index[k]}, audit);
  audit.addSeconds(clock.seconds());
}

void BsdfModelSubject::draw(pcg32& rng, std::vector<BsdfUniforms>& us,
                            std::vector<std::optional<DirectionSample>>& drawn) const {
  for (BsdfUniforms& u : us) u = drawUniforms(rng);
  if (model_.sampleBatch)
    model_.sampleBatch(setup_.wi, us, drawn);
  else
    for (size_t k = 0; k < us.size(); ++k) drawn[k] = model_.sample(setup_.wi, us[k]);
}

double BsdfModelSubject::drawingFloorSeconds(const Domain& cells, long long n, uint64_t seed,
                                             long long& binned) const {
  const PhaseClock clock;
  std::vector<long long> hist(cells.cells(), 0);
  const CellLocator locator(cells);
  std::vector<BsdfUniforms> us;
  std::vector<std::optional<DirectionSample>> drawn;
  for (long long c = 0; c * kSamplesPerStream < n; ++c) {
    pcg32 rng(seed, static_cast<uint64_t>(c));
    us.resize(std::min(kSamplesPerStream, n - c * kSamplesPerStream));
    drawn.resize(us.size());
    draw(rng, us, drawn);
    for (const std::optional<DirectionSample>& s : drawn) {
      if (!evaluable(s)) continue;
      const int cell = locator.cellOf(sphereCoords(setup_.frame.toWorld(s->wo)));
      if (cell >= 0) ++hist[cell];
    }
  }
  binned = 0;
  for (long long h : hist) binned += h;
  return clock.seconds();
}

void BsdfModelSubject::pdfBatch(const std::vector<Point2d>& points,
                                std::vector<double>& values) const {
  // The directions of a quadrature level's millions of nodes, over the threads while the
  // batch's own callable (Python's, under its lock) runs on one.
  std::vector<Vector3d> wos(points.size());
  tbb::parallel_for(size_t(0), points.size(), [&](size_t k) {
    wos[k] = setup_.frame.toLocal(sphereDirectionAtLastAzimuth(points[k].x(), points[k].y()));
  });
  model_.pdfBatch(setup_.wi, wos, values);
}

namespace {

// directionRounding, given for a component in [0.5, 1), scaled to the binade of v: the same
// number of units in its last place.
double roundingOf(double v, double directionRounding) {
  int exponent = 0;
  std::frexp(v, &exponent);  // |v| in [2^(e-1), 2^e)
  return v == 0 ? 0 : std::ldexp(directionRounding, exponent);
}

}  // namespace

template <class Q>
double BsdfModelSubject::roundingSpread(const Vector3d& wo, Q&& q) const {
  const Vector3d& wi = setup_.wi;
  const double reference = q(wi, wo);
  double spread = 0;
  const auto probe = [&](const Vector3d& i, const Vector3d& o) {
    spread = std::max(spread, factorDeviation(q(i, o), reference));
  };
  Vector3d step, stepI;
  for (int k = 0; k < 3; ++k) {
    step[k] = roundingOf(wo[k], setup_.directionRounding);
    stepI[k] = roundingOf(wi[k], setup_.directionRounding);
  }
  // Every component moved by its rounding, not renormalised: a direction rounded to float is
  // unit only to its rounding. wi too: a quantity of wi alone (a lobe's probability, a
  // Fresnel factor at a critical angle) rounds as much as one of wo.
  for (int signs = 0; signs < 8; ++signs) {
    Vector3d w = wo, i = wi;
    for (int k = 0; k < 3; ++k) w[k] += (signs >> k & 1 ? 1 : -1) * step[k];
    for (int k = 0; k < 3; ++k) i[k] += (signs >> k & 1 ? 1 : -1) * stepI[k];
    probe(wi, w);
    probe(i, wo);
  }
  // One component moved by its rounding and the direction kept unit, the others scaled to
  // match: a BSDF that renormalises a vector made from wo (a half vector) rounds that vector's
  // components again, which no move of the unnormalised wo reaches; near the normal this is
  // cos θ quantised, the move that changes 1 − cos²θ.
  for (int k = 0; k < 3; ++k)
    for (double sign : {-1.0, 1.0}) {
      const double moved = std::clamp(wo[k] + sign * step[k], -1.0, 1.0);
      const double rest = 1 - wo[k] * wo[k];
      if (step[k] == 0 || rest <= 0) continue;
      Vector3d w = wo * std::sqrt(std::max(0.0, 1 - moved * moved) / rest);
      w[k] = moved;
      probe(wi, w);
    }
  return spread;
}

template <class Values>
std::optional<Point2d> BsdfModelSubject::audited(const BsdfUniforms& u,
                                                 const std::optional<DirectionSample>& s,
                                                 const Values& values, Audit& audit) const {
  const Vector3d& wi = setup_.wi;
  if (!s) return std::nullopt;
  if (s->delta) {
    ++delta_;
    return std::nullopt;
  }
  // pbrt's convention: a sample of density 0 is no sample, whatever else it holds.
  if (s->pdf == 0) return std::nullopt;
  // Where a defect was found; formatted only when one is.
  auto at = [&] {
    return fmt::format("wi={} u=({}, {}, {}) wo={}", str(wi), u.lobe, u.xy.x, u.xy.y, str(s->wo));
  };
  if (!s->wo.allFinite()) {
    audit.record(Defect::NonFinite, "sampled direction " + at());
    return std::nullopt;
  }
  if (std::fabs(s->wo.norm() - 1) > 1e-3) {
    audit.record(Defect::NotUnit, "sampled direction not a unit vector: " + at());
    return std::nullopt;
  }
  const Vector3d& wo = s->wo;
  const Point2d binned = sphereCoords(setup_.frame.toWorld(wo));
  if (!sized(s->weight, "weight", at, audit)) return binned;
  if (!s->weight.allFinite() || !std::isfinite(s->pdf))
    audit.record(Defect::NonFinite,
                 fmt::format("weight {} pdf {} at {}", format(s->weight), s->pdf, at()));
  else if (!(s->weight >= 0).all() || s->pdf <= 0)
    audit.record(Defect::Negative,
                 fmt::format("weight {} pdf {} (a returned sample needs pdf > 0) at {}",
                             format(s->weight), s->pdf, at()));
  // The comparisons, which evaluate the model, on the samples audited.
  if (!audit.comparesSamples()) return binned;
  const Eigen::ArrayXd f = values.eval(wo);
  if (!sized(f, "eval", at, audit)) return binned;

  const double p = values.pdf(wo);
  if (!f.allFinite() || !std::isfinite(p))
    audit.record(Defect::NonFinite, fmt::format("eval {} pdf() {} at {}", format(f), p, at()));
  else if (!(f >= 0).all() || p < 0)
    audit.record(Defect::Negative, fmt::format("eval {} pdf() {} at {}", format(f), p, at()));
  else {
    const double tolerance = setup_.weightTolerance;
    if (!relativelyClose(s->pdf, p, tolerance)) {
      const double deviation = ratioDeviation(s->pdf, p);
      audit.recordClassifying(
          Defect::SamplePdf, deviation,
          [&] {
            return deviationWithinFactor(
                s->pdf / p, roundingSpread(wo, [&](const Vector3d& i, const Vector3d& o) {
                  return model_.pdf(i, o);
                }));
          },
          fmt::format("sample pdf {} vs pdf() {} (ratio {:.6f}, tolerance {:g}) at {}", s->pdf, p,
                      s->pdf / p, tolerance, at()));
    }
    // eval·|cos θo|/pdf, the weight the sample should carry, one component at a time: no
    // array is made for a sample that agrees.
    const double cosine = std::fabs(wo.z());
    const auto expectedAt = [&](int c) { return p > 0 ? f[c] * cosine / p : 0.0; };
    // The worst component, where any is beyond the tolerance.
    int worst = -1;
    double deviation = 0;
    for (int c = 0; c < f.size(); ++c) {
      const double expected = expectedAt(c);
      if (relativelyClose(s->weight[c], expected, tolerance)) continue;
      const double d = ratioDeviation(s->weight[c], expected);
      if (worst < 0 || d > deviation) {
        worst = c;
        deviation = d;
      }
    }
    if (worst >= 0) {
      Eigen::ArrayXd expected(f.size());
      for (int c = 0; c < f.size(); ++c) expected[c] = expectedAt(c);
      const auto weightAt = [&](const Vector3d& i, const Vector3d& w) {
        const double pw = model_.pdf(i, w);
        return pw > 0 ? model_.eval(i, w)[worst] * std::fabs(w.z()) / pw : 0.0;
      };
      audit.recordClassifying(
          Defect::Weight, deviation,
          [&] {
            return deviationWithinFactor(s->weight[worst] / expected[worst],
                                         roundingSpread(wo, weightAt));
          },
          fmt::format("weight {} vs eval*|cos|/pdf {} ({}ratio {:.6f}, "
                      "tolerance {:g}) at {}",
                      format(s->weight), format(expected), component(worst),
                      s->weight[worst] / expected[worst], tolerance, at()));
    }
  }
  if (setup_.checkReciprocity) checkReciprocity(wo, f, values.reversed(wo), audit);
  return binned;
}

void BsdfModelSubject::checkReciprocity(const Vector3d& wo, const Eigen::ArrayXd& f,
                                        const Eigen::ArrayXd& fr, Audit& audit) const {
  const Vector3d& wi = setup_.wi;
  auto where = [&] { return fmt::format("wi={} wo={}", str(wi), str(wo)); };
  const Eigen::ArrayXd fi = model_.evalAdjoint ? model_.evalAdjoint(wi, wo) : fr;
  if (!sized(fr, "eval(wo,wi)", where, audit) || !sized(fi, "evalAdjoint", where, audit)) return;
  const double etaI = indexOn(wi), etaO = indexOn(wo);
  const double tolerance = setup_.reciprocityTolerance;
  // The worst component of either comparison, where any is beyond the tolerance.
  double worst = -1, worstRatio = 1;
  int worstComponent = 0;
  bool adjoint = false;  // the worst is evalAdjoint's, else eval(wi, wo)'s
  std::string example;
  for (int c = 0; c < f.size(); ++c) {
    const double a = f[c] * etaO * etaO, b = fr[c] * etaI * etaI;
    if (!relativelyClose(a, b, tolerance) && ratioDeviation(a, b) > worst) {
      worst = ratioDeviation(a, b);
      worstRatio = a / b;
      worstComponent = c;
      adjoint = false;
      example = fmt::format(
          "eval(wi,wo)*eta_o^2 = {:.7g} vs eval(wo,wi)*eta_i^2 = {:.7g} "
          "({}ratio {:.6f}, tolerance {:g}) {}",
          a, b, component(c), a / b, tolerance, where());
    }
    if (!relativelyClose(fi[c], fr[c], tolerance) && ratioDeviation(fi[c], fr[c]) > worst) {
      worst = ratioDeviation(fi[c], fr[c]);
      worstRatio = fi[c] / fr[c];
      worstComponent = c;
      adjoint = true;
      example = fmt::format(
          "importance eval(wi,wo) = {:.7g} vs radiance eval(wo,wi) = {:.7g} "
          "({}ratio {:.6f}, tolerance {:g}) {}",
          fi[c], fr[c], component(c), fi[c] / fr[c], tolerance, where());
    }
  }
  if (worst < 0) return;
  // Either side of the comparison may be the one that rounding moves.
  const int c = worstComponent;
  audit.recordClassifying(
      Defect::Reciprocity, worst,
      [&] {
        const double forward = roundingSpread(wo, [&](const Vector3d& i, const Vector3d& w) {
          return adjoint && model_.evalAdjoint ? model_.evalAdjoint(i, w)[c] : model_.eval(i, w)[c];
        });
        const double backward = roundingSpread(
            wo, [&](const Vector3d& i, const Vector3d& w) { return model_.eval(w, i)[c]; });
        return deviationWithinFactor(worstRatio, std::max(forward, backward));
      },
      example);
}

std::vector<double> BsdfModelSubject::jumpCones() const {
  // The shading horizon n·ω = 0.
  std::vector<double> cosAngles{0};
  if (model_.relativeIndex() != 1) {
    // Transmission ends where the generalised half vector −(ηi ωi + ηo ωo) turns
    // perpendicular to n (Walter et al. 2007, eq. 16), i.e. on the cone
    // n·ωo = −ηi (n·ωi) / ηo; a distribution with D > 0 at the horizon (GGX at large
    // alpha) jumps there.
    // From wi renormalised in double, as a BSDF that computes in double from a float wi
    // (Verity's rough dielectric) sees it: the float-rounded wi of a family is up to 3·10⁻⁸
    // from unit length, and at α 4 and η 1.01 the dense lobe meets this edge, so a cone
    // declared from the raw wi left a sliver 2·10⁻⁹ wide where the BSDF's density was not
    // zero but the cells' was, and samples there failed the check outright.
    const Vector3d wi = setup_.wi.normalized();
    const double cosI = wi.z();
    const double etaI = indexOn(wi);
    const double etaO = cosI > 0 ? model_.interiorIndex : model_.exteriorIndex;
    cosAngles.push_back(-etaI * cosI / etaO);
  }
  return cosAngles;
}

std::vector<double> BsdfModelSubject::breakpointsY(double phi) const {
  std::vector<double> z;
  for (double c : jumpCones())
    for (double crossing : coneCrossings(setup_.frame.n, c, phi)) z.push_back(crossing);
  return z;
}

std::vector<double> BsdfModelSubject::breakpointCrossingsX(double z) const {
  std::vector<double> phi;
  for (double c : jumpCones())
    for (double azimuth : coneAzimuths(setup_.frame.n, c, z)) phi.push_back(azimuth);
  return phi;
}

std::vector<Point2d> BsdfModelSubject::peaks() const {
  const Vector3d wi = setup_.wi.normalized();  // as jumpCones() reads it
  std::vector<Point2d> out{sphereCoords(setup_.frame.toWorld(Vector3d(-wi.x(), -wi.y(), wi.z())))};
  if (model_.relativeIndex() != 1) {
    // Snell's law about the shading normal, from wi's side.
    const double eta = wi.z() > 0 ? model_.relativeIndex() : 1 / model_.relativeIndex();
    const double cosI = std::fabs(wi.z()), sin2T = (1 - cosI * cosI) / (eta * eta);
    if (sin2T < 1) {
      const double cosT = std::sqrt(1 - sin2T);
      Vector3d t = -wi / eta;
      t.z() = wi.z() > 0 ? -cosT : cosT;
      out.push_back(sphereCoords(setup_.frame.toWorld(t.normalized())));
    }
  }
  return out;
}

void BsdfModelSubject::extraChecks(Audit& audit) const {
  // eval at every cell centre: finite and non-negative everywhere, not only where sampled.
  std::vector<Vector3d> wos(domain_.cells());
  for (int c = 0; c < domain_.cells(); ++c) {
    const double phi = (c % domain_.nx + 0.5) * domain_.cellWidth();
    const double z = -1 + (c / domain_.nx + 0.5) * domain_.cellHeight();
    wos[c] = setup_.frame.toLocal(sphereDirection(phi, z));
  }
  std::vector<Eigen::ArrayXd> batch;
  if (model_.evalBatch) {
    batch.resize(wos.size());
    model_.evalBatch(std::vector<Vector3d>{setup_.wi}, wos, batch);
  }
  for (size_t c = 0; c < wos.size(); ++c) {
    const Vector3d& wo = wos[c];
    for (const BsdfModel::EvalFn* eval : {&model_.eval, &model_.evalAdjoint}) {
      if (!*eval && !(eval == &model_.eval && model_.evalBatch)) continue;
      const Eigen::ArrayXd f =
          eval == &model_.eval && model_.evalBatch ? batch[c] : (*eval)(setup_.wi, wo);
      auto where = [&] { return fmt::format("wi={} wo={}", str(setup_.wi), str(wo)); };
      if (!sized(f, "eval", where, audit)) continue;
      if (!validValue(f))
        audit.record(f.allFinite() ? Defect::Negative : Defect::NonFinite,
                     fmt::format("eval {} at wi={} wo={}", format(f), str(setup_.wi), str(wo)));
    }
  }
}

std::string BsdfModelSubject::describe() const {
  return fmt::format("{}\n  shading normal {}, local wi {}", setup_.name, str(setup_.frame.n),
                     str(setup_.wi));
}

}  // namespace verity::chi2
