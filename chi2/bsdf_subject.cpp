#include "chi2/bsdf_subject.h"

#include <fmt/format.h>

#include <numbers>

namespace verity::chi2 {

namespace {

std::string str(const Vector3f& v) {
  return fmt::format("({:.7g}, {:.7g}, {:.7g})", v.x(), v.y(), v.z());
}
std::string str(const Color3& c) {
  return fmt::format("({:.7g}, {:.7g}, {:.7g})", c.x(), c.y(), c.z());
}

bool validColor(const Color3& c) {
  return c.allFinite() && (c >= 0).all();
}

}  // namespace

Vector3f incidentDirection(double degrees, bool inside) {
  const double t = degrees * std::numbers::pi / 180;
  return Vector3f(float(std::sin(t)), 0.0f, float(inside ? -std::cos(t) : std::cos(t)));
}

BsdfSubject::BsdfSubject(BsdfSetup setup)
    : setup_(std::move(setup)),
      frame_(setup_.normal.normalized()),
      wiLocal_(frame_.toLocal(setup_.wi).normalized()),
      domain_(sphereDomain(setup_.resolution)),
      ior_(setup_.material->interiorIndex()) {}

double BsdfSubject::pdf(double phi, double z) const {
  const Vector3f wo = frame_.toLocal(sphereDirection(phi, z).cast<float>());
  return setup_.material->pdf(query_, wiLocal_, wo);
}

std::optional<Point2d> BsdfSubject::sample(pcg32& rng, Audit& audit) const {
  const float uLobe = uniform01(rng);
  const float u0 = uniform01(rng);
  const Point2f u(u0, uniform01(rng));
  const std::optional<BsdfSample> s =
      setup_.material->sample(query_, wiLocal_, uLobe, u, TransportMode::Radiance);
  if (!s) return std::nullopt;
  if (s->isDelta()) {
    ++delta_;
    return std::nullopt;
  }
  // Where a defect was found; formatted only when one is.
  auto at = [&] {
    return fmt::format("wi={} u=({}, {}, {}) wo={}", str(wiLocal_), uLobe, u.x(), u.y(),
                       str(s->wo));
  };
  if (!s->wo.allFinite() || std::fabs(s->wo.norm() - 1) > 1e-3f) {
    audit.record(Defect::NonFinite, "sampled direction not a unit vector: " + at());
    return std::nullopt;
  }
  const Vector3f& wo = s->wo;
  if (!s->weight.allFinite() || !std::isfinite(s->pdf))
    audit.record(Defect::NonFinite,
                 fmt::format("weight {} pdf {} at {}", str(s->weight), s->pdf, at()));
  else if (!(s->weight >= 0).all() || s->pdf <= 0)
    audit.record(Defect::Negative,
                 fmt::format("weight {} pdf {} (a returned sample needs pdf > 0) at {}",
                             str(s->weight), s->pdf, at()));

  const Color3 f = setup_.material->eval(query_, wiLocal_, wo, TransportMode::Radiance);
  const float p = setup_.material->pdf(query_, wiLocal_, wo);
  if (!f.allFinite() || !std::isfinite(p))
    audit.record(Defect::NonFinite, fmt::format("eval {} pdf() {} at {}", str(f), p, at()));
  else if (!(f >= 0).all() || p < 0)
    audit.record(Defect::Negative, fmt::format("eval {} pdf() {} at {}", str(f), p, at()));
  else {
    if (!relativelyClose(s->pdf, p, kWeightTolerance))
      audit.record(Defect::SamplePdf, fmt::format("sample pdf {} vs pdf() {} (ratio {:.6f}) at {}",
                                                  s->pdf, p, s->pdf / p, at()));
    const Color3 expected = p > 0 ? Color3(f * std::fabs(wo.z()) / p) : Color3::Zero();
    for (int c = 0; c < 3; ++c) {
      if (!relativelyClose(s->weight[c], expected[c], kWeightTolerance)) {
        audit.record(Defect::Weight,
                     fmt::format("weight {} vs eval*|cos|/pdf {} (ratio {:.6f}) at {}",
                                 str(s->weight), str(expected), s->weight[c] / expected[c], at()));
        break;
      }
    }
  }
  if (setup_.checkReciprocity) checkPair(wo, audit);
  return sphereCoords(frame_.toWorld(wo).cast<double>());
}

void BsdfSubject::checkPair(const Vector3f& wo, Audit& audit) const {
  const Material& m = *setup_.material;
  const Color3 f = m.eval(query_, wiLocal_, wo, TransportMode::Radiance);
  const Color3 fr = m.eval(query_, wo, wiLocal_, TransportMode::Radiance);
  const Color3 fi = m.eval(query_, wiLocal_, wo, TransportMode::Importance);
  const double etaI = wiLocal_.z() > 0 ? 1.0 : ior_;
  const double etaO = wo.z() > 0 ? 1.0 : ior_;
  for (int c = 0; c < 3; ++c) {
    const double a = f[c] * etaO * etaO, b = fr[c] * etaI * etaI;
    if (!relativelyClose(a, b, kReciprocityTolerance)) {
      audit.record(Defect::Reciprocity,
                   fmt::format("eval(wi,wo)*eta_o^2 = {:.7g} vs eval(wo,wi)*eta_i^2 = {:.7g} "
                               "(ratio {:.6f}) wi={} wo={}",
                               a, b, a / b, str(wiLocal_), str(wo)));
      return;
    }
    if (!relativelyClose(fi[c], fr[c], kReciprocityTolerance)) {
      audit.record(Defect::Reciprocity,
                   fmt::format("importance eval(wi,wo) = {:.7g} vs radiance eval(wo,wi) = {:.7g} "
                               "(ratio {:.6f}) wi={} wo={}",
                               fi[c], fr[c], fi[c] / fr[c], str(wiLocal_), str(wo)));
      return;
    }
  }
}

std::vector<double> BsdfSubject::breakpointsY(double phi) const {
  // The shading horizon n·ω = 0.
  const Vector3d n = frame_.n.cast<double>();
  std::vector<double> z = coneCrossings(n, 0, phi);
  if (ior_ != 1) {
    // Transmission ends where the generalised half vector −(ηi ωi + ηo ωo) turns
    // perpendicular to n (Walter et al. 2007, eq. 16), i.e. on the cone
    // n·ωo = −ηi (n·ωi) / ηo; a distribution with D > 0 at the horizon (GGX at large
    // alpha) jumps there.
    const double cosI = wiLocal_.z();
    const double etaI = cosI > 0 ? 1.0 : ior_, etaO = cosI > 0 ? ior_ : 1.0;
    for (double c : coneCrossings(n, -etaI * cosI / etaO, phi)) z.push_back(c);
  }
  return z;
}

std::vector<Point2d> BsdfSubject::peaks() const {
  const Vector3d wi = wiLocal_.cast<double>();
  std::vector<Point2d> out{sphereCoords(
      frame_.toWorld(Vector3d(-wi.x(), -wi.y(), wi.z()).cast<float>()).cast<double>())};
  if (ior_ != 1) {
    // Snell's law about the shading normal, from wi's side.
    const double eta = wi.z() > 0 ? ior_ : 1 / ior_;  // far over near
    const double cosI = std::fabs(wi.z()), sin2T = (1 - cosI * cosI) / (eta * eta);
    if (sin2T < 1) {
      const double cosT = std::sqrt(1 - sin2T);
      Vector3d t = -wi / eta;
      t.z() = wi.z() > 0 ? -cosT : cosT;
      out.push_back(sphereCoords(frame_.toWorld(t.normalized().cast<float>()).cast<double>()));
    }
  }
  return out;
}

void BsdfSubject::extraChecks(Audit& audit) const {
  // eval at every cell centre: finite and non-negative everywhere, not only where sampled.
  for (int c = 0; c < domain_.cells(); ++c) {
    const double phi = (c % domain_.nx + 0.5) * domain_.cellWidth();
    const double z = -1 + (c / domain_.nx + 0.5) * domain_.cellHeight();
    const Vector3f wo = frame_.toLocal(sphereDirection(phi, z).cast<float>());
    for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
      const Color3 f = setup_.material->eval(query_, wiLocal_, wo, mode);
      if (!validColor(f))
        audit.record(f.allFinite() ? Defect::Negative : Defect::NonFinite,
                     fmt::format("eval {} at wi={} wo={}", str(f), str(wiLocal_), str(wo)));
    }
  }
}

std::string BsdfSubject::describe() const {
  return fmt::format("{}\n  normal {}, world wi {}, local wi {}", setup_.name, str(setup_.normal),
                     str(setup_.wi), str(wiLocal_));
}

}  // namespace verity::chi2
