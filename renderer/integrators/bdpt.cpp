#include "integrators/bdpt.h"

#include "integrators/bdpt_connect.h"
#include "integrators/bdpt_mis.h"
#include "integrators/bdpt_subpath.h"

namespace verity {

namespace {

// Per-thread scratch space: vectors that keep their capacity between samples.
struct Scratch {
  std::vector<PathVertex> camera, light;
  MisPath mis;
};

Scratch& scratch() {
  thread_local Scratch s;
  return s;
}

// The full path of strategy (s, t): camera vertices 0 … t − 1, then light vertices s − 1 … 0,
// with the vertex a connection sampled in place of camera[0] (t = 1) or light[0] (s = 1).
struct FullPath {
  const std::vector<PathVertex>& camera;
  const std::vector<PathVertex>& light;
  int s, t;
  const PathVertex* sampledCamera = nullptr;
  const PathVertex* sampledLight = nullptr;

  int size() const { return s + t; }
  const PathVertex& operator[](int i) const {
    if (i < t) return i == 0 && sampledCamera ? *sampledCamera : camera[i];
    const int j = s + t - 1 - i;
    return j == 0 && sampledLight ? *sampledLight : light[j];
  }
};

// Fills the densities of `path` for its strategy: the stored forward and reverse densities,
// and those around the connection, which depend on the vertices connected.
void fillDensities(const Scene& scene, const FullPath& path, float lightEndpointNextEventPdf,
                   MisPath& mis) {
  const int n = path.size(), s = path.s, t = path.t;
  mis.reset(n);
  for (int i = 1; i < n; ++i) {
    const PathVertex& v = path[i];
    mis.C[i] = i < t ? v.pdfFwd : v.pdfRev;
    mis.L[i] = i < t ? v.pdfRev : v.pdfFwd;
    mis.delta[i] = v.delta;
  }
  // The connected vertices are evaluated, not sampled, on this path.
  mis.delta[t - 1] = 0;
  if (t < n) mis.delta[t] = 0;
  const PathVertex& end = path[n - 1];
  mis.endpointAtInfinity = end.atInfinity();
  float lightPathPdf = 0, nextEventPdf = 0;

  if (s == 0) {
    if (n >= 3) mis.L[n - 2] = emissionDensity(scene, end, path[n - 2]);
    endpointDensities(scene, end, n >= 3 ? &path[n - 2] : nullptr, &lightPathPdf, &nextEventPdf);
  } else {
    const PathVertex &pt = path[t - 1], &qs = path[t];
    const Vector3f ptToQs = directionTo(pt, qs);
    if (t >= 2) {
      const Vector3f& ptToPrevious = pt.wPrevious;
      mis.C[t] = toAreaDensity(scatterPdf(pt, ptToPrevious, ptToQs), pt, qs);
      if (t >= 3)
        mis.L[t - 2] = toAreaDensity(scatterPdf(pt, ptToQs, ptToPrevious), pt, path[t - 2]);
    } else {
      float pdfPos = 0, pdfDir = 0;
      scene.camera().pdfImportance(pt.p(), ptToQs, &pdfPos, &pdfDir);
      mis.C[1] = toAreaDensity(pdfDir, pt, qs);
    }
    if (s == 1) {
      if (t >= 2) mis.L[t - 1] = emissionDensity(scene, qs, pt);
      endpointDensities(scene, qs, t >= 2 ? &pt : nullptr, &lightPathPdf, &nextEventPdf);
    } else {
      const Vector3f qsToPt = -ptToQs, qsToNext = qs.wPrevious;
      if (t >= 2) mis.L[t - 1] = toAreaDensity(scatterPdf(qs, qsToNext, qsToPt), qs, pt);
      mis.C[t + 1] = toAreaDensity(scatterPdf(qs, qsToPt, qsToNext), qs, path[t + 1]);
      lightPathPdf = path.light[0].pdfFwd;
      nextEventPdf = lightEndpointNextEventPdf;
    }
  }
  mis.lightPathPdf = lightPathPdf;
  mis.nextEventPdf = nextEventPdf;
}

}  // namespace

Color3 Bdpt::Li(const Scene& scene, Sampler& sampler, const Ray& ray,
                SampleContext& context) const {
  Scratch& scratchSpace = scratch();
  std::vector<PathVertex>& camera = scratchSpace.camera;
  std::vector<PathVertex>& light = scratchSpace.light;
  MisPath& mis = scratchSpace.mis;
  // A full path of s + t vertices has s + t − 2 bounces.
  const int maxVertices = maxBounces_ + 2;
  traceCameraSubpath(scene, sampler, ray, maxVertices, roulette_, camera, context.stats);
  const float lightNextEventPdf =
      traceLightSubpath(scene, sampler, maxVertices - 1, roulette_, light, context.stats);
  const int nCamera = static_cast<int>(camera.size()), nLight = static_cast<int>(light.size());

  Color3 L = Color3::Zero();
  // Adds strategy (s, t)'s contribution `c`, weighted with the densities now in `mis`.
  const auto add = [&](int s, int t, const Color3& c) {
    if (isDropped(s, t)) return;
    const Color3 weighted = c * bdptMisWeight(mis, t, misPower_);
    L += weighted;
    if (context.components) context.components->addStrategy(s, t, weighted, c);
  };
  // s = 0: emission found by the camera subpath.
  for (int t = 2; t <= nCamera; ++t) {
    const Color3 c = emissionContribution(camera, t);
    if (isBlack(c)) continue;
    fillDensities(scene, FullPath{camera, light, 0, t}, lightNextEventPdf, mis);
    add(0, t, c);
  }
  // s = 1: next-event estimation.
  for (int t = 2; t <= std::min(nCamera, maxVertices - 1); ++t) {
    PathVertex sampled;
    const Color3 c = nextEventContribution(scene, sampler, camera, t, sampled, context.stats);
    if (isBlack(c)) continue;
    FullPath path{camera, light, 1, t};
    path.sampledLight = &sampled;
    fillDensities(scene, path, lightNextEventPdf, mis);
    add(1, t, c);
  }
  // s ≥ 2, t ≥ 2: edges between the subpaths.
  for (int t = 2; t <= nCamera; ++t)
    for (int s = 2; s <= nLight && s + t <= maxVertices; ++s) {
      const Color3 c = edgeContribution(scene, camera, t, light, s, context.stats);
      if (isBlack(c)) continue;
      fillDensities(scene, FullPath{camera, light, s, t}, lightNextEventPdf, mis);
      add(s, t, c);
    }
  // t = 1: light subpath vertices connected to the lens, splatted where they land.
  const Vector2i& resolution = scene.camera().resolution();
  for (int s = 1; s <= std::min(nLight, maxVertices - 1); ++s) {
    PathVertex sampled;
    Point2f film;
    const Color3 c = cameraContribution(scene, sampler, light, s, sampled, film, context.stats);
    if (isBlack(c) || isDropped(s, 1)) continue;
    FullPath path{camera, light, s, 1};
    path.sampledCamera = &sampled;
    fillDensities(scene, path, lightNextEventPdf, mis);
    const Color3 weighted = c * bdptMisWeight(mis, 1, misPower_);
    context.splat(film, resolution, weighted);
    if (context.components) context.components->splatStrategy(s, film, weighted, c);
  }
  return L;
}

}  // namespace verity
