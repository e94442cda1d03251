#include "scene/scene.h"

#include <fmt/format.h>

#include "core/error.h"
#include "materials/diffuse_light.h"

namespace verity {

namespace {
// Embree calls this from C code: it must not throw. Errors here are bugs, not bad input.
void embreeError(void*, RTCError code, const char* message) {
  fmt::print(stderr, "verity: Embree error {}: {}\n", static_cast<int>(code),
             message ? message : "");
  std::abort();
}
}  // namespace

std::string SceneSummary::explain() const {
  std::string s;
  s += fmt::format("geometry: {} shapes, {} primitives\n", shapes, primitives);
  s += fmt::format("emitters: {} area light(s){}\n", areaLights,
                   emittingBackground ? " and an emitting background" : ", black background");
  s += fmt::format("materials: {} ({} with textured parameters, the rest cost no lookup)\n",
                   materials, texturedMaterials);
  s += fmt::format("delta (specular) lobes: {}\n", hasDeltaLobes ? "yes" : "no");
  // The strategies depend on the integrator: integrators/strategy_explanation.h.
  return s;
}

Scene::Scene() {
  // No config string: "threads=N" would cap every TBB loop in the process (see the
  // engineering notes); the render's thread count is set by its task arena.
  device_ = rtcNewDevice(nullptr);
  if (!device_) throw VerityError("", "Embree", "cannot create a device (rtcNewDevice failed)");
  rtcSetDeviceErrorFunction(device_, embreeError, nullptr);
  rtcScene_ = rtcNewScene(device_);
  rtcSetSceneFlags(rtcScene_, RTC_SCENE_FLAG_ROBUST);
}

Scene::~Scene() {
  if (rtcScene_) rtcReleaseScene(rtcScene_);
  if (device_) rtcReleaseDevice(device_);
}

void Scene::setBackground(std::unique_ptr<EnvironmentLight> background) {
  background_ = background && !background->isBlackEverywhere() ? std::move(background) : nullptr;
}

void Scene::addMaterial(std::shared_ptr<const Material> material) {
  materials_.push_back(std::move(material));
}

void Scene::addShape(std::unique_ptr<Shape> shape, std::shared_ptr<const Material> material) {
  shape->material = material.get();
  materials_.push_back(std::move(material));
  const unsigned id = shape->attach(device_, rtcScene_);
  if (id >= geometryToShape_.size()) geometryToShape_.resize(id + 1);
  geometryToShape_[id] = static_cast<unsigned>(shapes_.size());
  shapes_.push_back(std::move(shape));
}

void Scene::finalize() {
  rtcCommitScene(rtcScene_);
  for (const auto& shape : shapes_) {
    bounds_.expand(shape->bounds());
    summary_.primitives += shape->primitiveCount();
    if (auto* light = dynamic_cast<const DiffuseLight*>(shape->material);
        light && light->isEmitter()) {
      areaLights_.push_back(std::make_unique<AreaLight>(*shape, light->radiance()));
      shape->light = areaLights_.back().get();
    }
  }
  if (bounds_.empty()) {
    bounds_.expand(Point3f::Zero());
  }
  radius_ = std::max(0.5f * (bounds_.hi - bounds_.lo).norm(), 1e-30f);

  std::vector<double> powers;
  for (const auto& l : areaLights_) {
    l->index = lights_.size();
    lights_.push_back(l.get());
    powers.push_back(l->power(radius_));
  }
  if (background_) {
    background_->index = lights_.size();
    lights_.push_back(background_.get());
    powers.push_back(background_->power(radius_));
  }
  lightDistribution_ = Distribution1D(powers);

  // Materials are shared between shapes: count each once.
  std::sort(materials_.begin(), materials_.end());
  materials_.erase(std::unique(materials_.begin(), materials_.end()), materials_.end());
  summary_.shapes = shapes_.size();
  summary_.areaLights = areaLights_.size();
  summary_.emittingBackground = background_ != nullptr;
  summary_.materials = materials_.size();
  for (const auto& m : materials_) {
    summary_.texturedMaterials += m->isTextured() ? 1 : 0;
    summary_.hasDeltaLobes |= m->hasDeltaLobe();
    summary_.hasNonDeltaLobes |= m->hasNonDeltaLobe();
  }
}

bool Scene::intersect(const Ray& ray, SurfaceInteraction& si) const {
  if (rayLog_) rayLog_->add(ray, false);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  rh.ray.org_x = ray.o.x();
  rh.ray.org_y = ray.o.y();
  rh.ray.org_z = ray.o.z();
  rh.ray.dir_x = ray.d.x();
  rh.ray.dir_y = ray.d.y();
  rh.ray.dir_z = ray.d.z();
  rh.ray.tnear = ray.tmin;
  rh.ray.tfar = ray.tmax;
  rh.ray.time = 0;
  rh.ray.mask = 0xffffffffu;
  rh.ray.id = 0;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(rtcScene_, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  const Shape& shape = *shapes_[geometryToShape_[rh.hit.geomID]];
  si.t = rh.ray.tfar;
  si.shape = &shape;
  si.material = shape.material;
  si.light = shape.light;
  shape.completeHit(ray, rh.hit, rh.ray.tfar, si);
  return true;
}

bool Scene::occluded(const Ray& ray) const {
  if (rayLog_) rayLog_->add(ray, true);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r;
  r.org_x = ray.o.x();
  r.org_y = ray.o.y();
  r.org_z = ray.o.z();
  r.dir_x = ray.d.x();
  r.dir_y = ray.d.y();
  r.dir_z = ray.d.z();
  r.tnear = ray.tmin;
  r.tfar = ray.tmax;
  r.time = 0;
  r.mask = 0xffffffffu;
  r.id = 0;
  r.flags = 0;
  rtcOccluded1(rtcScene_, &context, &r);
  return r.tfar < 0;
}

const Light* Scene::sampleLight(float u, float* pmf) const {
  if (lights_.empty()) return nullptr;
  return lights_[lightDistribution_.sampleDiscrete(u, pmf)];
}

LightChoice Scene::lightChoice(const Point3f& ref) const {
  if (lights_.size() <= 1 || lights_.size() > LightChoice::kMaxLightsByContribution)
    return LightChoice(lights_, lightDistribution_);
  return LightChoice(lights_, ref);
}

float Scene::lightPmf(const Light* light) const {
  return light ? lightDistribution_.pmf(light->index) : 0;
}

}  // namespace verity
