// The rough conductors' complex index: "ior"/"ext" as a number or an RGB triple, or a named
// metal ("conductor"), and the loader's errors for each way of stating it wrongly.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "materials/fresnel.h"
#include "materials/named_conductors.h"
#include "materials/tests/material_test_util.h"

namespace verity::test {
namespace {

const TextureQuery q;
const Vector3f kWi = direction(40, 0.3);
const Vector3f kWo = direction(25, 2.9);

Color3 evalOf(const std::string& json) {
  return makeMaterial(json)->eval(q, kWi, kWo, TransportMode::Radiance);
}

std::string errorOf(const std::string& json) {
  try {
    makeMaterial(json);
  } catch (const VerityError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an error for " << json;
  return "";
}

TEST(ConductorIndex, ANumberFillsEveryChannel) {
  for (const char* type : {"beckmann", "ggx"}) {
    const Color3 number =
        evalOf(fmt::format(R"({{"type":"{}","ab":0.3,"ior":0.34,"ext":3.9}})", type));
    const Color3 triple = evalOf(fmt::format(
        R"({{"type":"{}","ab":0.3,"ior":[0.34,0.34,0.34],"ext":[3.9,3.9,3.9]}})", type));
    EXPECT_TRUE((number == triple).all()) << number.transpose() << " vs " << triple.transpose();
    EXPECT_EQ(number.x(), number.z());
  }
}

// Each channel of an RGB index is the material with that channel's number everywhere.
TEST(ConductorIndex, AnRgbTripleIsOneIndexPerChannel) {
  const float eta[3] = {0.2f, 1.1f, 1.4f}, k[3] = {3.6f, 2.5f, 1.9f};
  for (const char* type : {"beckmann", "ggx"}) {
    const Color3 rgb =
        evalOf(fmt::format(R"({{"type":"{}","ab":0.3,"ior":[{},{},{}],"ext":[{},{},{}]}})", type,
                           eta[0], eta[1], eta[2], k[0], k[1], k[2]));
    for (int c = 0; c < 3; ++c) {
      const Color3 one =
          evalOf(fmt::format(R"({{"type":"{}","ab":0.3,"ior":{},"ext":{}}})", type, eta[c], k[c]));
      EXPECT_EQ(rgb[c], one[c]) << type << " channel " << c;
    }
    EXPECT_NE(rgb.x(), rgb.z());
  }
}

TEST(ConductorIndex, NamedMetalsUseTheirTable) {
  ASSERT_GE(namedConductors().size(), 4u);
  for (const NamedConductor& c : namedConductors()) {
    SCOPED_TRACE(c.name);
    const Color3 named =
        evalOf(fmt::format(R"({{"type":"ggx","ab":0.2,"conductor":"{}"}})", c.name));
    const Color3 stated = evalOf(fmt::format(
        R"({{"type":"ggx","ab":0.2,"ior":[{:.9g},{:.9g},{:.9g}],"ext":[{:.9g},{:.9g},{:.9g}]}})",
        c.eta.x(), c.eta.y(), c.eta.z(), c.k.x(), c.k.y(), c.k.z()));
    EXPECT_TRUE((named == stated).all()) << named.transpose() << " vs " << stated.transpose();
    EXPECT_TRUE((c.eta > 0).all() && (c.k > 0).all());
  }
}

// What the eye knows of them: gold reflects red most and blue least (yellow), copper too
// and more steeply in green (red), silver and aluminium nearly neutral and bright.
TEST(ConductorIndex, NamedMetalsHaveTheirColours) {
  auto f0 = [](const char* name) {
    const NamedConductor* c = findNamedConductor(name);
    EXPECT_NE(c, nullptr) << name;
    return c ? fresnelConductor(1.0f, c->eta, c->k) : Color3::Zero();
  };
  const Color3 au = f0("Au"), cu = f0("Cu"), ag = f0("Ag"), al = f0("Al");
  EXPECT_GT(au.x(), au.y());
  EXPECT_GT(au.y(), au.z() + 0.2f);
  EXPECT_GT(cu.x(), cu.y() + 0.2f);
  EXPECT_GT(au.y(), cu.y());  // gold is yellower than copper
  for (const Color3& neutral : {ag, al}) {
    EXPECT_GT(neutral.minCoeff(), 0.88f) << neutral.transpose();
    EXPECT_LT(neutral.maxCoeff() - neutral.minCoeff(), 0.03f) << neutral.transpose();
  }
  EXPECT_EQ(findNamedConductor("au"), nullptr);  // chemical symbols, case-sensitive
}

TEST(ConductorIndex, ErrorsNameTheKey) {
  struct Case {
    const char* json;
    const char* expected;
  };
  for (const Case& c : {
           Case{R"({"type":"ggx","conductor":"Pt"})", "conductor: unknown conductor \"Pt\""},
           Case{R"({"type":"ggx","conductor":3})", "conductor: expected a string"},
           Case{R"({"type":"beckmann","conductor":"Au","ior":0.2})",
                "conductor: \"conductor\" and \"ior\"/\"ext\" both give the index"},
           Case{R"({"type":"ggx","conductor":"Au","ext":[1,2,3]})", "conductor:"},
           Case{R"({"type":"ggx","ior":[0.2,1.1]})", "ior: expected a number or an array of 3"},
           Case{R"({"type":"ggx","ext":[1,2,3,4]})", "ext: expected a number or an array of 3"},
           Case{R"({"type":"ggx","ior":[0.2,0,1.1]})", "ior[1]: expected a number in (0, 100]"},
           Case{R"({"type":"ggx","ext":[1,-2,3]})", "ext[1]: expected a number in [0, 100]"},
           Case{R"({"type":"beckmann","ior":0})", "ior: expected a number in (0, 100]"},
           Case{R"({"type":"ggx","ext":1e3})", "ext: expected a number in [0, 100]"},
           Case{R"({"type":"ggx","ior":"Au"})", "ior: expected a number or an array of 3"},
           Case{R"({"type":"metal","roughness":0.3,"conductor":"Au"})", "conductor: unknown key"},
       }) {
    const std::string message = errorOf(c.json);
    EXPECT_NE(message.find(c.expected), std::string::npos)
        << c.json << "\n  gave: " << message << "\n  expected: " << c.expected;
  }
  // The unknown-name error lists the known names.
  const std::string message = errorOf(R"({"type":"ggx","conductor":"gold"})");
  for (const NamedConductor& c : namedConductors())
    EXPECT_NE(message.find(c.name), std::string::npos) << message;
}

}  // namespace
}  // namespace verity::test
