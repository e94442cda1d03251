#include "loader/scene_loader.h"

#include <fmt/format.h>

#include <cmath>
#include <functional>

#include "lights/background_registry.h"
#include "loader/scene_keys.h"
#include "materials/material_factory.h"
#include "params/transform_parser.h"
#include "sampling/sampler_registry.h"
#include "shapes/shape_registry.h"

namespace verity {

namespace {

const std::string kExtentProblem =
    "lies outside the supported extent: every coordinate must be within ±1e15";

bool withinExtent(const Point3f& p) {
  return p.cwiseAbs().maxCoeff() <= kMaxSceneCoordinate;  // false for NaN too
}

void checkPixelCount(const Vector2i& resolution, const std::function<void(std::string)>& fail) {
  if (int64_t{resolution.x()} * resolution.y() > scene_keys::kMaxPixels)
    fail(fmt::format("the image must have at most 8192 × 8192 pixels in all, not {} × {}",
                     resolution.x(), resolution.y()));
}

// The resolution `width` pixels wide with the aspect ratio of `resolution`.
Vector2i resolutionAtWidth(const Vector2i& resolution, int width) {
  const int height =
      std::max(1, int(std::lround(double(width) * resolution.y() / std::max(resolution.x(), 1))));
  const Vector2i result(width, height);
  const auto fail = [](const std::string& problem) {
    throw VerityError("", "--resolution", problem);
  };
  using scene_keys::kMaxImageSide;
  if (width > kMaxImageSide || height > kMaxImageSide)
    fail(fmt::format("{} pixels wide makes a {} × {} image: each side must be at most {}", width,
                     width, height, kMaxImageSide));
  checkPixelCount(result, fail);
  return result;
}

std::unique_ptr<Camera> parseCamera(const JsonNode& node, int width) {
  using namespace scene_keys;
  if (!node.isObject()) node.fail("expected a camera object");
  node.declare({"the camera", {&cameraKeys()}});
  const Transform toWorld = parseOptionalTransform(node);
  if (!withinExtent(toWorld.point(Point3f::Zero()))) node[kCameraTransform].fail(kExtentProblem);
  // The camera maps its image plane through the transform: a shear or non-uniform scale
  // would squash the image, as it would a sphere.
  if (!toWorld.isSimilarity(nullptr))
    node[kCameraTransform].fail(
        "a camera's transform must scale uniformly (no shear or non-uniform scale)");
  Vector2i resolution = node.get(kResolution);
  checkPixelCount(resolution, [&](const std::string& problem) { node[kResolution].fail(problem); });
  if (width > 0) resolution = resolutionAtWidth(resolution, width);
  const float vfov = node.get(kVfov);
  const float fdist = node.get(kFdist);
  const float aperture = node.get(kAperture);
  node.rejectUnknownKeys();
  return std::make_unique<Camera>(toWorld, resolution, vfov, fdist, aperture);
}

std::unique_ptr<EnvironmentLight> parseBackground(const JsonNode& node, TextureFactory& textures) {
  if (node.isNumber() || node.isArray()) {
    const Vector3f c = node.asVector3();
    if ((c.array() < 0).any()) node.fail("background radiance must not be negative");
    return std::make_unique<EnvironmentLight>(Color3(c.array()));
  }
  if (!node.isObject()) node.fail("expected a number, [r,g,b] or a background object");
  const BackgroundType& entry = backgroundTypes().get(node[{"type"}]);
  node.declare({"background " + entry.name, {&backgroundCommonKeys(), &entry.keys}});
  std::unique_ptr<EnvironmentLight> light = entry.build(node);
  node.rejectUnknownKeys();
  return light;
}

class SurfaceParser {
 public:
  SurfaceParser(Scene& scene, MaterialFactory& materials) : scene_(scene), materials_(materials) {}

  void parse(const JsonNode& node, const Transform& parent) {
    if (!node.isObject()) node.fail("expected a surface object");
    const JsonNode type = node[{"type"}];
    const Transform toWorld = parent * parseOptionalTransform(node);
    if (typeNameKey(type.asString()) == "group") {
      node.declare({"surface group", {&surfaceCommonKeys(), &groupKeys()}});
      const JsonNode children = node[scene_keys::kChildren];
      if (!children.isArray()) children.fail("expected an array of surfaces");
      for (size_t i = 0; i < children.size(); ++i) parse(children[i], toWorld);
      node.rejectUnknownKeys();
      return;
    }
    const ShapeType& entry = shapeTypes().get(type);
    node.declare(
        {"surface " + entry.name, {&surfaceCommonKeys(), &shapeCommonKeys(), &entry.keys}});
    std::unique_ptr<Shape> shape = entry.build(node, toWorld);
    const Bounds3f bounds = shape->bounds();
    if (!withinExtent(bounds.lo) || !withinExtent(bounds.hi)) node.fail(kExtentProblem);
    auto material = materials_.reference(node[{"material"}]);
    node.rejectUnknownKeys();
    scene_.addShape(std::move(shape), std::move(material));
  }

 private:
  Scene& scene_;
  MaterialFactory& materials_;
};

std::unique_ptr<Sampler> parseSampler(const JsonNode& root) {
  using namespace scene_keys;
  auto node = root.find(kSampler);
  // An unknown type is left to makeSampler's error.
  if (node && node->isObject()) {
    const SamplerType* entry = node->has({"type"})
                                   ? samplerTypes().find((*node)[{"type"}].asString())
                                   : &samplerTypes().front();
    if (entry) node->declare({"sampler " + entry->name, {&samplerCommonKeys(), &entry->keys}});
  }
  auto sampler = makeSampler(node ? &*node : nullptr);
  const int imageSamples = root.get(kImageSamples);
  int spp = imageSamples;
  if (node) {
    if (auto samples = node->find(kSamples)) {
      spp = node->get(kSamples);
      if (root.find(kImageSamples) && spp != imageSamples)
        samples->fail("disagrees with \"image_samples\"; give the sample count once");
    }
    node->rejectUnknownKeys();
  }
  sampler->setSamplesPerPixel(spp);
  return sampler;
}

// The file's sampler, or the one --sampler names with the file's sample count.
std::unique_ptr<Sampler> sceneSampler(const JsonNode& root, const std::string& override) {
  std::unique_ptr<Sampler> fileSampler = parseSampler(root);
  if (override.empty()) return fileSampler;
  std::unique_ptr<Sampler> sampler = makeSampler(override, "--sampler");
  sampler->setSamplesPerPixel(fileSampler->samplesPerPixel());
  return sampler;
}

SceneFile build(const JsonNode& root, const std::filesystem::path& file,
                const SceneOverrides& overrides) {
  using namespace scene_keys;
  SceneFile result;
  result.name = file.stem().string();
  result.scene = std::make_unique<Scene>();
  Scene& scene = *result.scene;
  TextureFactory textures;
  MaterialFactory materials(textures, result.warnings);
  root.declare({"the scene file", {&sceneKeys()}});

  scene.setCamera(parseCamera(root[kCamera], overrides.width));
  if (auto bg = root.find(kBackground)) scene.setBackground(parseBackground(*bg, textures));
  root.find(kAccelerator);  // DIRT's choice of accelerator: one serves all
  auto integrator = root.find(kIntegrator);
  result.integrator = overrideIntegrator(
      parseIntegratorSettings(integrator ? &*integrator : nullptr), overrides.integrator);
  result.sampler = sceneSampler(root, overrides.sampler);

  if (auto list = root.find(kMaterials)) {
    if (!list->isArray()) list->fail("expected an array of materials");
    std::set<std::string> names;
    for (size_t i = 0; i < list->size(); ++i)
      if (const JsonNode m = (*list)[i]; m.isObject())
        if (const auto name = m.find({"name"}); name && name->isString())
          names.insert(name->asString());
    materials.setListedNames(std::move(names));
    for (size_t i = 0; i < list->size(); ++i) {
      const JsonNode m = (*list)[i];
      const JsonNode name = m[{"name"}];
      auto material = materials.make(m);
      materials.addNamed(name, material);
      scene.addMaterial(material);
    }
  }
  if (auto list = root.find(kSurfaces)) {
    if (!list->isArray()) list->fail("expected an array of surfaces");
    SurfaceParser surfaces(scene, materials);
    for (size_t i = 0; i < list->size(); ++i) surfaces.parse((*list)[i], Transform());
  }
  root.rejectUnknownKeys();
  scene.finalize();
  return result;
}

}  // namespace

SceneFile loadScene(const std::filesystem::path& file, const SceneOverrides& overrides) {
  if (std::filesystem::is_directory(file))
    throw VerityError(file.string(), "", "is a directory, not a scene file");
  return build(JsonNode::load(file), file, overrides);
}

SceneFile loadSceneText(const std::string& text, const std::filesystem::path& file,
                        const SceneOverrides& overrides) {
  return build(JsonNode::parse(text, file), file, overrides);
}

}  // namespace verity
