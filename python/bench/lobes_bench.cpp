// The C++ side of python/bench/batched_quadrature.py: the Lambertian and GGX lobes of
// python/tests/lobes.py and examples/python/ggx.py, written in C++ and checked through the C++
// adapter (bsdf_adapter.h) point by point, at the checks' defaults (10⁶ samples) on the cell
// layout named. Prints "<lobe> <seconds> <verdict>" per lobe.
//
//   verity_python_bench equal|grid
#include <verity/chi2/bsdf_adapter.h>
#include <verity/chi2/partition.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <iostream>
#include <numbers>
#include <optional>

namespace {

using Eigen::Array3d;
using Eigen::Vector3d;
using verity::chi2::BsdfUniforms;
template <class Value>
using Sample = verity::chi2::SampledDirection<Vector3d, Value>;
constexpr double kPi = std::numbers::pi;

// Grey, as python/tests/lobes.py's.
struct Lambert {
  double albedo = 0.8;
  std::optional<Sample<double>> sample(const Vector3d&, const BsdfUniforms& u) const {
    const double r = std::sqrt(u.xy.x), phi = 2 * kPi * u.xy.y;
    Sample<double> s;
    s.wo = {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1 - u.xy.x))};
    s.pdf = s.wo.z() / kPi;
    s.weight = albedo;
    return s;
  }
  double eval(const Vector3d& wi, const Vector3d& wo) const {
    return wi.z() > 0 && wo.z() > 0 ? albedo / kPi : 0;
  }
  double pdf(const Vector3d&, const Vector3d& wo) const { return wo.z() > 0 ? wo.z() / kPi : 0; }
};

// Walter et al. 2007 with the height-correlated Smith term and Schlick's Fresnel, sampled by
// visible normals (Heitz 2018, "Sampling the GGX Distribution of Visible Normals", JCGT 7(4)).
struct Ggx {
  double alpha = 0.3;
  Array3d f0{0.95, 0.64, 0.54};
  double d(const Vector3d& h) const {
    const double a2 = alpha * alpha, t = h.z() * h.z() * (a2 - 1) + 1;
    return a2 / (kPi * t * t);
  }
  double lambda(const Vector3d& w) const {
    const double c2 = std::clamp(w.z() * w.z(), 1e-300, 1.0);
    return 0.5 * (std::sqrt(1 + alpha * alpha * (1 - c2) / c2) - 1);
  }
  static Vector3d half(const Vector3d& wi, const Vector3d& wo) {
    const Vector3d h = (wi + wo).normalized();
    return h.z() < 0 ? Vector3d(-h) : h;
  }
  Array3d eval(const Vector3d& wi, const Vector3d& wo) const {
    if (!(wi.z() > 0 && wo.z() > 0)) return Array3d::Zero();
    const Vector3d h = half(wi, wo);
    const double g2 = 1 / (1 + lambda(wi) + lambda(wo));
    const Array3d fresnel = f0 + (1 - f0) * std::pow(1 - std::clamp(wi.dot(h), 0.0, 1.0), 5);
    return d(h) * g2 / (4 * std::fabs(wi.z() * wo.z())) * fresnel;
  }
  double pdf(const Vector3d& wi, const Vector3d& wo) const {
    if (!(wi.z() > 0 && wo.z() > 0)) return 0;
    return d(half(wi, wo)) / (1 + lambda(wi)) / (4 * std::fabs(wi.z()));
  }
  std::optional<Sample<Array3d>> sample(const Vector3d& wi, const BsdfUniforms& u) const {
    const Vector3d v = Vector3d(alpha * wi.x(), alpha * wi.y(), wi.z()).normalized();
    const double lensq = v.x() * v.x() + v.y() * v.y();
    const Vector3d t1 =
        lensq > 0 ? Vector3d(Vector3d(-v.y(), v.x(), 0) / std::sqrt(lensq)) : Vector3d::UnitX();
    const Vector3d t2 = v.cross(t1);
    const double r = std::sqrt(u.xy.x), phi = 2 * kPi * u.xy.y, p1 = r * std::cos(phi);
    const double s = 0.5 * (1 + v.z());
    const double p2 = (1 - s) * std::sqrt(1 - p1 * p1) + s * r * std::sin(phi);
    const Vector3d nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1 - p1 * p1 - p2 * p2)) * v;
    const Vector3d h =
        Vector3d(alpha * nh.x(), alpha * nh.y(), std::max(1e-7, nh.z())).normalized();
    Sample<Array3d> out;
    out.wo = 2 * wi.dot(h) * h - wi;
    out.pdf = pdf(wi, out.wo);
    out.weight =
        out.pdf > 0 ? Array3d(eval(wi, out.wo) * std::fabs(out.wo.z()) / out.pdf) : Array3d::Zero();
    return out;
  }
};

template <class Lobe>
void run(const char* name, const Lobe& lobe, verity::chi2::CellLayout cells) {
  const auto model = verity::chi2::bsdfModel<Vector3d>(
      [lobe](const Vector3d& wi, const BsdfUniforms& u) { return lobe.sample(wi, u); },
      [lobe](const Vector3d& wi, const Vector3d& wo) { return lobe.eval(wi, wo); },
      [lobe](const Vector3d& wi, const Vector3d& wo) { return lobe.pdf(wi, wo); });
  verity::chi2::BsdfCheckOptions o;
  o.name = std::string("bench ") + name;
  o.significance = 0.01;
  o.cells = cells;
  const double t = 50 * kPi / 180;
  const auto start = std::chrono::steady_clock::now();
  const auto r = verity::chi2::checkBsdf(model, Vector3d(std::sin(t), 0, std::cos(t)), o);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << name << " " << seconds << " " << verity::chi2::verdictName(r.verdict()) << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  const auto cells = verity::chi2::parseCellLayout(argc > 1 ? argv[1] : "equal", "layout");
  run("lambert", Lambert{}, cells);
  run("ggx", Ggx{}, cells);
}
