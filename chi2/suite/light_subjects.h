// Light sampling as test subjects: the points an area light's sampleLi() chooses, seen as
// directions from the reference point, against pdfLi() at the point a ray in that
// direction hits (so sampling, density and intersection must all agree); next-event
// estimation's whole draw among several lights (the scene's choice of a light at the point,
// then its sampleLi()); and the sphere's uniform area sampling on its own surface.
#pragma once

#include <verity/chi2/subject.h>

#include <memory>
#include <string>

#include "core/math.h"

namespace verity::chi2 {

enum class LightSampling {
  SolidAngle,  // AreaLight::sampleLi from `ref` (spheres: the visible cone; others: by area)
  SphereArea,  // Shape::sampleArea of a sphere, as directions from its centre
  // Scene::lightChoice(ref)'s sample, then that light's sampleLi; the density is the chosen
  // light's pmf() there · pdfLi. Planar emitters (quads, triangles) that do not overlap
  // as seen from ref.
  Choice,
};

struct LightSetup {
  std::string name;
  // The JSON array of a DIRT scene's surfaces, holding exactly one emitter (Choice: several).
  std::string surfaces;
  // The text of an OBJ file that the surfaces may name as "mesh.obj" (empty: none).
  std::string obj;
  Point3f ref = Point3f::Zero();
  LightSampling sampling = LightSampling::SolidAngle;
  int resolution = 32;
};

std::unique_ptr<Subject> makeLightSubject(const LightSetup& setup);

}  // namespace verity::chi2
