#include "validation/studies/study_sampler.h"

#include <algorithm>
#include <cctype>
#include <typeinfo>

#include "core/error.h"
#include "sampling/sampler_registry.h"

namespace verity::studies {

std::string samplerTypeName(const Sampler& sampler) {
  // Each registry type builds its own class, so the class names the type, whatever keys the
  // scene gave it.
  for (const SamplerType& t : samplerTypes())
    if (typeid(*t.build(nullptr)) == typeid(sampler)) return t.name;
  throw VerityError("", "sampler.type", "a sampler of a type the sampler registry lacks");
}

std::vector<StudySampler> prepareSamplers(const SceneFile& file,
                                          const std::vector<std::string>& names,
                                          const std::string& option) {
  const std::string own = samplerTypeName(*file.sampler);
  std::vector<StudySampler> out;
  if (names.empty()) out.push_back({own, file.sampler->clone()});
  for (const std::string& name : names) {
    std::string spelling = name;
    std::transform(spelling.begin(), spelling.end(), spelling.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    const SamplerType* type = findSamplerType(spelling);
    if (!type)
      throw VerityError(
          "", option,
          "unknown sampler \"" + name + "\" (expected one of " + samplerTypeList() + ")");
    for (const StudySampler& s : out)
      if (s.type == type->name)
        throw VerityError("", option, "the sampler \"" + type->name + "\" is named twice");
    std::unique_ptr<Sampler> prototype =
        type->name == own ? file.sampler->clone() : type->build(nullptr);
    prototype->setSamplesPerPixel(file.sampler->samplesPerPixel());
    out.push_back({type->name, std::move(prototype)});
  }
  return out;
}

std::optional<bool> samplerSamplesAreIndependent(const std::string& type) {
  const SamplerType* entry = findSamplerType(type);
  if (!entry) return std::nullopt;
  return entry->build(nullptr)->samplesAreIndependent();
}

}  // namespace verity::studies
