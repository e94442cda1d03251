#include "lights/environment_light.h"

#include "core/frame.h"
#include "sampling/warp.h"

namespace verity {

EnvironmentLight::EnvironmentLight(const Color3& constant)
    : constant_(constant), average_(constant) {}

EnvironmentLight::EnvironmentLight(std::shared_ptr<const ImageTexture> image)
    : image_(std::move(image)) {
  const int w = image_->width(), h = image_->height();
  // Rows of the table run from v = 0 (bottom, −y) upwards; weight by sin θ of the row.
  std::vector<double> weights(size_t(w) * h);
  double solidAngleSum = 0;
  Eigen::Array3d sum = Eigen::Array3d::Zero();
  for (int row = 0; row < h; ++row) {
    const float v = (row + 0.5f) / h;
    const float sinTheta = std::sin(kPi * (1 - v));
    for (int x = 0; x < w; ++x) {
      const Color3 c = image_->texel(x, h - 1 - row);
      weights[size_t(row) * w + x] = std::max(0.0f, luminance(c)) * sinTheta;
      sum += c.cast<double>() * sinTheta;
      solidAngleSum += sinTheta;
    }
  }
  distribution_ = Distribution2D(weights, w, h);
  average_ = (sum / solidAngleSum).cast<float>();
}

Point2f EnvironmentLight::directionToUv(const Vector3f& d) {
  float u = std::atan2(d.x(), -d.z()) * kInv2Pi;
  if (u < 0) u += 1;
  const float theta = safeAcos(d.y());
  return {u, 1 - theta * kInvPi};
}

Vector3f EnvironmentLight::uvToDirection(const Point2f& uv) {
  const float phi = uv.x() * 2 * kPi;
  const float theta = (1 - uv.y()) * kPi;
  const float sinTheta = std::sin(theta);
  return {sinTheta * std::sin(phi), std::cos(theta), -sinTheta * std::cos(phi)};
}

Color3 EnvironmentLight::radiance(const Vector3f& d) const {
  if (!image_) return constant_;
  // Nearest texel, so that radiance is exactly as piecewise constant as the sampling density
  // (a bilinear lookup would be non-zero where the density is zero).
  const Point2f uv = directionToUv(d.normalized());
  const int w = image_->width(), h = image_->height();
  const int x = std::min(static_cast<int>(uv.x() * w), w - 1);
  const int y = std::min(static_cast<int>((1 - uv.y()) * h), h - 1);
  return image_->texel(x, y);
}

std::optional<LightSample> EnvironmentLight::sampleLi(const Point3f&, const Point2f& u) const {
  LightSample ls;
  ls.atInfinity = true;
  if (!image_) {
    ls.wi = warp::squareToUniformSphere(u);
    ls.pdf = kInv4Pi;
  } else {
    float mapPdf = 0;
    ls.wi = uvToDirection(distribution_.sample(u, &mapPdf));
    // The density as pdfLi() computes it for this direction, so that MIS sees one value
    // even where rounding moves the direction across a texel boundary.
    ls.pdf = pdfLi(ls.wi);
    if (!(mapPdf > 0) || !(ls.pdf > 0)) return std::nullopt;
  }
  ls.radiance = radiance(ls.wi);
  if (isBlack(ls.radiance) || !(ls.pdf > 0)) return std::nullopt;
  return ls;
}

float EnvironmentLight::pdfLi(const Vector3f& d) const {
  if (!image_) return kInv4Pi;
  const Vector3f n = d.normalized();
  const Point2f uv = directionToUv(n);
  // From the direction itself: accurate near the poles, where acos is not.
  const float sinTheta = std::hypot(n.x(), n.z());
  if (!(sinTheta > 0)) return 0;
  return distribution_.pdf(uv) / (2 * kPi * kPi * sinTheta);
}

double EnvironmentLight::power(double sceneRadius) const {
  return double{luminance(average_)} * (4 * kPi) * (kPi * sceneRadius * sceneRadius);
}

std::optional<LightEmission> EnvironmentLight::sampleLe(const Point2f& uPos, const Point2f& uDir,
                                                        const Point3f& sceneCenter,
                                                        float sceneRadius) const {
  const auto li = sampleLi(sceneCenter, uDir);
  if (!li) return std::nullopt;
  const Frame frame(li->wi);
  const Point2f disk = warp::squareToUniformDiskConcentric(uPos);
  LightEmission e;
  e.atInfinity = true;
  e.d = -li->wi;
  e.n = e.d;
  e.p = sceneCenter + sceneRadius * (li->wi + frame.s * disk.x() + frame.t * disk.y());
  e.radiance = li->radiance;
  e.pdfDir = li->pdf;
  e.pdfPos = 1.0f / (kPi * sceneRadius * sceneRadius);
  if (!(e.pdfPos > 0) || !std::isfinite(e.pdfPos)) return std::nullopt;
  return e;
}

void EnvironmentLight::pdfLe(const Vector3f& towardsEnvironment, float sceneRadius, float* pdfPos,
                             float* pdfDir) const {
  *pdfPos = 1.0f / (kPi * sceneRadius * sceneRadius);
  *pdfDir = pdfLi(towardsEnvironment);
}

}  // namespace verity
