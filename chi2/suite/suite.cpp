#include "chi2/suite/suite.h"

#include <fmt/format.h>

#include <span>
#include <utility>

#include "chi2/suite/suite_significance.h"
#include "materials/material_factory.h"
#include "materials/named_conductors.h"
#include "params/json_node.h"

namespace verity::chi2::suite {

namespace {

// A number as part of a GoogleTest name: 0.05 → 0p05.
std::string token(double v) {
  std::string s = fmt::format("{}", v);
  for (char& c : s)
    if (c == '.') c = 'p';
  return s;
}

const double kAlphas[] = {0.01, 0.05, 0.1, 0.3, 0.6, 1.0};
const double kIncidences[] = {0, 30, 60, 80, 89, 89.9};
// The incidences of the rotated shading normal (rotatedNormal), whose tilt of 29° sets the
// incidence the material sees: 29.2°, 51.3°, 68.5° and 77.3° from these, at an azimuth other
// than 0. kIncidences' 30 and 89 would give 30.1° and 76.5°, within a degree of the first
// and the last.
const double kRotatedIncidences[] = {0, 60, 80, 89.9};
// An index within 1e-3 of 1 is index-matched: RoughDielectric turns into a smooth
// pass-through there, a delta lobe the histogram cannot see (rough_dielectric.h), and the
// test would be INCONCLUSIVE with no valid sample. 1/1.001 = 0.999001 lies inside that band
// (it "passed" having tested nothing); 1/1.002 = 0.998004 is the nearest below 1 outside it.
const double kIors[] = {1.001, 1.33, 1.5, 2.4, 1 / 1.002, 1 / 1.33, 1 / 1.5, 1 / 2.4};
const char* kSamplings[] = {"visible", "normals"};
const char* kDistributions[] = {"beckmann", "ggx"};
// The incidences at which each corner of an accepted range is tested: normal, oblique,
// grazing, and 90° (wi.z = cos 90° = 6e-17 in single precision).
const double kCornerIncidences[] = {0, 45, 89.9, 90};

}  // namespace

Vector3f rotatedNormal() {
  return Vector3f(0.25f, 0.5f, 1.0f).normalized();
}

std::vector<WarpCase> warpCases() {
  std::vector<WarpCase> v;
  for (WarpKind k : {WarpKind::SquareIdentity, WarpKind::DiskPolar, WarpKind::DiskConcentric,
                     WarpKind::UniformSphere, WarpKind::UniformHemisphere,
                     WarpKind::CosineHemisphere, WarpKind::Triangle})
    v.push_back({warpName(k), k, 0, true});
  for (double c : {0.9, 0.0, -0.5})
    v.push_back({"spherical_cap_" + token(c), WarpKind::SphericalCap, float(c), true});
  for (auto& w : v)
    for (char& ch : w.name)
      if (ch == '-') ch = 'm';
  return v;
}

std::vector<MicrofacetCase> microfacetCases() {
  std::vector<MicrofacetCase> v;
  // Every distribution and sampling mode at each roughness and incidence, named with `prefix`.
  auto sweep = [&](const std::string& prefix, const auto& alphas, const auto& incidences) {
    for (int t = 0; t < 2; ++t)
      for (int s = 0; s < 2; ++s)
        for (double a : alphas)
          for (double th : incidences) {
            MicrofacetCase c;
            c.type = t ? MicrofacetType::GGX : MicrofacetType::Beckmann;
            c.sampling = s ? MicrofacetSampling::Normals : MicrofacetSampling::Visible;
            c.alpha = float(a);
            c.incidence = th;
            c.name = fmt::format("{}{}_{}_a{}_t{}", prefix, kDistributions[t], kSamplings[s],
                                 token(a), token(th));
            v.push_back(c);
          }
  };
  sweep("", kAlphas, kIncidences);
  for (size_t i = 0; i < v.size(); i += 12) v[i].quick = true;
  // The corners of the accepted roughness (kAlphaRange: 1e-4 to 4) at normal, oblique,
  // grazing and exactly grazing incidence (docs/checks.md, "Every accepted value at its
  // extremes"), appended so that the quick subset stays as it was.
  sweep("corner_", std::initializer_list<double>{1e-4, 4.0}, kCornerIncidences);
  return v;
}

std::vector<BsdfCase> bsdfCases() {
  std::vector<BsdfCase> v;
  auto add = [&](std::string name, std::string json, double th, bool inside, bool rotated) {
    BsdfCase c;
    c.name =
        fmt::format("{}_{}_t{}{}", name, inside ? "in" : "out", token(th), rotated ? "_rot" : "");
    c.json = std::move(json);
    c.incidence = th;
    c.inside = inside;
    c.rotated = rotated;
    v.push_back(std::move(c));
  };
  for (bool rot : {false, true}) {
    for (double th :
         rot ? std::span<const double>(kRotatedIncidences) : std::span<const double>(kIncidences)) {
      add("lambertian", R"({"type":"lambertian","albedo":0.8})", th, false, rot);
      for (double e : {2.0, 10.0, 100.0}) {
        add("phong_e" + token(e),
            fmt::format(R"({{"type":"phong","albedo":0.8,"exponent":{}}})", e), th, false, rot);
        add("blinnphong_e" + token(e),
            fmt::format(R"({{"type":"blinnphong","albedo":0.8,"exponent":{}}})", e), th, false,
            rot);
      }
      for (double s : {0.1, 0.35, 1.0})
        add("orennayar_s" + token(s),
            fmt::format(R"({{"type":"oren-nayar","albedo":0.8,"sigma":{}}})", s), th, false, rot);
      // Rough conductors with the seed report's complex index 0.34 + 3.9i.
      for (const char* d : kDistributions)
        for (const char* s : kSamplings)
          for (double a : kAlphas)
            add(fmt::format("{}_{}_a{}", d, s, token(a)),
                fmt::format(R"({{"type":"{}","alpha":{},"ior":0.34,"ext":3.9,"sampling":"{}"}})", d,
                            a, s),
                th, false, rot);
      // Rough dielectric: the alpha sweep at ior 1.5, from outside and from inside (beyond
      // the critical angle of 41.8° the inside incidences are under total internal
      // reflection for the macro-surface); the rotated normal from outside only.
      for (const char* d : kDistributions)
        for (const char* s : kSamplings)
          for (double a : kAlphas)
            for (bool inside : {false, true}) {
              if (rot && inside) continue;
              add(fmt::format("roughdielectric_{}_{}_a{}_ior1p5", d, s, token(a)),
                  fmt::format(R"({{"type":"rough_dielectric","distribution":"{}","alpha":{},)"
                              R"("ior":1.5,"sampling":"{}"}})",
                              d, a, s),
                  th, inside, rot);
            }
    }
  }
  // Rough dielectric: the index sweep at alpha 0.3 (both sides, normal frame; ior < 1 from
  // outside is total internal reflection territory too).
  for (const char* d : kDistributions)
    for (const char* s : kSamplings)
      for (double ior : kIors) {
        if (ior == 1.5) continue;  // in the alpha sweep above
        for (double th : {0.0, 60.0, 89.0})
          for (bool inside : {false, true})
            add(fmt::format("roughdielectric_{}_{}_a0p3_ior{}", d, s,
                            token(std::round(ior * 1e4) / 1e4)),
                fmt::format(R"({{"type":"rough_dielectric","distribution":"{}","alpha":0.3,)"
                            R"("ior":{},"sampling":"{}"}})",
                            d, ior, s),
                th, inside, false);
      }
  // Appended after the sweeps above so that their quick subset stays as it was.
  // Rough conductors with one index per channel: an RGB index, and the measured metals of
  // named_conductors.h ("conductor"), at incidences normal, oblique and grazing.
  const double kConductorIncidences[] = {0, 60, 89};
  for (const char* d : kDistributions)
    for (const char* s : kSamplings)
      for (double a : {0.05, 0.3, 1.0})
        for (double th : kConductorIncidences)
          add(fmt::format("{}_{}_a{}_rgbindex", d, s, token(a)),
              fmt::format(R"({{"type":"{}","alpha":{},"ior":[0.2,1.1,1.4],"ext":[3.6,2.5,1.9],)"
                          R"("sampling":"{}"}})",
                          d, a, s),
              th, false, false);
  for (const NamedConductor& c : namedConductors())
    for (const char* d : kDistributions)
      for (double th : kConductorIncidences)
        add(fmt::format("{}_visible_a0p3_{}", d, c.name),
            fmt::format(R"({{"type":"{}","alpha":0.3,"conductor":"{}"}})", d, c.name), th, false,
            false);
  // DIRT's rough metal (GGX with alpha = roughness², Schlick's Fresnel; roughness 0 is a
  // mirror, a delta lobe the histogram cannot see) and blends of non-delta materials.
  for (bool rot : {false, true})
    for (double th : kConductorIncidences) {
      for (const char* s : kSamplings)
        for (double r : {0.3, 1.0})
          add(fmt::format("metal_{}_r{}", s, token(r)),
              fmt::format(R"({{"type":"metal","albedo":[0.9,0.6,0.3],"roughness":{},)"
                          R"("sampling":"{}"}})",
                          r, s),
              th, false, rot);
      add("blend_lambertian_ggx",
          R"({"type":"blend","a":{"type":"lambertian","albedo":0.8},)"
          R"("b":{"type":"ggx","alpha":0.3,"conductor":"Au"},"amount":0.3})",
          th, false, rot);
      add("blend_orennayar_blinnphong",
          R"({"type":"blend","a":{"type":"oren-nayar","sigma":0.5},)"
          R"("b":{"type":"blinnphong","exponent":50},"amount":0.7})",
          th, false, rot);
    }
  // The quick subset: every 25th configuration, a fixed stride over all material types.
  for (size_t i = 0; i < v.size(); ++i) v[i].quick = i % 25 == 0;
  // The extremes of what `verity chi2` accepts, appended after the stride so that
  // the quick subset stays as it was: exactly grazing incidence (wi.z = cos 90° = 6e-17 in
  // single precision) and 1e-4 from it, for D(m)cos θm sampling, whose reflection Jacobian
  // 1/(4 wi·h) grows without bound as wo nears −wi; the smallest roughness the material
  // accepts (alpha 1e-4) and 1e-3 at normal incidence; the smallest index outside the
  // index-matched band (rough_dielectric.h) at oblique and normal incidence.
  const size_t extremes = v.size();
  for (const char* d : kDistributions)
    for (double th : {90.0, 89.9999})
      add(fmt::format("{}_normals_a0p3_extreme", d),
          fmt::format(R"({{"type":"{}","alpha":0.3,"ior":0.34,"ext":3.9,"sampling":"normals"}})",
                      d),
          th, false, false);
  add("ggx_visible_a0p0001_extreme", R"({"type":"ggx","alpha":0.0001,"ior":0.34,"ext":3.9})", 30,
      false, false);
  add("ggx_visible_a0p001_extreme", R"({"type":"ggx","alpha":0.001,"ior":0.34,"ext":3.9})", 0,
      false, false);
  for (double th : {30.0, 0.0})
    add("roughdielectric_ggx_visible_a0p1_ior1p001_extreme",
        R"({"type":"rough_dielectric","distribution":"ggx","alpha":0.1,"ior":1.001})", th, false,
        false);
  // Every material the loader knows with each accepted range at its ends (docs/checks.md,
  // "Every accepted value at its extremes"): the exponents' 0 and 1e6 (kExponent), α's 1e-4
  // and 4 (kAlphaRange, metal's roughness 0.01 and 2), a conductor's index at 1e-4 + 0i and
  // 100 + 100i (kIorRange, kExtinctionRange), the dielectric's index just outside the
  // index-matched band (1.001, 1/1.002), at 100 and at 0.01 (kIorRange), Oren-Nayar's σ at
  // 0 and π/2, a blend's amount at 0 and 1, and albedo 0. Delta lobes (dielectric, mirror,
  // metal of roughness 0, a rough dielectric within 1e-3 of index 1) have nothing to
  // histogram, and diffuse_light reflects nothing.
  auto corner = [&](const std::string& name, const std::string& json, bool transmits) {
    for (double th : kCornerIncidences)
      for (bool inside : {false, true})
        if (!inside || transmits) add("corner_" + name, json, th, inside, false);
  };
  corner("lambertian_albedo0", R"({"type":"lambertian","albedo":0})", false);
  for (const char* type : {"phong", "blinnphong"})
    for (double e : {0.0, 1e6})
      corner(fmt::format("{}_exp{}", type, e == 0 ? "0" : "1e6"),
             fmt::format(R"({{"type":"{}","exponent":{}}})", type, e), false);
  for (double sigma : {0.0, 1.5707963})
    corner(fmt::format("orennayar_sigma{}", sigma == 0 ? "0" : "pi2"),
           fmt::format(R"({{"type":"oren-nayar","sigma":{}}})", sigma), false);
  for (const char* d : kDistributions)
    for (const char* s : kSamplings)
      for (double a : {1e-4, 4.0})
        corner(fmt::format("{}_{}_a{}", d, s, token(a)),
               fmt::format(R"({{"type":"{}","alpha":{},"sampling":"{}"}})", d, a, s), false);
  corner("ggx_a0p3_ior0p0001_ext0", R"({"type":"ggx","alpha":0.3,"ior":0.0001,"ext":0})", false);
  corner("ggx_a0p3_ior100_ext100", R"({"type":"ggx","alpha":0.3,"ior":100,"ext":100})", false);
  for (double r : {0.01, 2.0})
    corner("metal_r" + token(r), fmt::format(R"({{"type":"metal","roughness":{}}})", r), false);
  for (const char* d : kDistributions)
    for (double a : {1e-4, 4.0})
      corner(fmt::format("roughdielectric_{}_a{}", d, token(a)),
             fmt::format(R"({{"type":"rough_dielectric","distribution":"{}","alpha":{}}})", d, a),
             true);
  for (double ior : {1.001, 1 / 1.002, 100.0, 0.01})
    corner("roughdielectric_ggx_a0p1_ior" + token(std::round(ior * 1e4) / 1e4),
           fmt::format(R"({{"type":"rough_dielectric","alpha":0.1,"ior":{}}})", ior), true);
  for (double amount : {0.0, 1.0})
    corner("blend_amount" + token(amount),
           fmt::format(R"({{"type":"blend","a":{{"type":"lambertian"}},)"
                       R"("b":{{"type":"phong","exponent":1e6}},"amount":{}}})",
                       amount),
           false);
  // The narrowest lobes on the 64 × 32 cells of `verity chi2`, where they keep the degrees
  // of freedom that a grid's few cells take from them (NarrowLobeCells).
  for (const auto& [name, json] :
       {std::pair{"phong_exp1e6", R"({"type":"phong","exponent":1e6})"},
        std::pair{"ggx_visible_a0p0001", R"({"type":"ggx","alpha":1e-4,"sampling":"visible"})"}}) {
    add(std::string("equalcells_") + name, json, 45, false, false);
    v.back().resolution = kSphereResolution;
    v.back().minDof = 1001;  // over a thousand of the 64 × 32 cells' 2,047
  }
  // Refraction near grazing at an index near 1: at α 1e-4, η 1.01 and 85° the lobe is 2·10⁻⁴
  // wide in cos θ, and a cos θt computed in single precision took only a few hundred values
  // across it (refract(), fresnel.cpp). The 64 × 32 cells are narrow enough to see that lattice
  // (χ² 2,422 on 1,919 dof); the sweep's 16 × 32 are not.
  add("roughdielectric_ggx_a0p0001_ior1p01_grazing_refraction",
      R"({"type":"rough_dielectric","alpha":1e-4,"ior":1.01})", 85, false, false);
  v.back().resolution = kSphereResolution;
  for (size_t i = extremes; i < v.size(); ++i) v[i].quick = false;
  // The corners whose valid draws are too rare for the sweep's target within its budget
  // (measured: the draws the target needs, from a run with the budget raised).
  const std::string rare =
      "of the draws are valid (the rest leave below the horizon or are "
      "declined), so a 2% error needs ";
  for (BsdfCase& c : v) {
    const auto is = [&](const std::string& prefix) { return c.name.rfind(prefix, 0) == 0; };
    const auto has = [&](const std::string& part) {
      return c.name.find(part) != std::string::npos;
    };
    const bool conductorA4 =
        ((is("corner_beckmann_") || is("corner_ggx_")) && has("_a4_")) || is("corner_metal_r2");
    if (conductorA4 && !c.inside && (c.incidence == 0 || c.incidence == 45))
      c.weaker = "alpha 4 (metal: roughness 2): about 6% " + rare + "1.7e7 draws";
    if (is("corner_roughdielectric_") && has("_a4_in_t0"))
      c.weaker = "alpha 4 from inside at 0 deg: about 7% " + rare + "1.4e7 draws";
    if (c.name == "corner_roughdielectric_ggx_a0p1_ior0p998_out_t90")
      c.weaker = "index 1/1.002 at 90 deg: about 17% " + rare + "6.0e6 draws";
    if (c.name == "corner_roughdielectric_ggx_a0p1_ior1p001_in_t90")
      c.weaker = "index 1.001 from inside at 90 deg: about 10% " + rare + "1.0e7 draws";
  }
  return v;
}

std::vector<LightCase> lightCases() {
  std::vector<LightCase> v;
  // `shape` is a surface's JSON members without its material; the light is a unit emitter.
  auto add = [&](std::string name, const std::string& shape,
                 LightSampling sampling = LightSampling::SolidAngle, std::string obj = "") {
    const std::string surfaces =
        "[{" + shape + R"(, "material": {"type": "diffuse_light", "emit": 1}}])";
    v.push_back(
        {name,
         {name, surfaces, std::move(obj), Point3f::Zero(), sampling, kSweepSphereResolution}});
  };
  auto sphere = [](double radius, const std::string& centre) {
    return fmt::format(R"("type": "sphere", "radius": {}, "transform": {{"translate": {}}})",
                       radius, centre);
  };
  // A quad turned by `angle` about y from facing +z (−90°: facing the origin), at x.
  auto quad = [](const std::string& size, double angle, double x) {
    return fmt::format(R"("type": "quad", "size": {}, "transform": [{{"axis": [0, 1, 0], )"
                       R"("angle": {}}}, {{"translate": [{}, 0, 0]}}])",
                       size, angle, x);
  };
  // Spheres along +x, where the direction cells are square-ish: the visible cone from far
  // (half-angle 5.7°), from mid range and from just outside the surface (nearly a
  // hemisphere), a sphere off the axis, and the uniform area sampling of the surface.
  add("sphere_cone_far", sphere(1, "[10, 0, 0]"));
  add("sphere_cone_mid", sphere(1, "[2, 0, 0]"));
  add("sphere_cone_near", sphere(1, "[1.02, 0, 0]"));
  add("sphere_cone_offaxis", sphere(0.5, "[1, 1.2, -0.7]"));
  add("sphere_area", sphere(2, "[1, 2, 3]"), LightSampling::SphereArea);
  // Quads facing the reference point: square on, close and large (most of a hemisphere),
  // and tilted to 80° so that it is seen nearly edge on.
  add("quad_facing", quad("[1, 1.5]", -90, 1));
  add("quad_close", quad("20", -90, 0.5));
  add("quad_grazing", quad("1", -10, 1));
  // A triangle, and a mesh of triangles of unequal areas (chosen by area).
  add("triangle",
      R"("type": "triangle", "positions": [[1, -0.5, -0.5], [1.2, 0, 0.9], [1, 0.8, -0.3]])");
  add("triangle_mesh", R"("type": "mesh", "filename": "mesh.obj")", LightSampling::SolidAngle,
      "v 1 0 0\nv 1 1 0\nv 1 0.2 0.3\nv 1.3 -0.8 -0.4\nv 1.1 -0.2 1.2\n"
      "f 1 3 2\nf 1 4 3\nf 3 5 2\n");
  // Next-event estimation's choice among lights: a near quad (radiance 1, 1.5 along +x), a far
  // larger and brighter one (radiance 3, 3 along −x), both facing the origin, and one below
  // that faces away (radiance 5: never chosen, and its density 0).
  const std::string quads =
      R"([{"type": "quad", "size": 1, "material": {"type": "diffuse_light", "emit": 1},
           "transform": [{"axis": [0, 1, 0], "angle": -90}, {"translate": [1.5, 0, 0]}]},
          {"type": "quad", "size": 2, "material": {"type": "diffuse_light", "emit": 3},
           "transform": [{"axis": [0, 1, 0], "angle": 90}, {"translate": [-3, 0, 0]}]},
          {"type": "quad", "size": 1, "material": {"type": "diffuse_light", "emit": 5},
           "transform": [{"axis": [1, 0, 0], "angle": 90}, {"translate": [0, -2, 0]}]}])";
  v.push_back({"choice_quads",
               {"choice_quads", quads, "", Point3f::Zero(), LightSampling::Choice,
                kSweepSphereResolution}});
  return v;
}

int controlCaseCount() {
  return 4;
}

int statisticalCheckCount() {
  const int samplingTests = static_cast<int>(warpCases().size() + microfacetCases().size() +
                                             bsdfCases().size() + lightCases().size()) +
                            controlCaseCount();
  return 2 * samplingTests;
}

std::shared_ptr<const Material> makeMaterial(const std::string& json) {
  TextureFactory textures;
  std::vector<VerityError> warnings;  // the sweep's albedos are at most 1
  MaterialFactory factory(textures, warnings);
  return factory.make(JsonNode::parse(json, "inline"));
}

BsdfSetup setupFor(const BsdfCase& c) {
  BsdfSetup s;
  s.name = fmt::format("bsdf {} {}, incidence {} deg {}{}", c.name, c.json, c.incidence,
                       c.inside ? "inside" : "outside", c.rotated ? ", rotated normal" : "");
  s.material = makeMaterial(c.json);
  s.normal = c.rotated ? rotatedNormal() : Vector3f::UnitZ();
  s.wi = incidentDirection(c.incidence, c.inside);
  s.resolution = c.resolution;
  return s;
}

TestOptions optionsFor(const std::string& name) {
  TestOptions o;
  o.seed = seedFromName(name);
  o.significance = perTestSignificance();
  o.cells = CellLayout::EqualProbability;
  o.detect = DetectionTarget{kSweepDensityError, kStatedMass, kDefaultPower};
  o.maxSamples = kSweepBudget;
  return o;
}

TestResult runWarp(const WarpCase& c) {
  const bool planar = c.kind == WarpKind::DiskPolar || c.kind == WarpKind::DiskConcentric ||
                      c.kind == WarpKind::Triangle || c.kind == WarpKind::SquareIdentity;
  auto subject = makeWarpSubject(c.kind, c.parameter,
                                 planar ? kSweepPlanarResolution : kSweepSphereResolution);
  return runSamplingTest(*subject, optionsFor("warp_" + c.name));
}

TestResult runMicrofacet(const MicrofacetCase& c) {
  auto subject = makeMicrofacetNormalSubject(c.distribution(), c.wi(), kSweepSphereResolution);
  return runSamplingTest(*subject, optionsFor("microfacet_" + c.name));
}

TestResult runBsdf(const BsdfCase& c) {
  BsdfSubject subject(setupFor(c));
  TestOptions o = optionsFor("bsdf_" + c.name);
  o.cells = c.cells;
  o.auditedSamples = kComparedSamples;
  if (!c.weaker.empty()) {
    o.detect.reset();
    o.samples = kSweepBudget;
  }
  return runSamplingTest(subject, o);
}

TestResult runLight(const LightCase& c) {
  auto subject = makeLightSubject(c.setup);
  return runSamplingTest(*subject, optionsFor("light_" + c.name));
}

}  // namespace verity::chi2::suite
