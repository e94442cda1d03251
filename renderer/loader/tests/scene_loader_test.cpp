// Every key and spelling of the scene format, and every class of error the loader reports.
#include "loader/scene_loader.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "params/transform_parser.h"

namespace verity {
namespace {

const char* kCamera =
    R"("camera": {"transform": {"from": [0,0,5], "at": [0,0,0], "up": [0,1,0]}, "vfov": 45, "resolution": [8, 6]})";

std::string sceneWith(const std::string& rest) {
  return std::string("{") + kCamera + (rest.empty() ? "" : ", " + rest) + "}";
}

// Loads text expecting an error; returns the message.
std::string loadError(const std::string& text, const std::string& file = "/tmp/bad.json") {
  try {
    loadSceneText(text, file);
  } catch (const VerityError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an error for: " << text;
  return "";
}

TEST(SceneLoader, MinimalSceneUsesDefaults) {
  SceneFile f = loadSceneText(sceneWith(""), "/tmp/minimal.json");
  EXPECT_EQ(f.name, "minimal");
  EXPECT_EQ(f.integrator.type->name, "path_tracer_mats");
  EXPECT_EQ(f.integrator.maxBounces, 64);
  EXPECT_EQ(f.sampler->samplesPerPixel(), 1);
  EXPECT_EQ(f.scene->camera().resolution(), Vector2i(8, 6));
  EXPECT_FALSE(f.scene->summary().hasEmitters());
}

TEST(SceneLoader, SampleCountSpellings) {
  EXPECT_EQ(
      loadSceneText(sceneWith(R"("image_samples": 7)"), "/tmp/a.json").sampler->samplesPerPixel(),
      7);
  EXPECT_EQ(
      loadSceneText(sceneWith(R"("sampler": {"type": "stratified", "samples": 9})"), "/tmp/a.json")
          .sampler->samplesPerPixel(),
      9);
  EXPECT_NE(loadError(sceneWith(R"("image_samples": 4, "sampler": {"samples": 8})"))
                .find("sampler.samples"),
            std::string::npos);
}

TEST(SceneLoader, IntegratorSpellings) {
  for (const char* spelling : {"path_tracer_mis", "path tracer mis"}) {
    SceneFile f = loadSceneText(sceneWith(std::string(R"("integrator": {"type": ")") + spelling +
                                          R"(", "max bounces": 5, "power": 2})"),
                                "/tmp/a.json");
    EXPECT_EQ(f.integrator.type->name, "path_tracer_mis");
    EXPECT_EQ(f.integrator.maxBounces, 5);
    EXPECT_EQ(f.integrator.misPower, 2);
  }
  EXPECT_EQ(
      loadSceneText(sceneWith(R"("integrator": {"type": "bdpt", "rr_depth": 7})"), "/tmp/a.json")
          .integrator.rrDepth,
      7);
  EXPECT_EQ(loadSceneText(sceneWith(R"("integrator": {"type": "bdpt"})"), "/tmp/a.json")
                .integrator.rrDepth,
            kDefaultRouletteDepth);
  EXPECT_EQ(
      loadSceneText(sceneWith(R"("integrator": {"type": "light_tracer", "rr_threshold": 0.25})"),
                    "/tmp/a.json")
          .integrator.rrThreshold,
      0.25f);
  // Unset, the threshold is the type's own, also when the command line changes the type.
  const IntegratorSettings unset =
      loadSceneText(sceneWith(R"("integrator": {"type": "path_tracer_mis"})"), "/tmp/a.json")
          .integrator;
  EXPECT_FALSE(unset.rrThreshold.has_value());
  EXPECT_EQ(makeRoulette(unset).threshold(), kPathTracerRouletteThreshold);
  IntegratorOverrides toBdpt;
  toBdpt.type = &integratorTypeNamed("bdpt", "--integrator");
  EXPECT_EQ(makeRoulette(overrideIntegrator(unset, toBdpt)).threshold(), kBdptRouletteThreshold);
  for (const char* type : {"normals", "ao", "path_tracer_mats", "path_tracer_nee"})
    EXPECT_EQ(loadSceneText(sceneWith(std::string(R"("integrator": {"type": ")") + type + "\"}"),
                            "/tmp/a.json")
                  .integrator.type->name,
              type);
}

// A mirror image of a triangle (no vertex normals) keeps its front on the mirrored side: the
// same side as a quad's, whose front a mirroring transform keeps too.
TEST(SceneLoader, AMirroringTransformKeepsATrianglesFront) {
  for (const char* transform :
       {R"({"scale": [1, 1, 1]})", R"({"scale": [-1, 1, 1]})", R"({"scale": [1, 1, -1]})"}) {
    SceneFile f = loadSceneText(sceneWith(fmt::format(R"("surfaces": [
          {{"type": "triangle", "positions": [[-1,-1,0],[1,-1,0],[0,1,0]], "material": {{"type": "lambertian"}}, "transform": {0}}},
          {{"type": "quad", "size": 2, "material": {{"type": "lambertian"}}, "transform": [{0}, {{"translate": [0, 0, -3]}}]}}])",
                                                      transform)),
                                "/tmp/a.json");
    SurfaceInteraction triangle, quad;
    const Ray ray(Point3f(0.1f, -0.2f, 5), Vector3f(0, 0, -1));
    ASSERT_TRUE(f.scene->intersect(ray, triangle)) << transform;
    ASSERT_TRUE(f.scene->intersect(Ray(triangle.p + Vector3f(0, 0, -1e-3f), ray.d), quad));
    EXPECT_GT(triangle.ng.dot(quad.ng), 0.99f) << transform;
  }
}

// Materials that would invent or lose energy load, with one warning each naming its path: an
// albedo above 1 (constant or a texture that can reach it), a light emitting nothing.
TEST(SceneLoader, WarnsOncePerMaterialThatInventsOrLosesEnergy) {
  SceneFile f = loadSceneText(sceneWith(R"(
    "materials": [
      {"name": "bright", "type": "lambertian", "albedo": [0.5, 1.2, 0.5]},
      {"name": "fine", "type": "lambertian", "albedo": 1},
      {"name": "dark", "type": "diffuse light", "emit": 0},
      {"name": "checks", "type": "oren-nayar",
       "albedo": {"type": "checker", "even": 0.5, "odd": {"type": "marble", "base": [1, 3, 1]}}}],
    "surfaces": [
      {"type": "sphere", "material": "bright"}, {"type": "sphere", "material": "bright"},
      {"type": "sphere", "material": "fine"}, {"type": "quad", "material": "dark"},
      {"type": "sphere", "material": "checks"},
      {"type": "sphere", "material": {"type": "ggx", "albedo": 1.01}}])"),
                              "/tmp/w.json");
  std::vector<std::string> where;
  for (const VerityError& w : f.warnings) {
    EXPECT_EQ(w.file(), "/tmp/w.json");
    where.push_back(w.jsonPath());
  }
  EXPECT_EQ(where,
            (std::vector<std::string>{"materials[0].albedo", "materials[2]", "materials[3].albedo",
                                      "surfaces[5].material.albedo"}));
  EXPECT_NE(f.warnings[0].problem().find("1.2"), std::string::npos);
  EXPECT_NE(f.warnings[2].problem().find("texture that reaches 3"), std::string::npos);
}

TEST(SceneLoader, AShippedSceneHasNoWarnings) {
  for (const char* name : {"cornell-box", "furnace", "textured-box", "veach-mats"})
    EXPECT_TRUE(loadScene(std::filesystem::path(VERITY_SOURCE_DIR) / "scenes" /
                          (std::string(name) + ".json"))
                    .warnings.empty())
        << name;
}

TEST(SceneLoader, SurfacesMaterialsAndBackgrounds) {
  const std::string text = sceneWith(R"(
    "accelerator": {"type": "bbh"},
    "background": {"type": "constant", "color": [0.1, 0.2, 0.3]},
    "materials": [{"type": "lambertian", "name": "white", "albedo": 0.7},
                  {"type": "diffuse_light", "name": "lamp", "emit": [1, 2, 3]}],
    "surfaces": [
      {"type": "sphere", "radius": 2, "material": "white", "transform": {"o": [1, 0, 0]}},
      {"type": "quad", "size": [1, 2], "material": "lamp"},
      {"type": "quad", "size": 3, "material": {"type": "diffuse light", "emit": 1}},
      {"type": "triangle", "positions": [[0,0,0],[1,0,0],[0,1,0]], "normals": [[0,0,1],[0,0,1],[0,0,1]], "material": "white"},
      {"type": "group", "transform": {"translate": [0, 5, 0]}, "children": [
        {"type": "sphere", "material": "white"}]}
    ])");
  SceneFile f = loadSceneText(text, "/tmp/a.json");
  const SceneSummary& s = f.scene->summary();
  EXPECT_EQ(s.shapes, 5u);
  EXPECT_EQ(s.areaLights, 2u);
  EXPECT_TRUE(s.emittingBackground);
  EXPECT_EQ(f.scene->lights().size(), 3u);
  // The group's translation reaches its child: the scene extends to y = 6.
  EXPECT_NEAR(f.scene->bounds().hi.y(), 6.0f, 1e-4f);
}

TEST(SceneLoader, BackgroundForms) {
  EXPECT_NE(loadSceneText(sceneWith(R"("background": 1)"), "/tmp/a.json").scene->background(),
            nullptr);
  EXPECT_NE(
      loadSceneText(sceneWith(R"("background": [0, 0.5, 0])"), "/tmp/a.json").scene->background(),
      nullptr);
  // A black background is no emitter at all.
  EXPECT_EQ(loadSceneText(sceneWith(R"("background": 0)"), "/tmp/a.json").scene->background(),
            nullptr);
}

TEST(SceneLoader, TextureForms) {
  const std::string text = sceneWith(R"(
    "surfaces": [
      {"type": "sphere", "material": {"type": "lambertian", "albedo": {"type": "constant", "color": 0.5}}},
      {"type": "sphere", "material": {"type": "lambertian", "albedo": {"type": "checker", "even": 1, "odd": [0, 0, 0], "scale": 4}}},
      {"type": "sphere", "material": {"type": "lambertian", "albedo": {"type": "marble", "veins": 0.1, "base": 0.9, "scale": 2}}}
    ])");
  SceneFile f = loadSceneText(text, "/tmp/a.json");
  EXPECT_EQ(f.scene->summary().texturedMaterials, 2u);
}

TEST(SceneLoaderErrors, SyntaxErrorNamesLineAndColumn) {
  const std::string message = loadError("{\n  \"camera\": {\n    \"vfov\": 40,,\n  }\n}");
  EXPECT_NE(message.find("/tmp/bad.json"), std::string::npos) << message;
  EXPECT_NE(message.find("line 3"), std::string::npos) << message;
  EXPECT_NE(message.find("column 16"), std::string::npos) << message;
}

struct ErrorCase {
  const char* json;
  const char* path;  // the JSON path the message must name
};

class SceneLoaderErrorCases : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(SceneLoaderErrorCases, NamesFileAndPath) {
  const std::string message = loadError(sceneWith(GetParam().json));
  EXPECT_NE(message.find("/tmp/bad.json"), std::string::npos) << message;
  EXPECT_NE(message.find(GetParam().path), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    All, SceneLoaderErrorCases,
    ::testing::Values(
        ErrorCase{R"("colour": 1)", "colour: unknown key"},
        ErrorCase{
            R"("surfaces": [{"type": "sphere", "radius": -1, "material": {"type": "lambertian"}}])",
            "surfaces[0].radius"},
        ErrorCase{
            R"("surfaces": [{"type": "sphere", "radius": "big", "material": {"type": "lambertian"}}])",
            "surfaces[0].radius: expected a number"},
        ErrorCase{R"("surfaces": [{"type": "cube", "material": {"type": "lambertian"}}])",
                  "surfaces[0].type"},
        ErrorCase{R"("surfaces": [{"type": "sphere", "material": "nothing"}])",
                  "surfaces[0].material"},
        ErrorCase{R"("surfaces": [{"type": "sphere"}])",
                  "surfaces[0]: missing required key \"material\""},
        ErrorCase{
            R"("surfaces": [{"type": "sphere", "material": {"type": "lambertian", "albedo": [1, 2]}}])",
            "surfaces[0].material.albedo"},
        ErrorCase{
            R"("surfaces": [{"type": "sphere", "material": {"type": "lambertian", "albedo": -0.5}}])",
            "surfaces[0].material.albedo"},
        ErrorCase{
            R"("surfaces": [{"type": "sphere", "material": {"type": "lambertian", "albdo": 0.5}}])",
            "surfaces[0].material.albdo: unknown key"},
        ErrorCase{R"("surfaces": [{"type": "sphere", "material": {"type": "velvet"}}])",
                  "surfaces[0].material.type"},
        ErrorCase{
            R"("surfaces": [{"type": "sphere", "material": {"type": "lambertian", "albedo": {"type": "wood"}}}])",
            "surfaces[0].material.albedo.type"},
        ErrorCase{
            R"("surfaces": [{"type": "mesh", "filename": "missing.obj", "material": {"type": "lambertian"}}])",
            "surfaces[0].filename"},
        ErrorCase{
            R"("surfaces": [{"type": "sphere", "material": {"type": "lambertian", "albedo": {"type": "image", "filename": "missing.png"}}}])",
            "surfaces[0].material.albedo.filename"},
        ErrorCase{
            R"("surfaces": [{"type": "sphere", "material": {"type": "lambertian"}, "transform": {"scale": [1, 2, 1]}}])",
            "surfaces[0].transform"},
        ErrorCase{
            R"("surfaces": [{"type": "quad", "material": {"type": "lambertian"}, "transform": {"scale": 0}}])",
            "surfaces[0].transform.scale"},
        ErrorCase{
            R"("surfaces": [{"type": "quad", "material": {"type": "lambertian"}, "transform": {"translate": [1,1,1], "scale": 2}}])",
            "surfaces[0].transform"},
        ErrorCase{
            R"("surfaces": [{"type": "quad", "material": {"type": "lambertian"}, "transform": {"matrix": [1, 2, 3]}}])",
            "surfaces[0].transform.matrix"},
        ErrorCase{
            R"("surfaces": [{"type": "quad", "size": 0, "material": {"type": "lambertian"}}])",
            "surfaces[0].size"},
        ErrorCase{R"("surfaces": {"type": "quad"})", "surfaces: expected an array"},
        ErrorCase{R"("integrator": {"type": "photon_mapper"})", "integrator.type"},
        ErrorCase{R"("integrator": {"type": "path_tracer_nee", "max_bounces": -1})",
                  "integrator.max_bounces"},
        ErrorCase{R"("integrator": {"type": "path_tracer_nee", "max_bounces": 2.5})",
                  "integrator.max_bounces"},
        ErrorCase{
            R"("integrator": {"type": "path_tracer_nee", "max_bounces": 3, "max bounces": 3})",
            "integrator"},
        ErrorCase{R"("integrator": {"type": "path_tracer_nee", "rr_depth": -1})",
                  "integrator.rr_depth: expected an integer >= 1, found -1"},
        ErrorCase{R"("integrator": {"type": "bdpt", "rr_depth": 2.5})", "integrator.rr_depth"},
        ErrorCase{R"("integrator": {"type": "light_tracer", "rr_depth": 0})",
                  "integrator.rr_depth"},
        ErrorCase{R"("integrator": {"type": "ao", "rr_depth": 3})",
                  "integrator.rr_depth: unknown key"},
        ErrorCase{R"("integrator": {"type": "path_tracer_nee", "rr_threshold": 0})",
                  "integrator.rr_threshold: expected a number in (0, 1], found 0"},
        ErrorCase{R"("integrator": {"type": "bdpt", "rr_threshold": 1.5})",
                  "integrator.rr_threshold"},
        ErrorCase{R"("integrator": {"type": "light_tracer", "rr_threshold": "half"})",
                  "integrator.rr_threshold"},
        ErrorCase{R"("integrator": {"type": "normals", "rr_threshold": 0.5})",
                  "integrator.rr_threshold: unknown key"},
        ErrorCase{R"("sampler": {"type": "zsobol"})", "sampler.type"},
        ErrorCase{R"("image_samples": 0)", "image_samples"},
        ErrorCase{R"("background": {"type": "sky"})", "background.type"},
        ErrorCase{R"("background": {"type": "image", "filename": "nope.exr"})",
                  "background.filename"},
        ErrorCase{R"("background": [1, -1, 1])", "background"},
        ErrorCase{R"("materials": [{"type": "lambertian"}])",
                  "materials[0]: missing required key \"name\""},
        ErrorCase{R"("materials": [{"type": "diffuse light", "name": "l", "emit": 1e39}])",
                  "materials[0].emit"},
        ErrorCase{
            R"("materials": [{"type": "lambertian", "name": "m"}, {"type": "lambertian", "name": "m", "albedo": 0.2}])",
            "materials[1].name: a material named \"m\" is already defined"},
        // Far-away geometry would put ray origins beyond what Embree accepts.
        ErrorCase{
            R"("surfaces": [{"type": "sphere", "material": {"type": "lambertian"}, "transform": {"translate": [1e24, 0, 0]}}])",
            "surfaces[0]: lies outside the supported extent"},
        ErrorCase{
            R"("surfaces": [{"type": "group", "transform": {"scale": 1e10}, "children": [{"type": "quad", "size": 1e6, "material": {"type": "lambertian"}}]}])",
            "surfaces[0].children[0]: lies outside the supported extent"},
        ErrorCase{
            R"("surfaces": [{"type": "quad", "material": {"type": "lambertian"}, "transform": {"matrix": [1,0,0,0, 0,1,0,0, 0,0,1,1, 1,0,0,1]}}])",
            "surfaces[0].transform.matrix: the last row must be [0, 0, 0, 1]"},
        // A repeated key is named by its path, past arrays of values and of arrays.
        ErrorCase{
            R"("surfaces": [{"type": "sphere", "material": {"type": "lambertian"}}, {"type": "triangle", "positions": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "material": {"type": "lambertian", "albedo": 0.5, "albedo": 0.2}}])",
            "surfaces[1].material.albedo: the key appears twice in one object"}));

// Builds a value nested `depth` levels deep: groups, blends or textures recurse once per level.
std::string nestedGroups(int depth) {
  std::string open, close;
  for (int i = 0; i < depth; ++i) {
    open += R"({"type": "group", "children": [)";
    close += "]}";
  }
  return R"("surfaces": [)" + open + R"({"type": "sphere", "material": {"type": "lambertian"}})" +
         close + "]";
}

TEST(SceneLoaderErrors, DeepNestingIsAnErrorNotAStackOverflow) {
  EXPECT_NO_THROW(loadSceneText(sceneWith(nestedGroups(20)), "/tmp/nested.json"));
  for (int depth : {40, 100000}) {
    const std::string message = loadError(sceneWith(nestedGroups(depth)));
    EXPECT_NE(message.find("nested deeper than 64 levels"), std::string::npos) << depth;
    EXPECT_NE(message.find("surfaces[0].children[0].children[0]"), std::string::npos) << depth;
  }
}

TEST(SceneLoader, LightChoiceStaysFiniteForPowersBeyondSinglePrecision) {
  // emit × π × area overflows a float; the light-selection probabilities must not.
  SceneFile f = loadSceneText(sceneWith(R"(
      "surfaces": [
        {"type": "quad", "size": 4, "material": {"type": "diffuse light", "emit": 3e38}},
        {"type": "quad", "size": 1, "material": {"type": "diffuse light", "emit": 1},
         "transform": {"translate": [0, 0, 1]}}])"),
                              "/tmp/bright.json");
  const auto& lights = f.scene->lights();
  ASSERT_EQ(lights.size(), 2u);
  EXPECT_FLOAT_EQ(f.scene->lightPmf(lights[0]), 1.0f);
  EXPECT_GE(f.scene->lightPmf(lights[1]), 0.0f);
  EXPECT_LT(f.scene->lightPmf(lights[1]), 1e-30f);
}

// A command line's overrides apply to the parsed file, before the scene is built; their errors
// name the option, not the file.
TEST(SceneLoader, OverridesApplyBeforeTheSceneIsBuilt) {
  const std::string text = sceneWith(
      R"("integrator": {"type": "path_tracer_nee", "max_bounces": 7},
         "sampler": {"type": "independent", "samples": 5})");
  SceneOverrides overrides = SceneOverrides::atWidth(20);
  overrides.integrator.type = &integratorTypeNamed("bdpt", "--integrator");
  overrides.integrator.rrDepth = 9;
  overrides.integrator.rrThreshold = 0.125f;
  overrides.sampler = "sobol";
  const SceneFile f = loadSceneText(text, "/tmp/a.json", overrides);
  EXPECT_EQ(f.scene->camera().resolution(), Vector2i(20, 15));  // 8 × 6 widened, aspect kept
  EXPECT_EQ(f.integrator.type->name, "bdpt");
  EXPECT_EQ(f.integrator.maxBounces, 7);  // the file's, not overridden
  EXPECT_EQ(f.integrator.rrDepth, 9);
  EXPECT_EQ(f.integrator.rrThreshold, 0.125f);
  EXPECT_FALSE(f.sampler->samplesAreIndependent());  // sobol in place of the independent one
  EXPECT_EQ(f.sampler->samplesPerPixel(), 5);

  const auto error = [&](const SceneOverrides& o) {
    try {
      loadSceneText(text, "/tmp/a.json", o);
    } catch (const VerityError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error(SceneOverrides::atWidth(100000)).rfind("--resolution: 100000 pixels wide", 0),
            0u);
  EXPECT_EQ(error(SceneOverrides::atWidth(20000)).rfind("--resolution: the image must have", 0),
            0u);
  SceneOverrides roulette;
  roulette.integrator.type = &integratorTypeNamed("normals", "--integrator");
  roulette.integrator.rrDepth = 2;
  EXPECT_EQ(error(roulette).rfind("--rr-depth: ", 0), 0u) << error(roulette);
  roulette.integrator.rrDepth = 0;
  roulette.integrator.rrThreshold = 0.5f;
  EXPECT_EQ(error(roulette).rfind("--rr-threshold: ", 0), 0u) << error(roulette);
  SceneOverrides sampler;
  sampler.sampler = "sobolev";
  EXPECT_EQ(error(sampler).rfind("--sampler: ", 0), 0u) << error(sampler);
}

// An integrator type says it has Russian roulette (--rr-depth and --rr-threshold apply) exactly
// when its scene object takes "rr_depth" and "rr_threshold".
TEST(SceneLoader, RussianRouletteFlagMatchesTheKeysItReads) {
  for (const IntegratorType& type : integratorTypes()) {
    const std::string text = sceneWith(R"("integrator": {"type": ")" + type.name +
                                       R"(", "rr_depth": 5, "rr_threshold": 0.75})");
    bool reads = true;
    try {
      const IntegratorSettings s = loadSceneText(text, "/tmp/a.json").integrator;
      reads = s.rrDepth == 5 && s.rrThreshold == 0.75f;
    } catch (const VerityError&) {
      reads = false;
    }
    EXPECT_EQ(type.hasRussianRoulette, reads) << type.name;
  }
}

TEST(SceneLoaderErrors, CameraValues) {
  auto cam = [](const std::string& body) { return loadError("{\"camera\": {" + body + "}}"); };
  EXPECT_NE(cam(R"("resolution": [0, 10])").find("camera.resolution[0]"), std::string::npos);
  EXPECT_NE(cam(R"("resolution": [10])").find("camera.resolution"), std::string::npos);
  EXPECT_NE(cam(R"("vfov": 180)").find("camera.vfov"), std::string::npos);
  EXPECT_NE(cam(R"("fdist": 0)").find("camera.fdist"), std::string::npos);
  EXPECT_NE(cam(R"("aperture": -1)").find("camera.aperture"), std::string::npos);
  EXPECT_NE(cam(R"("aperture": 1e30)").find("camera.aperture"), std::string::npos);
  EXPECT_NE(cam(R"("fdist": 1e30)").find("camera.fdist"), std::string::npos);
  EXPECT_NE(cam(R"("resolution": [32768, 32768])").find("camera.resolution: the image must have"),
            std::string::npos);
  EXPECT_NE(cam(R"("transform": {"translate": [0, 0, 1e20]})").find("camera.transform: lies"),
            std::string::npos);
  EXPECT_NE(cam(R"("transform": {"from": [0,0,0], "at": [0,0,0]})").find("camera.transform"),
            std::string::npos);
  EXPECT_NE(cam(R"("transform": {"from": [1e20, 0, 0], "at": [0, 0, 0]})")
                .find("camera.transform: lies outside the supported extent"),
            std::string::npos);
  EXPECT_NE(cam(R"("transform": {"from": [0, 0, 5], "at": [0, 0, 0], "up": [0, 1e-30, 1]})")
                .find("\"up\" is parallel"),
            std::string::npos);
  EXPECT_NE(loadError("{}").find("missing required key \"camera\""), std::string::npos);
  EXPECT_NE(loadError("[1, 2]").find("must be a JSON object"), std::string::npos);
}

TEST(SceneLoaderErrors, MissingSceneFile) {
  try {
    loadScene("/nonexistent/scene.json");
    FAIL();
  } catch (const VerityError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/scene.json"), std::string::npos);
  }
}

TEST(SceneLoaderErrors, BrokenObjNamesTheMesh) {
  const auto dir = std::filesystem::temp_directory_path() / "verity_obj_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "broken.obj") << "v 0 0 0\nv 1 0 0\nf 1 2 7\n";
  std::ofstream(dir / "empty.obj") << "# nothing\n";
  for (const char* name : {"broken.obj", "empty.obj"}) {
    const std::string message =
        loadError(sceneWith(std::string(R"("surfaces": [{"type": "mesh", "filename": ")") + name +
                            R"(", "material": {"type": "lambertian"}}])"),
                  (dir / "scene.json").string());
    EXPECT_NE(message.find("surfaces[0].filename"), std::string::npos) << message;
    EXPECT_NE(message.find(name), std::string::npos) << message;
  }
}

TEST(Transforms, FormsCompose) {
  auto parse = [](const std::string& text) {
    return parseTransform(JsonNode::parse("{\"t\": " + text + "}", "/tmp/t.json")[{"t"}]);
  };
  const Point3f p(1, 2, 3);
  EXPECT_TRUE(parse(R"({"translate": [1, 1, 1]})").point(p).isApprox(Point3f(2, 3, 4)));
  EXPECT_TRUE(parse(R"({"scale": 2})").point(p).isApprox(Point3f(2, 4, 6)));
  EXPECT_TRUE(parse(R"({"axis": [0, 0, 1], "angle": 90})")
                  .point(Point3f(1, 0, 0))
                  .isApprox(Point3f(0, 1, 0), 1e-6f));
  // Array entries apply first to last: scale, then translate.
  EXPECT_TRUE(
      parse(R"([{"scale": 2}, {"translate": [1, 0, 0]}])").point(p).isApprox(Point3f(3, 4, 6)));
  EXPECT_TRUE(parse(R"({"matrix": [1,0,0,5, 0,1,0,0, 0,0,1,0, 0,0,0,1]})")
                  .point(p)
                  .isApprox(Point3f(6, 2, 3)));
  EXPECT_TRUE(parse(R"({"o": [1, 0, 0], "x": [0, 1, 0], "y": [-1, 0, 0]})")
                  .point(Point3f(1, 0, 0))
                  .isApprox(Point3f(1, 1, 0)));
  // Look-at: the camera's −z axis points from "from" to "at"; "to" is a spelling of "at".
  const Transform look = parse(R"({"from": [0, 0, 10], "to": [0, 0, 0], "up": [0, 1, 0]})");
  EXPECT_TRUE(look.vector(Vector3f(0, 0, -1)).isApprox(Vector3f(0, 0, -1)));
  EXPECT_TRUE(look.point(Point3f::Zero()).isApprox(Point3f(0, 0, 10)));
  // Normals stay perpendicular under non-uniform scale.
  const Transform s = parse(R"({"scale": [1, 4, 1]})");
  const Vector3f tangent = s.vector(Vector3f(1, -1, 0));
  EXPECT_NEAR(s.normal(Normal3f(1, 1, 0)).dot(tangent), 0.0f, 1e-6f);
}

}  // namespace
}  // namespace verity
