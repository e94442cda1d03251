// The vertices of bidirectional path tracing's subpaths (Veach 1997, "Robust Monte Carlo
// Methods for Light Transport Simulation", ch. 10) and what connecting two of them needs:
// directions, the conversion of solid-angle densities to the area measure, and the
// scattering factor of a vertex between its two neighbours.
//
// Measures. Every density stored on a vertex is per unit area at that vertex, except at a
// vertex at infinity (the environment), where it is per unit solid angle of the direction,
// and the density of the surface point after it is the emitting disk's density projected on
// the surface (the convention of pbrt-v3 §16.3 for infinite lights).
//
// Scattering factor. With geometric cosines in the geometry term
//   G(x, y) = |cos θ_x| |cos θ_y| / |x − y|²   (geometric normals),
// a surface vertex contributes f(x) · |ω_L · n_s| / |ω_L · n_g|, where ω_L points to its
// neighbour on the light side. On camera subpaths this is the usual shading cosine; on light
// subpaths it is Veach's adjoint correction for shading normals (1997, §5.3, eq. 5.17), so
// that both directions of tracing evaluate one and the same path contribution.
#pragma once

#include <cstdint>

#include "lights/light.h"
#include "materials/material.h"
#include "shapes/interaction.h"

namespace verity {

enum class VertexKind : uint8_t {
  Camera,       // the lens point (si.p)
  Light,        // a point on an area light that starts a path or was chosen by NEE
  Environment,  // the end of a path at infinity: `w` points towards the environment
  Surface,      // a scattering point; si.light is set when the surface also emits
};

struct PathVertex {
  VertexKind kind = VertexKind::Surface;
  // The walk left this vertex through a delta lobe: the densities of its two neighbours that
  // depend on it are Dirac deltas (stored as 0) and no strategy may connect here.
  bool delta = false;
  SurfaceInteraction si;                   // position, normals and material (si.p only for Camera)
  Vector3f w = Vector3f::UnitZ();          // Environment: unit direction towards the environment
  Vector3f wPrevious = Vector3f::UnitZ();  // walk vertices: unit direction to the one before
  const Light* light = nullptr;            // Light and Environment: the emitter
  Color3 beta = Color3::Ones();            // subpath throughput up to and including this vertex
  float pdfFwd = 0;  // density of this vertex by the walk that built the subpath
  float pdfRev = 0;  // density of this vertex by a walk from the other end

  const Point3f& p() const { return si.p; }
  bool atInfinity() const { return kind == VertexKind::Environment; }
  bool onSurface() const { return kind == VertexKind::Surface || kind == VertexKind::Light; }
  // Whether a connection edge may end here: a surface with a non-delta lobe, or a point on
  // an area light (the camera is connected through its own sampling).
  bool connectible() const {
    if (kind == VertexKind::Light) return true;
    return kind == VertexKind::Surface && si.material && si.material->hasNonDeltaLobe();
  }
};

// Unit direction from `from` to `to` (either may be at infinity, not both).
Vector3f directionTo(const PathVertex& from, const PathVertex& to);

// Converts a solid-angle density at `from` of the direction towards `to` into the density of
// `to`: per area (with to's geometric cosine) or, at infinity, unchanged.
float toAreaDensity(float pdfSolidAngle, const PathVertex& from, const PathVertex& to);

// Scattering factor of surface vertex v with neighbours towards `cameraSide` and `lightSide`
// (see the header comment); `mode` is Radiance for camera-subpath vertices and Importance
// for light-subpath vertices, which is how the material expects wi and wo.
Color3 scatterFactor(const PathVertex& v, const Vector3f& towardsCamera,
                     const Vector3f& towardsLight, TransportMode mode);

// Solid-angle density with which the material of surface vertex v samples `next` when the
// walk arrived from `previous`: camera walks and light walks use the same densities.
float scatterPdf(const PathVertex& v, const Vector3f& towardsPrevious, const Vector3f& towardsNext);

// Radiance an emitting vertex sends towards direction d (0 if it does not emit that way).
Color3 emittedRadiance(const PathVertex& v, const Vector3f& d);

}  // namespace verity
