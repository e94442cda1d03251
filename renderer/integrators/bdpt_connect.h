// The unweighted contributions of bidirectional path tracing's connection strategies
// (Veach 1997, §10.2.1): each returns the path throughput divided by the density of the
// strategy that sampled it, visibility included, or zero. Shadow rays are traced only for
// connections that would contribute.
#pragma once

#include <vector>

#include "integrators/integrator.h"
#include "integrators/path_vertex.h"

namespace verity {

// s = 0: the camera subpath's vertex t − 1 emits towards vertex t − 2 (an emitting surface or
// the background at infinity).
Color3 emissionContribution(const std::vector<PathVertex>& camera, int t);

// s = 1: next-event estimation at camera vertex t − 1 (t ≥ 2), with the scene's light choice
// and light sampling. The chosen emitter point becomes `sampled` (for the MIS weight).
Color3 nextEventContribution(const Scene& scene, Sampler& sampler,
                             const std::vector<PathVertex>& camera, int t, PathVertex& sampled,
                             PathStats& stats);

// s ≥ 2, t ≥ 2: an edge between camera vertex t − 1 and light vertex s − 1.
Color3 edgeContribution(const Scene& scene, const std::vector<PathVertex>& camera, int t,
                        const std::vector<PathVertex>& light, int s, PathStats& stats);

// t = 1: light vertex s − 1 (s ≥ 1) connected to a point on the lens. The lens point becomes
// `sampled` (a Camera vertex) and the position on the film, in pixels, goes to `film`.
Color3 cameraContribution(const Scene& scene, Sampler& sampler,
                          const std::vector<PathVertex>& light, int s, PathVertex& sampled,
                          Point2f& film, PathStats& stats);

// t = 1 with s = 1 at infinity: a light subpath that starts on the environment, connected to
// a point on the lens along its own direction (the background seen directly). The lens point
// is chosen for that direction; the position on the film goes to `film`. Only the light
// tracer uses it: bidirectional path tracing finds the background seen directly with its
// camera subpaths (s = 0), and its MIS weights treat this strategy as impossible.
Color3 backgroundCameraContribution(const Scene& scene, Sampler& sampler,
                                    const std::vector<PathVertex>& light, Point2f& film,
                                    PathStats& stats);

}  // namespace verity
