#include "scene/scene_loader.h"

#include "materials/material_factory.h"
#include "scene/transform_parser.h"
#include "shapes/obj_loader.h"
#include "shapes/quad.h"
#include "shapes/sphere.h"
#include "shapes/triangle_mesh.h"

namespace verity {

namespace {

// The most pixels an image may have (8192²): the film keeps several channels per pixel.
constexpr int64_t kMaxPixels = int64_t{1} << 26;

const std::string kExtentProblem =
    "lies outside the supported extent: every coordinate must be within ±1e15";

bool withinExtent(const Point3f& p) {
  return p.cwiseAbs().maxCoeff() <= kMaxSceneCoordinate;  // false for NaN too
}

std::unique_ptr<Camera> parseCamera(const JsonNode& node) {
  if (!node.isObject()) node.fail("expected a camera object");
  const Transform toWorld = parseOptionalTransform(node);
  if (!withinExtent(toWorld.point(Point3f::Zero()))) node[{"transform"}].fail(kExtentProblem);
  Vector2i resolution(512, 512);
  if (auto r = node.find({"resolution"})) {
    resolution = r->asVector2i(1, 1 << 15);
    if (int64_t{resolution.x()} * resolution.y() > kMaxPixels)
      r->fail("the image must have at most 8192 × 8192 pixels in all");
  }
  const float vfov = node.getFloat({"vfov"}, 90, Range{0, 180, true, true});
  const float fdist = node.getFloat({"fdist"}, 1, Range{0, kMaxSceneCoordinate, true, false});
  const float aperture = node.getFloat({"aperture"}, 0, Range{0, kMaxSceneCoordinate});
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
  const std::string type = node.type();
  std::unique_ptr<EnvironmentLight> light;
  if (type == "constant") {
    const JsonNode color = node[{"color"}];
    const Vector3f c = color.asVector3();
    if ((c.array() < 0).any()) color.fail("background radiance must not be negative");
    light = std::make_unique<EnvironmentLight>(Color3(c.array()));
  } else if (type == "image") {
    const JsonNode file = node[{"filename"}];
    try {
      light = std::make_unique<EnvironmentLight>(
          std::make_shared<ImageTexture>(node.resolve(file.asString()), file.path()));
    } catch (const VerityError& e) {
      if (!e.file().empty()) throw;
      throw VerityError(node.file().string(), e.jsonPath(), e.problem());
    }
  } else {
    node[{"type"}].fail("unknown background type \"" + type + "\" (expected constant or image)");
  }
  node.rejectUnknownKeys();
  return light;
}

class SurfaceParser {
 public:
  SurfaceParser(Scene& scene, MaterialFactory& materials) : scene_(scene), materials_(materials) {}

  void parse(const JsonNode& node, const Transform& parent) {
    if (!node.isObject()) node.fail("expected a surface object");
    const std::string type = node.type();
    const Transform toWorld = parent * parseOptionalTransform(node);
    if (type == "group") {
      const JsonNode children = node[{"children"}];
      if (!children.isArray()) children.fail("expected an array of surfaces");
      for (size_t i = 0; i < children.size(); ++i) parse(children[i], toWorld);
      node.rejectUnknownKeys();
      return;
    }
    std::unique_ptr<Shape> shape;
    if (type == "sphere") {
      const float radius = node.getFloat({"radius"}, 1, Range::positive());
      if (!toWorld.isSimilarity(nullptr))
        node[{"transform"}].fail(
            "a sphere's transform must scale uniformly (no shear or non-uniform scale)");
      shape = std::make_unique<Sphere>(toWorld, radius);
    } else if (type == "quad") {
      Vector2f size(1, 1);
      if (auto s = node.find({"size"})) {
        if (s->isNumber()) {
          size.setConstant(s->asFloat(Range::positive()));
        } else {
          if (!s->isArray() || s->size() != 2) s->fail("expected a number or [width, height]");
          size = Vector2f((*s)[0].asFloat(Range::positive()), (*s)[1].asFloat(Range::positive()));
        }
      }
      shape = std::make_unique<Quad>(toWorld, size);
    } else if (type == "mesh") {
      const JsonNode file = node[{"filename"}];
      try {
        shape = std::make_unique<TriangleMesh>(
            keepFront(loadObj(node.resolve(file.asString()), toWorld, file.path()), toWorld));
      } catch (const VerityError& e) {
        if (!e.file().empty()) throw;
        throw VerityError(node.file().string(), e.jsonPath(), e.problem());
      }
    } else if (type == "triangle") {
      shape = std::make_unique<TriangleMesh>(keepFront(parseTriangle(node, toWorld), toWorld));
    } else {
      node[{"type"}].fail("unknown surface type \"" + type +
                          "\" (expected sphere, quad, mesh, triangle or group)");
    }
    const Bounds3f bounds = shape->bounds();
    if (!withinExtent(bounds.lo) || !withinExtent(bounds.hi)) node.fail(kExtentProblem);
    auto material = materials_.reference(node[{"material"}]);
    node.rejectUnknownKeys();
    scene_.addShape(std::move(shape), std::move(material));
  }

 private:
  // A triangle's front side is the side its winding turns counter-clockwise around; a
  // mirroring transform reverses the winding, so it is reversed back to keep the front on the
  // same side of the surface (as quads do; pbrt flips such normals too).
  static MeshData keepFront(MeshData mesh, const Transform& toWorld) {
    if (toWorld.flipsHandedness())
      for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
        std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
    return mesh;
  }

  static MeshData parseTriangle(const JsonNode& node, const Transform& toWorld) {
    MeshData mesh;
    const JsonNode positions = node[{"positions"}];
    if (!positions.isArray() || positions.size() != 3) positions.fail("expected 3 points");
    for (size_t i = 0; i < 3; ++i)
      mesh.positions.push_back(toWorld.point(positions[i].asVector3()));
    if (auto normals = node.find({"normals"})) {
      if (!normals->isArray() || normals->size() != 3) normals->fail("expected 3 normals");
      for (size_t i = 0; i < 3; ++i) {
        const Normal3f n = toWorld.normal((*normals)[i].asVector3());
        if (!(n.norm() > 0)) (*normals)[i].fail("a normal must not be zero");
        mesh.normals.push_back(n.normalized());
      }
    }
    if (auto uvs = node.find({"uvs"})) {
      if (!uvs->isArray() || uvs->size() != 3) uvs->fail("expected 3 uv pairs");
      for (size_t i = 0; i < 3; ++i) {
        const JsonNode uv = (*uvs)[i];
        if (!uv.isArray() || uv.size() != 2) uv.fail("expected [u, v]");
        mesh.uvs.emplace_back(uv[0].asFloat(), uv[1].asFloat());
      }
    }
    mesh.indices = {0, 1, 2};
    return mesh;
  }

  Scene& scene_;
  MaterialFactory& materials_;
};

std::unique_ptr<Sampler> parseSampler(const JsonNode& root) {
  auto node = root.find({"sampler"});
  auto sampler = makeSampler(node ? &*node : nullptr);
  const int imageSamples = root.getInt({"image_samples"}, 1, 1, 1 << 24);
  int spp = imageSamples;
  if (node) {
    if (auto samples = node->find({"samples"})) {
      spp = samples->asInt(1, 1 << 24);
      if (root.has({"image_samples"}) && spp != imageSamples)
        samples->fail("disagrees with \"image_samples\"; give the sample count once");
    }
    node->rejectUnknownKeys();
  }
  sampler->setSamplesPerPixel(spp);
  return sampler;
}

SceneFile build(const JsonNode& root, const std::filesystem::path& file) {
  SceneFile result;
  result.name = file.stem().string();
  result.scene = std::make_unique<Scene>();
  Scene& scene = *result.scene;
  TextureFactory textures;
  MaterialFactory materials(textures, result.warnings);

  scene.setCamera(parseCamera(root[{"camera"}]));
  if (auto bg = root.find({"background"})) scene.setBackground(parseBackground(*bg, textures));
  root.find({"accelerator"});  // DIRT's choice of accelerator: one serves all
  auto integrator = root.find({"integrator"});
  result.integrator = parseIntegratorSettings(integrator ? &*integrator : nullptr);
  result.sampler = parseSampler(root);

  if (auto list = root.find({"materials"})) {
    if (!list->isArray()) list->fail("expected an array of materials");
    for (size_t i = 0; i < list->size(); ++i) {
      const JsonNode m = (*list)[i];
      const JsonNode name = m[{"name"}];
      auto material = materials.make(m);
      materials.addNamed(name, material);
      scene.addMaterial(material);
    }
  }
  if (auto list = root.find({"surfaces"})) {
    if (!list->isArray()) list->fail("expected an array of surfaces");
    SurfaceParser surfaces(scene, materials);
    for (size_t i = 0; i < list->size(); ++i) surfaces.parse((*list)[i], Transform());
  }
  root.rejectUnknownKeys();
  scene.finalize();
  return result;
}

}  // namespace

SceneFile loadScene(const std::filesystem::path& file) {
  return build(JsonNode::load(file), file);
}

SceneFile loadSceneText(const std::string& text, const std::filesystem::path& file) {
  return build(JsonNode::parse(text, file), file);
}

}  // namespace verity
