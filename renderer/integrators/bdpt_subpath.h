// Random walks that build the two subpaths of bidirectional path tracing (Veach 1997, §10.2):
// one from the camera, carrying radiance, and one from an emitter, carrying importance. Each
// vertex records its throughput and its forward and reverse area densities for the MIS
// weights (Veach 1997, §10.2.2; the reverse density of a vertex is filled in when the walk
// samples the direction leaving the vertex after it).
#pragma once

#include <vector>

#include "integrators/integrator.h"
#include "integrators/path_vertex.h"
#include "integrators/russian_roulette.h"

namespace verity {

// Both walks end by `roulette` as the path tracer's paths do. The survival probabilities are
// not part of the MIS densities: the weights of all strategies are computed from the same
// densities, so they still sum to one and the estimator stays unbiased; only the choice among
// strategies is slightly less good.

// The camera subpath of `ray` (from generateRay): vertex 0 on the lens, then the surfaces it
// scatters at, at most `maxVertices` vertices in all. A ray that escapes while the scene has
// an emitting background ends in an Environment vertex.
void traceCameraSubpath(const Scene& scene, Sampler& sampler, const Ray& ray, int maxVertices,
                        const RussianRoulette& roulette, std::vector<PathVertex>& path,
                        PathStats& stats);

// The light subpath: an emitter chosen with the scene's light-selection probabilities (the
// ones next-event estimation uses), an emitted ray, then the surfaces it scatters at, at most
// `maxVertices` vertices in all (none when no emission could be sampled). Returns the area
// density with which next-event estimation from vertex 1 would choose vertex 0 (0 when the
// path has fewer than two vertices).
float traceLightSubpath(const Scene& scene, Sampler& sampler, int maxVertices,
                        const RussianRoulette& roulette, std::vector<PathVertex>& path,
                        PathStats& stats);

// Density with which the emitter of `emitter` (a Light, Environment or emitting Surface
// vertex) sends its emitted ray to `to`, per area at `to`.
float emissionDensity(const Scene& scene, const PathVertex& emitter, const PathVertex& to);

// Densities of choosing the emitting endpoint `emitter`: by a light subpath (light choice
// times the origin's density: per area, or per solid angle at infinity) and by next-event
// estimation from `from` (same measure; 0 when from is null).
void endpointDensities(const Scene& scene, const PathVertex& emitter, const PathVertex* from,
                       float* lightPathPdf, float* nextEventPdf);

}  // namespace verity
