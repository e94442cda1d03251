// Everything a render reads: geometry in an Embree scene, materials, lights, the camera and
// the background, plus what the scene calls for (its summary).
#pragma once

#include <embree3/rtcore.h>

#include <memory>
#include <string>
#include <vector>

#include "camera/camera.h"
#include "lights/area_light.h"
#include "lights/environment_light.h"
#include "materials/material.h"
#include "sampling/distribution.h"
#include "scene/light_choice.h"
#include "scene/ray_log.h"
#include "shapes/shape.h"

namespace verity {

// What the renderer must simulate for this scene; integrators skip the rest.
struct SceneSummary {
  size_t shapes = 0, primitives = 0, areaLights = 0, materials = 0, texturedMaterials = 0;
  bool emittingBackground = false;
  bool hasDeltaLobes = false;     // some material has a specular (delta) lobe
  bool hasNonDeltaLobes = false;  // next-event estimation can contribute somewhere
  bool hasEmitters() const { return areaLights > 0 || emittingBackground; }
  std::string explain() const;
};

class Scene {
 public:
  Scene();
  ~Scene();
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  // Building (used by the loader), then finalize() once.
  void setCamera(std::unique_ptr<Camera> camera) { camera_ = std::move(camera); }
  void setBackground(std::unique_ptr<EnvironmentLight> background);
  void addMaterial(std::shared_ptr<const Material> material);
  void addShape(std::unique_ptr<Shape> shape, std::shared_ptr<const Material> material);
  void finalize();

  bool intersect(const Ray& ray, SurfaceInteraction& si) const;
  bool occluded(const Ray& ray) const;
  // Every ray traced from now on is also appended to `log` (null: none; the default).
  void setRayLog(RayLog* log) { rayLog_ = log; }

  const Camera& camera() const { return *camera_; }
  // Null when the background is black (it then emits nothing and is never looked up).
  const EnvironmentLight* background() const { return background_.get(); }

  const std::vector<const Light*>& lights() const { return lights_; }
  // Chooses a light with probability proportional to its power (light subpaths, and BDPT's
  // connections, whose MIS weights read the same choice).
  const Light* sampleLight(float u, float* pmf) const;
  float lightPmf(const Light* light) const;
  // How next-event estimation chooses a light at `ref` (light_choice.h).
  LightChoice lightChoice(const Point3f& ref) const;

  const SceneSummary& summary() const { return summary_; }
  const Bounds3f& bounds() const { return bounds_; }
  float boundingRadius() const { return radius_; }
  const std::vector<std::unique_ptr<Shape>>& shapes() const { return shapes_; }

 private:
  RTCDevice device_ = nullptr;
  RTCScene rtcScene_ = nullptr;
  std::unique_ptr<Camera> camera_;
  std::unique_ptr<EnvironmentLight> background_;
  std::vector<std::shared_ptr<const Material>> materials_;
  std::vector<std::unique_ptr<Shape>> shapes_;
  std::vector<unsigned> geometryToShape_;
  std::vector<std::unique_ptr<AreaLight>> areaLights_;
  std::vector<const Light*> lights_;
  Distribution1D lightDistribution_;
  SceneSummary summary_;
  Bounds3f bounds_;
  float radius_ = 1;
  RayLog* rayLog_ = nullptr;
};

}  // namespace verity
