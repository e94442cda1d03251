#include "integrators/bdpt_mis.h"

#include <cmath>

namespace verity {

namespace {

// Reads a density in a ratio: a Dirac delta (stored as 0) counts as 1, since it cancels.
double cameraDensity(const MisPath& p, int i) {
  return p.delta[i - 1] ? 1.0 : p.C[i];
}
double lightDensity(const MisPath& p, int i) {
  return i + 1 < p.n && p.delta[i + 1] ? 1.0 : p.L[i];
}

double endpointDensity(const MisPath& p, int t) {
  const int s = p.n - t;
  if (s == 0) return cameraDensity(p, p.n - 1);
  if (s == 1 && t >= 2) return p.nextEventPdf;
  return p.lightPathPdf;
}

// Whether strategy t can sample the path at all: it must not connect at a delta vertex,
// and a light subpath of one vertex at infinity cannot be connected to the lens.
bool usable(const MisPath& p, int t) {
  if (t < 1 || t > p.n) return false;
  if (t == p.n) return true;
  if (t == 1 && p.n == 2 && p.endpointAtInfinity) return false;
  return !p.delta[t - 1] && !p.delta[t];
}

double heuristic(double ratio, float power) {
  return power == 1 ? ratio : std::pow(ratio, static_cast<double>(power));
}

}  // namespace

float bdptMisWeight(const MisPath& p, int tSampled, float power) {
  const double own = endpointDensity(p, tSampled);
  if (!(own > 0)) return 0;
  double sum = 1;
  // Towards the camera: p_t / p_{t+1} = L_t / C_t (the endpoint aside); for t + 1 = n the
  // middle products are equal and only the endpoint changes.
  double middle = 1;
  for (int t = tSampled - 1; t >= 1; --t) {
    if (t + 1 < p.n) {
      const double c = cameraDensity(p, t);
      if (!(c > 0)) return 0;
      middle *= lightDensity(p, t) / c;
    }
    if (usable(p, t)) sum += heuristic(middle * endpointDensity(p, t) / own, power);
  }
  // Towards the light: p_t / p_{t−1} = C_{t−1} / L_{t−1} (the endpoint aside).
  middle = 1;
  for (int t = tSampled + 1; t <= p.n; ++t) {
    if (t < p.n) {
      const double l = lightDensity(p, t - 1);
      if (!(l > 0)) return 0;
      middle *= cameraDensity(p, t - 1) / l;
    }
    if (usable(p, t)) sum += heuristic(middle * endpointDensity(p, t) / own, power);
  }
  const double w = 1 / sum;
  return std::isfinite(w) ? static_cast<float>(w) : 0.0f;
}

}  // namespace verity
