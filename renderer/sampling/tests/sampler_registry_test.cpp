// The sampler registry: every name and alias builds its own type, no spelling belongs to two
// types, a scene without a sampler object gets the first (default) type, and the unknown-
// type error and the help list every type.
#include "sampling/sampler_registry.h"

#include <gtest/gtest.h>

#include <set>
#include <typeinfo>

#include "params/json_node.h"
#include "sampling/independent_sampler.h"
#include "sampling/sampler.h"
#include "testing/error_of.h"

namespace verity {
namespace {

std::unique_ptr<Sampler> samplerFrom(const std::string& json) {
  const JsonNode node = JsonNode::parse(json, "/tmp/sampler.json");
  return makeSampler(&node);
}

TEST(SamplerRegistry, EverySpellingBuildsItsOwnType) {
  std::set<std::string> spellings;
  ASSERT_GE(samplerTypes().size(), 2u);
  for (const SamplerType& t : samplerTypes()) {
    EXPECT_FALSE(t.description.empty()) << t.name;
    ASSERT_NE(t.build, nullptr) << t.name;
    const auto reference = t.build(nullptr);
    ASSERT_NE(reference, nullptr) << t.name;
    std::vector<std::string> all = t.aliases;
    all.push_back(t.name);
    for (const std::string& s : all) {
      EXPECT_TRUE(spellings.insert(s).second) << "\"" << s << "\" names two types";
      EXPECT_EQ(findSamplerType(s), &t) << s;
      const auto sampler = samplerFrom(R"({"type":")" + s + R"("})");
      EXPECT_EQ(typeid(*sampler), typeid(*reference)) << s;
    }
  }
  EXPECT_EQ(findSamplerType("sobolev"), nullptr);
}

TEST(SamplerRegistry, DefaultIsIndependent) {
  EXPECT_EQ(samplerTypes().front().name, "independent");
  const auto none = makeSampler(nullptr);
  const auto untyped = samplerFrom("{}");
  EXPECT_EQ(typeid(*none), typeid(IndependentSampler));
  EXPECT_EQ(typeid(*untyped), typeid(IndependentSampler));
}

TEST(SamplerRegistry, UnknownTypeErrorAndHelpListEveryType) {
  const std::string message = errorOf([] { samplerFrom(R"({"type":"sobolev"})"); });
  EXPECT_NE(message.find("/tmp/sampler.json"), std::string::npos) << message;
  EXPECT_NE(message.find("unknown sampler type \"sobolev\""), std::string::npos) << message;
  const std::string help = samplerTypes().help();
  for (const SamplerType& t : samplerTypes()) {
    EXPECT_NE(message.find(t.name), std::string::npos) << message;
    EXPECT_NE(help.find(t.name + (t.aliases.empty() ? ":" : " (")), std::string::npos) << help;
  }
}

}  // namespace
}  // namespace verity
